"""Working stresses of a spur mesh: ISO 6336-2 (pitting, method B) and ISO 6336-3 (tooth root,
method C of the 1996 edition: load at the tip, Y_F·Y_S with Y_ε), load factors of ISO 6336-1
(method B for K_v, method C for K_Hβ, Table 9 for K_Hα); the root stress also by method B of ISO 6336-3:2006.  Spur gears only (β = 0), external pinion
with an external or internal mate.  mm, N, MPa, radians.

Contact (ISO 6336-2:2006 eq. 1–3, 9, 10, 18, 25):

    σ_H0 = Z_H·Z_E·Z_ε·Z_β·√(F_t/(d_1·b) · (u + 1)/u)        u = z2/z1 (< 0 for an internal mate)
    σ_H  = Z_B·σ_H0·√(K_A·K_v·K_Hβ·K_Hα)
    Z_H  = √(2·cos α_w / (cos² α·sin α_w)),   Z_E = √(1/(π·((1 − ν1²)/E1 + (1 − ν2²)/E2)))
    Z_ε  = √((4 − ε_α)/3),   Z_β = 1 (spur)
    Z_B  = max(1, M_1),  M_1 = tan α_w / √((√(d_a1²/d_b1² − 1) − 2π/z1)·(√(d_a2²/d_b2² − 1) − (ε_α − 1)·2π/z2))
           (ISO 6336-2:2019, 6.2; an internal wheel with z2 < 0: its bracket √(d_a2²/d_b2² − 1) + (ε_α − 1)·2π/|z2|)
    Z_D  = max(1, M_2) for the wheel (M_1 with pinion and wheel exchanged), 1 for an internal wheel;
           σ_H of the wheel = Z_D·σ_H0·√(...)

Tooth root (ISO 6336-3:1996 eq. 2–3, method C: load applied at the tip, d_en = d_a):

    σ_F = F_t/(b·m) · Y_F·Y_S·Y_ε·Y_β · K_A·K_v·K_Fβ·K_Fα
    E = π/4·m − h_fP·tan α + s_pr/cos α − (1 − sin α)·ρ_fP/cos α            (eq. 22)
    G = ρ_fP/m − h_fP/m + x,   H = 2/z·(π/2 − E/m) − π/3,   θ = 2G/z·tan θ − H   (eq. 23–25, 30° tangent)
    s_Fn/m = z·sin(π/3 − θ) + √3·(G/cos θ − ρ_fP/m),  ρ_F/m = ρ_fP/m + 2G²/(cos θ·(z·cos² θ − 2G))
    α_en = arccos(d_b/d_en),  γ_e = (π/2 + 2x·tan α)/z + inv α − inv α_en,  α_Fen = α_en − γ_e
    h_Fe/m = ½·((cos γ_e − sin γ_e·tan α_Fen)·d_en/m − z·cos(π/3 − θ) − G/cos θ + ρ_fP/m)
    Y_F = 6·(h_Fe/m)·cos α_Fen / ((s_Fn/m)²·cos α),   Y_S = (1.2 + 0.13 L)·q_s^(1/(1.21 + 2.3/L)),
    L = s_Fn/h_Fe,  q_s = s_Fn/(2ρ_F),   Y_ε = 0.25 + 0.75/ε_α

Load factors (ISO 6336-1:2006):

    K_v = 1 + (K_1/(K_A·F_t/b) + K_2)·v·z_1/100·√(u²/(1 + u²))     (method B, eq. 14; spur K_2 = 0.0193,
          K_1 by accuracy grade, Table 8; F_t/b taken >= 100 N/mm)
    K_Hβ = 1 + c_γβ·F_βy / (2·F_m/b)  (<= 2; above: √(2·c_γβ·F_βy/(F_m/b))), F_m = F_t·K_A·K_v,
          F_βy = F_βx − y_β,  y_β = 0.15·F_βx (<= 6 µm, hardened),  F_βx = 1.33·f_sh + f_ma (method C),
          f_ma = f_Hβ of ISO 1328-1 at the grade, c_γβ = 0.85·c_γα, c_γα = 20 N/(mm·µm)
    f_sh = 0.023·(n·F_m/b)·(b/d_1)²  µm  (ISO 6336-1:2019 clause 7, method C, the pinion's torsional deformation:
          the term of a pinion whose shaft bending is nil, as for the floating sun; n the meshes whose torque the
          pinion's body carries — a sun meshing with n planets twists under all n; 0 for a pinion that passes
          no torque through its body, as a planet on its pin)
    K_Fβ = K_Hβ^N_F,  N_F = (b/h)² / (1 + b/h + (b/h)²),  h the deeper tooth's depth (b/h the smaller of b/h1, b/h2),
          b/h taken >= 3 (ISO 6336-1:2006
          eq. 61–62, as in :func:`propulsor.gears.iso6336_helical.k_f_beta`)
    K_Hα = K_Fα by Table 9 (surface-hardened spur gears, F_t·K_A/b >= 100 N/mm)

Tooth root by method B of ISO 6336-3:2006 beside method C: the same Y_F, Y_S construction with the load
at the outer point of single pair contact, no Y_ε (Y_β = Y_B = Y_DT = 1 for a spur gear of solid rim and
ε_α < 2):

    d_en = 2·√((√(r_a² − r_b²) − p_b·(ε_α − 1))² + r_b²),   p_b = π·m·cos α
    σ_F = F_t/(b·m) · Y_F·Y_S · K_A·K_v·K_Fβ·K_Fα

The internal gear's (ring's) root: ISO 6336-3:2019's substitute rack (:mod:`propulsor.gears.iso6336_internal`),
when the caller gives its thickness as made, the cutter's tip radius and its rim (:class:`InternalRoot`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError, require_positive
from .involute import inv
from .tooth_form import ToothForm

__all__ = ["Material", "STEEL", "z_e", "z_h", "z_eps", "z_b", "z_d", "f_h_beta", "contact_factors", "tooth_form_factor",
           "ToothForm", "k_v_method_b", "f_sh_torsion", "FaceLoad", "face_load_method_c", "k_h_beta_method_c",
           "k_h_alpha", "d_en_single_contact", "MeshLoad", "MeshStress", "operating_angle", "InternalRoot", "root_face_width",
           "mesh_stress"]


@dataclass(frozen=True)
class Material:
    E: float = 206000.0   # MPa
    nu: float = 0.3


STEEL = Material()

# ISO 6336-1:2006 Table 8: K_1 of spur gears by ISO 1328 accuracy grade 3 ... 12
_K1_SPUR = {3: 2.1, 4: 3.9, 5: 7.5, 6: 14.9, 7: 26.8, 8: 39.1, 9: 52.8, 10: 76.6, 11: 102.6, 12: 146.3}
_K2_SPUR = 0.0193
# ISO 6336-1:2006 Table 9: K_Hα = K_Fα, surface-hardened spur gears, K_A·F_t/b >= 100 N/mm
_KHA_HARDENED_SPUR = {3: 1.0, 4: 1.0, 5: 1.0, 6: 1.0, 7: 1.1, 8: 1.2}


def z_e(m1: Material = STEEL, m2: Material = STEEL) -> float:
    """Elasticity factor Z_E, √MPa (ISO 6336-2 eq. 18)."""
    return math.sqrt(1.0 / (math.pi * ((1 - m1.nu ** 2) / m1.E + (1 - m2.nu ** 2) / m2.E)))


def z_h(alpha: float, alpha_w: float) -> float:
    """Zone factor Z_H of a spur mesh (ISO 6336-2 eq. 9 with β = 0)."""
    return math.sqrt(2.0 * math.cos(alpha_w) / (math.cos(alpha) ** 2 * math.sin(alpha_w)))


def z_eps(eps_alpha: float) -> float:
    """Contact ratio factor Z_ε of a spur mesh (ISO 6336-2 eq. 25)."""
    return math.sqrt((4.0 - eps_alpha) / 3.0)


def z_b(alpha_w, d_a1, d_b1, z1, d_a2, d_b2, z2, eps_alpha, internal: bool) -> float:
    """Single pair contact factor Z_B of the pinion, ISO 6336-2:2019, 6.2 (spur gears, ε_β = 0): Z_B = max(1, M_1),

        M_1 = tan α_w / √((√(d_a1²/d_b1² − 1) − 2π/z1)·(√(d_a2²/d_b2² − 1) − (ε_α − 1)·2π/z2))

    the ratio of the radii of curvature at the pitch point to those at the pinion's inner point of single pair
    contact B.  An internal wheel enters with the standard's sign convention (z2, d_a2, d_b2 negative), so its
    second bracket becomes √(d_a2²/d_b2² − 1) + (ε_α − 1)·2π/|z2|: the ring's (concave) radius of curvature at B,
    its tip point moved (ε_α − 1) base pitches into the path of contact.  Only Z_D of an internal wheel is 1."""
    f1 = math.sqrt((d_a1 / d_b1) ** 2 - 1.0) - 2.0 * math.pi / z1
    sgn = -1.0 if internal else 1.0
    f2 = math.sqrt((d_a2 / d_b2) ** 2 - 1.0) - sgn * (eps_alpha - 1.0) * 2.0 * math.pi / z2
    M1 = math.tan(alpha_w) / math.sqrt(f1 * f2)
    return max(1.0, M1)


def z_d(alpha_w, d_a1, d_b1, z1, d_a2, d_b2, z2, eps_alpha, internal: bool) -> float:
    """Single pair contact factor Z_D of the wheel, ISO 6336-2:2019, 6.2: max(1, M_2), M_2 being M_1 with pinion
    and wheel exchanged (the wheel's inner point of single contact D); 1 for an internal wheel (6.2)."""
    if internal:
        return 1.0
    return z_b(alpha_w, d_a2, d_b2, z2, d_a1, d_b1, z1, eps_alpha, False)


def contact_factors(alpha, alpha_w, eps_alpha) -> tuple[float, float, float]:
    """(Z_H, Z_E, Z_ε) of a steel spur mesh."""
    return z_h(alpha, alpha_w), z_e(), z_eps(eps_alpha)


def tooth_form_factor(z: int, m: float, x: float, d_en: float, alpha: float = math.radians(20.0),
                      h_fP_star: float = 1.25, rho_fP_star: float = 0.38, s_pr: float = 0.0,
                      E_sn: float = 0.0) -> ToothForm:
    """Y_F and Y_S of an external spur gear cut by a rack, load at diameter d_en (ISO 6336-3 eq. 22–32;
    method C of the 1996 edition puts d_en = d_a).

    E_sn: the tooth thickness allowance the gear is made with (arc thickness on d, mm, the reduction), cut as the
    solids are: the rack's tooth widened by E_sn at the same depth (each flank moved E_sn/2 along the pitch line,
    the root circle kept), so E = π/4·m − h_fP·tan α + s_pr/cos α − (1 − sin α)·ρ_fP/cos α + E_sn/2 and the
    tooth's half angle at d_en, γ_e, loses E_sn/d (ISO 6336-3:2019, 6.2: the form factor of the tooth as generated)."""
    require_positive("z", z)
    if not (math.isfinite(E_sn) and E_sn >= 0.0):
        raise InputError("E_sn", E_sn, "tooth thickness allowance must be >= 0 mm")
    h_fP, rho_fP = h_fP_star * m, rho_fP_star * m
    E = (math.pi / 4 * m - h_fP * math.tan(alpha) + s_pr / math.cos(alpha)
         - (1 - math.sin(alpha)) * rho_fP / math.cos(alpha) + 0.5 * E_sn)
    G = rho_fP_star - h_fP_star + x
    H = 2.0 / z * (math.pi / 2 - E / m) - math.pi / 3
    theta = math.pi / 6
    for _ in range(200):
        new = 2.0 * G / z * math.tan(theta) - H
        if abs(new - theta) < 1e-14:
            theta = new
            break
        theta = new
    else:  # z = 1, 2 (the fixed point repels) and a few teeth of extreme racks (35°, h_a* 0.8, z <= 7, x <= -1)
        raise InputError("z", z, "30° tangent iteration of ISO 6336-3 did not converge")
    s_Fn = m * (z * math.sin(math.pi / 3 - theta) + math.sqrt(3.0) * (G / math.cos(theta) - rho_fP_star))
    rho_F = m * (rho_fP_star + 2.0 * G * G / (math.cos(theta) * (z * math.cos(theta) ** 2 - 2.0 * G)))
    d = m * z
    d_b = d * math.cos(alpha)
    if not d_en > d_b:
        raise InputError("d_en", d_en, f"must exceed the base diameter {d_b:.4f} mm")
    a_en = math.acos(d_b / d_en)
    g_e = (math.pi / 2 + 2.0 * x * math.tan(alpha)) / z - E_sn / d + inv(alpha) - inv(a_en)
    a_Fen = a_en - g_e
    h_Fe = 0.5 * m * ((math.cos(g_e) - math.sin(g_e) * math.tan(a_Fen)) * d_en / m - z * math.cos(math.pi / 3 - theta)
                      - G / math.cos(theta) + rho_fP_star)
    Y_F = 6.0 * (h_Fe / m) * math.cos(a_Fen) / ((s_Fn / m) ** 2 * math.cos(alpha))
    L = s_Fn / h_Fe
    q_s = s_Fn / (2.0 * rho_F)
    Y_S = (1.2 + 0.13 * L) * q_s ** (1.0 / (1.21 + 2.3 / L))
    return ToothForm(theta, s_Fn, rho_F, h_Fe, a_Fen, Y_F, Y_S)


def k_v_method_b(v: float, z1: int, u: float, Ft_b: float, K_A: float, grade: int) -> float:
    """Dynamic factor K_v of a spur mesh (ISO 6336-1:2006 eq. 14, method B simplified); v in m/s at the
    reference circle (relative to the carrier in a planetary set), F_t/b in N/mm (taken >= 100)."""
    if grade not in _K1_SPUR:
        raise InputError("accuracy_grade", grade, "must be an ISO 1328 grade 3 ... 12")
    load = max(K_A * Ft_b, 100.0)
    return 1.0 + (_K1_SPUR[grade] / load + _K2_SPUR) * v * z1 / 100.0 * math.sqrt(u * u / (1.0 + u * u))


def f_h_beta(d: float, b: float, grade: int) -> float:
    """Helix slope deviation f_Hβ of ISO 1328-1:1995, µm: (0.07√d + 0.45√b + 3)·2^((Q − 5)/2)."""
    return (0.07 * math.sqrt(d) + 0.45 * math.sqrt(b) + 3.0) * 2.0 ** ((grade - 5) / 2.0)


def f_sh_torsion(F_m: float, b: float, d1: float, n_meshes: int = 1) -> float:
    """Pinion torsional deformation f_sh, µm, ISO 6336-1:2019, clause 7, method C, with no shaft bending:
    0.023·(n·F_m/b)·(b/d_1)² (F_m in N per mesh, b and d_1 in mm).  n: the meshes whose torque the pinion's body
    carries over the face width — a pinion meshing with several gears (a sun with n planets) twists under
    the sum of their torques, n·F_m, not under one mesh's."""
    if int(n_meshes) != n_meshes or n_meshes < 1:
        raise InputError("n_meshes", n_meshes, "must be a whole number of meshes >= 1")
    return 0.023 * (n_meshes * F_m / b) * (b / d1) ** 2


@dataclass(frozen=True)
class FaceLoad:
    """The steps of K_Hβ, K_Fβ by ISO 6336-1 method C (µm, N/(mm·µm), N/mm)."""

    f_sh: float
    f_ma: float
    F_betax: float
    y_beta: float
    F_betay: float
    c_gamma_beta: float
    F_m_b: float
    K_Hbeta: float
    h: float
    N_F: float
    K_Fbeta: float


def face_load_method_c(F_m: float, b: float, d1: float, grade: int, h: float, c_gamma_alpha: float = 20.0,
                       f_sh: float = 0.0) -> FaceLoad:
    """K_Hβ and K_Fβ by ISO 6336-1 method C: F_βx = 1.33·f_sh + f_ma, f_ma = f_Hβ (see module docstring)."""
    f_ma = f_h_beta(d1, b, grade)
    F_bx = 1.33 * f_sh + f_ma
    y_b = min(0.15 * F_bx, 6.0)
    F_by = F_bx - y_b
    c_gb = 0.85 * c_gamma_alpha
    K_Hb = 1.0 + c_gb * F_by / (2.0 * F_m / b)
    if K_Hb > 2.0:  # the contact does not span the face
        K_Hb = math.sqrt(2.0 * c_gb * F_by / (F_m / b))
    bh = max(b / h, 3.0)   # ISO 6336-1: b/h < 3 is taken as 3
    N_F = bh * bh / (1.0 + bh + bh * bh)
    return FaceLoad(f_sh, f_ma, F_bx, y_b, F_by, c_gb, F_m / b, K_Hb, h, N_F, K_Hb ** N_F)


def k_h_beta_method_c(F_m: float, b: float, d1: float, grade: int, h: float,
                      c_gamma_alpha: float = 20.0, f_sh: float = 0.0) -> tuple[float, float]:
    """(K_Hβ, K_Fβ) by ISO 6336-1 method C with F_βx = 1.33·f_sh + f_ma (see module docstring)."""
    f = face_load_method_c(F_m, b, d1, grade, h, c_gamma_alpha, f_sh)
    return f.K_Hbeta, f.K_Fbeta


def k_h_alpha(grade: int) -> float:
    """K_Hα = K_Fα of surface-hardened spur gears (ISO 6336-1:2006 Table 9)."""
    if grade not in _KHA_HARDENED_SPUR:
        raise InputError("accuracy_grade", grade, "Table 9 of ISO 6336-1 is used for grades 3 ... 8")
    return _KHA_HARDENED_SPUR[grade]


def d_en_single_contact(d_a: float, d_b: float, m: float, alpha: float, eps_alpha: float) -> float:
    """Diameter of the outer point of single pair contact of an external spur gear (ISO 6336-3:2006 method B):
    the tip point moved (ε_α − 1) base pitches down the line of action."""
    r_b = 0.5 * d_b
    g = math.sqrt((0.5 * d_a) ** 2 - r_b ** 2) - math.pi * m * math.cos(alpha) * (eps_alpha - 1.0)
    return 2.0 * math.sqrt(g * g + r_b * r_b)


@dataclass(frozen=True)
class MeshLoad:
    """What loads one mesh: the pinion torque per mesh, the speed, the quality; `pinion_torsion`: the pinion
    passes its torque through its body (a sun), so its torsional deformation f_sh enters K_Hβ; `pinion_meshes`: the
    number of meshes whose torque that body carries (the sun: every planet's), which f_sh takes as the torque."""

    T1: float          # N·m on the pinion (one mesh)
    v: float = 0.0     # m/s at the reference circle (relative to the carrier)
    K_A: float = 1.0
    grade: int = 6
    pinion_torsion: bool = False
    pinion_meshes: int = 1   # meshes whose torque twists the pinion's body (a sun: the number of planets)


@dataclass(frozen=True)
class MeshStress:
    F_t: float
    b: float
    K_A: float
    K_v: float
    K_Hbeta: float
    K_Halpha: float
    K_Fbeta: float
    K_Falpha: float
    Z_H: float
    Z_E: float
    Z_eps: float
    Z_B: float
    sigma_H0: float
    sigma_H: float
    Y_F1: float          # method C (load at the tip), Y_ε applied
    Y_S1: float
    Y_F2: float | None
    Y_S2: float | None
    Y_eps: float
    sigma_F1: float
    sigma_F2: float | None
    # --- the basis and the other method
    d1: float = 0.0              # mm, the pinion's reference diameter F_t is taken on
    u: float = 0.0               # z2/z1, negative for an internal mate
    eps_alpha: float = 0.0
    Z_D: float = 1.0
    face: FaceLoad | None = None
    root1_B: ToothForm | None = None     # method B (outer point of single contact), no Y_ε
    root2_B: ToothForm | None = None
    d_en1: float = 0.0
    d_en2: float | None = None
    sigma_F1_B: float = 0.0
    sigma_F2_B: float | None = None
    a_w: float = 0.0             # mm, the centre distance the mesh runs at
    Y_B2: float = 1.0            # rim thickness factor of the wheel (an internal wheel's rim)
    b_F1: float = 0.0            # mm, face widths the roots are bent over (pinion, wheel)
    b_F2: float = 0.0
    alpha_w: float = 0.0         # rad, its operating pressure angle

    @property
    def sigma_H_wheel(self) -> float:
        """σ_H of the wheel: Z_D instead of Z_B (ISO 6336-2)."""
        return self.sigma_H / self.Z_B * self.Z_D


def operating_angle(pair, a_w: float | None) -> float:
    """Operating pressure angle α_w of a pair run at the centre distance a_w (mm): cos α_w = a·cos α/a_w
    (ISO 21771, a = m·(z2 ± z1)/2); None: the pair's own α_w from its shifts."""
    if a_w is None:
        return pair.alpha_w
    require_positive("a_w", a_w, "mm")
    c = pair.a * math.cos(pair.alpha) / a_w
    if not 0.0 < c < 1.0:
        raise InputError("a_w", a_w, f"no involute mesh at this centre distance (a·cos α/a_w = {c:.6f})")
    return math.acos(c)


def root_face_width(b_gear: float, b_mesh: float, m: float) -> float:
    """Face width a gear's root is bent over, mm (ISO 6336-3:2019, 5.2): the mesh's common face b_mesh plus at most
    one module beyond each of its ends, within the gear's own face b_gear."""
    return min(b_gear, b_mesh + 2.0 * m)


@dataclass(frozen=True)
class InternalRoot:
    """What the root of an internal wheel needs beyond the pair (ISO 6336-3:2019, internal gears): its arc tooth
    thickness on the reference circle as made (mm), the fillet radius ρ_fP2 (the generating cutter's tip radius,
    mm) and the rim under the root s_R (mm)."""

    s: float
    rho_fP: float
    s_R: float


def mesh_stress(pair, d_a1: float, d_a2: float, b: float, load: MeshLoad, a_w: float | None = None,
                internal_root: InternalRoot | None = None, E_sn: float = 0.0,
                b_F: tuple[float, float] | None = None) -> MeshStress:
    """σ_H and σ_F of one spur mesh (a :class:`~propulsor.gears.gear_pair.GearPair`), face width b (mm), tips
    d_a1, d_a2 as made.  a_w: the centre distance the mesh runs at when its mounting sets it (a planet on its
    carrier pin), which may differ from the one of the shifts; α_w, ε_α, Z_H, Z_B and Z_D are then taken there:
    cos α_w = a·cos α/a_w, ε_α = (ρ_a1 ± ρ_a2 ∓ a_w·sin α_w)/p_b (ISO 21771; ± external/internal).
    internal_root: the internal wheel's root is rated too (:mod:`propulsor.gears.iso6336_internal`), with Y_B of
    its rim; without it an internal wheel's root stress stays None.  E_sn: the tooth thickness allowance the external
    gears are made with (see :func:`tooth_form_factor`); an internal wheel's is in its ``internal_root.s``.
    b_F: the face widths (mm) each root is bent over, pinion and wheel (default b both): ISO 6336-3:2019, 5.2 —
    the wider gear's root may be taken as the narrower face plus at most one module on each side
    (:func:`root_face_width`)."""
    require_positive("b", b, "mm")
    bF1, bF2 = (b, b) if b_F is None else (require_positive("b_F1", b_F[0], "mm"), require_positive("b_F2", b_F[1], "mm"))
    g1, g2 = pair.gear1, pair.gear2
    m, alpha = pair.m, pair.alpha
    aw = operating_angle(pair, a_w)
    a_w_run = pair.a_w if a_w is None else a_w
    if a_w is None:
        eps = pair.epsilon_alpha(d_a1, d_a2)
    else:
        r1, r2 = g1.rho_at(d_a1), g2.rho_at(d_a2)
        g = a_w_run * math.sin(aw)
        eps = ((r1 - r2 + g) if pair.internal else (r1 + r2 - g)) / g1.p_b
    u = g2.z / g1.z * (-1.0 if pair.internal else 1.0)
    d1 = g1.d
    F_t = 2000.0 * load.T1 / d1
    K_v = k_v_method_b(load.v, g1.z, abs(u), F_t / b, load.K_A, load.grade)
    # ISO 6336-1 (K_Fβ): b/h the smaller of b/h1 and b/h2 - the deeper tooth's depth (an internal gear's root
    # circle lies outside its tip circle)
    h = max(0.5 * (d_a1 - g1.d_f), 0.5 * abs(g2.d_f - d_a2))
    F_m = F_t * load.K_A * K_v
    f_sh = f_sh_torsion(F_m, b, d1, load.pinion_meshes) if load.pinion_torsion else 0.0
    face = face_load_method_c(F_m, b, d1, load.grade, h, f_sh=f_sh)
    K_Hb, K_Fb = face.K_Hbeta, face.K_Fbeta
    K_Ha = k_h_alpha(load.grade)
    Z_H, Z_E, Z_e = contact_factors(alpha, aw, eps)
    Z_B = z_b(aw, d_a1, g1.d_b, g1.z, d_a2, g2.d_b, g2.z, eps, pair.internal)
    Z_D = z_d(aw, d_a1, g1.d_b, g1.z, d_a2, g2.d_b, g2.z, eps, pair.internal)
    s0 = Z_H * Z_E * Z_e * math.sqrt(F_t / (d1 * b) * (u + 1.0) / u)
    sH = Z_B * s0 * math.sqrt(load.K_A * K_v * K_Hb * K_Ha)
    rack = g1.rack
    Y_eps = 0.25 + 0.75 / eps
    K = load.K_A * K_v * K_Fb * K_Ha
    f1 = tooth_form_factor(g1.z, m, g1.x, d_a1, alpha, rack.h_fP_star, rack.rho_f_star, E_sn=E_sn)
    sF1 = F_t / (bF1 * m) * f1.Y_F * f1.Y_S * Y_eps * K
    d_en1 = d_en_single_contact(d_a1, g1.d_b, m, alpha, eps)
    b1 = tooth_form_factor(g1.z, m, g1.x, d_en1, alpha, rack.h_fP_star, rack.rho_f_star, E_sn=E_sn)
    sF1_B = F_t / (bF1 * m) * b1.Y_F * b1.Y_S * K
    Y_F2 = Y_S2 = sF2 = b2 = d_en2 = sF2_B = None
    Y_B2 = 1.0
    if pair.internal and internal_root is not None:
        from .iso6336_internal import d_en_internal, internal_tooth_form, y_b_internal

        ir = internal_root
        Y_B2 = y_b_internal(ir.s_R, m)
        f2 = internal_tooth_form(g2.d, g2.d_f, ir.s, m, ir.rho_fP, d_a2, alpha)
        Y_F2, Y_S2 = f2.Y_F, f2.Y_S
        sF2 = F_t / (bF2 * m) * Y_F2 * Y_S2 * Y_eps * Y_B2 * K
        d_en2 = d_en_internal(d_a2, g2.d_b, m, alpha, eps)
        b2 = internal_tooth_form(g2.d, g2.d_f, ir.s, m, ir.rho_fP, d_en2, alpha)
        sF2_B = F_t / (bF2 * m) * b2.Y_F * b2.Y_S * Y_B2 * K
    if not pair.internal:
        rack2 = g2.rack
        f2 = tooth_form_factor(g2.z, m, g2.x, d_a2, alpha, rack2.h_fP_star, rack2.rho_f_star, E_sn=E_sn)
        Y_F2, Y_S2 = f2.Y_F, f2.Y_S
        sF2 = F_t / (bF2 * m) * Y_F2 * Y_S2 * Y_eps * K
        d_en2 = d_en_single_contact(d_a2, g2.d_b, m, alpha, eps)
        b2 = tooth_form_factor(g2.z, m, g2.x, d_en2, alpha, rack2.h_fP_star, rack2.rho_f_star, E_sn=E_sn)
        sF2_B = F_t / (bF2 * m) * b2.Y_F * b2.Y_S * K
    return MeshStress(F_t, b, load.K_A, K_v, K_Hb, K_Ha, K_Fb, K_Ha, Z_H, Z_E, Z_e, Z_B, s0, sH,
                      f1.Y_F, f1.Y_S, Y_F2, Y_S2, Y_eps, sF1, sF2,
                      d1=d1, u=u, eps_alpha=eps, Z_D=Z_D, face=face, root1_B=b1, root2_B=b2, d_en1=d_en1,
                      d_en2=d_en2, sigma_F1_B=sF1_B, sigma_F2_B=sF2_B, a_w=a_w_run, alpha_w=aw, Y_B2=Y_B2,
                      b_F1=bF1, b_F2=bF2)
