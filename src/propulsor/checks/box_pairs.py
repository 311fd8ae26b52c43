"""The broad phase of the self-intersection check (:func:`propulsor.checks.mesh.overlapping_pairs`): one level of the
implicit bounding-volume hierarchy's traversal against itself, compiled with numba.

A level takes the node pairs of the level above (``A[i] <= B[i]``) and gives the pairs of their children whose boxes
overlap, in the order the numpy formulation (``tests/box_pairs_reference.py``) gives them: the self pairs' left
children, their right children, then the candidates of the self pairs (left, right) and of the distinct pairs (left
left, left right, right left, right right), each block in the order of its parents, those past the level's end or
apart on an axis left out.  Written straight into its output (no candidate arrays, no masks): the numpy
formulation's temporaries were about 580 MiB for the 469 000 triangles of the final drive's ring.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from ..nbcache import bind

__all__ = ["child_pairs"]


@njit(cache=True, inline="always")
def _apart(c, d, box):
    """Whether the boxes of nodes c and d (rows of ``box``: lo x, y, z, hi x, y, z) are apart on an axis (closed
    boxes: touching is overlapping)."""
    return not (box[c, 0] <= box[d, 3] and box[d, 0] <= box[c, 3] and box[c, 1] <= box[d, 4]
                and box[d, 1] <= box[c, 4] and box[c, 2] <= box[d, 5] and box[d, 2] <= box[c, 5])


@njit(cache=True)
def child_pairs(A, B, box):
    """(A', B'): the overlapping pairs of the children of the node pairs (A, B) on the level whose node bounds are
    the rows of ``box`` (n, 6), float32: lo x, y, z, hi x, y, z (a node's box in one place: its six bounds are read
    together)."""
    n = len(box)
    m = len(A)
    if len(B) != m:
        raise ValueError("child_pairs: A and B differ in length")
    n_self = 0
    for i in range(m):
        if A[i] == B[i]:
            n_self += 1
    cap = 3 * n_self + 4 * (m - n_self)
    outA = np.empty(cap, np.int32)
    outB = np.empty(cap, np.int32)
    k = 0
    for half in range(2):  # the self pairs at the child level: every left child, then every right child
        for i in range(m):
            if A[i] == B[i]:
                c = 2 * A[i] + half
                if c < n:
                    outA[k] = c
                    outB[k] = c
                    k += 1
    for i in range(m):  # a self pair's two children
        if A[i] == B[i]:
            c, d = 2 * A[i], 2 * A[i] + 1
            if d < n and not _apart(c, d, box):
                outA[k] = c
                outB[k] = d
                k += 1
    for block in range(4):  # a distinct pair's four: (l, l), (l, r), (r, l), (r, r)
        da, db = block // 2, block % 2
        for i in range(m):
            if A[i] != B[i]:
                c, d = 2 * A[i] + da, 2 * B[i] + db
                if d < n and not _apart(c, d, box):
                    outA[k] = c
                    outB[k] = d
                    k += 1
    return outA[:k].copy(), outB[:k].copy()


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
