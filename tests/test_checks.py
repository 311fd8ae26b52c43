"""Checks layer: Check results, B-rep validity, mesh topology, self-intersection."""

from __future__ import annotations

import json
import math

import cadquery as cq
import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

from propulsor.checks.brep import brep_checks, step_roundtrip_check, volume
from propulsor.checks.mesh import (
    euler_genus,
    mesh_checks,
    overlapping_pairs,
    self_intersections,
    signed_volume,
)
from propulsor.checks.result import Check, all_passed, failures
from propulsor.export.mesh import to_trimesh
from propulsor.export.step import write_step
from propulsor.policy import MESH_CHORD_LIMIT_MM, MESH_VOLUME_REL_TOL

# --- fixtures -------------------------------------------------------------------

PLATE_V = 10 * 20 * 30 - math.pi * 2.5**2 * 30  # box 10x20x30 with a through hole d = 5


@pytest.fixture(scope="module")
def plate():
    return cq.Workplane().box(10, 20, 30).faces(">Z").workplane().hole(5).val()


@pytest.fixture(scope="module")
def plate_mesh(plate):
    return to_trimesh(plate)


def by_name(checks, suffix):
    (c,) = [c for c in checks if c.name.endswith(suffix)]
    return c


def two_boxes(offset):
    b1 = trimesh.creation.box((10, 10, 10))
    b2 = trimesh.creation.box((10, 10, 10))
    b2.apply_translation(offset)
    return trimesh.util.concatenate([b1, b2])


# --- Check ------------------------------------------------------------------------


def test_check_constructors():
    assert Check.at_most("x", 1.0, 1.0).passed
    assert not Check.at_most("x", 1.0 + 1e-12, 1.0).passed
    assert not Check.at_most("x", float("nan"), 1.0).passed
    assert Check.at_least("x", 2, 2).passed and not Check.at_least("x", 1.999, 2).passed
    assert not Check.greater_than("v", 0.0, 0.0).passed
    c = Check.equal_within("V", 100.05, 100.0, rel_tol=1e-3, unit="mm^3")
    assert c.passed and c.limit["expected"] == 100.0
    assert not Check.equal_within("V", 100.2, 100.0, rel_tol=1e-3).passed
    assert not Check.equal_within("V", float("nan"), 100.0, rel_tol=1e-3).passed
    assert Check.flag("ok", np.bool_(True)).passed
    d = Check.at_most("s", np.float64(3.5), 4.0, "MPa").to_dict()
    assert d == {"name": "s", "passed": True, "value": 3.5, "limit": 4.0, "unit": "MPa", "message": "s <= 4.0 MPa"}
    assert type(d["value"]) is float
    json.dumps(Check.at_most("n", float("inf"), 1.0).to_dict(), allow_nan=False)
    cs = [Check.flag("a", True), Check.flag("b", False, "broken")]
    assert not all_passed(cs) and len(failures(cs)) == 1 and "FAIL" in failures(cs)[0]


# --- B-rep ------------------------------------------------------------------------


def test_brep_valid_plate(plate):
    cs = brep_checks(plate, "plate")
    assert all_passed(cs), failures(cs)
    assert volume(plate) == pytest.approx(PLATE_V, rel=1e-9)
    assert by_name(cs, "volume").value == pytest.approx(5410.951377, abs=1e-6)


def test_brep_open_shell_and_two_solids_fail():
    faces = cq.Workplane().box(10, 10, 10).faces().vals()[:5]
    shell = cq.Shell.makeShell(faces)
    cs = brep_checks(shell, "open box")
    assert by_name(cs, "open shells").value == 1 and not by_name(cs, "open shells").passed
    assert by_name(cs, "solids").value == 0
    two = cq.Compound.makeCompound([cq.Solid.makeBox(1, 1, 1), cq.Solid.makeBox(1, 1, 1, pnt=cq.Vector(5, 0, 0))])
    cs = brep_checks(two, "two")
    assert by_name(cs, "solids").value == 2 and not all_passed(cs)


def test_occt_volume_failure_is_caught():
    """OCCT's Gauss integration over an extruded 400-point periodic spline is
    ~8 % off; the triangulated volume agrees with the analytic one."""
    t = np.linspace(0, 2 * np.pi, 400, endpoint=False)
    r = 100 + 5 * np.cos(20 * t)
    pts = list(zip((r * np.cos(t)).tolist(), (r * np.sin(t)).tolist()))
    s = cq.Workplane().spline(pts, periodic=True).close().extrude(10).val()
    exact = np.pi * (100**2 + 5**2 / 2) * 10  # area of r(t) = 100 + 5 cos 20t, times height
    assert abs(volume(s) / exact - 1) > 0.05
    cs = brep_checks(s, "wavy", chord_tol=0.05)
    assert [c.name for c in cs if not c.passed] == ["wavy: exact volume vs triangulated"]
    c = by_name(cs, "exact volume vs triangulated")
    assert c.limit["expected"] == pytest.approx(exact, rel=1e-4)  # the triangulated volume is right


def test_step_roundtrip(plate, tmp_path):
    p = write_step(plate, tmp_path / "plate.step", "plate")
    c = step_roundtrip_check(plate, p, "plate")
    assert c.passed and c.name == "plate: STEP round trip", str(c)
    assert c.value == pytest.approx(PLATE_V, rel=1e-9)
    # truncated file -> failed check, not an exception
    t = tmp_path / "trunc.step"
    t.write_bytes(p.read_bytes()[: len(p.read_bytes()) // 2])
    c = step_roundtrip_check(plate, t)
    assert not c.passed and "re-import failed" in c.message
    # a different solid -> volume mismatch (6000 vs 5410.95 mm^3)
    c = step_roundtrip_check(cq.Workplane().box(10, 20, 30).val(), p)
    assert not c.passed and c.limit["expected"] == pytest.approx(6000.0)
    # two solids in one file -> fails although the volume sums match
    two = cq.Compound.makeCompound([cq.Solid.makeBox(1, 1, 1), cq.Solid.makeBox(1, 1, 1, pnt=cq.Vector(5, 0, 0))])
    q = write_step(two, tmp_path / "two.step", "two")
    c = step_roundtrip_check(two, q)
    assert not c.passed and c.value == pytest.approx(2.0)



def test_step_round_trip_reads_a_face_turned_inside_out_as_written_where_a_healing_reader_would_hide_it(tmp_path):
    """A box whose shell holds one face reversed, written as it is: OCCT's default healing turns the face back (the
    box read is whole, 6000 mm^3; propulsor check reads anyone's file so), the round trip's read of a file we wrote
    (export.step.UNHEALED: no shell orientation fix) keeps the defect, so the check fails on it; a whole box reads the
    same both ways.  The fix parameters only act when set
    after ReadFile: set before, the read would heal the box again and this test would fail."""
    from OCP.BRep import BRep_Builder
    from OCP.BRepTools import BRepTools
    from OCP.STEPControl import STEPControl_AsIs, STEPControl_Reader, STEPControl_Writer
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS_Shell, TopoDS_Solid

    from propulsor.export.step import read_step

    box = cq.Solid.makeBox(10.0, 20.0, 30.0)
    b = BRep_Builder()
    shell, solid = TopoDS_Shell(), TopoDS_Solid()
    b.MakeShell(shell)
    ex = TopExp_Explorer(box.wrapped, TopAbs_FACE)
    first = True
    while ex.More():
        b.Add(shell, ex.Current().Reversed() if first else ex.Current())
        first = False
        ex.Next()
    b.MakeSolid(solid)
    b.Add(solid, shell)
    bad = tmp_path / "bad.step"
    w = STEPControl_Writer()
    w.Transfer(solid, STEPControl_AsIs)
    assert w.Write(str(bad)) == 1

    def healed(path):
        r = STEPControl_Reader()
        r.ReadFile(str(path))
        r.TransferRoots()
        return r.OneShape()

    assert volume(cq.Shape.cast(healed(bad))) == pytest.approx(6000.0, rel=1e-9)  # a healing reader hides it
    assert volume(cq.Shape.cast(read_step(bad))) == pytest.approx(6000.0, rel=1e-9)  # so does propulsor check's
    assert volume(cq.Shape.cast(read_step(bad, as_written=True))) == pytest.approx(-6000.0, rel=1e-9)  # as written
    c = step_roundtrip_check(box, bad, "box")
    assert not c.passed and c.value == pytest.approx(-6000.0, rel=1e-9)
    good = write_step(box, tmp_path / "good.step", "box")
    a, h = tmp_path / "a.brep", tmp_path / "h.brep"
    BRepTools.Write_s(read_step(good, as_written=True), str(a))
    BRepTools.Write_s(healed(good), str(h))
    assert a.read_bytes() == h.read_bytes()
    assert step_roundtrip_check(box, good, "box").passed


# --- mesh topology --------------------------------------------------------------


def test_plate_mesh_genus_1(plate, plate_mesh):
    cs = mesh_checks(plate_mesh, "plate", expected_volume=volume(plate), expected_genus=1)
    assert all_passed(cs), failures(cs)
    chi, bodies, genus = euler_genus(plate_mesh.vertices, plate_mesh.faces)
    assert (chi, bodies, genus) == (0, 1, 1)
    # polygon inscribed in the hole: a little more material than the B-rep
    assert 0 < signed_volume(plate_mesh.vertices, plate_mesh.faces) - PLATE_V < MESH_VOLUME_REL_TOL * PLATE_V


def test_torus_and_sphere_and_two_holes():
    R, r = 20.0, 5.0
    m = to_trimesh(cq.Solid.makeTorus(R, r))
    cs = mesh_checks(m, "torus", expected_volume=2 * math.pi**2 * R * r**2, expected_genus=1)
    assert all_passed(cs), failures(cs)
    m = to_trimesh(cq.Solid.makeSphere(7.0, angleDegrees1=-90))
    assert euler_genus(m.vertices, m.faces) == (2, 1, 0)
    # chord error measured independently: edge midpoints and centroids vs the exact sphere
    T = np.asarray(m.vertices)[np.asarray(m.faces)]
    mids = np.concatenate([(T + np.roll(T, 1, axis=1)) / 2, T.mean(axis=1, keepdims=True)], axis=1)
    dev = 7.0 - np.linalg.norm(mids, axis=-1)
    assert 0 < dev.max() <= MESH_CHORD_LIMIT_MM
    assert np.abs(np.linalg.norm(m.vertices, axis=1) - 7.0).max() < 1e-9
    assert by_name(mesh_checks(m, "sphere"), "chord deflection").passed
    assert signed_volume(m.vertices, m.faces) == pytest.approx(4 / 3 * math.pi * 343, rel=MESH_VOLUME_REL_TOL)
    two = cq.Workplane().box(40, 20, 5).faces(">Z").workplane().pushPoints([(-10, 0), (10, 0)]).hole(4).val()
    m = to_trimesh(two)
    cs = mesh_checks(m, "two holes", expected_genus=2)
    assert by_name(cs, "genus").value == 2 and all_passed(cs)
    cs = mesh_checks(m, "two holes", expected_genus=1)
    assert not by_name(cs, "genus").passed


def test_broken_meshes_detected(plate_mesh):
    V, F = np.asarray(plate_mesh.vertices), np.asarray(plate_mesh.faces)
    cs = mesh_checks((V, F[1:]), "hole")
    assert by_name(cs, "edges not shared by exactly 2 faces").value == 3
    G = F.copy()
    G[5] = G[5][::-1]
    cs = mesh_checks((V, G), "flipped")
    assert by_name(cs, "directed edges used twice").value == 3
    assert by_name(cs, "edges not shared by exactly 2 faces").passed
    cs = mesh_checks((V, F[:, ::-1]), "inside out")
    assert not by_name(cs, "volume").passed
    assert by_name(cs, "volume").value == pytest.approx(-signed_volume(V, F))


# --- self-intersection ----------------------------------------------------------


def _lp_intersect(t1, t2) -> bool:
    """Independent test: is there a point in both (closed) triangles? (LP feasibility)"""
    A = np.zeros((5, 6))
    A[:3, :3] = t1.T
    A[:3, 3:] = -t2.T
    A[3, :3] = 1
    A[4, 3:] = 1
    b = np.array([0, 0, 0, 1, 1.0])
    res = linprog(np.zeros(6), A_eq=A, b_eq=b, bounds=[(0, None)] * 6, method="highs")
    return res.status == 0


def _all_pairs_lp(V, F):
    hits = set()
    for i in range(len(F)):
        for j in range(i + 1, len(F)):
            if set(F[i]) & set(F[j]):
                continue
            if _lp_intersect(V[F[i]], V[F[j]]):
                hits.add((i, j))
    return hits


def test_two_overlapping_boxes_self_intersect():
    m = two_boxes((5, 5, 5))
    # trimesh's combinatorial flags do not see it
    assert m.is_watertight and m.is_winding_consistent and m.is_volume
    n, pairs = self_intersections(m.vertices, m.faces, max_report=1000)
    V, F = np.asarray(m.vertices), np.asarray(m.faces)
    expected = _all_pairs_lp(V, F)
    assert n == len(expected) == 18
    assert {tuple(p) for p in pairs.tolist()} == expected
    cs = mesh_checks(m, "2 boxes")
    assert not by_name(cs, "self-intersecting triangle pairs").passed
    assert by_name(cs, "bodies").value == 2
    # apart: no intersection; coplanar overlap (shift along x only): found
    assert self_intersections(*_vf(two_boxes((10.001, 0, 0))))[0] == 0
    V2, F2 = _vf(two_boxes((5, 0, 0)))
    n2, _ = self_intersections(V2, F2)
    assert n2 == len(_all_pairs_lp(V2, F2)) > 0


def _vf(m):
    return np.asarray(m.vertices), np.asarray(m.faces)


def test_adjacent_triangles():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.5, 0.2, 1], [0.2, 0.5, -1], [0, 0, 1], [-1, 0, 0]], float)
    # shared vertex 0, triangle (0,3,4) pierces (0,1,2) at (0.35, 0.35, 0)
    assert self_intersections(V, np.array([[0, 1, 2], [0, 3, 4]]))[0] == 1
    # shared vertex 0, no piercing
    assert self_intersections(V, np.array([[0, 1, 2], [0, 5, 6]]))[0] == 0
    W = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.3, 0.5, 0], [0.3, -0.5, 0], [0.3, 0.5, 0.5]], float)
    # shared edge 0-1: folded onto the same side -> intersection; opposite side / bent -> none
    assert self_intersections(W, np.array([[0, 1, 2], [1, 0, 3]]))[0] == 1
    assert self_intersections(W, np.array([[0, 1, 2], [1, 0, 4]]))[0] == 0
    assert self_intersections(W, np.array([[0, 1, 2], [1, 0, 5]]))[0] == 0
    # duplicated face
    assert self_intersections(W, np.array([[0, 1, 2], [2, 1, 0]]))[0] == 1


@settings(max_examples=60, deadline=None, derandomize=True)
@given(st.lists(st.floats(-1, 1, allow_nan=False), min_size=18, max_size=18))
def test_tri_tri_matches_lp(xs):
    P = np.array(xs).reshape(6, 3)
    t1, t2 = P[:3], P[3:]
    if min(np.linalg.norm(np.cross(t[1] - t[0], t[2] - t[0])) for t in (t1, t2)) < 1e-3:
        return  # skip slivers: LP and tolerance disagree only at measure-zero contacts
    lp = _lp_intersect(t1, t2)
    grown = _lp_intersect(*(t.mean(axis=0) + (t - t.mean(axis=0)) * (1 + 1e-6) for t in (t1, t2)))
    shrunk = _lp_intersect(*(t.mean(axis=0) + (t - t.mean(axis=0)) * (1 - 1e-6) for t in (t1, t2)))
    if grown != shrunk:
        return  # within ~1e-6 of touching: the LP's feasibility tolerance decides, not geometry
    n, _ = self_intersections(P, np.array([[0, 1, 2], [3, 4, 5]]))
    assert bool(n) == lp


def test_broad_phase_matches_brute_force():
    rng = np.random.default_rng(1)
    lo = rng.uniform(0, 10, (400, 3))
    hi = lo + rng.uniform(0, 1.5, (400, 3))
    got = {tuple(p) for p in overlapping_pairs(lo, hi).tolist()}
    ov = np.all((lo[:, None] <= hi[None]) & (lo[None] <= hi[:, None]), axis=2)
    i, j = np.nonzero(np.triu(ov, 1))
    assert got == set(zip(i.tolist(), j.tolist()))


def test_fine_mesh_is_clean():
    s = trimesh.creation.icosphere(subdivisions=6, radius=50.0)  # 81920 triangles
    n, _ = self_intersections(s.vertices, s.faces)
    assert n == 0
    # push one vertex through the opposite side: found
    V = np.asarray(s.vertices).copy()
    V[0] = -V[0] * 1.2
    assert self_intersections(V, s.faces)[0] > 0


def _spur_gear(z=56, m=10.0, b=80.0, bore=100.0):
    """Spur gear outline: per tooth two involute flanks (splines through 9 points),
    a tip arc and a root arc with radial lines; extruded, with a bore."""
    r = m * z / 2
    rb = r * math.cos(math.radians(20))
    ra, rf = r + m, r - 1.25 * m
    tmax = math.sqrt((ra / rb) ** 2 - 1)
    fl = [(rb * (math.cos(t) + t * math.sin(t)), rb * (math.sin(t) - t * math.cos(t))) for t in np.linspace(0, tmax, 9)]
    half = math.pi / (2 * z) + math.tan(math.radians(20)) - math.radians(20)

    def rot(p, a):
        c, s = math.cos(a), math.sin(a)
        return (c * p[0] - s * p[1], s * p[0] + c * p[1])

    pitch = 2 * math.pi / z
    start = rot((rf * math.cos(-half), rf * math.sin(-half)), 0.0)
    wp = cq.Workplane().moveTo(*start)
    for k in range(z):
        a0 = k * pitch
        right = [rot((x, y), a0 - half) for x, y in fl]
        left = [rot((x, -y), a0 + half) for x, y in fl][::-1]
        wp = wp.lineTo(*right[0]).spline(right[1:], includeCurrent=True)
        wp = wp.threePointArc(rot((ra, 0), a0), left[0]).spline(left[1:], includeCurrent=True)
        wp = wp.lineTo(*rot((rf * math.cos(half), rf * math.sin(half)), a0))
        end = start if k == z - 1 else rot((rf * math.cos(-half), rf * math.sin(-half)), a0 + pitch)
        wp = wp.threePointArc(rot((rf, 0), a0 + pitch / 2), end)
    return wp.close().extrude(b).faces(">Z").workplane().hole(bore).val()


def test_big_gear_mesh_valid():
    gear = _spur_gear()
    m = to_trimesh(gear)
    cs = mesh_checks(m, "gear z56 m10 b80", expected_volume=volume(gear), expected_genus=1)
    assert all_passed(cs), failures(cs)
    # a prism: its flanks as strips between their edges' nodes (15 148 triangles; BRepMesh's own triangles of the same
    # faces, with the interior nodes their deflection needed, over 30 000), not a coarser mesh either
    assert 12_000 < len(m.faces) < 20_000
    assert by_name(cs, "chord deflection").value <= MESH_CHORD_LIMIT_MM
