"""The colours of a picture's pixels, for the tests that look at screenshots and rendered views: one integer a
colour (r << 16 | g << 8 | b), so that counting or grouping the colours is one sort of integers.  numpy's row-wise
``np.unique(px, axis=0)`` gives the same colours in the same order but sorts the rows as structured records: about
0.8 s of CPU a 3D view's screenshot, 30 of them in one test."""

from __future__ import annotations

import numpy as np


def colour_keys(px) -> np.ndarray:
    """One integer a pixel of ``px`` (any shape ending in 3 channels of 0..255): r << 16 | g << 8 | b, which orders
    the colours as ``np.unique(px, axis=0)`` orders its rows."""
    px = np.asarray(px).reshape(-1, 3).astype(np.int64)
    if px.size and (px.min() < 0 or px.max() > 255):
        raise ValueError(f"8-bit channels expected, got {px.min()} .. {px.max()}")
    return (px[:, 0] << 16) | (px[:, 1] << 8) | px[:, 2]


def colour_rows(keys) -> np.ndarray:
    """The (r, g, b) rows of colour keys (the inverse of :func:`colour_keys`)."""
    keys = np.asarray(keys, np.int64)
    return np.column_stack([keys >> 16, (keys >> 8) & 255, keys & 255])


def colour_count(px) -> int:
    """How many colours the pixels of ``px`` show: ``len(np.unique(px.reshape(-1, 3), axis=0))``."""
    return len(np.unique(colour_keys(px)))
