"""Drive law of the driving wheel-walking propulsor (seeds 000 and 002).

One leg supports the hub for a quarter turn of the carrier (driven wheel),
phi in [-pi/4, pi/4]; four legs share the turn, so every quantity below is the
periodic extension with period pi/2 (docs/architecture.md, «drive law»): w = wrap(phi) in
[-pi/4, pi/4) and cos 2w, never cos 2phi over the whole turn.

    Y01 = a - b + c = A                         seed 000, eq. 1
    dX01/dphi = A + 3 b cos 2w                  seed 000, eq. 2
    U(phi) = d theta / d phi = u (A + 3 b cos 2w) / A      seed 000, eq. 14-15
    u = n pi A / (A pi + 6 b)                   seed 000, eq. 10 (n = 2), seed 002 (n = 4)
    theta(phi) = (u/A) (A phi + 3b/2 sin 2w + 3 b k),  phi = w + k pi/2
                                                seed 000, eq. 9/11 with the periodic wrap
    v / omega = (dX01/dphi) / U = A / u = const seed 000, text after eq. 3

All lengths in mm, angles in rad.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from propulsor.errors import InputError, require_finite
from propulsor.laws.walking_kernels import walking_many
from propulsor.policy import PHI_OF_THETA_TOL_RAD

#: one leg's support phase: the law's period in the driven angle phi (rad)
LEG_PERIOD = math.pi / 2
#: number of legs sharing one turn of the carrier
LEGS = 4


def wrap_leg(phi):
    """Leg-local angle w = wrap(phi) into [-pi/4, pi/4) (docs/architecture.md, «drive law»)."""
    phi = np.asarray(phi, dtype=float)
    return phi - LEG_PERIOD * np.floor((phi + math.pi / 4) / LEG_PERIOD)


def wrap_leg1(phi: float) -> float:
    """``wrap_leg`` of one finite float: the same operations in ``math`` (bit-identical, without
    the array overhead; for the one-point calls of the solvers)."""
    return phi - LEG_PERIOD * math.floor((phi + math.pi / 4) / LEG_PERIOD)


def leg_index(phi):
    """Whole number k of leg periods with phi = w + k pi/2, w = wrap_leg(phi)."""
    phi = np.asarray(phi, dtype=float)
    return np.floor((phi + math.pi / 4) / LEG_PERIOD)


def check_n_closes(n: int) -> None:
    """InputError unless n driver turns per driven turn close the pair: the driver pitch curve
    repeats every n*pi/2, so n must divide the 4 legs."""
    if 4 % n != 0:
        raise InputError(
            "n", n,
            "the driver pitch curve repeats every n*pi/2 and closes only if n divides the 4 legs: n in {1, 2, 4}",
        )


def invert_theta(law, theta, phi0, tol: float, max_iter: int):
    """phi with law.theta(phi) = theta: Newton from phi0 on the monotone theta (U > 0), until
    every step is below tol or after max_iter steps.  ``law``: any law with theta(phi), U(phi)."""
    phi = phi0
    for _ in range(max_iter):
        step = (law.theta(phi) - theta) / law.U(phi)
        phi = phi - step
        if np.all(np.abs(step) < tol):
            break
    return phi


def _length(name: str, value) -> float:
    v = require_finite(name, value)
    if v < 0:
        raise InputError(name, value, "a length must be >= 0 mm")
    return v


@dataclass(frozen=True)
class WalkingLaw:
    """Constant-hub-speed gear-ratio law of the driving wheel-walking propulsor.

    a: hub-to-crank axis distance (mm), b: crank length (mm), c: shoe stand
    length (mm), n: whole driver turns per driven (carrier) turn.
    Seed 000: a = 60, b = 100, c = 360, n = 2.  Seed 002: a = 100, b = 50,
    c = 236.5, n = 4.
    """

    a: float
    b: float
    c: float
    n: int

    # ---- the law interface (``laws.law.Law``) ---------------------------------------
    kind = "walking"
    #: the array functions give each angle the value it gets alone (law.py: ``elementwise``)
    elementwise = True
    period = LEG_PERIOD
    period_start = -math.pi / 4
    periods = LEGS
    #: the one-float functions are used by the array paths' callers only (``laws.law.Law``)
    scalar_path = False

    @property
    def breakpoints(self) -> tuple:
        """Ends of the smooth pieces of one leg: the leg itself (the corner sits at its ends)."""
        return (-math.pi / 4, math.pi / 4)

    @property
    def corner_phis(self) -> tuple:
        """The leg hand-over phi = pi/4, where U' jumps (b > 0)."""
        return (math.pi / 4,) if self.b > 0 else ()

    def __post_init__(self):
        a = _length("a", self.a)
        b = _length("b", self.b)
        c = _length("c", self.c)
        object.__setattr__(self, "a", a)
        object.__setattr__(self, "b", b)
        object.__setattr__(self, "c", c)
        nf = require_finite("n", self.n)
        if nf != round(nf):
            raise InputError("n", self.n, "driver turns per driven turn must be a whole number")
        if nf < 1:
            raise InputError("n", self.n, "driver turns per driven turn must be >= 1")
        object.__setattr__(self, "n", int(round(nf)))
        A = a - b + c
        if not A > 0:
            raise InputError(
                "a - b + c", A, "hub height Y01 = a - b + c must be > 0 mm, else the law is not positive"
            )
        # constants of the hot functions, cached by the expressions the properties / functions use
        # (not dataclass fields: equality, hashing and repr stay those of (a, b, c, n))
        object.__setattr__(self, "_A", A)
        object.__setattr__(self, "_u", self.n * math.pi * A / (A * math.pi + 6 * b))
        object.__setattr__(self, "_3b", 3 * b)
        object.__setattr__(self, "_m6bu", -6 * b * self._u)
        object.__setattr__(self, "_m12bu", -12 * b * self._u)
        object.__setattr__(self, "_uA", self._u / A)
        object.__setattr__(self, "_15b", 1.5 * b)
        # U > 0 everywhere needs no check of its own: with A > 0 and b >= 0, U = u (A + 3b cos 2w) / A >= u > 0
        # (cos 2w in [0, 1] on a leg)

    # ---- constants -----------------------------------------------------------
    @property
    def A(self) -> float:
        """Hub height Y01 = a - b + c (mm), seed 000 eq. 1."""
        return self._A

    @property
    def Y01(self) -> float:
        """Hub height above the support surface (mm), seed 000 eq. 1."""
        return self.A

    @property
    def u(self) -> float:
        """Reduced ratio coefficient u = n pi A / (A pi + 6 b), seed 000 eq. 10 generalised to n."""
        return self._u

    @property
    def hub_speed_ratio(self) -> float:
        """v / omega = Y01 / u (mm per rad of the driver), constant; seed 000 after eq. 8."""
        return self.A / self.u

    @property
    def U_min(self) -> float:
        """Smallest ratio (at leg hand-over w = +-pi/4 when b > 0)."""
        return self.u * min(self.A, self.A + 3 * self.b) / self.A

    @property
    def U_max(self) -> float:
        """Largest ratio (mid-support w = 0 when b > 0)."""
        return self.u * max(self.A, self.A + 3 * self.b) / self.A

    # ---- functions of the driven angle phi ------------------------------------
    def dX01_dphi(self, phi):
        """Horizontal hub speed analogue dX01/dphi = A + 3 b cos 2w (mm/rad), seed 000 eq. 2."""
        return self._A + self._3b * np.cos(2 * wrap_leg(phi))

    def U(self, phi):
        """Gear ratio U = d theta / d phi = u (A + 3b cos 2w)/A, seed 000 eq. 15 (periodic)."""
        return self._many(phi, 0)

    def dU_dphi(self, phi):
        """dU/dphi = -6 b u sin 2w / A (jumps at w = +-pi/4: docs/architecture.md, «drive law»)."""
        return self._many(phi, 1)

    def _many(self, phi, what: int):
        """``U`` (what 0) or ``dU_dphi`` (1) of an array of angles, shaped as phi: compiled, each angle by the
        operations numpy does on it (:func:`.walking_kernels.walking_many`)."""
        phi = np.asarray(phi, dtype=float)
        out = walking_many(np.ascontiguousarray(phi.ravel()), what, self._u, self._A, self._3b,
                           self._m6bu).reshape(phi.shape)
        return out[()] if out.ndim == 0 else out  # one angle: a numpy scalar, as numpy's operations give

    def d2U_dphi2(self, phi):
        """d2U/dphi2 = -12 b u cos 2w / A."""
        return self._m12bu * np.cos(2 * wrap_leg(phi)) / self._A

    def theta(self, phi):
        """Driver angle theta(phi) = integral_0^phi U dphi, exact closed form with the wrap.

        Seed 000 eq. 9/11 per leg; each whole leg period adds the integral of
        cos 2w over [-pi/4, pi/4), which is 1, so theta(2 pi) = 2 pi n exactly.
        """
        w = wrap_leg(phi)
        k = leg_index(phi)
        phi = np.asarray(phi, dtype=float)
        return self._uA * (self._A * phi + self._15b * np.sin(2 * w) + self._3b * k)

    # ---- the same functions of one finite float phi (``math``, bit-identical to the above) ----
    def U_derivs1(self, phi: float) -> tuple[float, float, float]:
        """(``U``, ``dU_dphi``, ``d2U_dphi2``) at one driven angle (float)."""
        w2 = 2 * wrap_leg1(phi)
        c = math.cos(w2)
        A = self._A
        return self._u * (A + self._3b * c) / A, self._m6bu * math.sin(w2) / A, self._m12bu * c / A

    def theta1(self, phi: float) -> float:
        """``theta`` at one driven angle (float)."""
        k = math.floor((phi + math.pi / 4) / LEG_PERIOD)
        w = phi - LEG_PERIOD * k
        return self._uA * (self._A * phi + self._15b * math.sin(2 * w) + self._3b * k)

    def hub_speed(self, phi):
        """v / omega = (dX01/dphi) / U (mm per rad of the driver); constant = A/u for this law."""
        return self.dX01_dphi(phi) / self.U(phi)

    def phi_of_theta(self, theta, tol: float = PHI_OF_THETA_TOL_RAD):
        """Inverse of theta(phi) (Newton on the monotone theta, U > 0)."""
        theta = np.asarray(theta, dtype=float)
        return invert_theta(self, theta, theta * (2 * math.pi) / (2 * math.pi * self.n), tol, 60)

    # ---- the papers' reading without the wrap (why the law is wrapped per leg) ------------
    def theta_unwrapped(self, phi):
        """theta if cos 2phi were (wrongly) used over the whole turn (docs/architecture.md, «drive law»).

        u/A (A phi + 3b/2 sin 2phi): over a full turn it gives u * 2 pi, i.e.
        1.25 driver turns for seed 000 instead of 2.  Only for demonstration.
        """
        phi = np.asarray(phi, dtype=float)
        return (self.u / self.A) * (self.A * phi + 1.5 * self.b * np.sin(2 * phi))


@dataclass(frozen=True)
class HubSpeedRipple:
    """Hub speed v/omega over the cycle: ripple = (max - min) / mean and where it sits.

    mean is the time (driver-angle) mean: leg travel / driver angle per leg, which
    is A/u for every law that closes (n whole driver turns per driven turn).
    phi_min / phi_max: driven angles (rad) of the extremes within one leg.
    """

    ripple: float
    mean: float
    v_min: float
    v_max: float
    phi_min: float
    phi_max: float


SEED_000 = dict(a=60.0, b=100.0, c=360.0, n=2)
SEED_002 = dict(a=100.0, b=50.0, c=236.5, n=4)
