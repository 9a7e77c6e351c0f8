"""flowsurf: dense, animated flow textures on triangle-mesh surfaces.

ISA and IBFVS (Laramee et al. 2004) and the hybrid physical/device-space LIC (Weiskopf &
Ertl 2004), rendered on the GPU (or Mesa's llvmpipe) into numpy arrays::

    import flowsurf, numpy as np
    s = flowsurf.Surface(points, triangles, vectors)          # (N,3), (M,3), (N,3)
    s = flowsurf.read("case.vtp", field="wallShearStress")     # any format the CLI reads
    img = flowsurf.render(s, method="hybrid", size=(800, 600), frames=90, seed=1)
    img, tex = flowsurf.render(s, method="isa", flow_texture=True)
    r = flowsurf.Renderer(method="ibfvs", size=(640, 480), alpha=0.1)
    img = flowsurf.render(s, dye=[(0, 0, 1), {"point": (1, 0, 0), "radius": 0.05, "color": "red"}])
    r.add_dye((0, 1, 0), radius=0.05, color="#00ff00")
    for frame in r.frames(s, n=120, orbit=1.0): ...
    r.stage_ms
    flowsurf.animate(s, frames=60, method="hybrid")            # plays inline in a notebook
    flowsurf.Player(s)                                         # play, seek, steer (ipywidgets)

Keywords are the command-line option names with ``_`` for ``-`` (``step_px``,
``filter_length``, ``on_camera_move``, ``time_per_frame``...), with the same defaults and
ranges (``flowsurf render --help``). Bad keywords or values raise ``ValueError`` naming
them; unreadable files raise ``OSError``; malformed data ``flowsurf.FormatError`` (a
``ValueError``). Rendering releases the GIL; renderers in several threads take turns.
"""

import struct as _struct
import zlib as _zlib

import numpy as _np

from ._flowsurf import (FieldError, FormatError, GlError, Surface, option_info, option_names, read_option_info,
                        read_option_names)
from ._flowsurf import _Renderer, _read, _topology

__all__ = ["Surface", "read", "render", "topology", "Renderer", "to_png", "Image", "Animation", "animate", "Player",
           "FormatError", "FieldError", "GlError", "option_names", "option_info", "read_option_names",
           "read_option_info"]

# The keywords, from the C++ option table: a Renderer's (what the frame loop applies) and
# read()'s (how the input is read); and what the table says of each Renderer option.
_OPTIONS = set(option_names())
_READ_OPTIONS = set(read_option_names())
_INFO = {o["name"]: o for o in option_info()}


def _dye_text(source):
    """One dye source as --dye's X,Y,Z[:RADIUS[:COLOR]]: a point (x, y, z), a dict with
    point, radius and color, or the text itself."""
    if isinstance(source, str):
        return source
    if isinstance(source, dict):
        unknown = set(source) - {"point", "radius", "color"}
        if unknown or "point" not in source:
            raise ValueError("a dye source dict takes point, radius, color (got %r)" % (source,))
        text = ",".join(repr(float(v)) for v in source["point"])
        text += ":" + repr(float(source.get("radius", 0.0)))
        return text + (":" + str(source["color"]) if source.get("color") else "")
    return ",".join(repr(float(v)) for v in source)


def _option_text(name, value):
    """A Python value as the command line's text for option `name`: a sequence of numbers
    joined as the option table says (size (800, 600): 800x600, time (0, 1): 0.0:1.0, eye:
    x,y,z); the option's own parser then checks it."""
    if name == "dye" and isinstance(value, (tuple, list)) and value and not isinstance(value[0], (int, float)):
        return ";".join(_dye_text(s) for s in value)  # several sources
    if isinstance(value, (bool, _np.bool_)):
        return "on" if value else "off"  # flags and on/off switches both read it
    if isinstance(value, (tuple, list, _np.ndarray)):
        info = _INFO.get(name, {})
        items = [v.item() if hasattr(v, "item") else v for v in value]
        number = (lambda v: "%d" % int(v)) if info.get("kind") in ("size", "int") else (lambda v: repr(float(v)))
        return info.get("separator", ",").join(number(v) for v in items)
    if isinstance(value, float):
        return repr(value)
    return str(value)


def _keywords(options, allowed, what):
    """(name, text) pairs of keyword options, checked against the option names `allowed`."""
    pairs = []
    for key, value in options.items():
        name = key.replace("_", "-")
        if name not in allowed:
            hint = " (%s is read with the surface: flowsurf.read(path, %s=...))" % (key, key) \
                if name in _READ_OPTIONS else ""
            raise ValueError("unknown keyword %r%s (%s: %s)" % (
                key, hint, what, ", ".join(sorted(o.replace("-", "_") for o in allowed))))
        if value is not None:
            pairs.append((key, name, _option_text(name, value)))
    return pairs


def _apply(renderer, options):
    for key, name, text in _keywords(options, _OPTIONS, "render options"):
        try:
            renderer.set(name, text)
        except ValueError as e:
            raise ValueError("%s=%r: %s" % (key, options[key], e)) from None


def read(path, field=None, **options):
    """Reads a surface: any format the command line reads, a file series, or builtin:NAME.
    `field` picks the vector array (default: the first that is not zero everywhere), or a
    derived one; "skin-friction" is derived while reading, from the velocity next to the walls
    of an OpenFOAM case or a volume file (docs/cfd.md); keywords say how the input is read
    (read_option_names(): patches, foam_case, foam_zero_time, viscosity)."""
    pairs = [(name, text) for _, name, text in _keywords(options, _READ_OPTIONS, "read options")]
    return _read(path, field or "", pairs)


def _triangles_from_faces(faces):
    """PyVista's flat face array [n, i0, .., i(n-1), n, ...] as (M,3) triangles (fans)."""
    faces = _np.asarray(faces).ravel()
    tris, i = [], 0
    while i < len(faces):
        n = int(faces[i])
        poly = faces[i + 1:i + 1 + n]
        if n < 3 or len(poly) != n:
            raise ValueError("faces: malformed cell at offset %d" % i)
        for k in range(1, n - 1):
            tris.append((poly[0], poly[k], poly[k + 1]))
        i += n + 1
    return _np.asarray(tris, dtype=_np.int64).reshape(-1, 3)


def _as_surface(mesh, field=None):
    """A flowsurf.Surface from a Surface, a PyVista-like mesh (points, faces, point_data)
    or a vedo Mesh (vertices, cells, pointdata)."""
    if isinstance(mesh, Surface):
        if field and field != mesh.field:
            mesh.set_field(field)
        return mesh
    if hasattr(mesh, "vertices") and hasattr(mesh, "cells") and hasattr(mesh, "pointdata"):  # vedo
        # vedo 2023.4 has methods vertices()/cells(); later versions properties.
        points = _np.asarray(mesh.vertices() if callable(mesh.vertices) else mesh.vertices)
        cells = mesh.cells() if callable(mesh.cells) else mesh.cells
        tris = []
        for c in cells:
            c = list(c)
            if len(c) < 3:
                raise ValueError("vedo mesh: a cell with %d points is not a surface polygon" % len(c))
            tris.extend((c[0], c[k], c[k + 1]) for k in range(1, len(c) - 1))
        triangles = _np.asarray(tris, dtype=_np.int64).reshape(-1, 3)
        data = mesh.pointdata
        names = list(data.keys())
    elif hasattr(mesh, "points") and hasattr(mesh, "faces"):  # PyVista PolyData layout
        points = _np.asarray(mesh.points)
        triangles = _triangles_from_faces(mesh.faces)
        data = getattr(mesh, "point_data", None) or getattr(mesh, "point_arrays", {})
        names = list(data.keys())
    else:
        raise ValueError("expected a flowsurf.Surface, a mesh with points and faces (PyVista), or a vedo Mesh; "
                         "got %s" % type(mesh).__name__)
    vectors = [n for n in names if _np.asarray(data[n]).ndim == 2 and _np.asarray(data[n]).shape[1] == 3
               and n.lower() != "normals"]
    if field is None:
        if not vectors:
            raise ValueError("the mesh has no 3-component point array to use as the vector field")
        field = vectors[0]
    if field not in names:
        raise FieldError("the mesh has no point array %r (has: %s)" % (field, ", ".join(names)))
    surface = Surface(points, triangles, _np.asarray(data[field]), field=field)
    for n in vectors:
        if n != field:
            surface.add_vectors(n, _np.asarray(data[n]))
    return surface


class Renderer:
    """A renderer with one method and its options; keeps its texture between frames.

    r = flowsurf.Renderer(method="hybrid", size=(800, 600), filter_length=41)
    img = r.render(surface)                        # (H, W, 3) uint8 after `frames` frames
    for img in r.frames(surface, n=120, orbit=1.0): ...   # an animation, frame by frame
    r.set(alpha=0.1); r.get("alpha"); r.stage_ms; r.camera; r.quality()"""

    def __init__(self, **options):
        self._r = _Renderer()
        _apply(self._r, options)

    def set(self, **options):
        """Sets options by keyword; the next frame starts over unless only the camera changed."""
        _apply(self._r, options)

    def add_dye(self, point, radius=0.0, color=None):
        """Releases dye at the surface point nearest `point`: radius in object units (0: a few
        pixels), colour a name, '#rrggbb' or 'r,g,b' (None: the next default colour). A running
        animation goes on; the source emits from the next frame (dye_release frames, 0: always)."""
        try:
            self._r.add_dye([float(v) for v in point], float(radius), color or "")
        except ValueError as e:
            raise ValueError("add_dye: %s" % e) from None

    def get(self, name):
        """An option's value as the command line would print it."""
        return self._r.get(name.replace("_", "-"))

    def render(self, surface, field=None):
        """Frames 0..`frames` from a fresh start; the last one as an (H, W, 3) uint8 array."""
        self._r.render(_as_surface(surface, field), int(self._r.get("frames")))
        return self._r.image()

    def frames(self, surface, n, field=None, **options):
        """Yields the image of frames 0..n-1 of an animation, as the command line's movie
        writes them: converged from frame 0 (the warm-up option), camera path, orbit and data
        time following the frame."""
        _apply(self._r, options)
        self._r.begin(_as_surface(surface, field))
        for _ in range(int(n)):
            self._r.advance()
            yield self._r.image()

    def image(self):
        return self._r.image()

    def flow_texture(self):
        """F_a of the last frame alone: (H, W) float32 in [0, 1]."""
        return self._r.flow_texture()

    @property
    def stage_ms(self):
        """Milliseconds per stage of the last frame."""
        return self._r.stage_ms()

    @property
    def camera(self):
        return self._r.camera()

    @property
    def frame(self):
        return self._r.frame

    @property
    def time(self):
        return self._r.time

    @property
    def gl_renderer(self):
        return self._r.gl_renderer()

    def set_quality_every(self, every):
        """Measure every N-th frame of the next render() or frames() against the field (0,
        the default: off); see quality()."""
        self._r.set_quality_every(int(every))

    def quality(self):
        """How faithful the texture is to the field (doc/algorithms.md §9, the numbers of
        `flowsurf quality`): {"frames": n, "median": {metric: value}, "worst": {...}} over
        the frames measured since render() or frames() began; with measuring off, the last
        frame measured now (no frame correlations). None where not measured."""
        return self._r.quality()


# What topology() takes: the analysis thresholds and how the field is shown, by the option
# table's names (docs/topology.md).
TOPOLOGY_OPTIONS = {"reverse-field", "curvature-radius", "topology-parts", "topology-scale", "topology-cancel-speed",
                    "topology-line-strength", "topology-line-length"}


def topology(surface, field=None, step=0, **options):
    """The flow topology of `surface`'s field at time step `step`, as `flowsurf topology` writes it:
    a dict with positions (K, 3) float32, types (K names: source, sink, saddle, center,
    repelling_focus, attracting_focus), index (K,) int64 (Poincare index), lines (dicts with
    kind "separation" or "attachment", points (n, 3) and strength (n,)), euler_characteristic,
    index_sum, closed, field and field_reversed. Keywords: reverse_field, topology_scale,
    topology_cancel_speed, topology_line_strength, topology_line_length, topology_parts."""
    s = _as_surface(surface, field)
    pairs = [(name, text) for _, name, text in _keywords(options, TOPOLOGY_OPTIONS, "topology options")]
    return _topology(s, step, pairs)


def render(surface, flow_texture=False, field=None, **options):
    """Renders `surface` as `flowsurf render` does: the image after `frames` frames (90),
    (H, W, 3) uint8; with flow_texture=True also F_a, (H, W) float32."""
    r = Renderer(**options)
    img = r.render(surface, field)
    return (img, r.flow_texture()) if flow_texture else img


def to_png(img):
    """PNG bytes of an (H, W, 3) uint8 image or an (H, W) float image in [0, 1]."""
    a = _np.asarray(img)
    if a.ndim == 2:
        a = _np.repeat((_np.clip(a, 0, 1) * 255 + 0.5).astype(_np.uint8)[:, :, None], 3, axis=2)
    if a.ndim != 3 or a.shape[2] != 3:
        raise ValueError("to_png: expected (H, W, 3) or (H, W), got shape %r" % (a.shape,))
    a = _np.ascontiguousarray(a, dtype=_np.uint8)
    h, w = a.shape[:2]
    raw = b"".join(b"\x00" + a[y].tobytes() for y in range(h))

    def chunk(kind, data):
        return (_struct.pack(">I", len(data)) + kind + data +
                _struct.pack(">I", _zlib.crc32(kind + data) & 0xFFFFFFFF))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", _struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", _zlib.compress(raw, 6)) + chunk(b"IEND", b""))


class Image:
    """An image that a notebook shows: Image(flowsurf.render(s))."""

    def __init__(self, img):
        self.array = _np.asarray(img)

    def _repr_png_(self):
        return to_png(self.array)

    def save(self, path):
        with open(path, "wb") as f:
            f.write(to_png(self.array))


def _options_doc():
    """The render options as a docstring section, from the option table (option_info())."""
    lines = ["Options (keywords of Renderer, Renderer.set, Renderer.frames, render and animate;",
             "the command line's names with _ for -, the same ranges and defaults):"]
    group = None
    for o in option_info():
        if o["group"] != group:
            group = o["group"]
            lines += ["", "  %s" % group]
        if o["kind"] in ("int", "float"):
            hi = "inf" if o["max"] >= 1e29 else "%g" % o["max"]
            value = "%s %g..%s" % (o["kind"], o["min"], hi)
        elif o["kind"] == "choice":
            value = "|".join(c for c in o["choices"] if c)
        else:
            value = o["kind"]
        default = " (default %s)" % o["default"] if o["default"] else ""
        lines.append("    %s: %s%s" % (o["name"].replace("-", "_"), value, default))
        lines.append("        %s" % o["help"])
    return "\n".join(lines)


Renderer.__doc__ = (Renderer.__doc__ or "") + "\n\n" + _options_doc()
render.__doc__ = (render.__doc__ or "") + "\n\nKeywords: the options of Renderer (help(flowsurf.Renderer))."

from .jupyter import Animation, Player, animate  # noqa: E402  (needs Renderer above)
