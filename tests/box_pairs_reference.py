"""The reference of the self-intersection check's broad phase (``checks/mesh.py``, :func:`overlapping_pairs`, whose
traversal runs level by level in the compiled ``checks/box_pairs.py``): the numpy formulation it replaced, every level's
candidates, masks and concatenations as arrays.  The tests compare the two pair for pair, in order."""

from __future__ import annotations

import numpy as np

from propulsor.checks.mesh import TooManyPairs, _f32_down, _f32_up, _morton


def overlapping_pairs(lo: np.ndarray, hi: np.ndarray, max_pairs: int | None = None) -> np.ndarray:
    """All pairs (i < j) whose boxes [lo, hi] overlap (closed), as an (k, 2) array.

    Implicit bounding-volume hierarchy: boxes sorted by the Morton code of their
    centres are the leaves of a complete binary tree (node i of level k covers
    leaves i*2^k ... (i+1)*2^k - 1); the tree is traversed against itself one
    level at a time, keeping node pairs whose boxes overlap.  Bounds are kept in
    float32 rounded outwards (conservative), one array per axis and side.  With `max_pairs`, more
    node pairs than that at any level raise TooManyPairs (memory stays bounded).
    """
    lo = np.asarray(lo, float)
    hi = np.asarray(hi, float)
    m = len(lo)
    if m < 2:
        return np.empty((0, 2), np.int64)
    order = np.argsort(_morton(0.5 * (lo + hi)), kind="stable")
    levels = [[_f32_down(lo[order, a]) for a in range(3)] + [_f32_up(hi[order, a]) for a in range(3)]]
    while len(levels[-1][0]) > 1:
        nxt = []
        for a, arr in enumerate(levels[-1]):
            if len(arr) % 2:
                arr = np.append(arr, arr[-1])
            nxt.append(np.minimum(arr[0::2], arr[1::2]) if a < 3 else np.maximum(arr[0::2], arr[1::2]))
        levels.append(nxt)
    A = np.zeros(1, np.int32)
    B = np.zeros(1, np.int32)
    for lev in range(len(levels) - 2, -1, -1):
        n = len(levels[lev][0])
        same = A == B
        As, Ad, Bd = A[same], A[~same], B[~same]
        # children of a self pair: (l,l), (l,r), (r,r); of a distinct pair: all four
        sa = np.concatenate([2 * As, 2 * As + 1])  # self pairs at the child level
        ca = np.concatenate([2 * As, 2 * Ad, 2 * Ad, 2 * Ad + 1, 2 * Ad + 1])
        cb = np.concatenate([2 * As + 1, 2 * Bd, 2 * Bd + 1, 2 * Bd, 2 * Bd + 1])
        ok = cb < n
        ca, cb = ca[ok], cb[ok]
        for a in range(3):
            lo_a, hi_a = levels[lev][a], levels[lev][a + 3]
            keep = (lo_a[ca] <= hi_a[cb]) & (lo_a[cb] <= hi_a[ca])
            ca, cb = ca[keep], cb[keep]
        sa = sa[sa < n]
        A = np.concatenate([sa, ca])
        B = np.concatenate([sa, cb])
        if max_pairs is not None and len(A) > max_pairs:
            raise TooManyPairs(f"more than {max_pairs} pairs of overlapping triangle boxes")
    keep = A != B
    i, j = order[A[keep]], order[B[keep]]
    return np.column_stack([np.minimum(i, j), np.maximum(i, j)])
