"""Isometric pictures of solids and assemblies: a numpy z-buffer of the triangles, flat Lambert shading.

The meshes are the ones the build already made (a solid's tessellation in its forked worker, an
assembly's components from their solids' meshes); nothing is tessellated here.  The view is the
standard isometric one (camera on the (1, -1, 1) diagonal, z up), so every picture of the project
is drawn from the same side.  The rasteriser is a span (scan-line) rasteriser written with numpy:
every triangle is cut into the pixel rows its interior crosses, every row into its pixels, and the
nearest fragment of every pixel wins.  Back faces are culled (the meshes are closed and oriented,
which the mesh checks prove).  Rendered at twice the size and box-filtered down (anti-aliasing).
Deterministic: the same meshes give the same PNG bytes (no time stamp or text chunk in the PNG).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from numba import njit

from ..nbcache import bind
from ..planar import box
from ..write_root import prepare

#: picture width in pixels (the height follows the part's projected aspect, within 0.5 … 1 of it)
PICTURE_WIDTH_PX = 600
#: supersampling factor (the picture is rendered this many times larger and box-filtered down)
SUPERSAMPLE = 2
#: the camera's direction (from the scene towards the camera): the isometric diagonal
VIEW_DIR = np.array([1.0, -1.0, 1.0]) / np.sqrt(3.0)
#: light direction in camera coordinates (right, up, towards the viewer): upper left, in front
LIGHT_CAM = np.array([-0.35, 0.55, 0.76]) / np.linalg.norm([-0.35, 0.55, 0.76])
AMBIENT = 0.32
BACKGROUND = (255, 255, 255)
#: a fixed palette, one colour per component (the GLB uses the same)
PALETTE = (
    (0.26, 0.45, 0.70), (0.87, 0.52, 0.20), (0.35, 0.63, 0.33), (0.78, 0.29, 0.29),
    (0.55, 0.43, 0.71), (0.55, 0.40, 0.33), (0.84, 0.50, 0.70), (0.50, 0.50, 0.50),
    (0.74, 0.73, 0.25), (0.25, 0.69, 0.75), (0.20, 0.30, 0.50), (0.95, 0.70, 0.40),
)


def palette_colour(k: int) -> tuple[float, float, float]:
    """The k-th component's colour (RGB in 0 … 1), the palette repeating."""
    return PALETTE[k % len(PALETTE)]


#: the isometric view from below (the other side of the z = 0 plane), for assemblies whose main part is
#: hidden under the others seen from above (the balancer's arm under its road wheel)
VIEW_DIR_BELOW = np.array([1.0, -1.0, -1.0]) / np.sqrt(3.0)


def _camera(view=VIEW_DIR) -> np.ndarray:
    """Rows: screen right, screen up, towards the viewer (world → camera rotation)."""
    back = np.asarray(view, np.float64) / np.linalg.norm(view)
    right = np.cross(np.array([0.0, 0.0, 1.0]), back)
    right /= np.linalg.norm(right)
    up = np.cross(back, right)
    return np.vstack([right, up, back])


def _placed(vertices, transform) -> np.ndarray:
    v = np.asarray(vertices, np.float64)
    if transform is None:
        return v
    t = np.asarray(transform, np.float64)
    return v @ t[:3, :3].T + t[:3, 3]


def render_iso(items, path: str | Path, width: int = PICTURE_WIDTH_PX, view=VIEW_DIR) -> Path:
    """Render `items` — (vertices (n, 3) mm, faces (m, 3), 4×4 placement or None, RGB 0 … 1) — into a
    PNG at `path`, isometric (the camera towards `view`, z up on the screen), shaded, the whole scene
    fitted with a margin; returns the path."""
    from PIL import Image

    cam = _camera(view)
    tris, cols = [], []
    for vertices, faces, transform, rgb in items:
        v = _placed(vertices, transform) @ cam.T  # camera coordinates: x right, y up, z towards the viewer
        f = np.asarray(faces, np.int64)
        if len(f) == 0:
            continue
        tris.append(v[f])
        cols.append(np.broadcast_to(np.asarray(rgb, np.float64), (len(f), 3)))
    tri = np.concatenate(tris) if tris else np.zeros((0, 3, 3))
    col = np.concatenate(cols) if cols else np.zeros((0, 3))
    # flat Lambert shading, back faces culled (closed, outward-oriented meshes)
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    front = n[:, 2] > 0
    tri, col, n = tri[front], col[front], n[front]
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    shade = AMBIENT + (1.0 - AMBIENT) * np.clip(n @ LIGHT_CAM, 0.0, 1.0)
    rgb = np.clip(col * shade[:, None] * 255.0, 0, 255)

    # fit the projected scene into the picture with a 4 % margin
    lo, hi = box(tri[:, :, :2].reshape(-1, 2)) if len(tri) else (np.zeros(2), np.ones(2))
    span = np.maximum(hi - lo, 1e-9)
    W = int(width) * SUPERSAMPLE
    H = int(round(W * float(np.clip(span[1] / span[0], 0.5, 1.0)))) // SUPERSAMPLE * SUPERSAMPLE
    scale = min(W * 0.92 / span[0], H * 0.92 / span[1])
    centre = 0.5 * (lo + hi)
    x = (tri[:, :, 0] - centre[0]) * scale + 0.5 * W
    y = 0.5 * H - (tri[:, :, 1] - centre[1]) * scale  # rows grow downwards
    z = tri[:, :, 2]

    image = np.empty((H * W, 3), np.uint8)
    image[:] = BACKGROUND
    if len(tri):
        # every fragment in order (triangle, row, column), painted where it is at least as near as the nearest so
        # far: a pixel ends as the last of its nearest fragments (compiled, no fragment array; the same rasteriser
        # in numpy, the reference of the tests: tests/render_reference.py)
        zbuf = np.full(H * W, -np.inf, dtype=np.float32)
        _paint(np.ascontiguousarray(x), np.ascontiguousarray(y), np.ascontiguousarray(z), rgb.astype(np.uint8),
               W, H, zbuf, image)
    img = Image.fromarray(image.reshape(H, W, 3), "RGB").reduce(SUPERSAMPLE)
    path = Path(path)
    prepare(path)
    img.save(path, format="PNG", optimize=False, compress_level=6)
    return path


@njit(cache=True)
def _paint(x, y, z, rgb, W, H, zbuf, image):
    """The span rasteriser's fragments (``tests/render_reference.py``, the numpy one it replaces), each painted as
    it is made: the same operations on the same floats (the depth plane and the row's span in float64, each pixel's
    depth in float32 from the span's first one), a fragment painted into ``image`` (rows of ``rgb``) and ``zbuf``
    where its depth is at least the buffer's.  Painting every fragment in order this way leaves each pixel the last
    of its nearest fragments, as painting the fragments of each run that are at least as near as the run's
    nearest."""
    for k in range(len(x)):
        x0, x1, x2 = x[k, 0], x[k, 1], x[k, 2]
        y0, y1, y2 = y[k, 0], y[k, 1], y[k, 2]
        z0 = z[k, 0]
        e1x, e1y, e1z = x1 - x0, y1 - y0, z[k, 1] - z0
        e2x, e2y, e2z = x2 - x0, y2 - y0, z[k, 2] - z0
        det = e1x * e2y - e2x * e1y
        if not abs(det) > 1e-12:
            continue
        a = (e1z * e2y - e2z * e1y) / det
        b = (e2z * e1x - e1z * e2x) / det
        c = z0 - a * x0 - b * y0
        r0 = int(min(max(np.ceil(min(y0, y1, y2) - 0.5), 0.0), float(H)))
        r1 = int(min(max(np.ceil(max(y0, y1, y2) - 0.5), 0.0), float(H)))
        step = np.float32(a)
        for row in range(r0, r1):
            yc = row + 0.5
            xl, xr = math.inf, -math.inf
            for e in range(3):
                i, j = e, (e + 1) % 3
                ya, yb, xa, xb = y[k, i], y[k, j], x[k, i], x[k, j]
                if min(ya, yb) <= yc and yc < max(ya, yb):
                    xs = xa + (yc - ya) * (xb - xa) / (yb - ya)
                    xl = min(xl, xs)
                    xr = max(xr, xs)
            c0 = min(max(np.ceil(xl - 0.5), 0.0), float(W))
            c1 = min(max(np.ceil(xr - 0.5), 0.0), float(W))
            ncol = int(max(c1 - c0, 0.0))
            if ncol <= 0:
                continue
            start = row * W + int(c0)
            d0 = np.float32(a * (c0 + 0.5) + b * (row + 0.5) + c)
            for o in range(ncol):
                depth = d0 + step * np.float32(o)
                p = start + o
                if depth >= zbuf[p]:
                    zbuf[p] = depth
                    image[p, 0], image[p, 1], image[p, 2] = rgb[k, 0], rgb[k, 1], rgb[k, 2]


# the disk cache of the kernel keyed on every kernel source (nbcache)
bind(globals())
