"""Animated GIFs of a mechanism's proven motion: the generic frame renderer (export layer).

A part hands over what to draw, already computed: rigid shapes (closed outlines or open polylines
in their body frames, mm) with one pose per frame (the poses its proof evaluated), markers and
captions per frame, and traces (a curve over the frames with the current pose marked).  This module
only draws them: world (mm, y up) -> pixel transform fitted to everything drawn over all frames
(centred, never clipped), polygons and polylines with ``PIL.ImageDraw`` on palette images, text
in PIL's default font, GIF encoding.  It computes no engineering value.

Deterministic: one fixed palette (no quantisation), frames drawn in the order given, no time
stamps; the same input gives the same bytes.  A GIF larger than ``max_bytes`` is encoded again
with every second frame (the frames named ``keep`` always stay) until it fits; the frames kept are
returned, so that the part can say which poses the file shows.
"""

from __future__ import annotations

import functools
import io
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

import numpy as np

from ..planar import box
from ..write_root import prepare

__all__ = ["PALETTE", "Shape", "Mark", "Trace", "Animation", "GifInfo", "render_frames", "encode_gif",
           "write_animation", "spell"]

#: the fixed palette: name -> RGB; a body colour has an edge (its name) and a fill (``<name>_fill``)
PALETTE: tuple = (
    ("bg", (255, 255, 255)), ("ink", (0, 0, 0)), ("grey", (120, 120, 120)), ("lightgrey", (222, 222, 222)),
    ("red", (220, 0, 0)),
    ("blue", (30, 90, 170)), ("blue_fill", (163, 196, 235)),
    ("orange", (195, 95, 0)), ("orange_fill", (250, 200, 140)),
    ("green", (30, 125, 50)), ("green_fill", (170, 220, 170)),
    ("purple", (105, 60, 160)), ("purple_fill", (208, 188, 232)),
    ("brown", (125, 78, 40)), ("brown_fill", (218, 192, 160)),
    ("teal", (0, 118, 130)), ("teal_fill", (160, 215, 222)),
    ("olive", (125, 118, 0)), ("olive_fill", (232, 226, 150)),
    ("steel", (75, 78, 90)), ("steel_fill", (192, 194, 204)),
    ("rubber", (25, 25, 25)), ("rubber_fill", (80, 80, 80)),
)
_INDEX = {name: k for k, (name, _) in enumerate(PALETTE)}
_PAL_BYTES = [c for _, rgb in PALETTE for c in rgb] + [0] * (768 - 3 * len(PALETTE))

HEADER_PX = 18   # one title line
LINE_PX = 14     # one caption line
FONT_SIZE = 11


#: characters PIL's default font lacks, written out (the frames' text only)
_SPELL = {"φ": "phi", "θ": "theta", "ω": "omega", "β": "beta", "ψ": "psi", "Δ": "Delta", "ε": "eps", "σ": "sigma",
          "λ": "lambda", "α": "alpha", "ρ": "rho", "²": "^2", "³": "^3", "×": "x", "≥": ">=", "≤": "<=", "–": "-",
          "—": "-", "−": "-", "≈": "~"}
_SPELL_TABLE = str.maketrans(_SPELL)


def spell(text: str) -> str:
    """``text`` in the characters PIL's default font draws (Greek letters written out)."""
    return text.translate(_SPELL_TABLE)


def _ci(name: str) -> int:
    if name not in _INDEX:
        raise ValueError(f"colour {name!r} is not in the palette ({', '.join(_INDEX)})")
    return _INDEX[name]


@dataclass(frozen=True)
class Shape:
    """A rigid body drawn in every frame.

    ``loops``: polylines in the body frame (mm); closed outlines (the first the outer boundary, the
    others holes, filled with the background) or, with ``closed = False``, open lines.  ``poses``:
    (frames, 2, 3) affine matrices body -> world, one per frame; None: the body stands still (its
    loops are world coordinates).  ``colour``: a palette name; a closed shape is filled with its
    ``_fill`` variant unless ``fill`` is False."""

    loops: tuple
    colour: str
    poses: np.ndarray | None = None
    fill: bool = True
    closed: bool = True
    width: int = 1


@dataclass(frozen=True)
class Mark:
    """A red (or other) marker in one frame at a world point, with an optional label beside it."""

    xy: tuple
    text: str = ""
    colour: str = "red"
    radius_px: int = 6


@dataclass(frozen=True)
class Trace:
    """A curve y(x) beside the mechanism, drawn up to the current frame's point ``index[frame]``
    (a moving marker on it); the whole curve faint behind; ``ref`` an optional reference curve
    (x, y) drawn dashed-grey."""

    label: str
    x: np.ndarray
    y: np.ndarray
    index: np.ndarray
    colour: str = "blue"
    x_label: str = ""
    fmt: str = "{:.4g}"
    ref: tuple | None = None


@dataclass(frozen=True)
class Animation:
    title: str
    shapes: Sequence[Shape]
    n_frames: int
    captions: Sequence[Sequence[str]] = ()   # per frame: lines written under the picture
    marks: Sequence[Sequence[Mark]] = ()     # per frame
    traces: Sequence[Trace] = ()
    width_px: int = 600
    frame_ms: int = 60
    keep: tuple = ()                         # frames never dropped to meet the size limit
    aspect_range: tuple = (0.55, 1.0)        # mechanism panel height / width, clamped
    margin_px: int = 8


@dataclass(frozen=True)
class GifInfo:
    path: str
    frames: tuple        # indices (into the animation's frames) of the frames written
    width_px: int
    height_px: int
    bytes: int
    frame_ms: int


# --------------------------------------------------------------------------------------------------
def _world(shape: Shape, k: int) -> list:
    if shape.poses is None:
        return [np.asarray(q, float) for q in shape.loops]
    M = shape.poses[k]
    return [np.asarray(q, float) @ M[:, :2].T + M[:, 2] for q in shape.loops]


def _hull(points: np.ndarray) -> np.ndarray:
    """The convex hull's vertices of a point set (all of them when too few or degenerate)."""
    from scipy.spatial import ConvexHull, QhullError

    if len(points) < 4:
        return points
    try:
        return points[ConvexHull(points).vertices]
    except QhullError:
        return points


def _static(shape: Shape) -> bool:
    return shape.poses is None or bool(np.all(shape.poses == shape.poses[0]))


def _bounds(anim: Animation) -> np.ndarray:
    """World box holding every shape in every frame (and every marker)."""
    lo, hi = np.full(2, np.inf), np.full(2, -np.inf)
    for s in anim.shapes:
        pts = [np.asarray(q, float) for q in s.loops if len(q)]
        if not pts:
            continue
        H = _hull(np.vstack(pts))
        if s.poses is None:
            W = H
        else:
            M = np.asarray(s.poses, float)
            W = (np.einsum("kij,pj->kpi", M[:, :, :2], H) + M[:, None, :, 2]).reshape(-1, 2)
        w_lo, w_hi = box(W)
        lo, hi = np.minimum(lo, w_lo), np.maximum(hi, w_hi)
    for fm in anim.marks:
        for m in fm:
            lo, hi = np.minimum(lo, m.xy), np.maximum(hi, m.xy)
    if not np.all(np.isfinite(lo)):
        lo, hi = np.zeros(2), np.ones(2)
    span = np.maximum(hi - lo, 1e-9)
    return np.array([lo - 0.02 * span, hi + 0.02 * span])


@dataclass(frozen=True)
class _View:
    """World (mm, y up) -> pixels of a box (x0, y0, w, h): uniform scale, centred."""

    scale: float
    cx: float
    cy: float
    px: float
    py: float

    @staticmethod
    def fit(bounds: np.ndarray, box: tuple) -> "_View":
        (x0, y0), (x1, y1) = bounds
        bx, by, bw, bh = box
        s = min(bw / (x1 - x0), bh / (y1 - y0))
        return _View(s, 0.5 * (x0 + x1), 0.5 * (y0 + y1), bx + 0.5 * bw, by + 0.5 * bh)

    def px_of(self, q: np.ndarray) -> np.ndarray:
        P = np.empty_like(q)
        P[:, 0] = self.px + (q[:, 0] - self.cx) * self.scale
        P[:, 1] = self.py - (q[:, 1] - self.cy) * self.scale
        return P


def _flat(P: np.ndarray) -> list:
    """Pixel polyline as PIL wants it, consecutive repeated pixels dropped."""
    Q = np.rint(P).astype(np.int64)
    if len(Q) > 2:
        keep = np.ones(len(Q), bool)
        keep[1:] = (Q[1:, 0] != Q[:-1, 0]) | (Q[1:, 1] != Q[:-1, 1])  # np.any(.., axis=1), without its reduction
        Q = Q[keep]
    return Q.ravel().tolist()


#: distinct strings whose bitmaps the frames' font keeps (captions carry numbers: a long-lived process, a study's
#: worker, would otherwise keep every one it ever drew)
FONT_MASKS_KEPT = 4096


@functools.lru_cache(maxsize=None)
def _font():
    """The frames' font (Pillow's default at FONT_SIZE), made once per process, its rendered text remembered: the
    same string drawn again (a caption or a scale label on every frame) takes the bitmap Pillow made the first
    time, pixel for pixel the same (``getmask2`` depends on its arguments alone)."""
    from PIL import ImageFont

    font = ImageFont.load_default(size=FONT_SIZE)
    render = font.getmask2
    kept = functools.lru_cache(maxsize=FONT_MASKS_KEPT)(lambda text, args, kwargs: render(text, *args, **dict(kwargs)))

    def getmask2(text, *args, **kwargs):
        try:
            return kept(text, args, tuple(sorted(kwargs.items())))
        except TypeError:  # an argument that is no key (a list of features): drawn afresh
            return render(text, *args, **kwargs)

    font.getmask2 = getmask2
    return font


#: the characters :func:`_put_text` sets from their own bitmaps: printable ASCII and the two others the captions use,
#: the degree sign and the ellipsis (in the frames' font each has a whole pixel advance, and no pair of them is kerned:
#: ``tests/test_animation.py`` holds both)
_GLYPH_CHARS = frozenset([chr(c) for c in range(32, 127)] + ["°", "…"])


@functools.lru_cache(maxsize=None)
def _glyphs() -> dict:
    """char -> (x, y of its set pixels from the pen position at the line's top, its advance in pixels, its left bearing
    if negative else 0) in the frames' font as Pillow draws it in mode "1" (each character drawn once on its own)."""
    from PIL import Image, ImageDraw

    font, out = _font(), {}
    pad = 2 * FONT_SIZE
    for c in sorted(_GLYPH_CHARS):
        im = Image.new("L", (4 * pad, 4 * pad), 0)
        d = ImageDraw.Draw(im)
        d.fontmode = "1"
        d.text((pad, pad), c, fill=255, font=font)
        ys, xs = np.nonzero(np.asarray(im))
        xs = xs - pad
        out[c] = (xs, ys - pad, int(font.getlength(c, "1")), min(int(xs.min()), 0) if len(xs) else 0)
    return out


def _put_text(im, d, xy, text: str, colour: int, font) -> None:
    """``d.text(xy, text, fill=colour, font=font)`` on the palette image ``im`` (drawn on by ``d``, fontmode "1"),
    the same pixels: a line at a whole pixel position is set from each character's bitmap at its pen position (Pillow
    renders every character of the line anew, about 20 us each; a caption changes from frame to frame), the line's
    mask made once for every place it is drawn at (:func:`_text_mask`); anything else is left to Pillow."""
    x, y = xy
    chars = set(text)
    # a line of underscores and spaces alone Pillow leaves undrawn (where it has spaces): left to Pillow
    if not (float(x).is_integer() and float(y).is_integer() and d.fontmode == "1" and chars <= _GLYPH_CHARS
            and not chars <= {" ", "_"}):
        d.text(xy, text, fill=colour, font=font)
        return
    got = _text_mask(text)
    if got is None:
        return
    ox, oy, mask = got
    x0, y0 = int(x) + ox, int(y) + oy
    im.paste(colour, (x0, y0, x0 + mask.width, y0 + mask.height), mask)


@functools.lru_cache(maxsize=FONT_MASKS_KEPT)
def _text_mask(text: str):
    """The mask of a line of :data:`_GLYPH_CHARS` set from each character's bitmap as Pillow places them, and where
    it lies from the line's whole-pixel start: (x, y of its top left pixel from there, the "L" mask), None where
    nothing is drawn.  A character whose bitmap starts left of its pen position (a negative bearing: "/", "x") is
    drawn from the pen position on, and the line is shifted by the first character's negative bearing.  The same
    line at another place is the same mask moved: a scale label or an axis name drawn on every frame is set from the
    mask of its first (the draws of seven part files' animations 1.51 -> 1.38 CPU s, bench/bench_animation.py); as
    many lines kept as the font's own bitmaps (a study's long-lived worker would otherwise keep every caption)."""
    from PIL import Image

    g = _glyphs()
    xs, ys, pen = [], [], g[text[0]][3] if text else 0
    for c in text:
        gx, gy, adv, bearing = g[c]
        if len(gx):
            xs.append(gx + (pen - bearing))
            ys.append(gy)
        pen += adv
    if not xs:
        return None
    X, Y = np.concatenate(xs), np.concatenate(ys)
    x0, y0 = int(X.min()), int(Y.min())
    mask = np.zeros((int(Y.max()) - y0 + 1, int(X.max()) - x0 + 1), np.uint8)
    mask[Y - y0, X - x0] = 255
    return x0, y0, Image.fromarray(mask, "L")


@functools.lru_cache(maxsize=None)
def _advances() -> dict:
    """char -> its advance in pixels in the frames' font (``getlength``, Pillow's default mode), the characters of
    :data:`_GLYPH_CHARS` (whole pixels, no pair kerned: ``tests/test_animation.py``)."""
    font = _font()
    return {c: font.getlength(c) for c in _GLYPH_CHARS}


def _length(text: str, font) -> float:
    """``font.getlength(text)`` in the frames' font: the sum of the characters' advances where every one is of
    :data:`_GLYPH_CHARS` (the same number; Pillow lays the whole line out again, 0.3 ms for a caption line), else
    Pillow's."""
    adv = _advances()
    try:
        return float(sum(adv[c] for c in text))
    except KeyError:
        return font.getlength(text)


def _wrap(text: str, font, width: float) -> list:
    """``text`` (already spelled) broken at spaces into lines at most ``width`` pixels long (word widths
    summed with the space's: within a pixel or two of the drawn line, 4 px kept spare)."""
    def length(word: str) -> float:
        return _length(word, font)

    if _length(text, font) <= width:
        return [text]
    space = length(" ")
    lines, cur, cur_w = [], [], 0.0
    for wd in text.split(" "):
        w = length(wd)
        if cur and cur_w + space + w > width - 4:
            lines.append(" ".join(cur))
            cur, cur_w = [wd], w
        else:
            cur_w = cur_w + space + w if cur else w
            cur.append(wd)
    return lines + [" ".join(cur)]


def _layout(anim: Animation, font) -> tuple:
    """(width, height, header lines, mechanism box, trace boxes, view, captions wrapped per frame)."""
    W = int(anim.width_px)
    m = anim.margin_px
    head = _wrap(spell(anim.title), font, W - 2 * m)
    captions = []
    for caps in anim.captions:
        wrapped = []
        for line in caps:
            red = line.startswith("!")
            wrapped += [("!" if red else "") + q for q in _wrap(spell(line.lstrip("!")), font, W - 2 * m)]
        captions.append(wrapped)
    n_cap = max((len(c) for c in captions), default=0)
    top = HEADER_PX * len(head)
    trace_w = int(round(0.36 * W)) if anim.traces else 0
    mech_w = W - trace_w - 2 * m
    b = _bounds(anim)
    aspect = float((b[1, 1] - b[0, 1]) / (b[1, 0] - b[0, 0]))
    lo, hi = anim.aspect_range
    mech_h = int(round(mech_w * min(max(aspect, lo), hi)))
    if anim.traces:  # room for the traces: at least 110 px each
        mech_h = max(mech_h, 110 * len(anim.traces))
    H = top + mech_h + n_cap * LINE_PX + 2 * m
    H += H % 2
    box = (m, top + m, mech_w, mech_h)
    view = _View.fit(b, box)
    tboxes = []
    if anim.traces:
        n = len(anim.traces)
        th = mech_h // n
        for j in range(n):
            tboxes.append((W - trace_w + 44, top + m + j * th + 14, trace_w - 44 - m, th - 34))
    return W, H, head, box, tboxes, view, captions


def _draw_trace(im, d, font, tr: Trace, box: tuple, k: int) -> None:
    bx, by, bw, bh = box
    xs = [np.asarray(tr.x, float)] + ([np.asarray(tr.ref[0], float)] if tr.ref else [])
    ys = [np.asarray(tr.y, float)] + ([np.asarray(tr.ref[1], float)] if tr.ref else [])
    x0, x1 = min(float(np.min(x)) for x in xs), max(float(np.max(x)) for x in xs)
    y0, y1 = min(float(np.min(y)) for y in ys), max(float(np.max(y)) for y in ys)
    if y1 - y0 < 1e-12 * max(1.0, abs(y1)):
        y0, y1 = y0 - 0.5 * max(abs(y0), 1.0) * 1e-3, y1 + 0.5 * max(abs(y1), 1.0) * 1e-3
    pad = 0.06 * (y1 - y0)
    y0, y1 = y0 - pad, y1 + pad
    if x1 <= x0:
        x1 = x0 + 1.0

    def P(x, y):
        return np.column_stack([bx + (np.asarray(x) - x0) / (x1 - x0) * bw, by + bh - (np.asarray(y) - y0) / (y1 - y0) * bh])

    d.rectangle([bx, by, bx + bw, by + bh], outline=_ci("grey"))
    if tr.ref:
        d.line(_flat(P(*tr.ref)), fill=_ci("grey"), width=1)
    d.line(_flat(P(tr.x, tr.y)), fill=_ci("lightgrey"), width=1)
    i = int(tr.index[k])
    if i >= 1:
        d.line(_flat(P(tr.x[:i + 1], tr.y[:i + 1])), fill=_ci(tr.colour), width=2)
    cx, cy = P([tr.x[i]], [tr.y[i]])[0]
    d.ellipse([cx - 4, cy - 4, cx + 4, cy + 4], fill=_ci("red"), outline=_ci("ink"))
    _put_text(im, d, (bx, by - 13), spell(f"{tr.label} = {tr.fmt.format(float(tr.y[i]))}"), _ci("ink"), font)
    for val, yy in ((y1, by - 5), (y0, by + bh - 7)):
        txt = tr.fmt.format(val)
        _put_text(im, d, (bx - 3 - d.textlength(txt, font=font), yy), txt, _ci("grey"), font)
    if tr.x_label:
        _put_text(im, d, (bx, by + bh + 2), spell(tr.x_label), _ci("grey"), font)


def _draw_shape(d, s: Shape, loops: list, bg: int) -> None:
    edge = _ci(s.colour)
    if not s.closed:
        for L in loops:
            if len(L) >= 4:
                d.line(L, fill=edge, width=s.width)
        return
    for j, L in enumerate(loops):
        if len(L) < 6:
            continue
        fill = (_ci(s.colour + "_fill") if j == 0 else bg) if s.fill else None
        d.polygon(L, fill=fill, outline=edge, width=s.width)


def render_frames(anim: Animation) -> list:
    """The frames as palette images (PIL), in order."""
    from PIL import Image, ImageDraw

    font = _font()
    W, H, head, box, tboxes, view, captions = _layout(anim, font)
    base = Image.new("P", (W, H), _ci("bg"))
    base.putpalette(_PAL_BYTES)
    d0 = ImageDraw.Draw(base)
    d0.fontmode = "1"
    for j, line in enumerate(head):
        _put_text(base, d0, (anim.margin_px, 3 + j * HEADER_PX), line, _ci("ink"), font)
    bg = _ci("bg")
    # shapes that stand still: their pixel polylines once; those below every moving one drawn once
    still = {id(s): [_flat(view.px_of(q)) for q in _world(s, 0)] for s in anim.shapes if _static(s)}
    n_under = 0
    while n_under < len(anim.shapes) and _static(anim.shapes[n_under]):
        _draw_shape(d0, anim.shapes[n_under], still[id(anim.shapes[n_under])], bg)
        n_under += 1
    frames = []
    for k in range(anim.n_frames):
        im = base.copy()
        d = ImageDraw.Draw(im)
        d.fontmode = "1"
        for s in anim.shapes[n_under:]:
            loops = still[id(s)] if id(s) in still else [_flat(view.px_of(q)) for q in _world(s, k)]
            _draw_shape(d, s, loops, bg)
        for mk in (anim.marks[k] if k < len(anim.marks) else ()):
            x, y = view.px_of(np.asarray([mk.xy], float))[0]
            r = mk.radius_px
            c = _ci(mk.colour)
            d.ellipse([x - r, y - r, x + r, y + r], outline=c, width=2)
            d.line([x - r - 4, y, x + r + 4, y], fill=c, width=1)
            d.line([x, y - r - 4, x, y + r + 4], fill=c, width=1)
            if mk.text:
                text = spell(mk.text)
                tw = d.textlength(text, font=font)
                tx = x + r + 4 if x + r + 4 + tw < W - 2 else x - r - 4 - tw
                ty = min(max(y - r - 14, box[1]), H - 14)
                d.rectangle([tx - 1, ty, tx + tw + 1, ty + 12], fill=bg)
                _put_text(im, d, (tx, ty), text, c, font)
        for tr, tb in zip(anim.traces, tboxes):
            _draw_trace(im, d, font, tr, tb, k)
        caps = captions[k] if k < len(captions) else ()
        y = box[1] + box[3] + anim.margin_px
        for line in caps:
            colour = "red" if line.startswith("!") else "ink"
            _put_text(im, d, (anim.margin_px, y), line.lstrip("!"), _ci(colour), font)
            y += LINE_PX
        frames.append(im)
    return frames


def encode_gif(frames: list, frame_ms: int) -> bytes:
    """GIF bytes of palette frames (fixed palette, looping): each frame after the first holds only the
    box that changed, its unchanged pixels transparent (Pillow's ``optimize``; deterministic)."""
    buf = io.BytesIO()
    frames[0].save(buf, format="GIF", save_all=True, append_images=frames[1:], duration=int(frame_ms), loop=0,
                   optimize=True)
    return buf.getvalue()


def write_animation(anim: Animation, path: str | Path, max_bytes: int = 2_000_000) -> GifInfo:
    """Render and write ``anim`` as a GIF at ``path``; thinned (every second frame, ``keep`` kept) until
    it is at most ``max_bytes``.  Returns what was written."""
    frames = render_frames(anim)
    idx = list(range(len(frames)))
    data = encode_gif(frames, anim.frame_ms)
    while len(data) > max_bytes and len(idx) > 2:
        idx = [i for j, i in enumerate(idx) if j % 2 == 0 or i in anim.keep]
        data = encode_gif([frames[i] for i in idx], anim.frame_ms)
    p = Path(path)
    prepare(p)
    p.write_bytes(data)
    return GifInfo(str(p), tuple(idx), frames[0].width, frames[0].height, len(data), int(anim.frame_ms))
