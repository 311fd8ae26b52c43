"""The isometric pictures' rasteriser in numpy (``export/render.py`` until 2026-11-30): every fragment of a run of
triangles at once, the run's nearest fragments painted.  The reference the compiled ``render._paint`` is held to,
pixel for pixel."""

from __future__ import annotations

import numpy as np


def fragments(x, y, z, W: int, H: int):
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


def paint(x, y, z, rgb, W: int, H: int, run: int = 65536) -> np.ndarray:
    """The picture's pixels ((H W, 3) uint8 on white) painted a run of ``run`` triangles at a time: each run's
    fragments at least as near as the nearest so far, in order (a pixel ends as the last of its nearest)."""
    image = np.empty((H * W, 3), np.uint8)
    image[:] = (255, 255, 255)
    zbuf = np.full(H * W, -np.inf, dtype=np.float32)
    for s0 in range(0, len(x), run):
        sl = slice(s0, s0 + run)
        pix, depth, owner = fragments(x[sl], y[sl], z[sl], W, H)
        np.maximum.at(zbuf, pix, depth)  # the nearest fragment: largest z towards the viewer
        win = depth >= zbuf[pix]
        image[pix[win]] = rgb[s0 + owner[win]].astype(np.uint8)
    return image
