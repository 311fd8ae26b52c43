"""The walking law's array functions, compiled (numba): ``WalkingLaw.U`` / ``dU_dphi`` (seed 000 eq. 15) and
``SmoothedWalkingLaw.U`` / ``dU_dphi`` (the blend around each leg hand-over) of an array of driven angles, one angle
after the other.

The tooth generator asks the law for U and dU/dphi on arrays of tens to hundreds of angles, several thousand times a
design: numpy's cost per call (a dozen element-wise operations, ``np.where`` of both branches) is most of it.  Here
the same operations on each angle in the same order, as numpy does them element by element: the wrap into the leg
``x - (pi / 2) floor((x + pi / 4) / (pi / 2))``, the blend's polynomial in s = t / delta, the exact law's
``u (A + 3 b cos 2w) / A``; ``math.cos`` / ``math.sin`` are the C library's, which numpy's float64 ``cos`` / ``sin``
give here too (a test compares the two paths bit for bit on random laws and angles, at the windows' edges, and at
non-finite angles).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..nbcache import bind

__all__ = ["walking_many", "smoothed_many"]

#: the leg's period and its half (laws/walking.py: ``LEG_PERIOD``, the wrap's shift)
_LEG = math.pi / 2
_QUARTER = math.pi / 4


@njit(cache=True, inline="always")
def _wrap_leg(x):
    """``walking.wrap_leg`` of one angle: x - (pi / 2) floor((x + pi / 4) / (pi / 2)), in [-pi/4, pi/4)."""
    return x - _LEG * np.floor((x + _QUARTER) / _LEG)


@njit(cache=True, inline="always")
def _exact(x, what, u, A, b3, m6bu):
    """``WalkingLaw.U`` (what 0) or ``dU_dphi`` (1) at one angle."""
    w2 = 2.0 * _wrap_leg(x)
    if what == 0:
        return u * (A + b3 * math.cos(w2)) / A
    return m6bu * math.sin(w2) / A


@njit(cache=True)
def walking_many(phi, what, u, A, b3, m6bu):
    """``WalkingLaw.U`` (what 0) or ``dU_dphi`` (1) of each angle of the 1-D array ``phi``."""
    out = np.empty(len(phi))
    for i in range(len(phi)):
        out[i] = _exact(phi[i], what, u, A, b3, m6bu)
    return out


@njit(cache=True)
def smoothed_many(phi, what, delta, a0, a1, a2, a3, scaled, one_me, u, A, b3, m6bu):
    """``SmoothedWalkingLaw.U`` (what 0) or ``dU_dphi`` (1) of each angle of the 1-D array ``phi``: within delta of a
    hand-over the blend p(t) = a0 + a1 s^2 + a2 s^4 + a3 s^6 (s = t / delta) or its slope, elsewhere the exact law's
    (times ``one_me`` where ``scaled``: the law with a free hand-over value)."""
    out = np.empty(len(phi))
    for i in range(len(phi)):
        x = phi[i]
        t = _wrap_leg(x - _QUARTER)
        if abs(t) < delta:
            s = t / delta
            s2 = s * s
            if what == 0:
                v = a0 + s2 * (a1 + s2 * (a2 + s2 * a3))
            else:
                v = s * (2.0 * a1 + s2 * (4.0 * a2 + 6.0 * a3 * s2)) / delta
        else:
            v = _exact(x, what, u, A, b3, m6bu)
            if scaled:
                v = one_me * v
        out[i] = v
    return out


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
