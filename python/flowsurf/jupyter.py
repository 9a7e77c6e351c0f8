"""flowsurf in Jupyter: animations that play inline, and a player that steers the renderer.

    anim = flowsurf.animate(surface, frames=60, method="hybrid", size=(400, 300))
    anim                                   # the last expression of a cell: a playable video
    flowsurf.Animation(r.frames(surface, n=60), fps=24)   # from any frames
    flowsurf.Player(surface, method="isa")                # play/pause, seek, steer (ipywidgets)

An Animation is an MP4 (H.264, through the same writer as ``flowsurf render -o movie.mp4``,
which needs the ``ffmpeg`` program) shown in an HTML5 ``<video>`` element, or an animated
PNG when ffmpeg is missing. The Player runs the library in the kernel: each frame the page
asks for (play, the frame slider) is rendered there and sent as a PNG; a change of method
or parameter restarts the animation, a camera change lets it go on. No second renderer:
it is flowsurf.Renderer underneath.
"""

import base64 as _base64
import math as _math
import os as _os
import struct as _struct
import tempfile as _tempfile
import zlib as _zlib

import numpy as _np

from . import Renderer, _as_surface, option_info, to_png
from ._flowsurf import _VideoWriter

__all__ = ["Animation", "animate", "Player"]


def _chunk(kind, data):
    return _struct.pack(">I", len(data)) + kind + data + _struct.pack(">I", _zlib.crc32(kind + data) & 0xFFFFFFFF)


def _apng(frames, fps):
    """An animated PNG of (H, W, 3) uint8 frames, looping (every browser shows it)."""
    h, w = frames[0].shape[:2]
    out = [b"\x89PNG\r\n\x1a\n", _chunk(b"IHDR", _struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)),
           _chunk(b"acTL", _struct.pack(">II", len(frames), 0))]
    seq = 0
    for i, f in enumerate(frames):
        raw = b"".join(b"\x00" + f[y].tobytes() for y in range(h))
        out.append(_chunk(b"fcTL", _struct.pack(">IIIIIHHBB", seq, w, h, 0, 0, 1, int(fps), 0, 0)))
        seq += 1
        data = _zlib.compress(raw, 6)
        if i == 0:
            out.append(_chunk(b"IDAT", data))
        else:
            out.append(_chunk(b"fdAT", _struct.pack(">I", seq) + data))
            seq += 1
    out.append(_chunk(b"IEND", b""))
    return b"".join(out)


class Animation:
    """Frames that a notebook plays inline: an MP4 video, or an animated PNG without ffmpeg.

    `frames`: any iterable of (H, W, 3) uint8 images of one size (``Renderer.frames()``, a
    list); `fps`: frames per second; `format`: "mp4", "png" (animated PNG) or None (mp4 when
    ffmpeg is there). ``save(path)`` writes ``.mp4`` or ``.png``."""

    def __init__(self, frames, fps=30, format=None):
        self.frames = [_np.array(f, dtype=_np.uint8, copy=True) for f in frames]
        if not self.frames:
            raise ValueError("Animation: no frames")
        shape = self.frames[0].shape
        if len(shape) != 3 or shape[2] != 3 or any(f.shape != shape for f in self.frames):
            raise ValueError("Animation: frames must all have one shape (H, W, 3), got %r" % (shape,))
        if not 1 <= int(fps) <= 240:
            raise ValueError("Animation: fps %r is out of range 1..240" % (fps,))
        if format not in (None, "mp4", "png"):
            raise ValueError("Animation: format must be 'mp4', 'png' or None, got %r" % (format,))
        self.fps = int(fps)
        self.format = format
        self._mp4 = None

    def __len__(self):
        return len(self.frames)

    def __getitem__(self, i):
        return self.frames[i]

    def to_mp4(self):
        """The movie as MP4 bytes (H.264, as the command line writes it). OSError without ffmpeg."""
        if self._mp4 is None:
            h, w = self.frames[0].shape[:2]
            with _tempfile.TemporaryDirectory(prefix="flowsurf-") as d:
                path = _os.path.join(d, "animation.mp4")
                writer = _VideoWriter(path, w, h, self.fps, 18)
                for f in self.frames:
                    writer.add_frame(f)
                writer.finish()
                with open(path, "rb") as fh:
                    self._mp4 = fh.read()
        return self._mp4

    def to_apng(self):
        """The movie as an animated PNG (bytes), looping."""
        return _apng(self.frames, self.fps)

    def save(self, path):
        data = self.to_mp4() if path.lower().endswith(".mp4") else self.to_apng()
        with open(path, "wb") as f:
            f.write(data)

    def _html(self):
        if self.format != "png":
            try:
                data = _base64.b64encode(self.to_mp4()).decode("ascii")
                return ('<video controls loop autoplay muted playsinline src="data:video/mp4;base64,%s">'
                        "</video>" % data)
            except OSError:
                if self.format == "mp4":
                    raise
        data = _base64.b64encode(self.to_apng()).decode("ascii")
        return '<img src="data:image/png;base64,%s"/>' % data

    def _repr_html_(self):
        return self._html()

    def __repr__(self):
        h, w = self.frames[0].shape[:2]
        return "<flowsurf.Animation: %d frames, %dx%d, %d fps>" % (len(self.frames), w, h, self.fps)


def animate(surface, frames=60, fps=30, field=None, format=None, **options):
    """Renders `frames` frames of `surface` as ``flowsurf render -o movie.mp4`` does (converged
    from frame 0, camera path, orbit and data time following the frame) and returns them as
    an Animation that plays inline. Keywords: the render options (``flowsurf.option_names()``)."""
    r = Renderer(**options)
    return Animation(r.frames(surface, int(frames), field=field), fps=fps, format=format)


# --- the player -------------------------------------------------------------------------

# The parameters the player shows a slider for, those of the method shown (option_info()'s
# "methods"), in this order; ranges and defaults come from the option table too.
_SLIDERS = ("alpha", "step-px", "filter-length", "lic-step-px", "noise-scale")
_CHOICES = ("method", "overlay", "colormap")


def _rotate(v, axis, degrees):
    """v turned about the unit `axis` (Rodrigues)."""
    a = _math.radians(degrees)
    return v * _math.cos(a) + _np.cross(axis, v) * _math.sin(a) + axis * _np.dot(axis, v) * (1 - _math.cos(a))


class Player:
    """An interactive player (ipywidgets) running flowsurf in the kernel.

    Play/pause and a frame slider; the method, overlay, colour map and each method's main
    parameters; camera azimuth, elevation and zoom about the fitted view; dye sources by
    point. Frames already rendered are kept (as PNG) until something changes, so seeking
    back is instant; seeking past the last rendered frame renders up to it.

        p = flowsurf.Player(surface, frames=120, size=(480, 360), method="hybrid")
        p                     # shows it; p.play, p.frame, p.controls["alpha"], ... are the widgets

    Keywords: the render options (``flowsurf.option_names()``)."""

    def __init__(self, surface, frames=120, fps=15, size=(400, 300), field=None, **options):
        try:
            import ipywidgets as w
            import traitlets
        except ImportError as e:
            raise ImportError("flowsurf.Player needs ipywidgets (Debian: python3-ipywidgets)") from e
        self.surface = _as_surface(surface, field)
        self.renderer = Renderer(size=size, **options)
        self._info = {o["name"]: o for o in option_info()}
        n = int(frames)
        if n < 1:
            raise ValueError("Player: frames must be at least 1")
        self._cache = {}      # frame -> PNG bytes, for the current settings
        self._last = -1       # the last frame advance() rendered since begin()
        self._base = None     # the fitted camera: eye, target, up
        self._busy = False

        self.image = w.Image(format="png", layout=w.Layout(width="%dpx" % size[0], height="%dpx" % size[1]))
        self.play = w.Play(min=0, max=n - 1, step=1, interval=max(1, int(1000 / fps)), description="play")
        self.frame = w.IntSlider(min=0, max=n - 1, description="frame", continuous_update=True)
        # Linked in the kernel (jslink would keep the kernel out of the browser's ticks).
        traitlets.link((self.play, "value"), (self.frame, "value"))
        self.controls = {}
        for name in _CHOICES:
            info = self._info[name]
            self.controls[name] = w.Dropdown(options=[c for c in info["choices"] if c],
                                             value=self.renderer.get(name), description=name)
        for name in sorted(_SLIDERS):
            info = self._info[name]
            default = float(info["default"])
            hi = min(info["max"], max(4 * default, info["min"] + 1))  # the table's range, capped for a slider
            if info["kind"] == "int":
                slider = w.IntSlider(min=int(info["min"]), max=int(hi), value=int(float(self.renderer.get(name))))
            else:
                slider = w.FloatSlider(min=info["min"], max=hi, step=(hi - info["min"]) / 100,
                                       value=float(self.renderer.get(name)))
            slider.description = name
            slider.continuous_update = False
            self.controls[name] = slider
        self.azimuth = w.FloatSlider(min=-180, max=180, value=0, description="azimuth", continuous_update=False)
        self.elevation = w.FloatSlider(min=-85, max=85, value=0, description="elevation", continuous_update=False)
        self.zoom = w.FloatSlider(min=0.25, max=4, value=1, step=0.05, description="zoom", continuous_update=False)
        self.dye_point = w.Text(placeholder="x,y,z", description="dye at")
        self.dye_button = w.Button(description="add dye")
        self.status = w.Label(layout=w.Layout(width="100%"))

        self.frame.observe(lambda change: self.show(change["new"]), "value")
        for name, control in self.controls.items():
            control.observe(lambda change, name=name: self._set_option(name, change["new"]), "value")
        for slider in (self.azimuth, self.elevation, self.zoom):
            slider.observe(lambda change: self._camera_changed(), "value")
        self.dye_button.on_click(lambda _: self.add_dye(self.dye_point.value))
        self._params_box = w.VBox()
        self.widget = w.VBox([self.image, w.HBox([self.play, self.frame]),
                              w.HBox([w.VBox([self.controls[c] for c in _CHOICES]), self._params_box]),
                              w.HBox([w.VBox([self.azimuth, self.elevation, self.zoom]),
                                      w.VBox([self.dye_point, self.dye_button])]),
                              self.status])
        self._show_params()
        self._restart()
        self.show(0)

    # --- what the widgets call --------------------------------------------------------
    def show(self, f):
        """Shows frame `f`: from the kept frames, or rendered (restarting when it is behind)."""
        f = int(f)
        if f not in self._cache:
            if f <= self._last:
                self._restart()
            while self._last < f:
                self.renderer._r.advance()
                self._last += 1
                self._cache[self._last] = to_png(self.renderer._r.image())
                if self._base is None:  # the view fitted to the surface: what the camera sliders turn
                    cam = self.renderer.camera
                    self._base = tuple(_np.array(cam[k], dtype=float) for k in ("eye", "target", "up"))
        self.image.value = self._cache[f]
        self.status.value = "frame %d, data time %g, %s" % (f, self.renderer.time, self._timing())

    def _timing(self):
        ms = self.renderer.stage_ms
        return "%.1f ms/frame" % sum(ms.values()) if ms else ""

    def _set_option(self, name, value):
        self.renderer.set(**{name.replace("-", "_"): value})
        if name == "method":
            self._show_params()
        self._restart()
        self.show(self.frame.value)

    def _show_params(self):
        method = self.renderer.get("method")
        self._params_box.children = [self.controls[p] for p in _SLIDERS if method in self._info[p]["methods"]]

    def _restart(self):
        """begin() with the current options: the animation starts over (with its warm-up)."""
        self._cache = {}
        self._last = -1
        self.renderer._r.begin(self.surface)

    def _camera_changed(self):
        """A camera option: the texture goes on (the remedy of --on-camera-move), the frames
        kept so far are dropped and the frame on screen is drawn from the new camera."""
        eye, target, up = self._base
        up = up / _np.linalg.norm(up)
        offset = eye - target
        offset = _rotate(offset, up, self.azimuth.value)
        side = _np.cross(up, offset)
        side /= _np.linalg.norm(side)
        offset = _rotate(offset, side, -self.elevation.value) / self.zoom.value
        self.renderer.set(eye=tuple(target + offset), target=tuple(target), up=tuple(up))
        self._redraw()

    def _redraw(self):
        """The next frame, in place of the one on screen (camera or dye changed)."""
        self.renderer._r.advance()
        self._last += 1
        png = to_png(self.renderer._r.image())
        self._cache = {self.frame.value: png}
        self._last = self.frame.value
        self.image.value = png

    def add_dye(self, point, radius=0.0, color=None):
        """Dye at the surface point nearest `point` ("x,y,z" or a sequence); it flows from the
        next frame on."""
        if isinstance(point, str):
            point = [float(v) for v in point.split(",")]
        self.renderer.add_dye(point, radius, color)
        self._redraw()

    def snapshot_html(self):
        """The frame on screen as HTML: what a page without the widgets' JavaScript shows (an
        exported notebook, nbconvert, a notebook viewer)."""
        data = _base64.b64encode(self.image.value).decode("ascii")
        return ('<div class="flowsurf-player"><img src="data:image/png;base64,%s"/><br/><code>flowsurf.Player: %s'
                " (play, seek and steer it in a running notebook)</code></div>" % (data, self.status.value))

    def _ipython_display_(self):
        """The widget. Where no page runs the widgets' JavaScript (an exported notebook), a
        still of the frame on screen: ipywidgets >= 7 carry it as the text/html fallback that
        nbconvert keeps without widget state; with ipywidgets 6 (Debian 12), whose page cannot
        be asked beforehand, FLOWSURF_JUPYTER_STILL=1 asks for the still (headless runs,
        tools/docs/run_notebook.py)."""
        from IPython.display import display
        w = self.widget
        still = {"text/html": self.snapshot_html(), "text/plain": repr(self)}
        if _os.environ.get("FLOWSURF_JUPYTER_STILL") == "1":
            display(still, raw=True)
        elif hasattr(w, "_repr_mimebundle_"):  # ipywidgets >= 7
            bundle = dict(still)
            bundle.update(w._repr_mimebundle_() or {})
            display(bundle, raw=True)
        else:  # ipywidgets 6: the view is made by a message to the page's widget JavaScript
            w._send({"method": "display"})
            w._handle_displayed()

    def __repr__(self):
        return "<flowsurf.Player: %s>" % self.status.value
