"""The drive law of a non-circular pair as a value: the interface every consumer uses.

A law relates the driver angle theta to the driven angle phi (both rad, theta(0) = 0):

    U(phi) = d theta / d phi > 0      the ratio (driver speed over driven speed)
    theta(phi), U, U', U''            the angle relation and its first two derivatives
    period P in phi                   U(phi + P) = U(phi); ``periods`` = 2 pi / P per driven turn
    n                                 whole driver turns per driven turn: theta(2 pi) = 2 pi n

The driven pitch curve has ``periods`` equal lobes; the driver's repeats every n P of phi, so its
curve closes on one body turn only if n divides ``periods`` (``require_law``).  Each law names the
smooth pieces of one reference period [period_start, period_start + P] (``breakpoints``: where U
is only C2 or jumps in slope) and its corners (``corner_phis``: where U' jumps, the pitch curves
have a kink).  A law whose array functions give every angle the value that angle gets alone, bit for bit (no
iteration until the whole array has converged, no sum across it; a small array's one-point path the same as the
array path's) says so with ``elementwise = True``: the curves of many teeth are then evaluated in one array
(``gears.curve_batch``).  Implementations: ``laws.walking.WalkingLaw`` and its blend
``gears.smoothed_law.SmoothedWalkingLaw``, ``laws.ratio_laws`` (elliptical, Fourier series).
"""

from __future__ import annotations

import math
from typing import Protocol, runtime_checkable

import numpy as np

from ..errors import InputError

__all__ = ["Law", "require_law", "is_walking", "one_point_values", "SMALL_ARRAY"]

#: arrays of at most this many angles take a law's one-point path (:func:`one_point_values`): numpy's cost per call is
#: the whole price of so few (a blended walking law's one-angle theta 24 us on the array path, 4 us on this one)
SMALL_ARRAY = 8


def one_point_values(law, phi, i: int):
    """Function ``i`` of the law at the angles ``phi`` by its one-point path, shaped as phi (i = 0, 1, 2: U, dU/dphi,
    d2U/dphi2 from ``U_derivs1``; -1: ``theta1``) where phi holds at most ``SMALL_ARRAY`` angles, all finite; else
    None (the array path).  A law calls it first in its array functions when its one-point functions reproduce
    them bit for bit (tests/test_one_point_paths.py, tests/test_fourier_one_point.py)."""
    phi = np.asarray(phi, dtype=float)
    if phi.size > SMALL_ARRAY or not np.all(np.isfinite(phi)):
        return None
    f = law.theta1 if i < 0 else (lambda x: law.U_derivs1(x)[i])
    return np.array([f(x) for x in phi.ravel().tolist()], dtype=float).reshape(phi.shape)


@runtime_checkable
class Law(Protocol):
    """What a consumer of a law may use (pitch curves, closure, curvature, teeth, proofs, tables)."""

    #: short name of the law's family ("walking", "elliptical", "fourier", ...)
    kind: str
    #: whole driver turns per driven turn
    n: int
    #: period of U in the driven angle phi (rad)
    period: float
    #: start of the reference period [period_start, period_start + period]
    period_start: float
    #: periods per driven turn (= 2 pi / period, the driven curve's lobes)
    periods: int
    #: ends of the smooth pieces of the reference period (first and last: its ends)
    breakpoints: tuple
    #: driven angles in the reference period where U' jumps (corners of both pitch curves)
    corner_phis: tuple
    #: the one-float functions (``U_derivs1``, ``theta1``) reproduce the array ones bit for bit and
    #: the solvers may use them
    scalar_path: bool

    def U(self, phi): ...

    def dU_dphi(self, phi): ...

    def d2U_dphi2(self, phi): ...

    def theta(self, phi): ...

    def phi_of_theta(self, theta): ...

    def U_derivs1(self, phi: float) -> tuple: ...

    def theta1(self, phi: float) -> float: ...


def require_law(law) -> None:
    """InputError unless ``law`` is a law (``Law``) whose driver curve closes: n divides the periods."""
    if not isinstance(law, Law):
        raise InputError("law", type(law).__name__, "must be a drive law (laws.law.Law: U, theta, period, n)")
    if law.periods < 1 or law.periods % law.n:
        raise InputError(
            "n", law.n,
            f"the driver pitch curve repeats every n periods of the law and closes only if n divides its "
            f"{law.periods} periods per driven turn",
        )
    if not abs(law.periods * law.period - 2 * math.pi) < 1e-12:
        raise InputError("period", law.period, f"{law.periods} periods must make one driven turn (2 pi)")


def is_walking(law) -> bool:
    """The law is the walking law (exact or blended): it has a hub, and a hub speed to report."""
    return getattr(law, "kind", "") == "walking"
