"""Solid rubber tyre of a road wheel: Kozlov's steady heat estimate (seed 004, ch. 7, eq. 76-80).

    T = t_air + Q / (alpha F)                                    eq. 76
    Q = psi A n / 60                                             eq. 77 (W; psi = 0.25 ... 0.5)
    n = 60 V / (3.6 * 2 pi R)   [rpm, V in km/h, R in m]         eq. 77, see note
    A = pi q_m lambda_m b R (1 - lambda_m / (2 R))               eq. 78 (J per wheel turn)
    lambda_m = l^2 / (8 R)                                       eq. 79 (largest deflection)
    l = 2 cbrt(H / R) sqrt(R P / (E b))                          eq. 80 (contact chord)
    q_m = 4 P / (pi b l)                                         text after eq. 80 (peak pressure)
    omega = 2 pi V / t                                           "track" frequency, §7.2

Checked against the seed text:
* eq. 76-80 and q_m as printed; q_m is the peak of a semi-elliptic pressure
  over the chord l (pi/4 q_m b l = P), lambda_m the sagitta of the chord l.
* eq. 77 prints n = 60 V / (3.6 pi R): that is the wheel speed only if R is the wheel
  DIAMETER, while eq. 78-80 use R as the radius (lambda_m = l^2/8R is the sagitta of a
  circle of radius R).  This module uses the kinematic n = V / (2 pi R) (rpm as above);
  ``n_rpm(..., as_printed=True)`` gives the printed expression, exactly twice as large.
* The seed prints no numeric Kozlov example (Table 12 feeds its Simulink model,
  eq. 81-83, not modelled here).  Its printed numbers reproduced here: the
  Table 12 rows omega = 2 pi V / L (L = 0.15 m, V = 4, 7, 20 m/s),
  tmprt_kfcent = 1 / (m c) and flow_coef = V A rho c_air, and the §7.2 estimate of the
  extra track-frequency load 36 kg x 30 g ~ 1000 kgf.

Units: lengths mm, force N, modulus MPa, speed km/h in Kozlov's formulas (as the
seed), m/s for the track frequency, alpha W/(m^2 K), temperatures deg C.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from propulsor.errors import InputError, require_finite, require_positive

G_ACC = 9.81


def track_frequency(V_mps, t_track_m: float):
    """Track-link excitation frequency omega = 2 pi V / t, rad/s (seed 004, §7.2; Table 12)."""
    t = require_positive("t_track", t_track_m, "m")
    V = np.asarray(V_mps, dtype=float)
    if not np.all(np.isfinite(V)) or np.any(V < 0):
        raise InputError("V", V_mps, "speeds must be finite and >= 0 m/s")
    return 2.0 * math.pi * V / t


def heating_coefficient(m_rubber_kg: float, c_rubber: float) -> float:
    """Table 12 'tmprt_kfcent' = 1 / (m c), K/J: temperature rise per joule of heated rubber."""
    m = require_positive("m_rubber", m_rubber_kg, "kg")
    c = require_positive("c_rubber", c_rubber, "J/(kg K)")
    return 1.0 / (m * c)


def air_cooling_coefficient(V_mps, area_m2: float, rho_air: float = 1.2, c_air: float = 1005.0):
    """Table 12 'flow_coef' = V A rho c_air, W/K."""
    A = require_positive("A_heatexchange", area_m2, "m^2")
    r = require_positive("rho_air", rho_air, "kg/m^3")
    c = require_positive("c_air", c_air, "J/(kg K)")
    V = np.asarray(V_mps, dtype=float)
    if not np.all(np.isfinite(V)) or np.any(V < 0):
        raise InputError("V", V_mps, "speeds must be finite and >= 0 m/s")
    return V * A * r * c


def inertial_load(mass_kg: float, accel_g: float) -> float:
    """Extra load m a of the unsprung wheel mass at accel_g * g, N (seed 004, §7.2)."""
    m = require_positive("mass", mass_kg, "kg")
    a = require_positive("accel_g", accel_g)
    return m * a * G_ACC


def n_rpm(V_kmh, R_mm: float, as_printed: bool = False):
    """Wheel speed, rpm, for vehicle speed V (km/h) and rolling radius R (mm) (eq. 77).

    as_printed=True returns the seed's 60 V / (3.6 pi R) (twice the kinematic value).
    """
    R = require_positive("R", R_mm, "mm") / 1000.0
    V = np.asarray(V_kmh, dtype=float)
    if not np.all(np.isfinite(V)) or np.any(V < 0):
        raise InputError("V", V_kmh, "speeds must be finite and >= 0 km/h")
    k = 1.0 if as_printed else 2.0
    return 60.0 * V / (3.6 * k * math.pi * R)


def tyre_surface(R_mm: float, b_mm: float, H_mm: float) -> float:
    """Free surface of a solid tyre ring, mm^2: two side faces + tread."""
    R = require_positive("R", R_mm, "mm")
    b = require_positive("b", b_mm, "mm")
    H = require_positive("H", H_mm, "mm")
    if not H < R:
        raise InputError("H", H_mm, f"rubber thickness must be < R = {R:g} mm")
    return 2.0 * math.pi * (R**2 - (R - H) ** 2) + 2.0 * math.pi * R * b


@dataclass(frozen=True)
class SolidTyre:
    """One solid rubber tyre (one row of a road wheel) and its cooling (Kozlov, eq. 76-80).

    R: outer (rolling) radius, mm; b: tyre width, mm; H: rubber thickness, mm;
    E: rubber compression modulus, MPa; psi: rubber internal friction (0.25 ... 0.5);
    alpha: heat transfer rubber -> air, W/(m^2 K); F: cooling surface, mm^2
    (None: two side faces + tread, ``tyre_surface``).
    """

    R: float
    b: float
    H: float
    E: float
    alpha: float
    psi: float = 0.35
    F: float | None = None

    def __post_init__(self):
        set_ = lambda k, v: object.__setattr__(self, k, v)  # noqa: E731
        set_("R", require_positive("R", self.R, "mm"))
        set_("b", require_positive("b", self.b, "mm"))
        set_("H", require_positive("H", self.H, "mm"))
        if not self.H < self.R:
            raise InputError("H", self.H, f"rubber thickness must be < R = {self.R:g} mm")
        set_("E", require_positive("E", self.E, "MPa"))
        set_("alpha", require_positive("alpha", self.alpha, "W/(m^2 K)"))
        psi = require_finite("psi", self.psi)
        if not 0 < psi < 1:
            raise InputError("psi", self.psi, "internal friction must lie in (0, 1) (seed: 0.25 ... 0.5)")
        set_("psi", psi)
        if self.F is None:
            set_("F", tyre_surface(self.R, self.b, self.H))
        else:
            set_("F", require_positive("F", self.F, "mm^2"))

    def _load(self, P):
        P = np.asarray(P, dtype=float)
        if not np.all(np.isfinite(P)) or np.any(P <= 0):
            raise InputError("P", P.tolist() if P.ndim else float(P), "tyre load must be finite and > 0 N")
        return P

    def contact_length(self, P):
        """Contact chord l, mm (eq. 80)."""
        P = self._load(P)
        return 2.0 * np.cbrt(self.H / self.R) * np.sqrt(self.R * P / (self.E * self.b))

    def deflection(self, P):
        """Largest deflection lambda_m = l^2 / 8R, mm (eq. 79)."""
        l = self.contact_length(P)
        lam = l**2 / (8.0 * self.R)
        if np.any(lam >= self.H):
            raise InputError("P", float(np.max(P)), f"deflection {float(np.max(lam)):.4g} mm reaches the rubber "
                             f"thickness H = {self.H:g} mm")
        return lam

    def q_m(self, P):
        """Peak contact pressure 4 P / (pi b l), MPa (after eq. 80)."""
        P = self._load(P)
        return 4.0 * P / (math.pi * self.b * self.contact_length(P))

    def q_mean(self, P):
        """Mean contact pressure P / (b l), MPa (the seed's first tyre criterion)."""
        P = self._load(P)
        return P / (self.b * self.contact_length(P))

    def work_per_turn(self, P):
        """Deformation work per wheel turn A, J (eq. 78)."""
        P = self._load(P)
        lam = self.deflection(P)
        A_Nmm = math.pi * self.q_m(P) * lam * self.b * self.R * (1.0 - lam / (2.0 * self.R))
        return A_Nmm / 1000.0

    def heat_rate(self, P, V_kmh, as_printed_n: bool = False):
        """Heat released per second Q = psi A n / 60, W (eq. 77)."""
        return self.psi * self.work_per_turn(P) * n_rpm(V_kmh, self.R, as_printed_n) / 60.0

    def temperature(self, P, V_kmh, t_air: float = 20.0, as_printed_n: bool = False):
        """Steady tyre temperature T = t_air + Q / (alpha F), deg C (eq. 76); arrays broadcast."""
        ta = require_finite("t_air", t_air)
        return ta + self.heat_rate(P, V_kmh, as_printed_n) / (self.alpha * self.F * 1e-6)

    def temperature_curve(self, P: float, V_max_kmh: float, t_air: float = 20.0, num: int = 51):
        """Temperature over 0 ... V_max, dict of arrays V_kmh, n_rpm, Q_W, T_C."""
        Vm = require_positive("V_max", V_max_kmh, "km/h")
        if int(num) < 2:
            raise InputError("num", num, "need >= 2 samples")
        V = np.linspace(0.0, Vm, int(num))
        return {"V_kmh": V, "n_rpm": n_rpm(V, self.R), "Q_W": self.heat_rate(P, V),
                "T_C": self.temperature(P, V, t_air)}
