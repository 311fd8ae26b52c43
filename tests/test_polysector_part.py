"""The composite (polysector) gear part end to end (seed 003): build through the command line, then
measure what it wrote — the file contract (composite_<k>_flow<j>.dxf, gear.dxf, transmission tables,
manifest positions), an independent overlap check of the DXF outlines at the table's poses — the
limiting case e = 0, and the command line's contract for bad input (exit 2, one line, nothing written)."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import manifold3d as m3d
import numpy as np
import pytest

from propulsor.cli import main
from propulsor.export.dxf import read_dxf_loops
from propulsor.params import load_params, read_part_file

ROOT = Path(__file__).resolve().parents[1]
PART = ROOT / "parts" / "polysector.toml"


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("poly") / "polysector"
    rc = main(["build", str(PART), "--out", str(out), "-q"])
    assert rc == 0
    return out


@pytest.fixture(scope="module")
def dd():
    from propulsor.parts.pipeline import design_of
    from propulsor.parts.polysector import PolysectorParams, design

    _, data = read_part_file(PART)
    p = load_params(PolysectorParams, data)
    return design_of(p, design)


def _manifest(out):
    return json.loads((out / "manifest.json").read_text())


def _table(path):
    with open(path) as fh:
        rows = list(csv.DictReader(fh))
    return rows


def test_every_check_passes_and_the_file_contract(built):
    m = _manifest(built)
    assert m["part"] == "polysector_gear" and m["passed"] is True
    assert [c["name"] for c in m["checks"] if not c["passed"]] == []
    paths = {f["path"] for f in m["files"]}
    for k in range(1, 4):
        assert {f"composite_{k}_flow1.dxf", f"composite_{k}_flow2.dxf", f"assembly_{k}.step",
                f"tables/transmission_{k}.csv", f"tables/contact_law_{k}.csv"} <= paths
    assert {"gear.dxf", "sector.dxf", "hub.dxf", "sector.step", "gear.step", "hub_disc.step", "sector.stl",
            "gear.3mf", "tables/positions.csv", "tables/tooth_position_error.csv", "tables/efficiency.csv",
            "tables/dynamics.csv", "plots/ratio_error.png", "report.md"} <= paths
    names = {c["name"] for c in m["checks"]}
    for k in range(1, 4):
        for tail in ("flow1.overlap_area", "flow2.overlap_area", "contact_continuity", "no_jam",
                     "epsilon_s_measured", "epsilon_s_eq4", "no_tip_on_tip", "no_snap"):
            assert f"position{k}.{tail}" in names
    for solid in ("sector", "hub_disc", "gear"):
        assert f"{solid}: STEP round trip" in names and f"{solid}: genus" in names


def test_manifest_positions(built):
    pos = _manifest(built)["derived"]["positions"]
    assert len(pos) == 3
    keys = {"offset_mm", "center_distance_mm", "ratio_nominal", "epsilon_s", "epsilon_s_per_flow",
            "ratio_error_max", "contact_pairs_min"}
    for q, zc, e in zip(pos, (36, 42, 48), (0.0, 9.0, 18.0)):
        assert keys <= set(q)
        assert q["offset_mm"] == pytest.approx(e, abs=1e-12)
        assert q["center_distance_mm"] == pytest.approx(1.5 * zc + 60.0, abs=1e-12)
        assert q["ratio_nominal"] == pytest.approx(40 / zc, rel=1e-14)
        # ε_s measured on the outline against eq. 4 (both flows = 2 × per flow)
        assert abs(q["epsilon_s"] - q["epsilon_s_eq4"]) <= 0.02
        assert q["epsilon_s"] == pytest.approx(2 * q["epsilon_s_per_flow"], rel=1e-12)
        assert q["epsilon_s"] >= 1.05
        assert q["contact_pairs_min"] >= 1
        # the tracked contact law: no tip on tip, no snap, the shares of the contact types cover the turn
        assert q["tip_on_tip_deg"] == 0.0 and q["snap_max_deg"] <= 0.05
        assert sum(q["contact_shares"].values()) == pytest.approx(1.0, abs=1e-12)
    # limiting case e = 0: the composite is the blank, conjugate to the gear
    assert pos[0]["ratio_error_max"] < 1e-6
    assert pos[2]["ratio_error_max"] > 1e-2  # and off it the ratio is not constant (eq. 5-8)
    eps = [q["epsilon_s"] for q in pos]
    assert all(a > b for a, b in zip(eps, eps[1:]))
    # ε_s also as the mean number of engaged sectors over the sampled steps (6 per pitch)
    for q in pos:
        assert abs(q["epsilon_s_steps"] - q["epsilon_s"]) < 0.1


def test_friction_loss_limiting_case_and_trend(built):
    """e = 0 is a solid pair: the measured mean loss is eq. 12/13 with C = 1 (within the sampling of the
    path); off it C_внеш grows with the offset (the pole wanders, C2 > 1)."""
    d = _manifest(built)["derived"]
    assert abs(d["position1_C_ext"] - 1.0) < 0.03
    c = [d[f"position{k}_C_ext"] for k in range(1, 4)]
    assert all(a < b for a, b in zip(c, c[1:])) and c[-1] > 1.05


def test_measured_ratio_follows_eq7_in_flank_contact(built):
    """Eq. 5-8 measured on the outlines: wherever the driving sector is in flank contact (away from the
    hand-over), the measured Δi is eq. 7/8's Δi of the pole of the base circles' common tangent."""
    for k in (2, 3):
        rows = _table(built / f"tables/transmission_{k}.csv")
        di = np.array([float(r["delta_i"]) for r in rows])
        eq = np.array([float(r["delta_i_eq8_flank"]) for r in rows])
        ok = np.isfinite(di)
        close = np.abs(di[ok] - eq[ok]) < 2e-3
        assert close.mean() > 0.7, (k, close.mean())
        assert np.max(np.abs(eq[ok][close])) > 0.005  # and where they agree, Δi is far from 0


def _section(loops):
    return m3d.CrossSection([np.ascontiguousarray(p) for p in loops], m3d.FillRule.EvenOdd)


def _rot(loops, ang, dx=0.0):
    c, s = math.cos(ang), math.sin(ang)
    R = np.array([[c, -s], [s, c]])
    return [p @ R.T + np.array([dx, 0.0]) for p in loops]


@pytest.mark.parametrize("k", [1, 3])
def test_dxf_outlines_do_not_overlap_at_the_tables_poses(built, k):
    """Independent of the proof: the CUT loops of gear.dxf placed at (a_k, 0) and of each flow's DXF, turned
    by the table's angles (gear: −theta_rad, i.e. gear_rotation_ccw_rad), do not overlap; and the gear,
    turned back by a hair more than the measured pose allows, does."""
    a = _manifest(built)["derived"]["positions"][k - 1]["center_distance_mm"]
    gear = read_dxf_loops(built / "gear.dxf", chord_tol=1e-4)
    flows = [read_dxf_loops(built / f"composite_{k}_flow{j}.dxf", chord_tol=1e-4) for j in (1, 2)]
    rows = _table(built / f"tables/transmission_{k}.csv")
    phi = np.array([float(r["phi_rad"]) for r in rows])
    th = np.array([float(r["theta_rad"]) for r in rows])
    assert phi[0] == 0.0 and np.allclose(np.diff(np.append(phi, 2 * math.pi)), phi[1])  # one full turn
    assert np.all(np.diff(th) > -1e-9)  # the gear never turns back
    assert np.allclose([float(r["gear_rotation_ccw_rad"]) for r in rows], -th)
    touching = 0
    for i in range(0, len(rows), 9):
        g = _section(_rot(gear, -th[i], a))
        over = [(_section(_rot(f, phi[i])) ^ g).area() for f in flows]
        assert max(over) < 1e-4, (i, over)
        g_back = _section(_rot(gear, -th[i] + 2e-4, a))  # 0.2 mrad back: into the driving flank
        if max((_section(_rot(f, phi[i])) ^ g_back).area() for f in flows) > 1e-6:
            touching += 1
    assert touching >= 0.9 * len(range(0, len(rows), 9))  # the measured pose is the contact pose


def test_e0_sector_teeth_lie_on_the_blank_gear(dd):
    """Limiting case e = 0: every sector tooth of both flows lies on the plain spur gear's outline."""
    from propulsor.checks.motion import outline
    from propulsor.checks.motion.distance import dist_each_point
    from propulsor.geometry.gear_outline import external_gear_profile

    pos = dd.positions[0]
    assert pos.offset == 0.0
    # the plain gear with a space on +x (the sector's mid-line; z_c = 10 is even)
    plain = external_gear_profile(36, 3.0, 0.0, thinning_n_mm=0.1).profile.transformed(-math.pi / 2 + math.pi / 36)
    blank = outline(plain, 1e-4)
    r_f = 54.0 - 1.25 * 3.0
    n = 0
    for f in (1, 2):
        for s in dd.placed_sectors(pos, f):
            P = s.outer.polyline(1e-4)
            P = P[np.hypot(P[:, 0], P[:, 1]) > r_f + 1e-3]
            n += len(P)
            assert np.max(dist_each_point(P, blank)) < 2e-4  # both polylines within 1e-4 of the same curves
    assert n > 1000


def _part_file_with(tmp_path, changes: dict) -> Path:
    """The default part file's parameters with ``changes``, written as a new part file (no [meta])."""
    kind, data = read_part_file(PART)
    data = {**data, **changes}
    body = "\n".join(f"{k} = {json.dumps(v)}" for k, v in data.items())
    f = tmp_path / "bad.toml"
    f.write_text(f'type = "{kind}"\n{body}\n')
    return f


@pytest.mark.parametrize("changes, param, words", [
    ({"sector_teeth": 12}, "sector_teeth", "too large for the gaps"),       # eq. 2: no empty pitch
    ({"conditional_teeth": [36, 60]}, "conditional_teeth", "largest offset"),  # past eq. 1/3
    ({"sector_teeth": 2}, "sector_teeth", "1.05"),                          # ε_s below 1.05 even at e = 0
    ({"conditional_teeth": [36, 40]}, "conditional_teeth", "multiple"),  # sectors out of tooth phase
    ({"stem_width_mm": 8.0}, "stem_width_mm", "stem"),
])
def test_bad_input_exit_2_one_line_nothing_written(tmp_path, capsys, changes, param, words):
    target = tmp_path / "never"
    code = main(["build", str(_part_file_with(tmp_path, changes)), "--out", str(target), "-q"])
    lines = capsys.readouterr().err.strip().splitlines()
    assert code == 2, lines
    assert len(lines) == 1 and param in lines[0] and words in lines[0], lines
    assert sorted(q.name for q in tmp_path.iterdir()) == ["bad.toml"]  # nothing written beside it


def test_position_animations_at_the_proofs_poses(built, assert_animations):
    """One GIF per position over one sector period; the frames are the proof's (φ, θ) and the least
    backlash marked is the least of that position's proof."""
    m = _manifest(built)
    tables = {f"position_{k}": (f"transmission_{k}", {"phi_rad": "phi_rad", "theta_rad": "theta_rad"}) for k in range(1, 4)}
    entries = assert_animations(built, m, tables)
    assert [e["path"] for e in entries] == [f"anim/position_{k}.gif" for k in range(1, 4)]
    for k, e in enumerate(entries, 1):
        with open(built / "tables" / f"anim_position_{k}.csv", newline="") as fh:
            rows = list(csv.DictReader(fh))
        pos = m["derived"]["positions"][k - 1]
        assert len(rows) == pos["proof_steps_per_period"] == e["frames"]  # every step of the period
        assert e["least_clearance_mm"] == pytest.approx(min(float(r["backlash_mm"]) for r in rows), abs=1e-12)


def test_every_derived_value_has_a_unit_and_a_meaning(built, assert_explained):
    assert_explained(built)
