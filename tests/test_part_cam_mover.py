"""Part `cam_mover` (seed 001): the fixed-cam propulsor built end to end through the CLI,
its acceptance items asserted on the OUTPUT files."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from propulsor import policy
from propulsor.checks.motion import Pose, sweep_pair
from propulsor.cli import main
from propulsor.export.dxf import read_dxf, read_dxf_loops
from propulsor.export.step import read_step_solids, step_product_names
from propulsor.export.tables import read_csv
from propulsor.geometry.profile import circle_loop
from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion
from propulsor.params import load_params
from propulsor.parts.cam_mover import CamMoverParams, plan

ROOT = Path(__file__).resolve().parents[1]
PART = ROOT / "parts" / "cam_mover.toml"
MECH = CamMechanism()  # the part file's mechanism: R0 = 90, r = 20, C = 210 mm, 4 legs
S = math.pi / 4


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("cam") / "cam_mover"
    rc = main(["build", str(PART), "--out", str(out), "-q"])
    manifest = json.loads((out / "manifest.json").read_text()) if out.is_dir() else None
    return rc, out, manifest


@pytest.fixture(scope="module")
def motion(built):
    """The roller-centre path of the chosen law, recomputed from the manifest with the library."""
    d = built[2]["derived"]
    return cam_motion(MECH, CurvatureLaw(d["law_kind"], d["k0"], d["k1"], symmetric=d["symmetric_law"]),
                      estimate_error=False)


def _table(path):
    head, rows = read_csv(path)
    return {h: [r[i] for r in rows] for i, h in enumerate(head)}


def _f(col):
    return np.array([float(x) for x in col])


# ------------------------------------------------------------------ build, manifest


def test_build_succeeds_and_every_check_passes(built):
    rc, out, man = built
    assert rc == 0
    assert man["part"] == "cam_mover"
    failed = [c["name"] for c in man["checks"] if not c["passed"]]
    assert failed == []
    names = {c["name"] for c in man["checks"]}
    # the proofs are really there (a missing proof must not pass silently)
    for must in ("roller in channel: overlap with the working wall", "roller in channel: overlap with the outer wall",
                 "roller in channel: gap to the working wall", "roller in channel: clearance to the outer wall",
                 "hub height: variation over a support phase (exported shoe DXF)",
                 "collision: neighbouring legs + shoes: overlap", "collision: legs in their slides: overlap",
                 "collision: shoes vs carrier: overlap", "roller in channel (3D, exported meshes): overlap volume",
                 "law: ODE error of H (eq. 20)", "law: pressure angle (eq. 17)", "law: Hertz stress (eq. 14-15)",
                 "law: convex cam radius of curvature (eq. 16)", "law: eq. 9-10 profile points vs finite differences",
                 "law: eq. 16 radius vs finite-difference curvature"):
        assert must in names, must
    # acceptance 4: every solid passed the foundation's checks (B-rep, STEP round trip, mesh)
    for part in ("cam", "carrier", "leg", "roller", "shoe"):
        own = [c for c in man["checks"] if c["name"].startswith(f"{part}: ")]
        assert len(own) >= 8, part
        assert any("STEP round trip" in c["name"] for c in own)
        assert any("genus" in c["name"] for c in own)
        for ext in ("step", "stl", "3mf"):
            assert (out / f"{part}.{ext}").stat().st_size > 0


def test_manifest_numbers_within_limits(built):
    d = built[2]["derived"]
    assert d["H_error_mm"] <= 1e-6  # acceptance 2
    assert d["fd_profile_points_max_mm"] <= 1e-6
    assert d["gamma_max_deg"] <= 30.0
    assert d["R_convex_min_mm"] >= 1.5 * 20.0
    assert max(d["sigma_max_support_MPa"], d["sigma_max_return_MPa"]) <= 1500.0
    assert d["search_candidates"] >= 200 and d["search_feasible"] >= 1
    assert d["hub_height_variation_dxf_mm"] <= 0.01
    assert d["roller_overlap_max_mm2"] == 0.0
    assert 0.0 < d["roller_clearance_outer_mm"][0] <= d["roller_clearance_outer_mm"][1] < 0.3


# --------------------------------------------------------------- hub height on the DXF


def _hub_heights(motion, pts, phi, H_scale=1.0):
    """Lowest point of the shoes of all four legs, placed by the leg position H(φ)·(sin φ, cos φ)
    (seed frame, Y down): depth of a leg-frame point = (H + Y)·cos φ + X·sin φ."""
    out = np.empty(len(phi))
    for k, p in enumerate(phi):
        a = p + np.arange(4) * math.pi / 2
        H = motion.H_derivs(a)[0] * H_scale
        dep = (H[:, None] + pts[None, :, 1]) * np.cos(a)[:, None] + pts[None, :, 0] * np.sin(a)[:, None]
        out[k] = dep.max()
    return out


def test_hub_height_constant_on_exported_shoe_dxf(built, motion):
    """Acceptance 3: the shoe outline READ BACK from shoe.dxf, placed at 721 carrier angles of
    a support phase, keeps the hub within 0.01 mm of R0 + r + C; the check can fail."""
    loops = read_dxf_loops(built[1] / "shoe.dxf")
    assert len(loops) == 1
    pts = loops[0]
    phi = np.linspace(-S, S, 721)
    hh = _hub_heights(motion, pts, phi)
    assert np.ptp(hh) <= 0.01
    assert np.max(np.abs(hh - 320.0)) <= 0.01
    # the part's own table says the same
    t = _table(built[1] / "tables" / "hub_height.csv")
    assert len(t["phi_deg"]) >= 720 and np.ptp(_f(t["hub_height_dxf_mm"])) <= 0.01
    # can fail: a cam path 0.5 % off, or the outline of another law, moves the hub by far more
    assert np.ptp(_hub_heights(motion, pts, phi, H_scale=1.005)) > 0.05
    other = plan(CamMoverParams(law="quadratic", k0=0.017)).shoe.profile.outer.polyline(0.005)
    assert np.ptp(_hub_heights(motion, other, phi)) > 0.05


# -------------------------------------------------------------------- roller sweep


def test_roller_sweep_table_covers_a_turn_without_overlap(built):
    t = _table(built[1] / "tables" / "roller_sweep.csv")
    phi = _f(t["phi_deg"])
    assert len(phi) >= 720 and phi[0] == 0.0 and 359.0 <= phi[-1] < 360.0
    assert np.all(_f(t["overlap_working_mm2"]) == 0.0) and np.all(_f(t["overlap_outer_mm2"]) == 0.0)
    gap, clr = _f(t["gap_working_wall_mm"]), _f(t["clearance_outer_wall_mm"])
    assert np.all(gap >= 0.0) and np.all(gap <= policy.CHORD_TOL_MM)  # rolling contact
    assert np.all(clr > 0.19) and np.all(clr < 0.21)  # channel clearance 0.2 mm kept


def test_roller_in_exported_channel_independent_sweep(built, motion):
    """Re-sweep on the DXF: a roller of radius r at H(φ) touches nothing; the check can fail."""
    loops = read_dxf_loops(built[1] / "cam_channel.dxf")
    assert len(loops) == 10  # rim, outer wall, working wall, bore, 6 holes
    phi = np.linspace(0.0, 2 * math.pi, 240, endpoint=False)
    H = motion.H_derivs(phi)[0]
    centres = np.column_stack([H * np.sin(phi), -H * np.cos(phi)])  # CAD frame, y up
    poses = [Pose(0.0, (0.0, 0.0), tuple(c)) for c in centres]
    res = sweep_pair(loops, Pose(), [circle_loop(20.0).polyline(1e-4)], poses, max_segment=0.5)
    assert res.max_overlap == 0.0
    assert 0.0 <= res.min_clearance <= policy.CHORD_TOL_MM
    big = sweep_pair(loops, Pose(), [circle_loop(20.25).polyline(1e-4)], poses[::8], max_segment=0.5)
    assert big.max_overlap > 1e-3  # wider than the channel: it must show
    low = [Pose(0.0, (0.0, 0.0), tuple(c * (1 - 0.02 / np.linalg.norm(c)))) for c in centres[::8]]
    assert sweep_pair(loops, Pose(), [circle_loop(20.0).polyline(1e-4)], low, max_segment=0.5).max_overlap > 1e-4


# ------------------------------------------------------------------------ files


def test_dxf_closed_loops_mm(built):
    out = built[1]
    for name, n_loops in (("cam_channel", 10), ("shoe", 1), ("carrier", 1 + 1 + 4)):
        info = read_dxf(out / f"{name}.dxf")
        assert info["insunits"] == 4
        cut = info["layers"]["CUT"]
        assert cut["open"] == [] and len(cut["loops"]) == n_loops, name
        for q in cut["loops"]:
            assert len(q) >= 3 and np.all(np.isfinite(q))


def test_assembly_step_names_and_solids(built):
    """One assembly: cam, carrier, and per leg a leg, a roller, a shoe (the identical parts
    as instances of one product each, every occurrence named)."""
    a = built[1] / "assembly.step"
    assert {"cam", "carrier"} <= set(step_product_names(a))
    occ = re.findall(r"NEXT_ASSEMBLY_USAGE_OCCURRENCE\('\d+','([^']*)'", a.read_text(encoding="latin-1"))
    assert sorted(occ) == sorted(["cam", "carrier"] + [f"{k}_{j}" for k in ("leg", "roller", "shoe")
                                                        for j in range(1, 5)])
    assert len(read_step_solids(a)) == 14


def test_tables_follow_seed_formulas(built):
    """Seed 001 eq. 7, 12, 13 on shoe.csv; limits on cam_law.csv; eq. 16 against finite
    differences of the profile columns (eq. 9) of the CSV itself."""
    out = built[1]
    sh = _table(out / "tables" / "shoe.csv")
    phi = np.radians(_f(sh["phi_deg"]))
    H, Y1, Y2, XB, YB = (_f(sh[k]) for k in ("H_mm", "Y1_mm", "Y2_mm", "X_B_mm", "Y_B_mm"))
    assert len(phi) == 181
    assert np.allclose((H + Y1) * np.cos(phi) + Y2, 320.0, atol=1e-9)  # eq. 7
    assert np.allclose(XB, Y2 * np.sin(phi), atol=1e-9) and np.allclose(YB, Y1 + Y2 * np.cos(phi), atol=1e-9)
    assert np.allclose(_f(sh["rho_mm"]), np.hypot(XB, YB), atol=1e-9)  # eq. 13
    assert np.allclose(np.radians(_f(sh["alpha_deg"])), np.arctan(XB / YB), atol=1e-12)  # eq. 12
    cl = _table(out / "tables" / "cam_law.csv")
    g = _f(cl["gamma_deg"])
    assert np.max(np.abs(g)) <= 30.0
    K, R, sig = _f(cl["K_path_per_mm"]), _f(cl["R_profile_mm"]), _f(cl["sigma_H_MPa"])
    assert np.all(R[K > 0] >= 30.0) and np.max(sig) <= 1500.0
    assert np.allclose(np.radians(g), np.arctan(_f(cl["dH_mm_per_rad"]) / _f(cl["H_mm"])), atol=1e-12)  # eq. 17
    X, Y = _f(cl["X_mm"]), _f(cl["Y_mm"])
    h = math.radians(0.5)
    w1 = np.array([1, -8, 0, 8, -1]) / (12 * h)
    w2 = np.array([-1, 16, -30, 16, -1]) / (12 * h * h)
    i = np.arange(10, 80)  # inside the support phase (−45° + 5° .. −5.5°), away from the joints
    win = i[:, None] + np.arange(-2, 3)[None, :]
    x1, y1, x2, y2 = X[win] @ w1, Y[win] @ w1, X[win] @ w2, Y[win] @ w2
    kfd = -(x1 * y2 - y1 * x2) / (x1 ** 2 + y1 ** 2) ** 1.5
    assert np.max(np.abs(1 / kfd - R[i]) / R[i]) <= 1e-4


def test_design_search_table(built):
    t = _table(built[1] / "tables" / "design_search.csv")
    assert len(t["rank"]) >= 200
    assert t["feasible"][0] == "true" and t["violations"][0] == ""
    d = built[2]["derived"]
    assert float(t["k0"][0]) == d["k0"] and float(t["k1"][0]) == d["k1"] and t["law"][0] == d["law_kind"]
    feas = _f([v for v, f in zip(t["hub_speed_variation_pct"], t["feasible"]) if f == "true"])
    assert feas[0] == feas.min()
    assert (built[1] / "plots" / "design_search.png").stat().st_size > 0


# ------------------------------------------------------------------- K = 0, laws


def test_zero_curvature_part_geometry_is_closed_form():
    """Acceptance 1 on the part's outlines: K = 0 → the roller-centre path is the straight
    line at H0 below the axle (H = H0/cos φ) and the shoe ground curve is the circle of
    radius C about the roller axle."""
    pl = plan(CamMoverParams(law="zero", carrier_radius_mm=300.0))  # K = 0 lifts the return phase high
    phi = np.linspace(-S, S, 201)
    H = pl.motion.H_derivs(phi)[0]
    assert np.max(np.abs(H - 110.0 / np.cos(phi))) <= 1e-7
    path = np.vstack([seg.sample(1e-4) for seg in pl.path.segments[:2]])
    assert np.max(np.abs(path[:, 1] + 110.0)) <= 1e-5  # spline of the path: y = −H0 (CAD frame)
    ground = np.vstack([seg.sample(1e-4) for seg in pl.shoe.curve])
    assert np.max(np.abs(np.hypot(ground[:, 0], ground[:, 1]) - 210.0)) <= 1e-5
    assert np.ptp(np.hypot(ground[:, 0], ground[:, 1])) <= 2e-5


def test_channel_walls_are_eq9_envelopes_within_fit_tolerance():
    """The B-spline walls of the cam (the STEP edges) follow eq. 9-10 within the fit tolerance,
    and the channel is 2r + clearance wide: working wall at r, outer wall at r + c."""
    from propulsor.geometry.bspline import spline_deviation

    pl = plan(CamMoverParams(law="quadratic", k0=0.017))
    bounds = [-S, 0.0, S, math.pi, 2 * math.pi - S]

    def wall(u):
        t = pl.motion.table(u)
        return np.column_stack([t.X, -t.Y])  # seed frame (Y down) → CAD frame

    for seg, a, b in zip(pl.working.segments, bounds[:-1], bounds[1:]):
        assert spline_deviation(seg, wall, a, b, n=400) <= policy.SPLINE_FIT_TOL_MM
    from scipy.spatial import cKDTree

    phi = np.linspace(0, 2 * math.pi, 3000, endpoint=False)
    H = pl.motion.H_derivs(phi)[0]
    centres = np.column_stack([H * np.sin(phi), -H * np.cos(phi)])
    for loop, dist in ((pl.working, 20.0), (pl.outer, 20.2)):
        d, _ = cKDTree(loop.polyline(1e-5)).query(centres)
        assert np.max(np.abs(d - dist)) <= 2e-3  # nearest polyline vertex: spacing-limited
        assert np.min(d) >= dist - 2e-5


def test_carrier_outline_area_closed_form():
    """Carrier: disc R minus four radial slots (open at the rim), the bore and the holes."""
    p = CamMoverParams(law="quadratic", k0=0.017)
    car = plan(p).carrier
    R, h, b = p.carrier_radius_mm, car.slot_half_width, car.slot_bottom
    L = math.sqrt(R * R - h * h)
    slot = 2 * h * (L - b) + R * R * math.asin(h / R) - h * L
    expected = (math.pi * R * R - 4 * slot - math.pi * (p.carrier_bore_mm / 2) ** 2
                - p.carrier_bolt_count * math.pi * (p.carrier_bolt_hole_mm / 2) ** 2)
    assert car.profile.area(1e-5) == pytest.approx(expected, rel=1e-6)
    assert h == pytest.approx(p.leg_width_mm / 2 + p.slide_clearance_mm)


@pytest.mark.parametrize("name", ["cam_linear", "cam_quadratic", "cam_exponential"])
def test_law_files_integrate_within_1e6_mm(name):
    from propulsor.params import read_part_file

    t, mapping = read_part_file(ROOT / "parts" / f"{name}.toml")
    assert t == "cam_mover"
    p = load_params(CamMoverParams, mapping)  # validate() computes the whole plan
    pl = plan(p)
    assert pl.law.kind == name.split("_")[1] and pl.motion.H_error_mm <= 1e-6
    assert pl.evaluation["feasible"], pl.evaluation["violations"]


# ---------------------------------------------------------------------- bad input


@pytest.mark.parametrize("body, param, value", [
    ('law = "linear"\nk0 = 0.0093\nR0_mm = 50.0\nroller_radius_mm = 60.0\n', "roller_radius_mm", "60.0"),
    ('law = "linear"\nk0 = 0.005\nsymmetric_law = false\n', "k0", "0.005"),
    ('law = "quadratic"\nk0 = 1.0\n', "k0", "1.0"),
    ('law = "exponential"\nk0 = 0.005\nk1 = 8.0\n', "k0, k1", "(0.005, 8.0)"),
    ('law = "searched"\nk0 = 0.01\n', "k0", "0.01"),
    ('law = "linear"\nk0 = 0.0093\ncarrier_radius_mm = 120.0\n', "carrier_radius_mm", "120.0"),
], ids=["roller_vs_curvature", "shoe_cusp", "ode_blow_up", "ode_blow_up_exp", "k0_with_search", "leg_leaves_slide"])
def test_bad_input_exit_2_one_line_nothing_written(tmp_path, capsys, body, param, value):
    f = tmp_path / "bad.toml"
    f.write_text('type = "cam_mover"\n' + body)
    out = tmp_path / "out"
    assert main(["build", str(f), "--out", str(out), "-q"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"propulsor: error: {param} = {value}:")
    assert "must" in err[0] or "blows up" in err[0]
    assert not out.exists() and not any(p.name.startswith(".out") for p in tmp_path.iterdir())


def test_blow_up_message_names_the_limit():
    import propulsor

    with pytest.raises(Exception) as e:  # the plan's own refusal (parts.vet: validate(), then design.feasible)
        propulsor.parameters("cam_mover", law="quadratic", k0=1.0)
    assert "blows up" in str(e.value) and "45°" in str(e.value)


# --------------------------------------------------------------------------- sweep


@pytest.mark.sweep
@pytest.mark.parametrize("name", ["cam_linear", "cam_quadratic", "cam_exponential"])
def test_law_files_build(tmp_path, name):
    out = tmp_path / name
    assert main(["build", str(ROOT / "parts" / f"{name}.toml"), "--out", str(out), "-q"]) == 0
    d = json.loads((out / "manifest.json").read_text())["derived"]
    assert d["hub_height_variation_dxf_mm"] <= 0.01 and d["roller_overlap_max_mm2"] == 0.0


@pytest.mark.sweep
def test_build_is_deterministic(built, tmp_path):
    out = tmp_path / "again"
    assert main(["build", str(PART), "--out", str(out), "-q"]) == 0
    a = {f["path"]: f["sha256"] for f in built[2]["files"]}
    b = {f["path"]: f["sha256"] for f in json.loads((out / "manifest.json").read_text())["files"]}
    assert a == b


@pytest.mark.sweep
def test_failing_limit_exits_1_and_writes_nothing(tmp_path, capsys):
    """K = 0.0093·|φ| is buildable but its pressure angle (23.3°) exceeds a 20° limit: a failed
    check, exit 1, nothing written."""
    f = tmp_path / "steep.toml"
    f.write_text('type = "cam_mover"\nlaw = "linear"\nk0 = 0.0093\ngamma_max_deg = 20.0\n')
    out = tmp_path / "out"
    assert main(["build", str(f), "--out", str(out), "-q"]) == 1
    assert "law: pressure angle (eq. 17)" in capsys.readouterr().err
    assert not out.exists()


def test_walking_animation_at_the_proofs_poses(built, assert_animations):
    """The frames are carrier angles of the motion proof with the hub height it found there; the least
    clearance marked is the proof's least over the roller's outer wall, the slides, the carrier and the legs."""
    _, out, man = built
    (e,) = assert_animations(out, man, {"walking": ("roller_sweep", {"phi_deg": "phi_deg"})})
    _, rows = read_csv(out / "tables" / "anim_walking.csv")
    _, hub = read_csv(out / "tables" / "hub_height.csv")
    for r in rows:  # frame, proof_step, phi_deg, hub_height_mm, ...
        assert float(r[3]) == pytest.approx(float(hub[int(r[1])][3]), abs=1e-9)
    d = man["derived"]
    named = min(d["roller_clearance_outer_mm"][0], d["leg_slide_clearance_mm"][0], d["shoe_carrier_clearance_min_mm"],
                d["neighbour_clearance_min_mm"])
    assert 0 < e["least_clearance_mm"] <= named + 1e-12
    assert e["least_clearance_mm"] == pytest.approx(min(float(r[4]) for r in rows), abs=1e-12)


def test_every_derived_value_has_a_unit_and_a_meaning(built, assert_explained):
    assert_explained(built[1])
