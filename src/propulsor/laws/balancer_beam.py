"""The suspension balancer's lever arm as a beam (seed 004, ch. 8; loads from ch. 2).

Pure statics and strength of materials, no FE.  Frame of the balancer (mm, N):
origin O on the upper-axle axis in the arm's mid-plane; x along the arm from O to the
road-wheel axle W (|OW| = R_b); y in the plane of rotation, perpendicular to the arm,
positive in the direction the wheel force turns the balancer; z along the axles,
positive outboard (towards the road wheel).  The upper axle (hull bearings, torsion-bar
socket) extends to -z, the lower axle (wheel spindle) to +z.

With the balancer at angle beta from the downward vertical, the arm direction is
u = (sin beta, -cos beta) and y = (cos beta, sin beta) in the (horizontal, vertical)
plane, so an upward wheel force P has F_x = -P cos beta, F_y = P sin beta and the torque
about the axle P R_b sin beta - the torque of eq. 13.

Load cases (seed 004, §8.1: force D from the elastic characteristic, force E on the
damper ear from the compression damper characteristic, support B = torsion bar):
  * "beta_m elastic": wheel force P(beta_m) (eq. 13) at the wheel mid-plane z = e_w;
  * "beta_m + damper": rod force R_a,comp (eq. 28) at the ear (x = L_a, z = e_a,
    perpendicular to the arm, resisting), wheel force raised so that the torsion bar
    still carries M_T(beta_m);
  * "stop": wheel force k_stop P(beta_m) with the balancer on the stop pad (x = s_stop);
    the bar carries M_T(beta_m), the pad the rest.  k_stop is an assumption (the seed
    gives no stop load); default 2.
The torsion bar reacts the z-moment, two hull bearings (z = -a1, -a2) the forces and
the x/y moments.

Internal forces at station s (from the loads outboard of s): N = sum F_x,
V_y = sum F_y, T = -sum z F_y (arm torsion), M_y = sum z F_x (out-of-plane bending),
M_z = sum (s_k - s) F_y (in-plane bending).

Section: rectangle b (along z) x h (along y), optionally hollow with wall t.
Stresses at three candidate points (conservative combination, each point's normal stress
with the largest torsional shear of the section):
  faces y = +-h/2: sigma = |N|/A + |M_z|/W_z,          tau = tau_T
  faces z = +-b/2: sigma = |N|/A + |M_y|/W_y,          tau = tau_T + tau_V
  corners:         sigma = |N|/A + |M_z|/W_z + |M_y|/W_y, tau = 0 (solid) / tau_T (hollow)
sigma_vM = sqrt(sigma^2 + 3 tau^2).  Torsion of a solid rectangle: Saint-Venant series
(Timoshenko & Goodier, Theory of Elasticity, §109); hollow: Bredt, tau = T / (2 A_m t).
Shear: tau_V = V Q / (I w) at the neutral axis.

Axle-arm transitions: stepped round shaft with a shoulder fillet, Peterson's curve fits
(Pilkey & Pilkey, Peterson's Stress Concentration Factors, 3rd ed., Charts 3.10 bending
and 3.12 torsion; the same fits as Roark 7th ed. Table 17.1 case 17), h = (D - d)/2,
K_t = C1 + C2 (2h/D) + C3 (2h/D)^2 + C4 (2h/D)^3.

Material 40KhN2MA (40ХН2МА), yield 930 MPa after quench 850 C and temper (seed 004, §8.3).

Comparison with the seed's FE (§8.3: ~300 MPa through the body, 724 MPa at a singular
point): with the default geometry of ``BalancerGeometry`` (solid arm 60 x 120 mm, wheel
mid-plane 150 mm outboard - assumed, the seed prints no dimensions) the constant-section
arm reaches 301 MPa for the elastic load P(beta_m) = 93.6 kN and 340 MPa with the damper
ear force added (the FE's two forces D and E) - the FE's "~300 MPa" order.  At the
axle-arm fillets (r = 6 mm, K_t = 2.05 bending / 1.61 torsion at the upper axle, 1.96 at
the spindle) the peaks are 419 / 449 MPa (upper axle) and 307 / 384 MPa (spindle) for
the same two cases, below the FE's 724 MPa, which the seed itself calls a singularity
(a sharp corner or support point of the mesh, not a resolved fillet).  This is a
plausibility comparison, not a reproduction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq

from propulsor.check import Check
from propulsor.errors import InputError, require_finite, require_positive
from propulsor.policy import ROOT_XTOL, SECTION_DEPTH_XTOL_MM, STATICS_REL_TOL
from propulsor.laws.suspension import SuspensionDesign

#: yield strength of 40ХН2МА after quench 850 C and temper, MPa (seed 004, §8.3)
YIELD_40KhN2MA = 930.0
#: density of steel, kg/mm^3
RHO_STEEL = 7.85e-6


# ------------------------------------------------------------------- records
def _limit_check(name: str, value: float, limit: float, unit: str, kind: str = "max", note: str = "") -> Check:
    """value <= limit (kind "max") or value >= limit (kind "min"); the message is the note or the name."""
    passed = value <= limit if kind == "max" else value >= limit
    return Check(name, bool(passed), value, limit, unit, note or name)


@dataclass(frozen=True)
class PointLoad:
    """A force on the balancer: station s (mm from O along the arm), offset z (mm), F_x, F_y (N)."""

    name: str
    s: float
    z: float
    F_x: float
    F_y: float

    def __post_init__(self):
        for k in ("s", "z", "F_x", "F_y"):
            object.__setattr__(self, k, require_finite(f"{self.name}.{k}", getattr(self, k)))


@dataclass(frozen=True)
class LoadCase:
    name: str
    loads: tuple
    beta: float  # balancer angle, rad
    bar_torque_expected: float  # N mm, the torsion bar's own M_T(beta)


# ------------------------------------------------------------------- geometry
@dataclass(frozen=True)
class BalancerGeometry:
    """Balancer dimensions, mm (defaults: plausible values, the seed prints none).

    b: arm width along the axles; h: constant arm depth (reference section);
    t_wall: None for a solid arm, else the wall of a hollow rectangular arm;
    e_w: wheel mid-plane offset from the arm mid-plane; e_a: damper ear offset;
    s_stop: stop-pad station; a1, a2: hull bearing centres along -z (a1 < a2);
    d_upper, D_upper, r_upper: upper axle journal, its shoulder (arm boss) and fillet;
    d_lower, D_lower, r_lower: wheel spindle, shoulder, fillet;
    h_min, h_max: bounds of the equal-strength depth;
    d_upper_bore, d_lower_bore: bores through the journal / spindle at the shoulder fillet
    (0: solid), e.g. the torsion-bar retaining-bolt bore; the fillet check uses the hollow
    section moduli pi (d^4 - d_i^4) / (32 d) and / (16 d).
    """

    b: float = 60.0
    h: float = 120.0
    t_wall: float | None = None
    e_w: float = 150.0
    e_a: float = 0.0
    s_stop: float = 300.0
    a1: float = 60.0
    a2: float = 200.0
    d_upper: float = 110.0
    D_upper: float = 150.0
    r_upper: float = 6.0
    d_lower: float = 90.0
    D_lower: float = 130.0
    r_lower: float = 6.0
    h_min: float = 40.0
    h_max: float = 400.0
    d_upper_bore: float = 0.0
    d_lower_bore: float = 0.0

    def __post_init__(self):
        set_ = lambda k, v: object.__setattr__(self, k, v)  # noqa: E731
        for k in ("b", "h", "s_stop", "a1", "a2", "d_upper", "D_upper", "r_upper",
                  "d_lower", "D_lower", "r_lower", "h_min", "h_max"):
            set_(k, require_positive(k, getattr(self, k), "mm"))
        for k in ("e_w", "e_a"):
            set_(k, require_finite(k, getattr(self, k)))
        if self.t_wall is not None:
            t = require_positive("t_wall", self.t_wall, "mm")
            if not 2 * t < self.b:
                raise InputError("t_wall", self.t_wall, f"must be < b/2 = {self.b / 2:g} mm")
            if not 2 * t < self.h_min:
                raise InputError("t_wall", self.t_wall, f"must be < h_min/2 = {self.h_min / 2:g} mm")
            set_("t_wall", t)
        if not self.a1 < self.a2:
            raise InputError("a2", self.a2, f"second bearing must lie beyond a1 = {self.a1:g} mm")
        if not self.h_min < self.h_max:
            raise InputError("h_min", self.h_min, f"must be < h_max = {self.h_max:g} mm")
        if not self.D_upper > self.d_upper:
            raise InputError("D_upper", self.D_upper, f"shoulder must exceed the journal d_upper = {self.d_upper:g} mm")
        if not self.D_lower > self.d_lower:
            raise InputError("D_lower", self.D_lower, f"shoulder must exceed the spindle d_lower = {self.d_lower:g} mm")
        for k, outer in (("d_upper_bore", "d_upper"), ("d_lower_bore", "d_lower")):
            v = require_finite(k, getattr(self, k))
            if not 0.0 <= v < getattr(self, outer):
                raise InputError(k, getattr(self, k), f"must lie in [0, {outer} = {getattr(self, outer):g}) mm")
            set_(k, v)
        if not self.e_w > self.b / 2:
            raise InputError("e_w", self.e_w, f"wheel mid-plane must lie outboard of the arm face b/2 = {self.b / 2:g} mm")


# ------------------------------------------------------------ section properties
def _rect_torsion(long_side: float, short_side: float, n_terms: int = 40):
    """Saint-Venant torsion of a solid rectangle: (J, tau_max / T) (Timoshenko & Goodier §109)."""
    hh, bb = max(long_side, short_side), min(long_side, short_side)
    n = np.arange(1, 2 * n_terms, 2, dtype=float)
    x = n * math.pi * hh / (2.0 * bb)
    J = hh * bb**3 / 3.0 * (1.0 - 192.0 * bb / (math.pi**5 * hh) * np.sum(np.tanh(x) / n**5))
    # 1/cosh overflows gracefully to 0 for large x
    with np.errstate(over="ignore"):
        s = np.sum(1.0 / (n**2 * np.cosh(x)))
    k = bb / J * (1.0 - 8.0 / math.pi**2 * s)
    return J, k


@dataclass(frozen=True)
class RectSection:
    """Rectangular section b (along z) x h (along y), solid or hollow with wall t."""

    b: float
    h: float
    t: float | None = None

    def __post_init__(self):
        set_ = lambda k, v: object.__setattr__(self, k, v)  # noqa: E731
        set_("b", require_positive("b", self.b, "mm"))
        set_("h", require_positive("h", self.h, "mm"))
        if self.t is not None:
            t = require_positive("t", self.t, "mm")
            if not (2 * t < self.b and 2 * t < self.h):
                raise InputError("t", self.t, f"wall must be < half of min(b, h) = {min(self.b, self.h) / 2:g} mm")
            set_("t", t)

    @property
    def _inner(self):
        if self.t is None:
            return 0.0, 0.0
        return self.b - 2 * self.t, self.h - 2 * self.t

    @property
    def A(self) -> float:
        bi, hi = self._inner
        return self.b * self.h - bi * hi

    @property
    def I_z(self) -> float:
        """Second moment for in-plane bending (about z), mm^4."""
        bi, hi = self._inner
        return (self.b * self.h**3 - bi * hi**3) / 12.0

    @property
    def I_y(self) -> float:
        """Second moment for out-of-plane bending (about y), mm^4."""
        bi, hi = self._inner
        return (self.h * self.b**3 - hi * bi**3) / 12.0

    @property
    def W_z(self) -> float:
        return self.I_z / (self.h / 2.0)

    @property
    def W_y(self) -> float:
        return self.I_y / (self.b / 2.0)

    @property
    def J_t(self) -> float:
        """Torsion constant, mm^4 (Saint-Venant solid, Bredt hollow)."""
        if self.t is None:
            return _rect_torsion(self.h, self.b)[0]
        Am = (self.b - self.t) * (self.h - self.t)
        per = 2.0 * ((self.b - self.t) + (self.h - self.t))
        return 4.0 * Am**2 * self.t / per

    def tau_torsion(self, T):
        """Largest torsional shear, MPa."""
        if self.t is None:
            return np.abs(T) * _rect_torsion(self.h, self.b)[1]
        Am = (self.b - self.t) * (self.h - self.t)
        return np.abs(T) / (2.0 * Am * self.t)

    def tau_shear_y(self, V_y):
        """Transverse shear from V_y at the neutral axis, MPa: V Q / (I w)."""
        bi, hi = self._inner
        Q = (self.b * self.h**2 - bi * hi**2) / 8.0
        w = self.b - bi
        return np.abs(V_y) * Q / (self.I_z * w)

    def von_mises(self, N, V_y, T, M_y, M_z):
        """Largest von Mises stress over the three candidate points, MPa (arrays broadcast)."""
        sN = np.abs(N) / self.A
        sz = np.abs(M_z) / self.W_z
        sy = np.abs(M_y) / self.W_y
        tT = self.tau_torsion(T)
        tV = self.tau_shear_y(V_y)
        p1 = np.sqrt((sN + sz) ** 2 + 3.0 * tT**2)
        p2 = np.sqrt((sN + sy) ** 2 + 3.0 * (tT + tV) ** 2)
        tc = 0.0 if self.t is None else tT
        p3 = np.sqrt((sN + sz + sy) ** 2 + 3.0 * tc**2)
        return np.maximum(np.maximum(p1, p2), p3)


# ------------------------------------------------------- stress concentration
def kt_shoulder_fillet(D: float, d: float, r: float, load: str = "bending") -> float:
    """Peterson K_t of a stepped round shaft with shoulder fillet (Pilkey & Pilkey, Charts 3.10/3.12).

    Valid 0.1 <= h/r <= 20 in bending, 0.25 <= h/r <= 4 in torsion, h = (D - d)/2.
    """
    D = require_positive("D", D, "mm")
    d = require_positive("d", d, "mm")
    r = require_positive("r", r, "mm")
    if not D > d:
        raise InputError("D", D, f"shoulder must exceed the shaft d = {d:g} mm")
    h = (D - d) / 2.0
    x = h / r
    u = math.sqrt(x)
    if load == "bending":
        if not 0.1 <= x <= 20.0:
            raise InputError("r", r, f"h/r = {x:.4g} outside Peterson's bending fit 0.1 ... 20")
        if x <= 2.0:
            C = (0.947 + 1.206 * u - 0.131 * x, 0.022 - 3.405 * u + 0.915 * x,
                 0.869 + 1.777 * u - 0.555 * x, -0.810 + 0.422 * u - 0.260 * x)
        else:
            C = (1.232 + 0.832 * u - 0.008 * x, -3.813 + 0.968 * u - 0.260 * x,
                 7.423 - 4.868 * u + 0.869 * x, -3.839 + 3.070 * u - 0.600 * x)
    elif load == "torsion":
        if not 0.25 <= x <= 4.0:
            raise InputError("r", r, f"h/r = {x:.4g} outside Peterson's torsion fit 0.25 ... 4")
        C = (0.905 + 0.783 * u - 0.075 * x, -0.437 - 1.969 * u + 0.553 * x,
             1.557 + 1.073 * u - 0.578 * x, -1.061 + 0.171 * u + 0.086 * x)
    else:
        raise InputError("load", load, "must be 'bending' or 'torsion'")
    q = 2.0 * h / D
    return C[0] + C[1] * q + C[2] * q**2 + C[3] * q**3


# ------------------------------------------------------------------ statics
def moment_about(loads, p) -> np.ndarray:
    """Sum of (r - p) x F over the loads, N mm (3-vector)."""
    M = np.zeros(3)
    for L in loads:
        r = np.array([L.s, 0.0, L.z]) - np.asarray(p, dtype=float)
        M += np.cross(r, [L.F_x, L.F_y, 0.0])
    return M


@dataclass(frozen=True)
class Reactions:
    """Support reactions: two hull bearings (force vectors at z = -a1, -a2) and the bar torque."""

    bearing1: np.ndarray
    bearing2: np.ndarray
    bar_torque: float  # torque the bar applies about +z, N mm
    z1: float
    z2: float

    def residual(self, loads) -> tuple[np.ndarray, np.ndarray]:
        """Force and moment (about O) of loads + reactions: both ~0 when balanced."""
        F = sum((np.array([L.F_x, L.F_y, 0.0]) for L in loads), np.zeros(3)) + self.bearing1 + self.bearing2
        M = (moment_about(loads, (0, 0, 0))
             + np.cross([0.0, 0.0, self.z1], self.bearing1)
             + np.cross([0.0, 0.0, self.z2], self.bearing2)
             + np.array([0.0, 0.0, self.bar_torque]))
        return F, M


def reactions(loads, a1: float, a2: float) -> Reactions:
    """Bearing forces and bar torque balancing the loads (bearings at z = -a1, -a2)."""
    z1, z2 = -float(a1), -float(a2)
    F = sum((np.array([L.F_x, L.F_y, 0.0]) for L in loads), np.zeros(3))
    M = moment_about(loads, (0, 0, 0))
    # bearing j at (0, 0, z_j) with force (Bx, By, 0): moment (-z_j By, z_j Bx, 0)
    A = np.array([[1.0, 1.0], [z1, z2]])
    Bx = np.linalg.solve(A, [-F[0], -M[1]])
    By = np.linalg.solve(A, [-F[1], M[0]])
    return Reactions(np.array([Bx[0], By[0], 0.0]), np.array([Bx[1], By[1], 0.0]), -M[2], z1, z2)


def internal_forces(loads, s) -> dict[str, np.ndarray]:
    """N, V_y, T, M_y, M_z (N, N mm) at stations s from the loads outboard of each station."""
    s = np.atleast_1d(np.asarray(s, dtype=float))
    out = {k: np.zeros_like(s) for k in ("N", "V_y", "T", "M_y", "M_z")}
    for L in loads:
        on = (L.s > s).astype(float)
        out["N"] += on * L.F_x
        out["V_y"] += on * L.F_y
        out["T"] += on * (-L.z * L.F_y)
        out["M_y"] += on * (L.z * L.F_x)
        out["M_z"] += on * (L.s - s) * L.F_y
    return out


# ------------------------------------------------------------------ load cases
def load_cases(design: SuspensionDesign, geom: BalancerGeometry, k_stop: float = 2.0) -> list[LoadCase]:
    """The three load cases of the module docstring at beta_m."""
    k = require_finite("k_stop", k_stop)
    tor = design.torsion
    if not k >= 1.0:
        raise InputError("k_stop", k_stop, "stop load factor must be >= 1 (the stop carries the excess over P(beta_m))")
    if not geom.s_stop <= tor.R_b:
        raise InputError("s_stop", geom.s_stop, f"stop pad must lie on the arm, <= R_b = {tor.R_b:g} mm")
    b, R = tor.beta_m, tor.R_b
    MT = tor.M_T_max

    def wheel(P):
        return PointLoad("wheel", R, geom.e_w, -P * math.cos(b), P * math.sin(b))

    cases = [LoadCase("beta_m elastic", (wheel(tor.P_m),), b, MT)]
    L_a = design.L_a
    if not L_a <= R:
        raise InputError("i_a", design.i_a, f"damper ear arm L_a = {L_a:.4g} mm lies beyond the balancer "
                         f"R_b = {R:g} mm (reading '{design.damper_reading}')")
    Fa = design.R_a_comp_max
    Pw = (MT + Fa * L_a) / (R * math.sin(b))
    cases.append(LoadCase("beta_m + damper", (wheel(Pw), PointLoad("damper ear", L_a, geom.e_a, 0.0, -Fa)), b, MT))
    Ps = k * tor.P_m
    Fs = (Ps * R * math.sin(b) - MT) / geom.s_stop
    cases.append(LoadCase("stop", (wheel(Ps), PointLoad("stop pad", geom.s_stop, 0.0, 0.0, -Fs)), b, MT))
    return cases


# ------------------------------------------------------------------ the analysis
def _section(geom: BalancerGeometry, h: float) -> RectSection:
    return RectSection(geom.b, h, geom.t_wall)


def equal_strength_depth(forces: dict, geom: BalancerGeometry, sigma_allow: float) -> np.ndarray:
    """Depth h(s) with sigma_vM(s) = sigma_allow, bounded below by h_min, mm."""
    sa = require_positive("sigma_allow", sigma_allow, "MPa")
    n = len(forces["N"])
    h = np.empty(n)
    for i in range(n):
        f = {k: forces[k][i] for k in forces}

        def g(hh):
            return float(_section(geom, hh).von_mises(f["N"], f["V_y"], f["T"], f["M_y"], f["M_z"])) - sa

        if g(geom.h_min) <= 0:
            h[i] = geom.h_min
        elif g(geom.h_max) > 0:
            raise InputError("h_max", geom.h_max, f"even h_max leaves sigma_vM > {sa:g} MPa at a station; "
                             "widen the arm (b) or raise h_max")
        else:
            h[i] = brentq(g, geom.h_min, geom.h_max, xtol=SECTION_DEPTH_XTOL_MM, rtol=ROOT_XTOL)
    return h


@dataclass(frozen=True)
class BalancerAnalysis:
    """Strength of the balancer for its load cases.

    sigma_yield: MPa (40ХН2МА 930); safety: required factor on yield (allowable =
    sigma_yield / safety) used by the equal-strength sizing; n_stations: samples along
    the arm.
    """

    design: SuspensionDesign
    geom: BalancerGeometry = field(default_factory=BalancerGeometry)
    k_stop: float = 2.0
    sigma_yield: float = YIELD_40KhN2MA
    safety: float = 1.5
    n_stations: int = 73

    def __post_init__(self):
        object.__setattr__(self, "sigma_yield", require_positive("sigma_yield", self.sigma_yield, "MPa"))
        sf = require_finite("safety", self.safety)
        if not sf >= 1.0:
            raise InputError("safety", self.safety, "safety factor must be >= 1")
        if int(self.n_stations) < 3:
            raise InputError("n_stations", self.n_stations, "need >= 3 stations")
        object.__setattr__(self, "n_stations", int(self.n_stations))

    @property
    def sigma_allow(self) -> float:
        return self.sigma_yield / self.safety

    @property
    def cases(self) -> list[LoadCase]:
        return load_cases(self.design, self.geom, self.k_stop)

    @property
    def s(self) -> np.ndarray:
        """Stations along the arm, mm (0 at the upper axle, R_b excluded: nothing outboard)."""
        R = self.design.torsion.R_b
        return np.linspace(0.0, R, self.n_stations + 1)[:-1]

    def forces(self, case: LoadCase) -> dict[str, np.ndarray]:
        return internal_forces(case.loads, self.s)

    def envelope_depth(self) -> np.ndarray:
        """Equal-strength depth: the largest over the load cases at each station, mm."""
        return np.max([equal_strength_depth(self.forces(c), self.geom, self.sigma_allow)
                       for c in self.cases], axis=0)

    def stresses(self, h) -> dict[str, np.ndarray]:
        """sigma_vM(s) per load case for depths h (scalar or per station), MPa."""
        h = np.broadcast_to(np.asarray(h, dtype=float), self.s.shape)
        out = {}
        for c in self.cases:
            f = self.forces(c)
            out[c.name] = np.array([float(_section(self.geom, hh).von_mises(
                f["N"][i], f["V_y"][i], f["T"][i], f["M_y"][i], f["M_z"][i])) for i, hh in enumerate(h)])
        return out

    # -- axle-arm transitions -------------------------------------------------
    def transitions(self) -> list[dict]:
        """Peak stresses at the two shoulder fillets for every load case."""
        g = self.geom
        kb_u = kt_shoulder_fillet(g.D_upper, g.d_upper, g.r_upper, "bending")
        kt_u = kt_shoulder_fillet(g.D_upper, g.d_upper, g.r_upper, "torsion")
        kb_l = kt_shoulder_fillet(g.D_lower, g.d_lower, g.r_lower, "bending")
        R = self.design.torsion.R_b
        rows = []
        for c in self.cases:
            # upper axle root at the inboard arm face: moment of all loads about (0, 0, -b/2)
            M = moment_about(c.loads, (0.0, 0.0, -g.b / 2.0))
            Mb, Mt = math.hypot(M[0], M[1]), abs(M[2])
            Wb_u = math.pi * (g.d_upper**4 - g.d_upper_bore**4) / (32.0 * g.d_upper)
            sb = Mb / Wb_u
            tt = Mt / (2.0 * Wb_u)
            rows.append({"case": c.name, "where": "upper axle fillet", "K_t_bending": kb_u, "K_t_torsion": kt_u,
                         "sigma_nom": sb, "tau_nom": tt, "sigma_vM_nom": math.sqrt(sb**2 + 3 * tt**2),
                         "sigma_vM_peak": math.sqrt((kb_u * sb) ** 2 + 3 * (kt_u * tt) ** 2)})
            # wheel spindle root at the outboard arm face: loads acting on the spindle only
            sp = [L for L in c.loads if L.s == R and L.z > g.b / 2.0]
            M = moment_about(sp, (R, 0.0, g.b / 2.0))
            Mb = math.hypot(M[0], M[1])
            sb = Mb / (math.pi * (g.d_lower**4 - g.d_lower_bore**4) / (32.0 * g.d_lower))
            rows.append({"case": c.name, "where": "wheel spindle fillet", "K_t_bending": kb_l, "K_t_torsion": 1.0,
                         "sigma_nom": sb, "tau_nom": 0.0, "sigma_vM_nom": sb, "sigma_vM_peak": kb_l * sb})
        return rows

    # -- mass ---------------------------------------------------------------
    def arm_mass(self, h=None) -> tuple[float, float]:
        """Mass (kg) and centre-of-mass station (mm) of the arm prism of depth h(s) (default: equal-strength)."""
        s = self.s
        h = self.envelope_depth() if h is None else np.broadcast_to(np.asarray(h, dtype=float), s.shape)
        A = np.array([_section(self.geom, hh).A for hh in h])
        ss = np.append(s, self.design.torsion.R_b)
        AA = np.append(A, A[-1])
        m = RHO_STEEL * np.trapezoid(AA, ss)
        sc = np.trapezoid(AA * ss, ss) / np.trapezoid(AA, ss)
        return float(m), float(sc)

    # -- everything ---------------------------------------------------------
    def run(self) -> dict:
        """Arrays along the arm for plots and the list of Check records."""
        s = self.s
        h_eq = self.envelope_depth()
        sig_eq = self.stresses(h_eq)
        sig_const = self.stresses(self.geom.h)
        checks: list[Check] = []
        tor = self.design.torsion
        for c in self.cases:
            r = reactions(c.loads, self.geom.a1, self.geom.a2)
            F, M = r.residual(c.loads)
            scale = max(abs(L.F_y) for L in c.loads) * tor.R_b
            checks.append(_limit_check(f"{c.name}: statics residual", float(np.linalg.norm(F) + np.linalg.norm(M) / tor.R_b),
                                STATICS_REL_TOL * scale / tor.R_b, "N"))
            checks.append(_limit_check(f"{c.name}: bar torque vs M_T(beta_m)",
                                abs(r.bar_torque - (-c.bar_torque_expected)) / c.bar_torque_expected,
                                STATICS_REL_TOL, "-", note="bar reacts the characteristic's torque"))
            sm = float(np.max(sig_const[c.name]))
            checks.append(_limit_check(f"{c.name}: constant arm sigma_vM", sm, self.sigma_allow, "MPa"))
            checks.append(_limit_check(f"{c.name}: equal-strength arm sigma_vM", float(np.max(sig_eq[c.name])),
                                self.sigma_allow * (1 + STATICS_REL_TOL), "MPa"))
        for row in self.transitions():
            checks.append(_limit_check(f"{row['case']}: {row['where']} safety factor",
                                self.sigma_yield / row["sigma_vM_peak"], self.safety, "-", kind="min",
                                note=f"K_t = {row['K_t_bending']:.3f} (Peterson)"))
        checks.append(_limit_check("torsion bar shear at beta_m", float(tor.tau(tor.beta_m)), tor.tau_max, "MPa"))
        m_eq, sc_eq = self.arm_mass(h_eq)
        m_c, sc_c = self.arm_mass(self.geom.h)
        return {
            "s": s, "h_equal_strength": h_eq, "sigma_vM_equal_strength": sig_eq,
            "sigma_vM_constant": sig_const,
            "forces": {c.name: self.forces(c) for c in self.cases},
            "mass_equal_strength_kg": m_eq, "com_equal_strength_mm": sc_eq,
            "mass_constant_kg": m_c, "com_constant_mm": sc_c,
            "transitions": self.transitions(), "checks": checks,
        }
