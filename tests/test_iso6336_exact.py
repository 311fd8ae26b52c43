"""ISO 6336 rating (gears/iso6336*.py, gear_materials.py, planetary*.py) checked against the standard's equations
computed here, independently of the code: both sides of every limit and clamp, refusals' messages in full
(issue 36, mutation testing: `make mutation MODULE=gears_rating`).  Fast, in-process, no part builds."""

from __future__ import annotations

import math

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
    bh = b / h
    N_F = bh ** 2 / (1 + bh + bh ** 2)
    return dict(f_sh=f_sh, f_ma=f_ma, F_betax=F_bx, y_beta=y_b, F_betay=F_by, c_gamma_beta=c_gb, F_m_b=F_m / b,
                K_Hbeta=K, h=h, N_F=N_F, K_Fbeta=K ** N_F)


@pytest.mark.parametrize("F_m,b,d1,grade,h,c,f_sh", [
    (100000.0, 75.0, 160.0, 6, 22.5, 20.0, None),     # f_sh left out: 0
    (60000.0, 40.0, 90.0, 7, 11.0, 18.0, 4.0),
    (3000.0, 75.0, 160.0, 8, 22.5, 20.0, 50.0),       # y_β at its 6 µm, the contact not spanning the face
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
    face = _face_by_hand(F_m, b, d1, grade, (d_a1 - g1.d_f) / 2, f_sh=f_sh)
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
    face = _face_by_hand(F_t * K_A * K_v, b, d1, grade, (d_a1 - g1.d_f) / 2)
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
