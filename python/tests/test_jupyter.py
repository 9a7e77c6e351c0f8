"""flowsurf in Jupyter, kernel side, as a notebook drives it: an Animation that plays inline
(MP4, or an animated PNG), and the Player's frame stream — play, seek, a parameter and a
camera change each change the picture the page is sent; seeking back shows the same frame."""
import shutil
import struct
import zlib

import numpy as np
import pytest

import flowsurf

SIZE = (96, 72)


def png_pixels(data):
    """(H, W, 3) of the 8-bit RGB PNGs flowsurf.to_png writes (filter type 0 on every row)."""
    pos, idat, w, h = 8, b"", 0, 0
    while pos < len(data):
        n, = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h = struct.unpack(">II", body[:8])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    rows = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(h, 1 + 3 * w)
    assert (rows[:, 0] == 0).all()
    return rows[:, 1:].reshape(h, w, 3).astype(float)


def differs(a, b):
    """Mean absolute difference of two PNGs in gray levels."""
    return float(np.abs(png_pixels(a) - png_pixels(b)).mean())


@pytest.fixture(scope="module")
def sphere():
    return flowsurf.read("builtin:sphere")


def test_animation_from_renderer_frames_plays_inline(sphere):
    r = flowsurf.Renderer(method="isa", size=SIZE)
    anim = flowsurf.Animation(r.frames(sphere, n=8), fps=12)
    assert len(anim) == 8 and anim[0].shape == (SIZE[1], SIZE[0], 3)
    html = anim._repr_html_()
    if shutil.which("ffmpeg"):
        assert html.startswith("<video controls") and "data:video/mp4;base64," in html
        assert anim.to_mp4()[4:8] == b"ftyp"
    else:
        assert html.startswith("<img")
    # The fallback: an animated PNG with one frame control per frame.
    apng = anim.to_apng()
    assert apng[:8] == b"\x89PNG\r\n\x1a\n" and b"acTL" in apng and apng.count(b"fcTL") == 8
    assert "8 frames" in repr(anim)


def test_animate_one_line(sphere):
    anim = flowsurf.animate(sphere, frames=5, method="hybrid", size=SIZE, format="png")
    assert anim._repr_html_().startswith('<img src="data:image/png;base64,')
    assert not np.array_equal(anim[0], anim[4])   # it moves
    with pytest.raises(ValueError, match="alpha"):
        flowsurf.animate(sphere, frames=2, alpha=7)


def test_player_stream_follows_play_seek_and_parameters(sphere):
    pytest.importorskip("ipywidgets")
    p = flowsurf.Player(sphere, frames=30, size=SIZE, method="isa")
    first = p.image.value
    assert png_pixels(first).shape == (SIZE[1], SIZE[0], 3)
    # Play: the Play widget's ticks move the frame slider (linked in the kernel) and the image.
    p.play.value = 6
    assert p.frame.value == 6
    at6 = p.image.value
    assert differs(first, at6) > 1.0
    # Seek back: the same frame as before, from the kept frames; forward again: a new one.
    p.frame.value = 2
    at2 = p.image.value
    assert differs(at2, at6) > 1.0
    p.frame.value = 6
    assert p.image.value == at6
    # A parameter: the method and a slider; the frame is rendered again with it.
    p.controls["method"].value = "hybrid"
    assert p.renderer.get("method") == "hybrid" and p.frame.value == 6
    hybrid = p.image.value
    assert differs(hybrid, at6) > 1.0
    assert [c.description for c in p._params_box.children] == ["filter-length", "lic-step-px", "noise-scale"]
    p.controls["filter-length"].value = 81
    assert p.renderer.get("filter_length") == "81" and differs(p.image.value, hybrid) > 0.5
    # The camera: azimuth turns the view (the surface moves on the screen).
    before = p.image.value
    p.azimuth.value = 60
    assert differs(p.image.value, before) > 1.0
    assert p.renderer.camera["eye"] != pytest.approx(p._base[0])
    # Dye: a source shows up in the next frame.
    before = p.image.value
    p.add_dye("0,0,1", radius=0.2, color="red")
    assert differs(p.image.value, before) > 0.2
    assert "frame" in p.status.value


def test_player_refuses_bad_options(sphere):
    pytest.importorskip("ipywidgets")
    with pytest.raises(ValueError, match="step_px"):
        flowsurf.Player(sphere, size=SIZE, step_px=-1)
