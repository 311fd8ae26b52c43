"""The planetary final drive part end to end (seed 004 ch. 4): build through the command line, then
measure the files it wrote — manifest, report, DXF, STEP assembly, sweep table — and the
command line's contract for bad input (exit 2, one line, nothing written)."""

from __future__ import annotations

import csv
import dataclasses
import json
import math
import re
import shutil
from pathlib import Path

import numpy as np
import pytest

from propulsor.checks.files import check_path
from propulsor.cli import main
from propulsor.export.dxf import read_dxf, read_dxf_loops
from propulsor.export.step import read_step_solids, step_instance_names
from propulsor.params import load_params, read_part_file
from propulsor.parts.final_drive import FinalDriveParams, carrier_sweep, gear_outlines, planetary_set

ROOT = Path(__file__).resolve().parents[1]
PART = ROOT / "parts" / "final_drive.toml"
THESIS = ROOT / "parts" / "final_drive_thesis.toml"


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("fd") / "final_drive"
    rc = main(["build", str(PART), "--out", str(out), "-q"])
    assert rc == 0
    return out


def _manifest(out):
    return json.loads((out / "manifest.json").read_text())


def test_every_check_passes_and_every_file_is_listed(built):
    m = _manifest(built)
    assert m["part"] == "planetary_final_drive" and m["passed"] is True
    failed = [c["name"] for c in m["checks"] if not c["passed"]]
    assert failed == []
    names = {c["name"] for c in m["checks"]}
    for solid in ("sun", "planet", "ring", "carrier"):  # the shared checks ran on every solid
        for what in ("BRepCheck_Analyzer valid", "STEP round trip", "genus", "self-intersecting triangle pairs",
                     "volume vs B-rep", "edges not shared by exactly 2 faces"):
            assert f"{solid}: {what}" in names
    paths = {f["path"] for f in m["files"]}
    for stem in ("sun", "planet", "ring"):
        assert {f"{stem}.step", f"{stem}.stl", f"{stem}.3mf", f"{stem}.dxf"} <= paths
    assert {"assembly.step", "tables/carrier_sweep.csv", "tables/sheet_sun_planet.csv",
            "tables/sheet_planet_ring.csv", "tables/conditions.csv", "plots/mesh_clearance.png",
            "plots/layout.png", "report.md"} <= paths


def test_thesis_sheet_values_in_the_manifest(built):
    d = _manifest(built)["derived"]
    assert d["W_k_sun_mm"] == pytest.approx(79.464, abs=1e-3)
    assert d["W_k_planet_mm"] == pytest.approx(80.025, abs=1e-3)
    assert d["a_w_sun_planet_mm"] == pytest.approx(188.643, abs=1e-3)
    assert abs(d["alpha_w_sun_planet_deg"] - (26 + 16 / 60 + 50 / 3600)) * 3600 <= 2.0
    assert d["a_w_planet_ring_mm"] == pytest.approx(d["a_w_sun_planet_mm"], abs=1e-9)  # corrected ring
    assert d["x_ring_used"] == pytest.approx(1.5, abs=1e-9)
    assert d["ratio_i_1H"] == pytest.approx(4.5)


def test_sweep_covers_a_carrier_turn_at_two_steps_per_degree_without_overlap(built):
    rows = list(csv.DictReader((built / "tables" / "carrier_sweep.csv").open()))
    psi = np.array([float(r["psi_deg"]) for r in rows])
    assert len(psi) >= 720 and psi[0] == 0.0 and np.max(np.diff(psi)) <= 0.5 + 1e-12 and psi[-1] >= 359.5
    meshes = [k[: -len("_clearance_mm")] for k in rows[0] if k.endswith("_clearance_mm")]
    assert len(meshes) == 6  # sun–planet and planet–ring for each of the 3 planets
    for mname in meshes:
        ov = np.array([float(r[f"{mname}_overlap_mm2"]) for r in rows])
        cl = np.array([float(r[f"{mname}_clearance_mm"]) for r in rows])
        assert ov.max() == 0.0
        # E_sn = 0.15 mm on each gear: the flank clearance is about E_sn·cos α_w·(d_w/d) ≈ 0.14 mm, never 0
        assert 0.12 < cl.min() <= cl.max() < 0.16


def test_dxf_units_layers_and_one_outer_loop(built):
    for stem, holes in (("sun", 1), ("planet", 1), ("ring", 1 + 12)):
        info = read_dxf(built / f"{stem}.dxf")
        assert info["insunits"] == 4
        loops = read_dxf_loops(built / f"{stem}.dxf")
        assert len(loops) == 1 + holes
        areas = sorted((abs(_area(p)) for p in loops), reverse=True)
        assert areas[0] > sum(areas[1:])  # one outer loop holds the rest
    # the planet's outline reaches exactly its tip diameter
    loops = read_dxf_loops(built / "planet.dxf")
    r = max(np.hypot(p[:, 0], p[:, 1]).max() for p in loops)
    assert 2 * r == pytest.approx(_manifest(built)["derived"]["d_a_planet_mm"], abs=1e-6)


def test_every_sheet_describes_the_solid_that_is_written(built):
    """One planet serves both meshes with one tip: the smaller of its two, shortened in the sun mesh (GOST 16532:
    d_a2 = d2 + 2(h_a* + x2 − Δy)m = 200 + 2·(1 + 0.5 − 0.1357)·10 = 227.286 mm), which its DXF outline reaches.
    Both sheets give that tip, and s_na and ε_α on it: ε_α = (ρ_a1 − ρ_a2 + a_w·sin α_w)/p_b with ρ_a1 = ½√(d_a1² −
    d_b1²) of the tip made (the unshortened 230 mm would give 1.430, the solid meshes at 1.349)."""
    d = _manifest(built)["derived"]
    loops = read_dxf_loops(built / "planet.dxf")
    d_a_dxf = 2 * max(np.hypot(p[:, 0], p[:, 1]).max() for p in loops)
    sheets = {}
    for mesh in ("sun_planet", "planet_ring"):
        rows = list(csv.reader((built / "tables" / f"sheet_{mesh}.csv").open()))
        sheets[mesh] = {r[1]: r[3:] for r in rows[1:]}
    planet_col = {"sun_planet": 1, "planet_ring": 0}
    for mesh, col in planet_col.items():
        assert float(sheets[mesh]["d_a"][col]) == pytest.approx(d_a_dxf, abs=1e-6)
        assert float(sheets[mesh]["s_na"][col]) == pytest.approx(d["s_na_planet_mm"], rel=1e-12)
        assert float(sheets[mesh]["E_sn"][col]) == 0.15
    assert float(sheets["planet_ring"]["epsilon_alpha"][0]) == pytest.approx(d["epsilon_alpha_planet_ring"], rel=1e-12)
    assert round(float(sheets["planet_ring"]["epsilon_alpha"][0]), 3) == 1.349
    assert float(sheets["sun_planet"]["d_a"][0]) == pytest.approx(d["d_a_sun_mm"], rel=1e-12)
    assert float(sheets["planet_ring"]["d_a"][1]) == pytest.approx(d["d_a_ring_mm"], rel=1e-12)


def _area(p):
    x, y = p[:, 0], p[:, 1]
    return 0.5 * (np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def test_assembly_names_and_places_its_components(built):
    assert step_instance_names(built / "assembly.step") == ["sun", "planet_1", "planet_2", "planet_3", "ring",
                                                            "carrier"]
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps

    solids = read_step_solids(built / "assembly.step")[:5]
    a_w = _manifest(built)["derived"]["a_w_sun_planet_mm"]
    centres = []
    for s in solids:
        g = GProp_GProps()
        BRepGProp.VolumeProperties_s(s, g)
        c = g.CentreOfMass()
        centres.append((math.hypot(c.X(), c.Y()), math.degrees(math.atan2(c.Y(), c.X())), c.Z(), g.Mass()))
    orbit = sorted(c for c in centres if c[0] > 1.0)  # planets (sun and ring are centred on the axis)
    assert len(orbit) == 3
    # planet centroids sit on the carrier radius a_w, 120° apart (the bore keyless planet is symmetric)
    assert all(abs(r - a_w) < 1e-3 for r, *_ in orbit)
    ang = sorted(a % 360 for _, a, *_ in orbit)
    assert np.allclose(np.diff(ang), 120.0, atol=1e-3)
    assert all(abs(z - 40.0) < 1e-6 for _, _, z, _ in orbit)  # mid face width of the 80 mm ring


def test_check_command_passes_and_catches_broken_files(built, tmp_path):
    sub = tmp_path / "sub"
    sub.mkdir()
    for f in ("sun.step", "sun.stl", "sun.3mf", "sun.dxf", "ring.dxf"):
        shutil.copy(built / f, sub / f)
    res = check_path(sub)
    assert all(c.passed for cs in res.values() for c in cs), [str(c) for cs in res.values() for c in cs if not c.passed]
    # a truncated STEP and an STL with a face missing are reported invalid
    (sub / "sun.step").write_bytes((built / "sun.step").read_bytes()[:20000])
    data = bytearray((built / "sun.stl").read_bytes())
    n = int.from_bytes(data[80:84], "little")
    data[80:84] = (n - 1).to_bytes(4, "little")
    (sub / "sun.stl").write_bytes(bytes(data[:-50]))
    assert main(["check", str(sub)]) == 1
    res = check_path(sub)
    assert any(not c.passed for c in res[str(sub / "sun.step")])
    assert any(not c.passed for c in res[str(sub / "sun.stl")])


def test_report_says_what_holds(built):
    rep = (built / "report.md").read_text()
    assert "PASSED: all" in rep and "Every condition of the set holds" in rep
    assert "x3 = 1.50000" in rep and "| a_w_sun_planet_mm | 188.643 | mm |" in rep


def test_thesis_ring_as_printed_interferes_on_the_finished_outlines():
    """x_ring = 1.417 as printed: not coaxial, and the ring teeth enter the planets (0.14 mm)."""
    _, mp = read_part_file(THESIS)
    p = load_params(FinalDriveParams, mp)
    ps = planetary_set(p)
    fails = {c.name for c in ps.conditions() if not c.passed}
    assert fails == {"coaxiality"}
    p = dataclasses.replace(p, n_planets=1)
    sweeps = {s.name: s for s in carrier_sweep(p, ps, gear_outlines(p, ps), steps_per_deg=0.05)}
    assert sweeps["mesh_sun_planet1"].overlap_mm2.max() == 0.0
    ring = sweeps["mesh_planet1_ring"]
    assert ring.overlap_mm2.min() > 1.0 and ring.clearance_mm.max() < -0.1


def _write(tmp_path, **changes):
    text = PART.read_text()
    for k, v in changes.items():
        lines = [ln for ln in text.splitlines() if not ln.startswith(f"{k} =")]
        i = lines.index("[meta]")
        lines.insert(i, f"{k} = {v}")
        text = "\n".join(lines) + "\n"
    f = tmp_path / "bad.toml"
    f.write_text(text)
    return f


@pytest.mark.parametrize("changes, param", [
    ({"module_mm": -10.0}, "module_mm"),
    ({"z_sun": 3}, "z_sun"),
    ({"x_sun": 1.6}, "x"),                # the sun tooth is pointed at its tip
    ({"n_planets": 5}, "n_planets"),      # (16 + 56)/5 is not whole: the planets cannot be assembled
    ({"module_mm": "nan"}, "module_mm"),
    ({"service_life_h": 0.0}, "service_life_h"),
    ({"sigma_Hlim_MPa": 2500.0}, "sigma_Hlim_MPa"),
    ({"root_roughness_Rz_um": 50.0}, "root_roughness_Rz_um"),
    ({"oil_viscosity_40_mm2_s": "\"thick\""}, "oil_viscosity_40_mm2_s"),
])
def test_bad_input_exit_2_one_line_nothing_written(tmp_path, capsys, changes, param):
    f = _write(tmp_path, **changes)
    out = tmp_path / "out"
    rc = main(["build", str(f), "--out", str(out), "-q"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2
    assert len(err) == 1 and param in err[0]
    assert not out.exists() and not any(p.name.startswith(".out") for p in tmp_path.iterdir())


# --- strength (seed 004 ch. 4.1-4.3, ISO 6336 / ISO 76) -------------------------------------------------
def test_strength_of_both_meshes_bearings_spline_and_shaft_in_the_manifest(built):
    m = _manifest(built)
    d = m["derived"]
    checks = {c["name"]: c for c in m["checks"]}
    for mesh, gears in (("sun_planet", ("sun", "planet")), ("planet_ring", ("planet", "ring"))):
        S_H = d[f"strength_{mesh}_S_H_static"]
        assert S_H == pytest.approx(44 * 59 / d[f"strength_{mesh}_sigma_H_MPa"], rel=1e-12)
        assert checks[f"strength_{mesh}.S_H_static"]["passed"] and S_H > 1.0
        assert "S_H static (σ_Hmax = 44·HRC" in checks[f"strength_{mesh}.S_H_static"]["message"]
        assert f"strength_{mesh}.S_H" not in checks      # the static check is not called the ISO safety
        for g in gears:
            S_F = d[f"strength_{mesh}_S_F_{g}_static"]
            assert S_F == pytest.approx(2.8 * 785 / d[f"strength_{mesh}_sigma_F_{g}_method_B_MPa"], rel=1e-12)
            assert checks[f"strength_{mesh}.S_F_{g}_static"]["passed"] and S_F > 1.75
            assert d[f"strength_{mesh}_sigma_F_{g}_method_C_MPa"] > 0
        # the face width each mesh needs is below the 75 mm it has
        assert 0 < d[f"strength_{mesh}_face_width_required_mm"] < 75.0
    # the sun's torsional wind-up under all three meshes' torque in K_Hβ (ISO 6336-1 method C f_sh), b = 80 mm
    # (the part file's planets): f_sh = 0.023·3·(F_m/b)·(80/160)² (tests/test_iso6336_planetary.py does it by hand)
    assert round(d["strength_sun_planet_K_Hbeta"], 3) == 1.234
    assert round(d["strength_planet_ring_K_Hbeta"], 3) == 1.069
    assert d["sun_torque_Nm"] == pytest.approx(90687.503 * 1.09 / 4.413, rel=1e-12)
    assert d["bearing_planet_C0_N"] == pytest.approx(128700.0)
    assert d["bearing_planet_S0"] > 1 and checks["bearing_planet.S0"]["passed"]
    assert d["bearing_carrier_S0"] == pytest.approx(1415838.17 / 858508.0, rel=1e-6)
    assert d["spline_margin"] == pytest.approx(121.294 / 117.164, rel=1e-4)
    assert d["spline_margin_thesis_785MPa"] == pytest.approx(1.29, abs=0.005)
    assert d["shaft_sigma_eq_MPa"] == pytest.approx(775.831, abs=1e-3)
    rows = list(csv.DictReader((built / "tables" / "bearings.csv").open()))
    assert [r["role"] for r in rows] == ["planet", "carrier"] and rows[1]["d_x_D_x_B_mm"] == "120 x 215 x 58"
    rep = (built / "report.md").read_text()
    assert "thesis 22 399 N·m" in rep and "printed 1.29" in rep
    # the allowables of seed 004 ch. 4.1 as printed: σ_FlimM = 2.8·σ_t = 2 198 MPa, σ_Fmax = 1 256 MPa; σ_Hmax = 44·HRC
    assert d["sigma_FlimM_MPa"] == pytest.approx(2198.0) and round(d["sigma_Fmax_allowable_MPa"]) == 1256
    assert d["sigma_Hmax_allowable_MPa"] == pytest.approx(44 * 59)


def test_traction_characteristic_table_plot_checks_and_note(built):
    """Seed 004 ch. 5.1.2-5.1.3 in the final drive's outputs: every Table 10 point in each of the 4 gears."""
    m = _manifest(built)
    d = m["derived"]
    checks = {c["name"]: c for c in m["checks"]}
    assert {"tables/traction_characteristic.csv", "plots/traction_characteristic.png"} <= {f["path"] for f in m["files"]}
    rows = list(csv.DictReader((built / "tables" / "traction_characteristic.csv").open()))
    assert len(rows) == 4 * 8
    U = {int(r["gear"]): float(r["U_tr"]) for r in rows}
    assert [round(U[j], 3) for j in (1, 3, 4)] == [28.655, 7.743, 4.5]          # eq. 69 as printed
    assert round(d["traction_gear2_V_top_kmh"], 3) == 16.888
    for r in rows:   # each point: the speed of eq. 69's ratio and f_g of ch. 5.1.3 from the row's own numbers
        n, Ueq, V = float(r["n_k_rpm"]), float(r["U_tr"]), float(r["V_kmh"])
        assert V == pytest.approx(0.06 * 15 * 0.125 * n / Ueq, rel=1e-5)
        f_g = 3600 * ((float(r["N_eob_kW"]) - float(r["N_str_kW"])) * 0.932 - float(r["N_cr_kW"])) * 0.94 / (490500 * V)
        assert float(r["f_g"]) == pytest.approx(f_g, rel=1e-3, abs=1e-5)
    assert checks["traction.first_gear_slope"]["passed"] and checks["traction.top_gear_road"]["passed"]
    assert d["traction_gear1_f_g_max"] == pytest.approx(0.600, abs=5e-4)
    assert re.search(r"Traction characteristic \(\[\d\] ch. 5.1.2–5.1.3", (built / "report.md").read_text())


def test_too_narrow_face_exits_1_naming_the_strength_check(tmp_path, capsys):
    """Planets of 20 mm face (the sun–planet mesh needs about 28 mm): the build fails on strength."""
    f = _write(tmp_path, width_planet_mm=20.0)
    out = tmp_path / "narrow"
    rc = main(["build", str(f), "--out", str(out)])
    text = capsys.readouterr()
    assert rc == 1
    said = text.out + text.err
    assert "strength_sun_planet.S_H_static" in said and "strength_sun_planet.face_width" in said


def test_carrier_solid_measured_and_its_pins_clear_the_planet_bores(built):
    """The carrier's STEP volume against its parts computed apart (cheek, pins, journal, spline section
    from the outline's polygon area), and the pin sweep over one carrier turn."""
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps

    from propulsor.geometry.involute_spline import InvoluteSpline
    from propulsor.parts.final_drive import carrier as car

    m = _manifest(built)
    d = m["derived"]
    (solid,) = read_step_solids(built / "carrier.step")
    g = GProp_GProps()
    BRepGProp.VolumeProperties_s(solid, g)
    a_w = d["a_w_sun_planet_mm"]
    R, t, r_pin = a_w + 55.0, 40.0, 27.5
    pins = 3 * math.pi * r_pin ** 2 * (80.0 + 5.0)               # cheek top (z = -5) to the ring's top face
    journal = math.pi * 60.0 ** 2 * (58 + 40 + 10)
    poly = InvoluteSpline(120.0, 3.5, 34).shaft_loop().polyline(1e-4)
    area = 0.5 * abs(np.dot(poly[:, 0], np.roll(poly[:, 1], 1)) - np.dot(poly[:, 1], np.roll(poly[:, 0], 1)))
    expected = math.pi * R ** 2 * t + pins + journal + area * 140.0
    assert g.Mass() == pytest.approx(expected, rel=1e-5)
    assert d["carrier_cheek_radius_mm"] == pytest.approx(R)
    checks = {c["name"]: c for c in m["checks"]}
    for k in (1, 2, 3):
        assert checks[f"carrier_pins_planet{k}.overlap_area"]["value"] == 0.0
        # pin Ø55 in the planet bore Ø110: the bearing's radial space at every step
        assert d[f"carrier_pins_planet{k}_min_clearance_mm"] == pytest.approx(27.5, abs=2e-3)
    assert "180 steps" in (built / "report.md").read_text()


def test_carrier_turn_animation_at_the_sweeps_poses(built, assert_animations):
    """The GIF's frames are carrier angles of the interference sweep; the least clearance it marks is the
    sweep's least over every mesh."""
    m = _manifest(built)
    (e,) = assert_animations(built, m, {"carrier_turn": ("carrier_sweep", {"psi_deg": "psi_deg"})})
    meshes = [k for k in m["derived"] if k.startswith("mesh_") and k.endswith("_min_clearance_mm")]
    assert len(meshes) == 6
    assert e["least_clearance_mm"] == pytest.approx(min(m["derived"][k] for k in meshes), abs=1e-12)
    assert e["frames"] >= 90  # a carrier turn in at most 4 degrees per frame


def test_every_derived_value_has_a_unit_and_a_meaning(built, assert_explained):
    assert_explained(built)


def test_fatigue_safeties_and_factor_table(built):
    """ISO 6336-2/-3 fatigue for the default 100 h at the design torque: checks per flank and root, the lives,
    and the factor table with a clause and a basis for every factor of the four calculations."""
    m = _manifest(built)
    d = m["derived"]
    checks = {c["name"]: c for c in m["checks"]}
    flanks = [("sun_planet", "sun"), ("sun_planet", "planet"), ("planet_ring", "planet"), ("planet_ring", "ring")]
    for mesh, g in flanks:
        c = checks[f"strength_{mesh}.S_H_pitting_{g}"]
        assert c["passed"] and c["value"] == d[f"strength_{mesh}_S_H_pitting_{g}"] and c["limit"] == 1.0
    for mesh, g in flanks:             # the ring's root too (ISO 6336-3, internal gear)
        c = checks[f"strength_{mesh}.S_F_fatigue_{g}"]
        assert c["passed"] and c["limit"] == 1.4
    # the sun is the weakest flank: 100 h of its 4.4e6 cycles give S_H ≈ 1.09; it reaches S_Hmin at ≈ 320 h
    assert d["load_cycles_per_hour_sun"] == pytest.approx(3600 * 3 * 3.5 * 7.852 / 3.6 / (15 * 0.125), rel=1e-12)
    assert d["load_cycles_per_hour_planet"] == pytest.approx(d["load_cycles_per_hour_sun"] / 3 * 16 / 20, rel=1e-12)
    assert 1.0 < d["strength_sun_planet_S_H_pitting_sun"] < d["strength_sun_planet_S_H_pitting_planet"]
    assert 100.0 < d["strength_sun_planet_pitting_life_sun_h"] < 1000.0
    rows = list(csv.DictReader((built / "tables" / "strength_factors.csv").open()))
    calcs = {(r["mesh"], r["calculation"]) for r in rows}
    assert calcs == {("sun_planet", "pitting"), ("sun_planet", "bending"), ("planet_ring", "pitting"),
                     ("planet_ring", "bending")}
    assert all(r["source"] and r["basis"] for r in rows)
    by = {(r["mesh"], r["calculation"], r["gear"], r["factor"]): r for r in rows}
    assert len(by) == len(rows)                   # one row per factor of each gear of each calculation
    for calc in ("pitting", "bending"):
        for f in ("F_t", "b", "K_A", "K_v", "K_Hbeta", "f_sh", "F_betax"):
            assert ("sun_planet", calc, "", f) in by
    for f in ("Z_H", "Z_E", "Z_eps", "Z_B", "Z_D", "K_Halpha"):
        assert ("planet_ring", "pitting", "", f) in by
    for g in ("planet", "ring"):
        for f in ("sigma_H", "N_L", "Z_NT", "Z_L", "Z_v", "Z_R", "Z_W", "Z_X", "sigma_HG", "S_H", "S_H_static"):
            assert ("planet_ring", "pitting", g, f) in by
    for g in ("sun", "planet"):
        for f in ("d_en", "Y_F", "Y_S", "sigma_F", "Y_F_C", "Y_S_C", "Y_eps", "sigma_F_C", "Y_NT", "Y_delta_relT",
                  "Y_R_relT", "Y_X", "Y_M", "sigma_FG", "S_F", "S_F_static"):
            assert ("sun_planet", "bending", g, f) in by
    assert ("sun_planet", "bending", "", "K_Fbeta") in by and ("planet_ring", "bending", "ring", "Y_F") in by
    assert float(by[("planet_ring", "bending", "ring", "Y_M")]["value"]) == 1.0        # bent one way
    assert [float(by[("sun_planet", "bending", g, "Y_M")]["value"]) for g in ("sun", "planet")] == [1.0, 0.7]
    assert float(by[("sun_planet", "bending", "planet", "sigma_F")]["value"]) == pytest.approx(
        d["strength_sun_planet_sigma_F_planet_method_B_MPa"], rel=1e-12)
    assert float(by[("sun_planet", "pitting", "sun", "S_H")]["value"]) == pytest.approx(
        d["strength_sun_planet_S_H_pitting_sun"], rel=1e-12)
    # each factor's method and the life point it is taken at: the gear's N_L for the life factors and what they
    # make; the reference point for the factors the life interpolates (ISO 6336-2/-3 method B, 5.4)
    N_sun = 3600 * 3 * 3.5 * 7.852 / 3.6 / (15 * 0.125) * 100.0          # 4.397e6 cycles in 100 h
    for f, method in (("K_v", "B"), ("K_Hbeta", "C"), ("f_sh", "C"), ("Z_B", "B"), ("Z_NT", "B")):
        assert by[("sun_planet", "pitting", "sun" if f == "Z_NT" else "", f)]["method"] == method
    for f in ("Z_NT", "Z_LvR", "sigma_HG", "S_H"):
        assert float(by[("sun_planet", "pitting", "sun", f)]["N_L"]) == pytest.approx(N_sun, rel=1e-3)
    for f in ("Z_L", "Z_v", "Z_R"):
        assert by[("planet_ring", "pitting", "ring", f)]["N_L"] == "5e7 (reference)"
    assert by[("sun_planet", "bending", "planet", "Y_delta_relT_static")]["N_L"] == "1e3 (static)"
    assert by[("sun_planet", "bending", "planet", "Y_F_C")]["method"] == "C"
    assert by[("planet_ring", "bending", "ring", "Y_NT")]["N_L"] != "" and by[("sun_planet", "pitting", "", "F_t")]["N_L"] == ""
    assert "d_1 = 160 mm" in by[("sun_planet", "pitting", "", "F_t")]["basis"]
    assert "E = 206 000 MPa, ν = 0.3" in by[("sun_planet", "pitting", "", "Z_E")]["basis"]
    assert by[("sun_planet", "pitting", "", "Z_H")]["source"].startswith("ISO 6336-2 cl. 6")
    assert float(by[("sun_planet", "pitting", "", "K_Hbeta")]["value"]) == pytest.approx(
        d["strength_sun_planet_K_Hbeta"], rel=1e-12)
    rep = (built / "report.md").read_text()
    # the report numbers its references: "ISO 6336 [n]"
    assert re.search(r"ISO 6336 (\[\d+\] )?factor table, Sun–planet pitting: F_t = 93331\.61 N", rep)
    assert re.search(r"Fatigue \(ISO 6336-2 (\[\d+\] )?pitting, ISO 6336-3 (\[\d+\] )?method B bending", rep)


class _Writer:
    """The parts of the output writer the fatigue step uses."""

    draws_plots = True  # a build's writer: the steps draw their figures (``OutputWriter.draws_plots``)

    def __init__(self):
        self.derived, self.described, self.checks, self.notes, self.tables = {}, {}, [], [], {}

    def progress(self, *_):
        pass

    def describe(self, name, unit, meaning):
        self.described[name] = (unit, meaning)

    def add_checks(self, checks):
        self.checks += list(checks)

    def add_note(self, text):
        self.notes.append(text)

    def add_table(self, name, columns, rows):
        self.tables[name] = (columns, rows)


def test_fatigue_life_is_where_the_safety_meets_its_minimum():
    """At the life the step reports, running that long gives the minimum safety exactly; ten times the default
    fails the sun's pitting and the planet's bending fatigue checks; every value written is described."""
    from propulsor.parts.final_drive.design import design
    from propulsor.parts.final_drive.fatigue import fatigue

    _, mp = read_part_file(PART)
    p = load_params(FinalDriveParams, mp)
    w = _Writer()
    fatigue(design(p), w, {})
    assert set(w.derived) <= set(w.described) and all(c.passed for c in w.checks)
    life_H, life_F = w.derived["strength_sun_planet_pitting_life_sun_h"], w.derived["strength_sun_planet_bending_life_planet_h"]
    assert w.derived["strength_sun_planet_bending_life_sun_h"] == math.inf
    for hours, key in ((life_H, "strength_sun_planet_S_H_pitting_sun"), (life_F, "strength_sun_planet_S_F_fatigue_planet")):
        p = dataclasses.replace(p, service_life_h=hours)
        w = _Writer()
        fatigue(design(p), w, {})
        assert w.derived[key] == pytest.approx(1.0 if "S_H" in key else 1.4, rel=1e-9)
    p = dataclasses.replace(p, service_life_h=1000.0)
    w = _Writer()
    fatigue(design(p), w, {})
    assert {c.name for c in w.checks if not c.passed} == {"strength_sun_planet.S_H_pitting_sun",
                                                          "strength_sun_planet.S_F_fatigue_planet"}


def test_the_interference_sweep_counts_its_meshes_to_the_build_that_started_it(monkeypatch):
    """The mesh sweep runs in a worker beside the solids; the build's progress line counts the meshes it has swept
    (each planet's sun and ring mesh), the first count before any work (issue 39: no silent phase)."""
    from propulsor.parallel import result, start

    monkeypatch.setenv("PROPULSOR_JOBS", "1")  # inline: the counts arrive in order, as the worker sends them
    _, mp = read_part_file(THESIS)
    p = dataclasses.replace(load_params(FinalDriveParams, mp), n_planets=2)
    ps = planetary_set(p)
    told = []
    sweeps = result(start(carrier_sweep, p, ps, gear_outlines(p, ps), 0.02,
                          counter=lambda done, total: told.append((done, total))))
    assert [s.name for s in sweeps] == ["mesh_sun_planet1", "mesh_planet1_ring", "mesh_sun_planet2",
                                        "mesh_planet2_ring"]
    assert told == [(0, 4), (1, 4), (2, 4), (3, 4), (4, 4)]
