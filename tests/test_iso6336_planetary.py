"""The final drive's meshes by the letter of ISO 6336-1/-2/-3 (2019): the factors a planetary set needs beyond a
plain pair, each checked against hand arithmetic from the standard's formula with the numbers written out here
(the corrected set: z = 16/20/56, m = 10 mm, α = 20°, x = 0.5/0.5/1.5, a_w = 188.643 mm, three planets)."""

import math

import pytest

from propulsor.gears.iso6336 import MeshLoad, mesh_stress
from propulsor.gears.planetary import PlanetarySet

ALPHA = math.radians(20.0)
T_MESH = 90687.503 * 1.09 / 4.413 / 3      # N·m on the sun per mesh (seed 004 eq. 42, three planets)
V_REL = 2.0465125761411485                 # m/s, the sun's pitch-line speed relative to the carrier at 7.852 km/h


def _set():
    return PlanetarySet(n_planets=3).with_coaxial_ring()


def test_z_b_of_the_planet_in_the_ring_mesh_is_m1_with_the_rings_internal_geometry():
    """ISO 6336-2:2019, 6.2: Z_B = max(1, M_1) for the pinion also when its mate is internal; only Z_D of the
    internal wheel is 1.  With the internal wheel's z2, d_a2, d_b2 negative (the standard's sign convention):

        M_1 = tan α_w / √((√(d_a1²/d_b1² − 1) − 2π/z1)·(√(d_a2²/d_b2² − 1) + (ε_α − 1)·2π/|z2|))

    planet: d_b1 = 200·cos 20° = 187.939 mm, d_a1 = 227.286 mm (its tip as made: shortened in the sun mesh),
    ring: d_b2 = 560·cos 20° = 526.228 mm, d_a2 = 568.536 mm; cos α_w = 180·cos 20°/188.643 → α_w = 26.281°;
    ε_α = (ρ_a1 − ρ_a2 + a_w·sin α_w)/p_b = 1.349 (computed below)
    → M_1 = 1.2194 (the thesis prints 1.205); σ_H of the planet's flank = Z_B·σ_H0·√(K_A·K_v·K_Hβ·K_Hα)
    rises by that factor over the ring's (Z_D = 1): 793 → 967 MPa."""
    ps = _set()
    d_b1, d_b2 = 200.0 * math.cos(ALPHA), 560.0 * math.cos(ALPHA)
    d_a1, d_a2 = 227.28587198194845, 568.5358719819485
    a_w = 188.64293599097422
    alpha_w = math.acos(180.0 * math.cos(ALPHA) / a_w)
    rho_a1 = 0.5 * math.sqrt(d_a1 ** 2 - d_b1 ** 2)
    rho_a2 = 0.5 * math.sqrt(d_a2 ** 2 - d_b2 ** 2)
    p_b = math.pi * 10.0 * math.cos(ALPHA)
    eps = (rho_a1 - rho_a2 + a_w * math.sin(alpha_w)) / p_b
    f1 = math.sqrt((d_a1 / d_b1) ** 2 - 1.0) - 2.0 * math.pi / 20
    f2 = math.sqrt((d_a2 / d_b2) ** 2 - 1.0) + (eps - 1.0) * 2.0 * math.pi / 56
    M1 = math.tan(alpha_w) / math.sqrt(f1 * f2)
    assert round(M1, 3) == 1.219
    # the same ratio from the radii of curvature: √(ρ_red at the pitch point C / ρ_red at B), ρ_2 concave
    rC1, rC2 = 0.5 * d_b1 * math.tan(alpha_w), 0.5 * d_b2 * math.tan(alpha_w)
    rB1 = rho_a1 - p_b
    rB2 = rB1 + a_w * math.sin(alpha_w)
    assert M1 == pytest.approx(math.sqrt((rC1 * rC2 / (rC2 - rC1)) / (rB1 * rB2 / (rB2 - rB1))), rel=1e-12)
    s = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, 75.0, MeshLoad(T_MESH * 20 / 16, V_REL))
    assert s.eps_alpha == pytest.approx(eps, rel=1e-12)
    assert s.Z_B == pytest.approx(M1, rel=1e-12) and s.Z_D == 1.0
    assert s.sigma_H == pytest.approx(M1 * s.sigma_H_wheel, rel=1e-12)


def test_sun_f_sh_takes_the_torque_of_all_three_meshes():
    """ISO 6336-1:2019, clause 7, method C: f_sh = 0.023·(F_m/b)·(b/d_1)² is the pinion body's torsional wind-up
    under the torque it carries.  The sun meshes with three planets over the same face width, so its body twists
    under three meshes' torque: f_sh = 0.023·(3·F_m/b)·(b/d_1)².  By hand, b = 75 mm, d_1 = 160 mm, grade 6:

        F_t = 2000·T/d_1 = 2000·7466.93/160 = 93 331.6 N;  F_t/b = 1244.4 N/mm
        K_v = 1 + (14.9/(F_t/b) + 0.0193)·v·z_1/100·√(u²/(1 + u²)),  u = 20/16 = 1.25  → 1.0097
        F_m/b = F_t·K_v/b = 1256.6 N/mm;  f_sh = 0.023·3·1256.6·(75/160)² = 19.05 µm   (one mesh: 6.35 µm)
        f_ma = f_Hβ(ISO 1328-1, d = 160, b = 75, grade 6) = (0.07·√160 + 0.45·√75 + 3)·√2 = 11.01 µm
        F_βx = 1.33·f_sh + f_ma = 36.35 µm;  F_βy = 0.85·F_βx (y_β = 0.15·F_βx < 6 µm) = 30.90 µm
        K_Hβ = 1 + c_γβ·F_βy/(2·F_m/b) = 1 + 0.85·20·30.90/(2·1256.6) = 1.209   (one mesh's torque: 1.112)
    """
    ps = _set()
    F_t = 2000.0 * T_MESH / 160.0
    K_v = 1.0 + (14.9 / (F_t / 75.0) + 0.0193) * V_REL * 16 / 100.0 * math.sqrt(1.25 ** 2 / (1.0 + 1.25 ** 2))
    Fm_b = F_t * K_v / 75.0
    f_sh = 0.023 * 3 * Fm_b * (75.0 / 160.0) ** 2
    f_ma = (0.07 * math.sqrt(160.0) + 0.45 * math.sqrt(75.0) + 3.0) * math.sqrt(2.0)
    F_bx = 1.33 * f_sh + f_ma
    K_Hb = 1.0 + 0.85 * 20.0 * (F_bx - 0.15 * F_bx) / (2.0 * Fm_b)
    assert round(K_Hb, 3) == 1.209
    s = mesh_stress(ps.mesh_sun_planet, ps.d_a_sun, ps.d_a_planet, 75.0,
                    MeshLoad(T_MESH, V_REL, 1.0, 6, pinion_torsion=True, pinion_meshes=3))
    assert s.face.f_sh == pytest.approx(f_sh, rel=1e-12) and s.K_Hbeta == pytest.approx(K_Hb, rel=1e-12)


def test_the_final_drive_passes_the_planet_count_to_the_suns_wind_up():
    """The part's own stresses: the sun–planet mesh's f_sh is three meshes' (see above), at the part's face width."""
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.final_drive import FinalDriveParams
    from propulsor.parts.final_drive.design import planetary_set
    from propulsor.parts.final_drive.strength import mesh_stresses
    from pathlib import Path

    _, mp = read_part_file(Path(__file__).resolve().parents[1] / "parts" / "final_drive_thesis.toml")
    p = load_params(FinalDriveParams, mp)
    sp, _ = mesh_stresses(p, planetary_set(p))
    # b = 75 mm (the thesis's planets): F_m/b as above, f_sh = 0.023·3·(F_m/b)·(75/160)²
    assert sp.face.f_sh == pytest.approx(0.023 * 3 * sp.face.F_m_b * (75.0 / 160.0) ** 2, rel=1e-12)
    assert round(sp.K_Hbeta, 3) == 1.209


def test_the_thesis_sets_planet_ring_mesh_is_rated_at_the_carriers_centre_distance():
    """The thesis's ring shift x3 = 1.417 gives the planet–ring pair a_w = 187.997 mm from its shifts, but the
    carrier holds the planets at the sun–planet a_w = 188.643 mm: the mesh runs there, and its α_w, ε_α, Z_H and
    Z_B are taken there (ISO 21771: cos α_w = a·cos α/a_w with a = m·(z3 − z2)/2 = 180 mm):

        cos α_w = 180·cos 20°/188.643 → α_w = 26.281° (the shifts' 187.997 mm: 25.82°)
        ε_α = (ρ_a1 − ρ_a2 + a_w·sin α_w)/p_b, ρ_a = ½√(d_a² − d_b²) of the planet (227.286 mm) and the ring
              (567.452 mm, its tip as made with x3 = 1.417) → 1.398 (at the shifts' 187.997 mm: 1.348)
        Z_B = M_1 of ISO 6336-2:2019, 6.2 with the ring's internal geometry → 1.219 (at 187.997 mm: 1.205, the
        value the thesis prints)."""
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.final_drive import FinalDriveParams
    from propulsor.parts.final_drive.design import planetary_set
    from propulsor.parts.final_drive.strength import mesh_stresses
    from pathlib import Path

    _, mp = read_part_file(Path(__file__).resolve().parents[1] / "parts" / "final_drive_thesis.toml")
    p = load_params(FinalDriveParams, mp)
    ps = planetary_set(p)
    assert round(ps.mesh_planet_ring.a_w, 3) == 187.997 and round(ps.a_w, 3) == 188.643
    a_w = ps.a_w
    alpha_w = math.acos(180.0 * math.cos(ALPHA) / a_w)
    d_b1, d_b2 = 200.0 * math.cos(ALPHA), 560.0 * math.cos(ALPHA)
    d_a1, d_a2 = ps.d_a_planet, ps.d_a_ring
    assert (round(d_a1, 3), round(d_a2, 3)) == (227.286, 567.452)
    r1, r2 = 0.5 * math.sqrt(d_a1 ** 2 - d_b1 ** 2), 0.5 * math.sqrt(d_a2 ** 2 - d_b2 ** 2)
    p_b = math.pi * 10.0 * math.cos(ALPHA)
    eps = (r1 - r2 + a_w * math.sin(alpha_w)) / p_b
    f1 = math.sqrt((d_a1 / d_b1) ** 2 - 1.0) - 2.0 * math.pi / 20
    f2 = math.sqrt((d_a2 / d_b2) ** 2 - 1.0) + (eps - 1.0) * 2.0 * math.pi / 56
    Z_B = math.tan(alpha_w) / math.sqrt(f1 * f2)
    Z_H = math.sqrt(2.0 * math.cos(alpha_w) / (math.cos(ALPHA) ** 2 * math.sin(alpha_w)))
    _, pr = mesh_stresses(p, ps)
    assert pr.eps_alpha == pytest.approx(eps, rel=1e-12) and round(eps, 3) == 1.398
    assert (pr.Z_B, pr.Z_H) == pytest.approx((Z_B, Z_H), rel=1e-12) and round(Z_B, 3) == 1.219
    assert pr.a_w == a_w and pr.alpha_w == pytest.approx(alpha_w, rel=1e-12)
    # the shifts' centre distance gives the thesis's Z_B = 1.205: the value quoted beside ours in the report
    own = mesh_stress(ps.mesh_planet_ring, d_a1, d_a2, 75.0, MeshLoad(T_MESH * 20 / 16, V_REL))
    assert round(own.Z_B, 3) == 1.205 and own.a_w == pytest.approx(187.99721650532422, rel=1e-12)


def test_finite_life_takes_the_influence_factors_between_the_static_and_the_reference_point():
    """ISO 6336-2:2019 and ISO 6336-3:2019, 5.4 (method B): below the reference point the permissible stress lies on
    the log-log line from the static point, so Z_L·Z_v·Z_R and Y_δrelT·Y_RrelT·Y_X go from their reference values
    to their static ones as the life factor goes from 1 to 1.6 (2.5):  P(N) = P_ref·(P_static/P_ref)^w,
    w = log(N_ref/N)/log(N_ref/N_static).  The planet, 100 h at the design point: N_L = 1.1726e6 cycles.

    pitting, its flank on the ring side (case-hardened, σ_Hlim = 1500 MPa, ν_40 = 220 mm²/s, v = 2.0465 m/s,
    R_z = 3 µm, ρ_red at the pitch point of the ring mesh, C_ZL = 0.91, C_Zv = 0.93, C_ZR = 0.08):
        Z_L = 0.91 + 4·0.09/(1.2 + 134/220)² = 1.0200,  Z_v = 0.93 + 2·0.07/√(0.8 + 32/v) = 0.9646,
        Z_R = (3/R_z10)^0.08, R_z10 = 3·(10/ρ_red)^(1/3);  Z_NT = (5e7/N)^0.0756
        w = log(5e7/1.1726e6)/log(5e7/1e5) = 0.6039;  σ_HG = 1500·Z_NT·(Z_L·Z_v·Z_R)^(1 − w)·1^w
        → S_H 2.1364 → 2.0899 at b = 75 mm (−2.2 %: the reference product 1.037 counts only 40 % at this life)
    root of the planet (sun mesh, Y_M = 0.7): Y_δrelT,static = 0.44·Y_S + 0.12, Y_RrelT,static = Y_X,static = 1;
        w = log(3e6/N)/log(3e6/1e3);  σ_FG = 425·2·Y_NT·P_ref^(1 − w)·P_static^w·0.7
        → S_F 1.3820 → 1.3924 at b = 75 mm (still below 1.4: the part files say what the 75 mm planet needs)."""
    from propulsor.gears import iso6336_life as life

    ps = _set()
    N = 3600.0 * 3.5 * 7.852 / 3.6 / (15 * 0.125) * 16 / 20 * 100.0
    assert N == pytest.approx(1172565.333, rel=1e-9)
    alpha_w = math.acos(180.0 * math.cos(ALPHA) / 188.64293599097422)
    r1, r2 = 100.0 * math.cos(ALPHA) * math.tan(alpha_w), 280.0 * math.cos(ALPHA) * math.tan(alpha_w)
    rho_red = r1 * r2 / (r2 - r1)                             # ρ_2 concave
    Z_L = 0.91 + 4 * 0.09 / (1.2 + 134.0 / 220.0) ** 2
    Z_v = 0.93 + 2 * 0.07 / math.sqrt(0.8 + 32.0 / V_REL)
    Z_R = (3.0 / (3.0 * (10.0 / rho_red) ** (1.0 / 3.0))) ** 0.08
    w = math.log(5e7 / N) / math.log(5e7 / 1e5)
    assert round(w, 4) == 0.6039
    s = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, 75.0, MeshLoad(T_MESH * 20 / 16, V_REL),
                    a_w=ps.a_w)
    sHG = 1500.0 * (5e7 / N) ** 0.0756 * (Z_L * Z_v * Z_R) ** (1.0 - w)
    P = life.pitting_safety(s.sigma_H, 1500.0, N, 220.0, V_REL, 3.0, 3.0, rho_red)
    assert P.sigma_HG == pytest.approx(sHG, rel=1e-12) and P.S_H == pytest.approx(sHG / s.sigma_H, rel=1e-12)
    # root of the planet in the sun mesh at N_L: method B tooth form (load at the outer point of single contact)
    sp = mesh_stress(ps.mesh_sun_planet, ps.d_a_sun, ps.d_a_planet, 75.0,
                     MeshLoad(T_MESH, V_REL, 1.0, 6, pinion_torsion=True, pinion_meshes=3))
    tf = sp.root2_B
    q_s = tf.s_Fn / (2.0 * tf.rho_F)
    Yd = (1 + math.sqrt(0.003 * (1 + 2 * q_s) / 5)) / (1 + math.sqrt(0.003 * 1.2))
    Y_ref = Yd * (1.674 - 0.529 * 11.0 ** 0.1) * (1.05 - 0.01 * 10.0)
    Y_st = 0.44 * tf.Y_S + 0.12
    wF = math.log(3e6 / N) / math.log(3e6 / 1e3)
    sFG = 425.0 * 2.0 * (3e6 / N) ** 0.115 * Y_ref ** (1.0 - wF) * Y_st ** wF * 0.7
    R = life.root_fatigue_safety(sp.sigma_F2_B, q_s, 10.0, 425.0, 10.0, N, 1.4, True, Y_S=tf.Y_S)
    assert R.sigma_FG == pytest.approx(sFG, rel=1e-12) and R.S_F == pytest.approx(sFG / sp.sigma_F2_B, rel=1e-12)


def _form_by_hand(z, x, d_en, E_sn, m=10.0, h_fP=12.5, rho=3.8):
    """ISO 6336-3:2019, 6.2 (30° tangent construction) written out, with the thickness allowance E_sn the way the
    solids are cut (the rack's tooth widened by E_sn at the same depth): E gains E_sn/2, γ_e loses E_sn/d."""
    a = ALPHA
    E = math.pi / 4 * m - h_fP * math.tan(a) - (1 - math.sin(a)) * rho / math.cos(a) + E_sn / 2
    G = rho / m - h_fP / m + x
    H = 2.0 / z * (math.pi / 2 - E / m) - math.pi / 3
    th = math.pi / 6
    for _ in range(100):
        th = 2 * G / z * math.tan(th) - H
    s_Fn = m * (z * math.sin(math.pi / 3 - th) + math.sqrt(3) * (G / math.cos(th) - rho / m))
    rho_F = rho + 2 * m * G * G / (math.cos(th) * (z * math.cos(th) ** 2 - 2 * G))
    d = m * z
    a_en = math.acos(d * math.cos(a) / d_en)
    g_e = (math.pi / 2 + 2 * x * math.tan(a)) / z - E_sn / d + (math.tan(a) - a) - (math.tan(a_en) - a_en)
    a_F = a_en - g_e
    h_Fe = 0.5 * m * ((math.cos(g_e) - math.sin(g_e) * math.tan(a_F)) * d_en / m - z * math.cos(math.pi / 3 - th)
                      - G / math.cos(th) + rho / m)
    Y_F = 6 * (h_Fe / m) * math.cos(a_F) / ((s_Fn / m) ** 2 * math.cos(a))
    L, q = s_Fn / h_Fe, s_Fn / (2 * rho_F)
    return s_Fn, Y_F, (1.2 + 0.13 * L) * q ** (1 / (1.21 + 2.3 / L))


def test_the_form_factors_are_those_of_the_thinned_teeth_the_solids_have():
    """The solids are cut with the allowance E_sn = 0.15 mm (arc thickness on d): the root chord s_Fn of the
    sun and the planet shrinks by 0.14 mm and Y_F·Y_S grows by 0.94 % each (a radial infeed of the hob, x_E, would
    also deepen the root, which the solid's is not).  The final drive's method B roots (load at the outer point of
    single contact) are those of the thinned teeth."""
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.final_drive import FinalDriveParams
    from propulsor.parts.final_drive.design import planetary_set
    from propulsor.parts.final_drive.strength import mesh_stresses
    from pathlib import Path

    _, mp = read_part_file(Path(__file__).resolve().parents[1] / "parts" / "final_drive.toml")
    p = load_params(FinalDriveParams, mp)
    assert p.tooth_thinning_mm == 0.15
    sp, _ = mesh_stresses(p, planetary_set(p))
    for z, root, d_en in ((16, sp.root1_B, sp.d_en1), (20, sp.root2_B, sp.d_en2)):
        s0, YF0, YS0 = _form_by_hand(z, 0.5, d_en, 0.0)
        s1, YF1, YS1 = _form_by_hand(z, 0.5, d_en, 0.15)
        assert (root.s_Fn, root.Y_F, root.Y_S) == pytest.approx((s1, YF1, YS1), rel=1e-9)
        assert round(s0 - s1, 2) == 0.14 and round(100 * (YF1 * YS1 / (YF0 * YS0) - 1), 2) == 0.94


def test_the_wider_suns_root_is_bent_over_the_common_face_plus_a_module_each_side():
    """ISO 6336-3:2019, 5.2: the wider gear's root carries the load over the narrower face plus at most one module
    beyond each end, within its own face.  The thesis's faces: sun 80 mm, planets 75 mm, m = 10 mm:
        sun:    b_F = min(80, 75 + 2·10) = 80 mm;   planet: b_F = 75 mm
        σ_F,sun = F_t/(b_F·m)·Y_F·Y_S·K_A·K_v·K_Fβ·K_Fα, 75/80 of its value over the common face (K_Fβ stays the
        mesh's, over 75 mm), so the sun's bending fatigue safety S_F = σ_FG/σ_F rises by 80/75: 1.741 → 1.857 with
        the other corrections here (1.869 → 1.994 on the factors before them)."""
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.final_drive import FinalDriveParams
    from propulsor.parts.final_drive.design import planetary_set
    from propulsor.parts.final_drive.strength import mesh_stresses
    from pathlib import Path

    _, mp = read_part_file(Path(__file__).resolve().parents[1] / "parts" / "final_drive_thesis.toml")
    p = load_params(FinalDriveParams, mp)
    sp, pr = mesh_stresses(p, planetary_set(p))
    assert (sp.b, sp.b_F1, sp.b_F2) == (75.0, 80.0, 75.0) and (pr.b_F1, pr.b_F2) == (75.0, 80.0)
    K = sp.K_A * sp.K_v * sp.K_Fbeta * sp.K_Falpha
    tf = sp.root1_B
    assert sp.sigma_F1_B == pytest.approx(sp.F_t / (80.0 * 10.0) * tf.Y_F * tf.Y_S * K, rel=1e-12)
    assert sp.sigma_F2_B == pytest.approx(sp.F_t / (75.0 * 10.0) * sp.root2_B.Y_F * sp.root2_B.Y_S * K, rel=1e-12)
    from propulsor.parts.final_drive.fatigue import fatigue_rows

    sp75, _ = mesh_stresses(p, planetary_set(p), 75.0, 75.0)       # every root over the common 75 mm
    assert sp75.sigma_F1_B / sp.sigma_F1_B == pytest.approx(80.0 / 75.0, rel=1e-12)
    _, _, root = fatigue_rows(p, planetary_set(p), sp, pr, V_REL)
    assert round(root[("sun_planet", "sun")][0].S_F, 3) == 1.857
