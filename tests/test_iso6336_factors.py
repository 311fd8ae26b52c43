"""ISO 6336 load factors, root method B and fatigue factors against hand arithmetic from the standard's formulas
(every expected number is worked out here from the formula, not by the module's own functions), and the load
factors pinned where a changed constant or branch would go unnoticed.

Formulas (ISO 6336-1/-2/-3:2006): K_v = 1 + (K_1/(K_A·F_t/b) + K_2)·v·z_1/100·√(u²/(1 + u²)), F_t/b >= 100 N/mm;
K_Hβ = 1 + c_γβ·F_βy/(2·F_m/b), above 2: √(2·c_γβ·F_βy/(F_m/b)); F_βx = 1.33·f_sh + f_ma, y_β = 0.15·F_βx <= 6 µm,
f_sh = 0.023·(F_m/b)·(b/d_1)²; K_Fβ = K_Hβ^N_F, N_F = (b/h)²/(1 + b/h + (b/h)²); Z_NT, Y_NT of case-hardened steel
(Tables 2 and 3: 1.6 / 1 / 0.85 at 1e5 / 5e7 / 1e10 cycles; 2.5 / 1 / 0.85 at 1e3 / 3e6 / 1e10 cycles);
Z_L, Z_v, Z_R of ISO 6336-2 clause 12.
"""

import math

import pytest

from propulsor.errors import InputError
from propulsor.gears import iso6336_life as life
from propulsor.gears.iso6336 import (MeshLoad, d_en_single_contact, k_h_beta_method_c, k_v_method_b, mesh_stress,
                                     tooth_form_factor)
from propulsor.gears.planetary import PlanetarySet

ALPHA = math.radians(20.0)
# ISO 1328-1:1995 f_Hβ at d = 160 mm, b = 75 mm, grade 6: (0.07·√160 + 0.45·√75 + 3)·2^0.5
F_HB_160_75_Q6 = (0.07 * 12.649110640673518 + 0.45 * 8.660254037844387 + 3.0) * 1.4142135623730951


def test_form_factor_refuses_a_load_point_on_the_base_circle():
    d_b = 10.0 * 16 * math.cos(ALPHA)
    with pytest.raises(InputError, match="d_en"):
        tooth_form_factor(16, 10.0, 0.5, d_b)
    assert tooth_form_factor(16, 10.0, 0.5, d_b * (1 + 1e-9)).Y_F > 0


@pytest.mark.parametrize("Ft_b, load", [(50.0, 100.0), (1000.0, 1000.0)])
def test_dynamic_factor_method_b_at_a_low_and_a_high_load(Ft_b, load):
    # grade 6 spur: K_1 = 14.9, K_2 = 0.0193; v = 5 m/s, z_1 = 16, u = 1.25: √(u²/(1 + u²)) = 1.25/√2.5625
    expected = 1.0 + (14.9 / load + 0.0193) * 5.0 * 16 / 100.0 * (1.25 / 1.6007810593582121)
    assert k_v_method_b(5.0, 16, 1.25, Ft_b, 1.0, 6) == pytest.approx(expected, rel=1e-12)


def test_face_load_factor_method_c_normal_and_low_load():
    f = F_HB_160_75_Q6                     # 11.0062 µm; y_β = 0.15·f (< 6 µm)
    F_by = f - 0.15 * f
    # normal load: F_m = 100 kN on b = 75 mm
    K_Hb = 1.0 + 17.0 * F_by / (2.0 * 100000.0 / 75.0)
    bh = 75.0 / 22.5
    N_F = bh ** 2 / (1.0 + bh + bh ** 2)
    assert k_h_beta_method_c(100000.0, 75.0, 160.0, 6, 22.5) == pytest.approx((K_Hb, K_Hb ** N_F), rel=1e-12)
    # low load, F_m/b = 40 N/mm: the linear form gives 2.99 > 2, the contact does not span the face
    assert 1.0 + 17.0 * F_by / 80.0 > 2.0
    K_low = math.sqrt(2.0 * 17.0 * F_by / 40.0)
    assert k_h_beta_method_c(3000.0, 75.0, 160.0, 6, 22.5) == pytest.approx((K_low, K_low ** N_F), rel=1e-12)
    # a large deviation: y_β stops at 6 µm (F_βx = 1.33·30 + f)
    F_bx = 1.33 * 30.0 + f
    K_big = 1.0 + 17.0 * (F_bx - 6.0) / (2.0 * 100000.0 / 75.0)
    assert k_h_beta_method_c(100000.0, 75.0, 160.0, 6, 22.5, f_sh=30.0)[0] == pytest.approx(K_big, rel=1e-12)


def _final_drive_sun_planet(torsion: bool):
    ps = PlanetarySet(n_planets=3).with_coaxial_ring()
    T1 = 90687.503 * 1.09 / 4.413 / 3            # seed 004 eq. 42, per mesh
    v = 2.0465125761411485                       # sun relative to the carrier at 7.852 km/h
    return ps, T1, v, mesh_stress(ps.mesh_sun_planet, ps.d_a_sun, ps.d_a_planet, 75.0,
                                  MeshLoad(T1, v, 1.0, 6, pinion_torsion=torsion))


def test_sun_torsional_deformation_raises_k_h_beta_from_1063_to_1112():
    ps, T1, v, s = _final_drive_sun_planet(True)
    _, _, _, s0 = _final_drive_sun_planet(False)
    F_t = 2000.0 * T1 / 160.0
    K_v = 1.0 + (14.9 / (F_t / 75.0) + 0.0193) * v * 16 / 100.0 * (1.25 / 1.6007810593582121)
    Fm_b = F_t * K_v / 75.0
    f_sh = 0.023 * Fm_b * (75.0 / 160.0) ** 2
    F_bx = 1.33 * f_sh + F_HB_160_75_Q6
    K_Hb = 1.0 + 17.0 * 0.85 * F_bx / (2.0 * Fm_b)
    K_Hb0 = 1.0 + 17.0 * 0.85 * F_HB_160_75_Q6 / (2.0 * Fm_b)
    assert (s.F_t, s.K_v) == pytest.approx((F_t, K_v), rel=1e-12)
    assert s.face.f_sh == pytest.approx(f_sh, rel=1e-12) and s0.face.f_sh == 0.0
    assert (s.K_Hbeta, s0.K_Hbeta) == pytest.approx((K_Hb, K_Hb0), rel=1e-12)
    assert round(s0.K_Hbeta, 3) == 1.063 and round(s.K_Hbeta, 3) == 1.112
    assert s.sigma_H / s0.sigma_H == pytest.approx(math.sqrt(K_Hb / K_Hb0), rel=1e-12)   # +2.3 %
    # the fields are the factors they name: K_Fβ = K_Hβ^N_F with h = (d_a1 − d_f1)/2 of the sun
    h = 0.5 * (ps.d_a_sun - ps.sun.d_f)
    bh = 75.0 / h
    assert s.K_Fbeta == pytest.approx(K_Hb ** (bh ** 2 / (1 + bh + bh ** 2)), rel=1e-12)
    assert (s.K_Hbeta, s.K_Fbeta) == pytest.approx(
        k_h_beta_method_c(F_t * K_v, 75.0, 160.0, 6, h, f_sh=f_sh), rel=1e-12)
    assert s.K_Hbeta > s.K_Fbeta > 1.0 and s.K_Halpha == s.K_Falpha == 1.0


def test_root_stress_method_b_at_the_outer_point_of_single_contact():
    ps, T1, v, s = _final_drive_sun_planet(True)
    eps = s.eps_alpha
    r_b = 80.0 * math.cos(ALPHA)
    g = math.sqrt((ps.d_a_sun / 2) ** 2 - r_b ** 2) - math.pi * 10.0 * math.cos(ALPHA) * (eps - 1)
    d_en = 2.0 * math.sqrt(g * g + r_b * r_b)
    assert s.d_en1 == pytest.approx(d_en, rel=1e-12)
    assert d_en_single_contact(ps.d_a_sun, 2 * r_b, 10.0, ALPHA, 1.0) == pytest.approx(ps.d_a_sun, rel=1e-12)
    assert ps.sun.d_b < s.d_en1 < ps.d_a_sun
    tf = tooth_form_factor(16, 10.0, 0.5, d_en)
    K = s.K_A * s.K_v * s.K_Fbeta * s.K_Falpha
    assert s.sigma_F1_B == pytest.approx(s.F_t / (75.0 * 10.0) * tf.Y_F * tf.Y_S * K, rel=1e-12)
    # method C keeps the load at the tip with Y_ε
    tc = tooth_form_factor(16, 10.0, 0.5, ps.d_a_sun)
    assert s.sigma_F1 == pytest.approx(s.F_t / 750.0 * tc.Y_F * tc.Y_S * (0.25 + 0.75 / eps) * K, rel=1e-12)
    assert s.sigma_F2_B is not None and s.d_en2 < ps.d_a_planet


def test_life_factors_at_the_tables_corners_and_between():
    assert life.z_nt(1e5) == 1.6 and life.z_nt(1e3) == 1.6
    assert life.z_nt(5e7) == pytest.approx(1.0) and life.z_nt(1e10) == pytest.approx(0.85, abs=5e-4)
    assert life.z_nt(1e6) == pytest.approx(50.0 ** 0.0756, rel=1e-12)
    assert life.z_nt(1e9) == pytest.approx(0.05 ** 0.0306, rel=1e-12) and life.z_nt(1e12) == life.z_nt(1e10)
    assert life.y_nt(1e3) == 2.5 and life.y_nt(3e6) == pytest.approx(1.0)
    assert life.y_nt(1e10) == pytest.approx(0.85, abs=5e-4) and life.y_nt(1e5) == pytest.approx(30.0 ** 0.115)
    for Z in (1.5, 1.1, 0.95, 0.9):
        assert life.z_nt(life.cycles_at_z_nt(Z)) == pytest.approx(Z, rel=1e-12)
        assert life.y_nt(life.cycles_at_y_nt(Z)) == pytest.approx(Z, rel=1e-12)
    assert life.cycles_at_z_nt(0.8) == math.inf and life.cycles_at_y_nt(2.6) == 0.0
    with pytest.raises(InputError, match="load_cycles"):
        life.z_nt(float("nan"))


def test_lubricant_speed_and_roughness_factors():
    # σ_Hlim = 1500 MPa (above 1200): C_ZL = 0.91, C_Zv = 0.93, C_ZR = 0.08
    assert life.z_l(220.0, 1500.0) == pytest.approx(0.91 + 4 * 0.09 / (1.2 + 134 / 220) ** 2, rel=1e-12)
    assert life.z_l(100.0, 1000.0) == pytest.approx(0.8642857142857143 + 4 * (1 - 0.8642857142857143)
                                                     / (1.2 + 1.34) ** 2, rel=1e-12)   # C_ZL = 0.83 + 0.08·150/350
    assert life.z_v(2.0, 1500.0) == pytest.approx(0.93 + 2 * 0.07 / math.sqrt(0.8 + 16.0), rel=1e-12)
    assert life.z_v(0.0, 1500.0) == pytest.approx(0.93)
    # ρ_red of the sun–planet pitch point: ρ = ½·d_b·tan α_w each
    r1, r2 = 0.5 * 150.0 * math.tan(0.45), 0.5 * 190.0 * math.tan(0.45)
    assert life.rho_red(150.0, 190.0, 0.45, False) == pytest.approx(r1 * r2 / (r1 + r2), rel=1e-12)
    assert life.rho_red(150.0, 500.0, 0.45, True) > r1           # concave ring flank
    Z_R, Rz10 = life.z_r(3.0, 3.0, 20.0, 1500.0)
    assert Rz10 == pytest.approx(3.0 * 0.5 ** (1 / 3), rel=1e-12) and Z_R == pytest.approx((3.0 / Rz10) ** 0.08)


def test_pitting_and_root_fatigue_safety_assemble_the_factors():
    # at N_L = 1e6 (between the static 1e5 and the reference 5e7) Z_L·Z_v·Z_R goes from its reference value to the
    # static 1 on the log-log line: w = log(5e7/1e6)/log(5e7/1e5) (tests/test_iso6336_planetary.py by hand)
    P = life.pitting_safety(1600.0, 1500.0, 1e6, 220.0, 2.0, 3.0, 3.0, 20.0, S_Hmin=1.0)
    w = math.log(50.0) / math.log(500.0)
    sHG = 1500.0 * 50.0 ** 0.0756 * (P.Z_L * P.Z_v * P.Z_R) ** (1.0 - w)
    assert (P.sigma_HG, P.S_H, P.Z_W, P.Z_X) == pytest.approx((sHG, sHG / 1600.0, 1.0, 1.0), rel=1e-12)
    q_s, Y_S = 1.9, 1.95
    sun = life.root_fatigue_safety(400.0, q_s, 10.0, 425.0, 10.0, 3e6, Y_S=Y_S)
    planet = life.root_fatigue_safety(400.0, q_s, 10.0, 425.0, 10.0, 3e6, idler=True, Y_S=Y_S)
    Yd = (1 + math.sqrt(0.003 * (1 + 2 * q_s) / 5)) / (1 + math.sqrt(0.003 * 1.2))
    Yr = 1.674 - 0.529 * 11.0 ** 0.1
    sFG = 425.0 * 2.0 * 1.0 * Yd * Yr * (1.05 - 0.01 * 10.0)     # the reference point: Y_NT = 1
    assert sun.sigma_FG == pytest.approx(sFG, rel=1e-12) and sun.S_F == pytest.approx(sFG / 400.0, rel=1e-12)
    assert planet.Y_M == 0.7 and planet.sigma_FG == pytest.approx(0.7 * sFG, rel=1e-12)
    # the static point (1e3 cycles and below): Y_NT = 2.5, Y_δrelT = 0.44·Y_S + 0.12, Y_RrelT = Y_X = 1
    st = life.root_fatigue_safety(400.0, q_s, 10.0, 425.0, 10.0, 1e3, Y_S=Y_S)
    assert st.sigma_FG == pytest.approx(425.0 * 2.0 * 2.5 * (0.44 * Y_S + 0.12), rel=1e-12)


def test_single_pair_contact_factors_of_sun_and_planet():
    ps, T1, v, s = _final_drive_sun_planet(True)
    m = ps.mesh_sun_planet
    a1 = math.sqrt((ps.d_a_sun / ps.sun.d_b) ** 2 - 1.0)
    a2 = math.sqrt((ps.d_a_planet / ps.planet.d_b) ** 2 - 1.0)
    eps = s.eps_alpha
    M1 = math.tan(m.alpha_w) / math.sqrt((a1 - 2 * math.pi / 16) * (a2 - (eps - 1) * 2 * math.pi / 20))
    M2 = math.tan(m.alpha_w) / math.sqrt((a2 - 2 * math.pi / 20) * (a1 - (eps - 1) * 2 * math.pi / 16))
    assert (s.Z_B, s.Z_D) == pytest.approx((max(1.0, M1), max(1.0, M2)), rel=1e-12)
    assert s.Z_B > s.Z_D > 1.0
    assert s.sigma_H_wheel == pytest.approx(s.sigma_H * M2 / M1, rel=1e-12)
    ring = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, 75.0, MeshLoad(T1 * 20 / 16, v))
    # ISO 6336-2:2019, 6.2: the internal wheel's Z_D is 1, the planet's Z_B is M_1 (tests/test_iso6336_planetary.py)
    assert ring.Z_D == 1.0 and ring.Z_B > 1.2 and ring.sigma_H_wheel == pytest.approx(ring.sigma_H / ring.Z_B, rel=1e-12)
