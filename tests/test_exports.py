"""Exports: STEP, STL/3MF, DXF, CSV, plots, manifest, report; and `check PATH`."""

from __future__ import annotations

import hashlib
import json
import math
import zipfile

import cadquery as cq
import ezdxf
import numpy as np
import pytest
import trimesh
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps

from propulsor.checks.brep import volume
from propulsor.checks.files import check_path, format_results, summary
from propulsor.checks.result import Check
from propulsor.export.dxf import polygon_area, read_dxf, read_dxf_loops, write_dxf
from propulsor.export.manifest import read_manifest, write_manifest
from propulsor.export.mesh import load_mesh, to_trimesh, write_3mf, write_stl
from propulsor.export.plots import line_plot, save_plot, new_figure
from propulsor.export.report import write_report
from propulsor.export.step import (
    STEP_TIMESTAMP,
    read_step_solids,
    step_product_names,
    write_assembly_step,
    write_step,
)
from propulsor.export.tables import read_csv, write_csv
from propulsor.geometry.profile import Arc, Line, Loop, Profile, Spline, circle_loop
from propulsor.policy import CHORD_TOL_MM, MESH_CHORD_LIMIT_MM

PLATE_V = 10 * 20 * 30 - math.pi * 2.5**2 * 30


@pytest.fixture(scope="module")
def plate():
    return cq.Workplane().box(10, 20, 30).faces(">Z").workplane().hole(5).val()


def same_bytes(a, b) -> bool:
    return a.read_bytes() == b.read_bytes()


def centre(shape):
    g = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, g)
    c = g.CentreOfMass()
    return np.array([c.X(), c.Y(), c.Z()])


# --- STEP -------------------------------------------------------------------------


def test_step_deterministic_named_mm(plate, tmp_path):
    a = write_step(plate, tmp_path / "a.step", "plate_A")
    b = write_step(plate, tmp_path / "b.step", "plate_A")
    assert same_bytes(a, b)
    text = a.read_text(encoding="latin-1")
    assert f"'{STEP_TIMESTAMP}'" in text
    assert "SI_UNIT(.MILLI.,.METRE.)" in text
    assert "AUTOMOTIVE_DESIGN" in text
    assert step_product_names(a) == ["plate_A"]
    (s,) = read_step_solids(a)
    assert volume(s) == pytest.approx(PLATE_V, rel=1e-9)


def test_step_assembly_names_and_placement(plate, tmp_path):
    comps = [("gear", plate, (100.0, 0.0, 0.0)), ("pin", cq.Solid.makeCylinder(3, 40), ((0, 0, 50), (0, 0, 1), 90.0))]
    a = write_assembly_step(comps, tmp_path / "a.step", "drive")
    b = write_assembly_step(comps, tmp_path / "b.step", "drive")
    assert same_bytes(a, b)
    names = step_product_names(a)
    assert {"drive", "gear", "pin"} <= set(names)
    solids = read_step_solids(a)
    assert len(solids) == 2
    vols = sorted(volume(s) for s in solids)
    assert vols == pytest.approx(sorted([PLATE_V, math.pi * 9 * 40]), rel=1e-9)
    cs = sorted((centre(s) for s in solids), key=lambda c: c[0])
    assert cs[0] == pytest.approx([0, 0, 70], abs=1e-9)  # cylinder 0..40 shifted up by 50
    assert cs[1] == pytest.approx([100, 0, 0], abs=1e-9)  # box-with-hole centred at x = 100
    # the part writer's form: path first, (name, solid, (x, y, z), rotation about z in rad)
    box = cq.Solid.makeBox(10, 2, 2)
    c = write_assembly_step(tmp_path / "c.step", [("arm", box, (0.0, 0.0, 0.0), math.pi / 2)], "rot")
    (s,) = read_step_solids(c)
    assert centre(s) == pytest.approx([-1, 5, 1], abs=1e-9)  # (5, 1, 1) turned by 90 deg about z


# --- meshes ----------------------------------------------------------------------


def test_tessellation_chord_and_files(tmp_path):
    R = 20.0
    cyl = cq.Solid.makeCylinder(R, 10)
    m = to_trimesh(cyl)
    assert m.metadata["chord_deflection_mm"] <= MESH_CHORD_LIMIT_MM
    V = np.asarray(m.vertices)
    # the rim polygon: vertices on z = 0 at radius R; consecutive ones in angle
    rim = V[(np.abs(V[:, 2]) < 1e-9) & (np.abs(np.hypot(V[:, 0], V[:, 1]) - R) < 1e-9)]
    ang = np.sort(np.arctan2(rim[:, 1], rim[:, 0]))
    dphi = np.diff(np.concatenate([ang, ang[:1] + 2 * np.pi]))
    sagitta = R * (1 - np.cos(dphi.max() / 2))
    assert 0.2 * CHORD_TOL_MM < sagitta <= CHORD_TOL_MM * (1 + 1e-9)
    assert m.volume == pytest.approx(math.pi * R**2 * 10, rel=1e-3)
    assert m.is_watertight and m.is_winding_consistent

    s1, s2 = write_stl(m, tmp_path / "a.stl", "cyl"), write_stl(m, tmp_path / "b.stl", "cyl")
    assert same_bytes(s1, s2)
    assert s1.stat().st_size == 84 + 50 * len(m.faces)
    back = load_mesh(s1)
    assert len(back.faces) == len(m.faces) and back.is_watertight
    assert back.volume == pytest.approx(m.volume, rel=1e-6)

    t1, t2 = write_3mf(m, tmp_path / "a.3mf", "cyl"), write_3mf(m, tmp_path / "b.3mf", "cyl")
    assert same_bytes(t1, t2)
    with zipfile.ZipFile(t1) as z:
        assert all(i.date_time == (1980, 1, 1, 0, 0, 0) for i in z.infolist())
        model = [n for n in z.namelist() if n.endswith(".model")][0]
        assert b'unit="millimeter"' in z.read(model) and b'name="cyl"' in z.read(model)
    back = load_mesh(t1)
    assert back.volume == pytest.approx(m.volume, rel=1e-9)


def test_tessellation_of_a_moved_shape():
    box = cq.Solid.makeBox(10, 20, 30).moved(cq.Location(cq.Vector(100, 0, 0), cq.Vector(0, 0, 1), 90))
    m = to_trimesh(box)
    # rotated 90 deg about z, then moved to x = 100: x in [80, 100], y in [0, 10]
    assert m.bounds == pytest.approx(np.array([[80, 0, 0], [100, 10, 30]]), abs=1e-9)
    assert m.volume == pytest.approx(6000.0, rel=1e-12) and len(m.faces) == 12


# --- DXF -----------------------------------------------------------------------------


def slot_profile():
    """40 x 20 slot-ended plate with a d = 6 hole; right end a semicircle (arc)."""
    outer = Loop(
        [
            Line((0.0, -10.0), (40.0, -10.0)),
            Arc((40.0, 0.0), 10.0, -math.pi / 2, math.pi / 2),
            Line((40.0, 10.0), (0.0, 10.0)),
            Line((0.0, 10.0), (0.0, -10.0)),
        ]
    )
    return Profile(outer, [circle_loop(3.0, (20.0, 0.0))], "slot")


def test_dxf_units_layers_closed_loops(tmp_path):
    prof = slot_profile()
    exact = 800 + math.pi * 100 / 2 - math.pi * 9
    refs = [("circle", {"center": (20.0, 0.0), "radius": 8.0}), ("polyline", {"points": [(0, 0), (40, 0)], "closed": False})]
    a = write_dxf(tmp_path / "a.dxf", [prof], refs)
    b = write_dxf(tmp_path / "b.dxf", [prof], refs)
    assert same_bytes(a, b)
    doc = ezdxf.readfile(a)
    assert doc.header["$INSUNITS"] == 4
    cut = [e for e in doc.modelspace() if e.dxf.layer == "CUT"]
    assert [e.dxftype() for e in cut] == ["LWPOLYLINE", "LWPOLYLINE"] and all(e.closed for e in cut)
    # the arc is one exact bulge: tan(pi / 4) = 1
    assert sorted(round(v[4], 12) for v in cut[0].get_points("xyseb")) == [0, 0, 0, 1.0]
    loops = read_dxf_loops(a)
    assert len(loops) == 2
    areas = [polygon_area(p) for p in loops]
    # chord error of the arc sampling: area error <= 2/3 * sagitta * arc length
    assert abs(sum(areas) - exact) <= 2 / 3 * CHORD_TOL_MM * (10 * math.pi + 6 * math.pi)
    fine = read_dxf_loops(a, chord_tol=1e-8)  # bulges are exact arcs: converges to the exact area
    assert sum(polygon_area(p) for p in fine) == pytest.approx(exact, abs=1e-5)
    assert areas[0] > 0 > areas[1]  # outer CCW, hole CW
    arcpts = loops[0][loops[0][:, 0] > 40 + 1e-9]
    assert np.abs(np.hypot(arcpts[:, 0] - 40, arcpts[:, 1]) - 10).max() < 1e-9
    info = read_dxf(a)
    assert len(info["layers"]["REF"]["loops"]) == 1 and len(info["layers"]["REF"]["open"]) == 1


def test_dxf_spline_and_placement(tmp_path):
    # quarter-circle-like cubic spline closed by two lines
    sp = Spline([0, 0, 0, 0, 1, 1, 1, 1], [(10, 0), (10, 5.5), (5.5, 10), (0, 10)])
    prof = Profile(Loop([sp, Line((0, 10), (0, 0)), Line((0, 0), (10, 0))]), [], "fan")
    p = write_dxf(tmp_path / "s.dxf", [prof, prof], placements=[(0, 0), (100.0, 50.0, math.pi / 2)])
    l0, l1 = read_dxf_loops(p)
    # Green's theorem on a dense sampling of the exact spline
    u = np.linspace(0, 1, 200001)
    q = sp.evaluate(u)
    exact = 0.5 * np.sum(q[:-1, 0] * q[1:, 1] - q[1:, 0] * q[:-1, 1])
    assert polygon_area(l0) == pytest.approx(exact, abs=40 * CHORD_TOL_MM)  # chord error x length
    assert polygon_area(l0) == pytest.approx(polygon_area(l1), rel=1e-12)
    # rotated by 90 deg about the origin, then moved to (100, 50)
    assert l1[:, 0].min() == pytest.approx(90.0, abs=1e-9) and l1[:, 1].min() == pytest.approx(50.0, abs=1e-9)
    # every DXF vertex lies on the exact outline: spline points within 1e-9 of the curve
    near = l0[(l0[:, 0] > 1e-6) & (l0[:, 1] > 1e-6)]
    d = np.min(np.linalg.norm(near[:, None, :] - q[None, ::10, :], axis=2), axis=1)
    assert d.max() < 2e-4


def test_dxf_open_loop_rejected(tmp_path):
    bad = Loop([Line((0, 0), (1, 0)), Line((1, 0), (1, 1)), Line((1, 1), (0, 0.5))])
    with pytest.raises(ValueError, match="not closed"):
        write_dxf(tmp_path / "x.dxf", [Profile(bad)])


# --- CSV, plots ----------------------------------------------------------------------


def test_csv_exact_and_deterministic(tmp_path):
    x = np.array([0.1, 1 / 3, -0.0, 1e-20, 12345.678901234567])
    a = write_csv(tmp_path / "a.csv", {"phi_rad": x, "z": np.arange(5), "ok": [True, False, True, True, False]})
    b = write_csv(tmp_path / "b.csv", {"phi_rad": x, "z": np.arange(5), "ok": [True, False, True, True, False]})
    assert same_bytes(a, b)
    head, rows = read_csv(a)
    assert head == ["phi_rad", "z", "ok"]
    assert [float(r[0]) for r in rows] == x.tolist()  # exact round trip
    assert rows[2][0] == "0.0" and rows[4][1] == "4" and rows[1][2] == "false"
    c = write_csv(tmp_path / "c.csv", ["r_H_mm", "u"], [[1 / 3, 2]], float_format="%.9g")
    assert c.read_text() == "r_H_mm,u\n0.333333333,2\n"
    with pytest.raises(ValueError):
        write_csv(tmp_path / "d.csv", {"a": [1, 2], "b": [1]})


def test_plots_deterministic(tmp_path):
    x = np.linspace(0, 2 * np.pi, 100)
    s = [(x, np.sin(x), "sin"), (x, np.cos(x), "cos")]
    a = line_plot(tmp_path / "a.png", s, "phi, rad", "y, mm", "t")
    b = line_plot(tmp_path / "b.png", s, "phi, rad", "y, mm", "t")
    assert same_bytes(a, b) and a.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert b"Software" not in a.read_bytes() and b"matplotlib" not in a.read_bytes()
    c = line_plot(tmp_path / "c.svg", s, "phi, rad", "y, mm")
    d = line_plot(tmp_path / "d.svg", s, "phi, rad", "y, mm")
    assert same_bytes(c, d)
    fig, _ = new_figure()
    with pytest.raises(ValueError):
        save_plot(tmp_path / "e.jpg", fig)


def _tight_figure(equal: bool):
    x = np.linspace(0, 2 * np.pi, 400)
    fig, ax = new_figure()
    ax.plot(x, 3 * np.sin(x), label="a, mm")
    ax.plot(np.cos(x), np.sin(x), label="b, mm")
    ax.set_xlabel("phi, rad")
    ax.set_title("tight")
    if equal:
        ax.set_aspect("equal", adjustable="datalim")
    ax.legend()
    fig.tight_layout()
    return fig


@pytest.mark.parametrize("equal", [False, True])
def test_plot_drawn_once_same_pixels(tmp_path, equal):
    """A figure laid out by tight_layout() is drawn once by save_plot (not once more, rendering off, for the
    placeholder engine tight_layout leaves), and its PNG is the bytes of matplotlib's own save with that extra
    draw."""
    fig = _tight_figure(equal)
    draws = []
    fig.canvas.mpl_connect("draw_event", lambda ev: draws.append(ev))
    save_plot(tmp_path / "one.png", fig)
    assert len(draws) == 1
    fig = _tight_figure(equal)
    assert fig.get_layout_engine() is not None  # the placeholder: savefig draws twice
    fig.savefig(tmp_path / "two.png", format="png", dpi=120, metadata={"Software": None}, bbox_inches=None)
    assert same_bytes(tmp_path / "one.png", tmp_path / "two.png")


# --- manifest, report, check PATH ---------------------------------------------------


def build_folder(folder, plate):
    write_step(plate, folder / "plate.step", "plate")
    m = to_trimesh(plate)
    write_stl(m, folder / "plate.stl", "plate")
    write_3mf(m, folder / "plate.3mf")
    write_dxf(folder / "plate.dxf", [slot_profile()])
    write_csv(folder / "tables" / "t.csv", {"x_mm": [1.0, 2.0]})
    checks = [Check.at_most("stress", np.float64(120.0), 300.0, "MPa"), Check.flag("valid", True)]
    info = {
        "plate.step": {"volume_mm3": volume(plate)},
        "plate.stl": {"volume_mm3": volume(plate), "genus": 1, "bodies": 1},
        "plate.3mf": {"volume_mm3": volume(plate), "genus": 1, "bodies": 1},
    }
    derived = {"V_mm3": np.float64(volume(plate)), "z": np.int64(3), "arr": np.array([1.0, 2.0])}
    write_report(folder / "report.md", "Plate", "A test plate.", {"b_mm": (10.0, "mm", "width")}, derived, checks)
    return write_manifest(folder, "plate", {"b_mm": 10.0}, derived, checks, file_info=info)


def test_manifest_report_and_check_path(plate, tmp_path):
    f1, f2 = tmp_path / "one", tmp_path / "two"
    m1, m2 = build_folder(f1, plate), build_folder(f2, plate)
    assert same_bytes(m1, m2)
    data = read_manifest(f1)
    assert set(data) >= {"part", "inputs", "derived", "checks", "files", "versions"}
    assert data["derived"]["z"] == 3 and data["derived"]["arr"] == [1.0, 2.0]
    assert data["checks"][0] == {"name": "stress", "passed": True, "value": 120.0, "limit": 300.0, "unit": "MPa", "message": "stress <= 300.0 MPa"}
    paths = [e["path"] for e in data["files"]]
    assert paths == sorted(paths) and "manifest.json" not in paths and "tables/t.csv" in paths
    e = {x["path"]: x for x in data["files"]}["plate.stl"]
    assert e["sha256"] == hashlib.sha256((f1 / "plate.stl").read_bytes()).hexdigest()
    assert e["bytes"] == (f1 / "plate.stl").stat().st_size and e["format"] == "STL"
    for k in ("python", "propulsor", "numpy", "scipy", "cadquery", "OCP", "manifold3d", "trimesh", "ezdxf"):
        assert data["versions"][k]
    rep = (f1 / "report.md").read_text()
    assert "| stress | 120 | 300 | MPa | PASS |" in rep and "PASSED: all 2 checks passed." in rep

    res = check_path(f1)
    n, failed = summary(res)
    assert failed == 0, [str(c) for v in res.values() for c in v if not c.passed]
    assert format_results(res).endswith(f"5 files, {n} checks, 0 failed")
    assert n > 30 and {p.split("/")[-1] for p in res} == {"plate.step", "plate.stl", "plate.3mf", "plate.dxf", "manifest.json"}

    # the writer's convention: derived '<stem>_volume_mm3' is used when the entry has none
    f3 = tmp_path / "three"
    write_step(plate, f3 / "plate.step", "plate")
    write_manifest(f3, "plate", {}, {"plate_volume_mm3": PLATE_V * (1 + 1e-5)}, [])
    bad = [c.name for c in check_path(f3)[str(f3 / "plate.step")] if not c.passed]
    assert bad == ["plate.step: volume vs manifest"]

    # tamper with a file: the manifest check sees it
    (f1 / "tables" / "t.csv").write_text("x_mm\n1.0\n")
    bad = [c for c in check_path(f1 / "manifest.json")[str(f1 / "manifest.json")] if not c.passed]
    assert [c.name for c in bad] == ["manifest.json: size mismatches", "manifest.json: sha256 mismatches"]


def test_check_path_finds_broken_files(plate, tmp_path):
    m = to_trimesh(plate)
    V, F = np.asarray(m.vertices), np.asarray(m.faces)

    def failed(path):
        return {c.name.split(": ", 1)[1] for c in check_path(path)[str(path)] if not c.passed}

    p = write_stl(trimesh.Trimesh(V, F[1:], process=False), tmp_path / "holed.stl")
    assert "edges not shared by exactly 2 faces" in failed(p)
    G = F.copy()
    G[7] = G[7][::-1]
    p = write_stl(trimesh.Trimesh(V, G, process=False), tmp_path / "flipped.stl")
    assert "directed edges used twice" in failed(p)
    b1, b2 = trimesh.creation.box((10, 10, 10)), trimesh.creation.box((10, 10, 10))
    b2.apply_translation((4, 3, 2))
    p = write_3mf(trimesh.util.concatenate([b1, b2]), tmp_path / "two.3mf")
    assert failed(p) == {"self-intersecting triangle pairs"}  # bodies not prescribed without a manifest
    s = write_step(plate, tmp_path / "p.step", "p")
    t = tmp_path / "trunc.step"
    t.write_bytes(s.read_bytes()[:4000])
    assert "STEP parses" in failed(t)
    assert failed(s) == set()
    t = tmp_path / "trunc.stl"
    t.write_bytes((tmp_path / "holed.stl").read_bytes()[:1000])
    assert failed(t)

    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 1
    doc.layers.add("CUT")
    doc.modelspace().add_lwpolyline([(0, 0), (1, 0), (1, 1)], dxfattribs={"layer": "CUT"})
    doc.saveas(tmp_path / "open.dxf")
    assert failed(tmp_path / "open.dxf") == {"$INSUNITS", "closed loops on CUT", "open entities on CUT"}
    (tmp_path / "garbage.dxf").write_text("0\nSECTION\n2\nENTITIES\n0\nLINE\n")
    assert failed(tmp_path / "garbage.dxf") == {"DXF parses"}


def test_dxf_bytes_do_not_depend_on_the_hash_seed(tmp_path):
    """ezdxf orders CLASS entries through a set of strings; the writer sorts them."""
    import os
    import subprocess
    import sys

    code = ("import sys; from propulsor.export.dxf import write_dxf; "
            "from propulsor.geometry.profile import Profile, circle_loop; "
            "write_dxf(sys.argv[1], [Profile(circle_loop(10.0), [circle_loop(3.0, ccw=False)])], "
            "[('circle', {'radius': 5.0}), ('point', {'p': (0.0, 0.0)})])")
    outs = []
    for seed in ("1", "2", "3", "4"):
        f = tmp_path / f"s{seed}.dxf"
        subprocess.run([sys.executable, "-c", code, str(f)], check=True, env={**os.environ, "PYTHONHASHSEED": seed})
        outs.append(f.read_bytes())
    assert all(o == outs[0] for o in outs)
