"""The Fourier law's one-point inversion, compiled (numba): ``FourierLaw.theta1`` and the series sums of
``FourierLaw.U_derivs1`` (laws/ratio_laws.py); and the law's array functions as that one-point path at each angle
(``theta_many``, ``derivs_many``, ``phi_many``), so that an angle gets the same value in any array (the law is
``elementwise``, laws/law.py).

The tooth generator and the contact search ask the law for theta(phi) one float at a time, tens of thousands of
times a design; in Python each call runs the Hermite start and two or three Newton steps over the series' terms.
Here the same operations, in the same order, on the same floats: ``math.cos`` / ``math.sin`` are the C library's
as in Python, no expression is regrouped, and Python's ``min`` / ``max`` of the step clamp are written out as Python
evaluates them, so the result is the Python path's to the last bit (a test compares them on random laws and
angles).  The powers of ``U_derivs1``'s return (``g1 ** 3``, ``g1 ** 5``: C ``pow`` in Python, a chain of products
in a compiled ``**``) stay in Python; the array path takes them by ``math.pow``, which numba leaves to the same C
``pow`` (numpy's ``**`` on an array is neither: its own vector loops).

``series`` is the law's (m, 3) array of its non-zero terms (j, c_j, s_j) in order; ``table`` the (2, n + 1) array of
the Hermite start's theta and slope per step (``FourierLaw._T``, ``_D``).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..nbcache import bind

__all__ = ["theta_one", "slopes_one", "theta_many", "derivs_many", "phi_many"]


@njit(cache=True, inline="always")
def _term(series, r, th):
    """(j, c_j, s_j, cos j theta, sin j theta) of the series' term r."""
    j = series[r, 0]
    return j, series[r, 1], series[r, 2], math.cos(j * th), math.sin(j * th)


@njit(cache=True, inline="always")
def _g01(th, k, series, c0):
    """(phi(theta), d phi / d theta) at one theta (``FourierLaw._g01``)."""
    g0 = th / k
    g1 = 1.0 / k
    for r in range(series.shape[0]):
        j, c, s, ca, sa = _term(series, r, th)
        g0 += c * ca + s * sa
        g1 += j * (s * ca - c * sa)
    return g0 - c0, g1


@njit(cache=True)
def theta_one(phi, k, series, c0, period, table, points):
    """theta(phi) at one finite float phi (``FourierLaw.theta1`` without its memory of the last phi)."""
    P = period
    m = math.floor(phi / P)
    x = (phi - m * P) * (points / P)
    i = int(x)
    if i < 0:
        i = 0
    if i > points - 1:
        i = points - 1
    t = x - i
    t2 = t * t
    t3 = t * t * t
    th = (2 * math.pi * m + (2 * t3 - 3 * t2 + 1) * table[0, i] + (t3 - 2 * t2 + t) * table[1, i]
          + (3 * t2 - 2 * t3) * table[0, i + 1] + (t3 - t2) * table[1, i + 1])
    for _ in range(100):
        g0, g1 = _g01(th, k, series, c0)
        v = (g0 - phi) / g1
        a = -0.5 if -0.5 > v else v  # max(v, -0.5) as Python evaluates it
        step = 0.5 if 0.5 < a else a  # min(a, 0.5)
        th -= step
        if abs(step) < 1e-12:
            break
    g0, g1 = _g01(th, k, series, c0)
    th -= (g0 - phi) / g1
    return th


@njit(cache=True)
def slopes_one(th, k, series):
    """(g1, g2, g3): d phi / d theta and its next two derivatives at one theta (``FourierLaw.U_derivs1``'s sums)."""
    g1 = 1.0 / k
    g2 = 0.0
    g3 = 0.0
    for r in range(series.shape[0]):
        j, c, s, ca, sa = _term(series, r, th)
        g1 += j * (s * ca - c * sa)
        g2 -= j * j * (c * ca + s * sa)
        g3 += j * j * j * (c * sa - s * ca)
    return g1, g2, g3


@njit(cache=True)
def theta_many(phis, k, series, c0, period, table, points):
    """theta at each angle of the 1-d array ``phis``, as ``FourierLaw.theta1`` gives it at that angle alone (nan at an
    angle not finite)."""
    out = np.empty(phis.shape[0])
    for i in range(phis.shape[0]):
        phi = phis[i]
        out[i] = theta_one(phi, k, series, c0, period, table, points) if math.isfinite(phi) else math.nan
    return out


@njit(cache=True)
def derivs_many(ths, k, series):
    """(3, n): U, dU/dphi and d2U/dphi2 at each theta of the 1-d array ``ths`` (``theta_many``'s), as
    ``FourierLaw.U_derivs1`` gives them from that theta."""
    out = np.empty((3, ths.shape[0]))
    for i in range(ths.shape[0]):
        g1, g2, g3 = slopes_one(ths[i], k, series)
        out[0, i] = 1.0 / g1
        out[1, i] = -g2 / math.pow(g1, 3.0)
        out[2, i] = (3 * g2 * g2 - g3 * g1) / math.pow(g1, 5.0)
    return out


@njit(cache=True)
def phi_many(ths, k, series, c0):
    """phi(theta) at each angle of the 1-d array ``ths``, summed as ``FourierLaw._g01`` sums it."""
    out = np.empty(ths.shape[0])
    for i in range(ths.shape[0]):
        out[i] = _g01(ths[i], k, series, c0)[0]
    return out


# the disk cache keyed on every kernel source (nbcache)
bind(globals())
