"""The least-squares problems of the flank curvatures (:func:`.tooth_load.curvatures_at`) set up in one compiled pass.

:func:`.tooth_load._problems` builds, for one vertex of a dense outline, the windows of its cubic fits (the centred
one and the two one-sided ones; at a corner the two sides) and :func:`.tooth_load._problem` each fit's points in the
frame of its tangent.  Here the same windows and the same coordinates for every vertex of a list at once: each window
is a run of consecutive vertices (the arc length from the vertex grows along the run, so ``|s| <= half_len`` and the
bounds at the corners cut one range), and each point's frame coordinates are numpy's ``q @ t``, which for two columns
is one fused multiply-add added to +0.0, ``fma(q0, t0, q1 * t1) + 0.0`` (OpenBLAS's gemv, which adds its sum to a
zeroed y: a -0.0 comes out +0.0; checked to the bit, signs of zero included, in ``tests/test_tooth_load_kernels.py``).  The powers of x stay numpy's (its ``x ** 3`` is not libm's
``pow`` where numpy has SIMD code for it), the solves LAPACK's.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..fused import fma as _fma
from ..nbcache import bind

__all__ = ["fit_windows", "frame_coordinates"]


@njit(cache=True)
def fit_windows(seg_len, corner, todo, half_len):
    """Each vertex of ``todo``'s fit windows (:func:`.tooth_load._problems`): (is_corner, K, first, last) with
    first, last of shape (len(todo), 3): the window positions j (0 .. 2K, the vertex at K; vertex (i + j - K) mod n)
    of the centred fit, the side ahead and the side behind (at a corner: ahead, behind and an empty third); an empty
    window has last < first."""
    n = len(seg_len)
    m = len(todo)
    is_corner = np.zeros(m, np.bool_)
    Ks = np.zeros(m, np.int64)
    first = np.zeros((m, 3), np.int64)
    last = np.full((m, 3), -1, np.int64)
    for r in range(m):
        i = todo[r]
        K = min(n // 2 - 1, int(math.ceil(2.0 * half_len / max(seg_len[i], 1e-9))) + 2)
        Ks[r] = K
        # arc length of each window position from vertex i (numpy's cumsum: sequential), the range |s| <= half_len
        c = np.empty(2 * K + 2)
        c[0] = 0.0
        acc = 0.0
        for j in range(2 * K + 1):
            acc = acc + seg_len[(i + j - K) % n]
            c[j + 1] = acc
        ck = c[K]
        k0, k1 = 2 * K + 1, -1
        for j in range(2 * K + 1):
            if abs(c[j] - ck) <= half_len:
                if j < k0:
                    k0 = j
                k1 = j
        # the last vertex ahead and behind before a corner (a corner ends the piece)
        hi = 2 * K
        for j in range(K + 1, 2 * K + 1):
            if corner[(i + j - K) % n]:
                hi = j
                break
        lo = 0
        for j in range(K - 1, -1, -1):
            if corner[(i + j - K) % n]:
                lo = j
                break
        if not corner[i]:
            first[r, 0], last[r, 0] = max(k0, lo), min(k1, hi)
            first[r, 1], last[r, 1] = max(k0, K), min(k1, hi)
            first[r, 2], last[r, 2] = max(k0, lo), min(k1, K)
        else:
            is_corner[r] = True
            first[r, 0], last[r, 0] = max(k0, K), min(k1, hi)
            first[r, 1], last[r, 1] = max(k0, lo), min(k1, K)
    return is_corner, Ks, first, last


@njit(cache=True)
def frame_coordinates(points, todo, Ks, first, last, frames, rows):
    """The points of each window ``rows[p] = (r, f)`` (vertex ``todo[r]``, fit f, its frame ``frames[p]`` the unit
    tangent) in that frame: (x, y) of ``q = points[vertex of j] - points[i]`` with the normal (-t1, t0), every window
    after the one before in flat arrays; offsets[p] where window p starts (offsets[-1]: the total)."""
    n = len(points)
    P = len(rows)
    offsets = np.zeros(P + 1, np.int64)
    for p in range(P):
        r, f = rows[p, 0], rows[p, 1]
        offsets[p + 1] = offsets[p] + max(0, last[r, f] - first[r, f] + 1)
    X = np.empty(offsets[P])
    Y = np.empty(offsets[P])
    for p in range(P):
        r, f = rows[p, 0], rows[p, 1]
        i = todo[r]
        K = Ks[r]
        t0, t1 = frames[p, 0], frames[p, 1]
        n0, n1 = -t1, t0
        px, py = points[i, 0], points[i, 1]
        k = offsets[p]
        for j in range(first[r, f], last[r, f] + 1):
            v = (i + j - K) % n
            qx, qy = points[v, 0] - px, points[v, 1] - py
            X[k] = _fma(qx, t0, qy * t1) + 0.0  # gemv adds its sum to y = +0.0: -0.0 comes out +0.0
            Y[k] = _fma(qx, n0, qy * n1) + 0.0
            k += 1
    return X, Y, offsets


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
