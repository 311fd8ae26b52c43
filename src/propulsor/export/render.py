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

from pathlib import Path

import numpy as np

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
#: triangles rasterised at a time (bounds the fragments' arrays)
RENDER_RUN_TRIANGLES = 65536
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
    lo = tri[:, :, :2].reshape(-1, 2).min(axis=0) if len(tri) else np.zeros(2)
    hi = tri[:, :, :2].reshape(-1, 2).max(axis=0) if len(tri) else np.ones(2)
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
        # the triangles a run at a time (their fragments' arrays stay bounded: a million triangles' fragments at once
        # held 350 MiB); each run's fragments at least as near as the nearest so far are painted, in order, so a
        # pixel ends as the last of its nearest fragments, as when every fragment is taken at once
        zbuf = np.full(H * W, -np.inf, dtype=np.float32)
        for s0 in range(0, len(tri), RENDER_RUN_TRIANGLES):
            run = slice(s0, s0 + RENDER_RUN_TRIANGLES)
            pix, depth, owner = _fragments(x[run], y[run], z[run], W, H)
            np.maximum.at(zbuf, pix, depth)  # the nearest fragment: largest z towards the viewer
            win = depth >= zbuf[pix]
            image[pix[win]] = rgb[s0 + owner[win]].astype(np.uint8)
    img = Image.fromarray(image.reshape(H, W, 3), "RGB").reduce(SUPERSAMPLE)
    path = Path(path)
    prepare(path)
    img.save(path, format="PNG", optimize=False, compress_level=6)
    return path


def _fragments(x, y, z, W: int, H: int):
    """Pixels (flat index), depths and triangle index of every fragment of the triangles (x, y, z
    are (m, 3) screen coordinates; pixel (i, j) has its centre at (i + 0.5, j + 0.5))."""
    m = len(x)
    # the depth plane of every triangle: z = a x + b y + c
    e1x, e1y, e1z = x[:, 1] - x[:, 0], y[:, 1] - y[:, 0], z[:, 1] - z[:, 0]
    e2x, e2y, e2z = x[:, 2] - x[:, 0], y[:, 2] - y[:, 0], z[:, 2] - z[:, 0]
    det = e1x * e2y - e2x * e1y
    ok = np.abs(det) > 1e-12
    det = np.where(ok, det, 1.0)
    a = (e1z * e2y - e2z * e1y) / det
    b = (e2z * e1x - e1z * e2x) / det
    c = z[:, 0] - a * x[:, 0] - b * y[:, 0]
    # rows whose centre lies in [min y, max y)
    r0 = np.clip(np.ceil(y.min(axis=1) - 0.5), 0, H).astype(np.int64)
    r1 = np.clip(np.ceil(y.max(axis=1) - 0.5), 0, H).astype(np.int64)
    nrow = np.where(ok, r1 - r0, 0)
    t = np.repeat(np.arange(m), nrow)
    row = (np.arange(len(t)) - np.repeat(np.cumsum(nrow) - nrow, nrow)) + r0[t]
    yc = row + 0.5
    # the span of the row: where the row's centre line crosses the triangle's edges
    xl = np.full(len(t), np.inf)
    xr = np.full(len(t), -np.inf)
    for i, j in ((0, 1), (1, 2), (2, 0)):
        ya, yb, xa, xb = y[t, i], y[t, j], x[t, i], x[t, j]
        cross = (np.minimum(ya, yb) <= yc) & (yc < np.maximum(ya, yb))
        dy = np.where(cross, yb - ya, 1.0)
        xs = xa + (yc - ya) * (xb - xa) / dy
        xl = np.where(cross, np.minimum(xl, xs), xl)
        xr = np.where(cross, np.maximum(xr, xs), xr)
    c0 = np.clip(np.ceil(xl - 0.5), 0, W)
    c1 = np.clip(np.ceil(xr - 0.5), 0, W)
    ncol = np.where(np.isfinite(c0) & np.isfinite(c1), np.maximum(c1 - c0, 0), 0).astype(np.int64)
    keep = ncol > 0
    t, row, c0, ncol = t[keep].astype(np.int32), row[keep], c0[keep].astype(np.int64), ncol[keep]
    # per span: first pixel, depth there and its step along the row; then every pixel of the span
    # (32-bit from here on: the fragments are millions, and halving their bytes halves the time)
    start = (row * W + c0).astype(np.int32)
    d0 = (a[t] * (c0 + 0.5) + b[t] * (row + 0.5) + c[t]).astype(np.float32)
    step = a[t].astype(np.float32)
    first = (np.cumsum(ncol) - ncol).astype(np.int32)
    s = np.repeat(np.arange(len(t), dtype=np.int32), ncol)
    offset = np.arange(len(s), dtype=np.int32) - first[s]
    return start[s] + offset, d0[s] + step[s] * offset.astype(np.float32), t[s]
