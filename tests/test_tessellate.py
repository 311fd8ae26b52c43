"""Tessellation of the exported meshes (solids/tessellate.py): OCCT's achieved deflection held to the
0.01 mm the files promise by meshing again only the faces that miss it, and the mesh as written (STL is
float32) still closed and free of self-intersections."""

import math

import cadquery as cq
import numpy as np
import pytest

from propulsor.checks.mesh import edge_counts, self_intersections
from propulsor.policy import MESH_CHORD_LIMIT_MM
from propulsor.solids import prism_mesh as P
from propulsor.solids import tessellate as T


def _disc(chamfer_mm: float, drill_point: bool):
    body = cq.Workplane("XY").circle(50.0).extrude(20.0).faces(">Z").edges().chamfer(chamfer_mm)
    if drill_point:  # a blind bore with a 118 deg drill point: a cone down to its apex
        r, depth = 8.0, 12.0
        tip = r / math.tan(math.radians(59.0))
        hole = (cq.Workplane("XZ").polyline([(0, 25), (r, 25), (r, 20 - depth), (0, 20 - depth - tip)]).close()
                .revolve(360, (0, 0, 0), (0, 1, 0)).translate((20, 0, 0)))
        body = body.cut(hole)
    return body.val()


def _mesh(solid, monkeypatch):
    passes, refined = [], []
    mesh_shape, refine_faces = T.mesh_shape, T.refine_faces
    monkeypatch.setattr(T, "mesh_shape", lambda *a, **k: passes.append(mesh_shape(*a, **k)) or passes[-1])
    monkeypatch.setattr(T, "refine_faces", lambda *a, **k: refined.append(refine_faces(*a, **k)) or refined[-1])
    v, f, d = T.triangulate(solid, parallel=False)
    return v, f, d, passes, refined


def _closed_and_clean_in_float32(v, f):
    v32 = v.astype(np.float32).astype(np.float64)  # what the STL holds
    counts = edge_counts(f)
    counts = counts[1] if isinstance(counts, tuple) else counts
    assert np.all(np.asarray(counts) == 2)
    assert self_intersections(v32, f)[0] == 0


def test_faces_that_miss_the_chord_are_meshed_again_alone(monkeypatch):
    """A 45 deg chamfer cone of a disc misses the request (0.0122 mm at 0.005): that face alone is meshed
    again with its surface deflection controlled, instead of the whole disc at half the request."""
    v, f, d, passes, refined = _mesh(_disc(8.0, drill_point=False), monkeypatch)
    assert len(passes) == 1 and passes[0] > MESH_CHORD_LIMIT_MM
    assert len(refined) == 1 and d == refined[0] <= MESH_CHORD_LIMIT_MM
    _closed_and_clean_in_float32(v, f)


def test_one_solid_placed_twice_is_meshed_twice_alike():
    """A compound of one solid at two places (as an assembly's STEP holds it; the faces share their triangulation):
    the chamfer cone that misses the request is meshed again at its first place, and its second place, whose
    triangulation that cleared, is not read for a deflection (an AttributeError before).  The mesh is the solid's
    own mesh twice, the second moved by the placement; both closed and clean, within the limit."""
    disc = _disc(8.0, drill_point=False)
    v1, f1, d1 = T.triangulate(disc, parallel=False)
    comp = cq.Compound.makeCompound([disc, disc.moved(cq.Location(cq.Vector(120.0, 0.0, 0.0)))])
    v, f, d = T.triangulate(comp, parallel=False)
    n, m = len(v1), len(f1)
    assert len(v) == 2 * n and len(f) == 2 * m and d == d1 <= MESH_CHORD_LIMIT_MM
    assert np.array_equal(v[:n], v1) and np.array_equal(f[:m], f1)
    assert np.allclose(v[n:] - np.array([120.0, 0.0, 0.0]), v1, rtol=0.0, atol=1e-9)
    assert np.array_equal(f[m:] - n, f1)
    _closed_and_clean_in_float32(v, f)


def test_an_apex_is_measured_not_halved(monkeypatch):
    """A drill point's cone reaches its apex, where OCCT's estimate of the deflection (made in the parameter
    plane) is 0.0205 mm: refined alone it folds once written in float32, so it is kept and measured against
    the exact cone instead — within the request, no halving of the whole disc; the written mesh is closed
    and clean."""
    v, f, d, passes, refined = _mesh(_disc(8.0, drill_point=True), monkeypatch)
    assert len(passes) == 1 and len(refined) == 1 and d == refined[0] <= MESH_CHORD_LIMIT_MM
    _closed_and_clean_in_float32(v, f)


def _apex_faces(shape):
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS

    ex, out = TopExp_Explorer(shape, TopAbs_FACE), []
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        if T._has_apex(face):
            out.append(face)
        ex.Next()
    return out


@pytest.mark.parametrize("kind", ["cone", "sphere"])
def test_apex_deflection_is_the_distance_to_the_surface(kind):
    """The closed-form distance of _apex_deflection against OCCT's projection of the same sample points on the
    face's surface (GeomAPI_ProjectPointOnSurf).  OCCT's own estimate is right on the sphere (0.0105 mm at a
    request of 0.005 mm: triangulate halves it) and five times too large at the cone's apex."""
    from OCP.BRep import BRep_Tool
    from OCP.GeomAPI import GeomAPI_ProjectPointOnSurf
    from OCP.gp import gp_Pnt
    from OCP.TopLoc import TopLoc_Location

    solid = cq.Solid.makeCone(8.0, 0.0, 5.0) if kind == "cone" else cq.Workplane().sphere(7.0).val()
    shape = T.occ_shape(solid)
    T.mesh_shape(shape, 0.005, 0.1, False)
    faces = _apex_faces(shape)
    assert faces
    for face in faces:
        got = T._apex_deflection(face)
        tri = BRep_Tool.Triangulation_s(face, TopLoc_Location())
        P = np.array([tri.Node(i).Coord() for i in range(1, tri.NbNodes() + 1)])
        F = np.array([tri.Triangle(i).Get() for i in range(1, tri.NbTriangles() + 1)]) - 1
        n = T._APEX_SAMPLES
        B = np.array([(i / n, j / n, 1 - (i + j) / n) for i in range(n + 1) for j in range(n + 1 - i)])
        X = np.einsum("bk,tkd->tbd", B, P[F]).reshape(-1, 3)[::7]  # every 7th sample: OCCT's projection is slow
        surf = BRep_Tool.Surface_s(face)
        ref = max(GeomAPI_ProjectPointOnSurf(gp_Pnt(*map(float, x)), surf).LowerDistance() for x in X)
        assert ref <= got + 1e-9
        assert got == pytest.approx(ref, rel=0.05)  # the subsample reaches the same worst triangle
        if kind == "cone":
            assert got <= 0.005 and tri.Deflection() > 4 * got  # OCCT's estimate at the apex
        else:
            assert got > MESH_CHORD_LIMIT_MM and tri.Deflection() == pytest.approx(got, rel=0.01)
    if kind == "sphere":
        v, f, d = T.triangulate(solid, parallel=False)
        assert d <= MESH_CHORD_LIMIT_MM


def _faces_meshed(solid, premesh: bool):
    """(surface type, node bytes, triangle bytes) of every face of a ruled solid meshed as mesh_shape does
    (interior vertices off), with or without the cylinder bands meshed first."""
    from OCP.BRep import BRep_Tool
    from OCP.BRepAdaptor import BRepAdaptor_Surface
    from OCP.BRepMesh import BRepMesh_IncrementalMesh
    from OCP.BRepTools import BRepTools
    from OCP.IMeshTools import IMeshTools_Parameters
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopLoc import TopLoc_Location
    from OCP.TopoDS import TopoDS

    shape = solid.wrapped
    BRepTools.Clean_s(shape)
    prm = IMeshTools_Parameters()
    prm.Deflection, prm.Angle, prm.Relative, prm.InParallel = 0.005, 0.1, False, False
    prm.InternalVerticesMode = prm.ControlSurfaceDeflection = False
    if premesh:
        T._premesh_cylinders(shape, prm)
    BRepMesh_IncrementalMesh(shape, prm)
    out = []
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        tri = BRep_Tool.Triangulation_s(face, TopLoc_Location())
        nodes = np.array([tri.Node(i).Coord() for i in range(1, tri.NbNodes() + 1)])
        tris = np.array([tri.Triangle(i).Get() for i in range(1, tri.NbTriangles() + 1)])
        out.append((str(BRepAdaptor_Surface(face).GetType()), nodes.tobytes(), tris.tobytes(), len(tris)))
        ex.Next()
    return out


def test_cylinder_bands_meshed_first_keep_every_node_and_the_planes():
    """A bored ring (road-wheel rim, 200 x 60 mm): its cylinder bands meshed first with interior vertices allowed
    (25 times faster) get no interior node: every face has the very nodes of the single pass, the planar faces
    the very triangles, the bands as many triangles (other diagonals)."""
    from OCP.BRep import BRep_Tool
    from OCP.BRepAdaptor import BRepAdaptor_Surface
    from OCP.BRepTools import BRepTools
    from OCP.IMeshTools import IMeshTools_Parameters
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopLoc import TopLoc_Location
    from OCP.TopoDS import TopoDS

    ring = cq.Workplane("XY").circle(100.0).circle(80.0).extrude(60.0).val()
    # the first pass alone: the two bands meshed (boundary nodes only), the two annuli not yet
    BRepTools.Clean_s(ring.wrapped)
    prm = IMeshTools_Parameters()
    prm.Deflection, prm.Angle = 0.005, 0.1
    T._premesh_cylinders(ring.wrapped, prm)
    meshed = []
    ex = TopExp_Explorer(ring.wrapped, TopAbs_FACE)
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        is_band = BRepAdaptor_Surface(face).GetType() == T.GeomAbs_Cylinder
        meshed.append((is_band, BRep_Tool.Triangulation_s(face, TopLoc_Location()) is not None))
        assert not is_band or T._boundary_nodes_only(face)
        ex.Next()
    assert sorted(meshed) == [(False, False), (False, False), (True, True), (True, True)]
    single, first = _faces_meshed(ring, False), _faces_meshed(ring, True)
    assert [f[0] for f in single].count("GeomAbs_SurfaceType.GeomAbs_Cylinder") == 2
    for (kind, nodes, tris, n), (kind2, nodes2, tris2, n2) in zip(single, first):
        assert kind == kind2 and nodes == nodes2 and n == n2
        if "Plane" in kind:
            assert tris == tris2


def test_a_face_with_interior_nodes_is_left_to_the_single_pass():
    """The rectangle test of the parameter plane: a planar disc meshed with interior vertices has nodes inside."""
    from OCP.BRepMesh import BRepMesh_IncrementalMesh
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS

    disc = cq.Workplane("XY").circle(50.0).extrude(10.0).val()
    BRepMesh_IncrementalMesh(disc.wrapped, 0.01, False, 0.1, False)
    kinds = []
    ex = TopExp_Explorer(disc.wrapped, TopAbs_FACE)
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        kinds.append((T.BRepAdaptor_Surface(face).GetType() == T.GeomAbs_Cylinder, T._boundary_nodes_only(face)))
        ex.Next()
    assert sorted(kinds) == [(False, False), (False, False), (True, True)]


def _spline_prism():
    """A prism of a closed spline (a lobed cam-like outline) with a bore: BRepPrimAPI's side faces are linear
    extrusions of the spline's edges, as a gear's flanks are."""
    t = np.linspace(0.0, 2 * math.pi, 25)[:-1]
    r = 30.0 + 4.0 * np.cos(3 * t) + 1.5 * np.sin(7 * t)
    pts = [(float(a), float(b)) for a, b in zip(r * np.cos(t), r * np.sin(t))]
    wp = cq.Workplane("XY").moveTo(*pts[0])
    for k in range(0, 24, 6):  # four spline edges, four side faces
        wp = wp.spline((pts + pts[:1])[k + 1:k + 7], includeCurrent=True)
    return wp.close().extrude(12.0).faces(">Z").workplane().hole(10.0).val()


def _faces(shape) -> list:
    """The shape's faces in the explorer's order (the face indices of the strips and copies)."""
    out = []
    ex = T.TopExp_Explorer(shape, T.TopAbs_FACE)
    while ex.More():
        out.append(T.TopoDS.Face_s(ex.Current()))
        ex.Next()
    return out


def _side_faces(shape):
    return [f for f in _faces(shape) if T.BRepAdaptor_Surface(f).GetType() == T.GeomAbs_SurfaceOfExtrusion]


def _distance_to_faces(X, faces):
    """The least distance of each point to the surfaces of ``faces``, each within its face's parameter bounds (OCCT's
    projection, set up once a face)."""
    from OCP.BRep import BRep_Tool
    from OCP.BRepTools import BRepTools
    from OCP.GeomAPI import GeomAPI_ProjectPointOnSurf
    from OCP.gp import gp_Pnt

    projections = []
    for face in faces:
        pr = GeomAPI_ProjectPointOnSurf()
        pr.Init(BRep_Tool.Surface_s(face), *BRepTools.UVBounds_s(face))
        projections.append(pr)
    out = []
    for x in X:
        p = gp_Pnt(*map(float, x))
        best = math.inf
        for pr in projections:
            pr.Perform(p)
            if pr.NbPoints():
                best = min(best, pr.LowerDistance())
        out.append(best)
    return np.array(out)


def test_prism_sides_are_strips_within_the_chord_they_report():
    """A prism's side faces meshed as strips between the nodes of their two curve edges: no more triangles than two
    a chord, the mesh closed and clean in float32, and the deflection it reports (the chords' distance from the
    curve) at least the distance of the side triangles from their faces measured by OCCT's projection, within the
    request; BRepMesh's own triangles of the same faces miss it (and were meshed again with interior nodes)."""
    solid = _spline_prism()
    shape = T.occ_shape(solid)
    T.mesh_shape(shape, 0.005, 0.1, False, MESH_CHORD_LIMIT_MM)
    sides = _side_faces(shape)
    strips = P.side_strips(shape)
    assert sides and len(strips) == len(sides)
    occt = max(T.BRep_Tool.Triangulation_s(f, T.TopLoc_Location()).Deflection() for f in sides)
    v, f, d = T.triangulate(solid, parallel=False)
    _closed_and_clean_in_float32(v, f)
    import trimesh

    mesh = trimesh.Trimesh(v, f, process=False)
    assert d <= 0.005 < occt
    # outward (a positive volume), and within the deflection times the area of the exact one
    assert mesh.is_winding_consistent and 0 < mesh.volume and abs(mesh.volume - solid.Volume()) <= d * solid.Area()
    # the side triangles: those with a vertical edge (both caps are flat at z = 0 and z = 12) off the bore (r = 5)
    z = v[f][:, :, 2]
    side = ((z.max(axis=1) - z.min(axis=1)) > 1.0) & (np.linalg.norm(v[f].mean(axis=1)[:, :2], axis=1) > 8.0)
    n_side = int(side.sum())
    chords = sum(len(s[1]) for s in strips.values())
    assert n_side == chords
    B = np.array([(1 / 3, 1 / 3, 1 / 3), (0.5, 0.5, 0.0), (0.25, 0.5, 0.25), (0.1, 0.45, 0.45)])
    X = np.einsum("bk,tkd->tbd", B, v[f[side]]).reshape(-1, 3)[::5]
    dist = _distance_to_faces(X, sides)
    assert dist.max() <= d + 1e-9
    assert dist.max() > 0.2 * d  # the chords' sag is there, and the reported value is of its size


def test_a_filleted_union_falls_back_to_brepmesh_where_no_strip_fits():
    """A user's solid (a CadQuery union of two prisms with filleted vertical edges): its side faces that are not
    bounded by two copies of one curve keep BRepMesh's triangles; the mesh is closed and clean, within the limit."""
    a = cq.Workplane("XY").rect(40, 20).extrude(10).edges("|Z").fillet(3.0)
    b = cq.Workplane("XY").center(15, 0).circle(12).extrude(16)
    solid = a.union(b).val()
    v, f, d = T.triangulate(solid, parallel=False)
    _closed_and_clean_in_float32(v, f)
    assert d <= MESH_CHORD_LIMIT_MM


def test_a_side_face_no_strip_fits_is_brepmeshs_the_others_stay_strips(monkeypatch):
    """A hole across the spline prism, through two of its sides: those faces have the hole's edges too, no strip fits
    them, and they are meshed by BRepMesh alone on the nodes the caps gave their edges (before, the whole prism was
    meshed again by BRepMesh); the other two sides stay strips.  They border the top cap, whose edge BRepMesh would
    discretise afresh: so no cap is copied.  The straight edges they share with the strips stay undivided; the mesh
    is closed, clean and outward, and holds the volume."""
    import trimesh
    from OCP.BRep import BRep_Tool
    from OCP.BRepAdaptor import BRepAdaptor_Curve
    from OCP.GeomAbs import GeomAbs_Line

    hole = cq.Workplane("YZ").workplane(offset=10.0).center(0.0, 6.0).circle(2.0).extrude(40.0).val()
    solid = cq.Workplane().add(_spline_prism()).cut(hole).val()
    apart = _apart_recorded(monkeypatch)
    v, f, d = T.triangulate(solid, parallel=False)
    assert len(apart) == 1 and apart[0] is not None
    strips, _, copied = apart[0]
    shape = T.occ_shape(solid)
    faces = _faces(shape)
    sides = [k for k, face in enumerate(faces) if T.BRepAdaptor_Surface(face).GetType() == T.GeomAbs_SurfaceOfExtrusion]
    holed = [k for k in sides if len(P.edges_of(faces[k])) > 4]
    assert len(sides) == 4 and len(holed) == 2 and copied == set()
    assert sorted(strips) == sorted(set(sides) - set(holed))
    for k in holed:
        tri, loc = P._triangulation(faces[k])
        lines = [e for e in P.edges_of(faces[k]) if BRepAdaptor_Curve(e).GetType() == GeomAbs_Line]
        assert len(lines) >= 2
        assert all(BRep_Tool.PolygonOnTriangulation_s(e, tri, loc).NbNodes() == 2 for e in lines)
    _closed_and_clean_in_float32(v, f)
    mesh = trimesh.Trimesh(v, f, process=False)
    assert d <= MESH_CHORD_LIMIT_MM and mesh.is_winding_consistent
    assert 0 < mesh.volume and abs(mesh.volume - solid.Volume()) <= d * solid.Area()


def test_prism_sides_meshed_apart_equal_the_strips_of_a_whole_pass():
    """The sides meshed apart (on the nodes the caps gave their edges) are the strips a whole BRepMesh pass gives, node
    for node: the same edges' discretisation either way."""
    solid = _spline_prism()
    shape = T.occ_shape(solid)
    T.mesh_shape(shape, 0.005, 0.1, False, MESH_CHORD_LIMIT_MM)
    whole = P.side_strips(shape)
    strips, _, _ = T._mesh_sides_apart(shape, 0.005, 0.1, False, False)
    assert sorted(strips) == sorted(whole)
    for k in strips:
        assert np.array_equal(strips[k][0], whole[k][0]) and np.array_equal(strips[k][1], whole[k][1])
        assert strips[k][2] == whole[k][2]


def _triangulated_without_twins(solid, monkeypatch):
    real = T._mesh_sides_apart
    with monkeypatch.context() as m:
        m.setattr(T, "_mesh_sides_apart", lambda shape, r, a, p, twins=True, **k: real(shape, r, a, p, False, **k))
        return T.triangulate(solid, parallel=False)


def test_a_prisms_second_cap_is_its_first_moved_node_for_node(monkeypatch):
    """The spline prism's top cap (its bore's circle and the spline's four edges, 12 mm above the bottom) is not meshed
    by BRepMesh: it is the bottom's triangulation moved up, and the mesh (nodes, triangles, reported deflection) is the
    one BRepMesh gives meshing both caps, to the bit; closed and clean."""
    solid = _spline_prism()
    shape = T.occ_shape(solid)
    twins = []
    real = P.cap_twins
    monkeypatch.setattr(P, "cap_twins", lambda *a: twins.append(real(*a)) or twins[-1])
    v, f, d = T.triangulate(solid, parallel=False)
    assert len(twins) == 1 and len(twins[0]) == 1
    (kb, (ka, t, pairs)), = twins[0].items()
    assert t.tolist() == [0.0, 0.0, 12.0] and len(pairs) == 5  # four spline edges and the bore's circle
    strips, _, copied = T._mesh_sides_apart(shape, 0.005, 0.1, False)
    assert copied == {kb} and kb in strips and ka not in strips
    v0, f0, d0 = _triangulated_without_twins(solid, monkeypatch)
    assert np.array_equal(v, v0) and np.array_equal(f, f0) and d == d0
    _closed_and_clean_in_float32(v, f)


def test_a_copied_cap_survives_its_neighbours_meshed_again(monkeypatch):
    """The spline prism's bore chamfered at both ends (45 deg cones, which miss the request and are meshed again
    alone): the caps are still twins, the top one copied, and the cones' second meshing leaves the bottom cap (and
    so the copy) as it was: the mesh is the one meshing both caps by BRepMesh gives, to the bit, within the limit."""
    solid = cq.Workplane().add(_spline_prism()).faces(">Z or <Z").edges("%CIRCLE").chamfer(2.5).val()
    shape = T.occ_shape(solid)
    _, _, copied = T._mesh_sides_apart(shape, 0.005, 0.1, False)
    assert len(copied) == 1
    refined = []
    refine_faces = T.refine_faces
    monkeypatch.setattr(T, "refine_faces", lambda *a, **k: refined.append(refine_faces(*a, **k)) or refined[-1])
    v, f, d = T.triangulate(solid, parallel=False)
    assert len(refined) == 1 and d <= MESH_CHORD_LIMIT_MM
    v0, f0, d0 = _triangulated_without_twins(solid, monkeypatch)
    assert np.array_equal(v, v0) and np.array_equal(f, f0) and d == d0
    _closed_and_clean_in_float32(v, f)


@pytest.mark.parametrize("shift, on_edges", [(2e-7, None), (3e-6, 1e-5)])
def test_a_cap_copy_off_its_edges_is_refused(monkeypatch, shift, on_edges):
    """A copy moved by 2e-7 mm off the top cap (beyond the 1e-7 mm its nodes must lie on the cap's edges within) is
    refused once the nodes are compared, and the caps are meshed by BRepMesh: the same mesh as without copies.  With
    the edges' tolerance widened to 1e-5 mm, a copy 3e-6 mm off is refused by the bore's band, whose own nodes on the
    top circle it would miss by more than the merge tolerance (1e-6 mm: the mesh would open there)."""
    solid = _spline_prism()
    real = P.cap_twins
    if on_edges is not None:
        monkeypatch.setattr(P, "STRIP_MATCH_MM", on_edges)

    def off(*a):
        return {kb: (ka, t + np.array([shift, 0.0, 0.0]), pairs) for kb, (ka, t, pairs) in real(*a).items()}

    monkeypatch.setattr(P, "cap_twins", off)
    shape = T.occ_shape(solid)
    strips, _, copied = T._mesh_sides_apart(shape, 0.005, 0.1, False)
    assert copied == set()
    v, f, d = T.triangulate(solid, parallel=False)
    v0, f0, d0 = _triangulated_without_twins(solid, monkeypatch)
    assert np.array_equal(v, v0) and np.array_equal(f, f0) and d == d0


def test_a_user_prism_counterbored_from_the_top_has_no_twin_caps():
    """A user's solid: the spline prism counterbored from the top (CadQuery ``cboreHole``).  The top cap's inner circle
    is the counterbore's, not the bore's moved up: no copy; the mesh is closed, clean, outward, and within the
    limit."""
    import trimesh

    solid = cq.Workplane().add(_spline_prism()).faces(">Z").workplane().cboreHole(10.0, 16.0, 4.0).val()
    shape = T.occ_shape(solid)
    faces = _faces(shape)
    assert P.cap_twins(faces, set()) == {}
    v, f, d = T.triangulate(solid, parallel=False)
    _closed_and_clean_in_float32(v, f)
    mesh = trimesh.Trimesh(v, f, process=False)
    assert d <= MESH_CHORD_LIMIT_MM and mesh.is_winding_consistent
    assert 0 < mesh.volume and abs(mesh.volume - solid.Volume()) <= d * solid.Area()


def _apart_recorded(monkeypatch):
    apart = []
    real = T._mesh_sides_apart
    monkeypatch.setattr(T, "_mesh_sides_apart", lambda *a, **k: apart.append(real(*a, **k)) or apart[-1])
    return apart


def test_a_located_prism_is_the_unlocated_ones_mesh_moved(monkeypatch):
    """The spline prism placed by a location (CadQuery ``moved``: turned 30 deg about z, shifted by (3, -2, 7) mm;
    its faces keep their geometry, their triangulations are stored in the prism's own frame): its sides are strips
    and its top cap a copy, as unlocated, and the mesh is the unlocated prism's moved, node for node within 1e-9 mm
    (the same triangles); closed and clean.  Before, a located face was left to BRepMesh (the cam plate's shifted
    core, meshed at 1.34 CPU s instead of 0.31)."""
    solid = _spline_prism()
    moved = solid.moved(cq.Location(cq.Vector(3.0, -2.0, 7.0), cq.Vector(0, 0, 1), 30.0))
    apart = _apart_recorded(monkeypatch)
    v, f, d = T.triangulate(moved, parallel=False)
    assert len(apart) == 1 and apart[0] is not None
    strips, _, copied = apart[0]
    assert len(copied) == 1 and len(strips) == len(_side_faces(T.occ_shape(solid))) + 1
    v0, f0, d0 = T.triangulate(solid, parallel=False)
    a = math.radians(30.0)
    R = np.array([[math.cos(a), -math.sin(a), 0.0], [math.sin(a), math.cos(a), 0.0], [0.0, 0.0, 1.0]])
    v0 = v0 @ R.T + [3.0, -2.0, 7.0]
    assert len(f) == len(f0) and abs(d - d0) <= 1e-9
    # the same triangles: each one's corners, as sorted rows, match
    key = lambda V, F: np.sort(np.round(V[F].reshape(len(F), 9), 6), axis=0)
    assert np.abs(key(v, f) - key(v0, f0)).max() <= 1e-6
    _closed_and_clean_in_float32(v, f)


def test_a_plate_fused_with_a_located_prism_has_its_sides_as_strips(monkeypatch):
    """A plate fused with a prism placed on it by a location (as the cam's plate and its raised core are,
    ``kernel.shifted_z``): the located prism's side faces are strips on the nodes the plate's and its own cap's
    triangulations give their edges (placed by their faces' locations); the mesh is closed, clean, outward, within
    the limit, and holds the solid's volume."""
    import trimesh

    core = _spline_prism().moved(cq.Location(cq.Vector(0.0, 0.0, 6.0)))
    solid = cq.Workplane("XY").circle(45.0).extrude(6.0).union(cq.Workplane().add(core)).val()
    shape = T.occ_shape(solid)
    located = [f for f in _side_faces(shape) if not f.Location().IsIdentity()]
    assert len(located) == 4
    apart = _apart_recorded(monkeypatch)
    v, f, d = T.triangulate(solid, parallel=False)
    assert len(apart) == 1 and apart[0] is not None and len(apart[0][0]) >= 4
    _closed_and_clean_in_float32(v, f)
    mesh = trimesh.Trimesh(v, f, process=False)
    assert d <= MESH_CHORD_LIMIT_MM and mesh.is_winding_consistent
    assert 0 < mesh.volume and abs(mesh.volume - solid.Volume()) <= d * solid.Area()


def test_a_user_prism_chamfered_at_its_top_is_meshed_within_the_limit():
    """A user's solid: the spline prism with its top outline chamfered (CadQuery ``chamfer(1.0)``: four B-spline
    chamfer faces, and so no strips).  BRepMesh reports 0.0296 mm at the request, 0.0388 once its faces that miss
    the limit are meshed again, 0.0335 at half the request: each halving's faces that miss the limit are meshed
    again too (0.0053 mm at half the request), where halving alone reached 0.047 mm (222 854 triangles) and failed
    the limit.  The mesh is closed, clean, outward, holds the volume, and its triangles (their centroids and edge
    midpoints, 800 of them) lie within the limit of the solid's surfaces, measured by OCCT's projection."""
    import trimesh

    solid = cq.Workplane().add(_spline_prism()).faces(">Z").edges("not %CIRCLE").chamfer(1.0).val()
    v, f, d = T.triangulate(solid, parallel=False)
    assert d <= MESH_CHORD_LIMIT_MM
    _closed_and_clean_in_float32(v, f)
    mesh = trimesh.Trimesh(v, f, process=False)
    assert mesh.is_winding_consistent and 0 < mesh.volume
    assert abs(mesh.volume - solid.Volume()) <= d * solid.Area()
    faces = _faces(T.occ_shape(solid))
    pick = np.random.default_rng(5).choice(len(f), 800, replace=False)
    B = np.array([(1 / 3, 1 / 3, 1 / 3), (0.5, 0.5, 0.0)])
    X = np.einsum("bk,tkd->tbd", B, v[f[pick]]).reshape(-1, 3)
    dist = _distance_to_faces(X, faces)
    assert dist.max() <= MESH_CHORD_LIMIT_MM


def test_the_faces_beside_an_edge_are_the_maps_list_in_its_order():
    """:func:`propulsor.solids.prism_mesh.faces_beside` (a list's ends read directly) gives the faces OCP's iteration
    over TopExp's edge-to-faces map gives, in the same order, at every edge of the spline prism and of a filleted
    CadQuery union."""
    from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE
    from OCP.TopExp import TopExp
    from OCP.TopTools import TopTools_IndexedDataMapOfShapeListOfShape

    union = cq.Workplane("XY").rect(40, 20).extrude(10).edges("|Z").fillet(3.0) \
        .union(cq.Workplane("XY").center(15, 0).circle(12).extrude(16)).val()
    for solid in (_spline_prism(), union):
        shape = T.occ_shape(solid)
        beside = TopTools_IndexedDataMapOfShapeListOfShape()
        TopExp.MapShapesAndAncestors_s(shape, TopAbs_EDGE, TopAbs_FACE, beside)
        sizes = set()
        for i in range(1, beside.Extent() + 1):
            edge = beside.FindKey(i)
            theirs, ours = list(beside.FindFromKey(edge)), P.faces_beside(beside, edge)
            sizes.add(len(theirs))
            assert len(ours) == len(theirs)
            assert all(a.IsEqual(b) for a, b in zip(ours, theirs))
        assert 2 in sizes


def test_equal_rows_is_numpys_row_unique_with_its_inverse():
    """``_equal_rows`` (one lexicographic sort of the columns) against ``np.unique(v, axis=0, return_inverse=True)``:
    the distinct rows in the same order and each row's index among them, on arrays full of repeated rows, of one to
    three columns, with 0.0 and -0.0 (equal, as numpy has them); an array with a NaN is numpy's own answer.  And
    merge_close_vertices on a triangle soup (every vertex written once per face, as an STL holds it) gives a mesh
    whose vertices are distinct and whose faces are the soup's."""
    rng = np.random.default_rng(11)
    for _ in range(300):
        v = rng.integers(-2, 3, size=(int(rng.integers(1, 60)), int(rng.integers(1, 4)))).astype(float)
        v[rng.random(v.shape) < 0.3] *= -1.0  # signed zeros
        u, inv = np.unique(v, axis=0, return_inverse=True)
        u2, inv2 = T._equal_rows(v)
        assert u2.shape == u.shape and np.array_equal(u2, u) and inv2.tolist() == inv.reshape(-1).tolist()
    v = np.array([[0.0, -0.0, 1.0], [-0.0, 0.0, 1.0], [1.0, 2.0, 3.0], [0.5, 9.0, 1.0], [1.0, 2.0, 3.0]])
    u, inv = T._equal_rows(v)
    assert u.tolist() == [[0.0, 0.0, 1.0], [0.5, 9.0, 1.0], [1.0, 2.0, 3.0]] and inv.tolist() == [0, 0, 2, 1, 2]
    w = np.array([[np.nan, 1.0], [0.0, 1.0], [0.0, 1.0]])
    u, inv = T._equal_rows(w)
    un, invn = np.unique(w, axis=0, return_inverse=True)
    assert np.array_equal(u, un, equal_nan=True) and inv.tolist() == invn.reshape(-1).tolist()
    # a cube's 12 triangles as a soup of 36 vertices: 8 vertices, the same triangles
    import trimesh

    box = trimesh.creation.box((2.0, 3.0, 4.0))
    soup = box.vertices[box.faces.reshape(-1)]
    nv, nf = T.merge_close_vertices(soup, np.arange(len(soup)).reshape(-1, 3))
    assert len(nv) == 8 and np.array_equal(nv[nf], box.vertices[box.faces])


def _triangles(v, f) -> set:
    """The triangles as sets of their corners' coordinates (independent of the vertices' order)."""
    return {frozenset(map(tuple, v[t].tolist())) for t in f}


def _watson(solid, monkeypatch):
    """The mesh with every face BRepMesh meshes triangulated by its default algorithm (Watson's)."""
    with monkeypatch.context() as m:
        m.setattr(T, "_planes_left", lambda shape: False)
        return T.triangulate(solid, parallel=False)


def test_a_prisms_cap_is_delabellas_on_the_nodes_watson_gets(monkeypatch):
    """The spline prism's bottom cap (four spline edges and the bore's circle) is triangulated by BRepMesh's Delabella
    algorithm: the mesh has the nodes of Watson's, as many triangles, the same ones off the caps and other ones on
    them; closed, clean in float32, its volume Watson's to 1e-12 relative."""
    from propulsor.checks.mesh import signed_volume

    solid = _spline_prism()
    algos = []
    real = T.BRepMesh_IncrementalMesh
    monkeypatch.setattr(T, "BRepMesh_IncrementalMesh", lambda s, p: algos.append(p.MeshAlgo) or real(s, p))
    v, f, d = T.triangulate(solid, parallel=False)
    assert algos.count(T.IMeshTools_MeshAlgoType_Delabella) == 1
    v0, f0, d0 = _watson(solid, monkeypatch)
    assert np.array_equal(np.unique(v, axis=0), np.unique(v0, axis=0)) and len(f) == len(f0) and d == d0
    ours, theirs = _triangles(v, f), _triangles(v0, f0)
    on_caps = lambda tris: {t for t in tris if all(abs(p[2]) < 1e-9 or abs(p[2] - 12.0) < 1e-9 for p in t)}
    assert ours - on_caps(ours) == theirs - on_caps(theirs) and on_caps(ours) != on_caps(theirs)
    _closed_and_clean_in_float32(v, f)
    assert signed_volume(v, f) == pytest.approx(signed_volume(v0, f0), rel=1e-12)


def test_a_plane_delabella_leaves_bare_has_the_rest_meshed_by_watson(monkeypatch):
    """Where the Delabella pass leaves a planar face without a triangulation (as it left extrusions' faces, which it is
    not given), the faces it was given are meshed again by Watson's: the mesh is Watson's, to the bit.  Both caps
    meshed by BRepMesh (no copy), one of them left bare: the other is not kept as Delabella made it."""
    solid = _spline_prism()
    real_apart = T._mesh_sides_apart
    monkeypatch.setattr(T, "_mesh_sides_apart", lambda shape, r, a, p, twins=True, **k: real_apart(shape, r, a, p, False,
                                                                                                  **k))
    v0, f0, d0 = _watson(solid, monkeypatch)
    real = T.BRepMesh_IncrementalMesh

    def failing(s, p):
        done = real(s, p)
        if p.MeshAlgo == T.IMeshTools_MeshAlgoType_Delabella:
            T.BRepTools.Clean_s(next(f for f in _faces(s) if T.BRepAdaptor_Surface(f).GetType() == T.GeomAbs_Plane))
        return done

    monkeypatch.setattr(T, "BRepMesh_IncrementalMesh", failing)
    v, f, d = T.triangulate(solid, parallel=False)
    assert np.array_equal(v, v0) and np.array_equal(f, f0) and d == d0


def test_cap_edges_are_paired_as_the_full_comparison_pairs_them():
    """`prism_mesh._one_to_one` (a k-d tree's candidates, each tested as before) gives the pairs of the full (n, n)
    comparison of the edges' nine coordinates within the tolerance, or None where that has a row or a column
    without exactly one: permuted copies, a copy a hair inside and a hair outside the tolerance, two edges within
    the tolerance of one."""
    rng = np.random.default_rng(7)
    tol = P.STRIP_MATCH_MM

    def full(Kb, Ka):
        close = np.abs(Kb[:, None, :] - Ka[None, :, :]).max(axis=2) <= tol
        ok = (close.sum(axis=1) == 1).all() and (close.sum(axis=0) == 1).all()
        return close.argmax(axis=1) if ok else None

    Ka = rng.uniform(-50.0, 50.0, (400, 9))
    perm = rng.permutation(400)
    cases = []
    for dev in (0.0, 0.999 * tol, 1.001 * tol, tol + 5e-13):  # the last within the tree's wider radius
        Kb = Ka[perm].copy()
        Kb[17, 4] += dev
        cases.append(Kb)
    Kb = Ka[perm].copy()
    Kb[5] = Kb[6] + 0.5 * tol  # two edges of B within the tolerance of one of A
    cases.append(Kb)
    Ka_close = Ka.copy()
    Ka_close[perm[9]] = Ka_close[perm[10]] + 0.5 * tol  # two of A within the tolerance of one of B
    for Kb in cases + [Ka[perm]]:
        for A in (Ka, Ka_close):
            want, got = full(Kb, A), P._one_to_one(Kb, A, tol)
            assert (want is None) == (got is None) and (want is None or np.array_equal(want, got))
    assert P._one_to_one(cases[0], Ka, tol) is not None and P._one_to_one(cases[2], Ka, tol) is None
    assert P._one_to_one(cases[3], Ka, tol) is None and P._one_to_one(cases[4], Ka, tol) is None
    assert P._one_to_one(Ka[perm], Ka_close, tol) is None
