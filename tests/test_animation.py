"""The animation frame renderer (export/animation.py) and the animation of every part type."""

from __future__ import annotations

import math

import numpy as np
import pytest
from PIL import Image

from propulsor.export.animation import Animation, Mark, Shape, Trace, encode_gif, render_frames, spell, write_animation


def _gear(z: int, r: float) -> np.ndarray:
    t = np.linspace(0.0, 2 * math.pi, 40 * z, endpoint=False)
    rr = r + 0.08 * r * np.sign(np.sin(z * t))
    return np.column_stack([rr * np.cos(t), rr * np.sin(t)])


def _anim(n: int = 12, keep=()) -> Animation:
    from propulsor.checks.motion import rotation_matrices

    a = np.linspace(0.0, 2 * math.pi / 20, n, endpoint=False)
    bore = np.column_stack([8 * np.cos(np.linspace(0, 2 * math.pi, 60)), 8 * np.sin(np.linspace(0, 2 * math.pi, 60))])[::-1]
    shapes = [Shape((_gear(20, 50.0), bore), "blue", rotation_matrices(a)),
              Shape((_gear(10, 25.0),), "orange", rotation_matrices(-2 * a, np.tile([78.0, 0.0], (n, 1)))),
              Shape((np.array([[-60.0, -60.0], [110.0, -60.0]]),), "ink", None, closed=False)]
    x = np.linspace(0.0, 1.0, 50)
    tr = Trace("U", x, np.sin(6 * x), np.linspace(0, 49, n).astype(int), x_label="φ, deg")
    return Animation("synthetic pair θ, φ", shapes, n, [[f"frame {k}", "!least 0.1 mm"] for k in range(n)],
                     [[Mark((50.0, 0.0), "0.123 mm")] if k == 3 else [] for k in range(n)], [tr], width_px=520,
                     keep=keep)


def test_same_input_same_bytes(tmp_path):
    a, b = write_animation(_anim(), tmp_path / "a.gif"), write_animation(_anim(), tmp_path / "b.gif")
    assert (tmp_path / "a.gif").read_bytes() == (tmp_path / "b.gif").read_bytes()
    assert a.bytes == b.bytes == (tmp_path / "a.gif").stat().st_size and a.frames == tuple(range(12))
    with Image.open(tmp_path / "a.gif") as im:
        assert im.n_frames == 12 and im.size == (a.width_px, a.height_px) == (520, a.height_px)
        im.seek(3)
        assert im.info["duration"] == 60
        # the frame decodes to what was drawn: the fixed palette, no quantisation
        assert im.convert("RGB").tobytes() == render_frames(_anim())[3].convert("RGB").tobytes()


def test_the_mechanism_is_inside_the_picture_and_moves():
    frames = render_frames(_anim())
    W, H = frames[0].size
    for im in frames:
        px = np.asarray(im)
        # the blue gear's fill (palette index of blue_fill) is drawn, and never touches the border
        from propulsor.export.animation import _INDEX

        ys, xs = np.nonzero(px == _INDEX["blue_fill"])
        assert len(xs) > 1000 and xs.min() > 0 and ys.min() > 0 and xs.max() < W - 1
    assert not np.array_equal(np.asarray(frames[0]), np.asarray(frames[1]))


def test_too_large_a_gif_is_thinned_keeping_the_marked_frame(tmp_path):
    full = len(encode_gif(render_frames(_anim()), 60))
    info = write_animation(_anim(keep=(3,)), tmp_path / "t.gif", max_bytes=int(0.7 * full))
    assert info.bytes <= 0.7 * full and 3 in info.frames and len(info.frames) < 12
    with Image.open(tmp_path / "t.gif") as im:
        assert im.n_frames == len(info.frames)


def test_text_in_the_default_font():
    assert spell("φ = 3°, θ ≥ β, 2 mm²") == "phi = 3°, theta >= beta, 2 mm^2"


def test_every_part_type_animates_its_motion():
    """Every registered part type's build starts its animations once its proof is there and records
    them (GIF, frame table, manifest media entry) before the writer finishes; the part tests check
    what each one writes."""
    from propulsor.parts import get_part_type, part_type_names

    for name in part_type_names():
        steps = [getattr(s, "__name__", "") for s in get_part_type(name).build.steps]
        assert "start_animations" in steps and steps[-1] == "collect_animations", (name, steps)
        assert steps.index("start_animations") < steps.index("collect_animations")


def test_the_frames_font_draws_a_string_again_from_its_first_bitmap_pixel_for_pixel():
    """The frames' font remembers each string's bitmap: drawn twice it is the very bitmap of the first time, and
    every string it draws (again or not) is pixel for pixel what a fresh font draws."""
    from PIL import ImageDraw, ImageFont

    from propulsor.export import animation as an

    font = an._font()
    assert an._font() is font
    fresh = ImageFont.load_default(size=an.FONT_SIZE)
    words = ["hub height 320.0000 mm", "0.100 mm", "phi, deg (grey: exact law)", "hub height 320.0000 mm",
             "least clearance 0.1407 mm (mesh_planet3_ring, psi = 65.0°)", "0.100 mm"]
    for f_a, f_b in ((font, fresh),):
        a, b = Image.new("P", (400, 20 * len(words)), 0), Image.new("P", (400, 20 * len(words)), 0)
        for im, f in ((a, f_a), (b, f_b)):
            d = ImageDraw.Draw(im)
            d.fontmode = "1"
            for k, w in enumerate(words):
                d.text((3.0 + 0.5 * (k % 2), 2.0 + 20 * k), w, fill=5, font=f)  # half-pixel starts too
        assert a.tobytes() == b.tobytes()
        assert np.count_nonzero(np.asarray(a)) > 500  # text was drawn
    m1 = font.getmask2("0.100 mm", "1")
    assert font.getmask2("0.100 mm", "1") is m1 and fresh.getmask2("0.100 mm", "1") is not m1


def _drawn(text: str, xy, ours: bool) -> bytes:
    from PIL import ImageDraw

    from propulsor.export import animation as A

    im = Image.new("P", (640, 48), 0)
    im.putpalette(A._PAL_BYTES)
    d = ImageDraw.Draw(im)
    d.fontmode = "1"
    if ours:
        A._put_text(im, d, xy, text, 4, A._font())
    else:
        d.text(xy, text, fill=4, font=A._font())
    return im.tobytes()


def test_the_frames_text_is_pillows_pixel_for_pixel():
    """Captions are set from each character's bitmap (export/animation.py, _put_text): the same pixels as Pillow's own
    rendering of the line, for every pair of its characters (printable ASCII, "°", "…"; a negative bearing, "/" or "x",
    first or after another), long random lines partly outside the image, and what Pillow leaves undrawn (underscores
    and spaces)."""
    import random

    from propulsor.export import animation as A

    font = A._font()
    chars = sorted(A._GLYPH_CHARS)
    # what the characters' own bitmaps rely on: whole pixel advances and no kerned pair
    adv = {c: font.getlength(c, "1") for c in chars}
    assert all(a == int(a) for a in adv.values())
    assert all(font.getlength(a + b, "1") == adv[a] + adv[b] for a in chars for b in chars)
    assert any(A._glyphs()[c][3] < 0 for c in chars)  # a negative bearing is among them
    for a in chars:
        line = "".join(a + b for b in chars)  # every pair (a, b) and (b, a) side by side
        assert _drawn(line, (3, 20), True) == _drawn(line, (3, 20), False), line
    for a in chars:
        for b in "/x\\ _":
            assert _drawn(a + b, (10, 10), True) == _drawn(a + b, (10, 10), False), a + b
            assert _drawn(b + a, (10, 10), True) == _drawn(b + a, (10, 10), False), b + a
    rng = random.Random(7)
    for _ in range(200):
        line = "".join(rng.choice(chars) for _ in range(rng.randint(1, 120)))
        xy = (rng.randint(-40, 600), rng.randint(-12, 44))
        assert _drawn(line, xy, True) == _drawn(line, xy, False), (line, xy)
    for line in ("_ ", " _", "__ ", "a_ ", "x", "/l", "φ = 1", "-"):
        assert _drawn(line, (10, 10), True) == _drawn(line, (10, 10), False), line
    assert _drawn("a/l", (10.5, 10), True) == _drawn("a/l", (10.5, 10), False)  # off the pixel grid: Pillow's
    # a line drawn again elsewhere is set from the mask of its first drawing, moved: still Pillow's pixels
    for line in ("x/0.100 mm", "phi, deg (grey: exact law)", "/a"):
        for xy in ((3, 20), (250, 7), (-4, 40), (600, -3), (3, 20)):
            assert _drawn(line, xy, True) == _drawn(line, xy, False), (line, xy)
    assert A._text_mask("x/0.100 mm") is A._text_mask("x/0.100 mm")


def test_the_captions_lengths_are_pillows():
    """A caption's width for its wrapping (export/animation.py, _length): the sum of its characters' advances, Pillow's
    getlength of the whole line for every pair of its characters (printable ASCII, "°", "…") and random lines; other
    text is Pillow's."""
    import random

    from propulsor.export import animation as A

    font = A._font()
    chars = sorted(A._GLYPH_CHARS)
    assert all(font.getlength(a + b) == A._length(a + b, font) for a in chars for b in chars)
    rng = random.Random(3)
    for _ in range(300):
        line = "".join(rng.choice(chars) for _ in range(rng.randint(0, 150)))
        assert A._length(line, font) == font.getlength(line), line
    assert A._length("3 mm²°", font) == font.getlength("3 mm²°")
    # the wrapped lines: each within the width, the words in order
    text = " ".join(f"word{k} {k * 1.2345:.4f} mm" for k in range(30))
    lines = A._wrap(text, font, 300)
    assert " ".join(lines) == text and len(lines) > 3 and all(font.getlength(q) <= 300 for q in lines)
