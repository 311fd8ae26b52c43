"""The final drive's strength and fatigue steps (parts/final_drive/strength.py, fatigue.py) and its carrier,
traction and design steps, value by value (issue 36: the mutation run of the final_drive target).  Each test runs
the step in this process on the part file's design (no part build): the ISO 6336 formulas and the seed 004 values
computed here, both sides of every limit, the messages and notes in full."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from propulsor.params import load_params, read_part_file
from propulsor.parts.final_drive import FinalDriveParams

ROOT = Path(__file__).resolve().parents[1]
PART = ROOT / "parts" / "final_drive.toml"
THESIS = ROOT / "parts" / "final_drive_thesis.toml"

from test_part_final_drive import _Writer  # noqa: E402 - the output writer's parts the steps use

# seed 004: M_vk.max (eq. 40), Ω (eq. 42), i_sil (eq. 41), V_min (eq. 65), z = 15 sprocket teeth of t = 125 mm
M_VK, OMEGA, I_SIL, V_KMH = 90687.503, 1.09, 4.413, 7.852
N_CARRIER = V_KMH / 3.6 / (15 * 0.125)                     # rev/s of the carrier (the sprocket)


def _params(path=PART, **changes):
    _, mp = read_part_file(path)
    return dataclasses.replace(load_params(FinalDriveParams, mp), **changes)


@pytest.fixture(scope="module")
def p():
    return _params()


def _strength(p):
    from propulsor.parts.final_drive.design import design
    from propulsor.parts.final_drive.strength import strength

    dd = design(p)
    w = _Writer()
    strength(dd, w, {})
    return dd, w


@pytest.fixture
def st(p):   # each test runs the step: mutmut ties a test to the functions it calls itself
    return _strength(p)


# ---- strength.py: the load path (seed 004 eq. 40-42) and the allowables (ch. 4.1) ---------------------------------
def test_strength_loads_and_allowables(st):
    dd, w = st
    d = w.derived
    T_sun = M_VK * OMEGA / I_SIL                            # 22 399.6 N·m (thesis 22 399)
    assert d["design_torque_carrier_Nm"] == M_VK
    assert d["sun_torque_Nm"] == pytest.approx(T_sun, rel=1e-12) and round(d["sun_torque_Nm"]) == 22400
    assert d["sun_torque_per_mesh_Nm"] == pytest.approx(T_sun / 3, rel=1e-12)
    # the sun's pitch circle (z = 16, m = 10: d = 160 mm) turns i - 1 = 56/16 = 3.5 times relative to the carrier
    assert dd.ps.ratio == pytest.approx(4.5, rel=1e-12)
    assert d["pitch_line_speed_rel_m_s"] == pytest.approx(math.pi * 0.160 * N_CARRIER * 3.5, rel=1e-12)
    assert d["sigma_Hmax_allowable_MPa"] == 44 * 59 == 2596
    assert d["sigma_FlimM_MPa"] == pytest.approx(2.8 * 785, rel=1e-15)
    assert d["sigma_Fmax_allowable_MPa"] == pytest.approx(2.8 * 785 / 1.75, rel=1e-15)


_MESH_KEYS = ("F_t", "b", "K_A", "K_v", "K_Hbeta", "K_Halpha", "K_Fbeta", "K_Falpha", "Z_H", "Z_E", "Z_eps", "Z_B",
              "Y_eps", "sigma_H0", "sigma_H")


def test_strength_mesh_values_and_table_are_those_of_iso6336_at_the_design_torque(st):
    from propulsor.gears.iso6336 import MeshLoad, mesh_stress, root_face_width
    from propulsor.parts.final_drive.strength import ring_root

    dd, w = st
    p, ps, d = dd.p, dd.ps, w.derived
    T1 = M_VK * OMEGA / I_SIL / 3
    v = math.pi * 0.160 * N_CARRIER * 3.5
    # sun-planet: the sun twists under the three meshes' torque; each root over the 80 mm common face
    sp = mesh_stress(ps.mesh_sun_planet, ps.d_a_sun, ps.d_a_planet, 80.0,
                     MeshLoad(T1, v, 1.0, 6, pinion_torsion=True, pinion_meshes=3), E_sn=p.tooth_thinning_mm,
                     b_F=(root_face_width(80.0, 80.0, 10.0), root_face_width(80.0, 80.0, 10.0)))
    # planet-ring: the idler planet passes the sun's tangential force on (torque x 20/16), at the carrier's a_w
    pr = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, 80.0, MeshLoad(T1 * 20 / 16, v, 1.0, 6),
                     a_w=ps.a_w, internal_root=ring_root(p, ps), E_sn=p.tooth_thinning_mm, b_F=(80.0, 80.0))
    assert sp.F_t == pytest.approx(2000 * T1 / 160, rel=1e-12) and pr.F_t == pytest.approx(sp.F_t, rel=1e-12)
    rows = w.tables["strength_meshes"]
    assert rows[0] == ["mesh", "quantity", "value"]
    expect = []
    for tag, s, gears in (("sun_planet", sp, ("sun", "planet")), ("planet_ring", pr, ("planet", "ring"))):
        vals = {("b_mm" if k == "b" else f"{k}_N" if k == "F_t" else f"{k}_MPa" if k.startswith("sigma") else k):
                getattr(s, k) for k in _MESH_KEYS}
        vals["S_H_static"] = 2596.0 / s.sigma_H
        for g, sC, sB, YF, YS in ((gears[0], s.sigma_F1, s.sigma_F1_B, s.Y_F1, s.Y_S1),
                                  (gears[1], s.sigma_F2, s.sigma_F2_B, s.Y_F2, s.Y_S2)):
            vals.update({f"Y_F_method_C_{g}": YF, f"Y_S_method_C_{g}": YS, f"sigma_F_{g}_method_C_MPa": sC,
                         f"sigma_F_{g}_method_B_MPa": sB, f"S_F_{g}_static": 2198.0 / sB})
        vals["face_width_required_mm"] = d[f"strength_{tag}_face_width_required_mm"]
        expect += [[tag, k, x] for k, x in vals.items()]
    assert [r[:2] for r in rows[1]] == [r[:2] for r in expect] and len(rows[1]) == 54
    for (tag, k, x), r in zip(expect, rows[1]):
        assert r[2] == pytest.approx(x, rel=1e-12), (tag, k)
        assert d[f"strength_{tag}_{k}"] == r[2]
    assert d["strength_sun_planet_b_mm"] == d["strength_planet_ring_b_mm"] == 80.0
    # the printed values of the default design (S_H static = 2596/1689.7, the ring's root 561.9 MPa by method B)
    assert round(d["strength_sun_planet_sigma_H_MPa"], 1) == 1689.7
    assert round(d["strength_planet_ring_sigma_H_MPa"], 1) == 938.8
    assert round(d["strength_planet_ring_sigma_F_ring_method_B_MPa"], 1) == 561.9


def test_required_face_width_is_where_the_smallest_static_safety_meets_its_minimum(st):
    from propulsor.parts.final_drive.strength import mesh_stresses

    dd, w = st
    p, ps = dd.p, dd.ps
    for k, tag in enumerate(("sun_planet", "planet_ring")):
        b = w.derived[f"strength_{tag}_face_width_required_mm"]

        def least(bb):
            s = mesh_stresses(p, ps, bb, bb)[k]
            return min(2596.0 / s.sigma_H, 2198.0 / s.sigma_F1_B / 1.75, 2198.0 / s.sigma_F2_B / 1.75)

        assert least(b) == pytest.approx(1.0, abs=1e-7)
        assert least(b - 1e-3) < 1.0 < least(b + 1e-3)
    assert round(w.derived["strength_sun_planet_face_width_required_mm"], 2) == 28.51
    # 34.53 since K_Fβ takes b/h < 3 as 3 (ISO 6336-1 eq. 61-62): 34.36 with the narrow face's own b/h
    assert round(w.derived["strength_planet_ring_face_width_required_mm"], 2) == 34.53


def test_required_face_width_search_ends_at_two_hundred_modules(p):
    """Beyond 200 m = 2000 mm of face the search gives up (inf); a contact safety reached at 1995 mm is found."""
    from propulsor.parts.final_drive.design import planetary_set
    from propulsor.parts.final_drive.strength import mesh_stresses, required_face_width

    ps = planetary_set(p)
    for bb in (1995.0, 2005.0):
        S_H = 2596.0 / mesh_stresses(p, ps, bb, bb)[0].sigma_H     # the static contact safety at that face
        q = dataclasses.replace(p, contact_safety_S_Hmin=S_H)
        got = required_face_width(q, ps, "sun_planet")
        if bb < 2000.0:
            assert got == pytest.approx(bb, abs=1e-5)
        else:
            assert got == math.inf


def test_strength_checks_in_full(st):
    _, w = st
    got = [(c.name, c.value, c.limit, c.unit, c.message, c.passed) for c in w.checks]
    d = w.derived
    want = [
        ("strength_sun_planet.S_H_static", 2596.0 / d["strength_sun_planet_sigma_H_MPa"], 1.0, "",
         "S_H static (σ_Hmax = 44·HRC = 2596 MPa, seed 004 ch. 4.1) over ISO 6336-2 σ_H = 1689.7 MPa at the design "
         "torque", True),
        ("strength_sun_planet.face_width", d["strength_sun_planet_face_width_required_mm"], 80.0, "mm",
         "face width the mesh needs for the static checks (28.51 mm) within the one it has (80 mm)", True),
        ("strength_sun_planet.S_F_sun_static", 2198.0 / d["strength_sun_planet_sigma_F_sun_method_B_MPa"], 1.75, "",
         "S_F static (σ_FlimM = 2.8·σ_t = 2198 MPa, seed 004 ch. 4.1) over ISO 6336-3 method B σ_F = 440.4 MPa "
         "(method C: 445.9 MPa)", True),
        ("strength_sun_planet.S_F_planet_static", 2198.0 / d["strength_sun_planet_sigma_F_planet_method_B_MPa"], 1.75,
         "", "S_F static (σ_FlimM = 2.8·σ_t = 2198 MPa, seed 004 ch. 4.1) over ISO 6336-3 method B σ_F = 440.4 MPa "
         "(method C: 443.5 MPa)", True),
        ("strength_planet_ring.S_H_static", 2596.0 / d["strength_planet_ring_sigma_H_MPa"], 1.0, "",
         "S_H static (σ_Hmax = 44·HRC = 2596 MPa, seed 004 ch. 4.1) over ISO 6336-2 σ_H = 938.8 MPa at the design "
         "torque", True),
        ("strength_planet_ring.face_width", d["strength_planet_ring_face_width_required_mm"], 80.0, "mm",
         "face width the mesh needs for the static checks (34.53 mm) within the one it has (80 mm)", True),
        ("strength_planet_ring.S_F_planet_static", 2198.0 / d["strength_planet_ring_sigma_F_planet_method_B_MPa"],
         1.75, "", "S_F static (σ_FlimM = 2.8·σ_t = 2198 MPa, seed 004 ch. 4.1) over ISO 6336-3 method B "
         "σ_F = 363.2 MPa (method C: 374.2 MPa)", True),
        ("strength_planet_ring.S_F_ring_static", 2198.0 / d["strength_planet_ring_sigma_F_ring_method_B_MPa"], 1.75,
         "", "S_F static (σ_FlimM = 2.8·σ_t = 2198 MPa, seed 004 ch. 4.1) over ISO 6336-3 method B σ_F = 561.9 MPa "
         "(method C: 525.7 MPa)", True),
        ("bearing_planet.S0", 128700.0 / d["bearing_planet_load_N"], 1.0, "",
         "ISO 76 C0 = 128700 N over the load 87334 N (10231 (thesis; d x D x B ours))", True),
        ("bearing_carrier.S0", d["bearing_carrier_C0_N"] / 858508.0, 1.0, "",
         "ISO 76 C0 = 1415838 N over the load 858508 N (3524 (GOST 5721))", True),
        ("spline.margin", d["spline_allowable_MPa"] / d["spline_sigma_MPa"], 1.0, "",
         "Эв. 120 x 3.5 GOST 6033-80 (z = 34, x = -0.407): σ = 117.164 MPa, [σ]_sm = σ_T/(n·K_Σ) = 121.294 MPa with "
         "the hub steel's σ_T = 630 MPa (thesis: 785 MPa → 151.136 MPa)", True),
        ("shaft.margin", 970.0 / d["shaft_sigma_eq_MPa"], 1.0, "",
         "σ_eq = √(σ² + 4τ²) = 775.831 MPa against σ_T = 970 MPa", True),
    ]
    assert [g[0] for g in got] == [x[0] for x in want]
    for g, x in zip(got, want):
        assert g[1] == pytest.approx(x[1], rel=1e-12) and g[2:] == x[2:], g[0]


def test_a_strength_check_fails_below_its_limit(p):
    """Hardness 30 HRC: σ_Hmax = 1320 MPa under the sun-planet mesh's 1689.7 MPa fails S_H static and the face."""
    _, w = _strength(dataclasses.replace(p, flank_hardness_HRC=30.0))
    failed = {c.name for c in w.checks if not c.passed}
    assert failed == {"strength_sun_planet.S_H_static", "strength_sun_planet.face_width"}
    assert w.derived["strength_sun_planet_face_width_required_mm"] > 80.0


def test_bearings_spline_and_shaft(st):
    dd, w = st
    d = w.derived
    # eq. 44: P_sat = M_vk·Ω/(r_vod·n_w·i), r_vod = a_w, 3 planets, 2 bearings a planet
    P_sat = M_VK * OMEGA / (dd.ps.a_w * 1e-3 * 3 * 2)
    assert round(dd.ps.a_w, 3) == 188.643
    assert d["bearing_planet_load_N"] == pytest.approx(P_sat, rel=1e-12)
    assert d["bearing_planet_C0_N"] == 128700.0
    assert d["bearing_planet_S0"] == pytest.approx(128700.0 / P_sat, rel=1e-12)
    assert d["bearing_carrier_load_N"] == 858508.0
    assert d["bearing_carrier_S0"] == pytest.approx(d["bearing_carrier_C0_N"] / 858508.0, rel=1e-12)
    assert round(d["bearing_carrier_C0_N"]) == 1415838
    cols, rows = w.tables["bearings"]
    assert cols == ["role", "designation", "d_x_D_x_B_mm", "C0_ISO76_N", "C0_thesis_Table8_N", "load_N", "S0",
                    "thesis_C0_N", "thesis_load_N", "thesis_S0"]
    assert rows[0][:5] == ["planet", "10231 (thesis; d x D x B ours)", "55 x 110 x 21", 128700.0, 128700.0]
    assert rows[0][5:7] == [d["bearing_planet_load_N"], d["bearing_planet_S0"]]
    assert rows[0][7:] == [128700.0, 92000.0, 1.39]
    assert rows[1][:3] == ["carrier", "3524 (GOST 5721)", "120 x 215 x 58"]
    assert rows[1][3:7] == [d["bearing_carrier_C0_N"], 1398120.0, 858508.0, d["bearing_carrier_S0"]]
    assert rows[1][7:] == [1398120.0, 858508.0, 1.629]
    # eq. 45-47: P_t = 2π·M/(z·t); the slack side P_0 - P_t/(1 + 10/64) < 0 is clamped to 0, so Q = P_t
    P_t = 2 * math.pi * M_VK / (15 * 0.125)
    assert d["track_pull_P_t_N"] == pytest.approx(P_t, rel=1e-12)
    assert d["sprocket_axle_load_Q_N"] == pytest.approx(P_t, rel=1e-12)
    # spline (seed 004 §4.3): σ = 2000·M/(S_u·L), [σ] = σ_T/(n·K_pr·K_z·K_p)
    assert d["spline_S_u_mm3_per_mm"] == pytest.approx(5528.74, rel=1e-12)
    sigma = 1000 * M_VK / (5528.74 * 140.0)
    assert d["spline_sigma_MPa"] == pytest.approx(sigma, rel=1e-12) and round(sigma, 3) == 117.164
    allow = 630.0 / (1.4 * 2.65 * 1.0 * 1.4)
    assert d["spline_allowable_MPa"] == pytest.approx(allow, rel=1e-12)
    assert d["spline_margin"] == pytest.approx(allow / sigma, rel=1e-12)
    assert d["spline_margin_thesis_785MPa"] == pytest.approx(785.0 / (1.4 * 2.65 * 1.4) / sigma, rel=1e-12)
    # shaft: σ = Q·L/W_i, τ = M/W_k, σ_eq = √(σ² + 4τ²) (thesis 775.831), margin σ_T/σ_eq
    s_b = P_t * 222.0 / 169646.003
    tau = M_VK * 1e3 / 272271.363
    assert d["shaft_sigma_bending_MPa"] == pytest.approx(s_b, rel=1e-12)
    assert d["shaft_tau_MPa"] == pytest.approx(tau, rel=1e-12)
    assert d["shaft_sigma_eq_MPa"] == pytest.approx(math.hypot(s_b, 2 * tau), rel=1e-12)
    assert d["shaft_margin"] == pytest.approx(970.0 / math.hypot(s_b, 2 * tau), rel=1e-12)


def test_a_light_torque_leaves_the_slack_side_tensioned(p):
    """M = 5000 N·m: P_t = 16 755 N, the slack side keeps P_0 - P_t/(1 + z_sv/z_rab) = 31 057 - P_t·64/74 > 0, and the
    axle load is the resultant of both branches 30° apart (eq. 47)."""
    _, w = _strength(dataclasses.replace(p, sprocket_torque_Nm=5000.0))
    P_t = 2 * math.pi * 5000.0 / (15 * 0.125)
    P_sv = 31057.0 - P_t / (1 + 10 / 64)
    P_r = P_sv + P_t
    Q = math.sqrt(P_sv ** 2 + P_r ** 2 + 2 * P_sv * P_r * math.cos(math.radians(30.0)))
    assert w.derived["track_pull_P_t_N"] == pytest.approx(P_t, rel=1e-12)
    assert w.derived["sprocket_axle_load_Q_N"] == pytest.approx(Q, rel=1e-12)
    assert w.derived["shaft_sigma_bending_MPa"] == pytest.approx(Q * 222.0 / 169646.003, rel=1e-12)


def test_the_ring_root_is_rated_with_its_rim_its_fillet_and_its_thinned_tooth(p):
    """A rim of 30 mm under the ring's root (outer Ø = d_f + 60 mm, no bolts): s_R/m = 3 < 3.5, so ISO 6336-3's rim
    factor Y_B = 1.15·ln(8.324/3) = 1.1735 raises the ring's root stress over the default rim (40 mm: Y_B = 1)."""
    from propulsor.parts.final_drive.design import planetary_set
    from propulsor.parts.final_drive.strength import mesh_stresses, ring_root

    ps = planetary_set(p)
    r = ring_root(p, ps)
    assert (r.s, r.rho_fP, r.s_R) == (pytest.approx(ps.ring.s - 0.15, rel=1e-15), 2.0,
                                      pytest.approx(40.0, rel=1e-12))
    thin = dataclasses.replace(p, ring_outer_d_mm=ps.ring.d_f + 60.0, ring_bolts=0)
    assert ring_root(thin, ps).s_R == pytest.approx(30.0, rel=1e-12)
    pr0, pr = mesh_stresses(p, ps)[1], mesh_stresses(thin, ps)[1]
    assert pr0.Y_B2 == 1.0 and pr.Y_B2 == pytest.approx(1.15 * math.log(8.324 / 3.0), rel=1e-12)
    assert pr.sigma_F2_B == pytest.approx(pr0.sigma_F2_B * pr.Y_B2, rel=1e-12)
    _, w = _strength(thin)
    assert w.derived["strength_planet_ring_sigma_F_ring_method_B_MPa"] == pytest.approx(pr.sigma_F2_B, rel=1e-12)


def test_the_accuracy_grade_reaches_both_meshes(p):
    """Grade 7 instead of 6: K_v (ISO 6336-1 method B) and f_ma (f_Hβ of ISO 1328-1 grade 7: √2 times grade 6's) of
    both meshes, and the thesis set's planet–ring rating at its own centre distance in the note."""
    from propulsor.gears.iso6336 import MeshLoad, mesh_stress

    q = dataclasses.replace(_params(THESIS), accuracy_grade=7)
    dd, w = _strength(q)
    ps = dd.ps
    T1 = M_VK * OMEGA / I_SIL / 3
    v = math.pi * 0.160 * N_CARRIER * 3.5
    for tag in ("sun_planet", "planet_ring"):
        s6 = _strength(_params(THESIS))[1].derived[f"strength_{tag}_K_Hbeta"]
        assert w.derived[f"strength_{tag}_K_Hbeta"] > s6
    sp7 = mesh_stress(ps.mesh_sun_planet, ps.d_a_sun, ps.d_a_planet, 75.0,
                      MeshLoad(T1, v, 1.0, 7, pinion_torsion=True, pinion_meshes=3), E_sn=q.tooth_thinning_mm)
    assert w.derived["strength_sun_planet_face_width_required_mm"] > 0
    assert w.derived["strength_sun_planet_sigma_H_MPa"] == pytest.approx(sp7.sigma_H, rel=1e-12)
    assert w.derived["strength_sun_planet_K_v"] == pytest.approx(sp7.K_v, rel=1e-12)
    own7 = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, 75.0, MeshLoad(T1 * 20 / 16, v, 1.0, 7))
    own6 = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, 75.0, MeshLoad(T1 * 20 / 16, v, 1.0, 6))
    assert f"{own7.sigma_H:.1f}" != f"{own6.sigma_H:.1f}"
    assert f"— the thesis prints 1.205 —, σ_H = {own7.sigma_H:.1f} MPa)" in w.notes[1]
    pr7 = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, 75.0, MeshLoad(T1 * 20 / 16, v, 1.0, 7),
                      a_w=ps.a_w)
    assert w.derived["strength_planet_ring_sigma_H_MPa"] == pytest.approx(pr7.sigma_H, rel=1e-12)


def test_strength_says_what_it_does():
    class W(_Writer):
        def progress(self, *a):
            self.said = getattr(self, "said", []) + [a]

    from propulsor.parts.final_drive.design import design
    from propulsor.parts.final_drive.strength import strength

    w = W()
    strength(design(_params()), w, {})
    assert w.said == [("strength: ISO 6336 stresses, bearings, spline, shaft",)]


_DESCRIBED = {
    "S_H_static": ("", "static contact safety σ_Hmax/σ_H, σ_Hmax = 44·HRC (seed 004 ch. 4.1)"),
    "face_width_required_mm": ("mm", "least face width meeting the static S_H and S_F (root stress by ISO 6336-3 "
                                     "method B)"),
}
_DESCRIBED_ROOT = {
    "sigma_F_{g}_method_B_MPa": ("MPa", "root stress by ISO 6336-3:2006 method B (load at the outer point of single "
                                        "contact); the checks use it"),
    "sigma_F_{g}_method_C_MPa": ("MPa", "root stress by ISO 6336-3:1996 method C (load at the tip, Y_ε), for "
                                        "comparison"),
    "Y_F_method_C_{g}": ("", "form factor Y_F, load at the tip (method C)"),
    "Y_S_method_C_{g}": ("", "stress correction factor Y_S, load at the tip (method C)"),
    "S_F_{g}_static": ("", "static bending safety σ_FlimM/σ_F (method B), σ_FlimM = 2.8·σ_t (seed 004 ch. 4.1)"),
}


def test_strength_describes_its_values_in_full(st):
    _, w = st
    want = {}
    for tag, gears in (("sun_planet", ("sun", "planet")), ("planet_ring", ("planet", "ring"))):
        want.update({f"strength_{tag}_{k}": v for k, v in _DESCRIBED.items()})
        for g in gears:
            want.update({f"strength_{tag}_{k.format(g=g)}": v for k, v in _DESCRIBED_ROOT.items()})
    assert w.described == want


NOTE_STRENGTH = (
    "Strength at the design torque M_vk.max = 90687.5 N·m (seed 004 eq. 40 with t = 0.125 m; printed 90 690 N·m), sun "
    "torque M_vk·Ω/i_sil = 22399.6 N·m (thesis 22 399 N·m), 7466.5 N·m per mesh; relative pitch-line speed 2.047 m/s "
    "at 7.852 km/h. ISO 6336 (spur; K_Hβ by method C with the sun's torsional deformation f_sh under all 3 meshes' "
    "torque): sun–planet σ_H = {sH_sp} MPa (S_H static = 44·HRC/σ_H = {SH_sp}), σ_F by method B sun {sF_s} MPa "
    "(S_F static = {SF_s}), planet {sF_p} MPa (method C: {sFC_s}, {sFC_p} MPa); planet–ring σ_H = {sH_pr} MPa (the "
    "planet's flank, Z_B = 1.2194; the ring's {sH_r} MPa; S_H static = {SH_pr}), σ_F planet {sF_pp} MPa by method B "
    "(S_F static = {SF_pp}; method C {sFC_pp} MPa). These static safeties set the working stresses at the peak torque "
    "against the thesis's allowables: σ_Hmax = 44·HRC = 2596 MPa, σ_FlimM = 2.8·σ_t = 2198 MPa, σ_Fmax = "
    "σ_FlimM/S_Fm = 1256 MPa; the thesis computes no working stress. The contact formulas used here (Z_H, Z_E, Z_ε, "
    "Z_B, σ_H0: the helical ones of gears/iso6336_helical.py at β = 0) reproduce the published ISO/TR 6336-30:2017 "
    "example 1 within 1 % (σ_H0, σ_H; tests/test_iso6336_helical.py); no published root-stress example was at hand. "
    "Face width needed: sun–planet 28.5 mm, planet–ring {b_pr} mm. The ring's root by ISO 6336-3 for internal gears "
    "(substitute rack with the shaper's tip radius {rho} mm as its fillet): σ_F {sF_r} MPa by method B "
    "(S_F static = {SF_r}).")
NOTE_BEARINGS = (
    "Bearings (ISO 76): planet bearing load eq. 44 = 87334 N with r_vod = a_w = 188.643 mm (thesis: r_vod = 180 mm → "
    "91 527 N, Table 8: 92 000 N), C0 = 128700 N, S0 = 1.474 (thesis 1.39); carrier bearing 3524: eq. 49 gives C0 = "
    "1415838 N, Table 8 lists 1 398 120 N; at Table 8's load 858 508 N S0 = 1.649 (thesis 1.629; the text says "
    "R = 522 000 N for it). Spline Эв. 120 x 3.5 GOST 6033-80 (z = 34, x = -0.407): S_u = 5528.74 mm³/mm, "
    "σ = 117.164 MPa (thesis 117.164), [σ]_sm = 121.294 MPa with the hub's 630 MPa — margin 1.035; the thesis uses "
    "785 MPa: 151.136 MPa, margin 1.290 (printed 1.29). Carrier shaft: σ = 397.681 MPa, τ = 333.078 MPa, "
    "σ_eq = √(σ² + 4τ²) = 775.831 MPa (thesis 775.831, printed as √(σ²·4τ²)), margin 1.250 (thesis 1.25).")


def test_strength_notes_in_full(st):
    _, w = st
    assert w.notes == [
        NOTE_STRENGTH.format(sH_sp="1689.7", SH_sp="1.536", sF_s="440.4", SF_s="4.991", sF_p="440.4", sFC_s="445.9",
                             sFC_p="443.5", sH_pr="938.8", sH_r="769.9", SH_pr="2.765", sF_pp="363.2", SF_pp="6.052",
                             sFC_pp="374.2", b_pr="34.5", rho="2", sF_r="561.9", SF_r="3.912"),
        NOTE_BEARINGS]


def test_strength_notes_of_the_thesis_set_rate_the_ring_mesh_at_the_carriers_centre_distance():
    """x_ring = 1.417 as printed: the planet-ring mesh runs at the sun-planet a_w = 188.643 mm, not the 187.997 mm of
    its shifts; the note gives both ratings (Z_B 1.2194 there, 1.2054 at its own a_w: the thesis prints 1.205)."""
    _, w = _strength(_params(THESIS))
    assert w.notes[0] == NOTE_STRENGTH.format(
        sH_sp="1726.9", SH_sp="1.503", sF_s="432.3", SF_s="5.085", sF_p="461.1", sFC_s="437.7", sFC_p="464.4",
        sH_pr="958.1", sH_r="785.7", SH_pr="2.710", sF_pp="371.6", SF_pp="5.916", sFC_pp="387.6", b_pr="44.0",
        rho="1", sF_r="707.5", SF_r="3.107")
    assert w.notes[1] == (
        "The planet–ring mesh is rated at the centre distance the carrier makes, a_w = 188.643 mm (α_w = 26.2802°, "
        "ε_α = 1.3979, Z_H = 2.1417, Z_B = 1.2194, σ_H = 958.1 MPa), not at the 187.997 mm of its shifts, which the "
        "thesis uses (there: α_w = 25.8788°, ε_α = 1.3481, Z_H = 2.1608, Z_B = 1.2054 — the thesis prints 1.205 —, "
        "σ_H = 964.7 MPa). The set is not coaxial: the planets sit on the sun–planet centre distance, so the "
        "planet–ring teeth run 0.646 mm deeper than their shifts provide for (the overlap the sweep reports).")
    assert w.notes[2] == NOTE_BEARINGS and len(w.notes) == 3


# ---- fatigue.py: ISO 6336-2/-3 fatigue for the service life, the factor table -------------------------------------
def _fatigue(p):
    from propulsor.parts.final_drive.design import design
    from propulsor.parts.final_drive.fatigue import fatigue

    dd = design(p)
    w = _Writer()
    fatigue(dd, w, {})
    return dd, w


def _golden():
    import json

    return json.loads((ROOT / "tests" / "golden" / "final_drive_fatigue.json").read_text("utf-8"))


def test_fatigue_factor_table_in_full(p):
    """Every row of tables/strength_factors.csv: mesh, calculation, gear, factor, value, unit, method, life point,
    clause and basis, as written for the part file (tests/golden/final_drive_fatigue.json; inf written as null)."""
    _, w = _fatigue(p)
    g = _golden()
    cols, rows = w.tables["strength_factors"]
    assert cols == g["columns"] == ["mesh", "calculation", "gear", "factor", "value", "unit", "method", "N_L",
                                    "source", "basis"]
    assert len(rows) == len(g["rows"]) == 226
    for r, x in zip(rows, g["rows"]):
        assert r[:4] + r[5:] == x[:4] + x[5:], r[:4]
        assert r[4] == (math.inf if x[4] is None else pytest.approx(x[4], rel=1e-9)), r[:4]


def test_fatigue_notes_in_full(p):
    _, w = _fatigue(p)
    assert w.notes == _golden()["notes"]


def test_fatigue_checks_in_full(p):
    _, w = _fatigue(p)
    g = _golden()["checks"]
    assert [[c.name, c.limit, c.message] for c in w.checks] == [[x[0], x[2], x[3]] for x in g]
    assert [c.unit for c in w.checks] == [""] * 8                 # safeties: ratios, no unit
    assert [c.value for c in w.checks] == pytest.approx([x[1] for x in g], rel=1e-9)
    d = w.derived
    for c in w.checks:
        tag, what = c.name.split(".")
        assert c.value == d[f"{tag}_{what}"] and c.passed == (c.value >= c.limit)
        assert c.limit == (1.0 if what.startswith("S_H") else 1.4)


def test_fatigue_safety_is_the_limit_over_the_stress_and_the_load_cycles_follow_the_carrier(p):
    dd, w = _fatigue(p)
    d = w.derived
    by = {(r[0], r[1], r[2], r[3]): r[4] for r in w.tables["strength_factors"][1]}
    # load cycles per hour: the sun's relative speed n_c·(i - 1) past 3 planets; a planet tooth once per turn of the
    # planet, n_c·(i - 1)·16/20; a ring tooth by each of 3 planets once per carrier turn
    n_s = N_CARRIER * 3.5
    assert d["load_cycles_per_hour_sun"] == pytest.approx(3600 * n_s * 3, rel=1e-12)
    assert d["load_cycles_per_hour_planet"] == pytest.approx(3600 * n_s * 16 / 20, rel=1e-12)
    assert d["load_cycles_per_hour_ring"] == pytest.approx(3600 * N_CARRIER * 3, rel=1e-12)
    for mesh, gears in (("sun_planet", ("sun", "planet")), ("planet_ring", ("planet", "ring"))):
        for g in gears:
            cph = d[f"load_cycles_per_hour_{g}"]
            assert by[(mesh, "pitting", g, "N_L")] == pytest.approx(cph * 100.0, rel=1e-12)
            assert by[(mesh, "bending", g, "N_L")] == pytest.approx(cph * 100.0, rel=1e-12)
            S_H = by[(mesh, "pitting", g, "sigma_HG")] / by[(mesh, "pitting", g, "sigma_H")]
            assert d[f"strength_{mesh}_S_H_pitting_{g}"] == pytest.approx(S_H, rel=1e-12)
            S_F = by[(mesh, "bending", g, "sigma_FG")] / by[(mesh, "bending", g, "sigma_F")]
            assert d[f"strength_{mesh}_S_F_fatigue_{g}"] == pytest.approx(S_F, rel=1e-12)
            assert by[(mesh, "bending", g, "S_F_static")] == pytest.approx(
                2198.0 / by[(mesh, "bending", g, "sigma_F")], rel=1e-12)
            assert by[(mesh, "pitting", g, "S_H_static")] == pytest.approx(
                2596.0 / by[(mesh, "pitting", g, "sigma_H")], rel=1e-12)
            # the planet is an idler: its root is bent both ways (Y_M = 0.7)
            assert by[(mesh, "bending", g, "Y_M")] == (0.7 if g == "planet" else 1.0)
    # the pitting stresses: the pinion's flank Z_B·σ_H0·√K, the wheel's Z_D·σ_H0·√K
    for mesh in ("sun_planet", "planet_ring"):
        K = math.sqrt(by[(mesh, "pitting", "", "K_A")] * by[(mesh, "pitting", "", "K_v")]
                      * by[(mesh, "pitting", "", "K_Hbeta")] * by[(mesh, "pitting", "", "K_Halpha")])
        s0 = by[(mesh, "pitting", "", "sigma_H0")]
        g1, g2 = ("sun", "planet") if mesh == "sun_planet" else ("planet", "ring")
        assert by[(mesh, "pitting", g1, "sigma_H")] == pytest.approx(by[(mesh, "pitting", "", "Z_B")] * s0 * K,
                                                                     rel=1e-12)
        assert by[(mesh, "pitting", g2, "sigma_H")] == pytest.approx(by[(mesh, "pitting", "", "Z_D")] * s0 * K,
                                                                     rel=1e-12)


@pytest.mark.parametrize("key, S_min", [
    ("strength_sun_planet_pitting_life_planet_h", ("strength_sun_planet_S_H_pitting_planet", 1.0)),
    ("strength_planet_ring_bending_life_planet_h", ("strength_planet_ring_S_F_fatigue_planet", 1.4)),
    ("strength_planet_ring_bending_life_ring_h", ("strength_planet_ring_S_F_fatigue_ring", 1.4)),
])
def test_each_finite_fatigue_life_is_where_its_safety_meets_the_minimum(p, key, S_min):
    _, w = _fatigue(p)
    hours = w.derived[key]
    assert 100.0 < hours < 1e6
    _, w = _fatigue(dataclasses.replace(p, service_life_h=hours))
    assert w.derived[S_min[0]] == pytest.approx(S_min[1], rel=1e-9)


def test_a_required_bending_safety_moves_the_bending_life(p):
    """S_Fmin = 1.6: the ring's root (S_F = 1.682 at 100 h) reaches 1.6 sooner than 1.4 (3126 h); its check's limit
    is 1.6."""
    _, w = _fatigue(dataclasses.replace(p, bending_fatigue_safety_S_Fmin=1.6))
    life = w.derived["strength_planet_ring_bending_life_ring_h"]
    assert 100.0 < life < 3126.0
    c = {c.name: c for c in w.checks}["strength_planet_ring.S_F_fatigue_ring"]
    assert c.limit == 1.6 and c.passed
    _, w = _fatigue(dataclasses.replace(p, bending_fatigue_safety_S_Fmin=1.6, service_life_h=life))
    assert w.derived["strength_planet_ring_S_F_fatigue_ring"] == pytest.approx(1.6, rel=1e-9)


def test_fatigue_describes_its_values_in_full(p):
    _, w = _fatigue(p)
    want = {}
    for mesh, g in (("sun_planet", "sun"), ("sun_planet", "planet"), ("planet_ring", "planet"), ("planet_ring", "ring")):
        want[f"strength_{mesh}_S_H_pitting_{g}"] = ("", f"pitting fatigue safety σ_HG/σ_H of the {g}'s flank "
                                                        f"(ISO 6336-2)")
        want[f"strength_{mesh}_pitting_life_{g}_h"] = ("h", f"running time at the design torque after which the {g}'s "
                                                            f"pitting safety falls to S_Hmin")
    for mesh, g in (("sun_planet", "sun"), ("sun_planet", "planet"), ("planet_ring", "planet"), ("planet_ring", "ring")):
        want[f"strength_{mesh}_S_F_fatigue_{g}"] = ("", f"bending fatigue safety σ_FG/σ_F of the {g}'s root "
                                                        f"(ISO 6336-3 method B)")
        want[f"strength_{mesh}_bending_life_{g}_h"] = ("h", f"running time at the design torque after which the {g}'s "
                                                            f"bending safety falls to S_Fmin")
    for g in ("sun", "planet", "ring"):
        want[f"load_cycles_per_hour_{g}"] = ("1/h", f"load cycles of a {g} tooth per hour at the design speed")
    assert w.described == want and list(w.described) == list(want)


def test_fatigue_says_what_it_does(p):
    from propulsor.parts.final_drive.design import design
    from propulsor.parts.final_drive.fatigue import fatigue

    class W(_Writer):
        def progress(self, *a):
            self.said = getattr(self, "said", []) + [a]

    w = W()
    fatigue(design(p), w, {})
    assert w.said == [("strength: ISO 6336 fatigue safeties and factor table",)]


@pytest.mark.parametrize("rho_star, q_s, outside", [(0.135, 8.348, True), (0.145, 7.760, False)])
def test_fatigue_table_says_when_q_s_leaves_the_formulas_range(p, rho_star, q_s, outside):
    """ISO 6336-3's Y_S formula holds for 1 <= q_s < 8.  The ring's root fillet is the shaper's tip radius: 1.35 mm
    makes q_s = s_Fn/(2·ρ_F) = 8.35 (the basis says so), 1.45 mm 7.76 (it does not)."""
    _, w = _fatigue(dataclasses.replace(p, shaper_tip_radius_star=rho_star))
    rows = {(r[0], r[1], r[2], r[3]): r for r in w.tables["strength_factors"][1]}
    got = rows[("planet_ring", "bending", "ring", "q_s")][4]
    assert round(got, 3) == q_s
    basis = rows[("planet_ring", "bending", "ring", "Y_S")][9]
    rho = rows[("planet_ring", "bending", "ring", "Y_S")][9].split("ρ_F = ")[1].split(" mm")[0]
    assert basis == f"method B, ρ_F = {rho} mm" + (f"; q_s = {got:.2f} outside the formula's 1 <= q_s < 8" if outside
                                                  else "")
    for g in ("sun", "planet"):            # the rack's fillet: q_s = 2.5 ... 2.6, inside
        assert "outside" not in rows[("sun_planet", "bending", g, "Y_S")][9]


def test_fatigue_table_gives_the_ring_its_rim_factor_and_the_planet_none(p):
    """A 30 mm rim under the ring's root (s_R/m = 3 < 3.5): Y_B = 1.15·ln(8.324/3) for the ring; the planet in the same
    mesh, an external gear with a solid rim, keeps Y_B = 1."""
    from propulsor.parts.final_drive.design import planetary_set

    d_f = planetary_set(p).ring.d_f
    _, w = _fatigue(dataclasses.replace(p, ring_outer_d_mm=d_f + 60.0, ring_bolts=0))
    rows = {(r[0], r[1], r[2], r[3]): r for r in w.tables["strength_factors"][1]}
    ring, planet = rows[("planet_ring", "bending", "ring", "Y_B")], rows[("planet_ring", "bending", "planet", "Y_B")]
    assert ring[4] == pytest.approx(1.15 * math.log(8.324 / 3.0), rel=1e-12)
    assert ring[9] == "internal gear: the rim under the root (1 from s_R >= 3.5·m)"
    assert planet[4] == 1.0 and planet[9] == "solid rim"
    assert rows[("sun_planet", "bending", "sun", "Y_B")][4] == 1.0


def test_fatigue_number_formats_at_their_limits():
    from propulsor.parts.final_drive.fatigue import _fmt, _hours, _life

    assert _fmt(math.inf) == "inf"
    assert [_fmt(x) for x in (0.000999, 0.001, -0.0005)] == ["0.000999", "0.0010", "-0.0005"]
    assert [_fmt(x) for x in (9.99994, 10.0, -5.0, 99999.99, 1e5, 4.397e6)] == [
        "9.9999", "10.00", "-5.0000", "99999.99", "1e+05", "4.397e+06"]
    assert _hours(math.inf, 10.0) == math.inf and _hours(1e6, 0.0) == math.inf and _hours(1e6, 1e3) == 1e3
    assert _hours(1e6, 0.5) == 2e6 and _hours(1e6, 1.0) == 1e6      # a slow gear: fewer than 1 cycle an hour
    assert _life(math.inf, "S_Hmin") == "never falls to S_Hmin: the life factor's floor 0.85 at 1e10 cycles keeps it above"
    assert _life(242.48549, "S_Fmin") == "falls to S_Fmin after 242.5 h"


# ---- carrier.py: the carrier's layout, solid and pin sweep --------------------------------------------------------
def _design(p):
    from propulsor.parts.final_drive.design import design

    return design(p)


def test_carrier_layout_and_values(p):
    """Cheek of radius a_w + d_pin, 40 mm thick, 5 mm below the gears; pins to the ring's top face (80 mm); journal for
    bearings 3524 (58 mm) and 224 (40 mm) with a 10 mm spacer; the spline's 140 mm below it."""
    from propulsor.parts.final_drive.carrier import carrier_layout, carrier_values

    dd = _design(p)
    a_w = dd.ps.a_w
    assert carrier_layout(dd) == {"R_cheek": pytest.approx(a_w + 55.0, rel=1e-15), "r_pin": 27.5, "z_pin_top": 80.0,
                                  "z_cheek_top": -5.0, "z_cheek_bot": -45.0, "z_journal_bot": -153.0,
                                  "z_spline_bot": -293.0}
    w = _Writer()
    carrier_values(dd, w, {})
    assert w.derived == {"carrier_cheek_radius_mm": pytest.approx(a_w + 55.0, rel=1e-15), "carrier_pin_d_mm": 55.0,
                         "carrier_journal_d_mm": 120.0, "carrier_spline_length_mm": 140.0,
                         "carrier_length_mm": 80.0 + 293.0}


def test_carrier_pins_sit_on_the_operating_centre_distance_a_third_of_a_turn_apart(p):
    from propulsor.parts.final_drive.carrier import _pin_centres

    dd = _design(p)
    _, centres = _pin_centres(dd)
    a_w = dd.ps.a_w
    assert len(centres) == 3 and all(type(v) is float for c in centres for v in c)
    for k, (x, y) in enumerate(centres):
        assert x == pytest.approx(a_w * math.cos(2 * math.pi * k / 3), abs=1e-9)
        assert y == pytest.approx(a_w * math.sin(2 * math.pi * k / 3), abs=1e-9)


@pytest.mark.parametrize("bore", [55.0, 40.0])
def test_carrier_refuses_planet_bores_not_wider_than_its_pins(p, bore):
    from propulsor.errors import InputError
    from propulsor.parts.final_drive.carrier import carrier_solid

    dd = _design(p)
    dd = dataclasses.replace(dd, p=dataclasses.replace(dd.p, planet_bore_mm=bore))
    with pytest.raises(InputError) as e:
        carrier_solid(dd)
    assert str(e.value) == str(InputError("planet_bore_mm", bore, "must exceed the planet pin Ø 55.0 mm"))


def test_carrier_solid_is_cheek_pins_journal_and_spline(p):
    """The carrier written by the step: its volume against its parts computed apart (the cheek, three pins above it,
    the journal below it, the spline section's polygon area over 140 mm), one solid of genus 0."""
    import numpy as np
    from propulsor.geometry.involute_spline import InvoluteSpline
    from propulsor.parts.final_drive.carrier import carrier

    class W(_Writer):
        def add_solid(self, name, solid, expected_genus=None):
            self.solids = getattr(self, "solids", []) + [(name, solid, expected_genus)]

    dd = _design(p)
    w, built = W(), {}
    carrier(dd, w, built)
    ((name, solid, genus),) = w.solids
    assert name == "carrier" and genus == 0 and built == {"solids": {"carrier": solid}}
    R = dd.ps.a_w + 55.0
    poly = InvoluteSpline(120.0, 3.5, 34).shaft_loop().polyline(1e-4)
    area = 0.5 * abs(np.dot(poly[:, 0], np.roll(poly[:, 1], 1)) - np.dot(poly[:, 1], np.roll(poly[:, 0], 1)))
    expected = (math.pi * R ** 2 * 40.0 + 3 * math.pi * 27.5 ** 2 * (80.0 + 5.0) + math.pi * 60.0 ** 2 * (58 + 40 + 10)
                + area * 140.0)
    assert solid.Volume() == pytest.approx(expected, rel=1e-5)
    bb = solid.BoundingBox()
    assert (bb.zmin, bb.zmax) == (pytest.approx(-293.0, abs=1e-3), pytest.approx(80.0, abs=1e-3))
    assert (bb.xmax, bb.ymin) == (pytest.approx(R, abs=1e-2), pytest.approx(-R, abs=1e-2))


def test_carrier_says_what_it_builds(p, monkeypatch):
    from propulsor.parts.final_drive import carrier as car

    monkeypatch.setattr(car, "carrier_solid", lambda dd: "the solid")      # built and measured above

    class W(_Writer):
        def progress(self, *a):
            self.said = getattr(self, "said", []) + [a]

        def add_solid(self, *a, **k):
            pass

    w = W()
    car.carrier(_design(p), w, {})
    assert w.said == [("carrier: cheek, planet pins, bearing journal, spline Эв. 120 × 3.5 × 34",)]


def test_carrier_pin_sweep_turns_the_pins_in_the_planet_bores(p, monkeypatch):
    """One carrier turn in 18 steps (0.05 steps a degree as the policy): the pin Ø 55 in the planet's bore Ø 110
    clears by the bearing's radial space 27.5 mm less the polylines' chord error, and never overlaps; the note, the
    values and the checks of each planet."""
    from propulsor import policy
    from propulsor.parts.final_drive.carrier import pin_sweep_results, start_pin_sweep

    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    monkeypatch.setattr(policy, "CARRIER_PIN_SWEEP_STEPS_PER_DEG", 0.0501)   # ceil(360·0.0501) = 19 steps
    dd = _design(p)
    w, built = _Writer(), {}
    start_pin_sweep(dd, w, built)
    pin_sweep_results(dd, w, built)
    psi, res = built["pin_sweeps"]
    assert "pending_pin_sweep" not in built
    assert len(psi) == 19 and psi[1] == pytest.approx(2 * math.pi / 19, rel=1e-15) and psi[0] == 0.0
    assert [r.name for r in res] == ["carrier_pins_planet1", "carrier_pins_planet2", "carrier_pins_planet3"]
    for k in (1, 2, 3):
        clear = w.derived[f"carrier_pins_planet{k}_min_clearance_mm"]
        assert 27.49 < clear < 27.5 and type(clear) is float
        assert w.derived[f"carrier_pins_planet{k}_max_overlap_mm2"] == 0.0
    assert [c.name for c in w.checks] == [f"carrier_pins_planet{k}.{q}" for k in (1, 2, 3)
                                          for q in ("overlap_area", "min_clearance")]
    assert all(c.passed for c in w.checks)
    assert [c.limit for c in w.checks if c.name.endswith("min_clearance")] == [0.0] * 3   # touching is the limit
    least = min(w.derived[f"carrier_pins_planet{k}_min_clearance_mm"] for k in (1, 2, 3))
    assert w.notes == [
        f"Carrier: cheek Ø {2 * (dd.ps.a_w + 55.0):.1f} mm with 3 pins Ø 55 mm (planet bearing bore, Table 8), journal "
        f"Ø 120 mm for bearings 3524 and 224, spline Эв. 120 × 3.5 × 34 over 140 mm. Swept over one carrier turn "
        f"(19 steps) against every planet: max overlap 0 mm², least clearance {least:.4f} mm (pin to planet bore: "
        f"the bearing's radial space)."]
    assert w.notes[0].startswith("Carrier: cheek Ø 487.3 mm") and "least clearance 27.499" in w.notes[0]


def test_carrier_pin_sweep_steps_and_segments(p):
    """An explicit step count wins over the policy's; the planet's outline is cut in segments of at most 0.05 m."""
    from propulsor.parts.final_drive.carrier import pin_sweep

    dd = _design(p)
    psi, res = pin_sweep(dd, 0.05)
    assert len(psi) == 18 and psi[-1] == pytest.approx(2 * math.pi * 17 / 18, rel=1e-15)
    for r in res:
        assert float(r.clearance.min()) == pytest.approx(27.499003933, abs=1e-6)
        assert float(r.overlap_area.max()) == 0.0


def test_carrier_pin_sweep_finds_pins_wider_than_the_planet_bores(p):
    """Planet bores of Ø 50 mm on the Ø 55 pins (the solid refuses them; the sweep measures them): at every step each
    pin overlaps its planet by the ring between the two circles, π·(27.5² − 25²) = 412.3 mm², and the checks fail."""
    from propulsor.parts.final_drive.carrier import pin_sweep

    dd = _design(dataclasses.replace(p, planet_bore_mm=50.0))
    psi, res = pin_sweep(dd, 0.05)
    ring = math.pi * (27.5 ** 2 - 25.0 ** 2)
    for r in res:
        assert r.overlap_area.min() == pytest.approx(ring, rel=1e-3) and r.overlap_area.max() == pytest.approx(ring, rel=1e-3)
        assert r.clearance.max() < 0
        assert not any(c.passed for c in r.checks())


# ---- traction.py: the traction characteristic in the final drive's build ------------------------------------------
class _PlotWriter(_Writer):
    def add_plot(self, name, fig):
        self.plots = getattr(self, "plots", []) + [(name, fig)]


def _traction(p):
    from propulsor.parts.final_drive.traction import traction

    dd = _design(p)
    w = _PlotWriter()
    traction(dd, w, {})
    return dd, w


def test_traction_not_drawn_for_a_standing_vehicle(p):
    _, w = _traction(dataclasses.replace(p, design_speed_kmh=0.0))
    assert w.notes == ["Traction characteristic (seed 004 ch. 5.1.3) not drawn: design_speed_kmh = 0 gives no lowest "
                       "gear."]
    assert w.tables == {} and w.derived == {} and w.checks == [] and not hasattr(w, "plots")


def test_traction_table_values_checks_and_note_in_full(p):
    from propulsor.laws import traction as tr

    _, w = _traction(p)
    v = dataclasses.replace(tr.VEHICLE_004, z=15, t=0.125)
    eta = tr.transmission_efficiency([(1, 0, 0), (0, 0, 1), (0, 0, 0), (1, 0, 1), (0, 0, 1), (0, 0, 1)])
    c = tr.traction_characteristic(v, 800.0, 7.852, 4, eta)
    cols, rows = w.tables["traction_characteristic"]
    assert cols == ["gear", "engine_mode", "n_k_rpm", "N_eob_kW", "U_tr", "V_kmh", "N_str_kW", "N_cr_kW", "f_g"]
    assert rows == [[j + 1, k + 1, c.n_k[k], c.N_eob[k], c.U[j], c.V[j][k], c.N_str[j][k], c.N_cr[j][k], c.f_g[j][k]]
                    for j in range(4) for k in range(8)]
    d = w.derived
    assert d["traction_eta_tr"] == eta and round(eta, 3) == 0.932
    assert d["traction_q_ut"] == pytest.approx((50.0 / 7.852 / 1.25) ** (1 / 3), rel=1e-12)   # eq. 66 (q^3 = V_max/V_min/K_g)
    assert round(d["traction_q_ut"], 3) == 1.721
    assert [round(d[f"traction_gear{j}_U_tr"], 3) for j in (1, 2, 3, 4)] == [28.655, 13.323, 7.743, 4.5]
    assert [round(d[f"traction_gear{j}_V_top_kmh"], 3) for j in (1, 2, 3, 4)] == [7.852, 16.888, 29.059, 50.0]
    for j in (1, 2, 3, 4):
        assert d[f"traction_gear{j}_f_g_max"] == max(c.f_g[j - 1])
    assert len(d) == 2 + 3 * 4
    f_c = 0.08 * math.cos(math.radians(30)) + math.sin(math.radians(30))      # eq. 64 on the steepest slope
    air = 0.6 * 10.293 * (50 / 3.6) ** 2 / (50000 * 9.81)                    # eq. 57 at V_max
    top = c.f_g[3][6]                                                         # Table 10 mode 7: n = n_N
    assert c.n_k[6] == v.n_N
    got = [(x.name, x.value, x.limit, x.message) for x in w.checks]
    assert got == [
        ("traction.first_gear_slope", max(c.f_g[0]), pytest.approx(f_c, rel=1e-12),
         "largest f_g of gear 1 (0.600) against f_c = f·cos α + sin α = 0.569 of the steepest slope (seed 004 eq. 64: "
         "f = 0.08, α = 30°)"),
        ("traction.top_gear_road", top, pytest.approx(0.015 + 0.025 + air, rel=1e-12),
         "f_g of the top gear at n_N (0.0469) against the design road f_gr + i = 0.04 plus air drag 0.0024 at "
         "V_max = 50 km/h (seed 004 eq. 57)")]
    assert w.notes == [
        "Traction characteristic (seed 004 ch. 5.1.2–5.1.3, Fig. 18; table traction_characteristic, plot "
        "traction_characteristic): 4 gears from V_min = 7.852 km/h, K_g = 1.25, q_ut = 1.7207 (thesis 1.721). Top "
        "speeds 7.852, 16.888, 29.059, 50.000 km/h (thesis 7.852, 16.888, 29.058, 50; its 29.058 follows from eq. 65's "
        "unrounded V_min = 7.85151, ours 29.059 from the printed 7.852); ratios eq. 69 U_tr = 28.655, 13.323, 7.743, "
        "4.500 (thesis 28.655, —, 7.743, 4.5: the second is lost in the print). Ahead of this final drive (i = 4.5) "
        "the gearbox ratios are 6.368, 2.961, 1.721, 1.000. Every Table 10 engine point in every gear: transmission "
        "losses eq. 70 (gears 1–2) / eq. 71 (3–4) with the gearbox input at engine speed, running gear eq. 72, "
        "η_tr = 0.932, η_r = 0.94; the thesis prints no f_g values (only Fig. 18). Verdict: gear 1 pulls f_g = 0.600 "
        "at most (near the torque peak; 0.528 at rated power, on which eq. 65 sized V_min), above the 0.569 of a 30° "
        "slope on f = 0.08 and above the adhesion f = 0.57 of eq. 40 — the tracks slip before the engine stalls, so "
        "the design torque is the adhesion-limited one; the top gear pulls 0.0469 at V_max against 0.0424 needed. "
        "Resistance lines f_c = f·cos α + sin α for f = 0.03, 0.06, 0.09, 0.12, 0.15 (the thesis gives only "
        "0.03 … 0.15) and α = 0 … 30° by 5°."]


@pytest.mark.parametrize("V_min, passed", [(8.0, True), (9.0, False)])
def test_traction_first_gear_check_on_both_sides_of_the_slope(p, V_min, passed):
    """Gear 1's largest pull falls as V_min rises (the same engine over a longer first gear): 8 km/h still climbs the
    30° slope on f = 0.08 (f_c = 0.569), 9 km/h does not; the top gear's pull at V_max is the same."""
    _, w = _traction(dataclasses.replace(p, design_speed_kmh=V_min))
    c1, c2 = w.checks
    assert c1.name == "traction.first_gear_slope" and c1.passed is passed and (c1.value >= c1.limit) is passed
    assert c1.limit == pytest.approx(0.08 * math.cos(math.radians(30)) + 0.5, rel=1e-12)
    assert c2.passed and c2.value == pytest.approx(0.04687601045403122, rel=1e-9)


def test_traction_is_drawn_for_any_moving_vehicle_and_says_so(p):
    """0.5 km/h is slow, not standing: the characteristic is drawn (q_ut = (50/0.5/1.25)^(1/3)); the progress line."""
    from propulsor.parts.final_drive.traction import traction

    class W(_PlotWriter):
        def progress(self, *a):
            self.said = getattr(self, "said", []) + [a]

    w = W()
    traction(_design(dataclasses.replace(p, design_speed_kmh=0.5)), w, {})
    assert w.said == [("traction characteristic (seed 004 ch. 5.1.2-5.1.3)",)]
    assert w.derived["traction_q_ut"] == pytest.approx((50.0 / 0.5 / 1.25) ** (1 / 3), rel=1e-12)
    assert [c.unit for c in w.checks] == ["", ""] and len(w.plots) == 1


@pytest.mark.parametrize("changes", [{"sprocket_teeth": 30}, {"track_pitch_mm": 250.0}])
def test_traction_ratios_follow_the_sprocket(p, changes):
    """The ratio eq. 69 takes the engine to the track over the sprocket's radius z·t/(2π): twice the teeth or twice the
    pitch needs twice the ratio for the same speeds (and the same pulls)."""
    _, w0 = _traction(p)
    _, w = _traction(dataclasses.replace(p, **changes))
    for j in (1, 2, 3, 4):
        assert w.derived[f"traction_gear{j}_U_tr"] == pytest.approx(2 * w0.derived[f"traction_gear{j}_U_tr"], rel=1e-12)
        assert w.derived[f"traction_gear{j}_f_g_max"] == pytest.approx(w0.derived[f"traction_gear{j}_f_g_max"],
                                                                        rel=1e-12)


def test_traction_plot_draws_without_a_warning(p):
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _, w = _traction(p)
    assert len(w.plots) == 1


def test_traction_plot_as_drawn(p):
    import numpy as np

    from propulsor.laws import traction as tr

    _, w = _traction(p)
    ((name, fig),) = w.plots
    assert name == "traction_characteristic"
    ax, axr, axn = fig.axes
    assert tuple(round(x, 3) for x in fig.get_size_inches()) == (9.0, 6.5)
    assert [round(x, 4) for x in ax.get_position().bounds] == [0.08, 0.4111, 0.6065, 0.5389]
    assert [round(x, 4) for x in axr.get_position().bounds] == [0.7374, 0.4111, 0.2426, 0.5389]
    assert [round(x, 4) for x in axn.get_position().bounds] == [0.08, 0.08, 0.6065, 0.2449]
    assert ax.get_title() == "Traction characteristic, 50 t carrier (seed 004 Fig. 18)"
    assert ax.title.get_fontsize() == 9 and axr.title.get_fontsize() == 9
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("", "specific pull f_g")
    assert (axr.get_title(), axr.get_xlabel()) == ("f_c = f·cos α + sin α", "slope α, °")
    assert (axn.get_xlabel(), axn.get_ylabel()) == ("vehicle speed V, km/h", "engine speed n, rpm")
    assert ax.get_ylim()[0] == 0.0
    assert axr.get_shared_y_axes().joined(ax, axr) and axn.get_shared_x_axes().joined(ax, axn)
    assert [ln.get_label() for ln in ax.lines] == ["gear 1, U_tr = 28.655", "gear 2, U_tr = 13.323",
                                                  "gear 3, U_tr = 7.743", "gear 4, U_tr = 4.500"]
    assert [ln.get_label() for ln in axn.lines] == ["gear 1", "gear 2", "gear 3", "gear 4"]
    assert [ln.get_label() for ln in axr.lines] == ["f = 0.03", "f = 0.06", "f = 0.09", "f = 0.12", "f = 0.15"]
    assert {(ln.get_marker(), ln.get_markersize(), ln.get_linewidth()) for ln in ax.lines} == {("o", 3, 1.2)}
    assert {(ln.get_marker(), ln.get_markersize(), ln.get_linewidth()) for ln in axn.lines} == {("o", 3, 1.0)}
    assert {(ln.get_marker(), ln.get_markersize(), ln.get_linewidth()) for ln in axr.lines} == {(".", 3, 0.9)}
    for a in (ax, axr, axn):
        grid = a.xaxis.get_gridlines()[0]
        assert grid.get_visible() and grid.get_linewidth() == 0.4 and grid.get_alpha() == 0.6
    assert [t.get_fontsize() for t in ax.get_legend().get_texts()] == [7] * 4
    assert [t.get_fontsize() for t in axr.get_legend().get_texts()] == [6] * 5
    assert list(axr.get_xticks()) == [0, 10, 20, 30]
    for f, ln in zip(tr.RESISTANCE_F, axr.lines):
        x, y = ln.get_data()
        assert list(x) == pytest.approx(tr.RESISTANCE_ALPHA_DEG, abs=1e-12)
        assert list(y) == pytest.approx([f * math.cos(math.radians(a)) + math.sin(math.radians(a))
                                         for a in tr.RESISTANCE_ALPHA_DEG], rel=1e-12)
    rows = w.tables["traction_characteristic"][1]
    for j, ln in enumerate(ax.lines):
        x, y = ln.get_data()
        assert list(x) == [r[5] for r in rows if r[0] == j + 1] and list(y) == [r[8] for r in rows if r[0] == j + 1]
        assert list(axn.lines[j].get_ydata()) == [r[2] for r in rows if r[0] == j + 1]
        assert list(axn.lines[j].get_xdata()) == [r[5] for r in rows if r[0] == j + 1]
    assert np.isfinite(ax.get_ylim()[1])


# ---- design.py: the set, its refusals, the outlines with their bores and bolt holes --------------------------------
def _refused(p, param, value, limit, **changes):
    from propulsor.errors import InputError
    from propulsor.parts.final_drive.design import design

    with pytest.raises(InputError) as e:
        design(dataclasses.replace(p, **changes))
    assert (e.value.parameter, e.value.value, e.value.limit) == (param, value, limit)


def test_planetary_set_of_the_part_file_is_coaxial(p):
    from propulsor.parts.final_drive.design import planetary_set

    ps = planetary_set(p)
    assert (ps.z_sun, ps.z_planet, ps.z_ring, ps.m, ps.x_sun, ps.x_planet, ps.n_planets) == (16, 20, 56, 10.0, 0.5,
                                                                                             0.5, 3)
    assert (ps.z0, ps.x0, ps.b_sun, ps.b_planet, ps.b_ring) == (14, 0.04, 80.0, 80.0, 80.0)
    assert ps.x_ring == pytest.approx(1.5, abs=1e-12) and abs(ps.coaxiality_mismatch) < 1e-9
    ps = planetary_set(dataclasses.replace(p, ring_shift_for_coaxiality=False))
    assert ps.x_ring == 1.417 and round(ps.mesh_planet_ring.a_w, 3) == 187.997


def test_design_refuses_planets_that_cannot_be_assembled_or_collide(p):
    _refused(p, "n_planets", 5, "assembly condition (seed 004 eq. 31): (z_sun + z_ring)/n_planets = 72/5 must be "
                                "whole", n_planets=5)
    from propulsor.parts.final_drive.design import planetary_set

    ps6 = planetary_set(dataclasses.replace(p, n_planets=6))
    assert ps6.assembly_ok and ps6.neighbour_gap < 0
    _refused(p, "n_planets", 6, f"neighbour condition (seed 004 eq. 30): planet tip circles overlap by "
                                f"{-ps6.neighbour_gap:.3f} mm at a_w = 188.643 mm", n_planets=6)
    assert f"{-ps6.neighbour_gap:.3f}" == f"{ps6.d_a_planet - 2 * ps6.a_w * math.sin(math.pi / 6):.3f}"


def test_design_takes_one_planet_and_four(p):
    from propulsor.parts.final_drive.design import design

    for n in (1, 4):                          # one planet has no neighbour; (16 + 56)/4 = 18
        assert design(dataclasses.replace(p, n_planets=n)).ps.n_planets == n


@pytest.mark.parametrize("field, limit_mm, text", [
    ("sun_bore_mm", 125.0, "must be < d_f − 2m = 125.000 mm"),         # d_f = 145 mm, m = 10
    ("planet_bore_mm", 165.0, "must be < d_f − 2m = 165.000 mm"),      # d_f = 185 mm
])
def test_design_refuses_bores_into_the_teeth_on_both_sides_of_the_limit(p, field, limit_mm, text):
    from propulsor.parts.final_drive.design import design

    _refused(p, field, limit_mm, text, **{field: limit_mm})
    _refused(p, field, limit_mm + 1.0, text, **{field: limit_mm + 1.0})
    dd = design(dataclasses.replace(p, **{field: limit_mm - 0.5, "sun_keyway": False}))
    assert dd.outlines is not None


def test_design_refuses_a_ring_rim_too_thin_for_its_bolts(p):
    from propulsor.parts.final_drive.design import design, ring_outer_d

    d_f = 610.4088761185126                       # the ring's root diameter, + 4 m = 650.409 mm
    _refused(p, "ring_outer_d_mm", d_f + 40.0, "must be > d_f + 4m = 650.409 mm (rim under the bolts)",
             ring_outer_d_mm=d_f + 40.0)
    _refused(p, "ring_outer_d_mm", 600.0, "must be > d_f + 4m = 650.409 mm (rim under the bolts)",
             ring_outer_d_mm=600.0)
    q = dataclasses.replace(p, ring_outer_d_mm=d_f + 41.0, ring_bolts=0)
    dd = design(q)
    assert ring_outer_d(q, dd.ps) == d_f + 41.0 and len(dd.outlines[2].profile.holes) == 1   # the teeth only
    # 0: the root diameter plus 8 modules
    assert ring_outer_d(p, dd.ps) == pytest.approx(d_f + 80.0, rel=1e-12)


def _bolt_holes(dd):
    return [h for h in dd.outlines[2].profile.holes if len(h.segments) == 2]


def test_ring_bolt_holes_on_the_middle_of_the_rim_between_the_teeth(p):
    """12 holes Ø 18 on the circle half way between the root (d_f = 610.409 mm) and the rim (690.409 mm): r = 325.204
    mm, the first at half a pitch (15°), each a clockwise circle (a hole)."""
    from propulsor.parts.final_drive.design import design

    dd = design(p)
    holes = _bolt_holes(dd)
    assert len(dd.outlines[2].profile.holes) == 1 + 12 and len(holes) == 12
    r_bc = 0.25 * (690.4088761185126 + 610.4088761185126)
    for k, h in enumerate(holes):
        a = 2 * math.pi * (k + 0.5) / 12
        for s in h.segments:
            assert s.radius == 9.0
            assert s.center[0] == pytest.approx(r_bc * math.cos(a), abs=1e-9)
            assert s.center[1] == pytest.approx(r_bc * math.sin(a), abs=1e-9)
        assert h.signed_area() < 0
    assert design(dataclasses.replace(p, ring_bolts=1)).outlines[2].profile.holes[1].segments[0].center == (
        pytest.approx(-r_bc, abs=1e-9), pytest.approx(0.0, abs=1e-9))
    assert len(design(dataclasses.replace(p, ring_bolts=0)).outlines[2].profile.holes) == 1


def test_ring_bolt_refusals_on_both_sides_of_their_limits(p):
    """The rim is 40 mm: a hole must be < 0.6·40 = 24 mm; holes of 23 mm on r = 325.204 mm need a pitch
    2r·sin(π/n) > 34.5 mm: 59 fit, 60 do not."""
    from propulsor.parts.final_drive.design import design

    _refused(p, "ring_bolt_d_mm", 24.0, "must be < 0.6 × rim width = 24.000 mm", ring_bolt_d_mm=24.0)
    assert len(_bolt_holes(design(dataclasses.replace(p, ring_bolt_d_mm=23.0)))) == 12
    r_bc = 0.25 * (690.4088761185126 + 610.4088761185126)
    assert 2 * r_bc * math.sin(math.pi / 60) <= 34.5 < 2 * r_bc * math.sin(math.pi / 59)
    _refused(p, "ring_bolts", 60, f"holes of 23.0 mm on a {2 * r_bc:.1f} mm bolt circle need a pitch > 1.5 d: at most "
                                  f"59 holes", ring_bolt_d_mm=23.0, ring_bolts=60)
    assert len(_bolt_holes(design(dataclasses.replace(p, ring_bolt_d_mm=23.0, ring_bolts=59)))) == 59


def test_gear_outlines_of_the_part_file(p):
    """Sun and planet generated by the rack, thinned by E_sn, to the tips of the set; the sun's bore Ø 80 with its
    keyway, the planet's Ø 110; the ring by the shaper, to its tip, with the rim Ø 690.409."""
    from propulsor.parts.final_drive.design import design

    dd = design(p)
    sun, planet, ring = dd.outlines
    ps = dd.ps
    assert (sun.d_f, planet.d_f) == (pytest.approx(145.0, abs=0.05), pytest.approx(185.0, abs=0.05))
    assert ring.d_f == pytest.approx(610.409, abs=0.05)
    for o, d_a in ((sun, ps.d_a_sun), (planet, ps.d_a_planet)):
        r = [float(np.hypot(*o.profile.outer.polyline(1e-3).T).max())]
        assert r[0] == pytest.approx(0.5 * d_a, abs=0.01)
    r_ring = np.hypot(*ring.profile.outer.polyline(1e-3).T)
    assert r_ring.max() == pytest.approx(0.5 * 690.4088761185126, abs=1e-6)
    sun_hole = np.hypot(*sun.profile.holes[0].polyline(1e-3).T)
    assert sun_hole.min() == pytest.approx(40.0, abs=1e-6) and sun_hole.max() > 40.5     # the keyway
    pl_hole = np.hypot(*planet.profile.holes[0].polyline(1e-3).T)
    assert (pl_hole.min(), pl_hole.max()) == (pytest.approx(55.0, abs=1e-6), pytest.approx(55.0, abs=1e-6))
    r_tip = np.hypot(*ring.profile.holes[0].polyline(1e-3).T).min()
    assert r_tip == pytest.approx(0.5 * ps.d_a_ring, abs=0.01)
    # the solids' teeth thinned by E_sn (the ring's spaces widened): each outline differs from the unthinned one
    assert p.tooth_thinning_mm > 0
    plain = design(dataclasses.replace(p, tooth_thinning_mm=0.0)).outlines
    for a, b in ((dd.outlines[0].profile.outer, plain[0].profile.outer),
                 (dd.outlines[1].profile.outer, plain[1].profile.outer),
                 (dd.outlines[2].profile.holes[0], plain[2].profile.holes[0])):     # the ring's teeth: a hole
        assert abs(a.signed_area()) != pytest.approx(abs(b.signed_area()), rel=1e-9)
    bare = design(dataclasses.replace(p, sun_bore_mm=0.0, planet_bore_mm=0.0, sun_keyway=False)).outlines
    assert len(bare[0].profile.holes) == 0 and len(bare[1].profile.holes) == 0
    keyless = design(dataclasses.replace(p, sun_keyway=False)).outlines[0]
    kh = np.hypot(*keyless.profile.holes[0].polyline(1e-3).T)
    assert kh.max() == pytest.approx(40.0, abs=1e-6)
    assert ring.profile.name == dd.outlines[2].profile.name and ring.profile.name


def test_body_offsets_turn_a_tooth_onto_x():
    from propulsor.parts.final_drive.design import body_offsets

    assert body_offsets(56) == (-0.5 * math.pi, -0.5 * math.pi - math.pi / 56)


def test_feasible_refuses_what_design_refuses(p):
    from propulsor.errors import InputError
    from propulsor.parts.final_drive.design import feasible

    assert feasible(p) is None
    with pytest.raises(InputError) as e:
        feasible(dataclasses.replace(p, n_planets=5))
    assert e.value.parameter == "n_planets"


# ---- proofs.py: the sheet and conditions, the generated outlines, the mesh sweep -----------------------------------
def test_dms_rounds_seconds_to_hundredths():
    from propulsor.parts.final_drive.proofs import dms

    assert dms(math.radians(20.5)) == "20°30'00.00\""
    assert dms(math.radians(1 + 1 / 60 + 1.5 / 3600)) == "1°01'01.50\""
    assert dms(math.radians(26.280223608488676)) == "26°16'48.80\""          # α_w of the corrected set
    assert dms(0.0) == "0°00'00.00\""


def test_sheet_and_conditions_of_the_corrected_set(p):
    from propulsor.parts.final_drive.proofs import sheet_and_conditions

    dd = _design(p)
    ps = dd.ps
    w = _Writer()
    sheet_and_conditions(dd, w, {})
    d = w.derived
    sp, pr = ps.mesh_sun_planet, ps.mesh_planet_ring
    assert d["ratio_i_1H"] == 1 + 56 / 16 and d["n_planets"] == 3
    assert d["x_ring_used"] == ps.x_ring == d["x_ring_for_coaxiality"] == pytest.approx(1.5, abs=1e-12)
    # α_w: cos α_w = a·cos α/a_w with a = 180 mm (sun-planet) and the same a_w for the ring
    alpha_w = math.degrees(math.acos(180.0 * math.cos(math.radians(20)) / d["a_w_sun_planet_mm"]))
    assert d["alpha_w_sun_planet_deg"] == pytest.approx(alpha_w, rel=1e-12)
    assert d["alpha_w_planet_ring_deg"] == pytest.approx(alpha_w, rel=1e-12)
    assert d["alpha_w_sun_planet_dms"] == d["alpha_w_planet_ring_dms"] == "26°16'48.80\""
    assert d["a_w_sun_planet_mm"] == sp.a_w and d["a_w_planet_ring_mm"] == pr.a_w
    assert round(sp.a_w, 3) == round(pr.a_w, 3) == 188.643 and abs(d["coaxiality_mismatch_mm"]) < 1e-9
    # neighbour gap 2·a_w·sin(π/3) − d_a,planet (eq. 30); assembly (16 + 56)/3 = 24 (eq. 31)
    assert d["neighbour_gap_mm"] == pytest.approx(2 * sp.a_w * math.sin(math.pi / 3) - ps.d_a_planet, rel=1e-12)
    assert d["assembly_quotient"] == 24.0
    for tag, g, z, da in (("sun", ps.sun, 16, ps.d_a_sun), ("planet", ps.planet, 20, ps.d_a_planet),
                          ("ring", ps.ring, 56, ps.d_a_ring)):
        assert d[f"d_{tag}_mm"] == 10.0 * z
        assert d[f"d_b_{tag}_mm"] == pytest.approx(10.0 * z * math.cos(math.radians(20)), rel=1e-12)
        assert (d[f"d_a_{tag}_mm"], d[f"d_f_{tag}_mm"], d[f"s_n_{tag}_mm"]) == (da, g.d_f, g.s_n)
        assert (d[f"k_W_{tag}"], d[f"W_k_{tag}_mm"], d[f"D_roller_{tag}_mm"]) == (g.k_W, g.W_k, g.D_recommended)
        assert d[f"M_{tag}_mm"] == g.M(g.D_recommended) and d[f"s_na_{tag}_mm"] == g.tip_thickness(da)
    assert (d["d_f_sun_mm"], d["d_f_planet_mm"], round(d["d_f_ring_mm"], 3)) == (145.0, 185.0, 610.409)
    assert [round(d[f"k_W_{t}"]) for t in ("sun", "planet", "ring")] == [3, 3, 9]
    # operating pitch diameters d_w = d·cos α/cos α_w
    f = math.cos(math.radians(20)) / math.cos(math.radians(alpha_w))
    assert [d[k] for k in ("d_w_sun_mm", "d_w_planet_sun_mesh_mm", "d_w_planet_ring_mesh_mm", "d_w_ring_mm")] == \
        pytest.approx([160 * f, 200 * f, 200 * f, 560 * f], rel=1e-12)
    assert d["epsilon_alpha_sun_planet"] == ps.epsilon_alpha_sun_planet and round(ps.epsilon_alpha_sun_planet, 4) == 1.227
    assert d["epsilon_alpha_planet_ring"] == ps.epsilon_alpha_planet_ring
    conds = ps.conditions()
    assert [(c.name, c.passed, c.value, c.limit, c.unit, c.message) for c in w.checks] == [
        (c.name, c.passed, c.value, c.limit, c.unit, c.message) for c in conds]
    assert len(conds) == 19 and all(c.passed for c in conds)
    cols = ["quantity", "symbol", "unit", "gear_1", "gear_2"]
    made = ["tooth thickness allowance of the solids (ring: space widening)", "E_sn", "mm", 0.15, 0.15]
    assert w.tables["sheet_sun_planet"] == (cols, [list(r) for r in sp.sheet(d_a1=ps.d_a_sun, d_a2=ps.d_a_planet)]
                                            + [made])
    assert w.tables["sheet_planet_ring"] == (cols, [list(r) for r in pr.sheet(d_a1=ps.d_a_planet, d_a2=ps.d_a_ring)]
                                             + [made])
    assert w.tables["conditions"] == (["name", "passed", "value", "limit", "unit", "message"],
                                      [[c.name, c.passed, c.value, c.limit, c.unit, c.message] for c in conds])


def test_the_thesis_set_fails_coaxiality_in_its_checks():
    from propulsor.parts.final_drive.proofs import sheet_and_conditions

    dd = _design(_params(THESIS))
    w = _Writer()
    sheet_and_conditions(dd, w, {})
    assert [c.name for c in w.checks if not c.passed] == ["coaxiality"]
    assert w.derived["x_ring_used"] == 1.417 and w.derived["x_ring_for_coaxiality"] == pytest.approx(1.5, abs=1e-12)
    assert round(w.derived["coaxiality_mismatch_mm"], 3) == -0.646     # planet–ring a_w 187.997 − 188.643 mm
    assert w.derived["alpha_w_planet_ring_dms"] == "25°52'43.83\"" and round(w.derived["alpha_w_planet_ring_deg"], 4) == 25.8788


def test_outline_checks_of_the_generated_outlines(p):
    from propulsor.parts.final_drive.proofs import outline_checks

    dd = _design(p)
    w = _Writer()
    outline_checks(dd, w, {})
    sun, planet, ring = dd.outlines
    assert w.derived == {"d_f_sun_generated_mm": sun.d_f, "d_f_planet_generated_mm": planet.d_f,
                         "d_f_ring_generated_mm": ring.d_f, "d_Ff_sun_mm": sun.d_Ff, "d_Ff_planet_mm": planet.d_Ff,
                         "ring_outer_d_mm": pytest.approx(610.4088761185126 + 80.0, rel=1e-12)}
    assert (round(sun.d_Ff, 4), round(planet.d_Ff, 4)) == (152.4958, 191.9766)
    assert [(c.name, c.passed, c.message) for c in w.checks] == [
        ("undercut_sun_generated", True, "rack envelope does not undercut the sun (form diameter d_Ff = 152.4958 mm)"),
        ("undercut_planet_generated", True,
         "rack envelope does not undercut the planet (form diameter d_Ff = 191.9766 mm)")]


def test_outline_checks_flag_an_undercut_sun(p):
    """z = 16 without its shift: x = 0 < x_min = 0.064, the rack undercuts the sun."""
    from propulsor.parts.final_drive.proofs import outline_checks

    dd = _design(dataclasses.replace(p, x_sun=0.0, x_planet=0.0, ring_shift_for_coaxiality=True))
    w = _Writer()
    outline_checks(dd, w, {})
    c = w.checks[0]
    assert (c.name, c.passed) == ("undercut_sun_generated", False)
    assert c.message == f"rack envelope undercuts the sun (form diameter d_Ff = {dd.outlines[0].d_Ff:.4f} mm)"


def test_member_poses_turn_the_sun_and_planets_with_the_carrier(p):
    """Ring fixed; the sun at i_1H·ψ; planet k on the orbit at ψ + 2πk/3: the poses' rotation and translation."""
    from propulsor.gears.planetary_kinematics import PlanetaryKinematics
    from propulsor.parts.final_drive.proofs import member_poses

    dd = _design(p)
    psi = [0.0, 0.1, 0.25]
    M_sun, M_ring, M_pl = member_poses(p, dd.ps, psi)
    kin = PlanetaryKinematics(16, 20, 56, 3, dd.ps.a_w)
    assert M_sun.shape == M_ring.shape == (3, 2, 3) and len(M_pl) == 3
    a = kin.sun_angle(np.array(psi)) - 0.5 * math.pi
    assert M_sun[:, 0, 0] == pytest.approx(np.cos(a), abs=1e-12) and M_sun[:, 1, 0] == pytest.approx(np.sin(a), abs=1e-12)
    assert np.all(M_sun[:, :, 2] == 0.0) and np.all(M_ring[:, :, 2] == 0.0)
    r = kin.ring_rotation - 0.5 * math.pi - math.pi / 56
    assert M_ring[:, 0, 0] == pytest.approx([math.cos(r)] * 3, abs=1e-12)
    assert M_ring[:, 1, 0] == pytest.approx([math.sin(r)] * 3, abs=1e-12)
    for k in range(3):
        c = kin.planet_centre(np.array(psi), k)
        assert M_pl[k][:, :, 2] == pytest.approx(c, abs=1e-9)
        ang = kin.planet_angle(np.array(psi), k) - 0.5 * math.pi
        assert M_pl[k][:, 0, 0] == pytest.approx(np.cos(ang), abs=1e-12)
        assert np.hypot(*c.T) == pytest.approx([dd.ps.a_w] * 3, rel=1e-12)


def test_carrier_sweep_clears_every_mesh_of_the_corrected_set(p, monkeypatch):
    """18 steps a turn: sun-planet and planet-ring of all three planets clear by 0.14 mm (backlash of E_sn = 0.15 mm
    thinning less the outlines' chord error) and never overlap; the sweep counts its meshes to the build."""
    from propulsor.parts.final_drive.proofs import start_sweep, sweep_results

    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    q = dataclasses.replace(p)
    object.__setattr__(q, "sweep_steps_per_deg", 0.0501)   # ceil(360·0.0501) = 19 steps (below the parameter's least)
    dd = _design(q)

    class W(_PlotWriter):
        def progress(self, *a):
            self.said = getattr(self, "said", []) + [a]

    w, built = W(), {}
    start_sweep(dd, w, built)
    assert w.said[0] == ("interference sweep over one carrier turn (19 steps), in a second process while the solids "
                         "are built",)
    sweep_results(dd, w, built)
    sweeps = built["sweeps"]
    assert "pending_sweep" not in built
    names = ["mesh_sun_planet1", "mesh_planet1_ring", "mesh_sun_planet2", "mesh_planet2_ring", "mesh_sun_planet3",
             "mesh_planet3_ring"]
    assert [s.name for s in sweeps] == names
    psi = sweeps[0].psi
    assert len(psi) == 19 and psi[1] == pytest.approx(2 * math.pi / 19, rel=1e-15)
    for s in sweeps:
        assert s.overlap_mm2.max() == 0.0 and 0.13 < s.clearance_mm.min() < 0.15
        assert w.derived[f"{s.name}_min_clearance_mm"] == float(s.clearance_mm.min())
        assert w.derived[f"{s.name}_max_overlap_mm2"] == 0.0
    cols, rows = w.tables["carrier_sweep"]
    assert cols == ["psi_deg"] + [f"{n}_{q}" for n in names for q in ("overlap_mm2", "clearance_mm")]
    assert len(rows) == 19 and rows[1][0] == pytest.approx(360 / 19, rel=1e-12)
    assert rows[3][1:] == [v for s in sweeps for v in (s.overlap_mm2[3], s.clearance_mm[3])]
    assert [c.name for c in w.checks] == [f"{n}.{q}" for n in names for q in ("overlap_area", "min_clearance")]
    ((name, fig),) = w.plots
    ax = fig.axes[0]
    assert name == "mesh_clearance" and [ln.get_label() for ln in ax.lines] == names
    assert {ln.get_linewidth() for ln in ax.lines} == {0.8}
    assert list(ax.lines[2].get_xdata()) == pytest.approx(list(np.degrees(psi)), rel=1e-12)
    assert list(ax.lines[2].get_ydata()) == list(sweeps[2].clearance_mm)
    assert (ax.get_xlabel(), ax.get_ylabel(), ax.get_title()) == (
        "carrier angle ψ, deg", "least clearance, mm (negative: penetration)",
        "Planetary final drive: clearance of every mesh over one carrier turn")
    assert [t.get_fontsize() for t in ax.get_legend().get_texts()] == [7] * 6
    assert w.said[-1] == ("interference sweep done",)
