"""Torsion-bar suspension of the 50 t tracked carrier (seed 004, ch. 2, eq. 1-28).

The seed follows Dyadchenko, Sarach, Kotiev (MGTU 2007).  Geometry and the elastic
element are in millimetres / newtons / MPa (the project standard); the body-pitch
quantities (eq. 1, 23, 25-27) keep the seed's SI units and say so in their names
(I_y_kgm2, c_N_per_m, mu_Ns_per_m, x_m).  Angles: radians inside, degrees only in
fields named ``*_deg``.

Elastic element (seed 004, §2.1.2-2.1.3):

    d_T_dyn = cbrt(64 P_st R_b sin(beta_st) / (pi [tau]))       eq. 6
    gamma_m = 2 [tau] L_T / (G d_T)                              eq. 7
    gamma_st = 32 P_st R_b sin(beta_st) L_T / (pi d_T^4 G)        eq. 8
    beta_0 = beta_st - gamma_st,  beta_m = beta_0 + gamma_m      eq. 9, 10
    f(beta) = R_b (cos beta_0 - cos beta)                        eq. 11
    f_dyn = f_full - f_st                                        eq. 12
    P(beta) = G J_p / L_T (beta - beta_0) / (R_b sin beta)       eq. 13
    J_p = pi d_T^4 / 32                                          eq. 14
    lambda_ut = pi d_T^2 [tau]^2 L_T / (16 P_st G)               eq. 16
    c' = 2 lambda_ut P_st / f_full^2                             eq. 20 = eq. 24

Body pitch and dampers (seed 004, §2.1.1, §2.1.5-2.1.6):

    c = 2 pi^2 I_y / (T_phi^2 sum l_i^2)                         eq. 1
    T_phi = sqrt(2 pi^2 I_y / (c sum l_i^2))                     eq. 26
    mu_k,mean = sqrt2 ln(nu) / sum l_j^2 * sqrt(c I_y sum l_i^2 / (4 pi^2 + ln^2 nu))   eq. 19 = eq. 23
    mu_k,reb_max = c T_phi / (4 ln(f_full / f_st))               eq. 25
    mu_k,reb = mu_k,mean / (0.8 ... 0.9);  mu_k,comp = 2 mu_mean - mu_reb   eq. 21
    R_k,comp_max = (G_p zdd - c n h g) / g / (2 n_a)             eq. 27
    R_a,comp_max = R_k,comp_max * (rod/wheel force ratio),  R_a,reb_max = P(f_full) * (ratio)   eq. 28

Where the seed's printed numbers disagree (each pinned in tests/test_suspension.py):

* gamma_st: eq. 8 gives 24.348 deg, printed 24.358; the seed's own c' = 2.138e5 N/m needs
  24.32 ... 24.35 deg, so the printed value is off in its last digit.
* beta_0 = 19, beta_m = 115 deg are printed rounded; f_st = 78.13 mm and f_full = 492.03 mm
  follow from the unrounded 18.796 and 114.839 deg.
* lambda_ut: eq. 16 gives 813.9 mm at d_T = 46 mm, printed 822 mm; the unrounded eq. 6
  diameter 46.21 mm gives 821.5 mm (the likeliest source); eq. 24 with 0.822 m gives the
  printed c' = 2.138e5 N/m.
* "c = 164 400 N/m" (also Table 11) is the tangent stiffness of eq. 13 at beta_st
  (164 522 N/m, 0.08 %), not eq. 1 at T_phi = 1.8 s: eq. 1 cannot be re-run (the l_i are not
  printed) and 8 wheels over 6.846 m give T_phi <= 1.47 s with it.  eq. 25 and eq. 27 reproduce
  their printed 5.229e4 and 2.134e4 N; eq. 23's printed mu_k,mean = 3.426e4 would need
  sum l_j^2 of the dampers above sum l_i^2 of all wheels, impossible - the formula is tested
  against the log decrement of a damped pitch oscillator instead.

Damper lever ratio (eq. 28), i = 0.453: read literally (i = R_b / L_a, R_a = R_k i) the ear
sits at 795 mm on a 360 mm balancer and needs a 52 mm piston at 20 MPa; read as a lever
(i = L_a / R_b, rod force = wheel force / i, the default "lever") the ear sits at 163 mm and
needs 114.7 mm - the seed adopts D_p = 0.11 m, so only the lever reading reproduces it.  The
literal reading stays available.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from propulsor.errors import InputError, require_finite, require_positive
from propulsor.policy import POSITION_EQUAL_TOL_M, REL_ROUNDING_TOL

#: standard gravity used by the seed (m/s^2)
G_ACC = 9.81

DAMPER_READINGS = ("lever", "literal")


def _deg(name: str, value, lo: float, hi: float) -> float:
    v = require_finite(name, value)
    if not (lo < v < hi):
        raise InputError(name, value, f"must lie in ({lo:g}, {hi:g}) deg")
    return v


# --------------------------------------------------------------------------- eq. 6
def torsion_bar_diameter(P_st: float, R_b: float, beta_st: float, tau_max: float) -> float:
    """Torsion-bar diameter for the full dynamic travel, mm (seed 004, eq. 6).

    P_st N, R_b mm, beta_st rad, tau_max MPa.
    """
    P = require_positive("P_st", P_st, "N")
    R = require_positive("R_b", R_b, "mm")
    t = require_positive("tau_max", tau_max, "MPa")
    b = require_finite("beta_st", beta_st)
    if not 0 < b < math.pi:
        raise InputError("beta_st", beta_st, "must lie in (0, pi) rad")
    return (64.0 * P * R * math.sin(b) / (math.pi * t)) ** (1.0 / 3.0)


# ---------------------------------------------------------------------- eq. 20/24
def equivalent_stiffness(lambda_ut: float, P_st: float, f_full: float) -> float:
    """Stiffness of the linear suspension of equal energy, c' = 2 lambda P / f^2 (eq. 20, 24).

    Units follow the arguments (m, N -> N/m; mm, N -> N/mm).
    """
    lam = require_positive("lambda_ut", lambda_ut)
    P = require_positive("P_st", P_st, "N")
    f = require_positive("f_full", f_full)
    return 2.0 * lam * P / f**2


# ------------------------------------------------------------------ eq. 1, 26 (SI)
def pitch_stiffness(I_y_kgm2: float, T_phi: float, sum_l2_m2: float) -> float:
    """Wheel suspension stiffness c (N/m) giving the body pitch period T_phi (eq. 1)."""
    I = require_positive("I_y", I_y_kgm2, "kg m^2")
    T = require_positive("T_phi", T_phi, "s")
    S = require_positive("sum_l2", sum_l2_m2, "m^2")
    return 2.0 * math.pi**2 * I / (T**2 * S)


def pitch_period(I_y_kgm2: float, c_N_per_m: float, sum_l2_m2: float) -> float:
    """Body pitch period T_phi (s) for wheel stiffness c on both sides (eq. 26).

    J theta'' + 2 c sum(l_i^2) theta = 0 (two tracks, sum over one side).
    """
    I = require_positive("I_y", I_y_kgm2, "kg m^2")
    c = require_positive("c", c_N_per_m, "N/m")
    S = require_positive("sum_l2", sum_l2_m2, "m^2")
    return math.sqrt(2.0 * math.pi**2 * I / (c * S))


# ---------------------------------------------------------------- eq. 19/23, 25, 27
def mean_damping_coefficient(c_N_per_m: float, I_y_kgm2: float, sum_l2_m2: float,
                             sum_la2_m2: float, nu: float) -> float:
    """Mean damper coefficient reduced to the wheel, N s/m (seed 004, eq. 19 = eq. 23).

    Chosen so that the pitch amplitude falls by the factor nu over one damped period:
    zeta = ln nu / sqrt(4 pi^2 + ln^2 nu) with damping torque 2 mu sum(l_j^2) theta'.
    """
    c = require_positive("c", c_N_per_m, "N/m")
    I = require_positive("I_y", I_y_kgm2, "kg m^2")
    S = require_positive("sum_l2", sum_l2_m2, "m^2")
    Sa = require_positive("sum_la2", sum_la2_m2, "m^2")
    v = require_finite("nu", nu)
    if not v > 1:
        raise InputError("nu", nu, "amplitude ratio over one period must be > 1")
    ln = math.log(v)
    return math.sqrt(2.0) * ln / Sa * math.sqrt(c * I * S / (4 * math.pi**2 + ln**2))


def rebound_damping_max(c_N_per_m: float, T_phi: float, f_full: float, f_st: float) -> float:
    """Largest rebound coefficient at the wheel that keeps it from hanging, N s/m (eq. 25)."""
    c = require_positive("c", c_N_per_m, "N/m")
    T = require_positive("T_phi", T_phi, "s")
    ff = require_positive("f_full", f_full)
    fs = require_positive("f_st", f_st)
    if not ff > fs:
        raise InputError("f_full", f_full, f"must exceed f_st = {fs:g}")
    return c * T / (4.0 * math.log(ff / fs))


def compression_force_max(G_p: float, c_N_per_m: float, n_side: int, h_n_m: float,
                          n_a_side: int, zdd_over_g: float = 0.5) -> float:
    """Largest compression damper force at the wheel allowed by 'shake' accelerations, N (eq. 27).

    R = (G_p zdd - c n h g) / g / (2 n_a) with zdd = zdd_over_g * g.
    """
    Gp = require_positive("G_p", G_p, "N")
    c = require_positive("c", c_N_per_m, "N/m")
    n = require_positive("n_side", n_side)
    h = require_positive("h_n", h_n_m, "m")
    na = require_positive("n_a_side", n_a_side)
    z = require_positive("zdd_over_g", zdd_over_g)
    R = (Gp * z * G_ACC - c * n * h * G_ACC) / G_ACC / (2.0 * na)
    if not R > 0:
        raise InputError("h_n", h_n_m, f"bump too high: compression force limit {R:.4g} N <= 0")
    return R


# ------------------------------------------------------------------------- eq. 28
def rod_force_ratio(i_a: float, reading: str = "lever") -> float:
    """Rod force / wheel force for the seed's damper ratio i_a = 0.453 (eq. 28).

    "lever":   i_a = L_a / R_b = V_rod / V_k  ->  F_rod = F_wheel / i_a
    "literal": i_a = V_k / V_rod = R_b / L_a  ->  F_rod = F_wheel * i_a (eq. 28 as printed)
    Either way F_rod V_rod = F_wheel V_k (power balance).
    """
    i = require_positive("i_a", i_a)
    if reading not in DAMPER_READINGS:
        raise InputError("damper_reading", reading, f"must be one of {DAMPER_READINGS}")
    return 1.0 / i if reading == "lever" else i


def damper_ear_arm(R_b: float, i_a: float, reading: str = "lever") -> float:
    """Damper ear distance from the balancer axis L_a (units of R_b) under a reading of i_a."""
    R = require_positive("R_b", R_b)
    return R / rod_force_ratio(i_a, reading)


def piston_diameter(F_rod: float, p_max: float, d_rod: float = 0.0) -> float:
    """Piston diameter so that F_rod / area = p_max; area = pi/4 (D^2 - d_rod^2), mm.

    F_rod N, p_max MPa, d_rod mm (0: full piston area, compression side).
    """
    F = require_positive("F_rod", F_rod, "N")
    p = require_positive("p_max", p_max, "MPa")
    d = require_finite("d_rod", d_rod)
    if d < 0:
        raise InputError("d_rod", d_rod, "must be >= 0 mm")
    return math.sqrt(4.0 * F / (math.pi * p) + d * d)


# ---------------------------------------------------------------- elastic element
@dataclass(frozen=True)
class TorsionSuspension:
    """Torsion-bar suspension of one road wheel (seed 004, §2.1.2-2.1.4).

    P_st: static wheel load, N; R_b: balancer arm, mm; beta_st_deg: static balancer
    angle from the downward vertical, deg (eq. 5); d_T, L_T: torsion bar diameter and
    length, mm; tau_max: allowed shear stress, MPa; G: shear modulus, MPa.
    beta0_deg / beta_m_deg: None -> computed from eq. 9 / 10; a number -> the designer's
    adopted value (the seed rounds to 19 / 115 deg), checked for order and for the
    torsion bar not yielding at beta_m.
    """

    P_st: float = 31490.0
    R_b: float = 360.0
    beta_st_deg: float = 43.144
    d_T: float = 46.0
    L_T: float = 2000.0
    tau_max: float = 1600.0
    G: float = 83000.0
    beta0_deg: float | None = None
    beta_m_deg: float | None = None

    def __post_init__(self):
        set_ = lambda k, v: object.__setattr__(self, k, v)  # noqa: E731
        set_("P_st", require_positive("P_st", self.P_st, "N"))
        set_("R_b", require_positive("R_b", self.R_b, "mm"))
        set_("d_T", require_positive("d_T", self.d_T, "mm"))
        set_("L_T", require_positive("L_T", self.L_T, "mm"))
        set_("tau_max", require_positive("tau_max", self.tau_max, "MPa"))
        set_("G", require_positive("G", self.G, "MPa"))
        set_("beta_st_deg", _deg("beta_st_deg", self.beta_st_deg, 0.0, 180.0))
        if self.beta0_deg is not None:
            b0 = _deg("beta0_deg", self.beta0_deg, -180.0, 180.0)
            if not b0 < self.beta_st_deg:
                raise InputError("beta0_deg", self.beta0_deg,
                                 f"must be < beta_st_deg = {self.beta_st_deg:g} (travel angles out of order)")
            set_("beta0_deg", b0)
        if self.gamma_st >= math.pi:
            raise InputError("d_T", self.d_T, "static twist gamma_st >= 180 deg: bar far too thin")
        if self.beta_m_deg is not None:
            bm = _deg("beta_m_deg", self.beta_m_deg, -180.0, 180.0)
            if not bm > self.beta_st_deg:
                raise InputError("beta_m_deg", self.beta_m_deg,
                                 f"must be > beta_st_deg = {self.beta_st_deg:g} (travel angles out of order)")
            set_("beta_m_deg", bm)
        if self.gamma_st >= self.gamma_m:
            raise InputError("d_T", self.d_T,
                             f"torsion bar yields under the static load: gamma_st = {math.degrees(self.gamma_st):.6g} "
                             f">= gamma_m = {math.degrees(self.gamma_m):.6g} deg (tau > [tau] = {self.tau_max:g} MPa)")
        if not self.beta0 < self.beta_st < self.beta_m:
            raise InputError("beta0_deg", math.degrees(self.beta0),
                             f"travel angles out of order: need beta0 < beta_st = {self.beta_st_deg:g} "
                             f"< beta_m = {math.degrees(self.beta_m):.6g} deg")
        if not self.beta0 > 0:
            raise InputError("beta0_deg", math.degrees(self.beta0),
                             "must be > 0 deg: the balancer may not swing through the downward vertical "
                             "(f(beta) would not be monotonic, P(beta) < 0)")
        if not self.beta_m < math.pi:
            raise InputError("beta_m_deg", math.degrees(self.beta_m),
                             "must be < 180 deg (P(beta) = M / (R_b sin beta) is singular there)")
        tau_m = self.tau(self.beta_m)
        if tau_m > self.tau_max * (1.0 + REL_ROUNDING_TOL):
            shown = self.beta_m_deg if self.beta_m_deg is not None else round(math.degrees(self.beta_m), 9)
            raise InputError("beta_m_deg", shown,
                             f"torsion bar yields at beta_m: tau = {tau_m:.6g} MPa > [tau] = {self.tau_max:g} MPa "
                             f"(twist {math.degrees(self.beta_m - self.beta0):.6g} > gamma_m = "
                             f"{math.degrees(self.gamma_m):.6g} deg)")

    # -- eq. 5-10 ------------------------------------------------------------
    @property
    def beta_st(self) -> float:
        return math.radians(self.beta_st_deg)

    @property
    def d_T_dyn(self) -> float:
        """Diameter required for the full dynamic travel, mm (eq. 6)."""
        return torsion_bar_diameter(self.P_st, self.R_b, self.beta_st, self.tau_max)

    @property
    def J_p(self) -> float:
        """Polar moment of area of the bar, mm^4 (eq. 14)."""
        return math.pi * self.d_T**4 / 32.0

    @property
    def torsion_stiffness(self) -> float:
        """G J_p / L_T, N mm / rad."""
        return self.G * self.J_p / self.L_T

    @property
    def gamma_m(self) -> float:
        """Largest twist of the bar at [tau], rad (eq. 7)."""
        return 2.0 * self.tau_max * self.L_T / (self.G * self.d_T)

    @property
    def gamma_st(self) -> float:
        """Static twist, rad (eq. 8)."""
        return (32.0 * self.P_st * self.R_b * math.sin(self.beta_st) * self.L_T
                / (math.pi * self.d_T**4 * self.G))

    @property
    def beta0(self) -> float:
        """Mounting (unloaded) balancer angle, rad (eq. 9 or adopted)."""
        if self.beta0_deg is not None:
            return math.radians(self.beta0_deg)
        return self.beta_st - self.gamma_st

    @property
    def beta_m(self) -> float:
        """Balancer angle at the largest twist, rad (eq. 10 or adopted)."""
        if self.beta_m_deg is not None:
            return math.radians(self.beta_m_deg)
        return self.beta0 + self.gamma_m

    # -- eq. 11-14 -----------------------------------------------------------
    def f(self, beta):
        """Vertical wheel travel from the unloaded position, mm (eq. 11)."""
        return self.R_b * (math.cos(self.beta0) - np.cos(np.asarray(beta, dtype=float)))

    def M_T(self, beta):
        """Torsion-bar torque, N mm: G J_p / L_T (beta - beta0)."""
        return self.torsion_stiffness * (np.asarray(beta, dtype=float) - self.beta0)

    def P(self, beta):
        """Elastic force reduced to the wheel axis, N (eq. 13)."""
        beta = np.asarray(beta, dtype=float)
        return self.M_T(beta) / (self.R_b * np.sin(beta))

    def tau(self, beta):
        """Shear stress at the bar surface, MPa: G d_T (beta - beta0) / (2 L_T)."""
        return self.G * self.d_T * (np.asarray(beta, dtype=float) - self.beta0) / (2.0 * self.L_T)

    @property
    def f_st(self) -> float:
        return float(self.f(self.beta_st))

    @property
    def f_full(self) -> float:
        return float(self.f(self.beta_m))

    @property
    def f_dyn(self) -> float:
        """Dynamic travel, mm (eq. 12)."""
        return self.f_full - self.f_st

    @property
    def P_m(self) -> float:
        """Elastic force at full travel P(beta_m) = P(f_full), N."""
        return float(self.P(self.beta_m))

    @property
    def M_T_max(self) -> float:
        return float(self.M_T(self.beta_m))

    def characteristic(self, num: int = 201) -> dict[str, np.ndarray]:
        """Elastic characteristic arrays beta (rad), f (mm), P (N), M_T (N mm), beta0..beta_m."""
        if int(num) < 2:
            raise InputError("num", num, "need >= 2 samples")
        b = np.linspace(self.beta0, self.beta_m, int(num))
        return {"beta": b, "f": self.f(b), "P": self.P(b), "M_T": self.M_T(b)}

    # -- eq. 16, 20 ----------------------------------------------------------
    @property
    def lambda_ut(self) -> float:
        """Refined specific potential energy, mm (eq. 16): bar energy at [tau] / P_st."""
        return (math.pi * self.d_T**2 * self.tau_max**2 * self.L_T
                / (16.0 * self.P_st * self.G))

    @property
    def energy_full(self) -> float:
        """Energy stored from beta0 to beta_m, N mm: G J_p / L_T (beta_m - beta0)^2 / 2."""
        return 0.5 * self.torsion_stiffness * (self.beta_m - self.beta0) ** 2

    @property
    def c_equiv(self) -> float:
        """Linear stiffness of equal energy, N/mm (eq. 20, 24) with this lambda_ut and f_full."""
        return equivalent_stiffness(self.lambda_ut, self.P_st, self.f_full)

    @property
    def c_equiv_N_per_m(self) -> float:
        return 1000.0 * self.c_equiv

    @property
    def stiffness_at_static(self) -> float:
        """Tangent stiffness dP/df at beta_st, N/mm (from eq. 11, 13)."""
        b = self.beta_st
        k, R = self.torsion_stiffness, self.R_b
        dP_db = k / (R * math.sin(b)) - k * (b - self.beta0) * math.cos(b) / (R * math.sin(b) ** 2)
        return dP_db / (R * math.sin(b))


# ----------------------------------------------------------- body pitch + dampers
@dataclass(frozen=True)
class SuspensionDesign:
    """The whole suspension calculation of seed 004 §2.1 for one vehicle.

    G_p: sprung weight, N; I_y_kgm2: body pitch inertia (eq. 2); wheel_x_m: wheel
    positions along one side from the centre of mass, m; damper_x_m: positions of the
    damped wheels of one side, m; T_phi: design pitch period, s (0.5 ... 1.8, eq. 1);
    nu: amplitude ratio over one period (10 ... 17); reb_factor: mu_reb = mu_mean /
    reb_factor (0.8 ... 0.9); h_n_m: bump height, m; zdd_over_g: allowed shake
    acceleration / g; i_a, damper_reading: see module docstring; p_max: damper
    pressure, MPa; d_rod: damper rod diameter, mm.
    """

    torsion: TorsionSuspension = field(default_factory=TorsionSuspension)
    G_p: float = 473000.0
    I_y_kgm2: float = 421100.0
    wheel_x_m: tuple = ()
    damper_x_m: tuple = ()
    T_phi: float = 1.8
    nu: float = 13.5
    reb_factor: float = 0.85
    h_n_m: float = 0.05
    zdd_over_g: float = 0.5
    i_a: float = 0.453
    damper_reading: str = "lever"
    p_max: float = 20.0
    d_rod: float = 40.0

    def __post_init__(self):
        set_ = lambda k, v: object.__setattr__(self, k, v)  # noqa: E731
        if not isinstance(self.torsion, TorsionSuspension):
            raise InputError("torsion", self.torsion, "must be a TorsionSuspension")
        set_("G_p", require_positive("G_p", self.G_p, "N"))
        set_("I_y_kgm2", require_positive("I_y_kgm2", self.I_y_kgm2, "kg m^2"))
        xs = tuple(require_finite("wheel_x_m", x) for x in self.wheel_x_m)
        if len(xs) < 2:
            raise InputError("wheel_x_m", self.wheel_x_m, "need >= 2 wheel positions per side")
        if len(set(xs)) != len(xs):
            raise InputError("wheel_x_m", self.wheel_x_m, "wheel positions must be distinct")
        set_("wheel_x_m", xs)
        xa = tuple(require_finite("damper_x_m", x) for x in self.damper_x_m)
        if not xa:
            raise InputError("damper_x_m", self.damper_x_m, "need >= 1 damped wheel per side")
        for x in xa:
            if not any(abs(x - w) <= POSITION_EQUAL_TOL_M for w in xs):
                raise InputError("damper_x_m", x, "a damper must sit on a wheel of wheel_x_m")
        if len(set(xa)) != len(xa):
            raise InputError("damper_x_m", self.damper_x_m, "one damper per wheel")
        set_("damper_x_m", xa)
        T = require_positive("T_phi", self.T_phi, "s")
        set_("T_phi", T)
        v = require_finite("nu", self.nu)
        if not v > 1:
            raise InputError("nu", self.nu, "must be > 1")
        rf = require_finite("reb_factor", self.reb_factor)
        if not 0 < rf <= 1:
            raise InputError("reb_factor", self.reb_factor, "must lie in (0, 1] (seed: 0.8 ... 0.9)")
        set_("h_n_m", require_positive("h_n_m", self.h_n_m, "m"))
        set_("zdd_over_g", require_positive("zdd_over_g", self.zdd_over_g))
        set_("i_a", require_positive("i_a", self.i_a))
        if self.damper_reading not in DAMPER_READINGS:
            raise InputError("damper_reading", self.damper_reading, f"must be one of {DAMPER_READINGS}")
        set_("p_max", require_positive("p_max", self.p_max, "MPa"))
        d = require_finite("d_rod", self.d_rod)
        if d < 0:
            raise InputError("d_rod", self.d_rod, "must be >= 0 mm")

    @property
    def n_side(self) -> int:
        return len(self.wheel_x_m)

    @property
    def n_a_side(self) -> int:
        return len(self.damper_x_m)

    @property
    def sum_l2(self) -> float:
        return float(sum(x * x for x in self.wheel_x_m))

    @property
    def sum_la2(self) -> float:
        return float(sum(x * x for x in self.damper_x_m))

    @property
    def c_design(self) -> float:
        """Wheel stiffness near the static position for the design period, N/m (eq. 1)."""
        return pitch_stiffness(self.I_y_kgm2, self.T_phi, self.sum_l2)

    @property
    def c_equiv(self) -> float:
        """c' of the torsion element, N/m (eq. 24)."""
        return self.torsion.c_equiv_N_per_m

    @property
    def T_phi_equiv(self) -> float:
        """Pitch period with the equal-energy stiffness c', s (eq. 26)."""
        return pitch_period(self.I_y_kgm2, self.c_equiv, self.sum_l2)

    @property
    def mu_mean(self) -> float:
        """Mean damper coefficient at the wheel, N s/m (eq. 23, c = c')."""
        return mean_damping_coefficient(self.c_equiv, self.I_y_kgm2, self.sum_l2, self.sum_la2, self.nu)

    @property
    def mu_reb_max(self) -> float:
        """No-hang limit of the rebound coefficient, N s/m (eq. 25, c = c', T = T_phi)."""
        t = self.torsion
        return rebound_damping_max(self.c_equiv, self.T_phi, t.f_full, t.f_st)

    @property
    def mu_reb(self) -> float:
        """Adopted rebound coefficient: min(mu_mean / reb_factor, eq. 25 limit), N s/m."""
        return min(self.mu_mean / self.reb_factor, self.mu_reb_max)

    @property
    def mu_comp(self) -> float:
        """Compression coefficient 2 mu_mean - mu_reb, N s/m (eq. 21)."""
        return 2.0 * self.mu_mean - self.mu_reb

    @property
    def c_static(self) -> float:
        """Stiffness 'near the static travel' (eq. 27): tangent dP/df at beta_st, N/m."""
        return 1000.0 * self.torsion.stiffness_at_static

    @property
    def R_k_comp_max(self) -> float:
        """Compression force limit at the wheel, N (eq. 27 with c = c_static)."""
        return compression_force_max(self.G_p, self.c_static, self.n_side, self.h_n_m,
                                     self.n_a_side, self.zdd_over_g)

    @property
    def rod_ratio(self) -> float:
        return rod_force_ratio(self.i_a, self.damper_reading)

    @property
    def L_a(self) -> float:
        """Damper ear arm on the balancer, mm."""
        return damper_ear_arm(self.torsion.R_b, self.i_a, self.damper_reading)

    @property
    def R_a_comp_max(self) -> float:
        """Compression rod force, N (eq. 28)."""
        return self.R_k_comp_max * self.rod_ratio

    @property
    def R_a_reb_max(self) -> float:
        """Rebound rod force P(f_full) * ratio, N (eq. 28)."""
        return self.torsion.P_m * self.rod_ratio

    @property
    def D_piston(self) -> float:
        """Piston diameter for the larger rod force at p_max on the full area, mm."""
        return piston_diameter(max(self.R_a_comp_max, self.R_a_reb_max), self.p_max)


def uniform_wheel_positions(n_side: int, base_m: float, x_cg_m: float | None = None) -> tuple:
    """n wheels equally spaced over the base (first to last wheel), positions from the CG, m.

    x_cg_m: CG measured from the first wheel (None: mid-base).
    """
    n = int(require_positive("n_side", n_side))
    if n < 2:
        raise InputError("n_side", n_side, "need >= 2 wheels")
    L = require_positive("base_m", base_m, "m")
    xc = 0.5 * L if x_cg_m is None else require_finite("x_cg_m", x_cg_m)
    return tuple(float(x) for x in np.linspace(0.0, L, n) - xc)


def thesis_design() -> SuspensionDesign:
    """Seed 004's carrier: 8 wheels a side (P_st 16 = 0.93 G + dP; 3125 kg per wheel, Table 11),
    base 6.846 m (Table 11), dampers on the two front and two rear wheels (n_a = 4).

    The wheel positions are NOT printed in the seed: equal spacing about the centre of
    mass is an assumption (mean spacing 0.978 m; the seed quotes ~1 m, §6.2).
    """
    xs = uniform_wheel_positions(8, 6.846)
    return SuspensionDesign(torsion=TorsionSuspension(), wheel_x_m=xs,
                            damper_x_m=(xs[0], xs[1], xs[-2], xs[-1]))
