"""Permissible stresses and fatigue safeties of a spur mesh of case-hardened steel: pitting by ISO 6336-2:2006
(σ_HP with Z_NT, Z_L, Z_v, Z_R, Z_W, Z_X) and tooth-root bending by ISO 6336-3:2006 (σ_FP with Y_ST, Y_NT,
Y_δrelT, Y_RrelT, Y_X, Y_M).  MPa, mm, µm, m/s, mm²/s.

Pitting (ISO 6336-2:2006 clause 5, basic formulae; Z_NT clause 11, Z_L, Z_v, Z_R clause 12, Z_W clause 13,
Z_X clause 14):

    σ_HG = σ_Hlim·Z_NT·Z_L·Z_v·Z_R·Z_W·Z_X,   σ_HP = σ_HG/S_Hmin,   S_H = σ_HG/σ_H
    Z_NT (case-hardened steel, no pitting permitted; Table 2):
        N_L <= 1e5: 1.6;   1e5 < N_L <= 5e7: (5e7/N_L)^0.0756;   5e7 < N_L <= 1e10: (5e7/N_L)^0.0306;
        above 1e10: 0.85
    Z_L = C_ZL + 4·(1 − C_ZL)/(1.2 + 134/ν_40)²,   C_ZL = 0.83 + 0.08·(σ_Hlim − 850)/350  (σ_Hlim taken
          within 850 ... 1200 MPa)
    Z_v = C_Zv + 2·(1 − C_Zv)/√(0.8 + 32/v),   C_Zv = C_ZL + 0.02
    Z_R = (3/R_z10)^C_ZR,  R_z10 = R_z·∛(10/ρ_red),  R_z = (R_z1 + R_z2)/2,  C_ZR = 0.32 − 0.0002·σ_Hlim
          (σ_Hlim taken within 850 ... 1200 MPa),  ρ_red = ρ_1·ρ_2/(ρ_1 + ρ_2) at the pitch point,
          ρ_i = ½·d_bi·tan α_w (ρ_2 < 0 for an internal wheel)
    Z_W = 1 (both flanks case-hardened),   Z_X = 1 (the standard's value for the pitting size factor)

Finite life (method B: ISO 6336-2:2019, 5.4, and ISO 6336-3:2019, 5.4 — the permissible stress of the limited life
range lies on the straight line, in log-log scale, between the static and the reference point): Z_L·Z_v·Z_R and
Y_δrelT·Y_RrelT·Y_X are their static values at and below N_static, their reference values at and above N_ref, and
between

    P(N_L) = P_ref·(P_static/P_ref)^w,   w = log(N_ref/N_L)/log(N_ref/N_static)
    pitting (case-hardened): N_static = 1e5, N_ref = 5e7, (Z_L·Z_v·Z_R)_static = 1
    root (case-hardened):    N_static = 1e3, N_ref = 3e6, Y_RrelT,static = Y_X,static = 1,
                             Y_δrelT,static = (0.44·Y_S + 0.12)/(0.44·Y_ST + 0.12) = 0.44·Y_S + 0.12 (Y_ST = 2)
(Z_NT and Y_NT of Tables 2 and 3 are that same line for the life factor: Z_NT = 1.6^w, Y_NT = 2.5^w.)

Tooth root (ISO 6336-3:2006 clause 5, basic formulae, method B factors; Y_δrelT, Y_RrelT, Y_X of
:mod:`propulsor.gears.iso6336_helical`):

    σ_FG = σ_Flim·Y_ST·Y_NT·Y_δrelT·Y_RrelT·Y_X·Y_M,   Y_ST = 2,   σ_FP = σ_FG/S_Fmin,   S_F = σ_FG/σ_F
    Y_NT (case-hardened steel; Table 3):
        N_L <= 1e3: 2.5;   1e3 < N_L <= 3e6: (3e6/N_L)^0.115;   3e6 < N_L <= 1e10: (3e6/N_L)^0.02;
        above 1e10: 0.85
    Y_M = 0.7 for an idler (a planet: its teeth bent both ways), 1 otherwise (case-hardened steel)
    (Y_δrelT·Y_RrelT·Y_X between the static and the reference point: see "Finite life" above)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError, require_positive

__all__ = ["z_nt", "y_nt", "cycles_at_z_nt", "cycles_at_y_nt", "z_l", "z_v", "z_r", "rho_red", "Pitting", "pitting_safety", "RootFatigue",
           "root_fatigue_safety", "N_STATIC_H", "N_REF_H", "N_STATIC_F", "N_REF_F", "life_weight", "between_static_and_reference",
           "y_delta_rel_t_static", "cycles_at_limit"]

#: load cycles of the static and the reference point of case-hardened steel: pitting (ISO 6336-2:2019 Table 2)
#: and tooth root (ISO 6336-3:2019 Table 3)
N_STATIC_H, N_REF_H = 1e5, 5e7
N_STATIC_F, N_REF_F = 1e3, 3e6


def _cycles(N_L: float) -> float:
    if not (isinstance(N_L, (int, float)) and math.isfinite(N_L) and N_L >= 0):
        raise InputError("load_cycles", N_L, "must be a finite number of cycles >= 0")
    return float(N_L)


def z_nt(N_L: float) -> float:
    """Pitting life factor Z_NT of case-hardened steel (ISO 6336-2:2006 Table 2, no pitting permitted)."""
    N = _cycles(N_L)
    if N <= 1e5:
        return 1.6
    if N <= 5e7:
        return (5e7 / N) ** 0.0756
    if N <= 1e10:
        return (5e7 / N) ** 0.0306
    return (5e7 / 1e10) ** 0.0306


def y_nt(N_L: float) -> float:
    """Root life factor Y_NT of case-hardened steel (ISO 6336-3:2006 Table 3)."""
    N = _cycles(N_L)
    if N <= 1e3:
        return 2.5
    if N <= 3e6:
        return (3e6 / N) ** 0.115
    if N <= 1e10:
        return (3e6 / N) ** 0.02
    return (3e6 / 1e10) ** 0.02


def cycles_at_z_nt(Z: float) -> float:
    """Load cycles at which Z_NT (case-hardened steel) falls to Z: 0 above 1.6, inf at 0.85 and below."""
    if Z > 1.6:
        return 0.0
    if Z <= (5e7 / 1e10) ** 0.0306:
        return math.inf
    return 5e7 / Z ** (1.0 / (0.0756 if Z >= 1.0 else 0.0306))


def cycles_at_y_nt(Y: float) -> float:
    """Load cycles at which Y_NT (case-hardened steel) falls to Y: 0 above 2.5, inf at 0.85 and below."""
    if Y > 2.5:
        return 0.0
    if Y <= (3e6 / 1e10) ** 0.02:
        return math.inf
    return 3e6 / Y ** (1.0 / (0.115 if Y >= 1.0 else 0.02))


def life_weight(N_L: float, N_static: float, N_ref: float) -> float:
    """w = log(N_ref/N_L)/log(N_ref/N_static) within 0 ... 1: the place of N_L between the reference (0) and the
    static point (1) on the log-log line of method B (ISO 6336-2:2019, 5.4; ISO 6336-3:2019, 5.4)."""
    N = _cycles(N_L)
    if N <= N_static:
        return 1.0
    if N >= N_ref:
        return 0.0
    return math.log(N_ref / N) / math.log(N_ref / N_static)


def between_static_and_reference(P_static: float, P_ref: float, N_L: float, N_static: float, N_ref: float) -> float:
    """A product of influence factors at N_L load cycles, method B: P_ref·(P_static/P_ref)^w (module docstring)."""
    require_positive("P_static", P_static)
    require_positive("P_ref", P_ref)
    return P_ref * (P_static / P_ref) ** life_weight(N_L, N_static, N_ref)


def y_delta_rel_t_static(Y_S: float, Y_ST: float = 2.0) -> float:
    """Relative notch sensitivity factor for static stress of case-hardened steel, method B (ISO 6336-3:2019,
    clause 12): Y_δrelT = (0.44·Y_S + 0.12)/(0.44·Y_ST + 0.12)."""
    require_positive("Y_S", Y_S)
    return (0.44 * Y_S + 0.12) / (0.44 * Y_ST + 0.12)


def cycles_at_limit(limit, target: float, N_lo: float, N_hi: float = 1e10) -> float:
    """Load cycles at which a falling limit stress ``limit(N)`` meets ``target``: 0 if it is already below at N_lo,
    inf if it is still above at N_hi (the life factors' floor)."""
    from scipy.optimize import brentq

    if limit(N_lo) < target:
        return 0.0
    if limit(N_hi) >= target:
        return math.inf
    lg = brentq(lambda x: limit(10.0 ** x) - target, math.log10(N_lo), math.log10(N_hi), xtol=1e-13, rtol=1e-15)
    return 10.0 ** lg


def _c_zl(sigma_Hlim: float) -> float:
    return 0.83 + 0.08 * (min(max(sigma_Hlim, 850.0), 1200.0) - 850.0) / 350.0


def z_l(nu40: float, sigma_Hlim: float) -> float:
    """Lubricant factor Z_L (ISO 6336-2:2006 clause 12, method B), ν_40 in mm²/s."""
    require_positive("oil_viscosity_40", nu40, "mm²/s")
    c = _c_zl(sigma_Hlim)
    return c + 4.0 * (1.0 - c) / (1.2 + 134.0 / nu40) ** 2


def z_v(v: float, sigma_Hlim: float) -> float:
    """Velocity factor Z_v (ISO 6336-2:2006 clause 12, method B), v the pitch-line speed, m/s (its limit C_Zv
    at standstill)."""
    if not (math.isfinite(v) and v >= 0):
        raise InputError("v", v, "must be a finite speed >= 0 m/s")
    c = _c_zl(sigma_Hlim) + 0.02
    return c if v == 0 else c + 2.0 * (1.0 - c) / math.sqrt(0.8 + 32.0 / v)


def rho_red(d_b1: float, d_b2: float, alpha_w: float, internal: bool) -> float:
    """Relative radius of curvature at the pitch point, mm (ρ_2 negative for an internal wheel)."""
    r1 = 0.5 * d_b1 * math.tan(alpha_w)
    r2 = 0.5 * d_b2 * math.tan(alpha_w) * (-1.0 if internal else 1.0)
    return r1 * r2 / (r1 + r2)


def z_r(R_z1: float, R_z2: float, rho_red_mm: float, sigma_Hlim: float) -> tuple[float, float]:
    """(Z_R, R_z10) of ISO 6336-2:2006 clause 12, method B: mean flank roughness R_z (µm) taken to the
    relative radius of curvature ρ_red (mm)."""
    require_positive("flank_roughness_Rz", min(R_z1, R_z2), "µm")
    require_positive("rho_red", rho_red_mm, "mm")
    Rz10 = 0.5 * (R_z1 + R_z2) * (10.0 / rho_red_mm) ** (1.0 / 3.0)
    c = 0.32 - 0.0002 * min(max(sigma_Hlim, 850.0), 1200.0)
    return (3.0 / Rz10) ** c, Rz10


@dataclass(frozen=True)
class Pitting:
    N_L: float
    Z_NT: float
    Z_L: float
    Z_v: float
    Z_R: float
    R_z10: float
    Z_W: float
    Z_X: float
    sigma_HG: float   # MPa, pitting stress limit at N_L
    sigma_HP: float   # MPa, σ_HG/S_Hmin
    S_H: float        # σ_HG/σ_H
    Z_LvR: float = 1.0    # Z_L·Z_v·Z_R at N_L (between the static 1 and the reference product Z_L·Z_v·Z_R)
    w: float = 0.0        # place of N_L between the reference (0) and the static point (1)

    def limit_at(self, N: float) -> float:
        """σ_HG (MPa) of this flank at N load cycles."""
        P = between_static_and_reference(1.0, self.Z_L * self.Z_v * self.Z_R, N, N_STATIC_H, N_REF_H)
        return self.sigma_HG / (self.Z_NT * self.Z_LvR) * z_nt(N) * P


def pitting_safety(sigma_H: float, sigma_Hlim: float, N_L: float, nu40: float, v: float, R_z1: float,
                   R_z2: float, rho_red_mm: float, S_Hmin: float = 1.0) -> Pitting:
    """Pitting fatigue safety of one flank of case-hardened steel at N_L load cycles (ISO 6336-2:2019, method B; the
    reference-life Z_L·Z_v·Z_R taken to N_L between the static and the reference point, 5.4)."""
    require_positive("sigma_Hlim", sigma_Hlim, "MPa")
    require_positive("sigma_H", sigma_H, "MPa")
    ZN, ZL, Zv = z_nt(N_L), z_l(nu40, sigma_Hlim), z_v(v, sigma_Hlim)
    ZR, Rz10 = z_r(R_z1, R_z2, rho_red_mm, sigma_Hlim)
    ZW = ZX = 1.0
    P = between_static_and_reference(1.0, ZL * Zv * ZR, N_L, N_STATIC_H, N_REF_H)
    sHG = sigma_Hlim * ZN * P * ZW * ZX
    return Pitting(N_L, ZN, ZL, Zv, ZR, Rz10, ZW, ZX, sHG, sHG / S_Hmin, sHG / sigma_H, P,
                   life_weight(N_L, N_STATIC_H, N_REF_H))


@dataclass(frozen=True)
class RootFatigue:
    N_L: float
    Y_ST: float
    Y_NT: float
    Y_delta_relT: float
    Y_R_relT: float
    Y_X: float
    Y_M: float
    sigma_FG: float   # MPa, root stress limit at N_L
    sigma_FP: float   # MPa, σ_FG/S_Fmin
    S_F: float        # σ_FG/σ_F
    Y_delta_relT_static: float = 1.0
    Y_dRX: float = 1.0    # Y_δrelT·Y_RrelT·Y_X at N_L (between the static and the reference product)
    w: float = 0.0        # place of N_L between the reference (0) and the static point (1)

    def limit_at(self, N: float) -> float:
        """σ_FG (MPa) of this root at N load cycles."""
        P = between_static_and_reference(self.Y_delta_relT_static, self.Y_delta_relT * self.Y_R_relT * self.Y_X, N,
                                         N_STATIC_F, N_REF_F)
        return self.sigma_FG / (self.Y_NT * self.Y_dRX) * y_nt(N) * P


def root_fatigue_safety(sigma_F: float, q_s: float, m: float, sigma_Flim: float, R_z: float, N_L: float,
                        S_Fmin: float = 1.0, idler: bool = False, *, Y_S: float) -> RootFatigue:
    """Bending fatigue safety of one case-hardened tooth root at N_L load cycles (ISO 6336-3:2019 method B; q_s and
    Y_S of the method B tooth form; the reference-life Y_δrelT·Y_RrelT·Y_X taken to N_L between the static and the
    reference point, 5.4)."""
    from .iso6336_helical import root_strength

    Y_M = 0.7 if idler else 1.0
    Yn = y_nt(N_L)
    r = root_strength(sigma_F, q_s, m, sigma_Flim, R_z, Y_NT=Yn, S_Fmin=S_Fmin, Y_M=Y_M)
    Yd_st = y_delta_rel_t_static(Y_S)
    P = between_static_and_reference(Yd_st, r.Y_delta_relT * r.Y_R_relT * r.Y_X, N_L, N_STATIC_F, N_REF_F)
    sFG = sigma_Flim * 2.0 * Yn * P * Y_M
    return RootFatigue(N_L, 2.0, Yn, r.Y_delta_relT, r.Y_R_relT, r.Y_X, r.Y_M, sFG, sFG / S_Fmin, sFG / sigma_F,
                       Yd_st, P, life_weight(N_L, N_STATIC_F, N_REF_F))
