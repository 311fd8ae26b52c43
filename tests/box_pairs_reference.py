"""The reference of the self-intersection check's broad phase, one level of its traversal (``checks/box_pairs.py``,
``child_pairs``, compiled): the numpy formulation it replaced, every level's candidates, masks and concatenations as
arrays.  The tests put it in the compiled one's place in ``checks/mesh.py`` and compare the pairs both ways, in
order."""

from __future__ import annotations

import numpy as np


def child_pairs(A, B, box):
    """``child_pairs``' value: the overlapping pairs of the children of the node pairs (A, B) on the level whose node
    bounds are the rows of ``box`` (lo x, y, z, hi x, y, z)."""
    n = len(box)
    same = A == B
    As, Ad, Bd = A[same], A[~same], B[~same]
    # children of a self pair: (l,l), (l,r), (r,r); of a distinct pair: all four
    sa = np.concatenate([2 * As, 2 * As + 1])  # self pairs at the child level
    ca = np.concatenate([2 * As, 2 * Ad, 2 * Ad, 2 * Ad + 1, 2 * Ad + 1])
    cb = np.concatenate([2 * As + 1, 2 * Bd, 2 * Bd + 1, 2 * Bd, 2 * Bd + 1])
    ok = cb < n
    ca, cb = ca[ok], cb[ok]
    for a in range(3):
        lo_a, hi_a = box[:, a], box[:, a + 3]
        keep = (lo_a[ca] <= hi_a[cb]) & (lo_a[cb] <= hi_a[ca])
        ca, cb = ca[keep], cb[keep]
    sa = sa[sa < n]
    return np.concatenate([sa, ca]), np.concatenate([sa, cb])
