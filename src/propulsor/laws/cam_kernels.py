"""The cam's motion (laws/cam_motion.py, laws/cam_return.py) read in compiled loops: the dense output of its DOP853
integration and the return phase's quintics, at hundreds of thousands of angles a design search (each candidate's
pressure angle, shoe table and hub speed, and the return's least-pressure-angle search).

:class:`DenseSolution`: scipy's ``OdeSolution`` of ``solve_ivp(..., method="DOP853", dense_output=True)`` sorts the
angles, splits them by step and calls each step's interpolant in Python (about 90 % of its time on 721 angles).  Here
the same operations, in the same order, on the same floats: the step of each angle as ``OdeSolution`` finds it
(``searchsorted`` on its sorted step ends with its own side, clamped to the steps, reversed for an integration
towards negative angles), then ``Dop853DenseOutput._call_impl``'s Horner scheme term by term (``y += f``, then
``y *= x`` or ``y *= 1 - x`` in turn, then ``y += y_old``, with ``x = (t - t_old) / h``).

:func:`quintic_derivs`: ``ReturnCurve.derivs``'s sums ``coef[piece, k] * fk * t ** (k - m)`` element by element, the
powers and factors computed by the caller in numpy and Python as before.

:func:`polyline_crosses_itself`: the shoe profile's self-crossing test (laws/shoe.py), every pair of segments' line
parameters as the all-pairs arrays computed them, stopping at the first crossing.

Each operation is a single IEEE addition, multiplication or division per element, in numpy as here (no expression
regrouped, no fused multiply-add): scipy's and numpy's values to the last bit (tests compare them).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from ..nbcache import bind

__all__ = ["DenseSolution", "quintic_derivs", "polyline_crosses_itself"]


@njit(cache=True)
def _dense_eval(ts_sorted, right, ascending, t_old, h, F, y_old, t):
    """(n_states, len(t)) values of the dense output at ``t`` (``OdeSolution.__call__`` of a 1-D array)."""
    nseg = t_old.shape[0]
    n = y_old.shape[1]
    p = F.shape[1]
    out = np.empty((n, t.shape[0]))
    for j in range(t.shape[0]):
        v = t[j]
        lo, hi = 0, ts_sorted.shape[0]
        while lo < hi:  # np.searchsorted(ts_sorted, v, side="right" if right else "left")
            mid = (lo + hi) >> 1
            if (ts_sorted[mid] <= v) if right else (ts_sorted[mid] < v):
                lo = mid + 1
            else:
                hi = mid
        s = min(max(lo - 1, 0), nseg - 1)
        if not ascending:
            s = nseg - 1 - s
        x = (v - t_old[s]) / h[s]
        x1 = 1 - x
        for c in range(n):
            y = 0.0
            for i in range(p):
                y += F[s, p - 1 - i, c]
                if i % 2 == 0:
                    y *= x
                else:
                    y *= x1
            out[c, j] = y + y_old[s, c]
    return out


class DenseSolution:
    """``sol`` (an ``OdeSolution`` of DOP853 steps) as arrays, called as ``sol`` is on a 1-D array of points:
    (n_states, n_points), the same floats."""

    def __init__(self, sol):
        steps = sol.interpolants
        if not steps or any(type(d).__name__ != "Dop853DenseOutput" for d in steps):
            raise TypeError("DenseSolution reads the steps of a DOP853 integration only")
        self.ts_sorted = np.ascontiguousarray(sol.ts_sorted, np.float64)
        self.right = sol.side == "right"
        self.ascending = bool(sol.ascending)
        self.t_old = np.array([float(d.t_old) for d in steps])
        self.h = np.array([float(d.h) for d in steps])
        self.F = np.ascontiguousarray(np.stack([np.asarray(d.F, np.float64) for d in steps]))
        self.y_old = np.ascontiguousarray(np.stack([np.asarray(d.y_old, np.float64) for d in steps]))

    def __call__(self, t) -> np.ndarray:
        t = np.ascontiguousarray(t, np.float64)
        if t.ndim != 1:
            raise ValueError("DenseSolution takes a 1-D array of points")
        return _dense_eval(self.ts_sorted, self.right, self.ascending, self.t_old, self.h, self.F, self.y_old, t)



@njit(cache=True)
def quintic_derivs(coef, piece, powers, fks, Lm):
    """[H, H', ..., H^(order)] of the two quintics ``coef`` (2, 6) at points of ``piece`` (0 or 1) whose local t has
    ``powers[e] = t ** e`` (e = 0..5): row m is ``sum over k = m..5 of coef[piece, k] * fks[m, k] * powers[k - m]``
    in that order, from 0.0, over ``Lm[m]`` (``L ** m``); order = len(Lm) - 1."""
    n = piece.shape[0]
    out = np.empty((Lm.shape[0], n))
    for m in range(Lm.shape[0]):
        for j in range(n):
            p = piece[j]
            val = 0.0
            for k in range(m, 6):
                val = val + coef[p, k] * fks[m, k] * powers[k - m, j]
            out[m, j] = val / Lm[m]
    return out



@njit(cache=True)
def polyline_crosses_itself(P) -> bool:
    """Whether two non-adjacent segments of the open polyline ``P`` (n, 2) cross, each segment half-open [start, end)
    (``shoe._segments_intersect``): for segments i < j - 1, with d = end - start, den = d_i x d_j, w = a_j - a_i,
    t = (w x d_j) / den and u = (w x d_i) / den (u x v = u0 v1 - u1 v0), a crossing where den != 0 and both lie in
    [0, 1)."""
    n = P.shape[0] - 1
    if n < 3:
        return False
    for i in range(n):
        ax, ay = P[i, 0], P[i, 1]
        dix, diy = P[i + 1, 0] - ax, P[i + 1, 1] - ay
        for j in range(i + 2, n):
            djx, djy = P[j + 1, 0] - P[j, 0], P[j + 1, 1] - P[j, 1]
            den = dix * djy - diy * djx
            if den == 0.0:
                continue
            wx, wy = P[j, 0] - ax, P[j, 1] - ay
            t = (wx * djy - wy * djx) / den
            u = (wx * diy - wy * dix) / den
            if t >= 0 and t < 1 and u >= 0 and u < 1:
                return True
    return False


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
