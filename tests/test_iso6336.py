"""ISO 6336 working stresses of a spur mesh (propulsor.gears.iso6336).

References the numbers are checked against:
* Y_Fa, Y_Sa (load at the tip, ISO 53 rack α = 20°, h_a* = 1, c* = 0.25, ρ_f* = 0.38, x = 0): the published
  table of Pu Lianggui & Ji Minggang, 《机械设计》 (Machine Design, Higher Education Press, Beijing),
  Table 10-5 "齿形系数 Y_Fa 及应力校正系数 Y_Sa" (GB/T 3480 ≡ ISO 6336-3), every row z = 17 ... 200 within 1 %.
* Z_E = 189.8 √MPa for steel on steel (ISO 6336-2, 6.3 example value) and Z_H = 2.495 for α = 20°,
  x1 + x2 = 0, β = 0 (ISO 6336-2 Figure 5 reads 2.49 ... 2.5).
* a complete DIN 3990 method B calculation (the method ISO 6336:1996 method B/C took over: load at the tip,
  Y_Fa·Y_Sa·Y_ε) recorded by an independent open-source implementation, hanslhansl/din3990,
  tests/test_1.py (z = 19/104, m = 4, x = 0.5/0.15, ρ_fP* = 0.25, d_a = 88/425.2, b = 48.64 mm,
  F_t = 14 103.42 N): Z_H, Z_ε, Z_B, σ_H0, Y_Fa, Y_Sa, Y_ε, σ_F0 within 0.1 % (it is not a standard's
  printed example; the published ISO/TR 6336-30:2017 example 1 is helical and is reproduced by the helical
  formulas in tests/test_iso6336_helical.py, whose β = 0 limit is this module's spur mesh; the tooth form of
  :func:`tooth_form_factor` at the method B load point and this module's σ_H0, Z_H, Z_ε, Z_B are checked against
  two KISSsoft ISO 6336:2006 method B reports (a helical pair and a spur planetary sun–planet mesh) in
  tests/test_iso6336_root.py — no worked example printed in a standard or textbook with σ_F numbers was found);
* σ_H0 against the Hertz line contact at the pitch point computed independently from the radii of
  curvature (external and internal mesh).
"""

import math

import pytest

from propulsor.errors import InputError
from propulsor.gears.gear_pair import GearPair
from propulsor.gears.involute import BasicRack, SpurGear
from propulsor.gears.iso6336 import (MeshLoad, f_h_beta, k_h_beta_method_c, k_v_method_b, mesh_stress,
                                     tooth_form_factor, z_e, z_eps, z_h)
from propulsor.gears.planetary import PlanetarySet

ALPHA = math.radians(20.0)

# Pu Lianggui, Machine Design, Table 10-5: z, Y_Fa, Y_Sa
TABLE_10_5 = [(17, 2.97, 1.52), (18, 2.91, 1.53), (19, 2.85, 1.54), (20, 2.80, 1.55), (21, 2.76, 1.56),
              (22, 2.72, 1.57), (23, 2.69, 1.575), (24, 2.65, 1.58), (25, 2.62, 1.59), (26, 2.60, 1.595),
              (27, 2.57, 1.60), (28, 2.55, 1.61), (29, 2.53, 1.62), (30, 2.52, 1.625), (35, 2.45, 1.65),
              (40, 2.40, 1.67), (45, 2.35, 1.68), (50, 2.32, 1.70), (60, 2.28, 1.73), (70, 2.24, 1.75),
              (80, 2.22, 1.77), (90, 2.20, 1.78), (100, 2.18, 1.79), (150, 2.14, 1.83), (200, 2.12, 1.865)]


@pytest.mark.parametrize("z,Y_Fa,Y_Sa", TABLE_10_5)
def test_form_and_stress_correction_factors_match_the_published_table(z, Y_Fa, Y_Sa):
    t = tooth_form_factor(z, 4.0, 0.0, 4.0 * (z + 2))
    assert t.Y_F == pytest.approx(Y_Fa, rel=0.01)
    assert t.Y_S == pytest.approx(Y_Sa, rel=0.01)


def test_form_factor_falls_with_positive_shift_and_does_not_scale_with_module():
    a = tooth_form_factor(16, 10.0, 0.5, 10.0 * (16 + 2 + 1.0))
    b = tooth_form_factor(16, 1.0, 0.5, 1.0 * (16 + 2 + 1.0))
    assert a.Y_F == pytest.approx(b.Y_F, rel=1e-12) and a.Y_S == pytest.approx(b.Y_S, rel=1e-12)
    assert a.s_Fn == pytest.approx(10 * b.s_Fn, rel=1e-12)
    assert a.Y_F < tooth_form_factor(16, 10.0, 0.0, 180.0).Y_F
    with pytest.raises(InputError, match="d_en"):
        tooth_form_factor(16, 10.0, 0.0, 100.0)


def test_elasticity_zone_and_contact_ratio_factors():
    assert z_e() == pytest.approx(189.8, abs=0.05)
    assert z_h(ALPHA, ALPHA) == pytest.approx(2.495, abs=5e-4)
    assert z_eps(1.0) == 1.0 and z_eps(2.0) == pytest.approx(math.sqrt(2 / 3))


@pytest.mark.parametrize("internal", [False, True])
def test_nominal_contact_stress_is_the_hertz_stress_at_the_pitch_point(internal):
    g1 = SpurGear(18, 5.0, 0.3)
    g2 = SpurGear(60, 5.0, 0.8, internal=True, z0=20, x0=0.0) if internal else SpurGear(41, 5.0, 0.2)
    pair = GearPair(g1, g2)
    T1, b = 700.0, 40.0
    s = mesh_stress(pair, pair.d_a1, pair.d_a2, b, MeshLoad(T1, 0.0))
    eps = pair.epsilon_alpha(pair.d_a1, pair.d_a2)
    # Hertz: normal force on the line of action, radii of curvature of both flanks at the pitch point
    F_bn = 2000.0 * T1 / g1.d_b
    rho1 = 0.5 * pair.d_w1 * math.sin(pair.alpha_w)
    rho2 = 0.5 * pair.d_w2 * math.sin(pair.alpha_w)
    curv = 1 / rho1 - 1 / rho2 if internal else 1 / rho1 + 1 / rho2
    E_star = 1.0 / (2 * (1 - 0.3 ** 2) / 206000.0)
    hertz = math.sqrt(F_bn * E_star * curv / (math.pi * b))
    assert s.sigma_H0 == pytest.approx(hertz * z_eps(eps), rel=1e-9)
    assert s.Z_B >= 1.0
    # σ_H grows as √F_t
    s4 = mesh_stress(pair, pair.d_a1, pair.d_a2, b, MeshLoad(4 * T1, 0.0))
    assert s4.sigma_H0 == pytest.approx(2 * s.sigma_H0, rel=1e-12)


def test_load_factors():
    # K_v: 1 at standstill, grows with speed and with a worse grade
    assert k_v_method_b(0.0, 16, 1.25, 1000.0, 1.0, 6) == 1.0
    assert 1.0 < k_v_method_b(5.0, 16, 1.25, 1000.0, 1.0, 6) < k_v_method_b(5.0, 16, 1.25, 1000.0, 1.0, 8)
    # ISO 1328-1:1995 f_Hβ, grade 5, d = 160, b = 75: 0.07√160 + 0.45√75 + 3 = 7.782 µm
    assert f_h_beta(160.0, 75.0, 5) == pytest.approx(7.7826, abs=1e-4)
    K_Hb, K_Fb = k_h_beta_method_c(100000.0, 75.0, 160.0, 6, 22.5)
    assert 1.0 < K_Fb < K_Hb < 2.0
    with pytest.raises(InputError, match="accuracy_grade"):
        k_v_method_b(1.0, 16, 1.0, 100.0, 1.0, 13)


def test_final_drive_meshes_at_the_thesis_torque():
    ps = PlanetarySet(n_planets=3).with_coaxial_ring()
    T_sun = 90687.503 * 1.09 / 4.413 / 3            # seed 004 eq. 42 per mesh
    sp = mesh_stress(ps.mesh_sun_planet, ps.d_a_sun, ps.d_a_planet, 75.0, MeshLoad(T_sun, 2.0))
    pr = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, 75.0, MeshLoad(T_sun * 20 / 16, 2.0))
    assert sp.F_t == pytest.approx(pr.F_t, rel=1e-12)      # one tangential force through the planet
    assert sp.Z_H == pytest.approx(pr.Z_H, rel=1e-9)         # coaxial set: one α_w
    assert pr.sigma_H < 0.6 * sp.sigma_H                     # concave ring flank
    assert 44 * 59 / sp.sigma_H > 1.0                        # within σ_Hmax = 44·HRC
    assert sp.sigma_F1 < 2198 / 1.75                         # within σ_Fmax = 1256 MPa


def test_a_recorded_din3990_method_b_calculation():
    """hanslhansl/din3990 tests/test_1.py: its printed intermediate values (see module docstring)."""
    rack = BasicRack(rho_f_star=0.25)
    pair = GearPair(SpurGear(19, 4.0, 0.5, rack), SpurGear(104, 4.0, 0.15, rack))
    assert pair.a_w == pytest.approx(248.506843355171, rel=1e-9)
    assert pair.epsilon_alpha(88.0, 425.2) == pytest.approx(1.5363235945832296, rel=1e-9)
    F_t, b, m = 14103.41869503906, 48.64, 4.0
    s = mesh_stress(pair, 88.0, 425.2, b, MeshLoad(F_t * 76.0 / 2000.0, 0.0))
    assert s.F_t == pytest.approx(F_t, rel=1e-12)
    assert s.Z_H == pytest.approx(2.3959406670899934, rel=1e-6)
    assert s.Z_eps == pytest.approx(0.906214912960638, rel=1e-6)
    assert s.Z_B == pytest.approx(1.00554704549864, rel=1e-6)
    assert s.sigma_H0 == pytest.approx(875.3827378988153, rel=1e-3)     # Z_E 189.81 here, 189.8 there
    assert s.Y_eps == pytest.approx(0.7381784037193403, rel=1e-6)
    assert (s.Y_F1, s.Y_F2) == pytest.approx((2.246336378902072, 2.1616566798058514), rel=1e-3)
    assert (s.Y_S1, s.Y_S2) == pytest.approx((1.9147262565947287, 2.008781657562889), rel=1e-3)
    sF0 = [F_t / (b * m) * yf * ys * s.Y_eps for yf, ys in ((s.Y_F1, s.Y_S1), (s.Y_F2, s.Y_S2))]
    assert sF0 == pytest.approx([230.15142071941582, 232.3547901900354], rel=1e-3)
