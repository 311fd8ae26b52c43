"""ISO 6336 rating (gears/iso6336*.py, gear_materials.py, planetary*.py) checked against the standard's equations
computed here, independently of the code: both sides of every limit and clamp, refusals' messages in full
(issue 36, mutation testing: `make mutation MODULE=gears_rating`).  Fast, in-process, no part builds."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.gears import iso6336 as iso
from propulsor.gears.gear_pair import GearPair
from propulsor.gears.involute import BasicRack, SpurGear
from propulsor.gears.planetary import PlanetarySet

A20, A25 = math.radians(20.0), math.radians(25.0)
# Z_E of steel on steel, ISO 6336-2 eq. 18 with E = 206 000 MPa, ν = 0.3 (189.81 √MPa)
Z_E_STEEL = math.sqrt(1.0 / (math.pi * 2.0 * (1.0 - 0.3 ** 2) / 206000.0))
# ISO 6336-1:2006 Table 8, K_1 of spur gears by ISO 1328 grade; Table 9, K_Hα of surface-hardened spur gears
K1_TABLE_8 = {3: 2.1, 4: 3.9, 5: 7.5, 6: 14.9, 7: 26.8, 8: 39.1, 9: 52.8, 10: 76.6, 11: 102.6, 12: 146.3}
KHA_TABLE_9 = {3: 1.0, 4: 1.0, 5: 1.0, 6: 1.0, 7: 1.1, 8: 1.2}


def _message(fn, *args, **kw) -> str:
    with pytest.raises(InputError) as e:
        fn(*args, **kw)
    return str(e.value)


def _inv(a):
    return math.tan(a) - a


def _bisect(f, lo, hi):
    """A root of f between lo and hi (f changes sign), by bisection to the last float: a solver unlike the
    module's fixed-point iteration."""
    flo = f(lo)
    assert flo * f(hi) < 0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        if mid in (lo, hi) or fm == 0.0:
            return mid
        if (fm < 0) == (flo < 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def form_by_hand(z, m, x, d_en, alpha=A20, h_fP_star=1.25, rho_star=0.38, s_pr=0.0, E_sn=0.0):
    """ISO 6336-3:2006 eq. 22–32 (the 30° tangent of a rack-generated fillet), the load at d_en, written out;
    E_sn: the rack's tooth widened by the thickness allowance (E + E_sn/2, γ_e − E_sn/d).  θ by bisection."""
    h_fP, rho = h_fP_star * m, rho_star * m
    E = (math.pi / 4 * m - h_fP * math.tan(alpha) + s_pr / math.cos(alpha)
         - (1 - math.sin(alpha)) * rho / math.cos(alpha) + E_sn / 2)                     # eq. 22
    G = rho / m - h_fP / m + x                                                            # eq. 23
    H = 2 / z * (math.pi / 2 - E / m) - math.pi / 3                                      # eq. 24
    theta = _bisect(lambda t: t - (2 * G / z * math.tan(t) - H), 0.0, math.pi / 3)      # eq. 25
    s_Fn = m * (z * math.sin(math.pi / 3 - theta) + math.sqrt(3) * (G / math.cos(theta) - rho / m))   # eq. 26
    rho_F = m * (rho / m + 2 * G ** 2 / (math.cos(theta) * (z * math.cos(theta) ** 2 - 2 * G)))       # eq. 27
    d = m * z
    a_en = math.acos(d * math.cos(alpha) / d_en)
    g_e = (math.pi / 2 + 2 * x * math.tan(alpha)) / z - E_sn / d + _inv(alpha) - _inv(a_en)
    a_Fen = a_en - g_e
    h_Fe = 0.5 * m * ((math.cos(g_e) - math.sin(g_e) * math.tan(a_Fen)) * d_en / m
                      - z * math.cos(math.pi / 3 - theta) - G / math.cos(theta) + rho / m)
    Y_F = 6 * (h_Fe / m) * math.cos(a_Fen) / ((s_Fn / m) ** 2 * math.cos(alpha))
    L, q_s = s_Fn / h_Fe, s_Fn / (2 * rho_F)
    Y_S = (1.2 + 0.13 * L) * q_s ** (1 / (1.21 + 2.3 / L))
    return dict(theta=theta, s_Fn=s_Fn, rho_F=rho_F, h_Fe=h_Fe, alpha_Fen=a_Fen, Y_F=Y_F, Y_S=Y_S)


def internal_form_by_hand(d, d_f, s, m, rho, d_en, alpha):
    """ISO 6336-3:2019, 6.2, internal gear: the substitute rack on the reference circle (depth y from d2)."""
    t = math.tan(alpha)
    h_fP = (d_f - d) / 2
    x_c = s / 2 + (h_fP - rho) * t + rho / math.cos(alpha)
    s_Fn = 2 * (x_c - rho * math.sqrt(3) / 2)
    y_F = h_fP - rho / 2
    y_e = (d_en - d) / 2
    h_Fe = y_F - y_e - (s / 2 + y_e * t) * t
    if not (h_Fe > 0 and s_Fn > 0):
        return dict(s_Fn=s_Fn, h_Fe=h_Fe)
    Y_F = 6 * (h_Fe / m) / (s_Fn / m) ** 2
    L, q_s = s_Fn / h_Fe, s_Fn / (2 * rho)
    return dict(theta=math.pi / 6, s_Fn=s_Fn, rho_F=rho, h_Fe=h_Fe, alpha_Fen=alpha, Y_F=Y_F,
                Y_S=(1.2 + 0.13 * L) * q_s ** (1 / (1.21 + 2.3 / L)))


def _fields(form):
    return {k: getattr(form, k) for k in ("theta", "s_Fn", "rho_F", "h_Fe", "alpha_Fen", "Y_F", "Y_S")}


# ============================================================================ iso6336.py: refusals in full
def _pair():
    return GearPair(SpurGear(18, 5.0, 0.3), SpurGear(41, 5.0, 0.2))


def test_iso6336_refusals_name_the_parameter_its_value_and_the_limit():
    from propulsor.gears.iso6336 import (f_sh_torsion, k_h_alpha, k_v_method_b, mesh_stress, MeshLoad,
                                         operating_angle, tooth_form_factor)
    whole = "must be a whole number of meshes >= 1"
    assert _message(f_sh_torsion, 1000.0, 40.0, 100.0, 0) == f"n_meshes = 0: {whole}"
    assert _message(f_sh_torsion, 1000.0, 40.0, 100.0, 1.5) == f"n_meshes = 1.5: {whole}"   # >= 1, not whole
    assert _message(f_sh_torsion, 1000.0, 40.0, 100.0, 0.5) == f"n_meshes = 0.5: {whole}"
    for g in (2, 9):
        assert _message(k_h_alpha, g) == f"accuracy_grade = {g}: Table 9 of ISO 6336-1 is used for grades 3 ... 8"
    for g in (2, 13):
        assert (_message(k_v_method_b, 1.0, 16, 1.0, 100.0, 1.0, g)
                == f"accuracy_grade = {g}: must be an ISO 1328 grade 3 ... 12")
    assert _message(tooth_form_factor, 0, 10.0, 0.0, 180.0) == "z = 0: must be > 0"
    assert (_message(tooth_form_factor, 16, 10.0, 0.0, 180.0, E_sn=-0.1)
            == "E_sn = -0.1: tooth thickness allowance must be >= 0 mm")
    assert (_message(tooth_form_factor, 16, 10.0, 0.0, 180.0, E_sn=math.inf)
            == "E_sn = inf: tooth thickness allowance must be >= 0 mm")
    assert (_message(tooth_form_factor, 16, 10.0, 0.0, 150.0)
            == "d_en = 150.0: must exceed the base diameter 150.3508 mm")          # 160·cos 20°
    # one or two teeth: 2G/z·sec²θ beyond -1, the 30° tangent's fixed point repels
    for z in (1, 2):
        assert (_message(tooth_form_factor, z, 1.0, 0.0, z + 2.0)
                == f"z = {z}: 30° tangent iteration of ISO 6336-3 did not converge")
    pair = _pair()
    load = MeshLoad(700.0)
    assert _message(mesh_stress, pair, pair.d_a1, pair.d_a2, 0.0, load) == "b = 0.0: must be > 0 mm"
    assert (_message(mesh_stress, pair, pair.d_a1, pair.d_a2, 40.0, load, b_F=(0.0, 40.0))
            == "b_F1 = 0.0: must be > 0 mm")
    assert (_message(mesh_stress, pair, pair.d_a1, pair.d_a2, 40.0, load, b_F=(40.0, -2.0))
            == "b_F2 = -2.0: must be > 0 mm")
    assert _message(operating_angle, pair, 0.0) == "a_w = 0.0: must be > 0 mm"
    a_cos = pair.a * math.cos(pair.alpha)                   # a_w = a·cos α: α_w = 0, no mesh (c = 1 exactly)
    assert (_message(operating_angle, pair, a_cos)
            == f"a_w = {a_cos!r}: no involute mesh at this centre distance (a·cos α/a_w = 1.000000)")
    assert (_message(operating_angle, pair, 0.9 * a_cos)
            == f"a_w = {0.9 * a_cos!r}: no involute mesh at this centre distance (a·cos α/a_w = 1.111111)")
    assert operating_angle(pair, a_cos * 1.000001) == pytest.approx(math.acos(1 / 1.000001), rel=1e-9)
    assert operating_angle(pair, None) == pair.alpha_w


# ============================================================================ iso6336.py: factors by hand
CASES = [  # z, m, x, d_en/m - z (the load point), rack, s_pr (mm), E_sn (mm)
    (16, 10.0, 0.5, 3.0, BasicRack(), 0.0, 0.0),
    (23, 4.0, -0.2, 1.6, BasicRack(rho_f_star=0.25), 0.0, 0.12),
    (31, 2.0, 0.3, 2.2, BasicRack(alpha=A25, rho_f_star=0.3), 0.04, 0.0),
    (40, 5.0, 0.0, 1.0, BasicRack(c_star=0.35, rho_f_star=0.3), 0.1, 0.2),
]


@pytest.mark.parametrize("z,m,x,over,rack,s_pr,E_sn", CASES)
def test_tooth_form_factor_is_iso_6336_3_eq_22_to_32(z, m, x, over, rack, s_pr, E_sn):
    from propulsor.gears.iso6336 import tooth_form_factor
    d_en = m * (z + over)
    t = tooth_form_factor(z, m, x, d_en, rack.alpha, rack.h_fP_star, rack.rho_f_star, s_pr=s_pr, E_sn=E_sn)
    hand = form_by_hand(z, m, x, d_en, rack.alpha, rack.h_fP_star, rack.rho_f_star, s_pr, E_sn)
    assert _fields(t) == pytest.approx(hand, rel=1e-11, abs=1e-13)


def test_protuberance_widens_the_root_chord_by_s_pr_over_cos_alpha_in_e():
    from propulsor.gears.iso6336 import tooth_form_factor
    a = tooth_form_factor(20, 1.0, 0.0, 22.0)
    b = tooth_form_factor(20, 1.0, 0.0, 22.0, s_pr=0.05)
    assert b.s_Fn < a.s_Fn       # E grows, H falls, θ changes: the undercut fillet thins the root
    assert _fields(b) == pytest.approx(form_by_hand(20, 1.0, 0.0, 22.0, s_pr=0.05), rel=1e-11)


def test_dynamic_factor_uses_table_8_at_every_grade():
    from propulsor.gears.iso6336 import k_v_method_b
    for grade, K1 in K1_TABLE_8.items():
        u = 2.5
        expected = 1.0 + (K1 / (1.25 * 400.0) + 0.0193) * 4.0 * 20 / 100.0 * math.sqrt(u * u / (1 + u * u))
        assert k_v_method_b(4.0, 20, u, 400.0, 1.25, grade) == pytest.approx(expected, rel=1e-12)


def test_transverse_load_factor_is_table_9():
    from propulsor.gears.iso6336 import k_h_alpha
    assert {g: k_h_alpha(g) for g in range(3, 9)} == KHA_TABLE_9


def test_torsional_deformation_is_one_mesh_by_default_and_n_meshes_times_it():
    from propulsor.gears.iso6336 import f_sh_torsion
    one = 0.023 * (30000.0 / 75.0) * (75.0 / 160.0) ** 2
    assert f_sh_torsion(30000.0, 75.0, 160.0) == pytest.approx(one, rel=1e-14)
    assert f_sh_torsion(30000.0, 75.0, 160.0, 3) == pytest.approx(3 * one, rel=1e-14)
    assert f_sh_torsion(30000.0, 75.0, 160.0, 2.0) == pytest.approx(2 * one, rel=1e-14)


def _face_by_hand(F_m, b, d1, grade, h, c_gamma_alpha=20.0, f_sh=0.0):
    f_ma = (0.07 * math.sqrt(d1) + 0.45 * math.sqrt(b) + 3.0) * 2.0 ** ((grade - 5) / 2.0)   # ISO 1328-1 f_Hβ
    F_bx = 1.33 * f_sh + f_ma
    y_b = min(0.15 * F_bx, 6.0)
    F_by = F_bx - y_b
    c_gb = 0.85 * c_gamma_alpha
    K = 1.0 + c_gb * F_by / (2.0 * F_m / b)
    if K > 2.0:
        K = math.sqrt(2.0 * c_gb * F_by / (F_m / b))
    bh = max(b / h, 3.0)                                   # ISO 6336-1:2006 eq. 61–62: b/h taken >= 3
    N_F = bh ** 2 / (1 + bh + bh ** 2)
    return dict(f_sh=f_sh, f_ma=f_ma, F_betax=F_bx, y_beta=y_b, F_betay=F_by, c_gamma_beta=c_gb, F_m_b=F_m / b,
                K_Hbeta=K, h=h, N_F=N_F, K_Fbeta=K ** N_F)


@pytest.mark.parametrize("F_m,b,d1,grade,h,c,f_sh", [
    (100000.0, 75.0, 160.0, 6, 22.5, 20.0, None),     # f_sh left out: 0
    (60000.0, 40.0, 90.0, 7, 11.0, 18.0, 4.0),
    (3000.0, 75.0, 160.0, 8, 22.5, 20.0, 50.0),       # y_β at its 6 µm, the contact not spanning the face
    (40000.0, 30.0, 90.0, 6, 15.0, 20.0, 2.0),        # a narrow face, b/h = 2: N_F of b/h = 3
])
def test_face_load_method_c_every_step(F_m, b, d1, grade, h, c, f_sh):
    from propulsor.gears.iso6336 import face_load_method_c
    f = (face_load_method_c(F_m, b, d1, grade, h, c) if f_sh is None
         else face_load_method_c(F_m, b, d1, grade, h, c, f_sh=f_sh))
    hand = _face_by_hand(F_m, b, d1, grade, h, c, f_sh or 0.0)
    got = {k: getattr(f, k) for k in hand}
    assert got == pytest.approx(hand, rel=1e-13)


def test_root_face_width_is_the_common_face_plus_a_module_each_side_within_the_gear():
    from propulsor.gears.iso6336 import root_face_width
    assert root_face_width(100.0, 40.0, 10.0) == 60.0
    assert root_face_width(55.0, 40.0, 10.0) == 55.0
    assert root_face_width(40.0, 40.0, 10.0) == 40.0


# ============================================================================ iso6336.py: mesh_stress by hand
def _k_v(v, z1, u, Ft_b, K_A, grade):
    u = abs(u)
    return 1.0 + (K1_TABLE_8[grade] / max(K_A * Ft_b, 100.0) + 0.0193) * v * z1 / 100.0 * math.sqrt(u * u / (1 + u * u))


def _m1(alpha_w, d_a1, d_b1, z1, d_a2, d_b2, z2, eps, internal):
    """M_1 of ISO 6336-2:2019, 6.2 (the internal wheel's bracket with + (ε_α − 1)·2π/|z2|)."""
    f1 = math.sqrt((d_a1 / d_b1) ** 2 - 1) - 2 * math.pi / z1
    f2 = math.sqrt((d_a2 / d_b2) ** 2 - 1) + (1 if internal else -1) * (eps - 1) * 2 * math.pi / z2
    return math.tan(alpha_w) / math.sqrt(f1 * f2)


def _external_stress_by_hand(pair, d_a1, d_a2, b, T1, v, K_A, grade, a_w, E_sn, bF, torsion=None):
    g1, g2, m, alpha = pair.gear1, pair.gear2, pair.m, pair.alpha
    aw = math.acos(pair.a * math.cos(alpha) / a_w)
    r_b1, r_b2 = g1.d_b / 2, g2.d_b / 2
    p_b = math.pi * m * math.cos(alpha)
    eps = (math.sqrt((d_a1 / 2) ** 2 - r_b1 ** 2) + math.sqrt((d_a2 / 2) ** 2 - r_b2 ** 2) - a_w * math.sin(aw)) / p_b
    u = g2.z / g1.z
    d1 = m * g1.z
    F_t = 2000.0 * T1 / d1
    K_v = _k_v(v, g1.z, u, F_t / b, K_A, grade)
    F_m = F_t * K_A * K_v
    f_sh = 0.0 if torsion is None else 0.023 * (torsion * F_m / b) * (b / d1) ** 2
    # ISO 6336-1: b/h the smaller of b/h1 and b/h2 (the deeper of the two teeth)
    face = _face_by_hand(F_m, b, d1, grade, max((d_a1 - g1.d_f) / 2, (d_a2 - pair.gear2.d_f) / 2), f_sh=f_sh)
    K_Ha = KHA_TABLE_9[grade]
    Z_H = math.sqrt(2 * math.cos(aw) / (math.cos(alpha) ** 2 * math.sin(aw)))
    Z_eps = math.sqrt((4 - eps) / 3)
    Z_B = max(1.0, _m1(aw, d_a1, g1.d_b, g1.z, d_a2, g2.d_b, g2.z, eps, False))
    Z_D = max(1.0, _m1(aw, d_a2, g2.d_b, g2.z, d_a1, g1.d_b, g1.z, eps, False))
    s0 = Z_H * Z_E_STEEL * Z_eps * math.sqrt(F_t / (d1 * b) * (u + 1) / u)
    sH = Z_B * s0 * math.sqrt(K_A * K_v * face["K_Hbeta"] * K_Ha)
    Y_eps = 0.25 + 0.75 / eps
    K_F = K_A * K_v * face["K_Fbeta"] * K_Ha
    out = dict(F_t=F_t, b=b, K_A=K_A, K_v=K_v, K_Hbeta=face["K_Hbeta"], K_Halpha=K_Ha, K_Fbeta=face["K_Fbeta"],
               K_Falpha=K_Ha, Z_H=Z_H, Z_E=Z_E_STEEL, Z_eps=Z_eps, Z_B=Z_B, sigma_H0=s0, sigma_H=sH, Y_eps=Y_eps,
               d1=d1, u=u, eps_alpha=eps, Z_D=Z_D, a_w=a_w, alpha_w=aw, Y_B2=1.0, b_F1=bF[0], b_F2=bF[1],
               sigma_H_wheel=Z_D * s0 * math.sqrt(K_A * K_v * face["K_Hbeta"] * K_Ha))
    for i, (g, d_a) in enumerate(((g1, d_a1), (g2, d_a2)), start=1):
        rack = g.rack
        tip = form_by_hand(g.z, m, g.x, d_a, alpha, rack.h_fP_star, rack.rho_f_star, 0.0, E_sn)
        r_b, = (g.d_b / 2,)
        gg = math.sqrt((d_a / 2) ** 2 - r_b ** 2) - p_b * (eps - 1)       # method B: outer single contact
        d_en = 2 * math.sqrt(gg ** 2 + r_b ** 2)
        inner = form_by_hand(g.z, m, g.x, d_en, alpha, rack.h_fP_star, rack.rho_f_star, 0.0, E_sn)
        out[f"Y_F{i}"], out[f"Y_S{i}"] = tip["Y_F"], tip["Y_S"]
        out[f"sigma_F{i}"] = F_t / (bF[i - 1] * m) * tip["Y_F"] * tip["Y_S"] * Y_eps * K_F
        out[f"d_en{i}"] = d_en
        out[f"sigma_F{i}_B"] = F_t / (bF[i - 1] * m) * inner["Y_F"] * inner["Y_S"] * K_F
        out[f"root{i}_B"] = inner
    return out, face


def _compare(s, hand, face):
    got = {k: getattr(s, k) for k in hand if not k.startswith("root")}
    assert got == pytest.approx({k: v for k, v in hand.items() if not k.startswith("root")}, rel=1e-10)
    for k in ("root1_B", "root2_B"):
        assert _fields(getattr(s, k)) == pytest.approx(hand[k], rel=1e-10, abs=1e-12)
    assert {k: getattr(s.face, k) for k in face} == pytest.approx(face, rel=1e-12)


def test_external_mesh_stress_every_field_by_hand():
    """An external pair of a 0.25 fillet rack at 25°, grade 7 (K_Hα = 1.1), K_A = 1.25, running at a centre
    distance 0.3 mm over its shifts' (α_w, ε_α, Z_H, Z_B, Z_D there), the gears made with E_sn = 0.1 mm, the pinion's
    root bent over 44 mm of a 40 mm mesh."""
    from propulsor.gears.iso6336 import MeshLoad, mesh_stress
    rack = BasicRack(alpha=A25, rho_f_star=0.25)
    pair = GearPair(SpurGear(17, 4.0, 0.35, rack), SpurGear(46, 4.0, 0.1, rack))
    a_w = pair.a_w + 0.3
    d_a1, d_a2 = pair.d_a1 - 0.2, pair.d_a2 - 0.3
    s = mesh_stress(pair, d_a1, d_a2, 40.0, MeshLoad(300.0, 6.0, 1.25, 7), a_w=a_w, E_sn=0.1, b_F=(44.0, 40.0))
    hand, face = _external_stress_by_hand(pair, d_a1, d_a2, 40.0, 300.0, 6.0, 1.25, 7, a_w, 0.1, (44.0, 40.0))
    _compare(s, hand, face)
    assert s.sigma_H_wheel == pytest.approx(hand["sigma_H_wheel"], rel=1e-10)


def test_external_mesh_stress_of_a_twisted_pinion_at_its_own_centre_distance():
    """Grade 8 (K_Hα = 1.2), the pinion's body carrying three meshes' torque (f_sh = 0.023·3·F_m/b·(b/d)²), the
    mesh at its own α_w (a_w not given), ISO 53 rack, b_F not given (b both)."""
    from propulsor.gears.iso6336 import MeshLoad, mesh_stress
    pair = GearPair(SpurGear(19, 3.0, 0.2), SpurGear(37, 3.0, -0.1))
    s = mesh_stress(pair, pair.d_a1, pair.d_a2, 30.0, MeshLoad(150.0, 9.0, 1.1, 8, True, 3))
    hand, face = _external_stress_by_hand(pair, pair.d_a1, pair.d_a2, 30.0, 150.0, 9.0, 1.1, 8, pair.a_w, 0.0,
                                          (30.0, 30.0), torsion=3)
    _compare(s, hand, face)
    assert s.face.f_sh > 0


def _internal_pair():
    rack = BasicRack(alpha=A25, rho_f_star=0.3)
    return GearPair(SpurGear(18, 5.0, 0.3, rack), SpurGear(60, 5.0, 0.8, rack, internal=True, z0=20, x0=0.0))


@pytest.mark.parametrize("given_a_w", [False, True])
def test_internal_mesh_stress_every_field_by_hand(given_a_w):
    """A pinion in a ring at 25°, grade 7, K_A = 1.5; the ring's root rated as made (InternalRoot: thickness less
    0.15 mm, the shaper's 1.5 mm tip radius, a rim of 2.5·m under the root: Y_B = 1.15·ln(8.324/2.5))."""
    from propulsor.gears.iso6336 import InternalRoot, MeshLoad, mesh_stress
    pair = _internal_pair()
    g1, g2, m, alpha = pair.gear1, pair.gear2, pair.m, pair.alpha
    a_w = pair.a_w - 0.25 if given_a_w else pair.a_w
    d_a1, d_a2 = pair.d_a1, pair.d_a2
    ir = InternalRoot(g2.s - 0.15, 1.5, 12.5)
    b, T1, v, K_A, grade = 36.0, 220.0, 5.0, 1.5, 7
    s = mesh_stress(pair, d_a1, d_a2, b, MeshLoad(T1, v, K_A, grade), a_w=a_w if given_a_w else None,
                    internal_root=ir, b_F=(40.0, 38.0))
    aw = math.acos(pair.a * math.cos(alpha) / a_w)
    p_b = math.pi * m * math.cos(alpha)
    r_b1, r_b2 = g1.d_b / 2, g2.d_b / 2
    eps = (math.sqrt((d_a1 / 2) ** 2 - r_b1 ** 2) - math.sqrt((d_a2 / 2) ** 2 - r_b2 ** 2) + a_w * math.sin(aw)) / p_b
    u = -60 / 18
    d1 = 90.0
    F_t = 2000.0 * T1 / d1
    K_v = _k_v(v, 18, u, F_t / b, K_A, grade)
    face = _face_by_hand(F_t * K_A * K_v, b, d1, grade, max((d_a1 - g1.d_f) / 2, (g2.d_f - d_a2) / 2))
    Z_H = math.sqrt(2 * math.cos(aw) / (math.cos(alpha) ** 2 * math.sin(aw)))
    Z_eps = math.sqrt((4 - eps) / 3)
    Z_B = max(1.0, _m1(aw, d_a1, g1.d_b, 18, d_a2, g2.d_b, 60, eps, True))
    s0 = Z_H * Z_E_STEEL * Z_eps * math.sqrt(F_t / (d1 * b) * (u + 1) / u)
    Y_eps = 0.25 + 0.75 / eps
    K_F = K_A * K_v * face["K_Fbeta"] * 1.1
    Y_B = 1.15 * math.log(8.324 / 2.5)
    tip = internal_form_by_hand(g2.d, g2.d_f, ir.s, m, 1.5, d_a2, alpha)
    gg = math.sqrt((d_a2 / 2) ** 2 - r_b2 ** 2) + p_b * (eps - 1)
    d_en2 = 2 * math.sqrt(gg ** 2 + r_b2 ** 2)
    inner = internal_form_by_hand(g2.d, g2.d_f, ir.s, m, 1.5, d_en2, alpha)
    hand = dict(F_t=F_t, K_v=K_v, K_Hbeta=face["K_Hbeta"], K_Fbeta=face["K_Fbeta"], K_Halpha=1.1, K_Falpha=1.1,
                Z_H=Z_H, Z_E=Z_E_STEEL, Z_eps=Z_eps, Z_B=Z_B, Z_D=1.0, sigma_H0=s0, u=u, eps_alpha=eps, a_w=a_w,
                alpha_w=aw, sigma_H=Z_B * s0 * math.sqrt(K_A * K_v * face["K_Hbeta"] * 1.1), Y_eps=Y_eps, Y_B2=Y_B,
                Y_F2=tip["Y_F"], Y_S2=tip["Y_S"], d_en2=d_en2, b_F1=40.0, b_F2=38.0,
                sigma_F2=F_t / (38.0 * m) * tip["Y_F"] * tip["Y_S"] * Y_eps * Y_B * K_F,
                sigma_F2_B=F_t / (38.0 * m) * inner["Y_F"] * inner["Y_S"] * Y_B * K_F)
    assert {k: getattr(s, k) for k in hand} == pytest.approx(hand, rel=1e-10)
    assert _fields(s.root2_B) == pytest.approx(inner, rel=1e-10)
    assert Y_B > 1.0 and s.sigma_H_wheel == pytest.approx(s0 * math.sqrt(K_A * K_v * face["K_Hbeta"] * 1.1), rel=1e-10)


def test_internal_mesh_without_its_root_leaves_the_rings_root_unrated():
    from propulsor.gears.iso6336 import MeshLoad, mesh_stress
    pair = _internal_pair()
    s = mesh_stress(pair, pair.d_a1, pair.d_a2, 36.0, MeshLoad(220.0, 5.0))
    assert (s.Y_F2, s.Y_S2, s.sigma_F2, s.root2_B, s.d_en2, s.sigma_F2_B) == (None,) * 6
    assert s.Y_B2 == 1.0 and s.Z_D == 1.0 and s.sigma_F1 > 0 and s.b_F1 == s.b_F2 == 36.0


# ============================================================================ iso6336_internal.py
def test_internal_root_refusals_in_full():
    from propulsor.gears.iso6336_internal import d_en_internal, internal_tooth_form, y_b_internal
    assert (_message(d_en_internal, 500.0, 500.0, 10.0, A20, 1.4)
            == "d_a2 = 500.0: the internal wheel's tip must lie outside its base circle 500.0000 mm")
    args = dict(d=560.0, d_f=585.0, s=14.0, m=10.0, rho_fP=2.5, d_en=570.0)
    for name in ("d", "s", "m", "rho_fP", "d_en"):
        assert _message(internal_tooth_form, **{**args, name: 0.0}) == f"{name} = 0.0: must be > 0 mm"
    assert (_message(internal_tooth_form, **{**args, "d_f": 560.0})
            == "d_f = 560.0: an internal gear's root diameter must exceed its reference diameter 560 mm")
    # the load point below the 30° tangents' depth: no bending arm
    with pytest.raises(InputError) as e:
        internal_tooth_form(**{**args, "d_en": 590.0})
    hand = internal_form_by_hand(560.0, 585.0, 14.0, 10.0, 2.5, 590.0, A20)
    assert str(e.value) == (f"d_en = 590.0: no bending arm below the load point (h_Fe = {hand['h_Fe']:.4f} mm, "
                            f"s_Fn = {hand['s_Fn']:.4f} mm)")
    assert _message(y_b_internal, 0.0, 10.0) == "s_R = 0.0: must be > 0 mm"
    assert (_message(y_b_internal, 17.5, 10.0)
            == "s_R = 17.5: rim under the root must exceed 1.75·m = 17.5 mm (ISO 6336-3 Y_B)")


def test_internal_root_refused_at_a_zero_arm_or_a_zero_or_negative_chord():
    """Both must be > 0: a load point exactly at the 30° tangents' depth (h_Fe = 0.0), a fillet as wide as the
    tooth (s_Fn = 0.0) or wider (s_Fn < 0, the load point inside the reference circle so that h_Fe > 0)."""
    from propulsor.gears.iso6336_internal import internal_tooth_form

    def refusal(*a):
        hand = internal_form_by_hand(*a, A20)
        return (f"d_en = {a[5]!r}: no bending arm below the load point (h_Fe = {hand['h_Fe']:.4f} mm, "
                f"s_Fn = {hand['s_Fn']:.4f} mm)"), hand

    for args in ((560.0, 585.0, 15.146527131916631, 10.0, 2.5, 575.0),     # h_Fe = 0.0 exactly
                 (560.0, 562.0, 2.2567811118127166, 10.0, 9.0, 540.0),     # s_Fn = 0.0 exactly
                 (560.0, 562.0, 0.5, 10.0, 9.0, 540.0)):                   # s_Fn < 0 < h_Fe
        text, hand = refusal(*args)
        assert abs(hand["h_Fe"]) < 1e-12 < hand["s_Fn"] or hand["s_Fn"] < 1e-12 < hand["h_Fe"]   # (0 in the code)
        assert _message(internal_tooth_form, *args) == text


def test_internal_form_factors_do_not_scale_with_the_module():
    """Y_F and Y_S are ratios: a ring 40 times smaller (m = 0.25 mm, s_Fn and h_Fe below 1 mm) has the same."""
    from propulsor.gears.iso6336_internal import internal_tooth_form
    big = internal_tooth_form(560.0, 585.0, 14.0, 10.0, 2.5, 566.0)
    small = internal_tooth_form(14.0, 14.625, 0.35, 0.25, 0.0625, 14.15)
    assert small.s_Fn < 1.0 and small.h_Fe < 1.0
    assert (small.Y_F, small.Y_S) == pytest.approx((big.Y_F, big.Y_S), rel=1e-12)
    assert small.s_Fn == pytest.approx(big.s_Fn / 40, rel=1e-12)


@pytest.mark.parametrize("alpha", [A20, A25])
def test_internal_tooth_form_is_the_substitute_rack_of_iso_6336_3(alpha):
    from propulsor.gears.iso6336_internal import internal_tooth_form
    for d_en in (564.0, 566.0, 568.0):
        got = internal_tooth_form(560.0, 585.0, 14.0, 10.0, 2.5, d_en, alpha)
        assert _fields(got) == pytest.approx(internal_form_by_hand(560.0, 585.0, 14.0, 10.0, 2.5, d_en, alpha),
                                             rel=1e-12)
    # the default pressure angle is 20°
    assert _fields(internal_tooth_form(560.0, 585.0, 14.0, 10.0, 2.5, 570.0)) == pytest.approx(
        internal_form_by_hand(560.0, 585.0, 14.0, 10.0, 2.5, 570.0, A20), rel=1e-12)


def test_internal_single_contact_diameter_and_rim_factor():
    from propulsor.gears.iso6336_internal import d_en_internal, y_b_internal
    r_b = 0.5 * 526.0
    g = math.sqrt(284.0 ** 2 - r_b ** 2) + math.pi * 10.0 * math.cos(A20) * 0.4
    assert d_en_internal(568.0, 526.0, 10.0, A20, 1.4) == pytest.approx(2 * math.sqrt(g * g + r_b * r_b), rel=1e-14)
    assert d_en_internal(568.0, 526.0, 10.0, A20, 1.0) == pytest.approx(568.0, rel=1e-14)
    # Y_B: 1 from 3.5·m up, 1.15·ln(8.324·m/s_R) between 1.75·m and 3.5·m
    assert y_b_internal(35.0, 10.0) == 1.0 and y_b_internal(80.0, 10.0) == 1.0
    assert y_b_internal(34.9, 10.0) == pytest.approx(1.15 * math.log(8.324 / 3.49), rel=1e-14)
    assert y_b_internal(17.6, 10.0) == pytest.approx(1.15 * math.log(8.324 / 1.76), rel=1e-14)
    assert y_b_internal(25.0, 10.0) == pytest.approx(1.15 * math.log(8.324 / 2.5), rel=1e-14)


# ============================================================================ iso6336_life.py
def test_life_refusals_in_full():
    from propulsor.gears import iso6336_life as life
    cyc = "must be a finite number of cycles >= 0"
    for bad, shown in ((-1.0, "-1.0"), (math.nan, "nan"), (math.inf, "inf"), ("1e6", "'1e6'")):
        for fn in (life.z_nt, life.y_nt):
            assert _message(fn, bad) == f"load_cycles = {shown}: {cyc}"
        assert _message(life.life_weight, bad, 1e3, 3e6) == f"load_cycles = {shown}: {cyc}"
    assert _message(life.between_static_and_reference, 0.0, 1.0, 1e4, 1e3, 3e6) == "P_static = 0.0: must be > 0"
    assert _message(life.between_static_and_reference, 1.0, -1.0, 1e4, 1e3, 3e6) == "P_ref = -1.0: must be > 0"
    assert _message(life.y_delta_rel_t_static, 0.0) == "Y_S = 0.0: must be > 0"
    assert _message(life.z_l, 0.0, 1500.0) == "oil_viscosity_40 = 0.0: must be > 0 mm²/s"
    for bad, shown in ((-1.0, "-1.0"), (math.nan, "nan"), (math.inf, "inf")):
        assert _message(life.z_v, bad, 1500.0) == f"v = {shown}: must be a finite speed >= 0 m/s"
    assert _message(life.z_r, 0.0, 3.0, 20.0, 1500.0) == "flank_roughness_Rz = 0.0: must be > 0 µm"
    assert _message(life.z_r, 3.0, -2.0, 20.0, 1500.0) == "flank_roughness_Rz = -2.0: must be > 0 µm"
    assert _message(life.z_r, 3.0, 3.0, 0.0, 1500.0) == "rho_red = 0.0: must be > 0 mm"
    p = (1600.0, 1500.0, 1e6, 220.0, 2.0, 3.0, 3.0, 20.0)
    assert _message(life.pitting_safety, p[0], 0.0, *p[2:]) == "sigma_Hlim = 0.0: must be > 0 MPa"
    assert _message(life.pitting_safety, 0.0, *p[1:]) == "sigma_H = 0.0: must be > 0 MPa"


def _z_nt(N):
    return 1.6 if N <= 1e5 else (5e7 / N) ** 0.0756 if N <= 5e7 else (5e7 / min(N, 1e10)) ** 0.0306


def _y_nt(N):
    return 2.5 if N <= 1e3 else (3e6 / N) ** 0.115 if N <= 3e6 else (3e6 / min(N, 1e10)) ** 0.02


def test_life_factors_of_tables_2_and_3_on_both_sides_of_every_corner():
    from propulsor.gears import iso6336_life as life
    for N in (0, 0.0, 1.0, 999.0, 1e3, 1001.0, 5e4, 1e5, 1.001e5, 1e6, 3e6, 3.1e6, 5e7, 5.1e7, 1e9, 1e10, 1.1e10,
              1e12):
        assert life.z_nt(N) == pytest.approx(_z_nt(N), rel=1e-14), N
        assert life.y_nt(N) == pytest.approx(_y_nt(N), rel=1e-14), N
    assert life.z_nt(1e5) == 1.6 and life.y_nt(1e3) == 2.5
    # half a cycle past each corner: the next line (its exponent), the floor beyond 1e10
    assert life.z_nt(100000.5) == (5e7 / 100000.5) ** 0.0756
    assert life.z_nt(50000000.5) == (5e7 / 50000000.5) ** 0.0306
    assert life.z_nt(1e10 + 0.5) == (5e7 / 1e10) ** 0.0306
    assert life.y_nt(1000.5) == (3e6 / 1000.5) ** 0.115
    assert life.y_nt(3000000.5) == (3e6 / 3000000.5) ** 0.02
    assert life.y_nt(1e10 + 0.5) == (3e6 / 1e10) ** 0.02


def test_cycles_at_a_life_factor_invert_the_tables():
    from propulsor.gears import iso6336_life as life
    z_floor, y_floor = (5e7 / 1e10) ** 0.0306, (3e6 / 1e10) ** 0.02
    assert life.cycles_at_z_nt(1.61) == 0.0 and life.cycles_at_y_nt(2.51) == 0.0
    assert life.cycles_at_z_nt(1.6) == pytest.approx(5e7 / 1.6 ** (1 / 0.0756), rel=1e-14)     # 99 800: 1e5 to 3 digits
    assert life.cycles_at_y_nt(2.5) == pytest.approx(3e6 / 2.5 ** (1 / 0.115), rel=1e-14)      # 1041
    assert life.cycles_at_z_nt(z_floor) == math.inf and life.cycles_at_y_nt(y_floor) == math.inf
    assert life.cycles_at_z_nt(z_floor * (1 + 1e-12)) == pytest.approx(1e10, rel=1e-6)
    assert life.cycles_at_y_nt(y_floor * (1 + 1e-12)) == pytest.approx(1e10, rel=1e-6)
    assert life.cycles_at_z_nt(1.0) == pytest.approx(5e7, rel=1e-14)
    assert life.cycles_at_y_nt(1.0) == pytest.approx(3e6, rel=1e-14)
    assert life.cycles_at_z_nt(1.2) == pytest.approx(5e7 / 1.2 ** (1 / 0.0756), rel=1e-14)
    assert life.cycles_at_z_nt(0.9) == pytest.approx(5e7 / 0.9 ** (1 / 0.0306), rel=1e-14)
    assert life.cycles_at_y_nt(1.7) == pytest.approx(3e6 / 1.7 ** (1 / 0.115), rel=1e-14)
    assert life.cycles_at_y_nt(0.9) == pytest.approx(3e6 / 0.9 ** (1 / 0.02), rel=1e-14)


def test_method_b_line_between_the_static_and_the_reference_point():
    from propulsor.gears import iso6336_life as life
    assert (life.N_STATIC_H, life.N_REF_H, life.N_STATIC_F, life.N_REF_F) == (1e5, 5e7, 1e3, 3e6)
    assert life.life_weight(0.0, 1e3, 3e6) == 1.0 and life.life_weight(1e3, 1e3, 3e6) == 1.0
    assert life.life_weight(3e6, 1e3, 3e6) == 0.0 and life.life_weight(1e9, 1e3, 3e6) == 0.0
    w = math.log(3e6 / 2e4) / math.log(3e6 / 1e3)
    assert life.life_weight(2e4, 1e3, 3e6) == pytest.approx(w, rel=1e-14)
    assert life.between_static_and_reference(1.3, 0.8, 2e4, 1e3, 3e6) == pytest.approx(0.8 * (1.3 / 0.8) ** w,
                                                                                        rel=1e-14)
    assert life.between_static_and_reference(1.3, 0.8, 10.0, 1e3, 3e6) == pytest.approx(1.3, rel=1e-14)
    assert life.between_static_and_reference(1.3, 0.8, 1e8, 1e3, 3e6) == pytest.approx(0.8, rel=1e-14)
    assert life.y_delta_rel_t_static(1.9) == pytest.approx((0.44 * 1.9 + 0.12) / (0.44 * 2 + 0.12), rel=1e-14)
    assert life.y_delta_rel_t_static(1.9, 2.2) == pytest.approx((0.44 * 1.9 + 0.12) / (0.44 * 2.2 + 0.12), rel=1e-14)


def test_cycles_at_limit_both_ends_and_between():
    from propulsor.gears import iso6336_life as life

    def limit(N):   # a falling limit: 1000 MPa at 1e4, slope 0.05 in log-log
        return 1000.0 * (1e4 / N) ** 0.05

    assert life.cycles_at_limit(limit, 1000.0 + 1e-9, 1e4) == 0.0
    N = 1e4 * (1000.0 / 800.0) ** (1 / 0.05)                   # 8.67e5
    assert life.cycles_at_limit(limit, 800.0, 1e4) == pytest.approx(N, rel=1e-9)
    assert life.cycles_at_limit(limit, 1000.0, 1e4) == pytest.approx(1e4, rel=1e-9)      # met at N_lo: not 0
    assert life.cycles_at_limit(limit, limit(1e10), 1e4) == math.inf                    # met at N_hi: never below
    assert life.cycles_at_limit(limit, limit(1e10) * (1 + 1e-9), 1e4) == pytest.approx(1e10, rel=1e-6)
    assert life.cycles_at_limit(limit, 800.0, 1e4, 8e5) == math.inf                      # N_hi given
    # the crossing to the solver's 1e-13 in log10 N (2.3e-13 in N), along the whole line
    for i in range(200):
        target = 990.0 - 1.3 * i
        assert life.cycles_at_limit(limit, target, 1e4) == pytest.approx(1e4 * (1000.0 / target) ** 20, rel=2.5e-13)


def _c_zl(s):
    return 0.83 + 0.08 * (min(max(s, 850.0), 1200.0) - 850.0) / 350.0


@pytest.mark.parametrize("s_Hlim", [700.0, 850.0, 1000.0, 1200.0, 1500.0])
def test_lubricant_speed_and_roughness_factors_with_their_clamped_constants(s_Hlim):
    from propulsor.gears import iso6336_life as life
    c = _c_zl(s_Hlim)
    assert life.z_l(150.0, s_Hlim) == pytest.approx(c + 4 * (1 - c) / (1.2 + 134.0 / 150.0) ** 2, rel=1e-14)
    cv = c + 0.02
    assert life.z_v(0.0, s_Hlim) == pytest.approx(cv, rel=1e-14)
    assert life.z_v(3.0, s_Hlim) == pytest.approx(cv + 2 * (1 - cv) / math.sqrt(0.8 + 32.0 / 3.0), rel=1e-14)
    c_zr = 0.32 - 0.0002 * min(max(s_Hlim, 850.0), 1200.0)
    Rz10 = 0.5 * (2.0 + 4.0) * (10.0 / 12.0) ** (1 / 3)
    assert life.z_r(2.0, 4.0, 12.0, s_Hlim) == pytest.approx(((3.0 / Rz10) ** c_zr, Rz10), rel=1e-14)


def test_relative_radius_of_curvature_at_the_pitch_point():
    from propulsor.gears import iso6336_life as life
    r1, r2 = 0.5 * 150.0 * math.tan(0.45), 0.5 * 500.0 * math.tan(0.45)
    assert life.rho_red(150.0, 500.0, 0.45, False) == pytest.approx(r1 * r2 / (r1 + r2), rel=1e-14)
    assert life.rho_red(150.0, 500.0, 0.45, True) == pytest.approx(r1 * r2 / (r2 - r1), rel=1e-14)   # concave ring


@pytest.mark.parametrize("N_L", [1e4, 1e6, 5e7, 1e9])
def test_pitting_safety_every_field_by_hand(N_L):
    from propulsor.gears import iso6336_life as life
    s_H, s_lim, nu, v, Rz1, Rz2, rho, S_min = 1300.0, 1500.0, 220.0, 2.5, 2.0, 4.0, 15.0, 1.25
    P = life.pitting_safety(s_H, s_lim, N_L, nu, v, Rz1, Rz2, rho, S_Hmin=S_min)
    c = _c_zl(s_lim)
    ZL = c + 4 * (1 - c) / (1.2 + 134 / nu) ** 2
    Zv = c + 0.02 + 2 * (1 - c - 0.02) / math.sqrt(0.8 + 32 / v)
    Rz10 = 3.0 * (10 / rho) ** (1 / 3)
    ZR = (3 / Rz10) ** (0.32 - 0.0002 * 1200.0)
    w = 1.0 if N_L <= 1e5 else 0.0 if N_L >= 5e7 else math.log(5e7 / N_L) / math.log(5e7 / 1e5)
    LvR = (ZL * Zv * ZR) * (1.0 / (ZL * Zv * ZR)) ** w
    sHG = s_lim * _z_nt(N_L) * LvR
    hand = dict(N_L=N_L, Z_NT=_z_nt(N_L), Z_L=ZL, Z_v=Zv, Z_R=ZR, R_z10=Rz10, Z_W=1.0, Z_X=1.0, sigma_HG=sHG,
                sigma_HP=sHG / S_min, S_H=sHG / s_H, Z_LvR=LvR, w=w)
    assert {k: getattr(P, k) for k in hand} == pytest.approx(hand, rel=1e-13)
    assert life.pitting_safety(s_H, s_lim, N_L, nu, v, Rz1, Rz2, rho).sigma_HP == pytest.approx(sHG, rel=1e-13)
    # the limit at other lives lies on the same lines
    for N in (1e3, 3e5, 5e7, 2e9):
        assert P.limit_at(N) == pytest.approx(life.pitting_safety(s_H, s_lim, N, nu, v, Rz1, Rz2, rho).sigma_HG,
                                              rel=1e-12)


@pytest.mark.parametrize("N_L,idler", [(5e2, False), (1e5, True), (3e6, False), (1e9, True)])
def test_root_fatigue_safety_every_field_by_hand(N_L, idler):
    from propulsor.gears import iso6336_life as life
    s_F, q_s, m, s_Flim, R_z, S_min, Y_S = 420.0, 2.2, 8.0, 425.0, 8.0, 1.4, 2.05
    r = life.root_fatigue_safety(s_F, q_s, m, s_Flim, R_z, N_L, S_min, idler, Y_S=Y_S)
    Yd = (1 + math.sqrt(0.003 * (1 + 2 * q_s) / 5)) / (1 + math.sqrt(0.003 * 1.2))
    Yr = 1.674 - 0.529 * (R_z + 1) ** 0.1
    Yx = 1.05 - 0.01 * m
    Yd_st = (0.44 * Y_S + 0.12) / (0.44 * 2 + 0.12)
    w = 1.0 if N_L <= 1e3 else 0.0 if N_L >= 3e6 else math.log(3e6 / N_L) / math.log(3e6 / 1e3)
    dRX = (Yd * Yr * Yx) * (Yd_st / (Yd * Yr * Yx)) ** w
    Y_M = 0.7 if idler else 1.0
    sFG = s_Flim * 2.0 * _y_nt(N_L) * dRX * Y_M
    hand = dict(N_L=N_L, Y_ST=2.0, Y_NT=_y_nt(N_L), Y_delta_relT=Yd, Y_R_relT=Yr, Y_X=Yx, Y_M=Y_M, sigma_FG=sFG,
                sigma_FP=sFG / S_min, S_F=sFG / s_F, Y_delta_relT_static=Yd_st, Y_dRX=dRX, w=w)
    assert {k: getattr(r, k) for k in hand} == pytest.approx(hand, rel=1e-13)
    assert (_message(life.root_fatigue_safety, s_F, q_s, m, s_Flim, R_z, N_L, 0.0, idler, Y_S=Y_S)
            == "S_Fmin = 0.0: must be > 0")
    plain = life.root_fatigue_safety(s_F, q_s, m, s_Flim, R_z, N_L, Y_S=Y_S)
    assert plain.sigma_FP == pytest.approx(plain.sigma_FG, rel=1e-14) and plain.Y_M == 1.0
    for N in (1e2, 4e4, 3e6, 2e9):
        assert r.limit_at(N) == pytest.approx(
            life.root_fatigue_safety(s_F, q_s, m, s_Flim, R_z, N, S_min, idler, Y_S=Y_S).sigma_FG, rel=1e-12)


# ============================================================================ gear_materials.py
def test_material_catalogue_lookups_and_refusal():
    from propulsor.gears.gear_materials import LIVES, material, materials
    assert LIVES == ("iso6336_case", "iso6336_through", "static")
    cat = materials()
    assert material("steel_case_MQ") is cat["steel_case_MQ"]
    names = ", ".join(cat)
    assert _message(material, "wood") == f"gear_material = 'wood': is not in the gear material catalogue ({names})"
    assert (_message(material, "wood", "sun_material")
            == f"sun_material = 'wood': is not in the gear material catalogue ({names})")
    assert names == "steel_case_MQ, steel_through_MQ, PLA, PETG, nylon"
    st = cat["steel_case_MQ"]
    assert (st.iso.E, st.iso.nu) == (206000.0, 0.3) and not st.static and cat["PLA"].static
    assert (cat["PLA"].iso.E, cat["PLA"].iso.nu) == (3000.0, 0.36)
    assert {m.life for m in cat.values()} == set(LIVES)


def test_life_factors_of_each_material_line():
    from propulsor.gears.gear_materials import material, y_nt_of, z_nt_of
    case, through, pla = material("steel_case_MQ"), material("steel_through_MQ"), material("PLA")
    for m in (case, through, pla):
        assert z_nt_of(m, None) == 1.0 and y_nt_of(m, None) == 1.0
    for N in (1e2, 1e5, 1e7, 1e9, 1e11):
        assert z_nt_of(pla, N) == 1.0 and y_nt_of(pla, N) == 1.0
        assert z_nt_of(case, N) == _z_nt(N) and z_nt_of(through, N) == _z_nt(N)
        assert y_nt_of(case, N) == _y_nt(N)
    # through-hardened steel, ISO 6336-3:2006 Table 3 (V): 2.5 to 1e4, (3e6/N)^0.159 to 3e6, (3e6/N)^0.02 to 1e10
    k = math.log(2.5) / math.log(3e6 / 1e4)
    assert round(k, 3) == 0.161
    for N, Y in ((0.0, 2.5), (1e3, 2.5), (1e4, 2.5), (1.0001e4, (3e6 / 1.0001e4) ** k), (1e5, (3e6 / 1e5) ** k),
                 (3e6, 1.0), (3.1e6, (3e6 / 3.1e6) ** 0.02), (1e10, (3e6 / 1e10) ** 0.02),
                 (2e10, (3e6 / 1e10) ** 0.02), (1e12, (3e6 / 1e10) ** 0.02)):
        assert y_nt_of(through, N) == pytest.approx(Y, rel=1e-14), N
    assert y_nt_of(through, 1e4) == 2.5 and y_nt_of(through, 3e6) == pytest.approx(1.0, rel=1e-15)
    # just past the corners: the next line's exponent, the floor beyond 1e10
    assert y_nt_of(through, 3000000.5) == (3e6 / 3000000.5) ** 0.02
    assert y_nt_of(through, 1e10 + 0.5) == (3e6 / 1e10) ** 0.02
    assert y_nt_of(through, 10000.5) == (3e6 / 10000.5) ** k


# ============================================================================ iso6336_helical.py
# (the transverse geometry of HelicalPair is read from its properties, which the TR 6336-30 example checks in
# tests/test_iso6336_helical.py; every factor below is worked out here from ISO 6336-1/-2/-3:2006)
def _hpair(beta_deg=8.0, z1=16, z2=20, m_n=4.0, x1=0.3, x2=0.2, alpha_n=A20):
    from propulsor.gears import iso6336_helical as h
    m_t = m_n / math.cos(math.radians(beta_deg))
    return h.HelicalPair(m_n, z1, z2, x1, x2, math.radians(beta_deg), z1 * m_t + 2 * m_n * (1 + x1),
                         z2 * m_t + 2 * m_n * (1 + x2), alpha_n)


def _m1_m2(p):
    ea = p.eps_alpha
    r1, r2 = math.sqrt((p.d_a1 / p.d_b1) ** 2 - 1), math.sqrt((p.d_a2 / p.d_b2) ** 2 - 1)
    t = math.tan(p.alpha_wt)
    M1 = t / math.sqrt((r1 - 2 * math.pi / p.z1) * (r2 - (ea - 1) * 2 * math.pi / p.z2))
    M2 = t / math.sqrt((r2 - 2 * math.pi / p.z2) * (r1 - (ea - 1) * 2 * math.pi / p.z1))
    return M1, M2


def test_helical_refusals_in_full():
    from propulsor.gears import iso6336_helical as h
    ok = dict(m_n=4.0, z1=16, z2=20, x1=0.3, x2=0.2, beta=0.1, d_a1=76.0, d_a2=92.0)
    assert _message(h.HelicalPair, **{**ok, "m_n": 0.0}) == "m_n = 0.0: must be > 0 mm"
    assert _message(h.HelicalPair, **{**ok, "z1": 0}) == "z1 = 0: must be > 0"
    assert _message(h.HelicalPair, **{**ok, "z2": -3}) == "z2 = -3: must be > 0"
    assert _message(h.HelicalPair, **{**ok, "beta": math.radians(45.0)}) == "beta = 45.0: 0 <= beta < 45 deg"
    assert (_message(h.HelicalPair, **{**ok, "beta": math.radians(45.5)})
            == f"beta = {math.degrees(math.radians(45.5))!r}: 0 <= beta < 45 deg")
    assert (_message(h.HelicalPair, **{**ok, "beta": -0.01})
            == f"beta = {math.degrees(-0.01)!r}: 0 <= beta < 45 deg")
    assert h.HelicalPair(**{**ok, "beta": 0.0}).beta == 0.0
    p = _hpair()
    assert _message(h.pitting, p, 0.0, 100.0, 1.0, 1.0, 1.0, 1.0) == "b = 0.0: must be > 0 mm"
    assert _message(h.tooth_root, p, 0.0, 100.0, 1.0, 1.0, 1.0, 1.0, 6) == "b = 0.0: must be > 0 mm"
    assert (_message(h.k_v_method_b, 1.0, 16, 1.2, 200.0, 1.0, 13, 0.5)
            == "accuracy_grade = 13: must be an ISO 1328 grade 3 ... 12")
    assert _message(h.d_en, p, 3) == "gear = 3: must be 1 (pinion) or 2 (wheel)"
    assert _message(h.d_en, p, 0) == "gear = 0: must be 1 (pinion) or 2 (wheel)"
    assert _message(h.y_b, 0.0, 9.0) == "s_R = 0.0: must be > 0 mm"
    assert _message(h.y_b, 4.5, 9.0) == "s_R = 4.5: rim thickness must exceed 0.5·h = 4.500 mm (ISO 6336-3 Y_B)"
    assert _message(h.y_delta_rel_t, 2.0, 0.0) == "rho_prime = 0.0: must be > 0 mm"
    for R_z in (0.0, 40.5, -1.0):
        assert _message(h.y_r_rel_t, R_z) == f"R_z = {R_z!r}: root roughness must be within 0 < R_z <= 40 µm"
    assert _message(h.y_x, 8.0, "soft") == "material = 'soft': must be surface_hardened or through_hardened"
    assert _message(h.root_strength, 400.0, 2.0, 8.0, 0.0, 8.0) == "sigma_Flim = 0.0: must be > 0 MPa"
    assert _message(h.root_strength, 400.0, 2.0, 8.0, 425.0, 8.0, S_Fmin=0.0) == "S_Fmin = 0.0: must be > 0"
    for Y_M in (0.0, 1.01, -0.5):
        assert (_message(h.root_strength, 400.0, 2.0, 8.0, 425.0, 8.0, Y_M=Y_M)
                == f"Y_M = {Y_M!r}: mean stress factor must be within 0 < Y_M <= 1")


def test_helical_root_factors_on_both_sides_of_their_limits():
    from propulsor.gears import iso6336_helical as h
    # Y_X, ISO 6336-3:2006: surface hardened 1 to 5 mm, 1.05 − 0.01·m_n to 25 mm, 0.8 beyond
    for m, Y in ((1.0, 1.0), (5.0, 1.0), (5.5, 1.05 - 0.055), (24.9, 1.05 - 0.249), (25.0, 0.8), (25.5, 0.8),
                 (40.0, 0.8)):
        assert h.y_x(m) == pytest.approx(Y, rel=1e-14) and h.y_x(m, "surface_hardened") == h.y_x(m)
    # through hardened 1 to 5 mm, 1.03 − 0.006·m_n to 30 mm, 0.85 beyond
    for m, Y in ((2.0, 1.0), (5.0, 1.0), (6.0, 1.03 - 0.036), (29.9, 1.03 - 0.1794), (30.5, 0.85), (40.0, 0.85)):
        assert h.y_x(m, "through_hardened") == pytest.approx(Y, rel=1e-14), m
    assert h.y_x(30.0, "through_hardened") == 0.85          # the table's value, not 1.03 − 0.18 (0.8500000000000001)
    # Y_RrelT: 1.120 below R_z = 1 µm, 1.674 − 0.529·(R_z + 1)^0.1 from 1 to 40 µm
    assert h.y_r_rel_t(0.5) == 1.12
    for R_z in (1.0, 1.5, 10.0, 40.0):
        assert h.y_r_rel_t(R_z) == pytest.approx(1.674 - 0.529 * (R_z + 1) ** 0.1, rel=1e-14)
    # Y_δrelT = (1 + √(ρ'·χ*))/(1 + √(ρ'·1.2)), χ* = (1 + 2·q_s)/5, ρ' = 0.003 mm (case hardened) by default
    assert h.y_delta_rel_t(2.5) == pytest.approx(1.0, rel=1e-14)
    assert h.y_delta_rel_t(1.8, 0.1005) == pytest.approx((1 + math.sqrt(0.1005 * 4.6 / 5)) / (1 + math.sqrt(0.1005 * 1.2)),
                                                         rel=1e-14)
    # Y_DT: 1 above grade 4 or at ε_αn <= 2.05, 2.366 − 0.666·ε_αn to 2.5, 0.7 above
    assert h.y_dt(2.3, 5) == 1.0 and h.y_dt(2.05, 4) == 1.0 and h.y_dt(1.6, 4) == 1.0
    assert h.y_dt(2.06, 4) == pytest.approx(2.366 - 0.666 * 2.06, rel=1e-14)
    assert h.y_dt(2.5, 4) == pytest.approx(2.366 - 0.666 * 2.5, rel=1e-14)     # 0.701 at 2.5 itself
    assert h.y_dt(2.6, 3) == 0.7
    # Y_B of an external rim: 1 from s_R/h = 1.2, 1.6·ln(2.242·h/s_R) down to 0.5
    assert h.y_b(None, 9.0) == 1.0 and h.y_b(12.0, 10.0) == 1.0 and h.y_b(30.0, 10.0) == 1.0
    assert h.y_b(11.9, 10.0) == pytest.approx(1.6 * math.log(2.242 / 1.19), rel=1e-14)
    assert h.y_b(8.0, 10.0) == pytest.approx(1.6 * math.log(2.242 / 0.8), rel=1e-14)
    # K_Fβ = K_Hβ^N_F with b/h taken >= 3
    for b, hh in ((20.0, 10.0), (30.0, 10.0), (35.0, 10.0), (80.0, 10.0)):
        bh = max(b / hh, 3.0)
        assert h.k_f_beta(1.3, b, hh) == pytest.approx(1.3 ** (bh * bh / (1 + bh + bh * bh)), rel=1e-14)
    # root strength's defaults: Y_NT = 1, S_Fmin = 1, Y_ST = 2, Y_M = 1
    r = h.root_strength(400.0, 2.2, 8.0, 425.0, 8.0)
    Yd = (1 + math.sqrt(0.003 * 5.4 / 5)) / (1 + math.sqrt(0.0036))
    sFG = 425.0 * 2.0 * Yd * (1.674 - 0.529 * 9.0 ** 0.1) * (1.05 - 0.08)
    assert (r.sigma_FG, r.sigma_FP, r.S_F, r.Y_M) == pytest.approx((sFG, sFG, sFG / 400.0, 1.0), rel=1e-13)
    r = h.root_strength(400.0, 2.2, 8.0, 425.0, 8.0, Y_NT=1.3, S_Fmin=1.5, Y_M=1.0)
    assert (r.sigma_FG, r.sigma_FP) == pytest.approx((1.3 * sFG, 1.3 * sFG / 1.5), rel=1e-13)
    # a nitrided, through-hardened root: ρ' = 0.1005 mm, Y_X = 1.03 − 0.006·m_n
    r = h.root_strength(400.0, 2.2, 8.0, 425.0, 8.0, rho_prime=0.1005, material="through_hardened")
    Yd_n = (1 + math.sqrt(0.1005 * 5.4 / 5)) / (1 + math.sqrt(0.1005 * 1.2))
    assert (r.Y_delta_relT, r.Y_X) == pytest.approx((Yd_n, 1.03 - 0.048), rel=1e-14)
    assert r.sigma_FG == pytest.approx(425.0 * 2.0 * Yd_n * (1.674 - 0.529 * 9.0 ** 0.1) * (1.03 - 0.048), rel=1e-13)


def test_helical_contact_factors_by_hand():
    from propulsor.gears import iso6336_helical as h
    assert h.z_h(0.36, 0.41) == pytest.approx(math.sqrt(2 * math.cos(0.41) / (math.cos(0.36) ** 2 * math.sin(0.41))),
                                             rel=1e-14)
    assert h.z_eps(1.6) == pytest.approx(math.sqrt(2.4 / 3), rel=1e-14)
    assert h.z_eps(1.6, 0.4) == pytest.approx(math.sqrt(2.4 / 3 * 0.6 + 0.4 / 1.6), rel=1e-14)
    assert h.z_eps(1.6, 1.3) == pytest.approx(math.sqrt(1 / 1.6), rel=1e-14)
    p = _hpair()
    M1, M2 = _m1_m2(p)
    assert M1 > 1 and M2 > 1
    assert h.z_b_z_d(p, 0.0) == pytest.approx((M1, M2), rel=1e-13)
    assert h.z_b_z_d(p, 0.4) == pytest.approx((M1 - 0.4 * (M1 - 1), M2 - 0.4 * (M2 - 1)), rel=1e-13)
    assert h.z_b_z_d(p, 1.0) == (1.0, 1.0) and h.z_b_z_d(p, 1.7) == (1.0, 1.0)
    # an M below 1 gives 1 (Z_D of the 40/60 pair, Z_B of the 60/40), also between ε_β = 0 and 1
    for q, low in ((_hpair(z1=40, z2=60, x1=0.3, x2=0.3), 1), (_hpair(z1=60, z2=40, x1=0.3, x2=0.3), 0)):
        M = _m1_m2(q)
        assert M[low] < 1.0 < M[1 - low]
        for eb in (0.0, 0.5):
            want = [M[0] - eb * (M[0] - 1), M[1] - eb * (M[1] - 1)]
            want[low] = 1.0
            assert h.z_b_z_d(q, eb) == pytest.approx(tuple(want), rel=1e-13)
            assert h.z_b_z_d(q, eb)[low] == 1.0


def _k_v_helical(v, z1, u, Ft_b, K_A, grade, eps_beta):
    K1_he = {3: 1.9, 4: 3.5, 5: 6.7, 6: 13.3, 7: 23.9, 8: 34.8, 9: 47.0, 10: 68.2, 11: 91.4, 12: 130.3}
    load = max(K_A * Ft_b, 100.0)
    f = v * z1 / 100.0 * math.sqrt(u * u / (1 + u * u))
    sp = 1 + (K1_TABLE_8[grade] / load + 0.0193) * f
    he = 1 + (K1_he[grade] / load + 0.0087) * f
    return he if eps_beta >= 1 else sp - eps_beta * (sp - he)


def test_helical_dynamic_factor_between_spur_and_helical_at_every_grade():
    from propulsor.gears import iso6336_helical as h
    for grade in range(3, 13):
        for eps_beta in (0.0, 0.4, 1.0, 1.5):
            for Ft_b in (40.0, 400.0):
                assert h.k_v_method_b(3.0, 19, 2.2, Ft_b, 1.2, grade, eps_beta) == pytest.approx(
                    _k_v_helical(3.0, 19, 2.2, Ft_b, 1.2, grade, eps_beta), rel=1e-13)


def _k_alpha(ea, eb, c, f_pb, y_a, FtH_b, Z_eps):
    eg = ea + eb
    term = c * (f_pb - y_a) / FtH_b
    K = eg / 2 * (0.9 + 0.4 * term) if eg <= 2 else 0.9 + 0.4 * math.sqrt(2 * (eg - 1) / eg) * term
    return min(max(K, 1.0), eg / (ea * Z_eps ** 2)), min(max(K, 1.0), eg / (0.25 * ea + 0.75))


@pytest.mark.parametrize("ea,eb,c,f_pb,y_a,FtH_b,Z", [
    (1.6, 0.3, 20.0, 12.0, 0.8, 150.0, 0.9),     # ε_γ <= 2, K between its limits
    (1.7, 0.8, 20.0, 12.0, 0.8, 220.0, 0.8),     # ε_γ > 2
    (1.6, 0.3, 20.0, 40.0, 0.8, 150.0, 0.9),     # K above both limits (K_Hα's the lower)
    (1.6, 0.3, 20.0, 2.0, 0.8, 900.0, 0.9),      # K below 1
])
def test_helical_transverse_load_factors_method_b(ea, eb, c, f_pb, y_a, FtH_b, Z):
    from propulsor.gears import iso6336_helical as h
    assert h.k_alpha_method_b(ea, eb, c, f_pb, y_a, FtH_b, Z) == pytest.approx(
        _k_alpha(ea, eb, c, f_pb, y_a, FtH_b, Z), rel=1e-14)


def test_helical_mesh_stiffness_with_its_factors_off_their_defaults():
    from propulsor.gears import iso6336_helical as h
    C = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)  # Table 12
    p = _hpair(beta_deg=12.0, alpha_n=A25)
    zn1, zn2, x1, x2 = p.z_n1, p.z_n2, 0.3, 0.2
    q = (C[0] + C[1] / zn1 + C[2] / zn2 + C[3] * x1 + C[4] * x1 / zn1 + C[5] * x2 + C[6] * x2 / zn2
         + C[7] * x1 ** 2 + C[8] * x2 ** 2)
    C_B = (1 + 0.5 * (1.2 - 1.4)) * (1 - 0.02 * (20.0 - 25.0))
    c1 = 1 / q * 0.7 * 0.9 * C_B * math.cos(math.radians(12.0))
    c_ga = c1 * (0.75 * p.eps_alpha + 0.25)
    s = h.mesh_stiffness(p, 1.4, C_R=0.9, C_M=0.7)
    assert (s.c_th, s.c_single, s.c_gamma_alpha, s.c_gamma_beta) == pytest.approx((1 / q, c1, c_ga, 0.85 * c_ga),
                                                                                  rel=1e-13)


def test_helical_pitting_every_field_by_hand():
    from propulsor.gears import iso6336_helical as h
    from propulsor.gears.iso6336 import Material
    p = _hpair()
    b, T1 = 40.0, 250.0
    soft = Material(100000.0, 0.25)
    s = h.pitting(p, b, T1, 1.25, 1.1, 1.2, 1.05, soft)
    eb = b * math.sin(p.beta) / (math.pi * 4.0)
    ea = p.eps_alpha
    Z_H = math.sqrt(2 * math.cos(p.beta_b) * math.cos(p.alpha_wt) / (math.cos(p.alpha_t) ** 2 * math.sin(p.alpha_wt)))
    Z_E = math.sqrt(1 / (math.pi * ((1 - 0.25 ** 2) / 100000.0 + (1 - 0.09) / 206000.0)))
    Z_eps = math.sqrt((4 - ea) / 3 * (1 - eb) + eb / ea)
    Z_beta = 1 / math.sqrt(math.cos(p.beta))
    M1, M2 = _m1_m2(p)
    Z_B, Z_D = M1 - eb * (M1 - 1), M2 - eb * (M2 - 1)
    F_t = 2000 * T1 / p.d1
    u = 20 / 16
    s0 = Z_H * Z_E * Z_eps * Z_beta * math.sqrt(F_t / (p.d1 * b) * (u + 1) / u)
    k = math.sqrt(1.25 * 1.1 * 1.2 * 1.05)
    hand = dict(F_t=F_t, eps_alpha=ea, eps_beta=eb, Z_H=Z_H, Z_E=Z_E, Z_eps=Z_eps, Z_beta=Z_beta, Z_B=Z_B, Z_D=Z_D,
                sigma_H0=s0, sigma_H1=Z_B * s0 * k, sigma_H2=Z_D * s0 * k)
    assert {k_: getattr(s, k_) for k_ in hand} == pytest.approx(hand, rel=1e-13)
    assert h.pitting(p, b, T1, 1.0, 1.0, 1.0, 1.0).Z_E == pytest.approx(Z_E_STEEL, rel=1e-14)
    assert h.pitting(p, b, T1, 1.0, 1.0, 1.0, 1.0, m2=soft).Z_E == pytest.approx(Z_E, rel=1e-14)   # the wheel soft


def test_helical_tooth_root_every_field_by_hand():
    """Grade 4 (Y_DT looked at), rims on the pinion only (Y_B from h = h_a + h_f), a 1.4 dedendum rack."""
    from propulsor.gears import iso6336_helical as h
    p = _hpair(beta_deg=10.0)
    b, T1, K_A, K_v, K_Fb, K_Fa = 40.0, 250.0, 1.25, 1.1, 1.15, 1.05
    h_fP_star, rho_star, s_pr = 1.4, 0.3, 0.02
    t = h.tooth_root(p, b, T1, K_A, K_v, K_Fb, K_Fa, 4, h_fP_star, rho_star, s_pr, s_R=(9.0, None))
    eb = b * math.sin(p.beta) / (math.pi * 4.0)
    eps_an = p.eps_alpha / math.cos(p.beta_b) ** 2
    Y_beta = 1 - min(eb, 1.0) * 10.0 / 120.0
    F_t = 2000 * T1 / p.d1
    K = K_A * K_v * K_Fb * K_Fa
    assert (t.F_t, t.eps_alpha_n, t.Y_beta, t.Y_DT) == pytest.approx((F_t, eps_an, Y_beta, 1.0), rel=1e-13)
    for i, (g, z, z_n, x, d, d_a, s_R) in enumerate(((t.gear1, 16, p.z_n1, 0.3, p.d1, p.d_a1, 9.0),
                                                     (t.gear2, 20, p.z_n2, 0.2, p.d2, p.d_a2, None)), start=1):
        d_n = 4.0 * z_n
        r_bn, r_an = d_n * math.cos(A20) / 2, (d_n + d_a - d) / 2
        gg = math.sqrt(r_an ** 2 - r_bn ** 2) - math.pi * d * math.cos(p.beta) * math.cos(A20) / z * (eps_an - 1)
        den = 2 * math.sqrt(gg ** 2 + r_bn ** 2)
        assert h.d_en(p, i) == pytest.approx(den, rel=1e-13)
        form = form_by_hand(z_n, 4.0, x, den, A20, h_fP_star, rho_star, s_pr)
        depth = (d_a - d) / 2 + (h_fP_star - x) * 4.0
        Y_B = 1.0 if s_R is None or s_R / depth >= 1.2 else 1.6 * math.log(2.242 * depth / s_R)
        s0 = F_t / (b * 4.0) * form["Y_F"] * form["Y_S"] * Y_beta * Y_B
        got = (g.z_n, g.d_en, g.q_s, g.Y_B, g.sigma_F0, g.sigma_F)
        assert got == pytest.approx((z_n, den, form["s_Fn"] / (2 * form["rho_F"]), Y_B, s0, s0 * K), rel=1e-10)
        assert _fields(g.form) == pytest.approx(form, rel=1e-10, abs=1e-13)
    assert t.gear1.Y_B > 1.0 and t.gear2.Y_B == 1.0


def test_helical_tooth_root_of_a_deep_tooth_takes_y_dt():
    """ε_αn > 2.05 at grade 4: Y_DT = 2.366 − 0.666·ε_αn divides nothing, it multiplies σ_F0."""
    from propulsor.gears import iso6336_helical as h
    m_n, z1, z2, beta = 2.0, 40, 60, math.radians(10.0)
    m_t = m_n / math.cos(beta)
    p = h.HelicalPair(m_n, z1, z2, 0.0, 0.0, beta, z1 * m_t + 2 * m_n * 1.35, z2 * m_t + 2 * m_n * 1.35)
    eps_an = p.eps_alpha / math.cos(p.beta_b) ** 2
    assert 2.05 < eps_an <= 2.5
    t4 = h.tooth_root(p, 20.0, 50.0, 1.0, 1.0, 1.0, 1.0, 4, 1.6, 0.2)
    t5 = h.tooth_root(p, 20.0, 50.0, 1.0, 1.0, 1.0, 1.0, 5, 1.6, 0.2)
    assert t4.Y_DT == pytest.approx(2.366 - 0.666 * eps_an, rel=1e-14) and t5.Y_DT == 1.0
    assert t4.gear1.sigma_F0 == pytest.approx(t5.gear1.sigma_F0 * t4.Y_DT, rel=1e-13)


# ============================================================================ planetary.py
def _inv_inverse(y):
    return _bisect(lambda a: math.tan(a) - a - y, 0.0, 1.5)


def _conditions_by_hand(ps):
    """Every condition of the set (seed 004 eq. 30–35 and the gear checks), the set's own numbers worked out here;
    the single gears' and meshes' quantities (tip thickness, x_min, interference) read from them."""
    from propulsor.policy import (GEAR_CONTACT_RATIO_MIN as EPS_MIN, GEAR_INTERFERENCE_TOL_MM as INT_TOL,
                                  GEAR_TIP_THICKNESS_MIN_MODULE as S_MIN, PLANET_TIP_CLEARANCE_MIN_MODULE as GAP_MIN,
                                  PLANETARY_COAXIALITY_TOL_MM as COAX)
    m, z1, z2, z3, n = ps.m, ps.z_sun, ps.z_planet, ps.z_ring, ps.n_planets
    sp, pr = ps.mesh_sun_planet, ps.mesh_planet_ring
    sun, planet, ring = sp.gear1, sp.gear2, pr.gear2
    d_a1, d_a2, d_a3 = sp.d_a1, min(sp.d_a2, pr.d_a1), pr.d_a2
    out = []
    i = 1 + z3 / z1
    if ps.ratio_target is None:
        out.append(("willis_ratio", True, i, i, "-", f"i_1H = 1 + z3/z1 = {i:.6g}"))
    else:
        dev = abs(i - ps.ratio_target)
        out.append(("willis_ratio", dev <= ps.ratio_tol, dev, ps.ratio_tol, "-",
                    f"|i_1H − i_target| = |{i:.6g} − {ps.ratio_target:.6g}| must be <= {ps.ratio_tol:g}"))
    mis = pr.a_w - sp.a_w
    # x_ring for coaxiality (GOST 19274): x3 = x2 + (z3 − z2)(inv α_w − inv α)/(2 tan α), cos α_w = a·cos α/a_w
    a = ps.rack.alpha
    aw = math.acos(m * (z3 - z2) / 2 * math.cos(a) / sp.a_w)
    x3 = ps.x_planet + (z3 - z2) * (_inv(aw) - _inv(a)) / (2 * math.tan(a))
    out.append(("coaxiality", abs(mis) <= COAX, abs(mis), COAX, "mm",
                f"a_w sun–planet {sp.a_w:.4f} mm vs planet–ring {pr.a_w:.4f} mm; x_ring for coaxiality = {x3:.5f}"))
    gap = math.inf if n == 1 else 2 * sp.a_w * math.sin(math.pi / n) - d_a2
    out.append(("neighbour", gap >= GAP_MIN * m, 1e300 if n == 1 else gap, GAP_MIN * m, "mm",
                f"2·a_w·sin(π/{n}) − d_a,planet = {gap:.4f} mm must be >= {GAP_MIN * m:.4f} mm"))
    q = (z1 + z3) / n
    out.append(("assembly", (z1 + z3) % n == 0, q, round(q), "-", f"(z1 + z3)/k = {z1 + z3}/{n} = {q:.6g} must be whole"))
    p_b = math.pi * m * math.cos(a)

    def rho(d, g):
        return 0.5 * math.sqrt(d * d - g.d_b ** 2)

    for name, mesh, da, db, sign in (("contact_ratio_sun_planet", sp, d_a1, d_a2, 1),
                                     ("contact_ratio_planet_ring", pr, d_a2, d_a3, -1)):
        if db < mesh.gear2.d_b:
            with pytest.raises(InputError) as e:
                mesh.epsilon_alpha(da, db)
            out.append((name, False, 0.0, EPS_MIN, "-", f"ε_α undefined: {e.value}"))
            continue
        eps = (rho(da, mesh.gear1) + sign * (rho(db, mesh.gear2) - mesh.a_w * math.sin(mesh.alpha_w))) / p_b
        out.append((name, eps >= EPS_MIN, eps, EPS_MIN, "-", f"ε_α = {eps:.4f} must be >= {EPS_MIN}"))
    for name, g in (("undercut_sun", sun), ("undercut_planet", planet)):
        out.append((name, g.x >= g.x_min, g.x, g.x_min, "-", f"x = {g.x:.4f} must be >= x_min = {g.x_min:.4f}"))
    s_min = S_MIN * m
    for name, g, da in (("tip_thickness_sun", sun, d_a1), ("tip_thickness_planet", planet, d_a2),
                        ("tip_thickness_ring", ring, d_a3)):
        if da < g.d_b:
            out.append((name, False, -1.0, s_min, "mm", f"tip d_a = {da:.4f} mm inside the base circle"))
            continue
        s_a = g.tip_thickness(da)
        out.append((name, s_a >= s_min, s_a, s_min, "mm", f"s_na = {s_a:.4f} mm must be >= {s_min:.4f} mm"))
    for mesh, tag, tips, who in ((sp, "sun_planet", (d_a1, d_a2), ("pinion", "wheel")),
                                 (pr, "planet_ring", (d_a2, d_a3), ("planet", "ring"))):
        for w, mar in zip(who, mesh.involute_interference_margins(*tips)):
            out.append((f"involute_interference_{tag}_{w}", mar >= 0, mar, 0.0, "mm",
                        f"active profile margin (ρ_p − ρ_l) = {mar:.4f} mm must be >= 0"))
    depth = pr.tip_interference_depth(d_a2, d_a3)
    out.append(("tip_interference_planet_ring", depth <= INT_TOL, depth, INT_TOL, "mm",
                f"deepest tip-corner entry {depth:.3e} mm must be <= {INT_TOL:g} mm"))
    # tip-to-root clearances along the line of centres: external a_w − r_a − r_f, internal r_a3 − a_w − r_f2 and
    # r_f3 − a_w − r_a2
    c_sp = min(sp.a_w - d_a2 / 2 - sun.d_f / 2, sp.a_w - d_a1 / 2 - planet.d_f / 2)
    c_pr = min(d_a3 / 2 - pr.a_w - planet.d_f / 2, ring.d_f / 2 - pr.a_w - d_a2 / 2)
    for tag, c in (("sun_planet", c_sp), ("planet_ring", c_pr)):
        out.append((f"root_clearance_{tag}", c > 0, c, 0.0, "mm", f"least tip-to-root clearance {c:.4f} mm must be > 0"))
    if ps.z0 is not None and d_a3 >= ring.d_b:
        marg = rho(d_a3, ring) - ring.a_w0 * math.sin(ring.alpha_w0)
        out.append(("ring_tip_cut_by_shaper", marg >= 0, marg, 0.0, "mm",
                    f"ring tip meets the shaper on its involute: margin {marg:.4f} mm must be >= 0"))
    return out


def _check_conditions(ps):
    got = [tuple(c) for c in ps.conditions()]
    hand = _conditions_by_hand(ps)
    assert [g[0] for g in got] == [h_[0] for h_ in hand]
    for g, h_ in zip(got, hand):
        assert (g[0], g[1], g[4], g[5]) == (h_[0], h_[1], h_[4], h_[5])
        assert type(g[1]) is bool and type(g[2]) is float and type(g[3]) is float
        assert g[2:4] == pytest.approx(h_[2:4], rel=1e-9, abs=1e-12), g[0]
    assert ps.failures() == [c for c in ps.conditions() if not c.passed]
    assert ps.valid == (not any(not h_[1] for h_ in hand))
    return got


def test_planetary_conditions_of_the_thesis_set_and_the_corrected_one():
    got = _check_conditions(PlanetarySet())
    assert [c[0] for c in got if not c[1]] == ["coaxiality"]
    ps = PlanetarySet(n_planets=3).with_coaxial_ring()
    got = _check_conditions(ps)
    assert all(c[1] for c in got) and ps.valid


def test_planetary_conditions_with_a_ratio_target_on_both_sides_of_its_tolerance():
    base = PlanetarySet(n_planets=3).with_coaxial_ring()
    dev = abs(base.ratio - 4.4)
    for tol, ok in ((dev, True), (0.05, False), (0.2, True)):
        ps = PlanetarySet(n_planets=3, x_ring=base.x_ring, ratio_target=4.4, ratio_tol=tol)
        got = _check_conditions(ps)
        assert got[0][:2] == ("willis_ratio", ok)
    assert PlanetarySet(ratio_target=4.5).ratio_tol == 0.0 and _check_conditions(PlanetarySet(ratio_target=4.5))[0][1]


def test_planetary_conditions_of_one_planet_and_of_a_ring_tip_inside_its_base_circle():
    one = PlanetarySet(n_planets=1)
    got = _check_conditions(one)
    assert got[2][:3] == ("neighbour", True, 1e300) and "= inf mm" in got[2][5]
    # a 10° rack: the ring's tip inside its base circle (no ε_α, no tip thickness, no shaper margin)
    r10 = BasicRack(alpha=math.radians(10.0), rho_f_star=0.2)
    low = PlanetarySet(rack=r10, x_ring=0.5)
    assert low.d_a_ring < low.ring.d_b
    got = _check_conditions(low)
    names = [c[0] for c in got]
    assert "contact_ratio_sun_planet" in names and "contact_ratio_planet_ring" in names
    assert "tip_thickness_ring" in names and "ring_tip_cut_by_shaper" not in names
    # no shaper: no shaper margin either
    assert "ring_tip_cut_by_shaper" not in [c[0] for c in _check_conditions(PlanetarySet(z0=None, x_ring=1.5))]


def test_planetary_undercut_limit_is_met_at_x_min_itself():
    from propulsor.gears.involute import SpurGear
    x_min = SpurGear(16, 10.0, 0.5).x_min
    ps = PlanetarySet(x_sun=x_min, n_planets=3)
    got = _check_conditions(ps)
    assert ("undercut_sun", True) == next(c[:2] for c in got if c[0] == "undercut_sun")


def test_planetary_ring_shift_for_coaxiality_of_a_25_degree_rack():
    rack = BasicRack(alpha=A25, rho_f_star=0.3)
    ps = PlanetarySet(rack=rack, x_sun=0.3, x_planet=0.3, x_ring=0.8, n_planets=3)
    aw = math.acos(10.0 * 36 / 2 * math.cos(A25) / ps.a_w)
    x3 = 0.3 + 36 * (_inv(aw) - _inv(A25)) / (2 * math.tan(A25))
    assert ps.ring_shift_for_coaxiality() == pytest.approx(x3, rel=1e-10)
    assert abs(ps.with_coaxial_ring().coaxiality_mismatch) < 1e-9
    _check_conditions(ps)


def test_planetary_set_refusals_in_full():
    assert _message(PlanetarySet, m=0.0) == "m = 0.0: must be > 0 mm"
    assert _message(PlanetarySet, n_planets=2.5) == "n_planets = 2.5: must be a whole number >= 1"
    assert _message(PlanetarySet, n_planets=0) == "n_planets = 0: must be a whole number >= 1"
    for name in ("b_sun", "b_planet", "b_ring"):
        assert _message(PlanetarySet, **{name: 0.0}) == f"{name} = 0.0: must be > 0 mm"
    assert _message(PlanetarySet, ratio_target=0.0) == "ratio_target = 0.0: must be > 0"
    assert _message(PlanetarySet, ratio_target=4.5, ratio_tol=math.nan) == "ratio_tol = nan: must be a finite number"
    assert _message(PlanetarySet, ratio_target=4.5, ratio_tol=-0.1) == "ratio_tol = -0.1: must be >= 0"
    assert (_message(PlanetarySet, z_sun=30, z_planet=10, z_ring=30)
            == "z_ring = 30: must exceed z_sun = 30 and z_planet = 10")
    assert (_message(PlanetarySet, z_sun=16, z_planet=30, z_ring=30)
            == "z_ring = 30: must exceed z_sun = 16 and z_planet = 30")
    ps = PlanetarySet(n_planets=3.0)
    assert type(ps.n_planets) is int and ps.n_planets == 3


def test_planetary_root_clearances_each_tip_against_its_mates_root():
    """Along the line of centres: external a_w − r_a2 − r_f1 and a_w − r_a1 − r_f2; internal (ring) r_a3 − a_w − r_f2
    and r_f3 − a_w − r_a2 (ISO 53: c*·m = 2.5 mm at the reference profile)."""
    ps = PlanetarySet(x_ring=1.5, n_planets=3)
    sp, pr = ps.mesh_sun_planet, ps.mesh_planet_ring
    d_a1, d_a2, d_a3 = sp.d_a1, min(sp.d_a2, pr.d_a1), pr.d_a2
    assert ps._root_clearances(sp) == pytest.approx(
        (sp.a_w - d_a2 / 2 - ps.sun.d_f / 2, sp.a_w - d_a1 / 2 - ps.planet.d_f / 2), rel=1e-13)
    assert ps._root_clearances(pr) == pytest.approx(
        (d_a3 / 2 - pr.a_w - ps.planet.d_f / 2, ps.ring.d_f / 2 - pr.a_w - d_a2 / 2), rel=1e-13)


def test_planetary_limits_at_small_margins():
    """A rack without bottom clearance (c* = 0): the sun–planet tips touch the roots, clearance 0.0, which fails
    (it must be > 0); c* = 0.05 and 0.1: clearances of 0.5 and 1 mm and an involute margin of 0.11 mm pass; a shaper
    of x0 = −1.2 cuts the ring's tip on its involute by 0.05 mm."""
    touching = PlanetarySet(rack=BasicRack(c_star=0.0, rho_f_star=0.0), x_ring=1.5, n_planets=3)
    got = {c[0]: c for c in _check_conditions(touching)}
    assert got["root_clearance_sun_planet"][1:3] == (False, 0.0)
    for c_star in (0.05, 0.1):
        got = {c[0]: c for c in _check_conditions(PlanetarySet(rack=BasicRack(c_star=c_star), x_ring=1.5))}
        assert got["root_clearance_sun_planet"][1:3] == (True, pytest.approx(10.0 * c_star))
    assert 0 < got["involute_interference_planet_ring_planet"][2] < 1 and got["involute_interference_planet_ring_planet"][1]
    got = {c[0]: c for c in _check_conditions(PlanetarySet(x_ring=1.5, x0=-1.2, z0=20))}
    assert 0 < got["ring_tip_cut_by_shaper"][2] < 0.1 and got["ring_tip_cut_by_shaper"][1]


# ============================================================================ planetary_kinematics.py
def test_planetary_kinematics_positions_and_angles_by_hand():
    """Seed 004 eq. 31–32 (Willis, ring fixed): planet k sits at the carrier angle ψ + 2πk/n on the circle a_w and
    turns by (1 − z3/z2)·(ψ + 2πk/n) + π − π/z2 (a space to the sun at ψ = 0); the sun turns by (1 + z3/z1)·ψ."""
    from propulsor.gears.planetary_kinematics import PlanetaryKinematics
    k = PlanetaryKinematics(16, 20, 56, 3, 188.643)
    assert k.planet_slot_angle(2) == pytest.approx(4 * math.pi / 3, rel=1e-15)
    psi = np.array([0.0, 0.3, 1.1])
    for j in range(3):
        a = psi + 2 * math.pi * j / 3
        assert k.planet_centre(psi, j) == pytest.approx(np.stack([188.643 * np.cos(a), 188.643 * np.sin(a)], axis=1),
                                                        rel=1e-14, abs=1e-12)
        assert k.planet_angle(psi, j) == pytest.approx(a * (1 - 56 / 20) + math.pi - math.pi / 20, rel=1e-14)
    assert k.planet_angle(0.0, 0) == pytest.approx(math.pi - math.pi / 20, rel=1e-15)
    assert k.sun_angle([0, 1, 2]) == pytest.approx([0.0, 4.5, 9.0], rel=1e-15)
    # shapes: a scalar ψ gives one point, a grid of ψ a grid of points (x, y last)
    assert k.planet_centre(0.25, 1).shape == (2,)
    assert k.planet_centre(0.25, 1) == pytest.approx([188.643 * math.cos(0.25 + 2 * math.pi / 3),
                                                       188.643 * math.sin(0.25 + 2 * math.pi / 3)], rel=1e-14)
    grid = np.linspace(0.0, 1.0, 6).reshape(2, 3)
    c = k.planet_centre(grid, 0)
    assert c.shape == (2, 3, 2) and c[1, 2] == pytest.approx([188.643 * math.cos(1.0), 188.643 * math.sin(1.0)],
                                                             rel=1e-14)
    # the ring turned half a pitch for an odd planet
    assert k.ring_rotation == 0.0 and PlanetaryKinematics(16, 19, 56, 3, 180.0).ring_rotation == math.pi / 56


@pytest.mark.parametrize("n", [5, 7])
def test_assembly_phase_error_is_the_suns_fraction_of_a_pitch(n):
    """Planet k needs the sun turned (1 + z3/z1)·(2πk/n) = (z1 + z3)·k/n sun pitches: the error is its distance to
    the nearest whole number (72/5 = 14.4: 0.4 for k = 1)."""
    from propulsor.gears.planetary_kinematics import PlanetaryKinematics
    k = PlanetaryKinematics(16, 20, 56, n, 188.0)
    for j in range(n):
        p = 72 * j / n
        assert k.assembly_phase_error(j) == pytest.approx(p - round(p), abs=1e-12)
    assert abs(k.assembly_phase_error(1)) > 0.1


def test_face_load_factor_of_a_narrow_face_takes_b_over_h_as_3():
    """ISO 6336-1:2006 eq. 61–62: N_F = (b/h)²/(1 + b/h + (b/h)²) with b/h < 3 taken as 3 (the helical module's
    k_f_beta does so).  b = 30 mm on h = 15 mm: N_F = 9/13 = 0.692, not 4/7 = 0.571 (an unconservative K_Fβ, 1.162
    instead of 1.199 at K_Hβ = 1.3).  Bug found by the mutation run of issue 36: the spur module took b/h as it came."""
    from propulsor.gears import iso6336_helical as h
    from propulsor.gears.iso6336 import face_load_method_c
    f = face_load_method_c(40000.0, 30.0, 90.0, 6, 15.0)
    assert f.N_F == pytest.approx(9 / 13, rel=1e-14)
    assert f.K_Fbeta == pytest.approx(f.K_Hbeta ** (9 / 13), rel=1e-14)
    assert f.K_Fbeta == pytest.approx(h.k_f_beta(f.K_Hbeta, 30.0, 15.0), rel=1e-14)
    wide = face_load_method_c(40000.0, 45.0, 90.0, 6, 15.0)                 # b/h = 3 itself: the same N_F
    assert wide.N_F == pytest.approx(9 / 13, rel=1e-14)


def test_face_load_factor_takes_the_deeper_tooth_of_the_pair():
    """ISO 6336-1 (K_Fβ = K_Hβ^N_F): b/h is the smaller of b1/h1 and b2/h2.  A pinion with its tip cut 1.2 mm
    down has the shallower tooth: the wheel's depth sets N_F (the pinion's would give a larger b/h, a larger N_F and
    a larger K_Fβ: the wrong one)."""
    from propulsor.gears.iso6336 import MeshLoad, mesh_stress
    pair = GearPair(SpurGear(19, 3.0, 0.2), SpurGear(37, 3.0, -0.1))
    d_a1 = pair.d_a1 - 1.2
    h1, h2 = (d_a1 - pair.gear1.d_f) / 2, (pair.d_a2 - pair.gear2.d_f) / 2
    assert h2 > h1 + 0.5
    s = mesh_stress(pair, d_a1, pair.d_a2, 30.0, MeshLoad(150.0, 9.0, 1.1, 8))
    assert s.face.h == pytest.approx(h2, rel=1e-12)
    bh = 30.0 / h2
    assert s.face.N_F == pytest.approx(bh * bh / (1 + bh + bh * bh), rel=1e-12)
    assert s.K_Fbeta == pytest.approx(s.K_Hbeta ** s.face.N_F, rel=1e-12)
