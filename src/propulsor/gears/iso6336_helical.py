"""Pitting stress of a helical (or spur) external mesh by ISO 6336-2:2006 with the load factors of
ISO 6336-1:2006 that do not need the shaft layout: mesh stiffness (9.x), K_v (method B, simplified form),
K_Hα = K_Fα (method B), K_Fβ from K_Hβ.  mm, N, MPa, radians.  β = 0 gives the spur formulas of
:mod:`propulsor.gears.iso6336` (the final drive's meshes keep that module; this one carries the helical
terms a published example needs).

Transverse geometry (ISO 21771):

    α_t = atan(tan α_n / cos β),   β_b = atan(tan β · cos α_t),   m_t = m_n / cos β
    d = z·m_t,   d_b = d·cos α_t,   inv α_wt = inv α_t + 2·tan α_n·(x1 + x2)/(z1 + z2),   a_w = a·cos α_t / cos α_wt
    ε_α = (√(d_a1² − d_b1²) + √(d_a2² − d_b2²) − 2·a_w·sin α_wt) / (2·p_bt),  p_bt = π·m_t·cos α_t
    ε_β = b·sin β / (π·m_n),   ε_γ = ε_α + ε_β,   z_n = z / (cos² β_b · cos β)

Contact (ISO 6336-2:2006 eq. 1–5, 9, 10, 18, 25–29, 31):

    σ_H0 = Z_H·Z_E·Z_ε·Z_β·√(F_t/(d_1·b) · (u + 1)/u),   σ_H1,2 = Z_B,D·σ_H0·√(K_A·K_v·K_Hβ·K_Hα)
    Z_H = √(2·cos β_b·cos α_wt / (cos² α_t·sin α_wt)),   Z_β = 1/√cos β
    Z_ε = √((4 − ε_α)/3·(1 − ε_β) + ε_β/ε_α)  (ε_β < 1),   √(1/ε_α)  (ε_β >= 1)
    Z_B = M_1, Z_D = M_2 (>= 1) for ε_β = 0;  M − ε_β·(M − 1) for ε_β < 1;  1 for ε_β >= 1

Mesh stiffness (ISO 6336-1:2006 9.2–9.4, solid blanks):

    q' = C1 + C2/z_n1 + C3/z_n2 + C4·x1 + C5·x1/z_n1 + C6·x2 + C7·x2/z_n2 + C8·x1² + C9·x2²
    c'_th = 1/q',   c' = c'_th·C_M·C_R·C_B·cos β,   C_M = 0.8, C_R = 1,
    C_B = (1 + 0.5·(1.2 − h_fP/m_n))·(1 − 0.02·(20° − α_n)),   c_γα = c'·(0.75·ε_α + 0.25),   c_γβ = 0.85·c_γα

Transverse load factor (ISO 6336-1:2006 eq. 73–76, method B):

    ε_γ <= 2: K_Fα = ε_γ/2·(0.9 + 0.4·c_γα·(f_pb − y_α)/(F_tH/b))
    ε_γ > 2:  K_Fα = 0.9 + 0.4·√(2(ε_γ − 1)/ε_γ)·c_γα·(f_pb − y_α)/(F_tH/b)
    K_Hα = K_Fα within 1 ... ε_γ/(ε_α·Z_ε²);  K_Fα within 1 ... ε_γ/(0.25·ε_α + 0.75)

Tooth root by ISO 6336-3:2006 method B (load at the outer point of single pair contact, taken on the virtual
spur gear of the normal section; the 30° tangent construction of :func:`propulsor.gears.iso6336.tooth_form_factor`
with z → z_n, d_en below):

    σ_F0 = F_t/(b·m_n) · Y_F·Y_S·Y_β·Y_B·Y_DT,   σ_F = σ_F0·K_A·K_v·K_Fβ·K_Fα
    d_n = m_n·z_n,  d_bn = d_n·cos α_n,  d_an = d_n + d_a − d,  ε_αn = ε_α/cos² β_b
    d_en = 2·√([√((d_an/2)² − (d_bn/2)²) − π·d·cos β·cos α_n/z·(ε_αn − 1)]² + (d_bn/2)²)
    Y_β = 1 − ε_β·β/120°  (ε_β taken <= 1, β <= 30°)
    Y_DT = 2.366 − 0.666·ε_αn for 2.05 < ε_αn <= 2.5, 0.7 above (ISO grade <= 4 only), else 1
    Y_B = 1.6·ln(2.242·h/s_R) for 0.5 < s_R/h < 1.2 (external), 1 from s_R/h >= 1.2

Permissible root stress (ISO 6336-3:2006 method B factors, ISO 6336-5 σ_Flim):

    σ_FG = σ_Flim·Y_ST·Y_NT·Y_δrelT·Y_RrelT·Y_X·Y_M,   σ_FP = σ_FG/S_Fmin,   S_F = σ_FG/σ_F
    (Y_M the mean stress factor: 1 for one-way bending, 0.7 for an idler's alternating bending, hardened steel)
    Y_δrelT = (1 + √(ρ'·χ*))/(1 + √(ρ'·χ*_T)),  χ* = (1 + 2·q_s)/5,  χ*_T = 1.2 (q_sT = 2.5)
    Y_RrelT = 1.674 − 0.529·(R_z + 1)^0.1 (surface/through hardened, 1 <= R_z <= 40 µm; 1.120 below 1 µm)
    Y_X = 1.05 − 0.01·m_n (surface hardened), 1.03 − 0.006·m_n (through hardened), 1 for m_n <= 5
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError, require_positive
from .involute import inv, inv_inverse
from .iso6336 import STEEL, Material, ToothForm, tooth_form_factor, z_e

__all__ = ["HelicalPair", "z_h", "z_eps", "z_beta", "z_b_z_d", "MeshStiffness", "mesh_stiffness", "k_v_method_b",
           "k_alpha_method_b", "k_f_beta", "Pitting", "pitting", "d_en", "y_beta", "y_dt", "y_b", "RootGear",
           "ToothRoot", "tooth_root", "RHO_PRIME", "y_delta_rel_t", "y_r_rel_t", "y_x", "RootStrength", "root_strength"]

# ISO 6336-1:2006 Table 8: K_1 by ISO 1328 accuracy grade 3 ... 12 and K_2, spur and helical
_K1 = {"spur": {3: 2.1, 4: 3.9, 5: 7.5, 6: 14.9, 7: 26.8, 8: 39.1, 9: 52.8, 10: 76.6, 11: 102.6, 12: 146.3},
       "helical": {3: 1.9, 4: 3.5, 5: 6.7, 6: 13.3, 7: 23.9, 8: 34.8, 9: 47.0, 10: 68.2, 11: 91.4, 12: 130.3}}
_K2 = {"spur": 0.0193, "helical": 0.0087}
# ISO 6336-1:2006 9.3, Table 12: coefficients C1 ... C9 of the single stiffness
_C = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)


@dataclass(frozen=True)
class HelicalPair:
    """An external cylindrical pair: normal module and pressure angle, helix angle, teeth, shifts, tips."""

    m_n: float
    z1: int
    z2: int
    x1: float
    x2: float
    beta: float                 # rad, at the reference cylinder
    d_a1: float
    d_a2: float
    alpha_n: float = math.radians(20.0)

    def __post_init__(self):
        require_positive("m_n", self.m_n, "mm")
        require_positive("z1", self.z1)
        require_positive("z2", self.z2)
        if not 0.0 <= self.beta < math.radians(45.0):
            raise InputError("beta", math.degrees(self.beta), "0 <= beta < 45 deg")

    @property
    def alpha_t(self) -> float:
        return math.atan(math.tan(self.alpha_n) / math.cos(self.beta))

    @property
    def beta_b(self) -> float:
        return math.atan(math.tan(self.beta) * math.cos(self.alpha_t))

    @property
    def m_t(self) -> float:
        return self.m_n / math.cos(self.beta)

    @property
    def d1(self) -> float:
        return self.z1 * self.m_t

    @property
    def d2(self) -> float:
        return self.z2 * self.m_t

    @property
    def d_b1(self) -> float:
        return self.d1 * math.cos(self.alpha_t)

    @property
    def d_b2(self) -> float:
        return self.d2 * math.cos(self.alpha_t)

    @property
    def u(self) -> float:
        return self.z2 / self.z1

    @property
    def alpha_wt(self) -> float:
        return inv_inverse(inv(self.alpha_t) + 2.0 * math.tan(self.alpha_n) * (self.x1 + self.x2) / (self.z1 + self.z2))

    @property
    def a_w(self) -> float:
        return 0.5 * (self.d1 + self.d2) * math.cos(self.alpha_t) / math.cos(self.alpha_wt)

    @property
    def eps_alpha(self) -> float:
        p_bt = math.pi * self.m_t * math.cos(self.alpha_t)
        g = (math.sqrt(self.d_a1 ** 2 - self.d_b1 ** 2) + math.sqrt(self.d_a2 ** 2 - self.d_b2 ** 2)
             - 2.0 * self.a_w * math.sin(self.alpha_wt))
        return 0.5 * g / p_bt

    def eps_beta(self, b: float) -> float:
        return b * math.sin(self.beta) / (math.pi * self.m_n)

    @property
    def z_n1(self) -> float:
        return self.z1 / (math.cos(self.beta_b) ** 2 * math.cos(self.beta))

    @property
    def z_n2(self) -> float:
        return self.z2 / (math.cos(self.beta_b) ** 2 * math.cos(self.beta))


def z_h(alpha_t: float, alpha_wt: float, beta_b: float = 0.0) -> float:
    """Zone factor Z_H (ISO 6336-2:2006 eq. 10)."""
    return math.sqrt(2.0 * math.cos(beta_b) * math.cos(alpha_wt) / (math.cos(alpha_t) ** 2 * math.sin(alpha_wt)))


def z_eps(eps_alpha: float, eps_beta: float = 0.0) -> float:
    """Contact ratio factor Z_ε (ISO 6336-2:2006 eq. 26–28)."""
    if eps_beta >= 1.0:
        return math.sqrt(1.0 / eps_alpha)
    return math.sqrt((4.0 - eps_alpha) / 3.0 * (1.0 - eps_beta) + eps_beta / eps_alpha)


def z_beta(beta: float) -> float:
    """Helix angle factor Z_β = 1/√cos β (ISO 6336-2:2006 eq. 29)."""
    return 1.0 / math.sqrt(math.cos(beta))


def z_b_z_d(pair: HelicalPair, eps_beta: float) -> tuple[float, float]:
    """Single pair tooth contact factors (Z_B, Z_D) of pinion and wheel (ISO 6336-2:2006 eq. 3–8)."""
    ea = pair.eps_alpha
    r1 = math.sqrt((pair.d_a1 / pair.d_b1) ** 2 - 1.0)
    r2 = math.sqrt((pair.d_a2 / pair.d_b2) ** 2 - 1.0)
    t = math.tan(pair.alpha_wt)
    M1 = t / math.sqrt((r1 - 2.0 * math.pi / pair.z1) * (r2 - (ea - 1.0) * 2.0 * math.pi / pair.z2))
    M2 = t / math.sqrt((r2 - 2.0 * math.pi / pair.z2) * (r1 - (ea - 1.0) * 2.0 * math.pi / pair.z1))
    if eps_beta >= 1.0:
        return 1.0, 1.0
    if eps_beta == 0.0:
        return max(1.0, M1), max(1.0, M2)
    return max(1.0, M1 - eps_beta * (M1 - 1.0)), max(1.0, M2 - eps_beta * (M2 - 1.0))


@dataclass(frozen=True)
class MeshStiffness:
    c_th: float           # N/(mm·µm), theoretical single stiffness c'_th
    c_single: float       # N/(mm·µm), single stiffness c'
    c_gamma_alpha: float  # N/(mm·µm), mesh stiffness c_γα
    c_gamma_beta: float   # N/(mm·µm), c_γβ = 0.85·c_γα


def mesh_stiffness(pair: HelicalPair, h_fP_star: float = 1.25, C_R: float = 1.0, C_M: float = 0.8) -> MeshStiffness:
    """Single and mesh stiffness of solid steel gears (ISO 6336-1:2006 9.2–9.4; F_t·K_A/b >= 100 N/mm)."""
    C1, C2, C3, C4, C5, C6, C7, C8, C9 = _C
    zn1, zn2, x1, x2 = pair.z_n1, pair.z_n2, pair.x1, pair.x2
    q = C1 + C2 / zn1 + C3 / zn2 + C4 * x1 + C5 * x1 / zn1 + C6 * x2 + C7 * x2 / zn2 + C8 * x1 * x1 + C9 * x2 * x2
    c_th = 1.0 / q
    C_B = (1.0 + 0.5 * (1.2 - h_fP_star)) * (1.0 - 0.02 * (20.0 - math.degrees(pair.alpha_n)))
    c1 = c_th * C_M * C_R * C_B * math.cos(pair.beta)
    c_ga = c1 * (0.75 * pair.eps_alpha + 0.25)
    return MeshStiffness(c_th, c1, c_ga, 0.85 * c_ga)


def k_v_method_b(v: float, z1: int, u: float, Ft_b: float, K_A: float, grade: int, eps_beta: float) -> float:
    """Dynamic factor K_v of ISO 6336-1:2006 (simplified method B, eq. 14 with Table 8): K_v = 1 + (K_1/(K_A·F_t/b)
    + K_2)·v·z_1/100·√(u²/(1 + u²)); helical constants for ε_β >= 1, linear in ε_β between spur and helical below.
    v m/s, F_t/b N/mm (taken >= 100)."""
    if grade not in _K1["spur"]:
        raise InputError("accuracy_grade", grade, "must be an ISO 1328 grade 3 ... 12")
    load = max(K_A * Ft_b, 100.0)
    f = v * z1 / 100.0 * math.sqrt(u * u / (1.0 + u * u))
    k_sp = 1.0 + (_K1["spur"][grade] / load + _K2["spur"]) * f
    k_he = 1.0 + (_K1["helical"][grade] / load + _K2["helical"]) * f
    if eps_beta >= 1.0:
        return k_he
    return k_sp - eps_beta * (k_sp - k_he)


def k_alpha_method_b(eps_alpha: float, eps_beta: float, c_gamma_alpha: float, f_pb: float, y_alpha: float,
                     FtH_b: float, Z_eps: float) -> tuple[float, float]:
    """(K_Hα, K_Fα) by ISO 6336-1:2006 method B (eq. 73–76); f_pb, y_α µm, F_tH/b N/mm, c_γα N/(mm·µm)."""
    eg = eps_alpha + eps_beta
    term = c_gamma_alpha * (f_pb - y_alpha) / FtH_b
    if eg <= 2.0:
        K = eg / 2.0 * (0.9 + 0.4 * term)
    else:
        K = 0.9 + 0.4 * math.sqrt(2.0 * (eg - 1.0) / eg) * term
    K_H = min(max(K, 1.0), eg / (eps_alpha * Z_eps ** 2))
    K_F = min(max(K, 1.0), eg / (0.25 * eps_alpha + 0.75))
    return K_H, K_F


def k_f_beta(K_Hbeta: float, b: float, h: float) -> float:
    """K_Fβ = K_Hβ^N_F, N_F = (b/h)²/(1 + b/h + (b/h)²), b/h taken >= 3 (ISO 6336-1:2006 eq. 61–62)."""
    bh = max(b / h, 3.0)
    return K_Hbeta ** (bh * bh / (1.0 + bh + bh * bh))


@dataclass(frozen=True)
class Pitting:
    F_t: float
    eps_alpha: float
    eps_beta: float
    Z_H: float
    Z_E: float
    Z_eps: float
    Z_beta: float
    Z_B: float
    Z_D: float
    sigma_H0: float
    sigma_H1: float
    sigma_H2: float


def pitting(pair: HelicalPair, b: float, T1: float, K_A: float, K_v: float, K_Hbeta: float, K_Halpha: float,
            m1: Material = STEEL, m2: Material = STEEL) -> Pitting:
    """σ_H0 and σ_H of pinion and wheel (ISO 6336-2:2006 eq. 1–3) at the pinion torque T1 (N·m), face width b (mm)."""
    require_positive("b", b, "mm")
    F_t = 2000.0 * T1 / pair.d1
    ea, eb = pair.eps_alpha, pair.eps_beta(b)
    ZH, ZE = z_h(pair.alpha_t, pair.alpha_wt, pair.beta_b), z_e(m1, m2)
    Ze, Zb = z_eps(ea, eb), z_beta(pair.beta)
    ZB, ZD = z_b_z_d(pair, eb)
    u = pair.u
    s0 = ZH * ZE * Ze * Zb * math.sqrt(F_t / (pair.d1 * b) * (u + 1.0) / u)
    k = math.sqrt(K_A * K_v * K_Hbeta * K_Halpha)
    return Pitting(F_t, ea, eb, ZH, ZE, Ze, Zb, ZB, ZD, s0, ZB * s0 * k, ZD * s0 * k)


# ---------------------------------------------------------------- tooth root (ISO 6336-3:2006, method B)

def d_en(pair: HelicalPair, gear: int) -> float:
    """Diameter of the outer point of single pair contact on the virtual spur gear of gear 1 or 2, mm
    (ISO 6336-3:2006 method B, external gears; see the module docstring)."""
    if gear not in (1, 2):
        raise InputError("gear", gear, "must be 1 (pinion) or 2 (wheel)")
    z, d, d_a, z_n = ((pair.z1, pair.d1, pair.d_a1, pair.z_n1) if gear == 1
                      else (pair.z2, pair.d2, pair.d_a2, pair.z_n2))
    an, bb = pair.alpha_n, pair.beta_b
    eps_an = pair.eps_alpha / math.cos(bb) ** 2
    d_n = pair.m_n * z_n
    r_bn = 0.5 * d_n * math.cos(an)
    r_an = 0.5 * (d_n + d_a - d)
    g = math.sqrt(r_an * r_an - r_bn * r_bn) - math.pi * d * math.cos(pair.beta) * math.cos(an) / z * (eps_an - 1.0)
    return 2.0 * math.sqrt(g * g + r_bn * r_bn)


def y_beta(beta: float, eps_beta: float) -> float:
    """Helix angle factor Y_β = 1 − ε_β·β/120° with ε_β <= 1 and β <= 30° (ISO 6336-3:2006)."""
    return 1.0 - min(eps_beta, 1.0) * min(math.degrees(beta), 30.0) / 120.0


def y_dt(eps_alpha_n: float, grade: int) -> float:
    """Deep tooth factor Y_DT (ISO 6336-3:2006): below 1 only for ISO grade <= 4 and ε_αn > 2.05."""
    if grade > 4 or eps_alpha_n <= 2.05:
        return 1.0
    if eps_alpha_n > 2.5:
        return 0.7
    return 2.366 - 0.666 * eps_alpha_n


def y_b(s_R: float | None, h: float) -> float:
    """Rim thickness factor Y_B of an external gear (ISO 6336-3:2006); s_R None: a solid blank."""
    if s_R is None:
        return 1.0
    require_positive("s_R", s_R, "mm")
    r = s_R / h
    if r >= 1.2:
        return 1.0
    if r <= 0.5:
        raise InputError("s_R", s_R, f"rim thickness must exceed 0.5·h = {0.5 * h:.3f} mm (ISO 6336-3 Y_B)")
    return 1.6 * math.log(2.242 / r)


@dataclass(frozen=True)
class RootGear:
    z_n: float
    d_en: float       # mm
    form: ToothForm   # θ, s_Fn, ρ_F, h_Fe, α_Fen, Y_F, Y_S at d_en
    q_s: float
    Y_B: float
    sigma_F0: float   # MPa
    sigma_F: float    # MPa


@dataclass(frozen=True)
class ToothRoot:
    F_t: float
    eps_alpha_n: float
    Y_beta: float
    Y_DT: float
    gear1: RootGear
    gear2: RootGear


def tooth_root(pair: HelicalPair, b: float, T1: float, K_A: float, K_v: float, K_Fbeta: float, K_Falpha: float,
               grade: int, h_fP_star: float = 1.25, rho_fP_star: float = 0.38, s_pr: float = 0.0,
               s_R: tuple[float | None, float | None] = (None, None)) -> ToothRoot:
    """σ_F0 and σ_F of pinion and wheel by ISO 6336-3:2006 method B at the pinion torque T1 (N·m), face width b (mm),
    both gears cut by one basic rack (h_fP*, ρ_fP*, s_pr in mm); s_R the rim thicknesses (None: solid)."""
    require_positive("b", b, "mm")
    F_t = 2000.0 * T1 / pair.d1
    eps_an = pair.eps_alpha / math.cos(pair.beta_b) ** 2
    Yb, Ydt = y_beta(pair.beta, pair.eps_beta(b)), y_dt(eps_an, grade)
    K = K_A * K_v * K_Fbeta * K_Falpha
    gears = []
    for g, (z_n, x, d, d_a) in enumerate(((pair.z_n1, pair.x1, pair.d1, pair.d_a1),
                                          (pair.z_n2, pair.x2, pair.d2, pair.d_a2)), start=1):
        den = d_en(pair, g)
        f = tooth_form_factor(z_n, pair.m_n, x, den, pair.alpha_n, h_fP_star, rho_fP_star, s_pr)
        h = 0.5 * (d_a - d) + (h_fP_star - x) * pair.m_n          # tooth depth h_a + h_f
        YB = y_b(s_R[g - 1], h)
        s0 = F_t / (b * pair.m_n) * f.Y_F * f.Y_S * Yb * YB * Ydt
        gears.append(RootGear(z_n, den, f, f.s_Fn / (2.0 * f.rho_F), YB, s0, s0 * K))
    return ToothRoot(F_t, eps_an, Yb, Ydt, gears[0], gears[1])


#: slip-layer thickness ρ' (mm) of ISO 6336-3:2006 method B: case-, flame- or induction-hardened and nitrided
#: steel (through-hardened steel: 0.0281 ... 0.0014 mm for a yield point of 500 ... 1000 MPa, pass it directly)
RHO_PRIME = {"case_hardened": 0.0030, "nitrided": 0.1005}


def y_delta_rel_t(q_s: float, rho_prime: float = RHO_PRIME["case_hardened"]) -> float:
    """Relative notch sensitivity factor Y_δrelT, method B (ISO 6336-3:2006), χ* = (1 + 2·q_s)/5, ρ' in mm."""
    require_positive("rho_prime", rho_prime, "mm")
    return (1.0 + math.sqrt(rho_prime * (1.0 + 2.0 * q_s) / 5.0)) / (1.0 + math.sqrt(rho_prime * 1.2))


def y_r_rel_t(R_z: float) -> float:
    """Relative surface factor Y_RrelT of surface- or through-hardened steel (σ_B >= 800 MPa), method B
    (ISO 6336-3:2006); R_z the root roughness, µm."""
    if not 0.0 < R_z <= 40.0:
        raise InputError("R_z", R_z, "root roughness must be within 0 < R_z <= 40 µm")
    return 1.120 if R_z < 1.0 else 1.674 - 0.529 * (R_z + 1.0) ** 0.1


def y_x(m_n: float, material: str = "surface_hardened") -> float:
    """Size factor Y_X of the tooth root, method B (ISO 6336-3:2006); surface hardened: case-, flame-, induction-
    hardened or nitrided steel."""
    if material == "surface_hardened":
        return 1.0 if m_n <= 5.0 else (1.05 - 0.01 * m_n if m_n < 25.0 else 0.8)
    if material == "through_hardened":
        return 1.0 if m_n <= 5.0 else (1.03 - 0.006 * m_n if m_n < 30.0 else 0.85)
    raise InputError("material", material, "must be surface_hardened or through_hardened")


@dataclass(frozen=True)
class RootStrength:
    Y_delta_relT: float
    Y_R_relT: float
    Y_X: float
    Y_M: float
    sigma_FG: float   # MPa, tooth root stress limit
    sigma_FP: float   # MPa, permissible root stress σ_FG/S_Fmin
    S_F: float        # safety σ_FG/σ_F


def root_strength(sigma_F: float, q_s: float, m_n: float, sigma_Flim: float, R_z: float, Y_NT: float = 1.0,
                  S_Fmin: float = 1.0, Y_ST: float = 2.0, rho_prime: float = RHO_PRIME["case_hardened"],
                  material: str = "surface_hardened", Y_M: float = 1.0) -> RootStrength:
    """Limit, permissible stress and safety of one tooth root of hardened steel (ISO 6336-3:2006 method B; σ_Flim
    of ISO 6336-5, Y_NT the life factor at the gear's load cycles)."""
    require_positive("sigma_Flim", sigma_Flim, "MPa")
    require_positive("S_Fmin", S_Fmin)
    Yd = y_delta_rel_t(q_s, rho_prime)
    Yr = y_r_rel_t(R_z)
    Yx = y_x(m_n, material)
    if not 0.0 < Y_M <= 1.0:
        raise InputError("Y_M", Y_M, "mean stress factor must be within 0 < Y_M <= 1")
    sFG = sigma_Flim * Y_ST * Y_NT * Yd * Yr * Yx * Y_M
    return RootStrength(Yd, Yr, Yx, Y_M, sFG, sFG / S_Fmin, sFG / sigma_F)
