"""The balancer part built from parts/balancer.toml (seed 004 ch. 2 and 8).

One build per module; every assertion reads the OUTPUT folder (manifest, CSV, meshes, STEP,
DXF), not the code that wrote it.  What is accepted:
1. the thesis's suspension numbers reproduced (or their inconsistency shown);
2. stresses within the allowable at every station of the built arm, the critical sections
   (axle–arm shoulder fillets) with stated K_t, the FE comparison (~300 MPa body);
3. travel sweep β0 … β_m, >= 1 step/degree, no overlap, least clearance and where;
4. every pipeline check holds for every solid (genus, watertight, STEP round trip ...);
5. bad input -> exit 2, one line, nothing written.
"""

from __future__ import annotations

import csv
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from propulsor.cli import main

ROOT = Path(__file__).resolve().parents[1]
PART = ROOT / "parts" / "balancer.toml"
WHEEL = ROOT / "parts" / "road_wheel.toml"


def table(out, name):
    with open(out / "tables" / f"{name}.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    return rows


def column(rows, key):
    return np.array([float(r[key]) for r in rows])


def check(manifest, name):
    hits = [c for c in manifest["checks"] if c["name"] == name]
    assert len(hits) == 1, f"no single check named {name!r}"
    return hits[0]


# ------------------------------------------------------------------ 4. pipeline checks
def test_every_check_passed_and_the_files_exist(out, manifest):
    bad = [c["name"] for c in manifest["checks"] if not c["passed"]]
    assert bad == []
    files = {f["path"] for f in manifest["files"]}
    for f in ("balancer.step", "balancer.stl", "balancer.3mf", "assembly_beta_st.step", "balancer_arm_outline.dxf",
              "report.md", "tables/suspension.csv", "tables/arm_stresses.csv", "tables/travel_sweep.csv",
              "tables/transitions.csv", "tables/mass_properties.csv", "tables/elastic_characteristic.csv",
              "plots/elastic_characteristic.png", "plots/arm_stresses.png", "plots/travel_clearance.png"):
        assert f in files, f


def test_solid_checks_and_genus_from_the_mesh_file(out, manifest):
    for name in ("BRepCheck_Analyzer valid", "genus", "self-intersecting triangle pairs", "bodies",
                 "edges not shared by exactly 2 faces"):
        assert check(manifest, f"balancer: {name}")["passed"]
    assert check(manifest, "balancer: genus")["value"] == 3
    # independently of the manifest: the STL on disk is one closed body of genus 3
    from propulsor.checks.mesh import edge_counts, euler_genus
    from propulsor.export.mesh import load_mesh

    mesh = load_mesh(out / "balancer.stl")
    _, ucount, _ = edge_counts(mesh.faces)
    assert np.all(ucount == 2)
    chi, bodies, genus = euler_genus(mesh.vertices, mesh.faces)
    assert (bodies, genus) == (1, 3)


def test_assembly_names_balancer_and_wheel(out):
    from propulsor.export.step import read_step_solids, step_product_names

    names = step_product_names(out / "assembly_beta_st.step")
    assert "balancer" in names and any(n.startswith("road_wheel_tyre") for n in names)
    assert len(read_step_solids(out / "assembly_beta_st.step")) == 6  # balancer + disc + 2 rims + 2 tyres


def test_arm_outline_dxf(out):
    from propulsor.export.dxf import polygon_area, read_dxf

    d = read_dxf(out / "balancer_arm_outline.dxf")
    assert d["insunits"] == 4
    loops = d["layers"]["CUT"]["loops"]
    assert len(loops) == 2  # outline + damper-ear pin hole
    outer, pin = sorted(loops, key=lambda p: -abs(polygon_area(p)))
    r = np.linalg.norm(pin - pin.mean(axis=0), axis=1)  # the DXF's arc vertices lie on the true circle
    assert r == pytest.approx(np.full(len(r), 20.0), abs=1e-6)  # ear pin Ø40
    # the outline spans the bosses: from −R_upper to R_b + R_lower along the arm
    # (flattened at the 0.005 mm chord tolerance: an extreme may fall between two vertices)
    assert outer[:, 0].min() == pytest.approx(-90.0, abs=0.006)
    assert outer[:, 0].max() == pytest.approx(360.0 + 80.0, abs=0.006)


# ------------------------------------------------------------------ 1. thesis numbers
@pytest.fixture(scope="module")
def susp(out):
    return {(r["symbol"], r["equation"]): r for r in table(out, "suspension")}


def val(susp, sym, eq):
    return float(susp[(sym, eq)]["computed"])


def test_thesis_suspension_numbers(susp, manifest):
    assert round(val(susp, "gamma_m", "7"), 2) == 96.04
    # eq. 8 gives 24.348; printed 24.358 (see test_gamma_st_reading): within 0.011 deg
    assert abs(val(susp, "gamma_st", "8") - 24.36) < 0.013
    assert round(val(susp, "f_st", "11"), 3) == 0.078
    assert round(val(susp, "f_full", "11"), 3) == 0.492
    assert round(val(susp, "f_dyn", "12"), 3) == 0.414
    assert abs(val(susp, "lambda_ut", "16") / 0.822 - 1) < 0.01
    assert round(val(susp, "c'_printed_lambda", "20/24") / 1e5, 3) == 2.138   # printed λ, computed f_full
    assert abs(val(susp, "c'_eq16_lambda", "20/24") / 2.138e5 - 1) < 0.01     # with eq. 16's λ (1 % low)
    assert round(val(susp, "R_k,comp_max", "27") / 1e4, 3) == 2.134
    # 5.2285e4 with eq. 8's gamma_st; the printed 5.229e4 follows from the printed gamma_st = 24.358
    # (which in turn breaks c' = 2.138e5): the seed's last digits disagree, one unit either way
    assert val(susp, "mu_reb_max", "25") == pytest.approx(5.229e4, abs=1.0e1)
    assert round(val(susp, "mu_reb", "21") / 1e4, 3) == 4.031
    # 2 × 34 260 − 34 260 / 0.85 = 28 214; printed 28 220 (from a μ_reb rounded to 40 300)
    assert val(susp, "mu_comp", "21") == pytest.approx(28220.0, abs=10.0)
    assert round(val(susp, "D_p", "28"), 2) == 0.11                   # lever reading of i = 0.453
    assert round(val(susp, "P(beta_m)", "13") / 1000) == 94
    assert val(susp, "T_phi", "1, 25") == 1.8


def test_gamma_st_reading_and_the_unreproducible_rows(susp):
    # the table says which printed digits are matched: gamma_st and mu_k,mean / T_phi (eq. 26) are not
    assert susp[("gamma_st", "8")]["printed_digits_match"] == "false"
    assert susp[("gamma_m", "7")]["printed_digits_match"] == "true"
    assert susp[("mu_k,mean", "23")]["printed_digits_match"] == "false"
    assert "not printed" in susp[("mu_k,mean", "23")]["note"]
    assert float(susp[("T_phi", "26")]["computed"]) < 1.5  # 8 wheels over 6.846 m cannot give 1.8 s


def test_characteristic_table_is_eq13(out):
    rows = table(out, "elastic_characteristic")
    b = np.radians(column(rows, "beta_deg"))
    P = column(rows, "P_N")
    # independent eq. 13 with the printed data
    J = math.pi * 46.0**4 / 32
    b0 = b[0]
    assert P == pytest.approx(83000 * J / 2000 * (b - b0) / (360 * np.sin(b)), rel=1e-9, abs=1e-6)
    assert len(rows) >= 4 * 96


# ------------------------------------------------------------------ 2. strength
def test_stresses_within_allowable_at_every_station(out, manifest):
    rows = table(out, "arm_stresses")
    allow = 930.0 / 1.5
    s = column(rows, "s_mm")
    assert len(s) == 360 and s[0] == 0.0
    for case in ("beta_m_elastic", "beta_m_plus_damper", "stop"):
        sig = column(rows, f"{case}_sigma_vM_MPa")
        assert np.all(sig <= allow * (1 + 1e-9)), case
        assert np.all(column(rows, f"{case}_safety") >= 1.5 * (1 - 1e-9))
    # equal strength: the governing case runs at the allowable over most of the straight arm
    stop = column(rows, "stop_sigma_vM_MPa")
    assert np.mean(stop[(s > 100) & (s < 280)] > 0.9 * allow) > 0.6
    assert np.all(column(rows, "h_built_mm") >= column(rows, "h_equal_strength_mm"))
    assert check(manifest, "built depth - equal-strength depth")["passed"]


def test_critical_sections_with_stated_kt(out, manifest):
    rows = table(out, "transitions")
    assert {r["where"] for r in rows} == {"upper axle fillet", "wheel spindle fillet"}
    for r in rows:
        kt = float(r["K_t_bending"])
        assert 1.5 < kt < 2.5
        peak, nom = float(r["sigma_vM_peak_MPa"]), float(r["sigma_vM_nom_MPa"])
        assert nom < peak < 930.0 / 1.5
        assert float(r["safety"]) >= 1.5
        assert peak < 724.0  # below the FE's singular value
    up = [r for r in rows if r["where"] == "upper axle fillet"][0]
    assert float(up["K_t_bending"]) == pytest.approx(1.905, abs=1e-3)   # D/d = 160/120, r = 8 (Peterson)


def test_fe_comparison_reported(out, manifest):
    d = manifest["derived"]
    assert 250.0 < d["sigma_vM_body_elastic_built_MPa"] < 400.0      # seed FE: ~300 MPa in the body
    assert 250.0 < d["sigma_vM_constant_ref_MPa"]["beta_m elastic"] < 400.0
    report = (out / "report.md").read_text()
    assert "~300 MPa" in report and "724 MPa" in report


def test_mass_and_centre_of_mass(out, manifest):
    d = manifest["derived"]
    # independent: mass from the STEP solid's volume
    vol = d["balancer_volume_mm3"]
    assert d["mass_balancer_kg"] == pytest.approx(7.85e-6 * vol, rel=1e-9)
    assert 30.0 < d["mass_balancer_kg"] < 150.0
    com = d["centre_of_mass_balancer_mm"]
    assert len(com) == 3 and 0.0 < com[0] < 360.0
    # the mesh on disk has the same centre of mass
    import trimesh

    m = trimesh.load(out / "balancer.stl", process=True)
    assert np.allclose(m.center_mass, com, atol=0.05)


# ------------------------------------------------------------------ 3. travel sweep
def test_travel_sweep_no_overlap_and_least_clearance(out, manifest):
    rows = table(out, "travel_sweep")
    beta = column(rows, "beta_deg")
    d = manifest["derived"]
    assert beta[0] == pytest.approx(d["beta0_deg"]) and beta[-1] == pytest.approx(d["beta_m_deg"])
    assert np.all(np.diff(beta) <= 1.0 + 1e-9)  # >= 1 step per degree
    for pair in ("hull", "front", "rear"):
        assert np.all(column(rows, f"{pair}_overlap_mm3") <= 1e-3)
        gap = column(rows, f"{pair}_gap_mm")
        assert np.all(gap >= 10.0)
        assert d[f"min_clearance_{pair}_mm"] >= 10.0
        assert "at β =" in d[f"min_clearance_{pair}_where"]
        assert check(manifest, f"travel sweep clearance, " + {"hull": "hull envelope", "front": "front neighbour station",
                                                               "rear": "rear neighbour station"}[pair])["passed"]
    # the hull gap: collar edge (r 80, z −40) to the bearing-housing bore edge (r 85, z −52): √(5² + 12²)
    assert d["min_clearance_hull_mm"] == pytest.approx(13.0, abs=0.2)
    # neighbours: the wheel-to-wheel bound from the wheel axes holds, and the wheels are the closest parts
    for pair in ("front", "rear"):
        ub = column(rows, f"{pair}_wheel_gap_upper_bound_mm")
        assert d[f"min_clearance_{pair}_mm"] <= ub.min() + 0.5
        assert "tyre" in d[f"min_clearance_{pair}_where"]
    assert d["min_clearance_own_wheel_mm"] == pytest.approx(10.0, abs=0.2)  # hub face to arm face
    # the fender: the wheel top at beta_m, R_b sin(beta_m − 90°) + R, stays under it, and the envelope's
    # least gap (the hull's bore edge) does not exceed that analytic value
    top = -360.0 * math.cos(math.radians(d["beta_m_deg"])) + 315.0
    assert d["fender_over_wheel_top_at_beta_m_mm"] == pytest.approx(520.0 - top, abs=1e-9)
    assert d["min_clearance_hull_mm"] <= d["fender_over_wheel_top_at_beta_m_mm"]


# ------------------------------------------------------------------ 5. bad input
def _bad_file(tmp_path, **over) -> Path:
    lines = []
    for line in PART.read_text().splitlines():
        if line.startswith("[meta]"):
            break
        key = line.split("=")[0].strip()
        if key in over or key == "road_wheel_file":
            continue
        lines.append(line)
    for k, v in over.items():
        lines.append(f"{k} = {v}")
    lines.append(f'road_wheel_file = "{WHEEL.as_posix()}"')
    f = tmp_path / "bad_balancer.toml"
    f.write_text("\n".join(lines) + "\n")
    return f


@pytest.mark.parametrize("over, name, words", [
    ({"R_b_mm": 330.0}, "R_b_mm", "arm shorter than the wheel radius allows"),
    ({"beta0_deg": 19.0, "beta_m_deg": 116.0}, "beta_m_deg", "yields at beta_m"),
    ({"beta0_deg": 50.0}, "beta0_deg", "out of order"),
    ({"beta_m_deg": 40.0}, "beta_m_deg", "out of order"),
    ({"damper_reading": '"literal"'}, "i_a", "beyond the balancer"),
])
def test_bad_input_exit_2_one_line_nothing_written(tmp_path, capsys, over, name, words):
    f = _bad_file(tmp_path, **over)
    target = tmp_path / "o"
    rc = main(["build", str(f), "--out", str(target), "-q"])
    err = [l for l in capsys.readouterr().err.splitlines() if l.strip()]
    assert rc == 2
    assert len(err) == 1 and f"{name} = " in err[0] and words in err[0]
    assert not target.exists() and not any(tmp_path.glob(".o*"))


def test_good_file_through_the_same_helper_builds_inputs(tmp_path):
    # the bad-input helper itself yields a valid file when nothing is overridden (the tests above can fail)
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.balancer import BalancerParams, resolve

    f = _bad_file(tmp_path)
    _, mapping = read_part_file(f)
    m = resolve(load_params(BalancerParams, mapping), f)
    assert m.p.R_b_mm == 360.0 and m.wheel.r_tyre == 315.0


# ------------------------------------------------------------------ long runs (make check)
@pytest.mark.sweep
def test_fine_travel_sweep_agrees(manifest):
    """4 steps per degree on finer meshes: still no overlap, same least clearances."""
    import dataclasses

    from propulsor.params import load_params, read_part_file
    from propulsor.parts.balancer import BalancerParams, balancer_solid, sweep_mesh, resolve, travel_sweep
    from propulsor.parts.road_wheel import wheel_solids

    p = load_params(BalancerParams, read_part_file(PART)[1])
    p = dataclasses.replace(p, sweep_steps_per_deg=4.0, sweep_chord_mm=0.05)
    m = resolve(p, PART)
    ws = wheel_solids(m.wheel)
    m.extras["wheel_names"] = list(ws)
    res = travel_sweep(m, sweep_mesh(balancer_solid(m), 0.05), [sweep_mesh(s, 0.05) for s in ws.values()])
    assert len(res["beta"]) >= 4 * 96
    d = manifest["derived"]
    for pair, dd in res["pairs"].items():
        assert dd["overlap_mm3"].max() <= 1e-3
        k = dd["worst_step"]
        assert dd["gap_mm"][k] == pytest.approx(d[f"min_clearance_{pair}_mm"], abs=0.3)


@pytest.mark.sweep
def test_build_is_deterministic(out, tmp_path):
    again = tmp_path / "again"
    assert main(["build", str(PART), "--out", str(again), "-q"]) == 0
    a = {f["path"]: f["sha256"] for f in json.loads((out / "manifest.json").read_text())["files"]}
    b = {f["path"]: f["sha256"] for f in json.loads((again / "manifest.json").read_text())["files"]}
    assert a == b


# ------------------------------------------------------------------ damper heat (seed 004 ch. 6)
def test_damper_heat_table_plot_and_values(out, manifest):
    from propulsor import policy
    from propulsor.laws.damper_heat import Road, Station, cooling_coefficient, simulate

    d = manifest["derived"]
    rows = table(out, "damper_heat")
    assert len(rows) == 5 * len(policy.DAMPER_HEAT_SPEEDS_KMH)
    assert (out / "plots" / "damper_and_tyre_heat.png").stat().st_size > 10000
    # the unsprung mass is the built balancer plus its road wheel
    assert d["damper_heat_m1_unsprung_kg"] == pytest.approx(d["unsprung_balancer_plus_wheel_kg"], rel=1e-12)
    # one row recomputed apart: the 1 m bumps at 30 km/h
    st = Station(m1=d["damper_heat_m1_unsprung_kg"], C1=2.0e6, b1=2.0e3, b2=d["damper_heat_b2_Ns_per_m"])
    r = simulate(st, Road(0.05, 1.0), 30.0 / 3.6, policy.DAMPER_HEAT_T_END_S)
    row = next(x for x in rows if float(x["wavelength_m"]) == 1.0 and float(x["V_kmh"]) == pytest.approx(30.0))
    assert float(row["steady_rise_K"]) == pytest.approx(r.mean_power / cooling_coefficient(st, r.V), rel=1e-9)
    steady = [float(x["steady_rise_K"]) for x in rows]
    assert d["damper_heat_max_steady_rise_K"] == pytest.approx(max(steady))
    assert re.search(r"Damper heat \(\[\d\] ch. 6\)", (out / "report.md").read_text())  # seed 004, cited


def test_travel_animation_at_the_sweeps_poses(out, manifest, assert_animations):
    """Up and back down the travel at the sweep's angles (and the neighbours' angles of the sweep); the least
    clearance marked is the sweep's least against the hull and the neighbours."""
    cols = {"beta_deg": "beta_deg", "front_neighbour_beta_deg": "front_neighbour_beta_deg",
            "rear_neighbour_beta_deg": "rear_neighbour_beta_deg"}
    (e,) = assert_animations(out, manifest, {"travel": ("travel_sweep", cols)})
    d = manifest["derived"]
    assert e["least_clearance_mm"] == pytest.approx(min(d[f"min_clearance_{k}_mm"] for k in ("hull", "front", "rear")))
    beta = [float(r["beta_deg"]) for r in table(out, "anim_travel")]
    assert beta[0] == pytest.approx(d["beta0_deg"]) and max(beta) == pytest.approx(d["beta_m_deg"])
    assert beta[-1] < beta[-2]  # and back down


def test_every_derived_value_has_a_unit_and_a_meaning(out, assert_explained):
    assert_explained(out)


def test_the_travel_sweep_counts_its_bodies_to_the_build_that_started_it(monkeypatch):
    """The travel sweep runs in a worker beside the solids' checks; the build's progress line counts the bodies the
    balancer with its wheel has been swept against (the hull, the front and the rear neighbour), the first count
    before any work (issue 39: no silent phase).  Coarse meshes and steps: the count, not the gaps, is tested."""
    import dataclasses

    from propulsor.parallel import result, start
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.balancer import BalancerParams, balancer_solid, resolve, sweep_mesh, travel_sweep
    from propulsor.parts.road_wheel import wheel_solids

    monkeypatch.setenv("PROPULSOR_JOBS", "1")  # inline: the counts arrive in order
    p = dataclasses.replace(load_params(BalancerParams, read_part_file(PART)[1]), sweep_steps_per_deg=1.0,
                            sweep_chord_mm=1.0)
    m = resolve(p, PART)
    ws = wheel_solids(m.wheel)
    m.extras["wheel_names"] = list(ws)
    told = []
    res = result(start(travel_sweep, m, sweep_mesh(balancer_solid(m), 1.0), [sweep_mesh(s, 1.0) for s in ws.values()],
                       counter=lambda done, total: told.append((done, total))))
    assert list(res["pairs"]) == ["hull", "front", "rear"]
    assert told == [(0, 3), (1, 3), (2, 3), (3, 3)]
