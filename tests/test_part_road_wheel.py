"""The road wheel built from parts/road_wheel.toml (seed 004 ch. 5, 7).

One build per module; assertions read the output folder.  Kozlov's temperature is re-computed
here independently in SI units from the part file's numbers."""

from __future__ import annotations

import csv
import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from propulsor.cli import main

ROOT = Path(__file__).resolve().parents[1]
PART = ROOT / "parts" / "road_wheel.toml"
P = tomllib.loads(PART.read_text())


def rows(out, name):
    with open(out / "tables" / f"{name}.csv", newline="") as fh:
        return list(csv.DictReader(fh))


def test_all_checks_pass_and_solids_are_separate(out, manifest):
    assert [c["name"] for c in manifest["checks"] if not c["passed"]] == []
    for name in ("disc", "rim_1", "rim_2", "tyre_1", "tyre_2"):
        for ext in ("step", "stl", "3mf"):
            assert (out / f"{name}.{ext}").is_file()
    from propulsor.export.step import read_step_solids

    assert len(read_step_solids(out / "road_wheel_assembly.step")) == 5


@pytest.mark.parametrize("name, genus", [("disc", 1 + 2 * 6), ("rim_1", 1), ("rim_2", 1), ("tyre_1", 1),
                                         ("tyre_2", 1)])
def test_genus_from_the_mesh_files(out, manifest, name, genus):
    from propulsor.checks.mesh import euler_genus
    from propulsor.export.mesh import load_mesh

    m = load_mesh(out / f"{name}.stl")
    assert euler_genus(m.vertices, m.faces)[1:] == (1, genus)
    c = [c for c in manifest["checks"] if c["name"] == f"{name}: genus"][0]
    assert c["passed"] and c["value"] == genus


def test_tyre_and_rim_dimensions_from_the_meshes(out):
    from propulsor.export.mesh import load_mesh

    R, H, b = P["tyre_radius_mm"], P["tyre_thickness_mm"], P["tyre_width_mm"]
    for k in (1, 2):
        t = load_mesh(out / f"tyre_{k}.stl")
        r = np.hypot(t.vertices[:, 0], t.vertices[:, 1])
        assert r.max() == pytest.approx(R, abs=1e-4) and r.min() == pytest.approx(R - H, abs=0.01)  # float32 STL
        assert np.ptp(t.vertices[:, 2]) == pytest.approx(b, abs=1e-4)
        rim = load_mesh(out / f"rim_{k}.stl")
        rr = np.hypot(rim.vertices[:, 0], rim.vertices[:, 1])
        assert rr.max() == pytest.approx(R - H, abs=1e-4)  # the tyre sits on the rim
    t1, t2 = load_mesh(out / "tyre_1.stl"), load_mesh(out / "tyre_2.stl")
    assert t2.vertices[:, 2].min() - t1.vertices[:, 2].max() == pytest.approx(P["row_gap_mm"], abs=1e-4)


def test_hub_bore_holds_the_bearings_that_match_the_spindle(out):
    """Hub seats = bearing outside diameters; the balancer's spindle seats = their bores."""
    from propulsor.export.mesh import load_mesh

    from trimesh.intersections import mesh_plane

    disc = load_mesh(out / "disc.stl")
    B1, B2, L = P["bearing_inner_B_mm"], P["bearing_outer_B_mm"], P["hub_length_mm"]

    def bore_radius(z):  # least radius of the mesh's section by the plane z
        seg = mesh_plane(disc, [0.0, 0.0, 1.0], [0.0, 0.0, z]).reshape(-1, 3)
        return np.hypot(seg[:, 0], seg[:, 1]).min()

    assert bore_radius(0.5 * B1) == pytest.approx(P["bearing_inner_D_mm"] / 2, abs=0.01)
    assert bore_radius(L - 0.5 * B2) == pytest.approx(P["bearing_outer_D_mm"] / 2, abs=0.01)
    assert bore_radius(0.5 * L) == pytest.approx(P["hub_relief_d_mm"] / 2, abs=0.01)  # shoulders between
    # the balancer takes its spindle seats from the same file
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.balancer import BalancerParams, resolve, spindle_section

    f = ROOT / "parts" / "balancer.toml"
    m = resolve(load_params(BalancerParams, read_part_file(f)[1]), f)
    sec = spindle_section(m)
    xs = np.concatenate([s.sample(0.01)[:, 0] for s in sec.outer.segments])
    assert np.isclose(xs, P["bearing_inner_d_mm"] / 2).any() and np.isclose(xs, P["bearing_outer_d_mm"] / 2).any()


def test_kozlov_temperature_against_independent_si(out, manifest):
    t = rows(out, "tyre_temperature")
    V = np.array([float(r["V_kmh"]) for r in t])
    T = np.array([float(r["T_C"]) for r in t])
    R, b, H = P["tyre_radius_mm"] / 1000, P["tyre_width_mm"] / 1000, P["tyre_thickness_mm"] / 1000
    E, psi, alpha, Pw = P["E_rubber_MPa"] * 1e6, P["psi"], P["alpha_W_m2K"], P["load_N"] / P["rows"]
    l = 2 * (H / R) ** (1 / 3) * math.sqrt(R * Pw / (E * b))        # eq. 80
    lam = l * l / (8 * R)                                            # eq. 79
    q = 4 * Pw / (math.pi * b * l)
    A = math.pi * q * lam * b * R * (1 - lam / (2 * R))              # eq. 78
    n = V / 3.6 / (2 * math.pi * R) * 60                             # rpm, kinematic
    F = 2 * math.pi * (R**2 - (R - H) ** 2) + 2 * math.pi * R * b
    T_si = P["t_air_C"] + psi * A * n / 60 / (alpha * F)            # eq. 76-77
    assert T == pytest.approx(T_si, rel=1e-10)
    assert V[-1] == P["V_max_kmh"] and T[0] == pytest.approx(P["t_air_C"])
    assert manifest["derived"]["T_at_V_max_C"] == pytest.approx(T_si[-1], rel=1e-12)
    assert manifest["derived"]["T_at_V_max_C"] <= P["t_allow_C"]
    # the printed n = 60 V / (3.6 π R) doubles the rise
    Tp = np.array([float(r["T_printed_n_C"]) for r in t])
    assert Tp - P["t_air_C"] == pytest.approx(2 * (T - P["t_air_C"]), rel=1e-10)
    # track frequency: f = V / t
    f = np.array([float(r["track_frequency_Hz"]) for r in t])
    assert f == pytest.approx(V / 3.6 / P["track_pitch_m"], rel=1e-12)


def test_dxf_section_and_web(out):
    from propulsor.export.dxf import polygon_area, read_dxf

    web = read_dxf(out / "road_wheel_web.dxf")
    assert web["insunits"] == 4
    loops = web["layers"]["CUT"]["loops"]
    assert len(loops) == 2 + P["lightening_holes"]
    r_rim_in = P["tyre_radius_mm"] - P["tyre_thickness_mm"] - P["rim_thickness_mm"]
    net = sum(polygon_area(p) for p in loops)
    exact = math.pi * (r_rim_in**2 - (P["hub_outer_d_mm"] / 2) ** 2 - P["lightening_holes"] *
                       (P["lightening_hole_d_mm"] / 2) ** 2)
    assert abs(net) == pytest.approx(exact, rel=1e-4)
    sec = read_dxf(out / "road_wheel_section.dxf")
    assert len(sec["layers"]["CUT"]["loops"]) == 2 * (1 + 2 * P["rows"])  # both sides of the axis


def test_mass_properties(out, manifest):
    d = manifest["derived"]
    tyre = 1150e-9 * math.pi * (P["tyre_radius_mm"] ** 2 - (P["tyre_radius_mm"] - P["tyre_thickness_mm"]) ** 2) \
        * P["tyre_width_mm"]
    assert d["mass_tyre_1_kg"] == pytest.approx(tyre, rel=1e-9)
    assert 60.0 < d["mass_wheel_kg"] < 250.0
    assert d["centre_of_mass_wheel_mm"][:2] == pytest.approx([0.0, 0.0], abs=1e-6)


@pytest.mark.parametrize("line, name", [
    ("tyre_thickness_mm = 200.0", "tyre_thickness_mm"),
    ("hub_relief_d_mm = 170.0", "hub_relief_d_mm"),
    ("lightening_hole_d_mm = 170.0", "lightening_hole_d_mm"),
    ("E_rubber_MPa = 0.1", "load_N"),
])
def test_bad_input_exit_2(tmp_path, capsys, line, name):
    key = line.split("=")[0].strip()
    text = "\n".join(l for l in PART.read_text().splitlines() if not l.startswith(key + " "))
    text = text.replace("[meta]", line + "\n[meta]")
    f = tmp_path / "w.toml"
    f.write_text(text)
    rc = main(["build", str(f), "--out", str(tmp_path / "o"), "-q"])
    err = [l for l in capsys.readouterr().err.splitlines() if l.strip()]
    assert rc == 2 and len(err) == 1 and f"{name} = " in err[0]
    assert not (tmp_path / "o").exists()


def test_build_is_deterministic(out, tmp_path):
    again = tmp_path / "again"
    assert main(["build", str(PART), "--out", str(again), "-q"]) == 0
    a = {f["path"]: f["sha256"] for f in json.loads((out / "manifest.json").read_text())["files"]}
    b = {f["path"]: f["sha256"] for f in json.loads((again / "manifest.json").read_text())["files"]}
    assert a == b


def test_rolling_animation(out, manifest, assert_animations):
    """One revolution on the ground (no mechanism, no proof poses); the contact chord is Kozlov's l."""
    (e,) = assert_animations(out, manifest)
    assert e["path"] == "anim/rolling.gif" and e["frames"] == 36 and e["least_clearance_mm"] is None
    with open(out / "tables" / "anim_rolling.csv", newline="") as fh:
        angles = [float(r["wheel_angle_deg"]) for r in csv.DictReader(fh)]
    assert np.allclose(angles, np.arange(36) * 10.0)
    assert "anim/rolling.gif" in (out / "report.md").read_text()


def test_every_derived_value_has_a_unit_and_a_meaning(out, assert_explained):
    assert_explained(out)
