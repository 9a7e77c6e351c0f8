"""The Python module as a scientist uses it: numpy in, images out, the same bytes as the
command line, clear exceptions, vedo meshes, flat memory, threads."""
import os
import resource
import struct
import subprocess
import threading
import zlib

import numpy as np
import pytest

import flowsurf

FLOWSURF = os.environ.get("FLOWSURF", "flowsurf")


# --- helpers -------------------------------------------------------------------------

def sphere(rings=64, segments=128, w=(0.3, 1.0, 0.2)):
    """UV sphere in solid-body rotation about w: points, triangles, velocity w x p."""
    th = np.linspace(0, np.pi, rings + 1)
    ph = np.linspace(0, 2 * np.pi, segments + 1)
    T, P = np.meshgrid(th, ph, indexing="ij")
    pts = np.stack([np.sin(T) * np.cos(P), np.cos(T), np.sin(T) * np.sin(P)], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(rings), np.arange(segments), indexing="ij")
    a = (i * (segments + 1) + j).ravel()
    b = a + segments + 1
    tris = np.concatenate([np.stack([a, b, a + 1], 1), np.stack([a + 1, b, b + 1], 1)])
    w = np.asarray(w, float) / np.linalg.norm(w)
    return pts, tris, np.cross(w, pts), w


def read_png(path):
    """8-bit RGB or gray PNG -> array (our own decoder: no imaging library needed)."""
    data = open(path, "rb").read()
    pos, idat = 8, b""
    while pos < len(data):
        n, = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
    ch = {0: 1, 2: 3}[ctype] * depth // 8
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(h, 1 + w * ch)
    out = np.zeros((h, w * ch), np.int32)
    prev = np.zeros(w * ch, np.int32)
    for y in range(h):
        f, line = raw[y, 0], raw[y, 1:].astype(np.int32)
        cur = np.zeros_like(line)
        for x in range(len(line)):
            a = cur[x - ch] if x >= ch else 0
            b = prev[x]
            c = prev[x - ch] if x >= ch else 0
            pred = [0, a, b, (a + b) // 2][f] if f < 4 else (
                a if abs(b - c) <= abs(a - c) and abs(b - c) <= abs(a + b - 2 * c)
                else b if abs(a - c) <= abs(a + b - 2 * c) else c)
            cur[x] = (line[x] + pred) & 255
        out[y], prev = cur, cur
    return out.reshape(h, w, ch).astype(np.uint8) if depth == 8 else out


def gaussian_blur(a, sigma):
    r = int(3 * sigma)
    k = np.exp(-0.5 * (np.arange(-r, r + 1) / sigma) ** 2)
    k /= k.sum()
    a = np.apply_along_axis(lambda v: np.convolve(v, k, mode="same"), 0, a)
    return np.apply_along_axis(lambda v: np.convolve(v, k, mode="same"), 1, a)


def look_at(eye, target, up):
    f = np.subtract(target, eye)
    f /= np.linalg.norm(f)
    r = np.cross(f, up)
    r /= np.linalg.norm(r)
    return f, r, np.cross(r, f)


def orientation_error(img_tex, cam, w, width, height, fov):
    """Median angle (deg) between the streaks of F_a (structure tensor, sigma 4 px) and
    the projected field, where the sphere faces the camera and moves (as the GL tests)."""
    gy, gx = np.gradient(img_tex.astype(np.float64))
    jxx, jxy, jyy = (gaussian_blur(v, 4.0) for v in (gx * gx, gx * gy, gy * gy))
    grad_angle = 0.5 * np.arctan2(2 * jxy, jxx - jyy)   # image rows downwards
    streak = np.mod(grad_angle + np.pi / 2, np.pi)
    eye = np.array(cam["eye"])
    f, r, u = look_at(eye, cam["target"], cam["up"])
    t = np.tan(np.radians(fov) / 2)
    errs = []
    for py in range(8, height - 8, 5):
        for px in range(8, width - 8, 5):
            ndc = np.array([(px + 0.5) / width * 2 - 1, 1 - (py + 0.5) / height * 2])
            d = f + ndc[0] * t * width / height * r + ndc[1] * t * u
            d /= np.linalg.norm(d)
            b = np.dot(eye, d)
            disc = b * b - (np.dot(eye, eye) - 1.0)
            if disc < 0:
                continue
            p = eye + (-b - np.sqrt(disc)) * d            # unit sphere hit
            if np.dot(p, -d) < 0.4:
                continue                                   # near the silhouette
            v = np.cross(w, p)
            if np.linalg.norm(v) < 0.4 * 0.4:
                continue                                   # near the rotation poles

            def to_px(q):
                c = q - eye
                z = np.dot(c, f)
                return np.array([np.dot(c, r) / (z * t * width / height), np.dot(c, u) / (z * t)])

            dv = to_px(p + 0.01 * v) - to_px(p)
            expected = np.mod(np.arctan2(-dv[1] * height, dv[0] * width), np.pi)  # rows downwards
            e = abs(streak[py, px] - expected) % np.pi
            errs.append(np.degrees(min(e, np.pi - e)))
    assert len(errs) > 200
    return float(np.median(errs))


# --- tests ---------------------------------------------------------------------------

@pytest.mark.parametrize("method,limit", [("isa", 10.0), ("ibfvs", 10.0), ("hybrid", 5.0)])
def test_orientation_on_a_spinning_sphere_built_in_numpy(method, limit):
    pts, tris, vel, w = sphere()
    s = flowsurf.Surface(pts, tris, vel)
    eye = np.array([0.3, 0.4, 1.0]) / np.linalg.norm([0.3, 0.4, 1.0]) * 4.2
    r = flowsurf.Renderer(method=method, size=(320, 320), seed=7, frames=1 if method == "hybrid" else 100,
                          eye=eye, target=(0, 0, 0), up=(0, 1, 0), fov=30)
    r.render(s)
    err = orientation_error(r.flow_texture(), r.camera, w, 320, 320, 30)
    print("%s: median orientation error %.2f deg" % (method, err))
    assert err <= limit


@pytest.mark.parametrize("method", ["isa", "ibfvs", "hybrid"])
def test_same_bytes_as_the_command_line(method, tmp_path):
    out = tmp_path / "cli.png"
    subprocess.run([FLOWSURF, "render", "builtin:tori", "--method", method, "--size", "160x120", "--frames", "12",
                    "--seed", "5", "--alpha", "0.1", "-q", "-o", str(out)], check=True)
    img = flowsurf.render(flowsurf.read("builtin:tori"), method=method, size=(160, 120), frames=12, seed=5,
                          alpha=0.1)
    assert img.shape == (120, 160, 3) and img.dtype == np.uint8
    assert np.array_equal(img, read_png(out))


def test_errors_raise_the_named_exceptions(tmp_path):
    pts, tris, vel, _ = sphere(8, 16)
    bad = vel.copy()
    bad[5, 1] = np.nan
    with pytest.raises(flowsurf.FormatError, match="5"):
        flowsurf.Surface(pts, tris, bad)
    with pytest.raises(ValueError, match="out of range"):
        flowsurf.Surface(pts, np.where(tris == 3, 10 ** 6, tris), vel)
    with pytest.raises(ValueError, match="shape"):
        flowsurf.Surface(pts[:, :2], tris, vel)
    with pytest.raises(ValueError, match="rows"):
        flowsurf.Surface(pts, tris, vel[:-1])
    with pytest.raises(OSError, match="nosuch.vtp"):
        flowsurf.read(str(tmp_path / "nosuch.vtp"))
    garbage = tmp_path / "garbage.vtp"
    garbage.write_bytes(bytes((i * 7919) % 251 for i in range(3000)))
    with pytest.raises(flowsurf.FormatError, match="garbage.vtp"):
        flowsurf.read(str(garbage))
    assert issubclass(flowsurf.FormatError, ValueError)
    with pytest.raises(flowsurf.FieldError, match="pressure"):
        flowsurf.read("builtin:sphere", field="pressure")
    s = flowsurf.Surface(pts, tris, vel)
    with pytest.raises(ValueError, match="filter_lenght"):
        flowsurf.render(s, filter_lenght=20)
    with pytest.raises(ValueError, match="alpha=1.5"):
        flowsurf.render(s, alpha=1.5)
    with pytest.raises(ValueError, match="method"):
        flowsurf.render(s, method="lic")


def test_sequence_keywords_are_joined_as_the_option_table_says():
    r = flowsurf.Renderer(size=(64, 48), time=(0.5, 2), eye=np.array([0, 0, 5]))
    assert (r.get("size"), r.get("time"), r.get("eye")) == ("64x48", "0.5:2", "0,0,5")
    r.set(color_range=(0, 2.5))  # a range: MIN:MAX (it was joined by commas and refused)
    assert r.get("color_range") == "0:2.5"
    # A wrong count is refused by the option's own parser, naming it and its syntax.
    with pytest.raises(ValueError, match=r"size=\(64,\).*WIDTHxHEIGHT"):
        r.set(size=(64,))
    with pytest.raises(ValueError, match="START:END"):
        r.set(time=(0, 1, 2))


def test_inputs_need_not_be_contiguous_or_float32():
    pts, tris, vel, _ = sphere(16, 32)
    a = flowsurf.render(flowsurf.Surface(pts.astype(np.float32), tris.astype(np.int32), vel.astype(np.float32)),
                        method="hybrid", size=(64, 64), frames=1)
    wide = np.zeros((len(pts), 6))
    wide[:, ::2] = pts  # a strided view
    b = flowsurf.render(flowsurf.Surface(wide[:, ::2], tris.astype(np.uint64), vel.tolist()), method="hybrid",
                        size=(64, 64), frames=1)
    assert np.array_equal(a, b)


def test_vedo_mesh_and_pyvista_layout_are_accepted():
    vedo = pytest.importorskip("vedo")
    m = vedo.Sphere(res=48)
    pts = np.asarray(m.vertices() if callable(m.vertices) else m.vertices)
    m.pointdata["velocity"] = np.cross([0.0, 1.0, 0.0], pts)
    img = flowsurf.render(m, field="velocity", method="hybrid", size=(96, 96), frames=1)
    cells = m.cells() if callable(m.cells) else m.cells
    direct = flowsurf.render(flowsurf.Surface(pts, np.asarray(cells), np.cross([0.0, 1.0, 0.0], pts)),
                             method="hybrid", size=(96, 96), frames=1)
    assert np.array_equal(img, direct)
    assert (img != img[0, 0]).any(axis=2).sum() > 2000  # the sphere is there

    class PolyData:  # PyVista's layout: flat faces [3, i, j, k, ...], point_data
        points = pts
        faces = np.hstack([np.full((len(cells), 1), 3), np.asarray(cells)]).ravel()
        point_data = {"velocity": np.cross([0.0, 1.0, 0.0], pts)}

    assert np.array_equal(flowsurf.render(PolyData(), method="hybrid", size=(96, 96), frames=1), direct)


def rss_mb():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize() / 2 ** 20


def test_memory_stays_flat_over_500_renders():
    pts, tris, vel, _ = sphere(8, 16)
    s = flowsurf.Surface(pts, tris, vel)
    for _ in range(50):
        flowsurf.render(s, size=(32, 32), frames=1)
    before = rss_mb()
    for _ in range(500):
        flowsurf.render(s, size=(32, 32), frames=1)
    grown = rss_mb() - before
    print("resident memory grew %.1f MB over 500 renders" % grown)
    assert grown < 20


def test_two_threads_render_at_once():
    """Both work: calls take turns on the GL lock (GIL released while they wait)."""
    pts, tris, vel, _ = sphere(16, 32)
    s = flowsurf.Surface(pts, tris, vel)
    expected = {m: flowsurf.render(s, method=m, size=(80, 60), frames=6) for m in ("isa", "hybrid")}
    got = {}

    def work(m):
        got[m] = [flowsurf.render(s, method=m, size=(80, 60), frames=6) for _ in range(3)]

    threads = [threading.Thread(target=work, args=(m,)) for m in ("isa", "hybrid")]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for m in expected:
        assert all(np.array_equal(img, expected[m]) for img in got[m])


def test_animation_frames_and_stage_times():
    s = flowsurf.read("builtin:sphere")
    r = flowsurf.Renderer(method="ibfvs", size=(64, 48), alpha=0.1)
    frames = list(r.frames(s, n=5, orbit=1.0))
    assert len(frames) == 5 and frames[0].shape == (48, 64, 3)
    assert r.frame == 5
    assert "overlay" in r.stage_ms and all(v >= 0 for v in r.stage_ms.values())
    assert not np.array_equal(frames[0], frames[-1])


def test_png_for_notebooks(tmp_path):
    img = flowsurf.render(flowsurf.read("builtin:sphere"), size=(40, 30), frames=2)
    png = flowsurf.Image(img)._repr_png_()
    assert png.startswith(b"\x89PNG")
    (tmp_path / "a.png").write_bytes(flowsurf.to_png(img))
    assert np.array_equal(read_png(tmp_path / "a.png"), img)


def test_animation_frames_are_the_command_lines_movie_frames(tmp_path):
    # Same warm-up and noise clock as `render -o seq_%02d.png` (frame f at k = W + f); --frames 4
    # writes 4 files, as n=4 gives 4 frames [docs/cfd.md, colour ranges].
    subprocess.run([FLOWSURF, "render", "builtin:sphere", "--method", "ibfvs", "--size", "64x48", "--alpha", "0.1",
                    "--orbit", "1", "--frames", "4", "-q", "-o", str(tmp_path / "seq_%02d.png")], check=True)
    r = flowsurf.Renderer(method="ibfvs", size=(64, 48), alpha=0.1)
    frames = list(r.frames(flowsurf.read("builtin:sphere"), n=4, orbit=1.0))
    for f, img in enumerate(frames):
        assert np.array_equal(img, read_png(tmp_path / ("seq_%02d.png" % f))), "frame %d" % f


def test_input_options_go_to_read_not_to_the_renderer():
    # Once accepted by a Renderer and silently ignored.
    with pytest.raises(ValueError, match="flowsurf.read"):
        flowsurf.Renderer(patches="wall.*")
    with pytest.raises(ValueError, match="foam_case"):
        flowsurf.Renderer(foam_case="decomposed")
    with pytest.raises(ValueError, match="alpha"):
        flowsurf.read("builtin:sphere", alpha=0.1)
    assert set(flowsurf.read_option_names()) == {"patches", "foam-case", "foam-zero-time", "viscosity"}
    assert flowsurf.read("builtin:sphere", patches="wall.*").triangle_count > 0


def write_cube_case(root, times, initial_directive=False):
    """A one-cell OpenFOAM case (walls all round) with U = (t, 0, 0) in each time directory;
    0/ as the tutorials write it (#includeEtc) when `initial_directive`."""
    def foam(path, cls, body):
        path = root / path
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text("FoamFile\n{\n version 2.0;\n format ascii;\n class %s;\n object %s;\n}\n%s"
                        % (cls, path.name, body))
    root.mkdir(parents=True, exist_ok=True)
    (root / "case.foam").write_text("")
    foam("system/controlDict", "dictionary", "application icoFoam;\nstartTime 0;\nendTime 1;\ndeltaT 1;\n")
    foam("constant/polyMesh/points", "vectorField",
         "8\n(\n(0 0 0)\n(1 0 0)\n(1 1 0)\n(0 1 0)\n(0 0 1)\n(1 0 1)\n(1 1 1)\n(0 1 1)\n)\n")
    foam("constant/polyMesh/faces", "faceList",
         "6\n(\n4(0 3 2 1)\n4(4 5 6 7)\n4(0 1 5 4)\n4(3 7 6 2)\n4(0 4 7 3)\n4(1 2 6 5)\n)\n")
    foam("constant/polyMesh/owner", "labelList", "6\n(\n0 0 0 0 0 0\n)\n")
    foam("constant/polyMesh/neighbour", "labelList", "0\n(\n)\n")
    foam("constant/polyMesh/boundary", "polyBoundaryMesh", "1\n(\nwalls\n{\n type wall;\n nFaces 6;\n startFace 0;\n}\n)\n")
    for t in times:
        entry = ("#includeEtc \"caseDicts/setConstraintTypes\"\n" if initial_directive and t == "0" else "") + \
            "walls\n{\n type fixedValue;\n value uniform (%s 0 0);\n}\n" % t
        foam(t + "/U", "volVectorField", "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (%s 0 0);\n"
             "boundaryField\n{\n%s}\n" % (t, entry))
    return str(root / "case.foam")


def test_openfoam_initial_conditions_are_a_read_option(tmp_path, capfd):
    # 0/ is skipped when a solved time exists; foam_zero_time=True (a bool, typed so) reads it.
    info = {o["name"]: o for o in flowsurf.read_option_info()}
    assert info["foam-zero-time"]["kind"] == "flag" and info["foam-zero-time"]["default"] == "false"
    case = write_cube_case(tmp_path / "plain", ["0", "1"])
    assert flowsurf.read(case).times == [1.0]
    assert flowsurf.read(case, foam_zero_time=True).times == [0.0, 1.0]
    with pytest.raises(ValueError, match="foam_zero_time"):
        flowsurf.Renderer(foam_zero_time=True)
    # 0/ as the tutorials write it: VTK 9.1 cannot parse it; asked for, it is left out by
    # name and the solved time stays.
    case = write_cube_case(tmp_path / "tutorial", ["0", "1"], initial_directive=True)
    capfd.readouterr()
    s = flowsurf.read(case, foam_zero_time=True)
    assert s.times == [1.0]
    assert "left out time directory 0" in capfd.readouterr().err
    assert np.all(s.point_array("U") == np.float32([1, 0, 0]))


def test_arrays_out_are_the_stored_arrays_read_only(tmp_path):
    pts, tris, vel, _ = sphere(8, 16)
    s = flowsurf.Surface(pts, tris, vel)
    p, t, v = s.points(), s.triangles(), s.point_array("velocity")
    assert p.dtype == np.float32 and p.shape == pts.shape and np.array_equal(p, pts.astype(np.float32))
    # The triangles the surface keeps: the poles' zero-area ones are dropped on the way in.
    assert t.dtype == np.int64 and t.shape == (s.triangle_count, 3)
    assert {tuple(r) for r in t} <= {tuple(r) for r in tris}
    assert v.shape == vel.shape and np.array_equal(v, vel.astype(np.float32))
    for a in (p, t, v):
        assert not a.flags.writeable
        with pytest.raises(ValueError):
            a[0] = 0
    assert s.point_arrays() == ["velocity"]
    # A bad name or step: a Python error naming what there is; the program goes on.
    with pytest.raises(flowsurf.FieldError, match=r"no point array 'p' \(has: velocity\)"):
        s.point_array("p")
    for step in (1, -1):
        with pytest.raises(ValueError, match="out of range \\(the surface has one step, 0\\)"):
            s.points(step=step)
    assert s.points().shape == pts.shape

    # A file's scalar (n,) and vector (n, 3), as stored (values tied to the points, which
    # the reader may order its own way).
    xy = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    (tmp_path / "quad.vtk").write_text(
        "# vtk DataFile Version 3.0\nquad\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n" +
        "".join("%g %g 0\n" % (x, y) for x, y in xy) + "POLYGONS 2 8\n3 0 1 2\n3 0 2 3\nPOINT_DATA 4\n"
        "SCALARS p float 1\nLOOKUP_TABLE default\n" + "".join("%g\n" % (x + 10 * y) for x, y in xy) +
        "VECTORS U float\n" + "".join("%g 2 %g\n" % (y, -x) for x, y in xy))
    q = flowsurf.read(str(tmp_path / "quad.vtk"))
    qp, pr, u = q.points(), q.point_array("p"), q.point_array("U")
    assert set(q.point_arrays()) == {"p", "U"}
    assert pr.shape == (4,) and u.shape == (4, 3)
    assert np.array_equal(pr, (qp[:, 0] + 10 * qp[:, 1]).astype(np.float32))
    assert np.array_equal(u, np.stack([qp[:, 1], np.full(4, 2), -qp[:, 0]], 1).astype(np.float32))

    # A series whose mesh changes (the piston, streamed): each step its own mesh.
    piston = flowsurf.read("builtin:piston")
    first, longest = piston.points(), piston.points(step=12)  # bottom dead centre
    assert first.shape == (piston.point_count, 3)
    assert len(longest) > len(first) and longest[:, 2].min() < first[:, 2].min()
    assert piston.triangles(step=12).max() == len(longest) - 1
    assert all(len(piston.point_array(n, step=12)) == len(longest) for n in piston.point_arrays(step=12))
    with pytest.raises(ValueError, match=r"step 25 is out of range \(steps 0..24\)"):
        piston.points(step=25)


def test_quality_is_the_command_lines(tmp_path):
    # Renderer.quality() and `render --quality` measure the same frame the same way.
    subprocess.run([FLOWSURF, "render", "builtin:sphere", "--size", "96x80", "--frames", "20", "-q",
                    "-o", str(tmp_path / "a.png"), "--quality", str(tmp_path / "a.json")], check=True)
    import json
    cli = json.load(open(tmp_path / "a.json"))["methods"][0]
    r = flowsurf.Renderer(size=(96, 80), frames=20)
    r.set_quality_every(1)
    r.render(flowsurf.read("builtin:sphere"))
    q = r.quality()
    assert q["frames"] == cli["frames_measured"] == 1
    assert list(q["median"]) == list(cli["median"])
    for name, value in q["median"].items():
        assert value == pytest.approx(cli["median"][name], rel=1e-9), name
    assert 0 <= q["median"]["orientation_error_deg"] < 15
    # Measuring off: the last frame on demand, no correlation without the frame before.
    r.set_quality_every(0)
    r.render(flowsurf.read("builtin:sphere"))
    q0 = r.quality()
    assert q0["median"]["frame_correlation"] is None
    assert q0["median"]["orientation_error_deg"] == pytest.approx(q["median"]["orientation_error_deg"])


# --- dye [doc/algorithms.md §10] ------------------------------------------------------------------

def red_mass(img):
    """Dye seen in the image: red above green (a red dye on the gray overlay, unlit)."""
    d = img[..., 0].astype(int) - img[..., 1].astype(int)
    return np.clip(d, 0, None).sum() / 255.0


def test_dye_keyword_and_add_dye_release_ink_that_the_flow_carries():
    pts, tris, vel, w = sphere()
    s = flowsurf.Surface(pts, tris, vel)
    look = dict(size=(128, 128), overlay="gray", lighting=False, eye=(0, 0, 5), target=(0, 0, 0),
                time_per_frame=0.05, frames=10)
    assert red_mass(flowsurf.render(s, **look)) == 0
    img = flowsurf.render(s, dye=[(-0.6, 0, 0.8), {"point": (0, 0.5, 0.85), "radius": 0.1, "color": "red"}], **look)
    assert red_mass(img) > 10
    r = flowsurf.Renderer(dye_release=1, **look)
    frames = r.frames(s, 12)
    next(frames)
    assert red_mass(r.image()) == 0
    r.add_dye((0, 0, 1), radius=0.15, color="red")  # dropped into a running animation
    next(frames)
    first = r.image()
    assert red_mass(first) > 10
    for _ in range(8):
        last = next(frames)
    ys, xs = np.nonzero(first[..., 0].astype(int) - first[..., 1] > 60)
    ys2, xs2 = np.nonzero(last[..., 0].astype(int) - last[..., 1] > 60)
    assert xs2.mean() > xs.mean() + 5  # w ~ +y: the front of the sphere moves to +x
    assert r.get("dye").startswith("0,0,1:0.15:#")
    with pytest.raises(ValueError, match="add_dye"):
        r.add_dye((0, 0, 1), radius=-1)
    with pytest.raises(ValueError, match="dye"):
        flowsurf.Renderer(dye="1,2")


def test_topology_as_the_command_line_with_the_sign_rule():
    # The tori's vertical field: sources and sinks, swapped when the field is reversed.
    s = flowsurf.read("builtin:tori")
    t = flowsurf.topology(s)
    k = len(t["types"])
    assert k > 0 and t["positions"].shape == (k, 3) and t["positions"].dtype == np.float32
    assert t["index"].shape == (k,) and t["index"].dtype == np.int64
    assert set(t["types"]) <= {"source", "sink", "saddle", "center", "repelling_focus", "attracting_focus"}
    assert all(line["kind"] in ("separation", "attachment") and line["points"].shape[1] == 3 for line in t["lines"])
    assert t["euler_characteristic"] == 0 and t["index_sum"] == 0 and t["closed"]
    r = flowsurf.topology(s, reverse_field="on")
    assert r["field_reversed"] and sorted(r["types"]) == sorted(
        {"source": "sink", "sink": "source"}.get(x, x) for x in t["types"])
    # OpenFOAM's wallShearStress is shown reversed by default; the arrays stay as stored.
    pts, tris = s.points(), s.triangles()
    wss = flowsurf.Surface(pts, tris, s.point_array("velocity"), field="wallShearStress")
    w = flowsurf.topology(wss)
    assert w["field_reversed"] and sorted(w["types"]) == sorted(r["types"])
    assert np.array_equal(wss.point_array("wallShearStress"), s.point_array("velocity"))
    with pytest.raises(ValueError, match="topology_scale|unknown keyword"):
        flowsurf.topology(s, no_such_option=1)
    with pytest.raises(ValueError, match="topology-cancel-speed"):
        flowsurf.topology(s, topology_cancel_speed=2)
    with pytest.raises(ValueError, match="step"):
        flowsurf.topology(s, step=4)


def test_skin_friction_is_derived_while_reading():
    """field="skin-friction" reaches the reader: the wall stress of the shipped laminar cavity
    (tests/unit/data), beside the stored fields; the viscosity keyword is a read option."""
    case = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "unit", "data",
                        "openfoam_cavity_laminar", "case.foam")
    s = flowsurf.read(case, field="skin-friction")
    assert s.field == "skin-friction"
    assert {"skin-friction", "U", "wallShearStress"} <= set(s.fields)
    assert "skin-friction" not in flowsurf.read(case).fields
    assert flowsurf.read(case, field="skin-friction", viscosity=0.02).field == "skin-friction"
    with pytest.raises(ValueError, match="skin-friction"):
        flowsurf.read("builtin:sphere", field="skin-friction")


@pytest.mark.skipif(not os.environ.get("FLOWSURF_MAKE_CGNS"), reason="FLOWSURF_MAKE_CGNS not set")
def test_skin_friction_of_a_cgns_volume_is_a_point_array(tmp_path):
    """A CGNS volume result (tests/cgns: a linear shear u = (2y, 0, 0) between a floor at rest
    and a roof moving with the fluid): point_array("skin-friction") is nu * 2 along x on the
    floor and its opposite on the roof, one row per point."""
    subprocess.run([os.environ["FLOWSURF_MAKE_CGNS"], str(tmp_path)], check=True)
    s = flowsurf.read(str(tmp_path / "couette.cgns"), field="skin-friction", viscosity=0.5)
    tau, y = s.point_array("skin-friction"), s.points()[:, 1]
    assert tau.shape == (len(y), 3)
    floor, roof = np.abs(y) < 1e-6, np.abs(y - 1) < 1e-6
    assert floor.sum() == 15 and roof.sum() == 15 and (floor | roof).all()
    assert np.allclose(tau[floor], [1.0, 0, 0], atol=1e-5)
    assert np.allclose(tau[roof], [-1.0, 0, 0], atol=1e-5)
    with pytest.raises(Exception, match="couette_novelocity.cgns"):
        flowsurf.read(str(tmp_path / "couette_novelocity.cgns"), field="skin-friction")
