"""Pitch curves of the non-circular pair of the wheel-walking propulsor drive, or of any drive law
(``laws.law.Law``: the walking law, its blend, elliptical, Fourier, table, pitch-curve laws).

Driven (carrier) wheel r_H(phi), driver r(theta) for centre distance L and a
ratio law U(phi) = d theta / d phi (seed 000, eqs. 4-7, 12-13):

    r_H = L U / (1 + U),   r = L / (1 + U),   r + r_H = L

Tooth spacing is true arc length ds = sqrt(r^2 + r'^2) dphi (docs/architecture.md, «closure»);
whole tooth counts fix L for a module (closure).  Radius of curvature of a
polar curve r(psi):  rho = (r^2 + r'^2)^(3/2) / (r^2 + 2 r'^2 - r r'')
(> 0 convex, < 0 concave).

The exact law has corners at leg hand-over (docs/architecture.md, «drive law»); the product replaces
U on a window |phi - (pi/4 + k pi/2)| < delta by an even degree-6 polynomial
that matches U, U', U'' at the window ends (C2) and keeps the window integral
of U, so closure (n whole driver turns per driven turn) stays exact and U is
unchanged outside the windows; delta is chosen as the smallest that keeps both
pitch curves generable (rack undercut limit on convex parts, shaper cutter or
no concavity on concave parts).  The price is the hub speed ripple inside the
windows.  Method background: Litvin & Fuentes-Aznar, Noncircular Gears (2009).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from propulsor.errors import InputError, require_finite, require_positive
from propulsor.laws.law import require_law
from propulsor.laws.walking import HubSpeedRipple
from propulsor.policy import CORNER_SIDE_RAD, MINIMIZE_XATOL, ROOT_XTOL_FINE, TOOTH_COUNT_TOL

from .smoothed_law import SmoothedWalkingLaw  # the smoothed law, re-exported here for the callers

_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(96)
#: samples per smooth piece of one leg when searching curvature / speed extremes
_SAMPLES_PER_PIECE = 600
#: most sign changes of a pitch curve's curvature over one period (32 concave stretches): a law past it is
#: noise no cutter follows, refused before its root-findings (one per change) take minutes
MAX_CURVATURE_FLIPS = 64
#: default largest smoothing half-width searched (rad of the driven wheel)
DELTA_MAX_DEFAULT = math.pi / 8


def leg_breakpoints(law) -> tuple:
    """Ends of the smooth pieces of the law's reference period (one leg of the walking law,
    phi in [-pi/4, pi/4]; the blend windows' ends): ``law.breakpoints``."""
    return law.breakpoints


def _has_corners(law) -> bool:
    return bool(law.corner_phis)


def _leg_samples(law, per_piece: int = _SAMPLES_PER_PIECE) -> np.ndarray:
    bp = leg_breakpoints(law)
    parts = []
    for a, b in zip(bp[:-1], bp[1:]):
        # cosine spacing: dense at the piece ends, where the extremes sit
        s = 0.5 * (1 - np.cos(np.linspace(0.0, math.pi, per_piece)))
        parts.append(a + (b - a) * s)
    return np.unique(np.concatenate(parts))


def _leg_integral(law, f) -> float:
    """integral over the law's reference period (one leg, phi in [-pi/4, pi/4]) of f(phi),
    Gauss-Legendre per smooth piece."""
    bp = leg_breakpoints(law)
    total = 0.0
    for a, b in zip(bp[:-1], bp[1:]):
        x = 0.5 * (b - a) * _GAUSS_X + 0.5 * (a + b)
        total += 0.5 * (b - a) * float(np.dot(_GAUSS_W, f(x)))
    return total


def _extreme(f, x, y, which: str):
    """Refine the sampled min (or max) of f: returns (x*, f(x*))."""
    k = int(np.argmin(y) if which == "min" else np.argmax(y))
    lo, hi = x[max(k - 1, 0)], x[min(k + 1, len(x) - 1)]
    sgn = 1.0 if which == "min" else -1.0
    best = (float(x[k]), float(y[k]))
    if hi > lo:
        # f may be inf off its side of a change of curvature (_on_side): Brent's parabola through inf values is
        # nan, and it takes a golden-section step instead, silently (no RuntimeWarning on the user's terminal)
        with np.errstate(invalid="ignore"):
            res = minimize_scalar(lambda p: sgn * float(f(p)), bounds=(lo, hi), method="bounded",
                                  options={"xatol": MINIMIZE_XATOL})
        if res.fun < sgn * best[1]:  # res.fun is sgn f (a maximum was never refined: the sample stayed)
            best = (float(res.x), float(sgn * res.fun))
    return best


def _on_side(f, sign: float):
    """|f(p)| where f has the sign ``sign`` (+1: a convex radius, -1: a concave one), else inf: the refinement of
    one side's extreme stays on that side of a change of curvature."""
    def g(p):
        v = float(f(p))
        return abs(v) if sign * v > 0 else math.inf
    return g


def hub_speed_ripple(law) -> HubSpeedRipple:
    """Hub speed ripple (max - min)/mean of v/omega = (dX01/dphi)/U over the cycle.

    Works for WalkingLaw (ripple 0: the exact law is the constant-speed law)
    and SmoothedWalkingLaw.  mean = time mean = A/u (docs/architecture.md, «drive law»).
    """
    phi = _leg_samples(law)
    v = law.hub_speed(phi)
    f = law.hub_speed
    pmin, vmin = _extreme(f, phi, v, "min")
    pmax, vmax = _extreme(f, phi, v, "max")
    mean = law.hub_speed_ratio
    return HubSpeedRipple(ripple=(vmax - vmin) / mean, mean=mean, v_min=vmin, v_max=vmax,
                          phi_min=pmin, phi_max=pmax)


# =========================================================================== pitch curves
def _finite(p) -> bool:
    """p is one finite real number (a solver's one-point call)."""
    return isinstance(p, (float, int)) and math.isfinite(p)


def _rho(r, dr, d2r):
    """Signed radius of curvature of a polar curve (> 0 convex, < 0 concave)."""
    return (r * r + dr * dr) ** 1.5 / (r * r + 2 * dr * dr - r * d2r)


@dataclass(frozen=True)
class Corner:
    """A corner of a pitch curve of the exact law (docs/architecture.md, «drive law»)."""

    curve: str          #: 'driven' or 'driver'
    phi: float          #: driven angle of the hand-over (rad)
    angle: float        #: polar angle on that curve (phi for driven, theta for driver), rad
    turn: float         #: tangent turn across the corner (rad), > 0
    kind: str           #: 'concave' (notch) or 'convex' (sharp tip, rho -> 0)


@dataclass(frozen=True)
class PitchCurves:
    """Pitch curves of the pair for centre distance L (mm) and a ratio law.

    law: any drive law (``laws.law.Law``): the walking law (exact, with corners), its blend, ...
    Driven curve: polar r_H(phi), phi the driven body angle.  Driver curve:
    polar r(theta); functions named r*(phi) give the driver radius and its
    theta-derivatives at the point in contact when the driven angle is phi
    (theta = law.theta(phi)).  Seed 000 eqs. 12-13.
    Angles are body polar angles: in mesh the driven point at body angle phi
    touches the driver point at body angle theta(phi) on the line of centres;
    the two wheels turn in opposite senses.
    """

    law: object
    L: float

    def __post_init__(self):
        require_law(self.law)
        object.__setattr__(self, "L", require_positive("L", self.L, "mm"))

    # ---- driven ---------------------------------------------------------------------
    def r_H(self, phi):
        """Driven pitch radius r_H = L U/(1+U), seed 000 eq. 6/12."""
        U = self.law.U(phi)
        return self.L * U / (1 + U)

    def dr_H(self, phi):
        U, dU = self.law.U(phi), self.law.dU_dphi(phi)
        return self.L * dU / (1 + U) ** 2

    def d2r_H(self, phi):
        U, dU, d2U = self.law.U(phi), self.law.dU_dphi(phi), self.law.d2U_dphi2(phi)
        return self.L * (d2U / (1 + U) ** 2 - 2 * dU * dU / (1 + U) ** 3)

    def pitch1(self, phi: float):
        """(U, r_H, dr_H) at one finite float phi: the operations of ``law.U``, ``r_H``, ``dr_H`` on
        an array, in ``math`` (bit-identical; (1 + U)**2 of an array is its square)."""
        U, dU, _ = self.law.U_derivs1(phi)
        q = 1 + U
        return U, self.L * U / q, self.L * dU / (q * q)

    def rho_H(self, phi):
        """Signed radius of curvature of the driven pitch curve at phi (mm)."""
        return _rho(self.r_H(phi), self.dr_H(phi), self.d2r_H(phi))

    # ---- driver ---------------------------------------------------------------------
    def r(self, phi):
        """Driver pitch radius r = L/(1+U) at the contact for driven angle phi, seed 000 eq. 7/13."""
        return self.L / (1 + self.law.U(phi))

    def r_theta(self, phi):
        """dr/dtheta = (dr/dphi)/U."""
        U = self.law.U(phi)
        return -self.dr_H(phi) / U

    def r_thetatheta(self, phi):
        """d2r/dtheta2 = (r_phiphi U - r_phi U')/U^3."""
        U, dU = self.law.U(phi), self.law.dU_dphi(phi)
        r_p, r_pp = -self.dr_H(phi), -self.d2r_H(phi)
        return (r_pp * U - r_p * dU) / U**3

    def rho(self, phi):
        """Signed radius of curvature of the driver pitch curve at the contact for driven angle phi (mm)."""
        return _rho(self.r(phi), self.r_theta(phi), self.r_thetatheta(phi))

    def driver_radius(self, theta):
        """Driver pitch curve in polar form r(theta) (theta: driver body angle, rad)."""
        return self.r(self.law.phi_of_theta(theta))

    def driven_xy(self, phi):
        """Points (N, 2) of the driven pitch curve, polar angle phi."""
        phi = np.asarray(phi, dtype=float)
        rr = self.r_H(phi)
        return np.stack([rr * np.cos(phi), rr * np.sin(phi)], axis=-1)

    def driver_xy(self, theta):
        """Points (N, 2) of the driver pitch curve, polar angle theta."""
        theta = np.asarray(theta, dtype=float)
        rr = self.driver_radius(theta)
        return np.stack([rr * np.cos(theta), rr * np.sin(theta)], axis=-1)

    # ---- arc length / closure -------------------------------------------------------
    def ds_dphi(self, phi):
        """True arc length rate of the driven curve sqrt(r_H^2 + r_H'^2) (docs/architecture.md, «closure»)."""
        return np.hypot(self.r_H(phi), self.dr_H(phi))

    def perimeter_driven(self) -> float:
        """Perimeter of the driven pitch curve (mm) = its periods (4 legs of the walking law) x one."""
        return self.law.periods * _leg_integral(self.law, self.ds_dphi)

    def perimeter_driver(self) -> float:
        """Perimeter of the driver pitch curve over one driver turn (mm), integrated in theta.

        Independent of the rolling identity: integral over one driver turn,
        theta in [theta(-pi/4), theta(-pi/4) + 2 pi], of sqrt(r^2 + (dr/dtheta)^2),
        pieces split at the images of the law's breakpoints (needs n | 4).
        """
        n = self.law.n
        legs = self.law.periods // n  # driver turn = periods/n periods (legs) of the driven wheel
        bp = leg_breakpoints(self.law)
        phis = sorted({k * self.law.period + w for k in range(legs) for w in bp})
        ths = self.law.theta(np.array(phis))
        total = 0.0
        for a, b in zip(ths[:-1], ths[1:]):
            th = 0.5 * (b - a) * _GAUSS_X + 0.5 * (a + b)
            ph = self.law.phi_of_theta(th)
            total += 0.5 * (b - a) * float(np.dot(_GAUSS_W, np.hypot(self.r(ph), self.r_theta(ph))))
        return total

    # ---- corners / curvature ------------------------------------------------------
    def corners(self) -> list[Corner]:
        """Corners of both pitch curves (the law's ``corner_phis``; [] for a smooth law).

        One notch/tip per period on the driven curve (4: one per hand-over of the walking law),
        periods/n on the driver body (its corners repeat every turn).  angle: body polar angle.
        """
        if not _has_corners(self.law):
            return []
        out = []
        eps = CORNER_SIDE_RAD
        seen = set()
        at = [c + k * self.law.period for k in range(self.law.periods) for c in self.law.corner_phis]
        for ph in at:
            for curve in ("driven", "driver"):
                if curve == "driver":  # the driver turns n times: periods/n distinct tips on its body
                    key = round(float(self.law.theta(ph)) % (2 * math.pi), 9)
                    if key in seen:
                        continue
                    seen.add(key)
                if curve == "driven":
                    r, d_minus, d_plus = self.r_H(ph), self.dr_H(ph - eps), self.dr_H(ph + eps)
                    ang = ph
                else:
                    r, d_minus, d_plus = self.r(ph), self.r_theta(ph - eps), self.r_theta(ph + eps)
                    ang = float(self.law.theta(ph))
                # tangent direction relative to the radius: beta = atan2(r, r')
                jump = math.atan2(float(r), float(d_plus)) - math.atan2(float(r), float(d_minus))
                out.append(Corner(curve=curve, phi=ph, angle=ang, turn=abs(jump),
                                  kind="convex" if jump > 0 else "concave"))
        return out

    def _polar_derivatives(self, curve: str, phi: np.ndarray):
        """(r, r', r'') arrays of curve 'driven' (``r_H``, ``dr_H``, ``d2r_H``) or 'driver' (``r``,
        ``r_theta``, ``r_thetatheta``) at the angles phi (an array), with U, U', U'' evaluated once:
        the expressions of those functions."""
        law, L = self.law, self.L
        U, dU, d2U = law.U(phi), law.dU_dphi(phi), law.d2U_dphi2(phi)
        dr_H = L * dU / (1 + U) ** 2
        d2r_H = L * (d2U / (1 + U) ** 2 - 2 * dU * dU / (1 + U) ** 3)
        if curve == "driven":
            return L * U / (1 + U), dr_H, d2r_H
        r_p, r_pp = -dr_H, -d2r_H
        return L / (1 + U), -dr_H / U, (r_pp * U - r_p * dU) / U**3

    def polar_derivatives1(self, curve: str, p: float) -> tuple[float, float, float]:
        """(r, r', r'') of curve 'driven' (``r_H``, ``dr_H``, ``d2r_H``) or 'driver' (``r``,
        ``r_theta``, ``r_thetatheta``) at one finite float p, for a ``SmoothedWalkingLaw``: the
        operations those functions do for a scalar phi, in ``math`` (bit-identical).  There U, U',
        U'' are 0-d arrays, so U**3 is the array power; 1 + U is a numpy scalar, so (1 + U)**k is
        the scalar (libm) power, as a float's."""
        law, L = self.law, self.L
        p = float(p)
        U, dU, d2U = law.U_derivs1(p)
        r_H = L * U / (1 + U)
        dr_H = L * dU / (1 + U) ** 2
        d2r_H = L * (d2U / (1 + U) ** 2 - 2 * dU * dU / (1 + U) ** 3)
        if curve == "driven":
            r, d, dd = r_H, dr_H, d2r_H
        else:
            r = L / (1 + U)
            d = -dr_H / U
            r_p, r_pp = -dr_H, -d2r_H
            dd = (r_pp * U - r_p * dU) / float(np.array(U) ** 3)
        return r, d, dd

    def curvature(self, curve: str) -> "CurvatureSummary":
        """Radius-of-curvature summary of one curve ('driven' or 'driver') over the cycle; computed once per
        pair and curve (every cutter tried against these curves reads the same summary)."""
        if curve not in ("driven", "driver"):
            raise InputError("curve", curve, "must be 'driven' or 'driver'")
        cache = self.__dict__.setdefault("_curvature_cache", {})
        if curve not in cache:
            cache[curve] = self._curvature(curve)
        return cache[curve]

    def _curvature(self, curve: str) -> "CurvatureSummary":
        f_arr = self.rho_H if curve == "driven" else self.rho
        if curve == "driven":
            def den_arr(p):
                r, d, dd = self.r_H(p), self.dr_H(p), self.d2r_H(p)
                return r * r + 2 * d * d - r * dd
        else:
            def den_arr(p):
                r, d, dd = self.r(p), self.r_theta(p), self.r_thetatheta(p)
                return r * r + 2 * d * d - r * dd
        if self.law.scalar_path:
            # the solvers' one-point calls (floats) in math, bit-identical (``polar_derivatives1``)
            def f(p):
                if not _finite(p):
                    return f_arr(p)
                r, d, dd = self.polar_derivatives1(curve, p)
                return _rho(np.float64(r), d, dd)  # numpy division: +-inf where the denominator is 0

            def den(p):
                if not _finite(p):
                    return den_arr(p)
                r, d, dd = self.polar_derivatives1(curve, p)
                return r * r + 2 * d * d - r * dd
        else:
            f, den = f_arr, den_arr
        phi = _leg_samples(self.law)
        r, d, dd = self._polar_derivatives(curve, phi)
        D = r * r + 2 * d * d - r * dd  # = den_arr(phi), rho = f_arr(phi): U, U', U'' computed once
        rho = _rho(r, d, dd)
        convex = D > 0
        concave = D < 0
        # the extremes refined between neighbouring samples of the whole grid, on their side of the curvature (a
        # stretch narrower than a sample's spacing otherwise put a concave radius, -1.6e8 mm, in the convex least)
        cx = (_extreme(_on_side(f, 1.0), phi, np.where(convex, rho, math.inf), "min") if np.any(convex)
              else (math.nan, math.inf))
        # concave intervals from sign changes of the denominator
        intervals = []
        if np.any(concave):
            s = np.sign(D)
            flips = np.flatnonzero((s[:-1] != s[1:]) & (s[:-1] != 0) & (s[1:] != 0))
            if len(flips) > MAX_CURVATURE_FLIPS:  # a noisy law: its root-findings would grow with the noise
                raise InputError(getattr(self.law, "key", "law"), f"{len(flips)} changes of curvature",
                                 f"the {curve} pitch curve turns from convex to concave and back {len(flips)} times "
                                 f"over one period, more than {MAX_CURVATURE_FLIPS}: no cutter generates such a curve; "
                                 "a smoother law (fewer or smoother rows of a table)")
            edges = []
            for k in flips:
                edges.append(brentq(lambda p: float(den(p)), phi[k], phi[k + 1], xtol=ROOT_XTOL_FINE))
            bp = leg_breakpoints(self.law)
            lo = bp[0]
            pts = [lo] + edges + [bp[-1]]
            for a, b in zip(pts[:-1], pts[1:]):
                if den(0.5 * (a + b)) < 0:
                    intervals.append((a, b))
            cc = _extreme(_on_side(f, -1.0), phi, np.where(concave, np.abs(rho), math.inf), "min")
            cc_phi, cc_rho = cc
        else:
            cc_phi, cc_rho = math.nan, math.inf
        corners = [c for c in self.corners() if c.curve == curve and c.phi in self.law.corner_phis]
        corner = corners[0] if corners else None
        rho_convex_min = cx[1]
        phi_convex = cx[0]
        if corner is not None and corner.kind == "convex":
            rho_convex_min, phi_convex = 0.0, corner.phi
        if corner is not None and corner.kind == "concave":
            cc_rho, cc_phi = 0.0, corner.phi
            intervals = intervals or [(corner.phi, corner.phi)]
        return CurvatureSummary(
            curve=curve, rho_convex_min=float(rho_convex_min), phi_convex_min=float(phi_convex),
            concave=bool(intervals),  # a concave corner is an interval of its own (above)
            rho_concave_min=float(cc_rho), phi_concave_min=float(cc_phi),
            concave_intervals=tuple(intervals), corner=corner,
        )


@dataclass(frozen=True)
class CurvatureSummary:
    """Radius of curvature of one pitch curve over one period of the law (one leg of the walking law;
    angles: driven phi, period-local).

    rho_convex_min: smallest radius on convex parts (0 at a convex corner);
    rho_concave_min: smallest |radius| on concave parts (inf if none, 0 at a
    concave corner); concave_intervals: leg-local phi intervals where concave.
    """

    curve: str
    rho_convex_min: float
    phi_convex_min: float
    concave: bool
    rho_concave_min: float
    phi_concave_min: float
    concave_intervals: tuple
    corner: Corner | None


# =========================================================================== closure
def perimeter_per_mm(law) -> float:
    """Driven pitch-curve perimeter for L = 1 mm (the perimeter is linear in L)."""
    return PitchCurves(law, 1.0).perimeter_driven()


def whole_teeth(name: str, z, n: int) -> int:
    """z as a whole tooth count >= 1 that is a multiple of n (InputError naming ``name``)."""
    fz = require_finite(name, z)
    if fz != round(fz) or fz < 1:
        raise InputError(name, z, "tooth count must be a whole number >= 1")
    z = int(round(fz))
    if z % n:
        lo, hi = (z // n) * n, (z // n + 1) * n
        raise InputError(name, z, f"must be a multiple of n = {n} so the driver has z_H/n whole teeth",
                         f"nearest valid: {lo if lo > 0 else hi}, {hi}")
    return z


def centre_distance(law, m: float, z_H: int) -> float:
    """L such that the driven pitch curve carries z_H teeth of module m: perimeter = pi m z_H (docs/architecture.md, «closure»).

    The driver then carries z_H / n teeth (its perimeter is the driven's / n).
    """
    m = require_positive("m", m, "mm")
    z_H = whole_teeth("z_H", z_H, law.n)
    return math.pi * m * z_H / perimeter_per_mm(law)


def module_for(law, L: float, z_H: int) -> float:
    """Module m that closes the driven curve with z_H teeth at centre distance L."""
    L = require_positive("L", L, "mm")
    z_H = whole_teeth("z_H", z_H, law.n)
    return L * perimeter_per_mm(law) / (math.pi * z_H)


def driven_teeth(law, L: float, m: float) -> int:
    """Whole driven tooth count for centre distance L and module m, or InputError naming the nearest valid ones."""
    L = require_positive("L", L, "mm")
    m = require_positive("m", m, "mm")
    P1 = perimeter_per_mm(law)
    z = L * P1 / (math.pi * m)
    n = law.n
    if abs(z - round(z)) < TOOTH_COUNT_TOL and round(z) % n == 0 and round(z) > 0:
        return int(round(z))
    lo = max(n, int(math.floor(z / n)) * n)
    hi = lo + n if lo * 1.0 < z else lo
    parts = []
    for zz in sorted({lo, hi}):
        parts.append(f"z_H = {zz}: L = {math.pi * m * zz / P1:.4f} mm at m = {m:g}, "
                     f"or m = {L * P1 / (math.pi * zz):.5f} mm at L = {L:g}")
    raise InputError("L", L, f"gives z_H = {z:.4f} teeth of m = {m:g}, not a whole multiple of n = {n}",
                     "nearest valid: " + "; ".join(parts))


def whole_pitches(perimeter: float, m: float) -> int:
    """Number z_H of pitches pi m on a closed pitch curve of this perimeter; InputError naming
    ``m`` unless it is whole (within ``policy.TOOTH_COUNT_TOL``)."""
    z = perimeter / (math.pi * m)
    if not abs(z - round(z)) < TOOTH_COUNT_TOL:
        raise InputError("m", m, f"the driven pitch curve ({perimeter:.6f} mm) holds {z:.6f} pitches, not a whole number")
    return int(round(z))
