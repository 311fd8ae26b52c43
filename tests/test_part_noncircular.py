"""The non-circular walking-drive pair (seeds 000, 002) end to end: build the part files through the
command line, then measure what was written — DXF frames and loops, transmission.csv, the
manifest's derived values and checks, the papers' tables — and the command line's contract
for bad input (exit 2, one line, nothing written).  Plus the library pieces the part adds
(shared arc-length frame, shaper generation on an external pitch curve)."""

from __future__ import annotations

import csv
import json
import math
import re
from pathlib import Path

import manifold3d as m3d
import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from propulsor.cli import main
from propulsor.export.dxf import read_dxf
from propulsor.gears.noncircular import PitchCurves, SmoothedWalkingLaw
from propulsor.laws.walking import SEED_002, WalkingLaw

ROOT = Path(__file__).resolve().parents[1]
PARTS = ROOT / "parts"


def _build(tmp_path_factory, name: str, text: str | None = None, extra: str = ""):
    """Build parts/<name>.toml (or the given TOML text) into a fresh folder; returns the folder."""
    base = tmp_path_factory.mktemp(name)
    src = PARTS / f"{name}.toml"
    if text is not None or extra:
        src_txt = text if text is not None else src.read_text()
        head, _, meta = src_txt.partition("[meta]")
        for line in extra.strip().splitlines():  # replace the key's line, or append it
            key = line.split("=")[0].strip()
            head, n = re.subn(rf"(?m)^{key}\s*=.*$", line, head)
            if not n:
                head += line + "\n"
        src = base / f"{name}.toml"
        src.write_text(head + ("\n[meta]" + meta if meta else ""))
    out = base / "out"
    rc = main(["build", str(src), "--out", str(out), "-q"])
    assert rc == 0
    return out


@pytest.fixture(scope="module")
def seed002(tmp_path_factory):
    return _build(tmp_path_factory, "ncg_seed002")


@pytest.fixture(scope="module")
def seed000(tmp_path_factory):
    # the comparison with the sector method is exercised by the seed 002 builds; skipped here for time
    return _build(tmp_path_factory, "ncg_seed000", extra="compare_methods = false\n")


@pytest.fixture(scope="module")
def table002(tmp_path_factory):
    return _build(tmp_path_factory, "ncg_seed002_table")


def _manifest(out: Path) -> dict:
    return json.loads((out / "manifest.json").read_text())


def _csv(path: Path) -> tuple[list[str], list[list[str]]]:
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    return rows[0], rows[1:]


# --------------------------------------------------------------------------- generated pairs
SEED000_FULL = pytest.param("seed000", marks=pytest.mark.sweep)  # the full seed 000 build: ~40 s


@pytest.mark.parametrize("which", ["seed002", SEED000_FULL])
def test_generated_pair_manifest(which, request):
    out = request.getfixturevalue(which)
    m = _manifest(out)
    assert m["part"] == "noncircular_pair" and m["passed"] is True
    assert [c["name"] for c in m["checks"] if not c["passed"]] == []
    d = m["derived"]
    for key in ("center_distance_mm", "module_mm", "driver_teeth", "driven_teeth", "driver_turns", "method",
                "smoothing_deg", "speed_ripple"):
        assert key in d
    assert d["method"] == "generated"
    n, z, zH = (4, 20, 80) if which == "seed002" else (2, 48, 96)
    assert (d["driver_turns"], d["driver_teeth"], d["driven_teeth"]) == (n, z, zH)
    # acceptance 2: exactly n driver turns per driven turn, no overlap at any of >= 4 phases per tooth
    assert d["closure_error_rad"] < 1e-9
    assert d["proof_phases"] >= 4 * zH
    assert d["overlap_law_max_mm2"] == 0.0 and d["overlap_law_phases"] == 0 and d["jam_phases"] == 0
    # backlash around j_n / cos(alpha) = 0.170 mm, contact never lost
    assert 0.10 < d["backlash_min_mm"] < 0.170 < d["backlash_max_mm"] < 0.25
    assert d["contact_pairs_min"] >= 1 and d["contact_ratio_mean"] > 1.2
    # transmission error of the loaded flank: about half the backlash angle, small spread
    assert -2e-3 < d["te_min_rad"] < d["te_max_rad"] < 0.0 and d["te_pp_rad"] < 1e-3
    names = {c["name"] for c in m["checks"]}
    for solid in ("driver", "driven"):
        for what in ("BRepCheck_Analyzer valid", "STEP round trip", "genus", "self-intersecting triangle pairs",
                     "volume vs B-rep", "edges not shared by exactly 2 faces"):
            assert f"{solid}: {what}" in names
    assert {"mesh.overlap_area", "mesh.backlash_min", "mesh.contact_continuity", "law.closure_error",
            "teeth.driver_undercut", "generability.driver_rho_min"} <= names
    paths = {f["path"] for f in m["files"]}
    assert {"driver.step", "driver.stl", "driver.3mf", "driver.dxf", "driven.step", "driven.stl", "driven.3mf",
            "driven.dxf", "pair.step", "tables/transmission.csv", "tables/sectors.csv", "tables/radii.csv",
            "tables/driver_teeth.csv", "tables/driven_spaces.csv", "plots/figure2_ratio.png",
            "report.md"} <= paths


def test_seed002_numbers(seed002):
    d = _manifest(seed002)["derived"]
    # issue 10: the law search's least-ripple blend with a catalogue shaper (d0 25 mm, z0 10, own x0);
    # binding: the driver's convex end at the rack undercut limit; the former blend gave 2.94 %
    assert d["speed_ripple"] <= 0.025 and d["speed_ripple"] == pytest.approx(0.02456, abs=2e-4)
    assert d["smoothing_deg"] == pytest.approx(8.0, abs=1e-9)
    assert d["speed_ripple"] < d["compare_sectors_speed_ripple"]  # beats the papers' staircase (8.3 %)
    assert d["center_distance_mm"] == pytest.approx(124.2714, abs=1e-3)
    assert d["module_mm"] == 2.5
    assert (d["shaper_d0_mm"], d["shaper_z0"], d["shaper_x0"]) == (25.0, 10, 0.0)
    assert d["law_search_binding"] == "driver convex vs rack undercut limit"
    assert d["root_bridge_max_mm"] <= 0.1 * 2.5
    assert d["undercut_teeth"] == 0 and d["shaper_cut_teeth"] > 0
    report = (seed002 / "report.md").read_text()
    assert "Law search" in report and "2.46 %" in report and "sector method (ideal teeth) 8.27 %" in report
    cols, rows = _csv(seed002 / "tables" / "law_search.csv")
    assert cols[:3] == ["rank", "shaper_d0_mm", "z0"] and len(rows) == d["law_search_points"]
    assert [r[-1] for r in rows].count("built") == 1
    assert (seed002 / "plots" / "law_search_front.png").stat().st_size > 10_000


def test_seed000_generated_pair_proof():
    """ncg_seed000.toml without solids: the broad blend seed 000 needs at m = 2, closure, and the
    full-cycle proof (overlap 0 at every one of 4 x 96 phases, backlash, contact); the complete
    build with solids and files is the sweep-marked test_generated_pair_manifest[seed000]."""
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams, design, prove

    _, mapping = read_part_file(PARTS / "ncg_seed000.toml")
    p = load_params(NoncircularPairParams, mapping)
    d = design(p)
    # issue 10: the law search's least-ripple blend that the tooth generator can cut (catalogue shaper
    # d0 25 mm, z0 12, own x0); the former single-width blend gave 12.3 %, the papers' method 13.2 %
    assert d.ripple.ripple <= 0.08 and d.ripple.ripple == pytest.approx(0.0787, abs=5e-4)
    assert d.smoothing_deg == pytest.approx(6.0, abs=1e-9) and d.shaper.d0_mm == 25.0 and d.shaper.z0 == 12
    assert d.L == pytest.approx(138.738, abs=1e-3)
    assert (d.z, d.z_H) == (48, 96) and d.closure_error < 1e-9
    assert d.driver.undercut_teeth == 0 and d.driven.undercut_teeth == 0
    pr = prove(d, p.proof_phases_per_tooth, 4)
    s = pr.summary()
    assert s["steps"] == 4 * 96 and s["overlap_law_max_mm2"] == 0.0 and s["jams"] == 0
    assert 0.10 < s["backlash_min_mm"] < 0.170 < s["backlash_max_mm"] < 0.25
    assert s["contact_pairs_min"] >= 1 and -2e-3 < s["te_min_rad"] < s["te_max_rad"] < 0.0
    # as built: the driver's tips cut to 1.2 m (tip_height_max_module) clear the driven wheel's notches; both
    # directions resolved by contact events over one leg (the uncut tips: test_seed000_uncut_tips_... below)
    from propulsor.parts.noncircular_pair.as_built import as_built
    from propulsor.parts.noncircular_pair.as_built_outputs import as_built_checks, tooth_height_check

    ab = as_built(d, d.L, pr)
    assert ab.ripple == pytest.approx(0.0834, abs=5e-4) and ab.ripple <= 0.085
    assert ab.ripple <= d.ripple.ripple + p.as_built_ripple_margin
    assert ab.step_max < 0.005 and 0.99 < ab.speed_min < ab.speed_max < 1.006
    assert ab.drive.te_pp == pytest.approx(7.18e-4, rel=0.02) and ab.reverse.te_pp == pytest.approx(7.18e-4, rel=0.02)
    assert ab.backlash_min_mm == pytest.approx(s["backlash_min_mm"], abs=0.005)
    assert all(c.passed for c in as_built_checks(ab, p, d.ripple.ripple)), as_built_checks(ab, p, d.ripple.ripple)
    assert tooth_height_check(d, p).passed
    assert [t.tip_height_mm for t in d.driver.teeth] == pytest.approx([2.4] * 48)  # 1.2 m, not (1 + 0.5) m


def test_seed000_uncut_tips_touch_the_notches_outside_the_line_of_action():
    """Mutation of the cure (tip_height_max_module = 0: the driver's tips (1 + 0.5) m high): at driver 96.67 ..
    98.75 deg of each leg a driver tip corner pushes shortened driven tooth 10 10 deg off the line of centres (the
    driven wheel 5 % fast), then that tooth's corner slides down the driver's flank (61 % of the law's speed);
    the step of 43.7 % at the hand-over and the run on a corner fail their checks, which name where."""
    import dataclasses

    from propulsor.checks.motion.contact_events import DRIVE, REVERSE
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams, design
    from propulsor.parts.noncircular_pair.as_built import combine, pair_outlines
    from propulsor.parts.noncircular_pair.as_built_outputs import as_built_checks, tooth_height_check
    from propulsor.checks.motion.contact_events import resolve_contact

    _, mapping = read_part_file(PARTS / "ncg_seed000.toml")
    p = dataclasses.replace(load_params(NoncircularPairParams, mapping), tip_height_max_module=0.0)
    d = design(p)
    po = pair_outlines(d, d.L)
    drive, reverse = (resolve_contact(po, d.run_law.theta, 0.86, 0.90, k) for k in (DRIVE, REVERSE))
    assert drive.speed_min == pytest.approx(0.610, abs=0.005) and drive.speed_max == pytest.approx(1.053, abs=0.003)
    assert drive.step_max == pytest.approx(0.437, abs=0.01)
    (st,) = [s for s in drive.stretches() if s.speed_min < 0.9]
    assert st.theta_from_deg == pytest.approx(96.67, abs=0.05) and st.theta_to_deg == pytest.approx(98.75, abs=0.05)
    assert 10 in st.driven_teeth and "driver tip corner" in st.kinds
    ab = combine(d, drive, reverse)
    checks = {c.name: c for c in as_built_checks(ab, p, d.ripple.ripple)}
    assert not checks["as_built.speed_step"].passed and "drive 43.7" in checks["as_built.speed_step"].message
    assert not checks["as_built.corner_load"].passed and checks["as_built.corner_load"].value > 1.5
    assert not checks["as_built.hub_speed_ripple"].passed and ab.ripple > 0.4
    # a stated share of the addendum: the shaper-cut driven teeth keep 0.356 .. 0.417 of it, mirror teeth alike (teeth
    # 11 and 12 of the leg 0.356, 9 and 14 0.417); asked for 0.4, those below are named, those above are not
    th = tooth_height_check(d, dataclasses.replace(p, tooth_height_min_share=0.4))
    assert not th.passed and th.value == pytest.approx(0.3563, abs=0.0005)
    assert "driven 11 (0.356)" in th.message and "driven 12 (0.356)" in th.message
    assert "driven 9 (" not in th.message and "driven 14 (" not in th.message


def _outer_and_holes(loops):
    """Split DXF loops into outer loops (not inside another) and holes."""
    outer, holes = [], []
    for i, p in enumerate(loops):
        inside = any(m3d.CrossSection([q]).area() > 0 and _point_in(p[0], q) for j, q in enumerate(loops) if j != i)
        (holes if inside else outer).append(p)
    return outer, holes


def _point_in(pt, poly) -> bool:
    x, y = pt
    a, b = poly, np.roll(poly, -1, axis=0)
    cond = (a[:, 1] > y) != (b[:, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xi = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return bool(np.count_nonzero(cond & (x < xi)) % 2)


def _area(p) -> float:
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


@pytest.mark.parametrize("which", ["seed002", SEED000_FULL])
def test_dxf_frames_contract(which, request):
    """driver.dxf / driven.dxf: mm, one closed outer loop per gear (plus the bore), gear axis at the
    origin, phase phi = theta = 0: placed at (0, 0) and (L, 0) the two outlines mesh without overlap."""
    out = request.getfixturevalue(which)
    d = _manifest(out)["derived"]
    L = d["center_distance_mm"]
    loops = {}
    for role in ("driver", "driven"):
        info = read_dxf(out / f"{role}.dxf")
        assert info["insunits"] == 4
        cut = info["layers"]["CUT"]
        assert cut["open"] == []
        outer, holes = _outer_and_holes(cut["loops"])
        assert len(outer) == 1 and len(holes) == 1
        loops[role] = outer[0]
        # the axis is the origin: the bore (a circle with a keyway) is around it
        assert _point_in((0.0, 0.0), holes[0])
        ref = info["layers"]["REF"]["loops"]
        assert len(ref) == 1  # the closed pitch curve
        loops[role + "_pitch"] = ref[0]
    _, rows = _csv(out / "tables" / "pitch_curves.csv")
    phi0 = [r for r in rows if float(r[0]) == 0.0][0]
    rH0, r0 = float(phi0[1]), float(phi0[3])
    assert rH0 + r0 == pytest.approx(L, abs=1e-9)
    # the driven pitch point of phi = 0 on +x at r_H(0); the driver's of theta = 0 on -x at r(0)
    pd = loops["driven_pitch"]
    assert np.min(np.linalg.norm(pd - [rH0, 0.0], axis=1)) < 1e-9
    pr = loops["driver_pitch"]
    assert np.min(np.linalg.norm(pr - [-r0, 0.0], axis=1)) < 1e-9
    # in mesh at phi = theta = 0: no overlap, and in contact within the backlash
    a = m3d.CrossSection([loops["driven"]])
    b = m3d.CrossSection([loops["driver"] + [L, 0.0]])
    assert (a ^ b).area() < 1e-6
    from scipy.spatial import cKDTree

    gap = cKDTree(loops["driven"]).query(loops["driver"] + [L, 0.0])[0].min()
    assert gap < 0.2
    # the outer loops are the gears, counter-clockwise in the file or not: areas positive either way
    assert abs(_area(loops["driven"])) > abs(_area(loops["driver"])) > 0


def test_transmission_csv(seed002):
    header, rows = _csv(seed002 / "tables" / "transmission.csv")
    assert header[:3] == ["phi_rad", "theta_law_rad", "theta_actual_rad"]
    a = np.array([[float(v) for v in r[:3]] for r in rows])
    phi, th_law, th_act = a.T
    assert len(rows) == 4 * 80
    assert phi[0] == 0.0 and np.all(np.diff(phi) > 0) and phi[-1] < 2 * math.pi
    # the smoothed law of the manifest, independently: closure exact, theta(2 pi) = 2 pi n
    d = _manifest(seed002)["derived"]
    law = WalkingLaw(**SEED_002)
    u_h = d["blend_u_h_over_u"] * law.u if "blend_u_h_over_u" in d else None  # the law search's hand-over value
    sl = SmoothedWalkingLaw(law, d["smoothing_rad"], u_h=u_h)
    assert np.allclose(th_law, sl.theta(phi), atol=1e-12)
    assert abs(float(sl.theta(2 * math.pi)) - 8 * math.pi) < 1e-9
    # the teeth deliver the law to a fraction of a tooth: |theta_actual - theta_law| < 1 mrad * U
    err = th_act - th_law
    assert np.all(np.abs(err) < 5e-3) and np.ptp(err) < 2e-3
    # theta_actual lags: the loaded flank touches after the backlash is taken up
    assert np.all(err > 0)


def test_figure2_and_notes(seed002, table002):
    for out in (seed002, table002):
        assert (out / "plots" / "figure2_ratio.png").stat().st_size > 10_000
        report = (out / "report.md").read_text()
        assert "Comparison with the" in report


# --------------------------------------------------------------------------- the papers' case
def test_paper_tables_in_the_output(table002):
    """Acceptance 1 on the files: every printed row of Tables 1-4 of seed 002."""
    import test_sectors as ts

    def check(name, text, key_cols):
        header, rows = _csv(table002 / "tables" / f"{name}.csv")
        by_key = {tuple(int(r[header.index(k)]) for k in key_cols): r for r in rows}
        printed = ts.parse_printed_table(text)
        for cells in printed:
            key = tuple(int(c[0]) for c in cells[:len(key_cols)])
            row = by_key[key]
            for col, cell in zip(header[len(key_cols):], cells[len(key_cols):]):
                v = row[header.index(col)]
                ts.assert_printed(None if v in ("", "nan") else float(v), cell, f"{name} {key} {col}")
        return len(printed)

    assert check("sectors", ts.TABLE1_SEED002, ["i"]) == 20
    assert check("driver_teeth", ts.TABLE3_SEED002, ["i", "j"]) == 50
    assert check("driven_spaces", ts.TABLE4_SEED002, ["i", "j"]) == 60
    header, rows = _csv(table002 / "tables" / "radii.csv")
    printed = ts.parse_printed_table(ts.TABLE2_SEED002)
    assert len(rows) == len(printed) == 20
    for r, cells in zip(rows, printed):
        for col, cell in zip(header[1:], cells[1:]):
            ts.assert_printed(float(r[header.index(col)]), cell, f"radii {r[0]} {col}")


def test_paper_case_proof_and_price(table002):
    m = _manifest(table002)
    d = m["derived"]
    assert d["method"] == "sectors" and d["center_distance_mm"] == 125.0 and d["smoothing_deg"] == 0.0
    assert d["sector_arc_mm"] == pytest.approx(7.8346, abs=5e-5)
    assert d["speed_ripple"] == pytest.approx(0.083, abs=0.002)
    # the papers' teeth are not conjugate: they interfere at the law's positions and, on these
    # outlines, find no free position (documented expected failures, the build still succeeds)
    assert d["overlap_law_max_mm2"] > 0.1 and d["jam_phases"] > 0
    failed = {c["name"] for c in m["checks"] if not c["passed"]}
    assert failed <= {"sectors.runs_without_jam", "sectors.backlash_min", "sectors.contact_continuity"}
    assert not any(n.startswith("mesh.") for n in failed)
    # the generated comparison runs free
    assert d["compare_generated_jam_phases"] == 0 and d["compare_generated_overlap_law_max_mm2"] == 0.0
    assert all(c["passed"] for c in m["checks"] if ":" in c["name"])  # every solid check


def test_seed002_file_builds_with_the_sector_method(tmp_path_factory):
    """Acceptance 2: the part file builds with either method (its documented expected failures
    cover the papers' jams; generated checks are named mesh.* and stay enforced)."""
    out = _build(tmp_path_factory, "ncg_seed002", extra='method = "sectors"\ncompare_methods = false\n')
    m = _manifest(out)
    d = m["derived"]
    assert d["method"] == "sectors" and d["driver_teeth"] == 20 and d["driven_teeth"] == 80
    # L from the module: sector arc = pi m
    assert d["sector_arc_mm"] == pytest.approx(math.pi * 2.5, rel=1e-12)
    assert d["closure_error_rad"] < 1e-9
    assert {c["name"] for c in m["checks"] if not c["passed"]} <= {
        "sectors.runs_without_jam", "sectors.backlash_min", "sectors.contact_continuity"}
    assert (out / "driver.step").exists() and (out / "tables" / "transmission.csv").exists()


@pytest.mark.sweep
def test_seed000_file_builds_with_the_sector_method(tmp_path_factory):
    out = _build(tmp_path_factory, "ncg_seed000", extra='method = "sectors"\ncompare_methods = false\n')
    d = _manifest(out)["derived"]
    assert d["method"] == "sectors" and (d["driver_teeth"], d["driven_teeth"]) == (48, 96)


@pytest.mark.sweep
def test_seed000_paper_case(tmp_path_factory):
    """Table 1 of seed 000 from the output of its part file; the seed's installation distance."""
    import test_sectors as ts

    out = _build(tmp_path_factory, "ncg_seed000_table")
    header, rows = _csv(out / "tables" / "sectors.csv")
    printed = ts.parse_printed_table(ts.TABLE1_SEED000)
    assert len(rows) == len(printed) == 24
    for r, cells in zip(rows, printed):
        for col, cell in zip(header[1:], cells[1:]):
            ts.assert_printed(float(r[header.index(col)]), cell, f"sectors {r[0]} {col}")
    d = _manifest(out)["derived"]
    assert d["center_distance_mm"] == 143.5 and d["mounting_distance_mm"] == 144.0
    assert d["compare_generated_jam_phases"] == 0


# --------------------------------------------------------------------------- bad input
BASE = """type = "noncircular_pair"
a_mm = 100.0
b_mm = 50.0
c_mm = 236.5
driver_turns = 4
module_mm = 2.5
driven_teeth = 80
"""


@pytest.mark.parametrize("change, param", [
    ("a_mm = 10.0\nb_mm = 300.0\n", "a_mm - b_mm + c_mm"),   # a - b + c <= 0: the law is not positive
    ("c_mm = -5.0\n", "c_mm"),                               # a negative length
    ("driver_turns = 0\n", "driver_turns"),
    ("driver_turns = 3\n", "driver_turns"),
    ("module_mm = nan\n", "module_mm"),
    ("driven_teeth = 82\n", "driven_teeth"),                 # not a multiple of n = 4
    ("method = \"sectors\"\ncenter_distance_mm = 125.0\nmodule_mm = 4.0\n", "module_mm"),  # pointed sector teeth
    ("method = \"sectors\"\ncenter_distance_mm = 125.0\nmodule_mm = 4.0\n", "pointed"),
    ("driver_shift = 1.2\n", "driver_shift"),                # the shaper for the driven wheel (x0 = 1.2) is pointed
    ("center_distance_mm = 124.0\n", "center_distance_mm"),  # module and L both given for generated teeth
])
def test_bad_input_exit_2_one_line_nothing_written(tmp_path, capsys, change, param):
    lines = dict(l.split(" = ", 1) for l in BASE.strip().splitlines())
    for l in change.strip().splitlines():
        k, v = l.split(" = ", 1)
        lines[k] = v
    f = tmp_path / "bad.toml"
    f.write_text("\n".join(f"{k} = {v}" for k, v in lines.items()) + "\n")
    out = tmp_path / "out"
    rc = main(["build", str(f), "--out", str(out), "-q"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2
    assert len(err) == 1 and param in err[0]
    assert not out.exists()
    assert [p.name for p in tmp_path.iterdir()] == ["bad.toml"]


def test_seed000_unshifted_refused_with_numbers(tmp_path, capsys):
    """Acceptance 3: no generable smoothing -> exit 2 with the curvature needed, the undercut limit,
    and what would work (shift, teeth, module, a wider blend)."""
    f = tmp_path / "s000.toml"
    f.write_text((PARTS / "ncg_seed000.toml").read_text().replace("driver_shift = 0.5", "driver_shift = 0.0")
                 .replace("law_search = true", "law_search = false"))
    rc = main(["build", str(f), "--out", str(tmp_path / "out"), "-q"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1
    msg = err[0]
    for piece in ("rho_min 12.98", "undercut limit 17.097", "driver_shift >= 0.24", "driven_teeth >= 128", "module_mm <= 1.519",
                  "blend of 29.7", "ripple 16.2"):
        assert piece in msg, piece
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("part, change, param", [
    ("ncg_seed000", {"center_distance_band_mm": "0.01"}, "center_distance_band_mm = 0.01: no blend keeps both"),
    ("ncg_seed002", {"law_search": "false", "smoothing_deg": "3.0"}, "smoothing_deg = 3.0: the pitch curves are not"),
    ("ncg_seed000", {"law_search": "false", "smoothing_max_deg": "6.0"}, "smoothing_max_deg = 6.0: no C2 smoothing"),
    ("ncg_seed000", {"law_search": "false", "shaper_teeth": "60"}, "needs a shaper with shaper_teeth <= 21"),
    ("ncg_seed002", {"module_mm": "0.3"}, "module_mm = 0.3: the cutter catalogue lists no shaper"),
    ("ncg_seed002", {"mounting_distance_mm": "100.0"}, "mounting_distance_mm = 100.0: must be >= the design"),
])
def test_dry_run_refuses_what_the_build_refuses(tmp_path, capsys, part, change, param):
    """Files the dry run called valid and the build refused seconds later: the dry run runs the same screen
    (generability of the blend, the law search's band, the catalogue shaper at the module, the shaper a
    concave stretch needs, the installed centre distance) and prints the build's own line; nothing written."""
    text = (PARTS / f"{part}.toml").read_text()
    for k, v in change.items():
        text, n = re.subn(rf"(?m)^{k}\s*=.*$", f"{k} = {v}", text)
        if not n:
            text = text.replace("[meta]", f"{k} = {v}\n\n[meta]", 1)
    f = tmp_path / "bad.toml"
    f.write_text(text)
    out = tmp_path / "out"
    lines = []
    for extra in (["--dry-run"], []):
        rc = main(["build", str(f), "--out", str(out), "-q", *extra])
        err = capsys.readouterr().err.strip().splitlines()
        assert rc == 2 and len(err) == 1 and param in err[0], err
        lines.append(err[0])
    assert lines[0] == lines[1]
    assert not out.exists() and [p.name for p in tmp_path.iterdir()] == ["bad.toml"]


def test_build_reuses_the_dry_runs_screen(monkeypatch):
    """The screen runs once per part file: the build's design takes the law search of the validation."""
    import propulsor.gears.law_search as ls
    from propulsor.building import load_part
    from propulsor.parts.noncircular_pair.design import screened

    calls = []
    real = ls.search_law
    monkeypatch.setattr(ls, "search_law", lambda *a, **k: calls.append(1) or real(*a, **k))
    _, p, _ = load_part(PARTS / "ncg_seed002.toml")
    assert len(calls) == 1
    assert screened(p).search is screened(p).search and len(calls) == 1


# --------------------------------------------------------------------------- library pieces
def test_arc_frame_inverse_and_perimeter():
    from propulsor.gears.noncircular_teeth import ArcFrame

    sl = SmoothedWalkingLaw(WalkingLaw(**SEED_002), 0.15)
    pc = PitchCurves(sl, 124.3)
    fr = ArcFrame(pc)
    assert fr.perimeter == pytest.approx(pc.perimeter_driven(), rel=1e-13)
    phi = np.linspace(-7.0, 7.0, 4001)
    assert np.max(np.abs(fr.s(phi) - fr.s_exact(phi))) < 1e-10
    assert np.max(np.abs(fr.phi(fr.s_exact(phi)) - phi)) < 1e-12
    assert float(fr.s(np.array([0.0]))[0]) == pytest.approx(0.0, abs=1e-12)


@settings(max_examples=12, deadline=None)
@given(a=st.floats(0, 200), b=st.floats(1, 150), c=st.floats(100, 500), n=st.sampled_from([1, 2, 4]),
       delta=st.floats(0.02, 0.7), L=st.floats(50, 300))
@example(a=0.0, b=38.0, c=100.0, n=4, delta=0.03125, L=50.0)  # inversion error 1.02e-10 rad found here
@example(a=0.0, b=106.0, c=127.0, n=1, delta=0.34375, L=50.0)  # 1.078e-9 rad before phi(s) was polished
def test_arc_frame_property(a, b, c, n, delta, L):
    """The shared arc-length frame of any smoothed law: perimeter = the pitch curves' (closure by true arc length),
    s(phi + pi/2) = s(phi) + leg, phi(s) inverts s(phi) to rounding (|phi| <= 3 rad: a few 1e-16 rad; the two
    Hermite interpolants alone disagree by up to ~1e-9 rad where the ratio varies steeply); both pitch curves roll
    (equal arcs)."""
    from hypothesis import assume

    from propulsor.errors import InputError
    from propulsor.gears.noncircular_teeth import ArcFrame, BodyPitchCurve

    assume(a - b + c > 20)
    try:
        sl = SmoothedWalkingLaw(WalkingLaw(a=a, b=b, c=c, n=n), delta)
    except InputError:
        return
    pc = PitchCurves(sl, L)
    fr = ArcFrame(pc)
    assert fr.perimeter == pytest.approx(pc.perimeter_driven(), rel=1e-12)
    phi = np.linspace(-3.0, 3.0, 301)
    assert np.allclose(fr.s(phi + math.pi / 2), fr.s(phi) + fr.leg, atol=1e-9 * fr.perimeter)
    assert np.max(np.abs(fr.phi(fr.s(phi)) - phi)) < 1e-12
    assert max(abs(fr.phi1(float(x)) - p) for x, p in zip(fr.s(phi[::10]), phi[::10])) < 1e-12
    # rolling: |dP/dphi| of the driver equals that of the driven wheel
    dd = np.linalg.norm(BodyPitchCurve(pc, "driver").dpoint(phi), axis=1)
    dn = np.linalg.norm(BodyPitchCurve(pc, "driven").dpoint(phi), axis=1)
    assert np.allclose(dd, dn, rtol=1e-12)


def test_generated_teeth_are_conjugate_without_backlash():
    """With j_n = 0 the outlines touch on both flanks and the driven wheel follows the law to about
    a micro-radian (conjugate teeth); near the hand-over (the driver's sharpest, the driven wheel's
    concave stretch) the driven tips touch the driver's fillets within a few micrometres, which
    the default backlash clears (the full-cycle proof of the part files shows overlap 0)."""
    import dataclasses

    from propulsor.params import load_params, read_part_file
    from propulsor.laws.walking import wrap_leg
    from propulsor.parts.noncircular_pair import NoncircularPairParams, design, prove

    _, mapping = read_part_file(PARTS / "ncg_seed002.toml")
    p = dataclasses.replace(load_params(NoncircularPairParams, mapping), backlash_mm=0.0)
    d = design(p)
    pr = prove(d, 4, 1)
    away = np.abs(wrap_leg(pr.phi - math.pi / 4)) > math.radians(4.0)
    assert np.all(pr.overlap_law[away] <= 1e-6) and np.all(np.isfinite(pr.te_drive[away]))
    assert np.max(np.abs(pr.te_drive[away])) < 3e-6
    assert np.max(pr.backlash_mm[away]) < 1e-3
    assert pr.overlap_law.max() < 2e-3


def test_module_from_centre_distance():
    """Closure the other way round (by true arc length): L given, the module follows; the blend is the one
    chosen at m = 2.5 (the design is scale invariant: rho and the undercut limit both scale with m)."""
    from propulsor.params import load_params
    from propulsor.parts.noncircular_pair import NoncircularPairParams, design

    d = design(load_params(NoncircularPairParams, dict(module_mm=0.0, center_distance_mm=130.0, law_search=False)))
    assert d.L == 130.0 and d.m == pytest.approx(2.5 * 130.0 / 124.33187266550188, rel=1e-9)
    assert d.pc.perimeter_driven() == pytest.approx(80 * math.pi * d.m, rel=1e-12)
    assert d.smoothing_deg == pytest.approx(8.4747, abs=1e-3)
    assert len(d.driven.teeth) == 80 and len(d.driver.teeth) == 20


def test_outlines_are_deterministic():
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams, design

    _, mapping = read_part_file(PARTS / "ncg_seed002.toml")
    p = load_params(NoncircularPairParams, mapping)
    a, b = design(p), design(p)
    for ga, gb in ((a.driver, b.driver), (a.driven, b.driven)):
        sa, sb = ga.profile.outer.segments, gb.profile.outer.segments
        assert len(sa) == len(sb)
        assert all(np.array_equal(x.poles, y.poles) and np.array_equal(x.knots, y.knots) for x, y in zip(sa, sb))


def test_shaper_and_rack_generate_the_same_involute_on_a_circle():
    """With U = 1 (b = 0, n = 1) both pitch curves are circles of radius L/2: the generated flank is
    the involute of r cos(alpha) whether the ISO 53 rack or the shaper cuts it (same imaginary rack,
    x0 = -x), and it matches the closed-form involute of the tooth thickness m(pi/2 + 2 x tan a) - t."""
    from propulsor.gears.envelope import PitchCurveCentrode
    from propulsor.gears.noncircular_teeth import ArcFrame, BodyPitchCurve, ToothSpec, make_side

    law = WalkingLaw(a=0.0, b=0.0, c=100.0, n=1)
    m, z = 2.0, 40
    L = m * z  # r = L/2 = m z / 2
    pc = PitchCurves(law, L)
    fr = ArcFrame(pc)
    a = math.radians(20.0)
    for x, th in ((0.0, 0.0), (0.4, 0.1), (-0.3, 0.05)):
        spec = ToothSpec(m=m, x=x, thinning_mm=th, z0=16)
        for role in ("driven", "driver"):
            cur = BodyPitchCurve(pc, role)
            s_k = 0.37 * math.pi * m
            r = L / 2
            rb = r * math.cos(a)
            s_tooth = m * (math.pi / 2 + 2 * x * math.tan(a)) - th
            for tools in (spec.rack_tools(), spec.shaper_tools()):
                for tool in tools:
                    sd = make_side(tool, PitchCurveCentrode(cur, fr, s_k))
                    P = sd.flank(np.linspace(sd.flank.u0, sd.flank.u1, 200))
                    rr = np.linalg.norm(P, axis=1)
                    sel = (rr > rb * 1.01) & (rr < r + m * (1 + x))
                    P, rr = P[sel], rr[sel]
                    assert len(P) > 20
                    ang = np.arctan2(P[:, 1], P[:, 0])
                    centre = float(np.arctan2(*cur.point(fr.phi(np.array([s_k])))[0][::-1]))
                    # polar angle of the flank from the tooth centre (clockwise side = right = -)
                    inv = lambda al: math.tan(al) - al  # noqa: E731
                    expect = s_tooth / (2 * r) + inv(a) - (np.tan(np.arccos(rb / rr)) - np.arccos(rb / rr))
                    got = np.abs(np.angle(np.exp(1j * (ang - centre))))
                    assert np.max(np.abs(got - expect) * rr) < 1e-7, (role, x, tools[0].kind)


@pytest.mark.parametrize("which", ["seed002", "table002"])
def test_pair_animation_at_the_proofs_phases(which, request, assert_animations):
    """One driven turn at the full-cycle proof's phases: the driven wheel at the running angle the proof
    found (φ + te_run), the driver at θ_law; the least backlash marked is the proof's."""
    out = request.getfixturevalue(which)
    m = _manifest(out)
    cols = {"phi_rad": "phi_rad", "theta_law_rad": "theta_law_rad"}
    (e,) = assert_animations(out, m, {"pair": ("transmission", cols)})
    head, rows = _csv(out / "tables" / "anim_pair.csv")
    th, tr = _csv(out / "tables" / "transmission.csv")
    for r in rows:
        f, t = dict(zip(head, r)), dict(zip(th, tr[int(r[1])]))
        assert float(f["phi_run_rad"]) == pytest.approx(float(t["phi_rad"]) + float(t["te_run_rad"]), abs=1e-12)
    steps = [int(r[1]) for r in rows]
    assert steps[-1] - steps[0] >= 0.95 * len(tr)  # the whole driven turn
    # the proof's least backlash (its phases: tables/transmission.csv); the manifest's is the as-built one, resolved
    # by contact events between them: within 5 micrometres of it
    k = th.index("backlash_mm")
    bl = [float(r[k]) for r in tr if r[k] not in ("", "nan")]
    least = min(bl) if bl else math.nan  # none where every phase jams (the papers' teeth)
    if math.isnan(least):
        assert e["least_clearance_mm"] is None and m["derived"]["jam_phases"] == len(tr)
    else:
        assert e["least_clearance_mm"] == pytest.approx(least, abs=1e-12)
        assert float(m["derived"]["backlash_min_mm"]) == pytest.approx(least, abs=0.005)


@pytest.mark.parametrize("which", ["seed002", "seed000", "table002"])
def test_every_derived_value_has_a_unit_and_a_meaning(request, which, assert_explained):
    assert_explained(request.getfixturevalue(which))
