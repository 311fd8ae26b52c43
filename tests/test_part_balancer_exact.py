"""The balancer's design, proofs and damper heat, number by number (parts/balancer/design.py, proofs.py, damper.py):
the seed's suspension of the part file (seed 004 ch. 2's printed numbers), the model's stations, spindle and outline,
every refusal of ``resolve`` in full, the strength and socket checks against their formulas, the travel sweep of the
arm plate and a wheel of cylinders made in the test (manifold3d, a few steps), and the damper heat's wiring of the
two-mass model, on a stub of the output writer.

Fast and in this process, for mutation testing (mutation/targets.toml, target ``balancer_design``): every model is
resolved inside its test (0.7 s), no CAD solid is built and nothing written but a road wheel file in tmp_path.
"""

from __future__ import annotations

import dataclasses
import importlib
import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from propulsor import policy
from propulsor.errors import InputError
from propulsor.params import read_part_file
from propulsor.parts.balancer.params import BalancerParams
from stand_ins import SaidWriter

bd = importlib.import_module("propulsor.parts.balancer.design")
bp = importlib.import_module("propulsor.parts.balancer.proofs")
dm = importlib.import_module("propulsor.parts.balancer.damper")

ROOT = Path(__file__).resolve().parents[1]
FILE = ROOT / "parts" / "balancer.toml"


class _Done:
    def __init__(self, value):
        self.value = value

    def result(self):
        return self.value


def _params(**kw) -> BalancerParams:
    _, mapping = read_part_file(FILE)
    return BalancerParams(**{**mapping, **kw})


def _model(steps_per_deg=None, **kw):
    p = _params(**kw)
    if steps_per_deg is not None:
        object.__setattr__(p, "sweep_steps_per_deg", steps_per_deg)  # fewer than the file allows: 11 steps
    return bd.resolve(p, FILE)


def _refusal(source=FILE, **kw) -> str:
    with pytest.raises(InputError) as e:
        bd.resolve(_params(**kw), source)
    return str(e.value)


def _vf(solid):
    mesh = solid.to_mesh()
    return np.asarray(mesh.vert_properties[:, :3], float), np.asarray(mesh.tri_verts)


def _meshes(m):
    """The arm plate (its outline extruded over the arm width about z = 0) and the wheel as cylinders: the hub tube
    and per row the rim and the tyre rings (wheel frame), in the order of the wheel's solids."""
    from propulsor.checks.motion import outline
    from propulsor.solids.kernel import manifold_cylinder

    b = m.p.arm_width_mm
    arm = outline(m.outline.profile, 0.5, 5.0).section.extrude(b).translate([0.0, 0.0, -0.5 * b])
    w = m.wheel

    def ring(r0, r1, z0, z1):
        return (manifold_cylinder(z1 - z0, r1, 48, [0, 0, z0])
                - manifold_cylinder(z1 - z0 + 2.0, r0, 48, [0, 0, z0 - 1.0]))

    wheel = [_vf(manifold_cylinder(m.wheel_p.hub_length_mm, w.r_hub, 48))]
    for z0, z1 in w.rows_z:
        wheel += [_vf(ring(w.r_rim_in, w.r_rim_out, z0, z1)), _vf(ring(w.r_rim_out, w.r_tyre, z0, z1))]
    return _vf(arm), wheel


# ------------------------------------------------------------------------------------------ design.py


def test_resolve_hands_the_part_files_beam_values_to_the_library():
    """The beam model takes the part file's values, not the library's defaults (which equal the part file's own, so
    only changed values tell): the reference depth, the hull bearing centres, the equal-strength depth's bounds, the
    stop load factor, the yield, the safety; the damper ear on the arm's mid-plane (e_a = 0)."""
    m = _model(h_ref_mm=130.0, a2_mm=210.0, h_min_mm=45.0, h_max_mm=380.0, k_stop=2.5, yield_MPa=900.0, safety=1.6)
    g, an = m.geom, m.analysis
    assert (g.h, g.a2, g.h_min, g.h_max, g.e_a) == (130.0, 210.0, 45.0, 380.0, 0.0)
    assert (an.k_stop, an.sigma_yield, an.safety) == (2.5, 900.0, 1.6)
    assert an.geom is g and an.sigma_allow == pytest.approx(900.0 / 1.6, rel=1e-15)


def test_suspension_of_the_part_file_is_the_seeds():
    p = _params()
    d = bd.suspension_design(p)
    t = d.torsion
    th = bd.THESIS
    assert math.degrees(t.gamma_m) == pytest.approx(th["gamma_m_deg"], abs=5e-4)
    assert math.degrees(t.beta0) == pytest.approx(18.79566018574836, rel=1e-9)
    assert math.degrees(t.beta_m) == pytest.approx(114.83887361784025, rel=1e-9)
    assert math.degrees(t.beta_st) == pytest.approx(43.144, rel=1e-12)
    assert t.f_st / 1000 == pytest.approx(th["f_st_m"], abs=5e-4) and t.f_full / 1000 == pytest.approx(th["f_full_m"],
                                                                                                       abs=5e-4)
    assert (t.P_st, t.R_b, t.d_T, t.L_T, t.tau_max, t.G) == (31490.0, 360.0, 46.0, 2000.0, 1600.0, 83000.0)
    # eight wheels over 6.846 m about the middle; the dampers on wheels 1, 2, 7, 8
    xs = tuple(-3.423 + 6.846 * k / 7 for k in range(8))
    assert d.wheel_x_m == pytest.approx(xs, abs=1e-12)
    assert d.damper_x_m == pytest.approx((xs[0], xs[1], xs[6], xs[7]), abs=1e-12)
    assert d.mu_mean == pytest.approx(28942.876784989654, rel=1e-9)
    assert d.L_a == pytest.approx(0.453 * 360.0, rel=1e-12)
    assert (d.G_p, d.I_y_kgm2, d.T_phi, d.nu, d.reb_factor, d.h_n_m, d.zdd_over_g, d.i_a, d.damper_reading,
            d.p_max, d.d_rod) == (473000.0, 421100.0, 1.8, 13.5, 0.85, 0.05, 0.5, 0.453, "lever", 20.0, 40.0)
    # dampers listed in any order: the set of wheels, front to back
    d2 = bd.suspension_design(_params(damped_wheels=[8, 1]))
    assert d2.damper_x_m == pytest.approx((xs[0], xs[7]), abs=1e-12)
    # wheel numbers outside 1 ... n (the file's validate() refuses them) are left out here
    d4 = bd.suspension_design(_params(damped_wheels=[8, 1, 0, 9]))
    assert d4.damper_x_m == pytest.approx((xs[0], xs[7]), abs=1e-12)
    # adopted angles replace eq. 9 and 10
    d3 = bd.suspension_design(_params(beta0_deg=20.0, beta_m_deg=110.0))
    assert math.degrees(d3.torsion.beta0) == pytest.approx(20.0) and math.degrees(d3.torsion.beta_m) == \
        pytest.approx(110.0)


def test_suspension_design_renames_the_librarys_parameters():
    with pytest.raises(InputError) as e:
        bd.suspension_design(_params(tau_max_MPa=100.0))
    assert str(e.value) == ("d_T_mm = 46.0: torsion bar yields under the static load: gamma_st = 24.3483 >= gamma_m = "
                            "6.0027 deg (tau > [tau] = 100 MPa)")
    assert e.value.hint == ""
    e = bd._renamed(InputError("R_b", 5.0, "too short", hint="h"))
    assert (e.parameter, e.value, e.limit, e.hint) == ("R_b_mm", 5.0, "too short", "")
    e = bd._renamed(InputError("other", 1, "x"))
    assert (e.parameter, e.value, e.limit) == ("other", 1, "x")
    with pytest.raises(InputError) as e:
        bd.feasible(_params(tau_max_MPa=100.0))
    assert str(e.value).startswith("d_T_mm = 46.0: torsion bar yields")
    assert bd.feasible(_params(), FILE) is None  # the design resolved: its road wheel file beside the part file


def test_model_of_the_part_file():
    m = _model()
    p = m.p
    assert m.wheel_file == ROOT / "parts" / "road_wheel.toml" and m.wheel_p.load_N == 31490.0
    assert m.wheel.r_tyre == 315.0 and m.design.torsion.R_b == 360.0 and m.tor is m.design.torsion
    # the wheel hub's inboard face one collar outboard of the arm face, its mid-plane z_mid further
    assert m.z_hub == 0.5 * 60.0 + 10.0 and m.e_w == 40.0 + 135.0
    assert m.L_a == pytest.approx(163.08, abs=1e-12) and m.pitch == pytest.approx(6846.0 / 7, rel=1e-12)
    g = m.geom
    assert (g.b, g.h, g.e_w, g.e_a, g.s_stop, g.a1, g.a2) == (60.0, 120.0, 175.0, 0.0, 230.0, 70.0, 200.0)
    assert (g.d_upper, g.D_upper, g.r_upper, g.d_lower, g.D_lower, g.r_lower, g.h_min, g.h_max, g.d_upper_bore) == (
        120.0, 160.0, 8.0, 100.0, 140.0, 8.0, 40.0, p.h_max_mm, 22.0)
    an = m.analysis
    assert an.sigma_allow == pytest.approx(930.0 / 1.5) and len(an.s) == 360 and an.k_stop == 2.0
    assert m.spline.designation() == "Эв. 65 x 2 GOST 6033-80 (z = 31, x = +0.200)"
    ex = m.extras
    assert ex["spindle_seat_1"] == (40.0, 86.0) and ex["spindle_seat_2"] == (235.0, 270.0)
    assert ex["spindle_end"] == 300.0 and ex["z_cross"] == 160.5 and ex["spindle_relief_r"] == 42.0
    assert ex["wheel_names"] == ["disc", "rim_1", "tyre_1", "rim_2", "tyre_2"]
    from propulsor.laws.suspension import rebound_damping_max

    t = m.tor
    assert ex["mu_reb_max_printed_c"] == pytest.approx(rebound_damping_max(2.138e5, 1.8, t.f_full, t.f_st), rel=1e-12)
    assert ex["mu_reb_max_printed_c"] == pytest.approx(52284.63260428267, rel=1e-9)
    assert ex["h_eq"].min() == pytest.approx(106.31715075490656, rel=1e-9)
    assert ex["h_eq"].max() == pytest.approx(113.70854364074019, rel=1e-9) and len(ex["h_eq"]) == 360


def test_outline_ear_and_pad():
    m = _model()
    p = m.p
    L_a, y_e, r_pin, r_ear = m.ear
    assert L_a == m.L_a and r_pin == 0.5 * p.ear_pin_d_mm == 20.0 and r_ear == 20.0 + p.ear_wall_mm
    assert y_e == pytest.approx(79.1585753775596, rel=1e-9)
    x0, x1, y_pad = m.pad
    assert (x0, x1) == (230.0 - 25.0, 230.0 + 25.0) and y_pad == pytest.approx(77.85427182037009, rel=1e-9)
    # the core half-depth under the ear: the equal-strength depth's half plus the margin, smoothed (at least that)
    h = float(np.interp(m.L_a, m.analysis.s, m.extras["h_eq"]))
    assert y_e - p.ear_ligament_mm - r_pin >= 0.5 * h + p.depth_margin_mm - 1e-9
    assert m.outline.profile.area(1e-4) == pytest.approx(75455.2966654934, rel=1e-6)
    assert len(m.outline.profile.holes) == 1
    q = m.outline.profile.outer.polyline(1e-4)
    assert q.min(axis=0) == pytest.approx([-90.0, -90.0], abs=1e-3)
    assert q.max(axis=0) == pytest.approx([360.0 + 80.0, y_e + r_ear], abs=1e-3)
    hole = m.outline.profile.holes[0].polyline(1e-4)
    assert hole.mean(axis=0) == pytest.approx([L_a, y_e], abs=1e-6) and np.ptp(hole[:, 0]) == pytest.approx(40.0)


def test_outline_pad_sits_on_the_core_over_its_blends():
    """A taller pad and a deeper margin move the pad and the ear by exactly their change."""
    m0 = _model()
    m1 = _model(stop_pad_height_mm=m0.p.stop_pad_height_mm + 3.0, ear_ligament_mm=m0.p.ear_ligament_mm + 2.0)
    assert m1.pad[2] == pytest.approx(m0.pad[2] + 3.0, abs=1e-9)
    assert m1.ear[1] == pytest.approx(m0.ear[1] + 2.0, abs=1e-9)
    m2 = _model(depth_margin_mm=m0.p.depth_margin_mm + 1.0)
    assert m2.ear[1] == pytest.approx(m0.ear[1] + 1.0, abs=1e-6) and m2.pad[2] == pytest.approx(m0.pad[2] + 1.0,
                                                                                                 abs=1e-6)


def test_spindle_dims_closed_form():
    m = _model()
    wp = m.wheel_p
    d = bd.spindle_dims(m.p, wp, 50.0)
    assert d == {"spindle_seat_1": (50.0, 96.0), "spindle_seat_2": (50.0 + 230.0 - 35.0, 280.0),
                 "spindle_end": 280.0 + 30.0, "z_cross": 0.5 * (96.0 + 245.0), "spindle_relief_r": 42.0}


def test_resolve_refuses_a_wheel_that_does_not_fit():
    assert _refusal(D_lower_mm=105.0) == (
        "D_lower_mm = 105.0: the spindle collar must exceed the inner bearing bore 100 mm (road wheel) by 10 mm")
    assert _refusal(D_lower_mm=170.0) == (
        "D_lower_mm = 170.0: the collar must stay min_clearance_mm inside the wheel hub's seat (D = 180 mm): <= 160")
    assert _model(D_lower_mm=110.0).geom.D_lower == 110.0  # the bore 100 + 2·5 mm
    assert _model(D_lower_mm=160.0).geom.D_lower == 160.0  # 80 + 10 mm inside the seat's 90 mm radius
    assert _refusal(D_lower_mm=109.5) .startswith("D_lower_mm = 109.5: the spindle collar must exceed")
    assert _refusal(D_lower_mm=161.0, lower_boss_r_mm=90.0, s_stop_mm=220.0) == (
        "D_lower_mm = 161.0: the collar must stay min_clearance_mm inside the wheel hub's seat (D = 180 mm): <= 160")
    assert _refusal(lower_collar_mm=2.0) == (
        "lower_collar_mm = 2.0: the wheel's inboard face (z = 32 mm) must lie min_clearance_mm outboard of the arm "
        "face z = 30 mm")
    assert _refusal(lower_collar_mm=9.5) == (
        "lower_collar_mm = 9.5: the wheel's inboard face (z = 39.5 mm) must lie min_clearance_mm outboard of the arm "
        "face z = 30 mm")
    assert _refusal(R_b_mm=350.0) == (
        "R_b_mm = 350.0: arm shorter than the wheel radius allows: the tyre (R = 315 mm) passes the bolt boss on the "
        "upper axis (r = 30 mm, reaching z = 70 mm into the wheel) at R_b − R − r = 5 mm; need >= 355 mm (or a "
        "shorter boss)")
    # a boss that ends min_clearance before the wheel's face passes at any arm length; one that reaches it does not
    assert _model(R_b_mm=350.0, plug_length_mm=0.0, s_stop_mm=220.0).p.R_b_mm == 350.0
    assert _refusal(R_b_mm=350.0, plug_length_mm=0.5, s_stop_mm=220.0).startswith(
        "R_b_mm = 350.0: arm shorter than the wheel")
    assert _model(R_b_mm=355.0, s_stop_mm=225.0).p.R_b_mm == 355.0
    assert _refusal(R_b_mm=354.5, s_stop_mm=225.0).startswith("R_b_mm = 354.5: arm shorter")


def test_resolve_refuses_an_ear_and_a_pad_off_the_arm():
    assert _refusal(i_a=0.2) == ("i_a = 0.2: the damper ear (L_a = 72 mm, reading 'lever') must sit on the arm between "
                                 "the bosses (90 ... 280 mm)")
    assert _refusal(i_a=0.9) == ("i_a = 0.9: the damper ear (L_a = 324 mm, reading 'lever') must sit on the arm between "
                                 "the bosses (90 ... 280 mm)")
    assert _refusal(s_stop_mm=120.0) == ("s_stop_mm = 120.0: the stop pad with its blends (±20 mm) must lie between the "
                                         "bosses (90 ... 280 mm)")
    assert _refusal(s_stop_mm=255.0) == ("s_stop_mm = 255.0: the stop pad with its blends (±20 mm) must lie between the "
                                         "bosses (90 ... 280 mm)")
    assert _refusal(stop_pad_length_mm=20.0) == "stop_pad_length_mm = 20.0: must exceed 2 × smoothing_mm = 40 mm (flat face)"
    assert _refusal(stop_pad_length_mm=40.0, s_stop_mm=200.0) == (
        "stop_pad_length_mm = 40.0: must exceed 2 × smoothing_mm = 40 mm (flat face)")
    assert _model(stop_pad_length_mm=41.0, s_stop_mm=200.0).pad[:2] == (179.5, 220.5)
    # both ends of the stop pad's room: its blend may not reach a boss (x0 - 20 > 90, x1 + 20 < 280; a 50 mm pad)
    for s_ok in (135.5, 234.5):
        assert _model(stop_pad_length_mm=50.0, s_stop_mm=s_ok).pad[:2] == (s_ok - 25.0, s_ok + 25.0)
    for s_no in (135.0, 235.0):
        assert _refusal(stop_pad_length_mm=50.0, s_stop_mm=s_no).startswith(f"s_stop_mm = {s_no}: the stop pad")
    assert _refusal(s_stop_mm=400.0) == "s_stop_mm = 400.0: stop pad must lie on the arm, <= R_b = 360 mm"
    assert _refusal(damper_reading="literal") == (
        "i_a = 0.453: damper ear arm L_a = 794.7 mm lies beyond the balancer R_b = 360 mm (reading 'literal')")
    # the equal-strength depth's refusal under the part file's name (h_max_mm, not the library's h_max)
    assert _refusal(arm_width_mm=20.0) == (
        "h_max_mm = 400.0: even h_max leaves sigma_vM > 620 MPa at a station; widen the arm (b) or raise h_max")


def test_a_missing_road_wheel_is_refused_before_the_build_but_not_by_the_estimate(tmp_path, capfd):
    """The road wheel file is read by the feasibility check (``parts.vet``: the dry run, the Python API, each build's
    load), as the design reads it: a dry run names it, exit 2.  The size estimate that orders several builds needs
    only the suspension and does not read it (the build's own load then refuses the file)."""
    from propulsor.cli import main
    from propulsor.loading import early_estimate, load

    text = (ROOT / "parts" / "balancer.toml").read_text("utf-8")
    bad = tmp_path / "balancer.toml"
    bad.write_text(text.replace('road_wheel_file = "road_wheel.toml"', 'road_wheel_file = "nope.toml"'), "utf-8")
    assert main(["build", str(bad), "--dry-run", "-q"]) == 2
    assert capfd.readouterr().err.strip() == (
        f"propulsor: error: road_wheel_file = 'nope.toml': does not exist (looked for {tmp_path / 'nope.toml'})")
    with pytest.raises(InputError, match="road_wheel_file"):
        load(bad)
    assert early_estimate(bad) == load(ROOT / "parts" / "balancer.toml").estimate.seconds > 0


def test_resolve_reads_the_road_wheel_file(tmp_path, monkeypatch):
    assert _refusal(road_wheel_file="nope.toml") == (
        f"road_wheel_file = 'nope.toml': does not exist (looked for {ROOT / 'parts' / 'nope.toml'})")
    assert _refusal(road_wheel_file="balancer.toml") == (
        "road_wheel_file = 'balancer.toml': names part type 'balancer', not 'road_wheel'")
    monkeypatch.chdir(tmp_path)
    assert _refusal(source=None) == (
        f"road_wheel_file = 'road_wheel.toml': does not exist (looked for {tmp_path / 'road_wheel.toml'})")
    text = (ROOT / "parts" / "road_wheel.toml").read_text("utf-8")
    (tmp_path / "road_wheel.toml").write_text(text, "utf-8")
    m = bd.resolve(_params(), None)
    assert m.wheel_file == tmp_path / "road_wheel.toml" and m.wheel.r_tyre == 315.0
    m = bd.resolve(_params(road_wheel_file=str(ROOT / "parts" / "road_wheel.toml")), tmp_path / "x.toml")
    assert m.wheel_file == ROOT / "parts" / "road_wheel.toml"
    # the road wheel's own refusals (its validate() and its design) name its file
    (tmp_path / "bad.toml").write_text(text.replace("tyre_thickness_mm = 40.0", "tyre_thickness_mm = 190.0"), "utf-8")
    with pytest.raises(InputError) as e:
        bd.resolve(_params(road_wheel_file="bad.toml"), tmp_path / "balancer.toml")
    assert str(e.value) == "tyre_thickness_mm (in bad.toml) = 190.0: must be < R/2 = 157.5 mm"
    (tmp_path / "heavy.toml").write_text(text.replace("load_N = 31490.0", "load_N = 3e6"), "utf-8")
    with pytest.raises(InputError) as e:
        bd.resolve(_params(road_wheel_file="heavy.toml"), tmp_path / "balancer.toml")
    assert str(e.value).startswith("load_N (in heavy.toml) = 3000000.0: Kozlov's deflection")
    # a wheel whose inner row stands 5 mm inboard of its hub face: its inboard face is the row's, 35 mm from the arm
    (tmp_path / "inboard.toml").write_text(text.replace("row_offset_mm = 5.0", "row_offset_mm = -5.0"), "utf-8")
    with pytest.raises(InputError) as e:
        bd.resolve(_params(road_wheel_file="inboard.toml"), tmp_path / "balancer.toml")
    assert str(e.value) == ("lower_collar_mm = 10.0: the wheel's inboard face (z = 35 mm) must lie min_clearance_mm "
                            "outboard of the arm face z = 30 mm")
    (tmp_path / "bearing.toml").write_text(text.replace("bearing_outer_d_mm = 80.0", "bearing_outer_d_mm = 100.0")
                                           .replace("hub_relief_d_mm = 124.0", "hub_relief_d_mm = 125.0"), "utf-8")
    with pytest.raises(InputError) as e:
        bd.resolve(_params(road_wheel_file="bearing.toml"), tmp_path / "balancer.toml")
    assert str(e.value) == ("bearing_outer_d_mm (road wheel) = 100.0: the outboard bearing must be smaller than the "
                            "inboard one (100 mm): the bearings slide on from the spindle end")


# ------------------------------------------------------------------------------------------ proofs.py


def test_rz_turns_about_z_and_moves():
    T = bp._rz(0.5, (1.0, 2.0, 3.0))
    c, s = math.cos(0.5), math.sin(0.5)
    assert T == pytest.approx(np.array([[c, -s, 0, 1.0], [s, c, 0, 2.0], [0, 0, 1, 3.0], [0, 0, 0, 1]]), abs=1e-15)
    assert bp._rz(0.25) == pytest.approx(np.array([[math.cos(0.25), -math.sin(0.25), 0, 0],
                                                   [math.sin(0.25), math.cos(0.25), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]))


def test_fmt_point():
    assert bp.fmt_point(None) == "?"
    assert bp.fmt_point((1.04, -2.25, 3.0)) == "(1.0, -2.2, 3.0)"


def test_neighbour_angles_are_the_closest_axes():
    m = _model()
    t = m.tor
    betas = np.radians([20.0, 60.0, 110.0])
    off = m.pitch
    ang, dist = bp._neighbour_angles(m, betas, off)
    bb = np.linspace(t.beta0, t.beta_m, 4001)
    for b, a, d in zip(betas, ang, dist):
        dd = np.hypot(360 * np.sin(bb) + off - 360 * math.sin(b), -360 * np.cos(bb) + 360 * math.cos(b))
        j = int(np.argmin(dd))
        assert a == bb[j] and d == pytest.approx(dd[j], rel=1e-12)
        assert np.any(np.isclose(bb, a, rtol=0, atol=0))
    # the front neighbour comes closest when it swings back to β0 (its axis moves toward ours)
    assert ang[0] == t.beta0 or ang[0] < ang[2]
    ang_r, dist_r = bp._neighbour_angles(m, betas, -off)
    assert dist_r[0] < off and np.all(dist_r <= off + 720)


def test_neighbour_angles_golden():
    m = _model()
    ang, dist = bp._neighbour_angles(m, np.radians([20.0, 60.0, 110.0]), m.pitch)
    t = m.tor
    bb = np.linspace(t.beta0, t.beta_m, 4001)
    # a neighbour 978 mm ahead: at our β its closest angle is where R sin β' − R sin β + 978 is least on the
    # travel, i.e. the smallest β' (its wheel swung back): β0
    assert ang[0] == bb[0] and ang[1] == bb[0]
    assert dist[0] == pytest.approx(math.hypot(360 * math.sin(t.beta0) + m.pitch - 360 * math.sin(math.radians(20)),
                                               -360 * math.cos(t.beta0) + 360 * math.cos(math.radians(20))), rel=1e-12)


def test_gap_doubles_its_window():
    from propulsor.solids.kernel import manifold_cube

    a = manifold_cube([10.0, 10.0, 10.0])
    b = manifold_cube([10.0, 10.0, 10.0], [60.0, 0.0, 0.0])
    assert bp._gap(a, b, 20.0) == pytest.approx(50.0)
    assert bp._gap(a, b, 60.0) == pytest.approx(50.0)
    assert bp._gap(a, b, 50.0) == pytest.approx(50.0)
    c = manifold_cube([10.0, 10.0, 10.0], [3000.0, 0.0, 0.0])
    assert bp._gap(a, c, 20.0) == pytest.approx(2560.0)  # the window stops growing at 2560 >= 2000: capped there
    assert bp._gap(a, c, 2500.0) == pytest.approx(2500.0)
    assert bp._gap(a, c, 2000.0) == pytest.approx(2000.0)  # a window of 2000 mm is the largest searched
    assert bp._gap(a, c, 1500.0) == pytest.approx(2990.0)  # 1500 caps, 3000 holds the gap
    assert bp.SWEEP_GAP_MAX_MM == 2000.0


def test_hull_envelope_plates_and_bore():
    m = _model()
    p = m.p
    hull = bp.hull_envelope(m)
    X = m.pitch + 360.0 + 315.0 + 300.0
    z_out = m.z_hub + m.wheel.z_outboard + 200.0
    zs, H, yf = p.hull_side_z_mm, p.hull_bottom_mm, p.fender_height_mm
    side = 2 * X * (yf + H + 30.0) * 30.0
    bottom = 2 * X * 30.0 * 600.0
    fender = 2 * X * 30.0 * (z_out - zs + 10.0)
    # overlap: bottom ∩ side (2X × 30 × 30); the fender sits on the side plate's top (y = fender height); the bore
    # through the side plate
    bore = math.pi * (0.5 * p.hull_bore_d_mm) ** 2 * 30.0
    expected = side + bottom + fender - 2 * X * 30 * 30 - bore
    assert hull.volume() == pytest.approx(expected, rel=2e-4)
    lo, hi = np.asarray(hull.bounding_box()[:3]), np.asarray(hull.bounding_box()[3:])
    assert lo == pytest.approx([-X, -H - 30.0, zs - 600.0]) and hi == pytest.approx([X, yf + 30.0, z_out])
    # the bore is coaxial with the torsion axis: 0.3 mm inside its radius, in four directions at mid-plate, empty;
    # 0.3 mm outside, the plate
    from propulsor.solids.kernel import manifold_cube

    r = 0.5 * p.hull_bore_d_mm
    for c, s_ in ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)):
        for rr, solid in ((r - 0.3, False), (r + 0.3, True)):
            probe = manifold_cube([0.05, 0.05, 0.05], [rr * c - 0.025, rr * s_ - 0.025, zs - 15.0])
            assert ((hull ^ probe).volume() > 0.0) is solid, (c, s_, rr)


def test_which_body_is_nearest():
    m = _model()
    bal, wheel = _meshes(m)
    assert bp._which(m, None, 0.5, bal, wheel) == "?"
    # at β = 90° the balancer frame is the world frame: a vertex of the arm, a point on the first tyre's tread
    V = bal[0]
    v = V[np.argmin(np.abs(V[:, 0] - 150.0) + np.abs(V[:, 2] - 30.0))]
    assert bp._which(m, v, math.pi / 2, bal, wheel) == "balancer"
    zt = m.z_hub + 0.5 * sum(m.wheel.rows_z[0])
    assert bp._which(m, np.array([360.0 + 315.0, 0.0, zt]), math.pi / 2, bal, wheel) == "wheel tyre_1"
    zt2 = m.z_hub + 0.5 * sum(m.wheel.rows_z[1])
    assert bp._which(m, np.array([360.0, -315.0, zt2]), math.pi / 2, bal, wheel) == "wheel tyre_2"
    assert bp._which(m, np.array([360.0 + 269.0, 0.0, zt2]), math.pi / 2, bal, wheel) == "wheel rim_2"
    # turned by β: the same vertex of the arm seen from the world frame at β = 0 (the arm hangs straight down)
    down = np.array([v[1], -v[0], v[2]])
    assert bp._which(m, down, 0.0, bal, wheel) == "balancer"
    assert bp._which(m, down, math.pi / 2, bal, wheel) != "balancer"
    tread = np.array([315.0, -360.0, zt])  # the tyre's tread at β = 0: the wheel axis at (0, −R_b)
    assert bp._which(m, tread, 0.0, bal, wheel) == "wheel tyre_1"
    # an arm vertex on its outboard face (z = 30) under the wheel's disc (z from 40): the arm, at 0 mm; a point 1 mm
    # above it, still nearer the arm's vertex than the disc's; 2 mm below a vertex of the disc's inboard face, the disc
    hub_r = m.wheel.r_hub
    under = V[np.isclose(V[:, 2], 30.0) & (np.hypot(V[:, 0] - 360.0, V[:, 1]) < hub_r - 5.0)]
    assert len(under)
    assert bp._which(m, under[0], math.pi / 2, bal, wheel) == "balancer"
    assert bp._which(m, under[0] + [0.0, 0.0, 1.0], math.pi / 2, bal, wheel) == "balancer"
    k = int(np.argmin(np.hypot(wheel[0][0][:, 0], wheel[0][0][:, 1]) + np.abs(wheel[0][0][:, 2])))
    hub_v = wheel[0][0][k] + [360.0, 0.0, m.z_hub]  # a vertex of the hub's inboard face, balancer frame
    assert bp._which(m, hub_v - [0.0, 0.0, 2.0], math.pi / 2, bal, wheel) == "wheel disc"


def test_travel_sweep_of_the_arm_and_its_wheel():
    m = _model(steps_per_deg=0.1)
    bal, wheel = _meshes(m)
    res = bp.travel_sweep(m, bal, wheel)
    t = m.tor
    n = int(math.ceil(math.degrees(t.beta_m - t.beta0) * 0.1)) + 1
    assert n == 11 and res["beta"] == pytest.approx(np.linspace(t.beta0, t.beta_m, 11))
    assert res["window_mm"] == 20.0 and set(res["pairs"]) == {"hull", "front", "rear"}
    assert set(res["timing_s"]) == {"setup", "hull_steps", "hull_search", "hull_where", "front_steps", "front_search",
                                    "front_where", "rear_steps", "rear_search", "rear_where"}
    # the wheel on its spindle: 10 mm from the arm face (the collar), no overlap
    assert res["own"] == pytest.approx((0.0, 10.0), abs=1e-3)
    pa, pb, dist = res["own_where"]
    assert dist == pytest.approx(10.0, abs=1e-3) and pa[2] == pytest.approx(30.0) and pb[2] == pytest.approx(40.0)
    hull = res["pairs"]["hull"]
    # the arm's inboard face (z = −30) against the hull side (z = −52): 22 mm at every step, searched exactly
    assert hull["gap_mm"] == pytest.approx(np.full(11, 22.0), abs=1e-6)
    assert not hull["capped"].any() and hull["searched_steps"] == list(range(11))
    assert hull["worst_step"] == 0 and hull["what"] == "balancer"
    assert np.all(np.isnan(hull["neighbour_beta"])) and np.all(np.isnan(hull["axis_distance_mm"]))
    assert hull["overlap_mm3"] == pytest.approx(np.zeros(11))
    front, rear = res["pairs"]["front"], res["pairs"]["rear"]
    assert front["worst_step"] == 6 and rear["worst_step"] == 0
    assert front["what"] == "wheel tyre_1" and rear["what"] == "wheel tyre_1"
    assert front["searched_steps"] == list(range(11)) and rear["searched_steps"] == list(range(11))
    assert front["gap_mm"][6] == pytest.approx(157.38064741388004, rel=1e-6)
    assert rear["gap_mm"][0] == pytest.approx(156.12222986699405, rel=1e-6)
    assert list(front["capped"]) == [True] * 4 + [False] * 5 + [True] * 2
    assert list(rear["capped"]) == [False] * 3 + [True] * 8
    ang, dist = bp._neighbour_angles(m, res["beta"], m.pitch)
    assert front["neighbour_beta"] == pytest.approx(ang) and front["axis_distance_mm"] == pytest.approx(dist)
    ang, dist = bp._neighbour_angles(m, res["beta"], -m.pitch)
    assert rear["neighbour_beta"] == pytest.approx(ang) and rear["axis_distance_mm"] == pytest.approx(dist)
    # the wheel-to-wheel bound (axis distance − 2 R) is never below the exact gap
    assert np.all(front["gap_mm"] <= front["axis_distance_mm"] - 2 * 315.0 + 1.0 + 1e-6)
    assert front["where"][2] == pytest.approx(front["gap_mm"][6], abs=1e-3)
    assert bp.sweep_job(m, bal, wheel)["own"] == pytest.approx(res["own"])


def test_travel_sweep_window_progress_timing_and_the_wheels_pieces(monkeypatch):
    """The search window is max(2 min_clearance, 20 mm): 24 mm at a 12 mm clearance (the collar 12 mm); the build is
    told the bodies swept against, 0 to 3 of 3; each timing is the time it took (0 to a minute); the wheel is every one
    of its pieces in whatever order they come (the hub, the nearest to the arm, given second: 12 mm); a mesh that is
    not a closed 2-manifold is refused naming the balancer's or the wheel's mesh."""
    import propulsor.parallel as par
    from propulsor.errors import InputError as Refused

    told = []
    monkeypatch.setattr(par, "tick", lambda done, total: told.append((done, total)))
    m = _model(steps_per_deg=0.1, min_clearance_mm=12.0, lower_collar_mm=12.0)
    bal, wheel = _meshes(m)
    res = bp.travel_sweep(m, bal, [wheel[1], wheel[0]] + wheel[2:])
    assert res["window_mm"] == 24.0
    assert told == [(0, 3), (1, 3), (2, 3), (3, 3)]
    assert all(0.0 <= v < 60.0 for v in res["timing_s"].values())
    assert res["own"] == pytest.approx((0.0, 12.0), abs=1e-3)
    V, F = bal
    with pytest.raises(Refused) as e:
        bp.travel_sweep(m, (V, F[:-1]), wheel)
    assert str(e.value).startswith("balancer mesh = ")
    with pytest.raises(Refused) as e:
        bp.travel_sweep(m, bal, [wheel[0], (wheel[1][0], wheel[1][1][:-1])])
    assert str(e.value).startswith("wheel mesh = ")


def test_travel_sweep_of_close_neighbours_is_the_gap_of_the_neighbours_pose():
    """Stations 148 mm closer than the part file's (dataclasses.replace of the model's pitch): the neighbours' wheels
    come within the 20 mm window at some steps (one of them 19.5 mm: within a millimetre of the window, still exact),
    so their gaps come from the 3D sweep itself, not the exact search.
    At every step the sweep measured, its gap is manifold3d's least distance between the unit at beta and the
    neighbour's unit at its own travel angle, placed at +-pitch (made here: the same meshes, the wheel at R_b on the
    hub face); the hull's gap is the arm face's 22 mm, not a neighbour's."""
    import dataclasses as dc

    from propulsor.solids.kernel import manifold

    m0 = _model(steps_per_deg=0.1)
    m = dc.replace(m0, pitch=m0.pitch - 148.0)
    bal, wheel = _meshes(m)
    res = bp.travel_sweep(m, bal, wheel)
    W = res["window_mm"]
    wheel_T = bp._rz(0.0, (m.p.R_b_mm, 0.0, m.z_hub))
    unit = manifold(bal)
    for wm in wheel:
        unit = unit + manifold(wm).transform(np.ascontiguousarray(wheel_T[:3]))

    def at(beta, x):
        return unit.transform(np.ascontiguousarray(bp._rz(beta - math.pi / 2, (x, 0.0, 0.0))[:3]))

    assert res["pairs"]["hull"]["gap_mm"] == pytest.approx(np.full(len(res["beta"]), 22.0), abs=1e-6)
    inside, near_window = 0, False
    for name, x in (("front", m.pitch), ("rear", -m.pitch)):
        d = res["pairs"][name]
        for k, b in enumerate(res["beta"]):
            if d["gap_mm"][k] >= W - 1e-9:
                continue
            inside += 1
            g = float(at(b, 0.0).min_gap(at(d["neighbour_beta"][k], x), W))
            assert d["gap_mm"][k] == pytest.approx(g, abs=1e-6), (name, k)
            assert not d["capped"][k]
            near_window = near_window or W - 1.0 <= g
    assert inside >= 3 and near_window
    for name in ("front", "rear"):  # the least gap's place: its points as far apart as the gap, at the least step
        d = res["pairs"][name]
        k = d["worst_step"]
        assert k == int(np.argmin(d["gap_mm"])) and d["gap_mm"][k] < W
        assert d["where"][2] == pytest.approx(d["gap_mm"][k], abs=1e-3)


def test_exact_gaps_of_a_capped_pair():
    """Two cubes 50 mm apart at every step (a window of 20 mm caps them): the hull's gap is searched with a growing
    window at 13 spread steps; a neighbour's near its closest axes and at the same 13 steps."""
    from propulsor.solids.kernel import manifold_cube

    m = _model()
    a = manifold_cube([10.0, 10.0, 10.0])
    far = [60.0 + 10.0 * k for k in range(20)]

    def pose_a(k):
        return a

    def pose_b(k):
        return manifold_cube([10.0, 10.0, 10.0], [far[k], 0.0, 0.0])

    exact, lower = bp._exact_gaps(m, None, np.full(20, np.nan), pose_a, pose_b, 20.0)
    cand = np.linspace(0, 19, 13).round().astype(int).tolist()
    assert sorted(exact) == cand and lower == set()
    assert [exact[k] for k in cand] == pytest.approx([far[k] - 10.0 for k in cand])
    # a neighbour: the wheel bound 2 R_tyre below the axis distance; the closest axes at step 7
    cdist = np.array([2 * 315.0 + 200.0 + 5.0 * abs(k - 7) for k in range(20)])
    exact, lower = bp._exact_gaps(m, 1.0, cdist, pose_a, pose_b, 20.0)
    assert sorted(exact) == sorted(set(cand) | {5, 6, 7, 8, 9})
    for k in (5, 6, 7, 8, 9):
        assert exact[k] == pytest.approx(far[k] - 10.0)
    # later steps: windows min(bound, least gap found) + 1 = 111 mm: steps farther than that stay lower bounds
    g_min = min(exact[k] for k in (5, 6, 7, 8, 9))
    assert g_min == pytest.approx(100.0)
    for k in cand:
        if k not in (5, 6, 7, 8, 9):
            w = min(cdist[k] - 630.0, g_min) + 1.0
            assert exact[k] == pytest.approx(min(far[k] - 10.0, w))
    assert lower == {k for k in cand if k not in (5, 6, 7, 8, 9) and far[k] - 10.0 >= 101.0 - 1e-9}
    # a later step 100.5 mm apart: within its window of 101 mm, so exact (not a lower bound)
    far[0] = 110.5
    exact, lower = bp._exact_gaps(m, 1.0, cdist, pose_a, pose_b, 20.0)
    assert exact[0] == pytest.approx(100.5) and 0 not in lower
    far[0] = 60.0
    # the closest axes at the first step: the steps around it start at 0
    cdist = np.array([700.0 + k for k in range(20)])
    exact, _ = bp._exact_gaps(m, 1.0, cdist, pose_a, pose_b, 20.0)
    assert {0, 1, 2} <= set(exact) and 3 not in set(exact) - set(cand)
    # step 0 among them: searched with its own bound (70 mm), not the least gap found (55 mm at steps 1 and 2)
    far[:3] = [75.0, 65.0, 65.0]
    exact, lower = bp._exact_gaps(m, 1.0, cdist, pose_a, pose_b, 20.0)
    assert exact[0] == pytest.approx(65.0) and exact[1] == pytest.approx(55.0) and 0 not in lower
    far[:3] = [60.0, 70.0, 80.0]
    cdist = np.array([700.0 - k for k in range(20)])
    exact, _ = bp._exact_gaps(m, 1.0, cdist, pose_a, pose_b, 20.0)
    assert {17, 18, 19} <= set(exact) and 16 in exact


def test_exact_gaps_of_few_steps():
    from propulsor.solids.kernel import manifold_cube

    m = _model()
    a = manifold_cube([10.0, 10.0, 10.0])
    b = manifold_cube([10.0, 10.0, 10.0], [40.0, 0.0, 0.0])
    exact, lower = bp._exact_gaps(m, None, np.full(3, np.nan), lambda k: a, lambda k: b, 20.0)
    assert exact == pytest.approx({0: 30.0, 1: 30.0, 2: 30.0}) and lower == set()


def test_strength_proof_of_the_part_file():
    m = _model()
    w, built = SaidWriter(), {}
    bp.strength_proof(m, w, built)
    assert w.said == ["beam model on the built outline"]
    an, p = m.analysis, m.p
    from propulsor.geometry.arm_outline import section_depth

    h_built = section_depth(m.outline.profile, an.s)
    sig = an.stresses(h_built)
    names = [c.name for c in w.checks]
    assert names[:5] == ["arm sigma_vM, beta_m elastic", "arm sigma_vM, beta_m + damper", "arm sigma_vM, stop",
                         "built depth - equal-strength depth", "least arm depth vs h_min"]
    assert [c.unit for c in w.checks[:5]] == ["MPa", "MPa", "MPa", "mm", "mm"]
    for c, (name, v) in zip(w.checks[:3], sig.items()):
        k = int(np.argmax(v))
        assert c.value == pytest.approx(float(v.max()), rel=1e-12) and c.limit == pytest.approx(620.0 * (1 + 1e-9),
                                                                                              rel=1e-15)
        assert c.message == (f"beam model on the built section depth at every one of 360 stations; largest at s = "
                             f"{an.s[k]:.1f} mm (least safety {930.0 / v.max():.3f})")
    assert [c.value for c in w.checks[:3]] == pytest.approx([345.0604872162555, 412.00789245036725, 607.5153672130322],
                                                            rel=1e-9)
    c = w.checks[3]
    assert c.value == pytest.approx(float((h_built - m.extras["h_eq"]).min()), rel=1e-12) and c.limit == 0.0
    assert c.message == "built outline encloses the equal-strength depth everywhere (least margin at s = 230.0 mm)"
    c = w.checks[4]
    assert c.value == pytest.approx(float(h_built.min())) and c.limit == 40.0 and c.message == "least manufacturable depth"
    rest = names[5:]
    assert not any("constant arm" in x or "equal-strength arm" in x or x == "torsion bar shear at beta_m" for x in rest)
    res = an.run()
    kept = [c_.name for c_ in res["checks"] if not ("constant arm" in c_.name or "equal-strength arm" in c_.name
                                                     or c_.name == "torsion bar shear at beta_m")]
    assert rest == kept and len(kept) == 12
    assert any("constant arm" in c_.name for c_ in res["checks"]) and any(
        c_.name == "torsion bar shear at beta_m" for c_ in res["checks"])
    cols, rows = w.tables["arm_stresses"]
    assert rows is None and cols["s_mm"] == pytest.approx(an.s) and cols["h_built_mm"] == pytest.approx(h_built)
    assert cols["h_equal_strength_mm"] is m.extras["h_eq"]
    for name, v in sig.items():
        key = name.replace(" ", "_").replace("+", "plus")
        f = an.forces([c_ for c_ in an.cases if c_.name == name][0])
        assert cols[f"{key}_sigma_vM_MPa"] == pytest.approx(v, rel=1e-12)
        assert cols[f"{key}_safety"] == pytest.approx(930.0 / np.maximum(v, 1e-12))
        for q, fk in (("N_N", "N"), ("V_y_N", "V_y"), ("T_Nmm", "T"), ("M_y_Nmm", "M_y"), ("M_z_Nmm", "M_z")):
            assert cols[f"{key}_{q}"] == pytest.approx(f[fk])
    assert len(cols) == 3 + 3 * 7
    tcols, trows = w.tables["transitions"]
    assert tcols == ["case", "where", "K_t_bending", "K_t_torsion", "sigma_nom_MPa", "tau_nom_MPa", "sigma_vM_nom_MPa",
                     "sigma_vM_peak_MPa", "safety"]
    trs = res["transitions"]
    assert [r[:2] for r in trows] == [[r["case"], r["where"]] for r in trs]
    assert [float(x) for r in trows for x in r[2:8]] == pytest.approx(
        [float(r[k]) for r in trs for k in ("K_t_bending", "K_t_torsion", "sigma_nom", "tau_nom", "sigma_vM_nom",
                                            "sigma_vM_peak")])
    assert [r[8] for r in trows] == pytest.approx([930.0 / r["sigma_vM_peak"] for r in trs])
    assert set(w.plots) == {"arm_stresses"} and w.plots["arm_stresses"] is not None
    D = w.derived
    assert D["sigma_allow_MPa"] == 620.0
    assert D["sigma_vM_max_built_MPa"] == pytest.approx({k: float(v.max()) for k, v in sig.items()})
    body = float(np.max(sig["beta_m elastic"][h_built < 0.95 * 2 * 80.0]))
    assert D["sigma_vM_body_elastic_built_MPa"] == pytest.approx(body) and body == pytest.approx(345.0604872162555)
    assert D["sigma_vM_constant_ref_MPa"] == pytest.approx({'beta_m elastic': 325.87813539686545,
                                                            'beta_m + damper': 374.1915592848691,
                                                            'stop': 582.2641189988304}, rel=1e-9)
    assert D["transition_peak_max_MPa"] == pytest.approx(506.8942382933673, rel=1e-9)
    assert D["transition_peak_max_MPa"] == max(r["sigma_vM_peak"] for r in trs)
    assert D["K_t_upper_bending"] == pytest.approx(1.9054737427129058) and D["K_t_upper_torsion"] == pytest.approx(
        1.5176320929511307) and D["K_t_spindle_bending"] == pytest.approx(1.8333336773244449)
    assert D["e_w_wheel_mid_plane_mm"] == 175.0
    assert D["h_equal_strength_range_mm"] == pytest.approx([106.31715075490656, 113.70854364074019], rel=1e-9)
    assert set(built) == {"s", "h_eq", "h_built", "sig", "allow", "sc", "body_el", "trs"}
    assert built["allow"] == 620.0 and built["body_el"] == pytest.approx(body)
    assert built["h_built"] == pytest.approx(h_built) and built["h_eq"] is m.extras["h_eq"]
    assert [r["sigma_vM_peak"] for r in built["trs"]] == pytest.approx([r["sigma_vM_peak"] for r in trs])
    assert built["sc"]["stop"] == pytest.approx(res["sigma_vM_constant"]["stop"])


def test_strength_proof_of_a_body_thinner_than_the_boss():
    """The body's elastic stress is taken where the arm is thinner than 0.95 of the lower boss's diameter."""
    m = _model(lower_boss_r_mm=60.0, s_stop_mm=200.0)
    w, built = SaidWriter(), {}
    bp.strength_proof(m, w, built)
    h = built["h_built"]
    body = float(np.max(built["sig"]["beta_m elastic"][h < 0.95 * 2 * 60.0]))
    assert w.derived["sigma_vM_body_elastic_built_MPa"] == pytest.approx(body, rel=1e-12)
    assert body < w.derived["sigma_vM_max_built_MPa"]["beta_m elastic"] or body == pytest.approx(
        w.derived["sigma_vM_max_built_MPa"]["beta_m elastic"])


def test_the_bodys_elastic_stress_leaves_out_the_boss_where_the_peak_is_there(monkeypatch):
    """A stress peak put at the thickest station (in the boss: h >= 0.95 of the lower boss's diameter, 152 mm):
    the body's elastic stress is the largest of the stations thinner than that, below the peak; the stations and
    the stresses are handed on to the sweep as computed."""
    from propulsor.laws.balancer_beam import BalancerAnalysis

    real = BalancerAnalysis.stresses

    def peaked(self, h):
        sig = real(self, h)
        k = int(np.argmax(h))
        sig["beta_m elastic"] = sig["beta_m elastic"].copy()
        sig["beta_m elastic"][k] = 900.0
        return sig

    monkeypatch.setattr(BalancerAnalysis, "stresses", peaked)
    m = _model()
    w, built = SaidWriter(), {}
    bp.strength_proof(m, w, built)
    h, sig = built["h_built"], built["sig"]["beta_m elastic"]
    assert h.max() >= 0.95 * 2 * 80.0 and sig.max() == 900.0
    body = float(np.max(sig[h < 152.0]))
    assert body < 400.0 and w.derived["sigma_vM_body_elastic_built_MPa"] == body == built["body_el"]
    assert w.derived["sigma_vM_max_built_MPa"]["beta_m elastic"] == 900.0
    assert built["s"] is m.analysis.s or np.array_equal(built["s"], m.analysis.s)


def test_socket_ear_pad_checks_are_their_formulas():
    m = _model()
    p, t, d = m.p, m.tor, m.design
    w = SaidWriter()
    bp.socket_ear_pad_checks(m, w, {})
    sp = m.spline
    T = t.M_T_max
    assert T == pytest.approx(30579006.252981614, rel=1e-9)
    sig_cr = sp.crushing_stress(T, 120.0)
    d_o, d_i = 117.0, sp.D_f_hub
    tau = 16.0 * T * d_o / (math.pi * (d_o ** 4 - d_i ** 4))
    F = max(d.R_a_comp_max, d.R_a_reb_max)
    assert F == pytest.approx(206623.41396628373, rel=1e-9)
    F_stop = -[c_ for c_ in m.analysis.cases if c_.name == "stop"][0].loads[1].F_y
    assert F_stop == pytest.approx(132952.2011, rel=1e-6)
    got = [(c.name, c.passed, c.value, c.limit, c.unit) for c in w.checks]
    assert got == [
        ("spline socket crushing (GOST 21425, seed 004 §4.3)", True, pytest.approx(sig_cr, rel=1e-12),
         pytest.approx(930.0 / (1.4 * 3.71), rel=1e-12), "MPa"),
        ("socket wall torsion safety", True, pytest.approx(930.0 / (math.sqrt(3) * tau), rel=1e-12), 1.5, ""),
        ("ear pin double shear", True, pytest.approx(F / (2 * math.pi * 20.0 ** 2), rel=1e-12),
         pytest.approx(930.0 / (math.sqrt(3) * 1.5), rel=1e-12), "MPa"),
        ("ear bearing pressure", True, pytest.approx(F / (40.0 * 60.0), rel=1e-12), 620.0, "MPa"),
        ("ear net-section tension", True, pytest.approx(F / (2 * 20.0 * 60.0), rel=1e-12), 620.0, "MPa"),
        ("stop pad contact pressure", True, pytest.approx(F_stop / (50.0 * 60.0), rel=1e-9), 620.0, "MPa")]
    assert sig_cr == pytest.approx(163.61789353566115, rel=1e-9)
    assert [c.message for c in w.checks] == [
        "Эв. 65 x 2 GOST 6033-80 (z = 31, x = +0.200), l = 120 mm, T = M_T(β_m) = 30.579 kN m; [σ] = 930/(1.4 × 3.71)",
        "hollow journal 117/65.80 mm at the socket: τ = 108.0 MPa",
        "rod force max(R_a,comp, R_a,reb) = 206.6 kN, pin Ø40",
        "F / (d_pin b)", "F / (2 wall b)",
        "stop force 133.0 kN (k_stop = 2) on the flat pad"]
    cols, rows = w.tables["spline_socket"]
    assert cols == ["quantity", "value", "unit"]
    assert rows == [
        ["designation", sp.designation(), ""], ["module m", 2.0, "mm"], ["teeth z", 31, ""],
        ["pressure angle", 30.0, "deg"], ["profile shift x", pytest.approx(0.2), ""], ["pitch diameter d", 62.0, "mm"],
        ["base diameter d_b", pytest.approx(62.0 * math.cos(math.radians(30.0))), "mm"],
        ["hub minor diameter D_a", 61.0, "mm"], ["hub major diameter D_f (flat root)", pytest.approx(65.8), "mm"],
        ["shaft major diameter d_a", pytest.approx(64.6), "mm"], ["basic space width e", sp.e, "mm"],
        ["engagement length l", 120.0, "mm"], ["S_F = 0.5 d_m h z", sp.S_F, "mm^3/mm"],
        ["crushing stress", pytest.approx(sig_cr), "MPa"], ["admissible", pytest.approx(930.0 / (1.4 * 3.71)), "MPa"]]


def test_socket_ear_pad_checks_take_the_larger_rod_force():
    from types import SimpleNamespace

    m = _model()
    d = SimpleNamespace(torsion=m.tor, R_a_comp_max=3e5, R_a_reb_max=m.design.R_a_reb_max)
    w = SaidWriter()
    bp.socket_ear_pad_checks(dataclasses.replace(m, design=d), w, {})
    assert w.checks[2].value == pytest.approx(3e5 / (2 * math.pi * 400.0), rel=1e-12)
    assert w.checks[2].message == "rod force max(R_a,comp, R_a,reb) = 300.0 kN, pin Ø40"


def test_travel_sweep_checks_of_the_sweep():
    m = _model(steps_per_deg=0.1)
    bal, wheel = _meshes(m)
    res = bp.travel_sweep(m, bal, wheel)
    w, built = SaidWriter(), {"pending_sweep": _Done(res)}
    bp.travel_sweep_checks(m, w, built)
    assert "pending_sweep" not in built and built["sweep"] is res and w.said == ["travel sweep done"]
    p, t = m.p, m.tor
    betas = res["beta"]
    cols, rows = w.tables["travel_sweep"]
    assert rows is None and list(cols) == [
        "beta_deg", "f_mm", "P_N", "wheel_x_mm", "wheel_y_mm", "hull_overlap_mm3", "hull_gap_mm",
        "hull_gap_is_lower_bound", "front_neighbour_beta_deg", "front_wheel_gap_upper_bound_mm", "front_overlap_mm3",
        "front_gap_mm", "front_gap_is_lower_bound", "rear_neighbour_beta_deg", "rear_wheel_gap_upper_bound_mm",
        "rear_overlap_mm3", "rear_gap_mm", "rear_gap_is_lower_bound"]
    assert cols["beta_deg"] == pytest.approx(np.degrees(betas)) and cols["f_mm"] == pytest.approx(t.f(betas))
    assert cols["P_N"] == pytest.approx(t.P(betas))
    assert cols["wheel_x_mm"] == pytest.approx(360 * np.sin(betas)) and cols["wheel_y_mm"] == pytest.approx(
        -360 * np.cos(betas))
    fr = res["pairs"]["front"]
    assert cols["front_neighbour_beta_deg"] == pytest.approx(np.degrees(fr["neighbour_beta"]))
    assert cols["front_wheel_gap_upper_bound_mm"] == pytest.approx(fr["axis_distance_mm"] - 630.0)
    assert cols["front_gap_mm"] is fr["gap_mm"] and cols["front_overlap_mm3"] is fr["overlap_mm3"]
    assert cols["rear_gap_is_lower_bound"] is res["pairs"]["rear"]["capped"]
    assert set(w.plots) == {"travel_clearance"} and w.plots["travel_clearance"] is not None
    tol = policy.OVERLAP_VOLUME_TOL_MM3
    got = [(c.name, c.passed, c.limit, c.unit) for c in w.checks]
    assert got == [
        ("travel sweep overlap, hull envelope", True, tol, "mm^3"),
        ("travel sweep clearance, hull envelope", True, 10.0, "mm"),
        ("travel sweep overlap, front neighbour station", True, tol, "mm^3"),
        ("travel sweep clearance, front neighbour station", True, 10.0, "mm"),
        ("travel sweep overlap, rear neighbour station", True, tol, "mm^3"),
        ("travel sweep clearance, rear neighbour station", True, 10.0, "mm"),
        ("own wheel vs balancer overlap", True, tol, "mm^3"),
        ("own wheel vs balancer clearance", True, 10.0, "mm"),
        ("tyre to bolt boss (R_b - R - r_boss)", True, 10.0, "mm")]
    c = w.checks
    assert c[0].message == "manifold3d intersection volume at 11 steps β0 … β_m (0.1/deg); 0 steps overlap"
    assert c[1].value == pytest.approx(22.0, abs=1e-6)
    assert c[1].message.startswith("least gap at β = 18.80° (the same at every step) between the balancer near (")
    # the arm's inboard face (z = −30) against the hull side plane (z = −52), the same (x, y)
    assert ", -30.0) and the hull envelope near (" in c[1].message and c[1].message.endswith(", -52.0) (world mm)")
    a, b = c[1].message.split(" near ")[1:3]
    assert a.split(", ")[:2] == b.split(", ")[:2]
    assert c[3].value == pytest.approx(157.38064741388004, rel=1e-6)
    assert c[3].message.startswith("least gap at β = 76.42° between the wheel tyre_1 near (")
    assert " and the front neighbour station near (" in c[3].message
    assert c[5].message.startswith("least gap at β = 18.80° between the wheel tyre_1 near (")
    assert c[6].value == pytest.approx(0.0, abs=1e-6) and c[6].message == "road wheel mounted on the spindle"
    assert c[7].value == pytest.approx(10.0, abs=1e-3)
    pa, pb, _ = res["own_where"]
    assert c[7].message == (f"least gap near {bp.fmt_point(pa)} / {bp.fmt_point(pb)} (balancer frame); rigid over the "
                            f"travel")
    assert c[8].value == 360.0 - 315.0 - 30.0 and c[8].message == "constant over the travel: both on fixed radii"
    D = w.derived
    assert D["min_clearance_hull_mm"] == pytest.approx(22.0, abs=1e-6)
    assert D["min_clearance_hull_where"] == c[1].message.removeprefix("least gap ")
    assert D["min_clearance_front_mm"] == pytest.approx(157.38064741388004, rel=1e-6)
    assert D["min_clearance_rear_mm"] == pytest.approx(156.12222986699405, rel=1e-6)
    assert D["min_clearance_own_wheel_mm"] == pytest.approx(10.0, abs=1e-3)
    assert D["min_clearance_overall_mm"] == D["min_clearance_own_wheel_mm"]
    assert D["min_clearance_overall_where"] == (f"own road wheel to balancer near {bp.fmt_point(pa)} / "
                                                f"{bp.fmt_point(pb)} (balancer frame)")
    assert D["sweep_steps"] == 11
    assert D["fender_over_wheel_top_at_beta_m_mm"] == pytest.approx(520.0 - (-360 * math.cos(t.beta_m) + 315.0))
    assert D["wheel_bottom_below_axis_at_beta0_mm"] == pytest.approx(360 * math.cos(t.beta0) + 315.0)
    assert D["eq5_ground_clearance_minus_track_mm"] == pytest.approx(360 * math.cos(t.beta_st) - 100.0 + 315.0)
    th = t.beta_m - math.pi / 2
    pc = [230.0 * math.cos(th) - m.pad[2] * math.sin(th), 230.0 * math.sin(th) + m.pad[2] * math.cos(th)]
    assert D["stop_pad_face_at_beta_m_mm"] == pytest.approx(pc, rel=1e-12)
    assert D["stop_pad_normal_at_beta_max"] == pytest.approx([-math.sin(th), math.cos(th)], rel=1e-12)
    assert built["betas"] is betas and built["own_gap"] == D["min_clearance_own_wheel_mm"]
    assert built["pc"] == pytest.approx(pc) and built["nrm"] == pytest.approx([-math.sin(th), math.cos(th)])


def test_travel_sweep_checks_name_the_least_gap_overall_and_a_varying_gap():
    m = _model(steps_per_deg=0.1)
    bal, wheel = _meshes(m)
    res = bp.travel_sweep(m, bal, wheel)
    hull = res["pairs"]["hull"]
    hull["gap_mm"] = hull["gap_mm"].copy()
    hull["gap_mm"][3] = 5.0  # a hull 5 mm away at one step: the least gap overall, and the gap varies
    hull["worst_step"] = 3
    hull["overlap_mm3"] = hull["overlap_mm3"].copy()
    hull["overlap_mm3"][[2, 3]] = [0.5, 2e-3]
    w = SaidWriter()
    bp.travel_sweep_checks(m, w, {"pending_sweep": _Done(res)})
    c = w.checks
    assert not c[0].passed and c[0].value == 0.5
    assert c[0].message == "manifold3d intersection volume at 11 steps β0 … β_m (0.1/deg); 2 steps overlap"
    assert not c[1].passed and c[1].value == 5.0
    beta3 = math.degrees(res["beta"][3])
    assert c[1].message.startswith(f"least gap at β = {beta3:.2f}° between the balancer near (")
    D = w.derived
    assert D["min_clearance_overall_mm"] == 5.0 and D["min_clearance_overall_where"] == D["min_clearance_hull_where"]


def test_travel_sweep_checks_steady_gap_overlap_count_and_ties():
    """On the sweep's own result with given gaps: "the same at every step" only with at least two uncapped steps
    whose gaps spread less than 0.01 mm (two equal: yes; one: no; a spread of exactly 0.01 or of 0.5: no); a step
    overlapping exactly the tolerance is not counted; equal least gaps of two pairs name the first pair's place, and
    a least pair gap equal to the own wheel's names the pair's."""
    import copy

    m = _model(steps_per_deg=0.1)
    bal, wheel = _meshes(m)
    base = bp.travel_sweep(m, bal, wheel)
    tol = policy.OVERLAP_VOLUME_TOL_MM3

    def run(edit):
        res = copy.deepcopy(base)
        edit(res)
        w = SaidWriter()
        bp.travel_sweep_checks(m, w, {"pending_sweep": _Done(res)})
        return w

    def hull_gaps(gaps, capped):
        def edit(res):
            h = res["pairs"]["hull"]
            h["gap_mm"] = np.array(gaps, float)
            h["capped"] = np.array(capped, bool)
            h["worst_step"] = int(np.argmin(gaps))
        return edit

    n = len(base["beta"])
    steady = "(the same at every step)"
    two = [40.0] * n
    two[2] = two[5] = 30.0
    assert steady in run(hull_gaps(two, [i not in (2, 5) for i in range(n)])).checks[1].message
    assert steady not in run(hull_gaps(two, [i != 2 for i in range(n)])).checks[1].message
    spread = [40.0] * n
    spread[2], spread[5] = 30.0, 30.01
    msg = run(hull_gaps([0.0 if g == 30.0 else (0.01 if g == 30.01 else g) for g in spread],
                        [i not in (2, 5) for i in range(n)])).checks[1].message
    assert steady not in msg  # 0.0 and 0.01: a spread of exactly 0.01 mm
    spread[5] = 30.5
    assert steady not in run(hull_gaps(spread, [i not in (2, 5) for i in range(n)])).checks[1].message

    def overlap_at_tol(res):
        res["pairs"]["hull"]["overlap_mm3"] = np.where(np.arange(n) == 4, tol, 0.0)
    c = run(overlap_at_tol).checks[0]
    assert c.passed and c.message.endswith("; 0 steps overlap")

    def tie(res):
        for name in ("hull", "front"):
            d = res["pairs"][name]
            d["gap_mm"] = np.full(n, 50.0)
            d["gap_mm"][d["worst_step"]] = 5.0
    D = run(tie).derived
    assert D["min_clearance_hull_mm"] == D["min_clearance_front_mm"] == 5.0
    assert D["min_clearance_overall_where"] == D["min_clearance_hull_where"] != D["min_clearance_front_where"]

    def own_tie(res):
        tie(res)
        res["own"] = (res["own"][0], 5.0)
    D = run(own_tie).derived
    assert D["min_clearance_overall_mm"] == 5.0 and D["min_clearance_overall_where"] == D["min_clearance_hull_where"]


# ------------------------------------------------------------------------------------------ damper.py


def test_damper_job_is_the_two_mass_model_over_the_roads():
    from propulsor.laws.damper_heat import TABLE_11, Road, Station, cooling_coefficient, simulate

    st, speeds, out = dm._job(120.0, 28942.876784989654)
    assert st == Station(m1=120.0, C1=2.0e6, b1=2.0e3, b2=28942.876784989654)
    assert speeds == pytest.approx(np.array([5.0, 10.0, 20.0, 30.0, 40.0, 50.0]) / 3.6)
    assert [(o[0], o[1], o[2]) for o in out] == [(r[0], r[1], r[2]) for r in dm.ROADS]
    assert [o[2] for o in out] == [6.846, 10.269, 13.692, 17.115, 1.0] and [o[1] for o in out] == [0.2] * 4 + [0.05]
    name, h, L, runs, steady, design = out[4]
    ref = [simulate(st, Road(0.05, 1.0), float(V), 30.0) for V in speeds]
    assert [r.mean_power for r in runs] == pytest.approx([r.mean_power for r in ref], rel=1e-12)
    assert [r.V for r in runs] == pytest.approx(list(speeds))
    assert steady == pytest.approx([r.mean_power / cooling_coefficient(st, r.V) for r in ref], rel=1e-12)
    d_ref = simulate(st, Road(0.05, 1.0), TABLE_11["V"], 30.0)
    assert design.rise == pytest.approx(d_ref.rise, rel=1e-12) and design.V == TABLE_11["V"]
    assert out[0][5].rise == pytest.approx(6.588185112437312, rel=1e-6)
    assert out[4][4] == pytest.approx([1.6329476872208155, 3.7803789688450355, 6.394077002983555, 7.904999681741598,
                                       8.377974374254691, 8.116197147541365], rel=1e-6)


def test_start_damper_heat_runs_the_job_for_the_unsprung_mass():
    m = _model()
    w, built = SaidWriter(), {"mass": 70.0, "wm_tot": 50.0}
    dm.start_damper_heat(m, w, built)
    assert w.said == ["damper heat (seed 004 ch. 6): two-mass model over 5 roads × 6 speeds, in a second process"]
    st, speeds, out = built["pending_damper"].result()
    assert st.m1 == 120.0 and st.b2 == pytest.approx(m.design.mu_mean, rel=1e-12) and len(out) == 5


def test_damper_heat_results_table_values_and_note():
    m = _model()
    job = dm._job(120.0, float(m.design.mu_mean))
    w, built = SaidWriter(), {"pending_damper": _Done(job)}
    dm.damper_heat_results(m, w, built)
    assert "pending_damper" not in built
    st, speeds, res = job
    cols, rows = w.tables["damper_heat"]
    assert cols == ["road", "height_m", "wavelength_m", "V_kmh", "mean_damper_power_W", "rise_after_30s_K",
                    "steady_rise_K"]
    assert len(rows) == 30
    want = [[name, h, L, r.V * 3.6, r.mean_power, r.rise, s] for name, h, L, runs, steady, _ in res
            for r, s in zip(runs, steady)]
    assert [r_[:3] for r_ in rows] == [r_[:3] for r_ in want]
    assert [x for r_ in rows for x in r_[3:]] == pytest.approx([x for r_ in want for x in r_[3:]], rel=1e-12)
    D = w.derived
    assert D["damper_heat_m1_unsprung_kg"] == 120.0 and D["damper_heat_b2_Ns_per_m"] == pytest.approx(m.design.mu_mean)
    # the largest steady rise: the 1 m bumps at 40 km/h
    assert D["damper_heat_max_steady_rise_K"] == pytest.approx(8.377974374254691, rel=1e-6)
    assert D["damper_heat_max_steady_rise_road"] == "Δt4: L = 1 m (wheel spacing), 0.05 m"
    assert D["damper_heat_max_steady_rise_speed_kmh"] == pytest.approx(40.0, rel=1e-12)
    from propulsor.laws.damper_heat import TABLE_11

    for name, h, L, runs, steady, design in res:
        assert D[f"damper_heat_rise_at_{TABLE_11['V']:g}mps_L{L:g}_K"] == design.rise
    assert D[f"damper_heat_rise_at_{TABLE_11['V']:g}mps_L6.846_K"] == pytest.approx(6.588185112437312, rel=1e-6)
    assert set(w.plots) == {"damper_and_tyre_heat"} and len(w.plots["damper_and_tyre_heat"].axes) == 3
    (note,) = w.notes
    assert note.startswith(f"Damper heat (seed 004 ch. 6): two-mass station, sprung {st.m2:g} kg, unsprung 120.0 kg "
                           f"(built balancer + road wheel), C2 = {st.C2:g} N/m, damper b2 = μ_mean = {st.b2:.0f} N·s/m "
                           "at the wheel, tyre on track C1 = 2e+06 N/m, b1 = 2000 N·s/m (ours), solved exactly")
    assert "over 30 s from rest at 20 °C; damper 20 kg of steel (487 J/(kg·K)), cooled by the air flow V·S·ρ·c_air " \
           "over S = 0.247 m². Largest steady rise 8.38 K on Δt4: L = 1 m (wheel spacing), 0.05 m at 40 km/h." in note
    assert note.endswith("Plot: plots/damper_and_tyre_heat.png, beside the road wheel's tyre heat.")


def test_the_suspension_takes_every_value_of_the_part_file_not_the_librarys_defaults():
    """Each value the seed's suspension is made of, set away from the library's default (which the part file's
    defaults equal), reaches it: the wheel load, the arm, its static angle, the bar's diameter, length and shear modulus, the sprung weight and pitch inertia, the pitch period and
    amplitude ratio, the rebound factor, the bump and its shake limit, the damper's ratio, pressure and rod."""
    from propulsor.laws.suspension import SuspensionDesign, TorsionSuspension

    lib = SimpleNamespace(**{f.name: f.default for f in dataclasses.fields(SuspensionDesign)})
    bar = SimpleNamespace(**{f.name: f.default for f in dataclasses.fields(TorsionSuspension)})
    given = dict(P_st_N=30000.0, R_b_mm=370.0, beta_st_deg=42.0, d_T_mm=47.0, L_T_mm=2100.0,
                 G_MPa=79000.0, G_p_N=450000.0, I_y_kgm2=400000.0, T_phi_s=1.5, nu=12.0, reb_factor=0.8,
                 h_n_m=0.06, zdd_over_g=0.45, i_a=0.5, p_max_MPa=18.0, d_rod_mm=36.0)
    d = bd.suspension_design(_params(**given))
    t = d.torsion
    got = dict(P_st_N=t.P_st, R_b_mm=t.R_b, beta_st_deg=t.beta_st_deg, d_T_mm=t.d_T, L_T_mm=t.L_T,
               G_MPa=d.torsion.G, G_p_N=d.G_p, I_y_kgm2=d.I_y_kgm2, T_phi_s=d.T_phi, nu=d.nu,
               reb_factor=d.reb_factor, h_n_m=d.h_n_m, zdd_over_g=d.zdd_over_g, i_a=d.i_a, p_max_MPa=d.p_max,
               d_rod_mm=d.d_rod)
    assert got == given
    defaults = dict(P_st_N=bar.P_st, R_b_mm=bar.R_b, beta_st_deg=bar.beta_st_deg, d_T_mm=bar.d_T, L_T_mm=bar.L_T,
                    G_MPa=bar.G, G_p_N=lib.G_p, I_y_kgm2=lib.I_y_kgm2, T_phi_s=lib.T_phi, nu=lib.nu,
                    reb_factor=lib.reb_factor, h_n_m=lib.h_n_m, zdd_over_g=lib.zdd_over_g, i_a=lib.i_a,
                    p_max_MPa=lib.p_max, d_rod_mm=lib.d_rod)
    assert all(defaults[k] != v for k, v in given.items())  # each one told apart from the default
