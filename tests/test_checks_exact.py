"""The checks of meshes and exported files, each on geometry made in the test whose answer is known by hand:
tetrahedra, cubes, tori of known genus, boxes whose overlaps are counted on paper, files written byte by byte."""

import math

import numpy as np
import pytest
import trimesh

from propulsor.check import Check
from propulsor.checks.mesh import (
    TooManyPairs,
    _f32_down,
    _f32_up,
    body_labels,
    edge_counts,
    euler_genus,
    mesh_checks,
    overlapping_pairs,
    self_intersections,
    signed_volume,
)

# a tetrahedron wound outward (right-hand normals point away from the centroid)
TET_V = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
TET_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])


def _box(extents=(1.0, 1.0, 1.0), at=(0.0, 0.0, 0.0)):
    b = trimesh.creation.box(extents=extents)
    return np.asarray(b.vertices) + np.asarray(at, float), np.asarray(b.faces, np.int64)


def _join(*meshes):
    V, F, off = [], [], 0
    for v, f in meshes:
        V.append(v)
        F.append(np.asarray(f) + off)
        off += len(v)
    return np.vstack(V), np.vstack(F)


def _torus(R=10.0, r=2.0, at=(0.0, 0.0, 0.0)):
    t = trimesh.creation.torus(major_radius=R, minor_radius=r, major_sections=16, minor_sections=8)
    return np.asarray(t.vertices) + np.asarray(at, float), np.asarray(t.faces, np.int64)


# ------------------------------------------------------------------------------------------- topology
def test_edge_counts_of_a_tetrahedron_by_hand():
    """Six edges, each keyed min * n + max with n = 4 vertices, each in two faces; outward winding uses every
    directed edge once."""
    keys, count, dup = edge_counts(TET_F)
    assert keys.tolist() == [0 * 4 + 1, 0 * 4 + 2, 0 * 4 + 3, 1 * 4 + 2, 1 * 4 + 3, 2 * 4 + 3]
    assert count.tolist() == [2] * 6 and dup == 0
    flipped = TET_F.copy()
    flipped[3] = flipped[3][::-1]  # one face turned over: its three directed edges now repeat their neighbours'
    assert edge_counts(flipped)[2] == 3
    assert edge_counts(TET_F[:3])[1].tolist() == [2, 2, 2, 1, 1, 1]  # the face (1, 2, 3) removed
    keys, count, dup = edge_counts(np.empty((0, 3), np.int64))
    assert len(keys) == 0 and len(count) == 0 and dup == 0


def test_edge_keys_do_not_collide_when_the_last_vertex_is_used():
    """Edge (0, 3) and edge (1, 0) of a mesh whose highest vertex is 3: keys with n = 3 would both be 3."""
    f = np.array([[0, 1, 3], [1, 0, 2]])
    keys, count, _ = edge_counts(f)
    assert keys.tolist() == [1, 2, 3, 6, 7]  # (0,1), (0,2), (0,3), (1,2), (1,3) with n = 4
    assert count.tolist() == [2, 1, 1, 1, 1]


def test_bodies_are_joined_through_any_vertex_of_a_face():
    """Two tetrahedra sharing one vertex are one body through it, whichever corner of the faces it is; two apart are
    two bodies; the label of each face is its body's."""
    far = (TET_V + 5.0, TET_F)
    V, F = _join((TET_V, TET_F), far)
    lab = body_labels(F, len(V))
    assert lab[:4].tolist() == [lab[0]] * 4 and lab[4:].tolist() == [lab[4]] * 4 and lab[0] != lab[4]
    # the second tetrahedron moved so that its vertex 0 is the first one's vertex 3, faces rotated every way
    V2 = np.vstack([TET_V, TET_V[1:] + TET_V[3]])
    F2 = np.where(TET_F == 0, 3, np.where(TET_F > 0, TET_F + 3, TET_F))
    for roll in range(3):
        F_all = np.vstack([TET_F, np.roll(F2, roll, axis=1)])
        assert len(np.unique(body_labels(F_all, len(V2)))) == 1, roll
        assert euler_genus(V2, F_all)[1] == 1


def test_signed_volume_by_the_divergence_theorem():
    assert signed_volume(TET_V, TET_F) == pytest.approx(1 / 6, rel=1e-15)
    assert signed_volume(TET_V, TET_F[:, ::-1]) == pytest.approx(-1 / 6, rel=1e-15)
    v, f = _box((2.0, 3.0, 4.0))
    assert signed_volume(v, f) == pytest.approx(24.0, rel=1e-15)
    # far from the origin: the centroid shift keeps the digits (1e9 mm out, 24 mm^3 to 1e-12)
    assert signed_volume(v + 1e9, f) == pytest.approx(24.0, rel=1e-12)
    assert signed_volume(np.array(v, np.float32) + np.float32(3), f) == pytest.approx(24.0, rel=1e-6)


def test_euler_characteristic_bodies_and_genus():
    assert euler_genus(TET_V, TET_F) == (2, 1, 0)
    assert euler_genus(*_torus()) == (0, 1, 1)
    assert euler_genus(*_join(_torus(), _torus(at=(40.0, 0, 0)))) == (0, 2, 2)
    assert euler_genus(*_join(_box(), _torus(at=(40.0, 0, 0)))) == (2, 2, 1)
    assert euler_genus(*_join((TET_V, TET_F), _box(at=(5.0, 0, 0)))) == (4, 2, 0)
    # a vertex no face uses counts neither in V nor as a body
    assert euler_genus(np.vstack([TET_V, [[9.0, 9, 9]]]), TET_F) == (2, 1, 0)
    assert euler_genus(np.vstack([[[9.0, 9, 9]], TET_V]), TET_F + 1) == (2, 1, 0)


# ------------------------------------------------------------------------------------------- broad phase
def _brute_pairs(lo, hi):
    out = []
    for i in range(len(lo)):
        for j in range(i + 1, len(lo)):
            if np.all(lo[i] <= hi[j]) and np.all(lo[j] <= hi[i]):
                out.append((i, j))
    return out


@pytest.mark.parametrize("n", [2, 3, 5, 8, 9, 31, 64, 97])
def test_overlapping_box_pairs_are_the_brute_force_ones(n):
    """Boxes on a quarter-millimetre grid (exact in float32, so the outward rounding adds nothing): every pair whose
    closed boxes meet on all three axes, touching faces, edges and corners included, and no other."""
    rng = np.random.default_rng(n)
    lo = rng.integers(0, 40, size=(n, 3)) * 0.25
    hi = lo + rng.integers(0, 12, size=(n, 3)) * 0.25
    got = overlapping_pairs(lo, hi)
    assert got.dtype == np.int64 and got.shape[1] == 2
    assert sorted(map(tuple, got.tolist())) == _brute_pairs(lo, hi)


def _with_numpy_levels(monkeypatch):
    """overlapping_pairs with each level of its traversal in the numpy formulation (``tests/box_pairs_reference.py``)
    instead of the compiled ``child_pairs``."""
    from box_pairs_reference import child_pairs

    from propulsor.checks import mesh

    def reference(lo, hi, max_pairs=None):
        with monkeypatch.context() as m:
            m.setattr(mesh, "child_pairs", child_pairs)
            return mesh.overlapping_pairs(lo, hi, max_pairs)

    return reference


@pytest.mark.parametrize("n", [2, 3, 5, 8, 9, 31, 64, 97, 1000, 4097])
def test_the_compiled_traversal_gives_the_numpy_formulations_pairs_in_its_order(n, monkeypatch):
    """``checks/box_pairs.child_pairs`` (each level of the traversal, compiled) against the numpy formulation it
    replaced (``tests/box_pairs_reference.py``, put in its place): the same pairs in the same order, on boxes of a
    grid (many ties, touching faces) and on boxes of any size, odd level lengths included; the pair limit at the same
    level."""
    reference = _with_numpy_levels(monkeypatch)
    rng = np.random.default_rng(n)
    for lo, hi in ((rng.integers(0, 40, size=(n, 3)) * 0.25, None), (rng.uniform(-50.0, 50.0, size=(n, 3)), None)):
        hi = lo + (rng.integers(0, 12, size=(n, 3)) * 0.25 if lo.dtype == np.float64 and np.all(lo % 0.25 == 0)
                   else rng.uniform(0.0, 8.0, size=(n, 3)))
        want, got = reference(lo, hi), overlapping_pairs(lo, hi)
        assert got.dtype == want.dtype == np.int64 and np.array_equal(got, want)
        for limit in (len(want), max(len(want) // 2, 1)):
            try:
                w = reference(lo, hi, max_pairs=limit)
            except TooManyPairs as e:
                with pytest.raises(TooManyPairs) as g:
                    overlapping_pairs(lo, hi, max_pairs=limit)
                assert str(g.value) == str(e)
            else:
                assert np.array_equal(overlapping_pairs(lo, hi, max_pairs=limit), w)


def test_the_compiled_traversal_on_a_gears_triangles_is_the_numpy_one(monkeypatch):
    """The triangles of a toothed ring (a closed mesh of 24 teeth, many boxes touching along shared edges): the
    broad phase's pairs equal the numpy formulation's, in order, and the self-intersection check finds none."""
    import manifold3d as m3d

    reference = _with_numpy_levels(monkeypatch)

    t = np.linspace(0.0, 2 * np.pi, 24 * 16, endpoint=False)
    r = 20.0 + 1.5 * np.cos(24 * t)
    ring = np.column_stack([r * np.cos(t), r * np.sin(t)])
    bore = np.column_stack([8 * np.cos(t), 8 * np.sin(t)])[::-1]
    mesh = m3d.CrossSection([ring, bore]).extrude(6.0).to_mesh()
    V, F = np.asarray(mesh.vert_properties)[:, :3].astype(float), np.asarray(mesh.tri_verts, np.int64)
    T = V[F]
    lo, hi = T.min(axis=1) - 1e-9, T.max(axis=1) + 1e-9
    want = reference(lo, hi)
    assert len(F) > 1000 and len(want) > 5 * len(F)
    assert np.array_equal(overlapping_pairs(lo, hi), want)
    assert self_intersections(V, F)[0] == 0


def test_touching_boxes_overlap_and_boxes_a_hair_apart_do_not():
    lo = np.array([[0.0, 0, 0], [1.0, 0, 0], [0.0, 1, 1], [3.0, 3, 3]])
    hi = np.array([[1.0, 1, 1], [2.0, 1, 1], [1.0, 2, 2], [4.0, 4, 4]])
    # 0-1 share a face, 0-2 an edge, 1-2 the corner (1, 1, 1); 3 is apart
    assert sorted(map(tuple, overlapping_pairs(lo, hi).tolist())) == [(0, 1), (0, 2), (1, 2)]
    assert overlapping_pairs(lo[:1], hi[:1]).shape == (0, 2)
    assert overlapping_pairs(lo[:0], hi[:0]).shape == (0, 2)
    # apart by 1e-3 on one axis only (float32 resolves it at this size)
    for ax in range(3):
        lo2, hi2 = lo[:2].copy(), hi[:2].copy()
        lo2[1] = hi2[0] + 1e-3
        hi2[1] = lo2[1] + 1.0
        assert lo2[1][ax] > hi2[0][ax]
        assert overlapping_pairs(lo2, hi2).shape == (0, 2)
        lo3, hi3 = lo[:2].copy(), hi[:2].copy()
        lo3[1] = 0.0
        hi3[1] = 1.0
        lo3[1][ax] = 1.0 + 1e-3
        hi3[1][ax] = 2.0
        assert overlapping_pairs(lo3, hi3).shape == (0, 2), ax


def test_identical_boxes_make_every_pair_and_the_pair_limit_counts_node_pairs():
    """Eight identical boxes: the 28 pairs.  At the leaves the traversal holds all n (n + 1) / 2 = 36 node pairs
    (each leaf with itself too): a limit of 36 lets it through, 35 stops it."""
    lo = np.zeros((8, 3))
    hi = np.ones((8, 3))
    assert len(overlapping_pairs(lo, hi)) == 28
    assert len(overlapping_pairs(lo, hi, max_pairs=36)) == 28
    with pytest.raises(TooManyPairs) as e:
        overlapping_pairs(lo, hi, max_pairs=35)
    assert str(e.value) == "more than 35 pairs of overlapping triangle boxes"


def test_float32_bounds_round_outwards():
    x = np.array([0.1, -0.1, 1e-8, 3.0, -2.5, 123456.789])
    down, up = _f32_down(x), _f32_up(x)
    assert down.dtype == np.float32 and up.dtype == np.float32
    assert np.all(down.astype(float) <= x) and np.all(up.astype(float) >= x)
    # at most one float32 step from x, and exact where x is a float32
    assert np.all(np.nextafter(down, np.float32(np.inf)).astype(float) >= x)
    assert np.all(np.nextafter(up, np.float32(-np.inf)).astype(float) <= x)
    assert down[3] == up[3] == np.float32(3.0) and down[4] == up[4] == np.float32(-2.5)
    assert down[0] < up[0] and down[1] < up[1]


# ------------------------------------------------------------------------------------------- narrow phase
def _pierced(gap=-0.5):
    """A triangle in z = 0 and a vertical one whose lowest vertex is `gap` above the plane (negative: through it)."""
    V = np.array([[-2.0, -2, 0], [4, -2, 0], [-2, 4, 0], [0.0, -1, gap], [0.0, 1, gap], [0.0, 0, gap + 3]])
    return V, np.array([[0, 1, 2], [3, 4, 5]])


def test_a_triangle_through_another_is_one_pair():
    V, F = _pierced()
    n, pairs = self_intersections(V, F)
    assert n == 1 and pairs.tolist() == [[0, 1]] and pairs.dtype == np.int64
    # a zero-area triangle lying across both is skipped
    V2 = np.vstack([V, [[-1.0, 0, -1], [1.0, 0, 1], [0.0, 0, 0]]])
    F2 = np.vstack([F, [[6, 7, 8]]])
    assert self_intersections(V2, F2)[0] == 1
    assert self_intersections(V, F[:1]) == (0, pytest.approx(np.empty((0, 2))))
    assert self_intersections(V, F[:1])[1].shape == (0, 2)


def test_the_default_tolerance_is_a_ten_billionth_of_the_size():
    """The vertical triangle's lowest corner above the plane by 0.5 and by 2 tolerances (1e-10 of the bounding
    box's diagonal): touching within the tolerance is an intersection, twice as far is not."""
    V, F = _pierced(0.0)
    diag = float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))
    eps = 1e-10 * diag
    assert self_intersections(*_pierced(0.5 * eps))[0] == 1
    assert self_intersections(*_pierced(2.0 * eps))[0] == 0
    assert self_intersections(*_pierced(2.0 * eps), eps=4.0 * eps)[0] == 1
    assert self_intersections(*_pierced(1e-3))[0] == 0


def test_many_crossings_are_counted_and_the_report_is_cut():
    """Three vertical triangles through one horizontal one: 3 pairs, reported up to max_report."""
    V = [[-10.0, -10, 0], [10, -10, 0], [-10, 10, 0]]
    F = [[0, 1, 2]]
    for k, x in enumerate((-5.0, -3.0, -1.0)):
        V += [[x, -1, -1], [x, 1, -1], [x, 0, 2]]
        F.append([3 + 3 * k, 4 + 3 * k, 5 + 3 * k])
    n, pairs = self_intersections(np.array(V), np.array(F), max_report=2)
    assert n == 3 and len(pairs) == 2 and set(map(tuple, pairs.tolist())) <= {(0, 1), (0, 2), (0, 3)}
    n, pairs = self_intersections(np.array(V), np.array(F))
    assert sorted(map(tuple, pairs.tolist())) == [(0, 1), (0, 2), (0, 3)]
    with pytest.raises(TooManyPairs):
        self_intersections(np.array(V), np.array(F), max_pairs=2)


# ------------------------------------------------------------------------------------------- mesh_checks
def _by_name(checks):
    return {c.name.split(": ", 1)[1]: c for c in checks}


def test_mesh_checks_of_a_valid_box_in_full():
    v, f = _box((2.0, 3.0, 4.0))
    checks = mesh_checks((v, f), name="box", expected_genus=0)
    assert [c.name for c in checks] == [
        "box: edges not shared by exactly 2 faces", "box: directed edges used twice", "box: mesh volume",
        "box: bodies", "box: genus", "box: self-intersecting triangle pairs"]
    assert all(c.passed for c in checks)
    c = _by_name(checks)
    assert c["edges not shared by exactly 2 faces"] == Check(
        "box: edges not shared by exactly 2 faces", True, 0, 0, "edges", "watertight: every edge has two faces")
    assert c["directed edges used twice"] == Check(
        "box: directed edges used twice", True, 0, 0, "edges", "consistent winding: each directed edge once")
    assert c["mesh volume"].value == pytest.approx(24.0, rel=1e-15) and c["mesh volume"].limit == 0.0
    assert (c["mesh volume"].unit, c["mesh volume"].message) == ("mm^3", "positive enclosed volume (outward normals)")
    assert c["bodies"] == Check("box: bodies", True, 1, 1, "", "connected bodies (Euler characteristic 2)")
    assert c["genus"] == Check("box: genus", True, 0, 0, "", "genus from chi = V - E + F = 2")
    assert c["self-intersecting triangle pairs"] == Check(
        "box: self-intersecting triangle pairs", True, 0, 0, "pairs",
        "no two triangles intersect (BVH + triangle-triangle test)")
    assert mesh_checks((v, f))[0].name == "mesh: edges not shared by exactly 2 faces"


def test_mesh_checks_fail_each_defect_with_its_count():
    v, f = _box()
    c = _by_name(mesh_checks((v, f[:-1]), name="m"))  # a triangle missing: its three edges have one face
    assert (c["edges not shared by exactly 2 faces"].passed, c["edges not shared by exactly 2 faces"].value) == (False, 3)
    f2 = f.copy()
    f2[0] = f2[0][::-1]
    c = _by_name(mesh_checks((v, f2), name="m"))
    assert (c["directed edges used twice"].passed, c["directed edges used twice"].value) == (False, 3)
    c = _by_name(mesh_checks((v, f[:, ::-1]), name="m"))  # inside out
    assert not c["mesh volume"].passed and c["mesh volume"].value == pytest.approx(-1.0, rel=1e-15)
    two = _join(_box(), _box(at=(5.0, 0, 0)))
    c = _by_name(mesh_checks(two, name="m"))
    assert c["bodies"] == Check("m: bodies", False, 2, 1, "", "connected bodies (Euler characteristic 4)")
    c = _by_name(mesh_checks(two, name="m", expected_bodies=2))
    assert c["bodies"].passed
    c = _by_name(mesh_checks(two, name="m", expected_bodies=None))
    assert c["bodies"] == Check("m: bodies", True, 2, None, "", "connected bodies, not prescribed (Euler characteristic 4)")
    c = _by_name(mesh_checks(_torus(), name="m", expected_genus=0))
    assert c["genus"] == Check("m: genus", False, 1, 0, "", "genus from chi = V - E + F = 0")
    assert "genus" not in _by_name(mesh_checks(_torus(), name="m"))
    empty = mesh_checks((v, np.empty((0, 3), np.int64)), name="m")
    assert empty == [Check("m: has triangles", False, False, True, "", "mesh is empty")]


def test_two_interpenetrating_boxes_pass_trimesh_but_not_the_self_intersection_check():
    """A unit cube and one moved by half a unit on each axis: closed, wound outward, but their surfaces cross."""
    V, F = _join(_box(), _box(at=(0.5, 0.5, 0.5)))
    tm = trimesh.Trimesh(V, F, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    n, pairs = self_intersections(V, F)
    assert n > 0
    c = _by_name(mesh_checks((V, F), name="m", expected_bodies=2))
    x = c["self-intersecting triangle pairs"]
    assert not x.passed and x.value == n and x.limit == 0
    assert x.message == f"{n} intersecting triangle pairs, e.g. faces {pairs[:3].tolist()}"
    c = _by_name(mesh_checks((V, F), name="m", expected_bodies=2, max_box_pairs=3))
    x = c["self-intersecting triangle pairs"]
    assert not x.passed and x.value == -1
    assert x.message == "not tested: more than 3 pairs of overlapping triangle boxes"


def test_chord_deflection_and_volume_against_the_brep():
    """The volume may differ from the B-rep's by deflection x area (every triangle within the deflection of the
    surface), or by the relative tolerance where that is larger; the deflection is read from the mesh's metadata."""
    v, f = _box((2.0, 3.0, 4.0))  # 24 mm^3, area 52 mm^2
    c = _by_name(mesh_checks((v, f), name="m", chord_deflection=0.002, expected_volume=24.1))
    d = c["chord deflection"]
    assert d == Check("m: chord deflection", True, 0.002, 0.01, "mm",
                      "tessellation chord error: measured on a prism's side strips and at a cone's or sphere's apex, "
                      "OCCT's estimate on the faces BRepMesh meshes")
    vb = c["volume vs B-rep"]
    assert vb.passed  # 0.1 <= 0.002 x 52 = 0.104
    assert vb.limit == {"expected": 24.1, "rel_tol": 1e-3, "abs_tol": pytest.approx(0.104, rel=1e-12)}
    assert vb.message == ("mesh volume 24 vs B-rep 24.1 mm^3 (deviation 0.1; allowed: deflection 0.002 mm × area 52 "
                          "mm^2 = 0.104 mm^3, or 0.001 of the volume)")
    assert not _by_name(mesh_checks((v, f), name="m", chord_deflection=0.0019, expected_volume=24.1))[
        "volume vs B-rep"].passed  # 0.1 > 0.0988
    assert not _by_name(mesh_checks((v, f), name="m", chord_deflection=0.0101))["chord deflection"].passed
    # without a deflection: the limit's 0.01 mm x 52 mm^2 = 0.52 mm^3; brep_volume is the same argument
    c = _by_name(mesh_checks((v, f), name="m", brep_volume=24.5))
    assert c["volume vs B-rep"].passed and "deflection 0.01 mm" in c["volume vs B-rep"].message
    assert "chord deflection" not in c
    assert not _by_name(mesh_checks((v, f), name="m", brep_volume=24.53))["volume vs B-rep"].passed
    # the relative tolerance where it is the larger: 1 % of 24 = 0.24 mm^3 against 0.0052
    assert _by_name(mesh_checks((v, f), name="m", chord_deflection=1e-4, expected_volume=24.2,
                                volume_rel_tol=0.01))["volume vs B-rep"].passed
    tm = trimesh.Trimesh(v, f, process=False)
    tm.metadata["chord_deflection_mm"] = 0.003
    c = _by_name(mesh_checks(tm, name="m", expected_volume=24.0))
    assert c["chord deflection"].value == 0.003 and "deflection 0.003 mm" in c["volume vs B-rep"].message
    # a (V, F) tuple has no metadata: no deflection check
    assert "chord deflection" not in _by_name(mesh_checks((v, f), name="m"))
    assert "volume vs B-rep" not in _by_name(mesh_checks(tm, name="m"))


# ------------------------------------------------------------------------------------------- formats
import io  # noqa: E402
import struct  # noqa: E402
import zipfile  # noqa: E402

import ezdxf  # noqa: E402

from propulsor.checks import formats  # noqa: E402
from propulsor.checks.safe_read import Refused  # noqa: E402
from propulsor.policy import (  # noqa: E402
    CHORD_TOL_MM, DXF_COORD_MAX_MM, DXF_POINTS_MAX, READ_LIMIT_BYTES, THREEMF_MEMBERS_MAX, THREEMF_UNZIPPED_MAX_BYTES)


def _refused(fn, *args) -> str:
    with pytest.raises(Refused) as e:
        fn(*args)
    return str(e.value)


def _binary_stl(n: int, header: bytes = b"binary") -> bytes:
    return header.ljust(80, b" ") + struct.pack("<I", n) + bytes(50 * n)


def test_stl_kind_binary_by_its_length_and_ascii_by_its_first_word():
    assert formats.stl_kind(_binary_stl(0)) == "binary"  # 84 bytes exactly
    assert formats.stl_kind(_binary_stl(2)) == "binary"
    # a binary header may begin with 'solid' (many exporters write it): the length decides first
    assert formats.stl_kind(_binary_stl(3, b"solid part")) == "binary"
    assert formats.stl_kind(b"  \n SOLID x\nendsolid x\n") == "ascii"
    assert formats.stl_kind(_binary_stl(3, b"solid part") + b"\n") == "ascii"
    assert _refused(formats.stl_kind, b"0123456789") == (
        "10 bytes: shorter than a binary STL header (84 bytes) and not ASCII")
    assert _refused(formats.stl_kind, _binary_stl(0)[:83]) == (
        "83 bytes: shorter than a binary STL header (84 bytes) and not ASCII")
    assert _refused(formats.stl_kind, _binary_stl(2) + b"x") == (
        "binary STL declares 2 triangles, i.e. 84 + 50 n = 184 bytes, but the file has 185")
    assert _refused(formats.stl_kind, _binary_stl(2)[:-1]) == (
        "binary STL declares 2 triangles, i.e. 84 + 50 n = 184 bytes, but the file has 183")


def test_an_ascii_stl_is_read_up_to_its_own_limit():
    lim = READ_LIMIT_BYTES["stl_ascii"]
    body = b"solid x\n"
    assert formats.stl_kind(body + b" " * (lim - len(body))) == "ascii"
    assert _refused(formats.stl_kind, body + b" " * (lim - len(body) + 1)) == (
        f"ASCII STL of {lim + 1} bytes: larger than the {lim} bytes allowed")


def _zip(members: dict, method=zipfile.ZIP_DEFLATED) -> bytes:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", method) as zf:
        for name, data in members.items():
            zf.writestr(name, data)
    return buf.getvalue()


def test_3mf_zip_members_counted_and_sized_before_and_while_inflating():
    formats.check_3mf_zip(_zip({"3D/a.model": b"<model/>", "[Content_Types].xml": b"x"}))
    assert _refused(formats.check_3mf_zip, b"PK\x03\x04 not really").startswith("not a zip archive: ")
    assert _refused(formats.check_3mf_zip, b"") == "not a zip archive: File is not a zip file"
    many = {f"m{k}": b"" for k in range(THREEMF_MEMBERS_MAX)}
    formats.check_3mf_zip(_zip(many))
    many["one more"] = b""
    assert _refused(formats.check_3mf_zip, _zip(many)) == (
        f"{THREEMF_MEMBERS_MAX + 1} zip members: more than {THREEMF_MEMBERS_MAX}")
    # the declared sizes add up across members: exactly the limit inflates, one byte more is refused unread
    half = THREEMF_UNZIPPED_MAX_BYTES // 2
    formats.check_3mf_zip(_zip({"a": bytes(half), "b": bytes(THREEMF_UNZIPPED_MAX_BYTES - half)}))
    assert _refused(formats.check_3mf_zip, _zip({"a": bytes(half), "b": bytes(THREEMF_UNZIPPED_MAX_BYTES - half + 1)})) == (
        f"zip members declare {THREEMF_UNZIPPED_MAX_BYTES + 1} bytes: more than {THREEMF_UNZIPPED_MAX_BYTES} unzipped")


def test_a_corrupt_zip_member_is_named():
    data = bytearray(_zip({"3D/a.model": b"<model>" + b"x" * 100 + b"</model>"}, zipfile.ZIP_STORED))
    k = data.index(b"xxxx")
    data[k] = ord("y")  # the stored bytes no longer match their CRC-32
    assert _refused(formats.check_3mf_zip, bytes(data)) == (
        "zip member '3D/a.model' unreadable: BadZipFile: Bad CRC-32 for file '3D/a.model'")


def test_arc_points_by_the_sagitta():
    """An arc flattened so that no chord strays more than CHORD_TOL_MM from it: a chord spanning angle da has the
    sagitta r (1 - cos(da / 2)); the points are ceil(sweep / da) + 1, and an arc no larger than the tolerance is its
    two ends."""
    for r, sweep in ((10.0, math.pi), (1.0, 2 * math.pi), (250.0, 0.3), (10.0, -math.pi / 2), (0.0051, 1.0)):
        da = 2 * math.acos(1 - CHORD_TOL_MM / r)
        assert r * (1 - math.cos(da / 2)) == pytest.approx(CHORD_TOL_MM, rel=1e-9)
        assert formats._arc_points(r, sweep) == math.ceil(abs(sweep) / da) + 1
    assert formats._arc_points(CHORD_TOL_MM, math.pi) == 2
    assert formats._arc_points(0.0, 1.0) == 2
    assert formats._arc_points(10.0, 0.0) == 1
    # just above the tolerance: the half angle's cosine is 1 - tol / r (acos of at least -1: r > tol / 2)
    r = CHORD_TOL_MM * (1 + 1e-9)
    assert formats._arc_points(r, math.pi) == math.ceil(math.pi / (2 * math.acos(1 - CHORD_TOL_MM / r))) + 1


def test_coordinates_are_numbers_within_the_drawings_span():
    assert formats._coord("2.5", "x") == 2.5
    assert formats._coord(DXF_COORD_MAX_MM, "x") == DXF_COORD_MAX_MM
    assert formats._coord(-DXF_COORD_MAX_MM, "x") == -DXF_COORD_MAX_MM
    beyond = math.nextafter(DXF_COORD_MAX_MM, math.inf)
    assert _refused(formats._coord, beyond, "LINE #1 start") == (
        f"LINE #1 start = {beyond!r}: beyond the ±100000 mm a drawing may span")
    assert _refused(formats._coord, -beyond, "c") == f"c = {-beyond!r}: beyond the ±100000 mm a drawing may span"
    assert _refused(formats._coord, float("nan"), "c") == "c = nan: beyond the ±100000 mm a drawing may span"
    assert _refused(formats._coord, "abc", "c") == "c = 'abc': not a number"
    assert _refused(formats._coord, None, "c") == "c = None: not a number"


def test_bulged_polylines_count_their_arcs_points():
    """A bulge b between two points a chord c apart is an arc of sweep 4 atan b and radius c (1 + b^2) / (4 |b|):
    b = 1 is a half circle on the chord."""
    pts = [(0.0, 0.0, 1.0), (2.0, 0.0, 0.0), (2.0, 3.0, 0.0)]
    half = formats._arc_points(1.0, math.pi)
    assert formats._bulged(pts, "P", closed=False) == 3 + half
    assert formats._bulged([(x, y, 0.0) for x, y, _ in pts], "P", closed=True) == 3
    # closed: the last vertex's bulge bends the closing segment (3, 4, 5 triangle: the chord back is 3.6056)
    closing = [(0.0, 0.0, 0.0), (2.0, 0.0, 0.0), (2.0, 3.0, -0.5)]
    c = math.hypot(2.0, 3.0)
    assert formats._bulged(closing, "P", closed=True) == 3 + formats._arc_points(
        c * (1 + 0.25) / 2.0, 4 * math.atan(-0.5))
    assert formats._bulged(closing, "P", closed=False) == 3
    # a bulge below 1e-15 is a straight segment; 2e-15 is an arc of radius 1.25e14 mm, beyond the drawing
    assert formats._bulged([(0.0, 0.0, 1e-16), (1.0, 0.0, 0.0)], "P", closed=False) == 2
    msg = _refused(formats._bulged, [(0.0, 0.0, 2e-15), (1.0, 0.0, 0.0)], "P", False)
    assert msg == f"P arc radius (bulge 2e-15) = {1.0 * (1 + 4e-30) / 8e-15!r}: beyond the ±100000 mm a drawing may span"
    assert _refused(formats._bulged, [(0.0, 0.0, float("inf")), (1.0, 0.0, 0.0)], "P", False) == "P bulge = inf: not finite"
    assert _refused(formats._bulged, [(0.0, 0.0, "b"), (1.0, 0.0, 0.0)], "P", False) == "P bulge = 'b': not a number"
    assert _refused(formats._bulged, [(0.0, float("inf"), 0.0)], "P", False) == (
        "P y = inf: beyond the ±100000 mm a drawing may span")
    assert _refused(formats._bulged, [(1e6, 0.0, 0.0)], "P", False) == (
        "P x = 1000000.0: beyond the ±100000 mm a drawing may span")


def _doc():
    doc = ezdxf.new("R2010")
    return doc, doc.modelspace()


def test_every_entity_kind_of_a_drawing_is_bounded():
    doc, msp = _doc()
    msp.add_line((0, 0), (10, 0))
    msp.add_point((1, 2))
    msp.add_lwpolyline([(0, 0, 0, 0, 1.0), (2, 0, 0, 0, 0.0)], format="xyseb")
    msp.add_polyline2d([(0, 0), (5, 0), (5, 5)], close=True)
    msp.add_circle((1, 1), 5.0)
    msp.add_arc((0, 0), 3.0, 0, 90)
    msp.add_ellipse((0, 0), major_axis=(10, 0), ratio=1.0)
    msp.add_spline([(0, 0), (1, 1), (2, 0), (3, 1)])
    formats.check_dxf_doc(doc)

    def refused_one(add) -> str:
        d, m = _doc()
        add(m)
        return _refused(formats.check_dxf_doc, d)

    span = "beyond the ±100000 mm a drawing may span"
    assert refused_one(lambda m: m.add_line((0, 0), (1e6, 0))) == f"LINE #1 end = 1000000.0: {span}"
    assert refused_one(lambda m: m.add_point((0, 0, -2e5))) == f"POINT #1 location = -200000.0: {span}"
    assert refused_one(lambda m: (m.add_line((0, 0), (1, 0)), m.add_circle((0, 2e5), 1.0))) == (
        f"CIRCLE #2 centre y = 200000.0: {span}")
    assert refused_one(lambda m: m.add_arc((0, 0, 3e5), 1.0, 0, 90)) == f"ARC #1 centre z = 300000.0: {span}"
    assert refused_one(lambda m: m.add_circle((0, 0), 2e5)) == f"CIRCLE #1 radius = 200000.0: {span}"
    assert refused_one(lambda m: m.add_ellipse((0, 0), major_axis=(2e5, 0), ratio=0.5)) == (
        f"ELLIPSE #1 major axis = 200000.0: {span}")
    assert refused_one(lambda m: m.add_ellipse((0, 0), major_axis=(8e4, 8e4), ratio=0.5)) == (
        f"ELLIPSE #1 major axis = {math.hypot(8e4, 8e4)!r}: {span}")
    assert refused_one(lambda m: m.add_ellipse((4e5, 0), major_axis=(1, 0), ratio=0.5)) == (
        f"ELLIPSE #1 centre x = 400000.0: {span}")

    def ellipse_of_ratio(ratio: str):
        """ezdxf clamps a ratio set in code to (0, 1]; a file read as written keeps it"""
        d, m = _doc()
        m.add_ellipse((0, 0), major_axis=(10, 0), ratio=0.123456)
        text = io.StringIO()
        d.write(text)
        return ezdxf.read(io.StringIO(text.getvalue().replace("0.123456", ratio)))

    for bad in ("0.0", "1.0000001", "-0.5", "nan", "1.5"):
        assert _refused(formats.check_dxf_doc, ellipse_of_ratio(bad)) == (
            f"ELLIPSE #1 ratio = {float(bad)!r}: not within (0, 1]")
    formats.check_dxf_doc(ellipse_of_ratio("1.0"))
    formats.check_dxf_doc(ellipse_of_ratio("1e-9"))
    assert refused_one(lambda m: m.add_spline([(0, 0), (1, 2e5)])) == f"SPLINE #1 point = 200000.0: {span}"

    def spline(m, degree=3, knot=None):
        s = m.add_spline(fit_points=None)
        s.control_points = [(0, 0, 0), (1, 1, 0), (2, 0, 0), (3, 1, 0)]
        s.dxf.degree = degree
        s.knots = [0, 0, 0, 0, 1, 1, 1, 1] if knot is None else [0, 0, 0, 0, knot, 1, 1, 1]
        return s

    assert refused_one(lambda m: spline(m, degree=12)) == "SPLINE #1 degree = 12: not within 1 ... 11"
    # degree 0 only from a file (ezdxf refuses it in code)
    d, m = _doc()
    spline(m, degree=3)
    text = io.StringIO()
    d.write(text)
    d0 = ezdxf.read(io.StringIO(text.getvalue().replace("AcDbSpline\n 70\n0\n 71\n3\n", "AcDbSpline\n 70\n0\n 71\n0\n")))
    assert _refused(formats.check_dxf_doc, d0) == "SPLINE #1 degree = 0: not within 1 ... 11"
    assert refused_one(lambda m: spline(m, knot=float("inf"))) == "SPLINE #1 knot = inf: not finite"
    d, m = _doc()
    spline(m, degree=11)
    spline(m, degree=1)
    formats.check_dxf_doc(d)

    def poly3(m, z):
        p = m.add_polyline3d([(0, 0, 0), (1, 0, z)])
        return p

    assert refused_one(lambda m: poly3(m, 2e5)) == f"POLYLINE #1 z = 200000.0: {span}"
    assert refused_one(lambda m: m.add_polyline2d([(0, 0), (2e5, 0)])) == f"POLYLINE #1 x = 200000.0: {span}"


def test_a_drawing_whose_curves_flatten_past_the_limit_is_refused_at_the_entity_that_passes_it():
    """Circles of 1000 mm: each flattens to ceil(2 pi / da) + 1 points; as many as fit in DXF_POINTS_MAX pass, one more
    is refused, naming itself."""
    r = 1000.0
    each = math.ceil(2 * math.pi / (2 * math.acos(1 - CHORD_TOL_MM / r))) + 1
    fit = DXF_POINTS_MAX // each
    doc, msp = _doc()
    for _ in range(fit):
        msp.add_circle((0, 0), r)
    formats.check_dxf_doc(doc)
    msp.add_circle((0, 0), r)
    assert _refused(formats.check_dxf_doc, doc) == (
        f"its curves flatten to more than {DXF_POINTS_MAX} points (at CIRCLE #{fit + 1})")
    # a spline counts 64 points a control or fit point (and at least 64)
    doc, msp = _doc()
    n = DXF_POINTS_MAX // 64
    s = msp.add_spline(fit_points=None)
    s.control_points = [(k * 1e-3, 0, 0) for k in range(n)]
    formats.check_dxf_doc(doc)
    s2 = msp.add_spline(fit_points=None)
    s2.control_points = []
    assert _refused(formats.check_dxf_doc, doc) == (
        f"its curves flatten to more than {DXF_POINTS_MAX} points (at SPLINE #2)")


# ------------------------------------------------------------------------------------------- files
import hashlib  # noqa: E402
import json  # noqa: E402
import os  # noqa: E402

from propulsor.checks import files  # noqa: E402
from propulsor.errors import EnvironmentFailure  # noqa: E402
from propulsor.policy import CHECK_MEMORY_CEILING  # noqa: E402


def _box_stl(path, extents=(2.0, 3.0, 4.0)):
    path.write_bytes(trimesh.creation.box(extents=extents).export(file_type="stl"))
    return path


def _manifest(folder, entries, checks=(), **extra):
    data = {"part": "t", "files": entries, "checks": list(checks), **extra}
    (folder / "manifest.json").write_text(json.dumps(data))
    return folder / "manifest.json"


def _entry(folder, rel, **kw):
    data = (folder / rel).read_bytes()
    return {"path": rel, "bytes": len(data), "sha256": hashlib.sha256(data).hexdigest(), **kw}


def test_manifests_are_read_once_until_they_change(tmp_path):
    files._MANIFESTS.clear()
    assert files.load_manifest(tmp_path / "none.json") is None
    (tmp_path / "bad.json").write_text("{not json")
    assert files.load_manifest(tmp_path / "bad.json") is None
    (tmp_path / "list.json").write_text("[1, 2]")
    assert files.load_manifest(tmp_path / "list.json") == [1, 2]
    m = _manifest(tmp_path, [])
    a = files.load_manifest(m)
    assert a == {"part": "t", "files": [], "checks": []} and files.load_manifest(m) is a
    m.write_text(json.dumps({"part": "changed", "files": [], "checks": []}))
    assert files.load_manifest(m)["part"] == "changed"
    # more than 64 remembered: the memory starts again
    files._MANIFESTS.clear()
    for k in range(65):
        (tmp_path / f"m{k}.json").write_text("{}")
        files.load_manifest(tmp_path / f"m{k}.json")
    assert len(files._MANIFESTS) == 65
    (tmp_path / "m65.json").write_text("{}")
    files.load_manifest(tmp_path / "m65.json")
    assert len(files._MANIFESTS) == 1


def test_the_manifest_entry_of_a_file_is_the_nearest_manifests_with_numbers_only(tmp_path):
    files._MANIFESTS.clear()
    (tmp_path / "sub").mkdir()
    f = tmp_path / "sub" / "gear.stl"
    assert files._manifest_entry(f) == {}
    _manifest(tmp_path, [{"path": "sub/gear.stl", "volume_mm3": 12.5, "genus": True, "bodies": "1", "bytes": 7,
                          "note": "kept"}, "not an entry"], derived={"gear_volume_mm3": 99.0})
    assert files._manifest_entry(f) == {"path": "sub/gear.stl", "volume_mm3": 12.5, "bytes": 7, "note": "kept"}
    # the derived '<stem>_volume_mm3' where the entry has none (or a non-number)
    files._MANIFESTS.clear()
    _manifest(tmp_path, [{"path": "sub/gear.stl", "volume_mm3": "12.5"}], derived={"gear_volume_mm3": 99.0})
    assert files._manifest_entry(f) == {"path": "sub/gear.stl", "volume_mm3": 99.0}
    files._MANIFESTS.clear()
    _manifest(tmp_path, [{"path": "sub/gear.stl"}], derived={"gear_volume_mm3": "99"})
    assert files._manifest_entry(f) == {"path": "sub/gear.stl"}
    files._MANIFESTS.clear()
    _manifest(tmp_path, [], derived={"gear_volume_mm3": 5})
    assert files._manifest_entry(f) == {"volume_mm3": 5}
    files._MANIFESTS.clear()
    _manifest(tmp_path, [], derived=[1])
    assert files._manifest_entry(f) == {}
    # a nearer manifest wins, even a malformed one (its own check reports it)
    files._MANIFESTS.clear()
    (tmp_path / "sub" / "manifest.json").write_text(json.dumps({"files": {"gear.stl": {}}}))
    assert files._manifest_entry(f) == {}
    (tmp_path / "sub" / "manifest.json").write_text(json.dumps({"files": [{"path": "gear.stl", "genus": 2}]}))
    files._MANIFESTS.clear()
    assert files._manifest_entry(f) == {"path": "gear.stl", "genus": 2}
    (tmp_path / "sub" / "manifest.json").write_text("[]")
    files._MANIFESTS.clear()
    assert files._manifest_entry(f) == {}


def test_a_mesh_file_is_checked_against_its_manifest_entry(tmp_path):
    files._MANIFESTS.clear()
    stl = _box_stl(tmp_path / "box.stl")
    tm = trimesh.creation.box(extents=(2.0, 3.0, 4.0))
    (tmp_path / "box.3mf").write_bytes(tm.export(file_type="3mf"))
    for name in ("box.stl", "box.3mf"):
        cs = files.check_mesh_file(tmp_path / name)
        assert cs[0] == Check(f"{name}: loads", True, True, True, "", "12 triangles, 8 vertices")
        assert all(c.passed for c in cs) and len(cs) == 6
        assert [c.name for c in cs][1:] == [f"{name}: {n}" for n in (
            "edges not shared by exactly 2 faces", "directed edges used twice", "mesh volume", "bodies",
            "self-intersecting triangle pairs")]
    _manifest(tmp_path, [{"path": "box.stl", "volume_mm3": 24.6, "genus": 1, "bodies": 2}])
    cs = {c.name: c for c in files.check_mesh_file(stl)}
    assert not cs["box.stl: bodies"].passed and cs["box.stl: bodies"].limit == 2
    assert not cs["box.stl: genus"].passed and cs["box.stl: genus"].limit == 1
    vb = cs["box.stl: volume vs B-rep"]
    # an STL records no deflection: the limit's 0.01 mm x 52 mm^2 = 0.52 mm^3 (or 1e-3 of the volume)
    assert not vb.passed and vb.limit["expected"] == 24.6 and vb.limit["rel_tol"] == 1e-3
    files._MANIFESTS.clear()
    _manifest(tmp_path, [{"path": "box.stl", "volume_mm3": 24.5}])
    assert {c.name: c for c in files.check_mesh_file(stl)}["box.stl: volume vs B-rep"].passed


def test_a_mesh_file_that_does_not_load_is_one_failed_check(tmp_path):
    (tmp_path / "short.stl").write_bytes(b"0123456789")
    assert files.check_mesh_file(tmp_path / "short.stl") == [Check(
        "short.stl: loads", False, False, True, "", "10 bytes: shorter than a binary STL header (84 bytes) and not ASCII")]
    (tmp_path / "NOT.3MF").write_bytes(b"plain text")
    assert files.check_mesh_file(tmp_path / "NOT.3MF") == [Check(
        "NOT.3MF: loads", False, False, True, "", "not a zip archive: File is not a zip file")]
    (tmp_path / "empty.stl").write_bytes(b"\0" * 84)
    assert files.check_mesh_file(tmp_path / "empty.stl") == [Check(
        "empty.stl: loads", False, False, True, "", "ValueError: no triangles")]


def _dxf(path, loops=(((0, 0), (10, 0), (10, 5)),), insunits=4, layer="CUT", closed=True, extra=None):
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = insunits
    msp = doc.modelspace()
    for pts in loops:
        msp.add_lwpolyline(pts, close=closed, dxfattribs={"layer": layer})
    if extra:
        extra(msp)
    doc.saveas(path)
    return path


def test_a_dxf_is_in_millimetres_with_closed_loops_to_cut(tmp_path):
    cs = files.check_dxf_file(_dxf(tmp_path / "p.dxf"))
    assert cs == [
        Check("p.dxf: DXF parses", True, True, True, "", "DXF AC1024"),
        Check("p.dxf: $INSUNITS", True, 4, 4, "", "drawing units millimetres (4)"),
        Check("p.dxf: closed loops on CUT", True, 1.0, 1, "", "the outline to cut"),
        Check("p.dxf: open entities on CUT", True, 0, 0, "", "every cut contour closed"),
        Check("p.dxf: degenerate CUT loops", True, 0, 0, "", "each loop >= 3 points, non-zero area"),
    ]
    by = lambda p: {c.name.split(": ", 1)[1]: c for c in files.check_dxf_file(p)}  # noqa: E731
    c = by(_dxf(tmp_path / "in.dxf", insunits=1))
    assert not c["$INSUNITS"].passed and c["$INSUNITS"].value == 1
    c = by(_dxf(tmp_path / "open.dxf", closed=False))
    assert not c["open entities on CUT"].passed and c["open entities on CUT"].value == 1
    assert not c["closed loops on CUT"].passed and c["closed loops on CUT"].value == 0
    c = by(_dxf(tmp_path / "ref.dxf", layer="REF"))
    assert not c["closed loops on CUT"].passed and c["open entities on CUT"].passed
    # a loop of collinear points has no area; the other is fine
    c = by(_dxf(tmp_path / "flat.dxf", loops=(((0, 0), (10, 0), (20, 0)), ((0, 0), (1, 0), (0, 1)))))
    assert c["degenerate CUT loops"].value == 1 and not c["degenerate CUT loops"].passed
    assert c["closed loops on CUT"].value == 2
    c = by(_dxf(tmp_path / "two.dxf", loops=(((0, 0), (10, 0)),)))
    assert c["degenerate CUT loops"].value == 1
    far = _dxf(tmp_path / "far.dxf", extra=lambda m: m.add_circle((0, 0), 2e5))
    assert files.check_dxf_file(far) == [Check("far.dxf: DXF within bounds", False, False, True, "",
                                               "CIRCLE #2 radius = 200000.0: beyond the ±100000 mm a drawing may span")]
    (tmp_path / "junk.dxf").write_text("0\nSECTION\n2\nNOPE\n")
    c = files.check_dxf_file(tmp_path / "junk.dxf")
    assert len(c) == 1 and c[0].name == "junk.dxf: DXF parses" and not c[0].passed and ": " in c[0].message
    big = tmp_path / "big.dxf"
    with open(big, "wb") as fh:
        fh.truncate(READ_LIMIT_BYTES["dxf"] + 1)
    assert files.check_dxf_file(big) == [Check("big.dxf: DXF parses", False, False, True, "",
                                               f"{READ_LIMIT_BYTES['dxf'] + 1} bytes: larger than the "
                                               f"{READ_LIMIT_BYTES['dxf']} bytes a DXF file may have")]


def _folder(tmp_path):
    d = tmp_path / "out"
    (d / "sub").mkdir(parents=True)
    (d / "a.csv").write_text("x\n1\n")
    (d / "sub" / "b.txt").write_text("hello")
    return d


def test_a_manifest_lists_exactly_the_files_with_their_sizes_and_hashes(tmp_path):
    d = _folder(tmp_path)
    m = _manifest(d, [_entry(d, "a.csv"), _entry(d, "sub/b.txt")], checks=[{"name": "c1", "passed": True}])
    assert files.check_manifest_file(m) == [
        Check("manifest.json: parses", True, True, True, "", "2 files listed"),
        Check("manifest.json: listed files missing", True, 0, 0, "", "all listed files exist"),
        Check("manifest.json: listed files unreadable", True, 0, 0, "",
              "all listed files are regular files within the limit"),
        Check("manifest.json: size mismatches", True, 0, 0, "", "sizes as recorded"),
        Check("manifest.json: sha256 mismatches", True, 0, 0, "", "hashes as recorded"),
        Check("manifest.json: unlisted files", True, 0, 0, "", "every file listed"),
        Check("manifest.json: recorded failed checks", True, 0, 0, "", "all recorded checks passed"),
    ]


def test_a_manifest_names_every_file_that_differs(tmp_path):
    d = _folder(tmp_path)
    (d / "c.txt").write_text("same size")
    (d / "d.txt").write_text("d")
    entries = [_entry(d, "a.csv"), _entry(d, "sub/b.txt"), _entry(d, "c.txt")]
    entries[0]["bytes"] += 1                           # recorded size differs: a size and a hash mismatch
    entries[1]["sha256"] = "0" * 64                     # same size, another hash
    entries.append({"path": "gone.txt", "bytes": 1, "sha256": ""})
    entries.append({"path": "sub", "bytes": 1})          # a folder where a file is listed
    entries.append(dict(_entry(d, "c.txt"), bytes=True))  # a bool is no size
    checks = [{"name": "ok", "passed": True}, {"name": "bad", "passed": False}, {"name": "known", "passed": 0},
              "junk"]
    m = _manifest(d, entries, checks=checks, expected_failures=["known", 3])
    c = {x.name.split(": ", 1)[1]: x for x in files.check_manifest_file(m)}
    assert c["parses"].message == "6 files listed"
    assert (c["listed files missing"].value, c["listed files missing"].message) == (1, "missing: gone.txt")
    assert c["listed files unreadable"].value == 1
    assert c["listed files unreadable"].message == "sub (is a folder, not a regular file (not opened))"
    assert (c["size mismatches"].value, c["size mismatches"].message) == (2, "a.csv, c.txt")
    assert (c["sha256 mismatches"].value, c["sha256 mismatches"].message) == (3, "a.csv, sub/b.txt, c.txt")
    assert (c["unlisted files"].value, c["unlisted files"].message) == (1, "d.txt")
    assert c["recorded failed checks"].value == 2
    assert c["recorded failed checks"].message == (
        "bad; 'junk' (1 documented as expected failures in the part file: known)")
    assert not any(x.passed for k, x in c.items() if k != "parses")


def test_a_manifest_that_is_not_one_is_one_failed_check_saying_why(tmp_path):
    d = _folder(tmp_path)

    def first(data) -> Check:
        (d / "manifest.json").write_text(json.dumps(data) if not isinstance(data, str) else data)
        cs = files.check_manifest_file(d / "manifest.json")
        assert len(cs) == 1 and not cs[0].passed and cs[0].name == "manifest.json: parses"
        return cs[0].message

    assert first([]) == "is a JSON list, not an object"
    assert first({}) == ("'part' is missing or not a str; 'files' is missing or not a list; "
                         "'checks' is missing or not a list")
    assert first({"part": "t", "files": [], "checks": [], "expected_failures": "x"}) == (
        "'expected_failures' is missing or not a list")
    assert first({"part": "t", "files": [{"path": ""}, {}, 3, {"path": "/etc/passwd"}, {"path": "../x"},
                                         {"path": "sub/../../x"}], "checks": []}) == (
        "files[0] has no 'path'; files[1] has no 'path'; files[2] has no 'path'; files[3] path '/etc/passwd' leaves "
        "the folder; files[4] path '../x' leaves the folder; files[5] path 'sub/../../x' leaves the folder")
    assert first("{oops").startswith("JSONDecodeError: Expecting property name")
    (d / "manifest.json").write_bytes(b"\xff\xfe")
    cs = files.check_manifest_file(d / "manifest.json")
    assert cs[0].message.startswith("UnicodeDecodeError: 'utf-8' codec can't decode byte 0xff")


def test_check_file_turns_any_failure_of_a_checker_into_one_failed_check(tmp_path, monkeypatch):
    assert files.check_file(tmp_path / "notes.txt") == []
    p = tmp_path / "x.stl"

    def raising(exc):
        def fn(path):
            raise exc
        return fn

    for exc, msg in ((ValueError("bad number"), "ValueError: bad number"),
                     (Refused("is a FIFO"), "is a FIFO"),
                     (MemoryError(), f"out of memory: checking it needs more than the ceiling of "
                                     f"{CHECK_MEMORY_CEILING >> 20} MiB")):
        monkeypatch.setitem(files.CHECKERS, ".stl", raising(exc))
        assert files.check_file(p) == [Check("x.stl: readable", False, False, True, "", msg)]
    monkeypatch.setitem(files.CHECKERS, ".stl", raising(EnvironmentFailure(p, 5, "cannot read")))
    with pytest.raises(EnvironmentFailure):
        files.check_file(p)
    assert files._checker("manifest.json") is files.check_manifest_file
    assert files._checker("A.STEP") is files.check_step_file and files._checker("b.Stp") is files.check_step_file
    assert files._checker("manifest.json.bak") is None and files._checker("x.glb") is files.check_glb_file


def test_check_path_walks_a_folder_in_order_and_reports_progress(tmp_path):
    d = tmp_path / "out"
    d.mkdir()
    _box_stl(d / "b.stl")
    _dxf(d / "a.dxf")
    (d / "readme.txt").write_text("x")
    (tmp_path / "outside.stl").write_text("x")
    os.symlink(tmp_path / "outside.stl", d / "link.stl")
    said = []

    class Progress:
        def __call__(self, text):
            said.append(("step", text))

        def count(self, phase, done, total, unit):
            said.append((phase, done, total, unit))

    res = files.check_path(d, progress=Progress())
    assert list(res) == [str(d / "a.dxf"), str(d / "b.stl"), str(d / "link.stl")]
    assert res[str(d / "link.stl")] == [Check("link.stl: regular file in the folder", False, False, True, "",
                                              "is a symbolic link leading outside the folder checked")]
    phase = f"check: 2 file(s) to check under {d}"
    assert said == [("step", f"check: reading {d}"), (phase, 0, 2, "file"), (phase, 1, 2, "file"),
                    (phase, 2, 2, "file")]
    assert files.check_path(d / "b.stl") == {str(d / "b.stl"): files.check_file(d / "b.stl")}
    assert files.check_path(d / "readme.txt") == {}
    assert files.check_path(d / "nothing") == {str(d / "nothing"): [
        Check(f"{d / 'nothing'}: exists", False, False, True, "", "no such file or folder")]}
    # a plain callable without count: no counts; none at all: quiet
    plain = []
    files.check_path(d, progress=plain.append)
    assert plain == [f"check: reading {d}"]
    assert files.check_path(d) == res
    # the path given is followed when it is a link itself
    os.symlink(d / "b.stl", tmp_path / "given.stl")
    assert files.check_path(tmp_path / "given.stl") == {str(tmp_path / "given.stl"): files.check_file(d / "b.stl")}


def test_one_line_escapes_what_could_move_the_cursor():
    assert files.one_line("plain ünïcode — text") == "plain ünïcode — text"
    assert files.one_line("a\nb\tc\x1b[2J") == "a\\x0ab\\x09c\\x1b[2J"
    assert files.one_line("line\u2028para\u2029rtl\u202e") == "line\\u2028para\\u2029rtl\\u202e"
    assert files.one_line("tag\U000e0041") == "tag\\U000e0041"
    assert files.one_line("\x85\x7f") == "\\x85\\x7f"
    assert files.one_line(12) == "12"


def test_results_are_printed_one_line_a_file_then_the_failures_and_a_summary():
    ok = Check("a: x", True, 1, 1, "", "fine")
    bad = Check("b: y", False, 2, 1, "mm", "too\nlong")
    res = {"out/a.stl": [ok, ok], "out/b\n.dxf": [ok, bad]}
    assert files.summary(res) == (4, 1)
    assert files.format_results(res) == (
        "PASS out/a.stl (2 checks)\n"
        "FAIL out/b\\x0a.dxf (2 checks)\n"
        "    [FAIL] b: y: value 2 mm, limit 1 mm - too\\x0along\n"
        "2 files, 4 checks, 1 failed")
    assert files.format_results(res, verbose=True).splitlines()[1:3] == [
        "    [PASS] a: x: value 1, limit 1 - fine", "    [PASS] a: x: value 1, limit 1 - fine"]
    assert files.format_results({}) == "0 files, 0 checks, 0 failed"


# ------------------------------------------------------------------------------------------- pages
import base64  # noqa: E402

from propulsor.checks import pages  # noqa: E402
from propulsor.export.html import TABLE_SORT_SCRIPT, _sha256, content_security_policy, page, script_hash  # noqa: E402


def _glb_bytes():
    scene = trimesh.Scene()
    scene.add_geometry(trimesh.creation.box(extents=(0.01, 0.02, 0.03)), node_name="box")
    return scene.export(file_type="glb")


def _data_block(data: bytes, ident="0123456789abcdef") -> str:
    return (f'<script type="application/octet-stream" id="glb-{ident}" class="propulsor-glb">'
            f"{base64.b64encode(data).decode()}</script>")


def test_a_page_propulsor_writes_passes_and_counts_its_models():
    text = page("t", "<p>hi</p>" + _data_block(_glb_bytes()), script=TABLE_SORT_SCRIPT)
    assert pages.page_problems(text) == ("", 1)
    assert pages.page_problems(page("t", "<p>no script</p>")) == ("", 0)
    two = page("t", _data_block(_glb_bytes()) + "<p>x</p>" + _data_block(_glb_bytes(), "fedcba9876543210"))
    assert pages.page_problems(two) == ("", 2)
    assert script_hash(TABLE_SORT_SCRIPT) in pages.known_scripts() and len(pages.known_scripts()) == 2


def _with_policy(csp: str, body: str = "") -> str:
    good = page("t", body)
    head = pages._HEAD.match(good)
    return good[:head.start(1)] + csp + good[head.end(1):]


def test_the_pages_policy_must_be_exactly_the_one_propulsor_writes():
    sheet = _sha256("x")
    known = script_hash(TABLE_SORT_SCRIPT)
    base = {"default-src": "'none'", "img-src": "'self'", "style-src": sheet, "script-src": known,
            "base-uri": "'none'", "form-action": "'none'"}

    def policy(**change):
        d = dict(base)
        for k, v in change.items():
            k = k.replace("_", "-")
            if v is None:
                d.pop(k)
            else:
                d[k] = v
        return "; ".join(f"{k} {v}".strip() for k, v in d.items())

    assert pages._policy_problem(policy()) == ""
    assert pages._policy_problem(policy() + "; ;") == ""  # empty parts are nothing
    assert pages._policy_problem(policy(script_src="'none'")) == ""
    assert pages._policy_problem(policy().replace("default-src", "DEFAULT-SRC")) == ""
    assert pages._policy_problem(policy() + "; img-src 'self'") == "its policy names img-src twice"
    assert pages._policy_problem(policy(default_src="*")) == "its policy's default-src is '*', not 'none'"
    assert pages._policy_problem(policy(img_src="'self' data:")) == "its policy's img-src is \"'self' data:\", not 'self'"
    assert pages._policy_problem(policy(base_uri="")) == "its policy's base-uri is '', not 'none'"
    assert pages._policy_problem(policy(style_src=sheet + " 'unsafe-inline'")) == (
        "its policy's style-src allows more than its own style sheet")
    assert pages._policy_problem(policy(style_src="")) == "its policy's style-src allows more than its own style sheet"
    assert pages._policy_problem(policy(style_src=sheet + " " + _sha256("y"))) == ""
    other = _sha256("alert(1)")
    assert pages._policy_problem(policy(script_src=f"{known} {other}")) == (
        f"its policy's script-src allows {other}, not one of propulsor's scripts")
    assert pages._policy_problem(policy(script_src="")) == (
        "its policy's script-src allows nothing named, not one of propulsor's scripts")
    assert pages._policy_problem(policy() + "; connect-src *") == "its policy has connect-src, which propulsor does not write"
    assert pages._policy_problem(policy(form_action=None, base_uri=None)) == "its policy lacks base-uri"
    assert pages._policy_problem(policy(script_src=None)) == "its policy lacks script-src"
    assert pages._policy_problem(policy(style_src=None)) == "its policy lacks style-src"
    assert pages._policy_problem("") == "its policy lacks base-uri"
    # what page() writes
    assert pages._policy_problem(content_security_policy("body{}", "\n" + TABLE_SORT_SCRIPT + "\n")) == ""
    assert pages.page_problems(_with_policy(policy(default_src="*"))) == (
        "its policy's default-src is '*', not 'none'", 0)


def test_every_script_of_a_page_is_propulsors_or_a_sound_model():
    def at(text, snippet):
        return text.index(snippet)

    t = page("t", "<p>a</p><script>alert(1)</script>")
    assert pages.page_problems(t) == (f"an inline script at character {at(t, '<script>alert')} is not one of propulsor's", 0)
    t = page("t", _data_block(_glb_bytes()) + "<SCRIPT src=x.js></script>")
    assert pages.page_problems(t) == (
        f"a script element propulsor does not write at character {at(t, '<SCRIPT')}: <SCRIPT src=x.js>", 1)
    long_tag = '<script type="module" data-x="' + "y" * 80 + '">'
    t = page("t", long_tag + "</script>")
    assert pages.page_problems(t) == (
        f"a script element propulsor does not write at character {at(t, long_tag)}: {long_tag[:60]}", 0)
    t = page("t", _data_block(b"not a glb at all"))
    why, n = pages.page_problems(t)
    assert why.startswith(f"the model data at character {at(t, '<script type')} is a GLB the 3D view may not draw: ")
    assert n == 0
    t = page("t", '<script type="application/octet-stream" id="glb-0123456789abcdef" class="propulsor-glb">'
                  "***</script>")
    assert pages.page_problems(t) == (f"the model data at character {at(t, '<script type')} is not base64", 0)
    t = page("t", "<p>x</p><script>" + "\n" + TABLE_SORT_SCRIPT + "\n")
    assert pages.page_problems(t) == (f"a script at character {at(t, '<script>')} is not closed", 0)
    # a data block's id must be 16 hex digits
    bad_id = _data_block(_glb_bytes()).replace("glb-0123456789abcdef", "glb-0123456789ABCDEF")
    t = page("t", bad_id)
    assert pages.page_problems(t)[0].startswith("a script element propulsor does not write at character ")
    assert pages.page_problems("<html>" + page("t", "")) == (
        "it does not begin with propulsor's Content-Security-Policy", 0)


def test_a_page_file_is_one_check(tmp_path):
    p = tmp_path / "report.html"
    p.write_text(page("t", _data_block(_glb_bytes())), encoding="utf-8")
    assert pages.check_html_file(p) == [Check("report.html: runs only propulsor's scripts", True, True, True, "",
                                              "its policy and scripts are propulsor's; 1 model(s) sound")]
    p.write_text(page("t", "<script>x</script>"), encoding="utf-8")
    c = pages.check_html_file(p)[0]
    assert not c.passed and c.message.startswith("an inline script at character ")
    p.write_bytes(b"\xff<html>")
    assert pages.check_html_file(p) == [Check("report.html: runs only propulsor's scripts", False, False, True, "",
                                              "not UTF-8 (invalid start byte)")]


# ------------------------------------------------------------------------------------------- B-rep, STEP, GLB
import cadquery as cq  # noqa: E402

from propulsor.checks import brep  # noqa: E402
from propulsor.export.step import write_assembly_step, write_step  # noqa: E402


def test_brep_checks_of_a_box_in_full():
    box = cq.Solid.makeBox(2.0, 3.0, 4.0)
    cs = brep.brep_checks(box, "b")
    assert [c.name for c in cs] == ["b: BRepCheck_Analyzer valid", "b: solids", "b: open shells", "b: B-rep volume",
                                    "b: exact volume vs triangulated"]
    assert all(c.passed for c in cs)
    assert cs[0] == Check("b: BRepCheck_Analyzer valid", True, True, True, "", "OCCT topology and geometry check")
    assert cs[1] == Check("b: solids", True, 1, 1, "", "exactly one solid")
    assert cs[2] == Check("b: open shells", True, 0, 0, "", "1 shell(s), all closed")
    assert cs[3].value == pytest.approx(24.0, rel=1e-12) and cs[3].limit == 0.0
    assert (cs[3].unit, cs[3].message) == ("mm^3", "positive volume (outward faces)")
    t = brep.triangulated_volume(box)
    # planar faces triangulate exactly; the deflection is floored at the request
    assert t.volume_mm3 == pytest.approx(24.0, rel=1e-12) and t.area_mm2 == pytest.approx(52.0, rel=1e-12)
    assert t.deflection_mm == CHORD_TOL_MM and t.bound_mm3 == pytest.approx(52.0 * CHORD_TOL_MM, rel=1e-12)
    assert brep.volume_from_triangulation(box) == pytest.approx(24.0, rel=1e-12)
    assert cs[4].limit == {"expected": pytest.approx(24.0, rel=1e-12), "rel_tol": 1e-3,
                           "abs_tol": pytest.approx(0.26, rel=1e-12)}
    assert cs[4].message == ("OCCT volume 24 vs triangulation 24 mm^3: they may differ by the triangulation's deflection "
                             "0.005 mm times the area 52 mm^2 = 0.26 mm^3 (or 0.001 of the volume); more means OCCT's "
                             "volume integration failed")
    # the caller's volume is used as given: 24.3 is 0.3 from the triangulation's 24, past max(0.26, 0.0243)
    c = brep.brep_checks(box, "b", volume_mm3=24.3)
    assert c[3].value == 24.3 and not c[4].passed
    assert brep.brep_checks(box, "b", volume_mm3=24.25)[4].passed
    assert len(brep.brep_checks(box, "b", cross_check_volume=False)) == 4
    from OCP.TopoDS import TopoDS_Shape

    assert brep.brep_checks(TopoDS_Shape(), "n") == [Check("n: shape exists", False, False, True, "", "null shape")]


def test_brep_checks_count_solids_and_open_shells():
    a = cq.Solid.makeBox(1.0, 1.0, 1.0)
    b = cq.Solid.makeBox(1.0, 1.0, 1.0, pnt=cq.Vector(3, 0, 0))
    cs = {c.name: c for c in brep.brep_checks(cq.Compound.makeCompound([a, b]), "c")}
    assert cs["c: solids"].value == 2 and not cs["c: solids"].passed
    assert cs["c: open shells"].message == "2 shell(s), all closed"
    assert cs["c: B-rep volume"].value == pytest.approx(2.0, rel=1e-12)
    # a box's shell without its top face: open, and no solid to cross-check
    faces = [f for f in a.Faces() if f.Center().z < 0.99]
    shell = cq.Shell.makeShell(faces)
    cs = {c.name: c for c in brep.brep_checks(shell, "s")}
    assert cs["s: solids"].value == 0 and cs["s: open shells"].value == 1
    assert cs["s: open shells"].message == "1 shell(s), all closed" and not cs["s: open shells"].passed
    assert "s: exact volume vs triangulated" not in cs
    assert brep.shell_closed(a.Shells()[0].wrapped) and not brep.shell_closed(shell.wrapped)


def test_step_round_trip_of_a_box(tmp_path):
    box = cq.Solid.makeBox(2.0, 3.0, 4.0)
    p = write_step(box, tmp_path / "box.step", "box")
    c = brep.step_roundtrip_check(box, p)
    assert c.name == "box.step: STEP round trip" and c.passed and c.unit == "mm^3"
    assert c.value == pytest.approx(24.0, rel=1e-12)
    assert c.limit == {"expected": pytest.approx(24.0, rel=1e-12), "rel_tol": 1e-6, "solids": 1}
    assert c.message.startswith("1 solid(s) re-imported from box.step; volume 24 vs built 24 mm^3 (relative ")
    assert brep.step_roundtrip_check(box, p, name="part").name == "part: STEP round trip"
    # the built volume as the caller has it: 1e-6 of it is the limit, both sides
    assert brep.step_roundtrip_check(box, p, built_volume=24.0 * (1 + 0.9e-6)).passed
    assert not brep.step_roundtrip_check(box, p, built_volume=24.0 * (1 + 1.1e-6)).passed
    assert brep.step_roundtrip_check(box, p, built_volume=24.0 * (1 + 1.1e-6), rel_tol=2e-6).passed
    assert not brep.step_roundtrip_check(box, p, built_volume=0.0).passed
    two = cq.Compound.makeCompound([box, cq.Solid.makeBox(1.0, 1.0, 1.0, pnt=cq.Vector(5, 0, 0))])
    p2 = write_step(two, tmp_path / "two.step", "two")
    c = brep.step_roundtrip_check(box, p2)
    assert not c.passed and c.message.startswith("2 solid(s) re-imported from two.step; volume 25 vs built 24")
    c = brep.step_roundtrip_check(box, tmp_path / "none.step")
    assert c == Check("none.step: STEP round trip", False, None, {"solids": 1, "rel_tol": 1e-6}, "mm^3",
                      c.message) and c.message.startswith("STEP re-import failed: ")


def test_a_step_file_is_checked_solid_by_solid_against_its_manifest(tmp_path):
    files._MANIFESTS.clear()
    ring = cq.Workplane().circle(10.0).circle(4.0).extrude(5.0).val()  # genus 1
    p = write_step(ring, tmp_path / "ring.step", "ring")
    exact = math.pi * (10.0 ** 2 - 4.0 ** 2) * 5.0
    _manifest(tmp_path, [{"path": "ring.step", "volume_mm3": exact, "genus": 1}])
    cs = files.check_step_file(p)
    by = {c.name: c for c in cs}
    assert cs[0] == Check("ring.step: STEP parses", True, True, True, "", "read and transferred by OCCT")
    assert cs[1] == Check("ring.step: solids", True, 1.0, 1, "", "one or more solids")
    assert "ring.step: solid 1: solids" not in by  # each item is one solid by construction
    assert by["ring.step: solid 1: BRepCheck_Analyzer valid"].passed
    assert by["ring.step: solid 1 mesh: genus"] == Check("ring.step: solid 1 mesh: genus", True, 1, 1, "",
                                                          "genus from chi = V - E + F = 0")
    v = by["ring.step: volume vs manifest"]
    assert v.passed and v.value == pytest.approx(exact, rel=1e-9) and v.limit["rel_tol"] == 1e-6
    assert all(c.passed for c in cs)
    files._MANIFESTS.clear()
    _manifest(tmp_path, [{"path": "ring.step", "volume_mm3": exact * (1 + 2e-6), "genus": 0}])
    by = {c.name: c for c in files.check_step_file(p)}
    assert not by["ring.step: volume vs manifest"].passed and not by["ring.step: solid 1 mesh: genus"].passed
    # two solids: the genus is not asked of either, the volume is their sum
    two = cq.Compound.makeCompound([ring, cq.Solid.makeBox(1.0, 1.0, 1.0, pnt=cq.Vector(30, 0, 0))])
    write_step(two, tmp_path / "two.step", "two")
    files._MANIFESTS.clear()
    _manifest(tmp_path, [{"path": "two.step", "volume_mm3": exact + 1.0, "genus": 5}])
    by = {c.name: c for c in files.check_step_file(tmp_path / "two.step")}
    assert by["two.step: solids"].value == 2 and "two.step: solid 2 mesh: bodies" in by
    assert "two.step: solid 1 mesh: genus" not in by and by["two.step: volume vs manifest"].passed
    (tmp_path / "junk.step").write_text("ISO-10303-21;\nnonsense\n")
    c = files.check_step_file(tmp_path / "junk.step")
    assert len(c) == 1 and c[0].name == "junk.step: STEP parses" and not c[0].passed
    assert "/proc/self/fd" not in c[0].message


def test_a_glb_is_the_assemblys_components_in_metres(tmp_path):
    files._MANIFESTS.clear()
    a = cq.Solid.makeBox(20.0, 30.0, 40.0)
    b = cq.Solid.makeBox(10.0, 10.0, 10.0)
    write_assembly_step(tmp_path / "asm.step", [("a", a, (0, 0, 0), 0.0), ("b", b, (50, 0, 0), 0.0)], "asm")
    scene = trimesh.Scene()
    scene.add_geometry(trimesh.creation.box(extents=(0.02, 0.03, 0.04)), node_name="a",
                       transform=trimesh.transformations.translation_matrix((0.01, 0.015, 0.02)))
    scene.add_geometry(trimesh.creation.box(extents=(0.01, 0.01, 0.01)), node_name="b",
                       transform=trimesh.transformations.translation_matrix((0.055, 0.005, 0.005)))
    (tmp_path / "asm.glb").write_bytes(scene.export(file_type="glb"))
    models = [{"path": "asm.glb", "components": ["b", "a"], "step": "asm.step"}]
    _manifest(tmp_path, [], media={"models": models})
    cs = files.check_glb_file(tmp_path / "asm.glb")
    assert cs[0] == Check("asm.glb: loads", True, True, True, "", "2 mesh nodes")
    assert cs[1] == Check("asm.glb: nodes are the assembly's components", True, ["a", "b"], ["a", "b"], "",
                          "one named node per component of the assembly STEP")
    assert cs[2] == Check("asm.glb: nodes are the STEP's components", True, ["a", "b"], ["a", "b"], "",
                          "the component occurrences of asm.step")
    # extent 60 x 30 x 40 mm = 0.06 x 0.03 x 0.04 m
    assert cs[3].name == "asm.glb: extent vs the STEP in metres" and cs[3].passed and cs[3].value < 1e-9
    assert cs[3].limit == 1e-4 and cs[3].unit == "m" and len(cs) == 4
    # the same scene in millimetres is 1000 times too large
    mm = trimesh.Scene()
    mm.add_geometry(trimesh.creation.box(extents=(20.0, 30.0, 40.0)), node_name="a")
    mm.add_geometry(trimesh.creation.box(extents=(10.0, 10.0, 10.0)), node_name="b",
                    transform=trimesh.transformations.translation_matrix((45.0, 0, 0)))
    (tmp_path / "asm.glb").write_bytes(mm.export(file_type="glb"))
    c = files.check_glb_file(tmp_path / "asm.glb")[3]
    assert not c.passed and c.value == pytest.approx(60.0 - 0.06, rel=1e-9)
    for step, why in (("../asm.step", "the manifest names '../asm.step', not a file beside asm.glb"),
                      ("..", "the manifest names '..', not a file beside asm.glb")):
        files._MANIFESTS.clear()
        _manifest(tmp_path, [], media={"models": [dict(models[0], step=step)]})
        assert files.check_glb_file(tmp_path / "asm.glb")[-1] == Check(
            "asm.glb: assembly STEP in the folder", False, False, True, "", why)
    files._MANIFESTS.clear()
    _manifest(tmp_path, [], media={"models": [{"path": "asm.glb", "components": ["a"], "step": "gone.step"}]})
    cs = files.check_glb_file(tmp_path / "asm.glb")
    assert len(cs) == 2 and not cs[1].passed and cs[1].value == ["a", "b"]
    for media in ({"models": "x"}, [], {"models": [{"path": "other.glb", "components": ["q"]}]}):
        files._MANIFESTS.clear()
        _manifest(tmp_path, [], media=media)
        assert len(files.check_glb_file(tmp_path / "asm.glb")) == 1
    (tmp_path / "asm.glb").write_bytes(b"glTF")
    c = files.check_glb_file(tmp_path / "asm.glb")
    assert len(c) == 1 and c[0].name == "asm.glb: loads" and not c[0].passed


# ------------------------------------------------------------------------------------------- safe_read, memory
import errno  # noqa: E402
import resource  # noqa: E402
import socket  # noqa: E402

from propulsor.checks import memory, safe_read  # noqa: E402
from propulsor.policy import HASH_LIMIT_BYTES  # noqa: E402


def test_a_regular_file_is_read_whole_within_its_kinds_limit(tmp_path):
    p = tmp_path / "a.stl"
    p.write_bytes(b"x" * 100)
    assert safe_read.read_bytes(p, "stl") == b"x" * 100
    with safe_read.opened(p, limit=100) as f:
        assert f.size == 100 and f.path == p
        assert os.path.samefile(f.lib_path, p) and f.lib_path == f"/proc/self/fd/{f.fd}"
        assert f.read() == b"x" * 100 and f.read() == b"x" * 100  # from the start each time
    with pytest.raises(Refused) as e, safe_read.opened(p, limit=99):
        pass
    assert str(e.value) == "100 bytes: larger than the 99 bytes this file may have"
    assert safe_read._too_large(5, 4, "stl") == "5 bytes: larger than the 4 bytes a STL file may have"
    assert safe_read._too_large(5, 4, "manifest") == "5 bytes: larger than the 4 bytes a manifest may have"
    assert safe_read._too_large(5, 4, None) == "5 bytes: larger than the 4 bytes this file may have"
    assert safe_read.limit_of("glb") == READ_LIMIT_BYTES["glb"]
    big = tmp_path / "big.json"
    with open(big, "wb") as fh:
        fh.truncate(READ_LIMIT_BYTES["manifest"] + 1)
    with pytest.raises(Refused) as e:
        safe_read.read_bytes(big, "manifest")
    assert str(e.value) == (f"{READ_LIMIT_BYTES['manifest'] + 1} bytes: larger than the "
                            f"{READ_LIMIT_BYTES['manifest']} bytes a manifest may have")
    with open(big, "r+b") as fh:
        fh.truncate(READ_LIMIT_BYTES["manifest"])
    assert len(safe_read.read_bytes(big, "manifest")) == READ_LIMIT_BYTES["manifest"]


def test_what_is_not_a_regular_file_is_refused_unopened(tmp_path):
    def why(path, **kw) -> str:
        with pytest.raises(Refused) as e, safe_read.opened(path, "stl", **kw):
            pass
        return str(e.value)

    assert why(tmp_path / "none.stl") == "no such file"
    assert why(tmp_path) == "is a folder, not a regular file (not opened)"
    os.mkfifo(tmp_path / "fifo.stl")
    assert why(tmp_path / "fifo.stl") == "is a FIFO, not a regular file (not opened)"
    (tmp_path / "real.stl").write_bytes(b"x")
    os.symlink(tmp_path / "real.stl", tmp_path / "link.stl")
    assert why(tmp_path / "link.stl") == "is a symbolic link, not a regular file (not opened)"
    s = socket.socket(socket.AF_UNIX)
    try:
        s.bind(str(tmp_path / "sock.stl"))
        assert why(tmp_path / "sock.stl") == "is a socket, not a regular file (not opened)"
    finally:
        s.close()
    assert why("/dev/null") == "is a character device, not a regular file (not opened)"


def test_the_machines_refusals_are_environment_failures_and_the_files_are_refusals():
    for no in (errno.EACCES, errno.EPERM, errno.EIO, errno.EMFILE, errno.ENFILE, errno.ENOMEM):
        e = safe_read._os_error(OSError(no, os.strerror(no)), "/x", "cannot read")
        assert isinstance(e, EnvironmentFailure), no
    e = safe_read._os_error(OSError(errno.ELOOP, "loop"), "/x", "d")
    assert isinstance(e, Refused) and str(e) == "is a symbolic link (not followed)"
    e = safe_read._os_error(OSError(errno.ENOENT, "gone"), "/x", "d")
    assert isinstance(e, Refused) and str(e) == "no such file"
    e = safe_read._os_error(OSError(errno.ENAMETOOLONG, "File name too long"), "/x", "d")
    assert isinstance(e, Refused) and str(e) == "cannot open: [ENAMETOOLONG] File name too long"
    e = safe_read._os_error(OSError(99999, "odd"), "/x", "d")
    assert str(e) == "cannot open: [E?] odd"


def test_a_file_is_hashed_only_at_its_recorded_size(tmp_path):
    p = tmp_path / "f.bin"
    p.write_bytes(b"abc")
    want = hashlib.sha256(b"abc").hexdigest()
    assert safe_read.sha256_and_size(p) == (want, 3)
    assert safe_read.sha256_and_size(p, 3) == (want, 3)
    assert safe_read.sha256_and_size(p, 4) == ("", 3)
    assert safe_read.sha256_and_size(p, 0) == ("", 3)
    big = tmp_path / "big.bin"
    with open(big, "wb") as fh:
        fh.truncate(HASH_LIMIT_BYTES + 1)
    with pytest.raises(Refused) as e:
        safe_read.sha256_and_size(big)
    assert str(e.value) == f"{HASH_LIMIT_BYTES + 1} bytes: larger than the {HASH_LIMIT_BYTES} bytes this file may have"


def test_a_folder_is_walked_without_following_its_links(tmp_path):
    d = tmp_path / "out"
    (d / "sub" / "deeper").mkdir(parents=True)
    (d / "b.txt").write_text("b")
    (d / "sub" / "a.txt").write_text("a")
    (d / "sub" / "deeper" / "c.txt").write_text("c")
    (tmp_path / "outside.txt").write_text("o")
    os.symlink(d / "b.txt", d / "sub" / "inside_link")
    os.symlink(tmp_path / "outside.txt", d / "out_link")
    os.symlink(tmp_path / "nowhere", d / "dangling")
    os.symlink(d, d / "sub" / "to_root")
    os.symlink(tmp_path, d / "to_parent")
    os.mkfifo(d / "pipe")
    got, bad = safe_read.walk(d)
    assert got == [d / "b.txt", d / "sub" / "a.txt", d / "sub" / "deeper" / "c.txt"]
    assert bad == {d / "dangling": "is a symbolic link to nothing",
                   d / "out_link": "is a symbolic link leading outside the folder checked",
                   d / "to_parent": "is a symbolic link leading outside the folder checked",
                   d / "pipe": "is a FIFO: an output folder holds regular files only"}
    # walked through a link to it, the folder is the same folder
    os.symlink(d, tmp_path / "alias")
    got, bad = safe_read.walk(tmp_path / "alias")
    assert [p.name for p in got] == ["b.txt", "a.txt", "c.txt"] and len(bad) == 4


def test_the_memory_ceiling_lowers_the_address_space_only_where_it_can():
    """Applied while the checks run when the process maps less than half the ceiling and no lower limit is set;
    restored after.  What the process maps is /proc/self/status's VmSize."""
    status = open("/proc/self/status").read()
    vm = int(next(line.split()[1] for line in status.splitlines() if line.startswith("VmSize:"))) * 1024
    used = memory.address_space()
    assert abs(used - vm) < 64 << 20  # read a moment apart
    outer, hard0 = resource.getrlimit(resource.RLIMIT_AS)
    if hard0 != resource.RLIM_INFINITY:
        pytest.skip("the address space is limited already (ulimit -v)")
    # a soft limit of the caller (mutation/run.py caps its tests at 8 GiB) is lifted for the test and put back after
    resource.setrlimit(resource.RLIMIT_AS, (resource.RLIM_INFINITY, hard0))
    try:
        _memory_ceiling_cases(used, resource.RLIM_INFINITY, hard0)
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (outer, hard0))


def _memory_ceiling_cases(used, soft0, hard0):
    ceiling = int(used * 2.5) // 4096 * 4096
    with memory.memory_ceiling(ceiling):
        assert resource.getrlimit(resource.RLIMIT_AS) == (ceiling, hard0)
    assert resource.getrlimit(resource.RLIMIT_AS) == (soft0, hard0)
    # a process already mapping more than half of it: not applied (it would fail at once)
    with memory.memory_ceiling(int(used * 1.8)):
        assert resource.getrlimit(resource.RLIMIT_AS) == (soft0, hard0)
    # a lower soft limit already set is kept
    lower = int(used * 3)
    resource.setrlimit(resource.RLIMIT_AS, (lower, hard0))
    try:
        with memory.memory_ceiling(int(used * 4)):
            assert resource.getrlimit(resource.RLIMIT_AS) == (lower, hard0)
        with memory.memory_ceiling(lower):
            assert resource.getrlimit(resource.RLIMIT_AS) == (lower, hard0)
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft0, hard0))
    # restored when the checks raise
    with pytest.raises(KeyError), memory.memory_ceiling(ceiling):
        raise KeyError("x")
    assert resource.getrlimit(resource.RLIMIT_AS) == (soft0, hard0)


def _limits_inside(monkeypatch, used, ceiling=None):
    """RLIMIT_AS inside memory_ceiling when the process is said to map `used` bytes (the soft limit lifted for the
    call; nothing is allocated inside)."""
    monkeypatch.setattr(memory, "address_space", lambda: used)
    outer, hard = resource.getrlimit(resource.RLIMIT_AS)
    resource.setrlimit(resource.RLIMIT_AS, (resource.RLIM_INFINITY, hard))
    try:
        with (memory.memory_ceiling() if ceiling is None else memory.memory_ceiling(ceiling)):
            inside = resource.getrlimit(resource.RLIMIT_AS)
        after = resource.getrlimit(resource.RLIMIT_AS)
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (outer, hard))
    assert after == (resource.RLIM_INFINITY, hard)
    return inside


def test_the_memory_ceiling_applies_up_to_half_of_it_mapped_and_defaults_to_the_policys():
    """Applied while the process maps at most half the ceiling (ceiling // 2 bytes), not one byte more; the default
    ceiling is policy.CHECK_MEMORY_CEILING (2 GiB); unknown use (no /proc): not applied."""
    _, hard = resource.getrlimit(resource.RLIMIT_AS)
    if hard != resource.RLIM_INFINITY:
        pytest.skip("the address space's hard limit is set (ulimit -H -v)")
    mp = pytest.MonkeyPatch()
    try:
        c = 64 << 30
        assert _limits_inside(mp, c // 2, c) == (c, hard)
        assert _limits_inside(mp, c // 2 + 1, c) == (resource.RLIM_INFINITY, hard)
        assert _limits_inside(mp, None, c) == (resource.RLIM_INFINITY, hard)
        assert _limits_inside(mp, 1 << 20) == (CHECK_MEMORY_CEILING, hard) and CHECK_MEMORY_CEILING == 2048 << 20
    finally:
        mp.undo()



def _limits_under_ceiling_in_child(limit: int, ceiling: int) -> str:
    """repr of the address-space limits inside ``memory_ceiling(ceiling)`` in a forked child whose soft and hard limits
    are set to ``limit`` first."""
    import os
    import resource

    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:
        try:
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
            with memory.memory_ceiling(ceiling):
                got = resource.getrlimit(resource.RLIMIT_AS)
            os.write(w, repr(got).encode())
        finally:
            os._exit(0)
    os.close(w)
    os.waitpid(pid, 0)
    with os.fdopen(r) as f:
        return f.read()

def test_the_memory_ceiling_lowers_a_higher_soft_limit_and_keeps_a_lower_hard_one():
    """A soft limit above the ceiling is lowered to it (and put back); a hard limit below the ceiling leaves the
    limits as they are (in a forked child: a hard limit cannot be raised again)."""
    soft0, hard0 = resource.getrlimit(resource.RLIMIT_AS)
    if hard0 != resource.RLIM_INFINITY:
        pytest.skip("the address space's hard limit is set (ulimit -H -v)")
    c = 64 << 30
    resource.setrlimit(resource.RLIMIT_AS, (c + 4096, hard0))
    try:
        mp = pytest.MonkeyPatch()
        mp.setattr(memory, "address_space", lambda: 1 << 20)
        try:
            with memory.memory_ceiling(c):
                assert resource.getrlimit(resource.RLIMIT_AS) == (c, hard0)
            assert resource.getrlimit(resource.RLIMIT_AS) == (c + 4096, hard0)
            # in a forked child (a hard limit cannot be raised again): a hard limit just below the ceiling is kept
            assert _limits_under_ceiling_in_child(c - 4096, c) == repr((c - 4096, c - 4096))
            # a hard (and soft) limit above the ceiling: lowered to it
            assert _limits_under_ceiling_in_child(c, c - 8192) == repr((c - 8192, c))
        finally:
            mp.undo()
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft0, hard0))


@pytest.mark.parametrize("content, error", [(b"", None), (b"x 1 2", None), (None, OSError)])
def test_the_address_space_is_unknown_where_proc_says_nothing_readable(monkeypatch, content, error):
    """/proc/self/statm empty (IndexError), not a number (ValueError) or missing (OSError): None."""
    def fake_open(path, mode="r"):
        assert (path, mode) == ("/proc/self/statm", "rb")
        if error is not None:
            raise error("no /proc")
        return io.BytesIO(content)

    monkeypatch.setattr(memory, "open", fake_open, raising=False)
    assert memory.address_space() is None
    monkeypatch.setattr(memory, "open", lambda path, mode="r": io.BytesIO(b"3 2 1"), raising=False)
    assert memory.address_space() == 3 * os.sysconf("SC_PAGE_SIZE")


# ------------------------------------------------------------------------------------------- mesh: the gaps of the first run
def _segment_hits_triangle(p, q, a, b, c) -> bool:
    """Möller-Trumbore on the closed segment p-q (an independent test of a proper crossing)."""
    e1, e2, d = b - a, c - a, q - p
    h = np.cross(d, e2)
    det = float(np.dot(e1, h))
    if abs(det) < 1e-12:
        return False
    s = p - a
    u = float(np.dot(s, h)) / det
    qv = np.cross(s, e1)
    v = float(np.dot(d, qv)) / det
    t = float(np.dot(e2, qv)) / det
    return 0 <= u <= 1 and 0 <= v and u + v <= 1 and 0 <= t <= 1


def test_a_crossing_whose_vertex_wise_ranges_are_apart_is_found():
    """Two triangles that cross (an edge of one passes through the other), whose boxes per axis overlap, as the
    broad phase must take them; boxes taken over each vertex's coordinates instead would be apart."""
    V = np.array([[-6.0, -1, 0], [2, 1, -1], [-4, 1, -1], [4, 3, 3], [1, -2, -3], [-1, 1, -2]])
    A, B = V[:3], V[3:]
    assert any(_segment_hits_triangle(A[i], A[(i + 1) % 3], *B) for i in range(3)) or any(
        _segment_hits_triangle(B[i], B[(i + 1) % 3], *A) for i in range(3))
    lo, hi = V.reshape(2, 3, 3).min(axis=2), V.reshape(2, 3, 3).max(axis=2)
    assert np.any(lo[0] > hi[1]) or np.any(lo[1] > hi[0])
    assert self_intersections(V, np.array([[0, 1, 2], [3, 4, 5]]))[0] == 1


def _rotation(seed):
    q, _ = np.linalg.qr(np.random.default_rng(seed).normal(size=(3, 3)))
    return q * np.sign(np.linalg.det(q))


@pytest.mark.parametrize("scale", [1.0, 1e-3])
def test_decisions_do_not_depend_on_where_the_triangles_are(scale):
    """The pierced pair, the pair 0.5 and 2 tolerances apart, turned and moved 100 mm (and at a thousandth of the
    size, where a normal's length is far below 1): the same answers, the tolerance a ten-billionth of the size."""
    for seed in range(4):
        R, t = _rotation(seed), np.array([100.0, -40.0, 70.0]) * scale

        def moved(gap):
            V, F = _pierced(gap)
            return (V * scale) @ R.T + t, F

        assert self_intersections(*moved(-0.5))[0] == 1
        W0, _ = moved(0.0)
        eps = 1e-10 * float(np.linalg.norm(W0.max(axis=0) - W0.min(axis=0)))  # of the moved mesh's box
        for k, want in ((0.5, 1), (2.0, 0)):
            assert self_intersections(*moved(k * eps / scale))[0] == want, (seed, k, scale)


def test_the_tolerance_follows_the_size_of_the_whole_mesh_on_every_axis():
    """Moved 1000 mm along x only, the diagonal of the bounding box is what it was (9 mm): the tolerance too."""
    for gap_eps, want in ((0.5, 1), (2.0, 0)):
        V, F = _pierced(0.0)
        eps = 1e-10 * float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))
        V, F = _pierced(gap_eps * eps)
        assert self_intersections(V + [1000.0, 0, 0], F)[0] == want
        assert self_intersections(V + [0, 0, -1000.0], F)[0] == want


def test_more_crossings_than_reported():
    """101 vertical triangles through one horizontal triangle: 101 pairs counted, the first 100 reported."""
    V = [[-200.0, -10, 0], [200, -10, 0], [0, 400, 0]]
    F = [[0, 1, 2]]
    for k in range(101):
        x = -100.0 + 2.0 * k
        V += [[x, -1, -1], [x, 1, -1], [x, 0, 2]]
        F.append([3 + 3 * k, 4 + 3 * k, 5 + 3 * k])
    n, pairs = self_intersections(np.array(V), np.array(F))
    assert n == 101 and pairs.shape == (100, 2) and pairs.dtype == np.int64
    assert set(map(tuple, pairs.tolist())) < {(0, k) for k in range(1, 102)}
    assert self_intersections(np.array(V), np.array(F)[:1])[1].dtype == np.int64


def test_the_broad_phase_groups_neighbours_so_a_spread_mesh_stays_within_its_pair_budget():
    """64 disjoint unit boxes along a diagonal, given in a shuffled order: sorted by the Morton code of their centres,
    no level of the traversal holds more than the 64 leaves' own pairs; in the given order the upper levels' nodes
    span the whole diagonal and overlap."""
    k = np.random.default_rng(5).permutation(64).astype(float)
    lo = np.column_stack([2 * k, 2 * k, 2 * k])
    hi = lo + 1.0
    assert overlapping_pairs(lo, hi, max_pairs=64).shape == (0, 2)
    with pytest.raises(TooManyPairs):
        overlapping_pairs(lo, hi, max_pairs=63)
    # the same along each axis alone and in a plane (the code interleaves all three)
    for cols in ([0], [1], [2], [0, 2]):
        lo2 = np.zeros((64, 3))
        lo2[:, cols] = 2 * k[:, None]
        assert overlapping_pairs(lo2, lo2 + 1.0, max_pairs=64).shape == (0, 2), cols
    assert overlapping_pairs(lo[:1], hi[:1]).dtype == np.int64 and overlapping_pairs(lo[:0], hi[:0]).dtype == np.int64


def test_mesh_checks_on_one_crossing_and_on_a_mesh_without_metadata():
    from types import SimpleNamespace

    V, F = _pierced()
    x = _by_name(mesh_checks((V, F), name="m", expected_bodies=2))["self-intersecting triangle pairs"]
    assert (x.value, x.message) == (1, "1 intersecting triangle pairs, e.g. faces [[0, 1]]")
    v, f = _box((2.0, 3.0, 4.0), at=(5.0, 7.0, 9.0))
    c = _by_name(mesh_checks(SimpleNamespace(vertices=v, faces=f), name="m", expected_volume=24.0))
    assert "chord deflection" not in c and c["volume vs B-rep"].passed
    assert c["volume vs B-rep"].unit == "mm^3"
    assert c["volume vs B-rep"].limit["abs_tol"] == pytest.approx(0.01 * 52.0, rel=1e-12)
    # a deflection given wins over the mesh's own record
    tm = trimesh.Trimesh(v, f, process=False)
    tm.metadata["chord_deflection_mm"] = 0.003
    c = _by_name(mesh_checks(tm, name="m", chord_deflection=0.002, expected_volume=24.0))
    assert c["chord deflection"].value == 0.002
    assert c["volume vs B-rep"].limit["abs_tol"] == pytest.approx(0.002 * 52.0, rel=1e-12)


def test_the_volume_keeps_its_digits_far_from_the_origin_on_any_axis():
    v, f = _box((2.0, 3.0, 4.0))
    for off in ((1e9, -1e9, 0.0), (0.0, 0.0, 1e9), (-3e8, 1e9, 2e8)):
        assert signed_volume(v + np.array(off), f) == pytest.approx(24.0, rel=1e-9), off


@pytest.mark.parametrize("scale", [1.0, 1e-3])
def test_parallel_triangles_two_tolerances_apart_do_not_touch_at_any_size(scale):
    """A triangle above another, parallel, 2 tolerances up: apart; half a tolerance up: touching (coplanar within the
    tolerance).  At a thousandth of the size the normal's length (twice the area) is 4e-5: the distances to a plane
    are measured along its unit normal all the same."""
    base = np.array([[0.0, 0, 0], [6, 0, 0], [0, 6, 0]]) * scale
    top = np.array([[1.0, 1, 0], [4, 1, 0], [1, 4, 0]]) * scale
    R, t = _rotation(7), np.array([3.0, -2.0, 1.0]) * scale

    def moved(gap):
        return np.vstack([base, top + [0, 0, gap]]) @ R.T + t

    W0 = moved(0.0)
    eps = 1e-10 * float(np.linalg.norm(W0.max(axis=0) - W0.min(axis=0)))  # of the moved pair's box
    for k, want in ((2.0, 0), (0.5, 1)):
        W = moved(k * eps)
        assert self_intersections(W, np.array([[0, 1, 2], [3, 4, 5]]))[0] == want, (k, scale)


def test_the_morton_grouping_holds_off_the_origin_across_it_and_at_any_size():
    """The diagonal of 64 boxes offset differently on each axis, centred on the origin, and a thousand times smaller:
    the budget of the leaves' own 64 pairs holds each time."""
    k = np.random.default_rng(5).permutation(64).astype(float)
    for off, step in (((1000.0, -500.0, 3.0), 2.0), ((-64.0, -64.0, -64.0), 2.0), ((0.0, 0.0, 0.0), 2e-3),
                      ((5.0, 5.0, 5.0), 2e-3)):
        lo = np.column_stack([step * k + off[0], step * k + off[1], step * k + off[2]])
        hi = lo + step / 2
        assert overlapping_pairs(lo, hi, max_pairs=64).shape == (0, 2), (off, step)


# ------------------------------------------------------------------------------------------- the gaps of the first run
def test_reading_stops_at_the_size_the_file_had_when_opened(tmp_path):
    """A file read in chunks of 1 MiB: one byte past a chunk is read too; what is appended after it was opened is
    not, and a file cut short after it was opened gives what is there."""
    from propulsor.regular_file import CHUNK

    p = tmp_path / "a.stl"
    data = bytes(range(256)) * ((CHUNK + 1) // 256 + 1)
    p.write_bytes(data[:CHUNK + 1])
    assert safe_read.read_bytes(p, "stl") == data[:CHUNK + 1]
    with safe_read.opened(p, "stl") as f:
        with open(p, "ab") as fh:
            fh.write(b"appended")
        assert f.read() == data[:CHUNK + 1]
    with safe_read.opened(p, "stl") as f:
        os.truncate(p, 10)
        assert f.read() == data[:10]


def test_the_machines_refusal_names_the_path_the_errno_and_what_was_done(tmp_path, monkeypatch):
    e = safe_read._os_error(OSError(errno.EACCES, "Permission denied"), "/x/y.stl", "cannot read")
    assert str(e) == "cannot read /x/y.stl: [EACCES] Permission denied"
    e = safe_read._os_error(OSError(errno.EIO, ""), "/x", "cannot read")
    assert str(e) == "cannot read /x: [EIO] Input/output error"
    p = tmp_path / "f.bin"
    p.write_bytes(b"abc")

    def broken(fd):
        raise OSError(errno.EIO, "Input/output error")

    monkeypatch.setattr(safe_read, "hash_fd", broken)
    with pytest.raises(EnvironmentFailure) as ex:
        safe_read.sha256_and_size(p)
    assert str(ex.value) == f"cannot read {p}: [EIO] Input/output error"
    real_read = os.read

    def read_fails(fd, n):
        raise OSError(errno.EIO, "Input/output error")

    with safe_read.opened(p, "stl") as f:
        monkeypatch.setattr(os, "read", read_fails)
        try:
            with pytest.raises(EnvironmentFailure) as ex:
                f.read()
        finally:
            monkeypatch.setattr(os, "read", real_read)
    assert str(ex.value) == f"cannot read {p}: [EIO] Input/output error"


def test_a_folder_the_machine_will_not_list_or_whose_entries_vanish(tmp_path, monkeypatch):
    d = tmp_path / "out"
    d.mkdir()
    for name in ("a.txt", "b.txt", "c.txt"):
        (d / name).write_text(name)
    real_walk, real_lstat = os.walk, os.lstat

    def walk_refused(root, onerror=None, followlinks=False):
        assert followlinks is False and onerror is not None
        onerror(PermissionError(errno.EACCES, "Permission denied", str(root)))
        return iter(())

    monkeypatch.setattr(os, "walk", walk_refused)
    with pytest.raises(EnvironmentFailure) as ex:
        safe_read.walk(d)
    assert str(ex.value) == f"cannot list {d}: [EACCES] Permission denied"
    monkeypatch.setattr(os, "walk", real_walk)

    def lstat_vanishing(p, *a, **kw):
        if str(p).endswith("a.txt"):
            raise FileNotFoundError(errno.ENOENT, "No such file or directory", str(p))
        return real_lstat(p, *a, **kw)

    monkeypatch.setattr(os, "lstat", lstat_vanishing)
    assert safe_read.walk(d) == ([d / "b.txt", d / "c.txt"], {})

    def lstat_refused(p, *a, **kw):
        if str(p).endswith("b.txt"):
            raise PermissionError(errno.EACCES, "Permission denied", str(p))
        return real_lstat(p, *a, **kw)

    monkeypatch.setattr(os, "lstat", lstat_refused)
    with pytest.raises(EnvironmentFailure) as ex:
        safe_read.walk(d)
    assert str(ex.value) == f"cannot read {d / 'b.txt'}: [EACCES] Permission denied"


def test_stl_lengths_and_counts_at_their_edges():
    # a count past 2^31 is a count, not a negative number
    data = b"x" * 80 + struct.pack("<I", 0xFFFFFFFF) + b"y" * 16
    assert _refused(formats.stl_kind, data) == (
        "binary STL declares 4294967295 triangles, i.e. 84 + 50 n = 214748364834 bytes, but the file has 100")
    # exactly 84 bytes, neither empty binary nor ASCII: its count is what is wrong
    assert _refused(formats.stl_kind, _binary_stl(1)[:84]) == (
        "binary STL declares 1 triangles, i.e. 84 + 50 n = 134 bytes, but the file has 84")


def test_arcs_no_larger_than_the_tolerance_are_two_points_whatever_their_sweep():
    assert formats._arc_points(CHORD_TOL_MM, 2 * math.pi) == 2
    assert formats._arc_points(CHORD_TOL_MM * 0.5, 2 * math.pi) == 2


def test_bulges_on_any_vertex_of_an_open_polyline_off_the_origin():
    half = formats._arc_points(1.0, math.pi)
    # (10, 5) -> (12, 5) straight, (12, 5) -> (12, 7) a half circle of radius 1, (12, 7) the end
    assert formats._bulged([(10.0, 5.0, 0.0), (12.0, 5.0, 1.0), (12.0, 7.0, 0.0)], "P", closed=False) == 3 + half
    # the chord from (10, 20) to (16, 20): a bulge of 1 is a half circle of radius 3
    assert formats._bulged([(10.0, 20.0, 1.0), (16.0, 20.0, 0.0)], "P", closed=False) == 2 + formats._arc_points(
        3.0, math.pi)
    assert formats._bulged([(3.0, 10.0, 1.0), (3.0, 16.0, 0.0)], "P", closed=False) == 2 + formats._arc_points(
        3.0, math.pi)


def test_a_drawings_points_are_summed_over_every_entity_kind(monkeypatch):
    """With the limit set to a drawing's own total (each entity's points by hand), it passes; one less, and the last
    entity is named."""
    doc, msp = _doc()
    msp.add_lwpolyline([(10, 5, 0, 0, 0.0), (12, 5, 0, 0, 1.0), (12, 7, 0, 0, 0.0)], format="xyseb", close=True)
    lw = 3 + formats._arc_points(1.0, math.pi)  # the closing segment (12, 7) -> (10, 5) straight
    pl = msp.add_polyline2d([(0, 0), (5, 0), (5, 5)], close=True)
    for v in pl.vertices:
        v.dxf.discard("bulge")  # no bulge recorded: straight
    poly = 3
    msp.add_circle((1, 1), 5.0)
    circle = formats._arc_points(5.0, 2 * math.pi)
    msp.add_ellipse((0, 0), major_axis=(6, 8), ratio=0.5)
    ellipse = formats._arc_points(10.0, 2 * math.pi)
    s = msp.add_spline(fit_points=None)
    s.control_points = []
    spline = 64
    msp.add_line((0, 0), (1, 1))
    total = lw + poly + circle + ellipse + spline
    monkeypatch.setattr(formats, "DXF_POINTS_MAX", total)
    formats.check_dxf_doc(doc)
    monkeypatch.setattr(formats, "DXF_POINTS_MAX", total - 1)
    assert _refused(formats.check_dxf_doc, doc) == f"its curves flatten to more than {total - 1} points (at SPLINE #5)"
    monkeypatch.setattr(formats, "DXF_POINTS_MAX", lw - 1)
    assert _refused(formats.check_dxf_doc, doc) == f"its curves flatten to more than {lw - 1} points (at LWPOLYLINE #1)"
    monkeypatch.setattr(formats, "DXF_POINTS_MAX", lw + poly - 1)
    assert _refused(formats.check_dxf_doc, doc) == (
        f"its curves flatten to more than {lw + poly - 1} points (at POLYLINE #2)")
    monkeypatch.setattr(formats, "DXF_POINTS_MAX", lw + poly + circle + ellipse - 1)
    assert _refused(formats.check_dxf_doc, doc) == (
        f"its curves flatten to more than {lw + poly + circle + ellipse - 1} points (at ELLIPSE #4)")


def test_a_lines_start_and_a_polylines_vertices_are_bounded():
    span = "beyond the ±100000 mm a drawing may span"
    for add, text in ((lambda m: m.add_line((2e5, 0), (0, 0)), f"LINE #1 start = 200000.0: {span}"),
                      (lambda m: m.add_lwpolyline([(0, 0), (0, 3e5)]), f"LWPOLYLINE #1 y = 300000.0: {span}")):
        d, m = _doc()
        add(m)
        assert _refused(formats.check_dxf_doc, d) == text


def test_glb_refusals_and_drawn_triangles_by_hand():
    assert _refused(formats.check_glb, b"glTF") == _glb_refusal(b"glTF")
    gltf = formats.check_glb(_glb_bytes())
    assert formats.drawn_triangles(gltf) == 12  # one box: 6 faces of 2 triangles
    two = trimesh.Scene()
    box = trimesh.creation.box(extents=(0.01, 0.01, 0.01))
    two.add_geometry(box, node_name="a", geom_name="box")
    two.add_geometry(box, node_name="b", geom_name="box", transform=np.eye(4))
    assert formats.drawn_triangles(formats.check_glb(two.export(file_type="glb"))) == 24
    from propulsor.export import glb_check

    glb_check_limit = glb_check.GLB_DRAWN_TRIANGLES_MAX
    try:
        glb_check.GLB_DRAWN_TRIANGLES_MAX = 11
        with pytest.raises(Refused) as e:
            formats.drawn_triangles(gltf)
    finally:
        glb_check.GLB_DRAWN_TRIANGLES_MAX = glb_check_limit
    assert str(e.value) == "its nodes draw 12 triangles, more than the 11 the 3D view draws"


def _glb_refusal(data: bytes) -> str:
    from propulsor.export import glb_check

    with pytest.raises(glb_check.Refused) as e:
        glb_check.check_glb(data)
    return str(e.value)


def test_brep_checks_default_name_unit_and_chord_tolerance():
    cyl = cq.Solid.makeCylinder(10.0, 5.0)
    cs = brep.brep_checks(cyl)
    assert cs[0].name == "solid: BRepCheck_Analyzer valid"
    assert cs[4].unit == "mm^3" and cs[4].passed
    coarse = brep.brep_checks(cyl, "c", chord_tol=0.05)[4]
    assert "deflection 0.05 mm" in coarse.message
    # the triangulation's volume is the polyhedron's, below the exact cylinder's, within deflection x area
    t = brep.triangulated_volume(cyl, chord_tol=0.05)
    exact = math.pi * 10.0 ** 2 * 5.0
    assert 1e-3 < exact - t.volume_mm3 <= t.bound_mm3
    assert brep.volume_from_triangulation(cyl, chord_tol=0.05) == t.volume_mm3
    assert t.deflection_mm >= 0.05 and t.area_mm2 == pytest.approx(2 * math.pi * 10 * (10 + 5), rel=1e-9)


def _glb_of_json(doc: dict) -> bytes:
    body = json.dumps(doc).encode()
    body += b" " * (-len(body) % 4)
    return b"glTF" + struct.pack("<II", 2, 12 + 8 + len(body)) + struct.pack("<I", len(body)) + b"JSON" + body


def test_the_file_checks_say_why_in_full(tmp_path, monkeypatch):
    files._MANIFESTS.clear()
    (tmp_path / "junk.dxf").write_text("0\nSECTION\n2\nNOPE\n")
    assert files.check_dxf_file(tmp_path / "junk.dxf") == [Check(
        "junk.dxf: DXF parses", False, False, True, "", "DXFStructureError: DXFStructureError: missing ENDSEC tag.")]
    _dxf(tmp_path / "ok.dxf")

    def summary_fails(doc, *a, **kw):
        raise KeyError("layer")

    monkeypatch.setattr("propulsor.export.dxf.dxf_summary", summary_fails)
    assert files.check_dxf_file(tmp_path / "ok.dxf") == [Check(
        "ok.dxf: DXF parses", False, False, True, "", "KeyError: 'layer'")]
    monkeypatch.undo()
    (tmp_path / "junk.step").write_text("ISO-10303-21;\nnonsense\n")
    assert files.check_step_file(tmp_path / "junk.step") == [Check(
        "junk.step: STEP parses", False, False, True, "", "junk.step: STEP does not parse (status 3)")]
    os.mkfifo(tmp_path / "pipe.step")
    assert files.check_step_file(tmp_path / "pipe.step") == [Check(
        "pipe.step: STEP parses", False, False, True, "", "is a FIFO, not a regular file (not opened)")]
    (tmp_path / "x.glb").write_bytes(b"glTF")
    assert files.check_glb_file(tmp_path / "x.glb") == [Check(
        "x.glb: loads", False, False, True, "", _glb_refusal(b"glTF"))]
    empty = _glb_of_json({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
                          "nodes": [{"name": "empty"}]})
    (tmp_path / "e.glb").write_bytes(empty)
    assert files.check_glb_file(tmp_path / "e.glb") == [Check(
        "e.glb: loads", False, False, True, "", "ValueError: no mesh node")]
    os.mkfifo(tmp_path / "manifest.json")
    assert files.check_manifest_file(tmp_path / "manifest.json") == [Check(
        "manifest.json: parses", False, False, True, "", "is a FIFO, not a regular file (not opened)")]
    stl = _box_stl(tmp_path / "b.stl")
    assert files.check_file(stl)[0] == Check("b.stl: loads", True, True, True, "", "12 triangles, 8 vertices")


def test_a_step_solid_that_does_not_tessellate_is_said_so(tmp_path, monkeypatch):
    files._MANIFESTS.clear()
    p = write_step(cq.Solid.makeBox(2.0, 3.0, 4.0), tmp_path / "box.step", "box")

    def fails(solid, parallel=True):
        raise RuntimeError("BRepMesh failed")

    monkeypatch.setattr("propulsor.export.mesh.tessellate", fails)
    cs = files.check_step_file(p)
    assert cs[-1] == Check("box.step: solid 1 mesh: tessellates", False, False, True, "", "RuntimeError: BRepMesh failed")


def test_a_step_file_without_a_manifest_and_every_brep_check_after_the_solid_count(tmp_path):
    files._MANIFESTS.clear()
    p = write_step(cq.Solid.makeBox(2.0, 3.0, 4.0), tmp_path / "box.step", "box")
    by = {c.name: c for c in files.check_step_file(p)}
    assert "box.step: volume vs manifest" not in by
    for n in ("open shells", "B-rep volume", "exact volume vs triangulated"):
        assert f"box.step: solid 1: {n}" in by
    v = by["box.step: solid 1 mesh: volume vs B-rep"]
    assert v.passed and v.limit["expected"] == pytest.approx(24.0, rel=1e-12)
    files._MANIFESTS.clear()
    _manifest(tmp_path, [{"path": "box.step", "volume_mm3": 24.0}])
    c = {c.name: c for c in files.check_step_file(p)}["box.step: volume vs manifest"]
    assert c.unit == "mm^3" and c.limit == {"expected": 24.0, "rel_tol": 1e-6, "abs_tol": 0.0}
    assert c.message.startswith("box.step: volume vs manifest: ")


def test_the_box_pair_budget_reaches_every_mesh_a_file_check_makes(tmp_path, monkeypatch):
    """A limit of 3 box pairs: the STL's mesh and a STEP solid's tessellation say the self-intersection test was not
    run."""
    files._MANIFESTS.clear()
    stl = _box_stl(tmp_path / "b.stl")
    monkeypatch.setattr(files, "MESH_BOX_PAIRS_MAX", 3)
    x = files.check_mesh_file(stl)[-1]
    assert x.name == "b.stl: self-intersecting triangle pairs" and x.value == -1
    assert x.message == "not tested: more than 3 pairs of overlapping triangle boxes"
    p = write_step(cq.Solid.makeBox(2.0, 3.0, 4.0), tmp_path / "box.step", "box")
    x = {c.name: c for c in files.check_step_file(p)}["box.step: solid 1 mesh: self-intersecting triangle pairs"]
    assert x.value == -1 and x.message == "not tested: more than 3 pairs of overlapping triangle boxes"


def test_listed_files_by_size_and_hash_at_their_edges(tmp_path):
    d = tmp_path / "out"
    d.mkdir()
    (d / "one.txt").write_text("1")
    (d / "empty.txt").write_text("")
    (d / "nine.txt").write_text("123456789")
    entries = [dict(_entry(d, "one.txt"), bytes=True),      # a bool is no size, though True == 1
               _entry(d, "empty.txt"),                      # an empty file as recorded
               dict(_entry(d, "nine.txt"), bytes=9.0)]      # a float is no size either
    m = _manifest(d, entries)
    c = {x.name.split(": ", 1)[1]: x for x in files.check_manifest_file(m)}
    assert c["size mismatches"].message == "one.txt, nine.txt"
    assert c["listed files unreadable"].value == 0 and c["listed files missing"].value == 0


def test_every_list_in_a_manifests_checks_is_joined_in_full(tmp_path):
    d = tmp_path / "out"
    (d / "sub").mkdir(parents=True)
    (d / "u1.txt").write_text("1")
    (d / "u2.txt").write_text("2")
    (d / "dir1").mkdir()
    (d / "dir2").mkdir()
    entries = [{"path": "gone1", "bytes": 1}, {"path": "gone2", "bytes": 1}, {"path": "dir1", "bytes": 1},
               {"path": "dir2", "bytes": 1}]
    checks = [{"name": "a", "passed": False}, {"name": "b", "passed": False}, {"name": "c", "passed": False}]
    m = _manifest(d, entries, checks=checks, expected_failures=["a", "b"])
    c = {x.name.split(": ", 1)[1]: x for x in files.check_manifest_file(m)}
    assert c["listed files missing"].message == "missing: gone1, gone2"
    assert c["listed files unreadable"].message == ("dir1 (is a folder, not a regular file (not opened)), "
                                                    "dir2 (is a folder, not a regular file (not opened))")
    assert c["unlisted files"].message == "u1.txt, u2.txt"
    assert c["recorded failed checks"].message == "c (2 documented as expected failures in the part file: a; b)"


def test_the_entry_of_a_file_is_found_among_others(tmp_path):
    files._MANIFESTS.clear()
    f = tmp_path / "b.stl"
    _manifest(tmp_path, [{"path": "a.stl", "genus": 3}, {"path": "b.stl", "genus": 1}])
    assert files._manifest_entry(f) == {"path": "b.stl", "genus": 1}


def test_check_path_keeps_every_files_checks(tmp_path):
    d = tmp_path / "out"
    d.mkdir()
    stl = _box_stl(d / "b.stl")
    assert files.check_path(d) == {str(stl): files.check_file(stl)}


def test_a_policy_with_an_empty_directive_in_the_middle_is_read_to_its_end():
    sheet, known = _sha256("x"), script_hash(TABLE_SORT_SCRIPT)
    csp = (f"default-src 'none'; ; img-src 'self'; style-src {sheet}; script-src {known}; base-uri 'none'; "
           "form-action 'none'")
    assert pages._policy_problem(csp) == ""
    assert pages._policy_problem(csp.replace("form-action 'none'", "form-action *")) == (
        "its policy's form-action is '*', not 'none'")


def test_a_glb_assembly_off_the_origin_in_a_folder_whose_step_is_not_a_file(tmp_path):
    files._MANIFESTS.clear()
    a = cq.Solid.makeBox(20.0, 30.0, 40.0)
    write_assembly_step(tmp_path / "asm.step", [("a", a, (100.0, 50.0, 10.0), 0.0)], "asm")
    scene = trimesh.Scene()
    scene.add_geometry(trimesh.creation.box(extents=(0.02, 0.03, 0.04)), node_name="a")
    (tmp_path / "asm.glb").write_bytes(scene.export(file_type="glb"))
    _manifest(tmp_path, [], media={"models": [{"path": "asm.glb", "components": ["a"], "step": "asm.step"}]})
    cs = files.check_glb_file(tmp_path / "asm.glb")
    assert cs[-1] == Check("asm.glb: extent vs the STEP in metres", True, cs[-1].value, 1e-4, "m",
                           "glTF is in metres: the STEP's mm × 0.001") and cs[-1].value < 1e-9
    (tmp_path / "asm.step").unlink()
    (tmp_path / "asm.step").mkdir()
    files._MANIFESTS.clear()
    assert files.check_glb_file(tmp_path / "asm.glb")[-1] == Check(
        "asm.glb: assembly STEP readable", False, False, True, "",
        "asm.step is a folder, not a regular file (not opened)")


def test_the_kernels_are_cold_only_where_neither_compiled_nor_on_disk(monkeypatch):
    from propulsor.checks import kernels

    kernels.warm()
    ds = kernels._dispatchers()
    # not compiled in this process but each on disk: not cold
    monkeypatch.setattr(type(ds[0]), "signatures", property(lambda self: []))
    assert all(d._cache._cache_file._load_index() for d in ds)
    assert not kernels.cold()
    monkeypatch.undo()

    def unreadable():
        raise AttributeError("numba's layout changed")

    monkeypatch.setattr(kernels, "_dispatchers", unreadable)
    assert kernels.cold() is False


def test_nearest_points_of_bodies_whose_boxes_overlap_but_lie_far_apart():
    """A ball at the centre of a ring of radius 50: their boxes overlap, their surfaces are 39 mm apart, beyond the
    reach of a 5 mm bound (pad 5 + 2 x 10): nothing found."""
    import manifold3d as m3d

    ring = m3d.Manifold.cylinder(10.0, 52.0, 52.0, 128).translate([0.0, 0.0, -5.0]) - \
        m3d.Manifold.cylinder(12.0, 48.0, 48.0, 128).translate([0.0, 0.0, -6.0])
    ball = m3d.Manifold.sphere(9.0, 64)
    from propulsor.checks.proximity import nearest_points

    assert ring.min_gap(ball, 60.0) == pytest.approx(39.0, abs=0.1)
    assert nearest_points(ring, ball, 5.0) == (math.inf, None, None)
    d, pa, pb = nearest_points(ring, ball, 45.0, spacing=1.0, coarse=12.0)
    assert d == pytest.approx(39.0, abs=1.0) and np.hypot(pa[0], pa[1]) == pytest.approx(48.0, abs=0.5)


def test_warm_if_cold_warms_and_says_so_only_when_cold(monkeypatch):
    from propulsor.checks import kernels

    said, warmed = [], []
    monkeypatch.setattr(kernels, "warm", lambda: warmed.append(1))
    monkeypatch.setattr(kernels, "cold", lambda: False)
    assert kernels.warm_if_cold(said.append) is False and said == [] and warmed == []
    monkeypatch.setattr(kernels, "cold", lambda: True)
    assert kernels.warm_if_cold(said.append) is True and warmed == [1]
    assert said == ["compiling the numeric kernels for this machine (once after an install or an update: about 30 s)"]
    assert kernels.warm_if_cold() is True and warmed == [1, 1]


def test_a_closed_polylines_closing_bulge_counts_after_other_entities(monkeypatch):
    doc, msp = _doc()
    msp.add_circle((0, 0), 5.0)
    circle = formats._arc_points(5.0, 2 * math.pi)
    # closed: (0, 0) -> (4, 0) -> (4, 3) and back to (0, 0) over a bulge of 1 (a half circle on the 5 mm chord)
    msp.add_lwpolyline([(0, 0, 0, 0, 0.0), (4, 0, 0, 0, 0.0), (4, 3, 0, 0, 1.0)], format="xyseb", close=True)
    pl = msp.add_polyline2d([(10, 0), (14, 0), (14, 3)], close=True)
    pl.vertices[-1].dxf.bulge = 1.0
    lw = 3 + formats._arc_points(2.5, math.pi)
    total = circle + 2 * lw
    monkeypatch.setattr(formats, "DXF_POINTS_MAX", total)
    formats.check_dxf_doc(doc)
    monkeypatch.setattr(formats, "DXF_POINTS_MAX", total - 1)
    assert _refused(formats.check_dxf_doc, doc) == f"its curves flatten to more than {total - 1} points (at POLYLINE #3)"
    monkeypatch.setattr(formats, "DXF_POINTS_MAX", circle + lw - 1)
    assert _refused(formats.check_dxf_doc, doc) == (
        f"its curves flatten to more than {circle + lw - 1} points (at LWPOLYLINE #2)")


def test_the_machines_own_words_for_a_refusal_are_kept():
    e = safe_read._os_error(OSError(errno.EACCES, "denied by the site's policy"), "/x", "cannot read")
    assert str(e) == "cannot read /x: [EACCES] denied by the site's policy"

