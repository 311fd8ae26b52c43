"""Distance of points to a planar B-spline curve by Newton's foot-point iteration, and the exact area planar
B-splines sweep about the origin, compiled (numba).

The spline fit (:mod:`.bspline`) measures, every round of its refinement, the normal distance of the exact curve's
check points to the interpolating spline.  The iteration is that of ``bspline._project`` on scipy's BSpline: for each
point Q, from a start parameter t, ``iters`` steps ``t <- clip(t - f / f', lo, hi)`` with ``f = (C(t) - Q) . C'(t)``
and ``f' = C'(t) . C'(t) + (C(t) - Q) . C''(t)``; the result is ``|C(t) - Q|``.  Here C, C' and C'' come in one pass
of the basis functions and their derivatives at t (de Boor / Cox; The NURBS Book, algorithm A2.3) instead of three
scipy evaluations each step: the same quantities to rounding (the fit only compares them with half its tolerance).

:func:`sweep_area` gives a spline's ``integral of (x dy - y dx)`` (twice the signed area its chords to the origin
sweep): Gauss-Legendre's three points on each knot span, exact for the integrand's degree 2k - 1 <= 5 (a loop's
orientation, :meth:`.profile.Loop.oriented`, without sampling the loop).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..nbcache import bind

__all__ = ["foot_distances", "foot_distances_scipy", "sweep_area"]


@njit(cache=True)
def _span(t, k, n, x):
    """Index l with t[l] <= x < t[l + 1], k <= l <= n - 1 (the last non-empty span at the right end)."""
    lo, hi = k, n
    if x >= t[n]:
        l = n - 1
        while l > k and t[l] == t[l + 1]:
            l -= 1
        return l
    if x <= t[k]:
        l = k
        while l < n - 1 and t[l] == t[l + 1]:
            l += 1
        return l
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if t[mid] <= x:
            lo = mid
        else:
            hi = mid
    return lo


@njit(cache=True)
def _point_derivs(t, c, k, x, out, ndu, left, right, ders, a):
    """out[d] = d-th derivative (d = 0, 1, 2) of the curve sum_i c[i] N_{i,k}(x) (a zero row past the degree).
    ndu (k+1, k+1), left, right (k+1,), ders (3, k+1), a (2, k+1): the caller's scratch arrays, made once for all
    its points (five arrays allocated at every call cost a fifth of the fit's distances); each entry read is written
    first in this call (``ders`` and ``a`` are set to zero here as the arrays made afresh were)."""
    n = c.shape[0]
    l = _span(t, k, n, x)
    # basis functions of every degree up to k at x (ndu of A2.3: the upper triangle the knot differences)
    ndu[0, 0] = 1.0
    for j in range(1, k + 1):
        left[j] = x - t[l + 1 - j]
        right[j] = t[l + j] - x
        saved = 0.0
        for r in range(j):
            ndu[j, r] = right[r + 1] + left[j - r]
            temp = ndu[r, j - 1] / ndu[j, r]
            ndu[r, j] = saved + right[r + 1] * temp
            saved = left[j - r] * temp
        ndu[j, j] = saved
    nd = min(2, k)
    for d in range(3):
        for j in range(k + 1):
            ders[d, j] = 0.0
    for j in range(k + 1):
        ders[0, j] = ndu[j, k]
    for d in range(2):
        for j in range(k + 1):
            a[d, j] = 0.0
    for r in range(k + 1):
        s1, s2 = 0, 1
        a[0, 0] = 1.0
        for d in range(1, nd + 1):
            dd = 0.0
            rk = r - d
            pk = k - d
            if r >= d:
                a[s2, 0] = a[s1, 0] / ndu[pk + 1, rk]
                dd = a[s2, 0] * ndu[rk, pk]
            j1 = 1 if rk >= -1 else -rk
            j2 = d - 1 if r - 1 <= pk else k - r
            for j in range(j1, j2 + 1):
                a[s2, j] = (a[s1, j] - a[s1, j - 1]) / ndu[pk + 1, rk + j]
                dd += a[s2, j] * ndu[rk + j, pk]
            if r <= pk:
                a[s2, d] = -a[s1, d - 1] / ndu[pk + 1, r]
                dd += a[s2, d] * ndu[r, pk]
            ders[d, r] = dd
            s1, s2 = s2, s1
    f = k
    for d in range(1, nd + 1):
        for j in range(k + 1):
            ders[d, j] *= f
        f *= k - d
    for d in range(3):
        out[d, 0] = 0.0
        out[d, 1] = 0.0
    for d in range(nd + 1):
        for j in range(k + 1):
            i = l - k + j
            out[d, 0] += ders[d, j] * c[i, 0]
            out[d, 1] += ders[d, j] * c[i, 1]


@njit(cache=True)
def _foot(t, c, k, Q, t0, lo, hi, iters):
    m = Q.shape[0]
    dist = np.empty(m)
    out = np.zeros((3, 2))
    ndu, left, right = np.zeros((k + 1, k + 1)), np.zeros(k + 1), np.zeros(k + 1)
    ders, a = np.zeros((3, k + 1)), np.zeros((2, k + 1))
    for p in range(m):
        x = t0[p]
        for _ in range(iters):
            _point_derivs(t, c, k, x, out, ndu, left, right, ders, a)
            rx, ry = out[0, 0] - Q[p, 0], out[0, 1] - Q[p, 1]
            f = rx * out[1, 0] + ry * out[1, 1]
            fp = out[1, 0] * out[1, 0] + out[1, 1] * out[1, 1] + rx * out[2, 0] + ry * out[2, 1]
            x = min(max(x - f / (fp if abs(fp) > 1e-300 else 1e-300), lo), hi)
        _point_derivs(t, c, k, x, out, ndu, left, right, ders, a)
        dist[p] = np.sqrt((out[0, 0] - Q[p, 0]) ** 2 + (out[0, 1] - Q[p, 1]) ** 2)
    return dist


def foot_distances_scipy(bs, Q, t0, lo: float, hi: float, iters: int = 6) -> np.ndarray:
    """The same iteration on scipy's BSpline ``bs`` and its derivative splines (C, C', C'' evaluated apart): the
    method :func:`foot_distances` replaced, kept as its reference (tests, ``bench/bench_spline_fit.py``); degree >= 2."""
    d1, d2 = bs.derivative(1), bs.derivative(2)
    t = np.asarray(t0, float).copy()
    for _ in range(iters):
        r = bs(t) - Q
        g1, g2 = d1(t), d2(t)
        f = np.einsum("ij,ij->i", r, g1)
        fp = np.einsum("ij,ij->i", g1, g1) + np.einsum("ij,ij->i", r, g2)
        t = np.clip(t - f / np.where(np.abs(fp) > 1e-300, fp, 1e-300), lo, hi)
    return np.linalg.norm(bs(t) - Q, axis=1)


def foot_distances(knots, poles, degree: int, Q, t0, lo: float, hi: float, iters: int = 6) -> np.ndarray:
    """Distance (mm) of each point Q (m, 2) to the B-spline (knots, poles (n, 2), degree), Newton's foot-point
    iteration from the parameters t0 (m,) kept within [lo, hi] (see the module)."""
    return _foot(np.ascontiguousarray(knots, np.float64), np.ascontiguousarray(poles, np.float64), int(degree),
                 np.ascontiguousarray(Q, np.float64), np.ascontiguousarray(t0, np.float64), float(lo), float(hi),
                 int(iters))


#: Gauss-Legendre's three nodes and weights on [-1, 1]: exact for polynomials up to degree 5
_GAUSS_X = np.array([-math.sqrt(0.6), 0.0, math.sqrt(0.6)])
_GAUSS_W = np.array([5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0])


@njit(cache=True)
def _sweep(t, c, k, gx, gw):
    """The integral of (x y' - y x') of the spline (t, c, k) over its parameter range, span by span at the Gauss
    nodes ``gx`` (weights ``gw``)."""
    cv = np.zeros((3, 2))
    ndu, left, right = np.zeros((k + 1, k + 1)), np.zeros(k + 1), np.zeros(k + 1)
    ders, a = np.zeros((3, k + 1)), np.zeros((2, k + 1))
    acc = 0.0
    for l in range(k, c.shape[0]):
        lo, hi = t[l], t[l + 1]
        if not hi > lo:
            continue
        h, m = 0.5 * (hi - lo), 0.5 * (hi + lo)
        part = 0.0
        for g in range(len(gx)):
            _point_derivs(t, c, k, m + h * gx[g], cv, ndu, left, right, ders, a)
            part += gw[g] * (cv[0, 0] * cv[1, 1] - cv[0, 1] * cv[1, 0])
        acc += h * part
    return acc


def sweep_area(knots, poles, degree: int) -> float:
    """``integral of (x dy - y dx)`` along the clamped B-spline (knots, poles (n, 2), degree): twice the signed area
    its chords to the origin sweep, exact up to degree 3 (see the module)."""
    return float(_sweep(np.ascontiguousarray(knots, np.float64), np.ascontiguousarray(poles, np.float64), int(degree),
                        _GAUSS_X, _GAUSS_W))


# the disk cache keyed on every kernel source (nbcache)
bind(globals())
