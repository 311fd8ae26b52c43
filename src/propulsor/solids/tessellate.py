"""Tessellation of OCCT solids (part of the kernel adapter, see :mod:`propulsor.solids.kernel`).

The chord error (linear deflection) is policy.CHORD_TOL_MM, the angular deflection
policy.ANGULAR_TOL_RAD.  OCCT's BRepMesh discretises every edge once and shares it between the
two faces, so after merging coincident nodes (KD-tree, POINT_TOL-scale radius) the triangle mesh
of a closed solid is closed.  A prism's sides and second cap are not BRepMesh's: they are made from the nodes the
other faces give their edges (:mod:`propulsor.solids.prism_mesh`).
"""

from __future__ import annotations

import numpy as np
from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.GeomAbs import GeomAbs_Cone, GeomAbs_Cylinder, GeomAbs_Plane, GeomAbs_Sphere, GeomAbs_SurfaceOfExtrusion
from OCP.IMeshTools import IMeshTools_MeshAlgoType_Delabella, IMeshTools_Parameters
from OCP.BRepMesh import BRepMesh_IncrementalMesh
from OCP.BRepTools import BRepTools
from OCP.TopAbs import TopAbs_FACE, TopAbs_REVERSED
from OCP.TopExp import TopExp_Explorer
from OCP.TopLoc import TopLoc_Location
from OCP.TopoDS import TopoDS
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from ..geometry.rows import row_ids
from ..policy import ANGULAR_TOL_RAD, CHORD_TOL_MM, MERGE_TOL_MM, MESH_CHORD_LIMIT_MM
from . import prism_mesh
from .kernel import occ_shape

__all__ = ["MERGE_TOL_MM", "merge_close_vertices", "mesh_shape", "triangulate"]


def _equal_rows(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(v, axis=0, return_inverse=True)`` of an (n, k) float array, n >= 1 (:func:`.geometry.rows.row_ids`);
    an array with a NaN goes to numpy itself."""
    if not np.all(np.isfinite(v)):
        u, inv = np.unique(v, axis=0, return_inverse=True)
        return u, inv.reshape(-1)
    first, inv = row_ids(v)
    return v[first], inv


def merge_close_vertices(vertices: np.ndarray, faces: np.ndarray, tol: float = MERGE_TOL_MM,
                         max_pairs: int | None = None):
    """Merge vertices closer than `tol` (transitively); drop faces that collapse.

    Returns (vertices, faces) with vertices in order of first appearance so the
    result does not depend on hashing.  Equal vertices are merged first (a stack of equal
    vertices costs no pairs); with `max_pairs`, more close pairs of distinct points than that
    raise ValueError before they are listed.
    """
    v = np.asarray(vertices, float)
    f = np.asarray(faces, np.int64)
    n = len(v)
    if n:
        u, inv = _equal_rows(v)
    else:
        u, inv = v, np.arange(0)
    tree = cKDTree(u)
    if max_pairs is not None and len(u) and (int(tree.count_neighbors(tree, tol)) - len(u)) // 2 > max_pairs:
        raise ValueError(f"more than {max_pairs} pairs of vertices closer than {tol} mm")
    pairs = tree.query_pairs(tol, output_type="ndarray")
    if len(pairs):
        g = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(len(u), len(u)))
        _, label = connected_components(g, directed=False)
        label = label[inv]
    else:
        label = inv
    # representative = first vertex of each component, in index order
    _, first = np.unique(label, return_index=True)
    order = np.argsort(first)
    comp_new = np.empty(len(first), np.int64)
    comp_new[order] = np.arange(len(first))
    remap = comp_new[label]
    nv = v[np.sort(first)]
    nf = remap[f]
    keep = (nf[:, 0] != nf[:, 1]) & (nf[:, 1] != nf[:, 2]) & (nf[:, 0] != nf[:, 2])
    nf = nf[keep]
    used = np.zeros(len(nv), bool)
    used[nf.ravel()] = True
    if not used.all():
        idx = np.cumsum(used) - 1
        nf = idx[nf]
        nv = nv[used]
    return nv, nf


#: surfaces swept by straight lines: their exact triangulation needs no interior nodes
_RULED = (GeomAbs_Plane, GeomAbs_Cylinder, GeomAbs_Cone, GeomAbs_SurfaceOfExtrusion)


def _ruled_only(shape) -> bool:
    """True when every face lies on a plane, cylinder, cone or linear extrusion (a prism of a
    profile, a bored disc): strips between the edges' discretisations are then within the chord
    tolerance of the surface, and BRepMesh's interior nodes only add slivers."""
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        if BRepAdaptor_Surface(TopoDS.Face_s(ex.Current())).GetType() not in _RULED:
            return False
        ex.Next()
    return True


def _boundary_nodes_only(face) -> bool:
    """Whether every node of the face's triangulation lies on the border of its parameter rectangle (a
    cylinder band between two circles and its seam: no interior node)."""
    tri = BRep_Tool.Triangulation_s(face, TopLoc_Location())
    if tri is None or not tri.HasUVNodes():
        return False
    uv = np.array([tri.UVNode(i).Coord() for i in range(1, tri.NbNodes() + 1)])
    lo, hi = uv.min(axis=0), uv.max(axis=0)
    tol = 1e-9 * (1.0 + np.abs(uv).max())
    on_border = (np.abs(uv - lo) <= tol).any(axis=1) | (np.abs(uv - hi) <= tol).any(axis=1)
    return bool(on_border.all())


def _premesh_cylinders(shape, prm) -> None:
    """Triangulate the cylindrical faces one by one with interior vertices allowed (OCCT inserts none on a
    cylinder band: the same nodes, about 25 times faster than without: 0.45 -> 0.017 s for a rim band of
    1 476 nodes); a face that got interior nodes is cleared for the whole shape's pass.  The edges keep the
    discretisation of the whole shape's pass, so the neighbouring faces are meshed as before."""
    cyl = IMeshTools_Parameters()
    cyl.Deflection, cyl.Angle, cyl.Relative, cyl.InParallel = prm.Deflection, prm.Angle, False, False
    cyl.InternalVerticesMode, cyl.ControlSurfaceDeflection = True, False
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        ex.Next()
        if BRepAdaptor_Surface(face).GetType() != GeomAbs_Cylinder:
            continue
        if not BRepMesh_IncrementalMesh(face, cyl).IsDone() or not _boundary_nodes_only(face):
            BRepTools.Clean_s(face)


def _params(chord_tol, angular_tol, parallel, ruled: bool) -> IMeshTools_Parameters:
    """BRepMesh's parameters: absolute deflection and angle; a shape of ruled faces only without interior vertices and
    without the surface deflection control (its strips between the edges' nodes are within the chord)."""
    prm = IMeshTools_Parameters()
    prm.Deflection, prm.Angle, prm.Relative, prm.InParallel = chord_tol, angular_tol, False, parallel
    if ruled:
        prm.InternalVerticesMode = False
        prm.ControlSurfaceDeflection = False
    return prm


def mesh_shape(shape, chord_tol, angular_tol, parallel, chord_limit: float | None = None) -> float:
    """Run BRepMesh; return the largest achieved deflection (mm, :func:`_worst_deflection`: measured on a
    face with a degenerate edge when `chord_limit` is given).  A shape of ruled faces only is meshed without
    interior vertices, its cylinder bands first (:func:`_premesh_cylinders`)."""
    BRepTools.Clean_s(shape)
    ruled = _ruled_only(shape)
    prm = _params(chord_tol, angular_tol, parallel, ruled)
    if ruled:
        _premesh_cylinders(shape, prm)
    mesher = BRepMesh_IncrementalMesh(shape, prm)
    if not mesher.IsDone():
        raise RuntimeError("BRepMesh failed")
    return _worst_deflection(shape, chord_limit)


def _bare_faces(shape):
    """The faces of `shape` without a triangulation, in the explorer's order."""
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        ex.Next()
        if BRep_Tool.Triangulation_s(face, TopLoc_Location()) is None:
            yield face


def _planes_left(shape) -> bool:
    """Whether every face of `shape` without a triangulation lies on a plane."""
    return all(BRepAdaptor_Surface(face).GetType() == GeomAbs_Plane for face in _bare_faces(shape))


def _mesh_sides_apart(shape, request, angular_tol, parallel, twins: bool = True, ruled: bool = True):
    """:func:`propulsor.solids.prism_mesh.mesh_sides_apart` with BRepMesh meshing the faces that are not a prism's
    sides or second caps as :func:`mesh_shape` meshes the shape (``ruled``: cylinder bands first, no interior
    vertices).  Where the faces left after the cylinder bands are planes without interior vertices (a prism's first
    cap, a keyway's flats: every gear), BRepMesh triangulates them by its Delabella algorithm instead of its default
    (Watson's): the same nodes (the edges are discretised before either runs), as many triangles over the same plane
    region, about half the time (``bench/bench_tessellate.py``).  A face it leaves without a triangulation (it
    failed on extrusions' faces, which are not given to it) has them all meshed again by the default."""
    prm = _params(request, angular_tol, parallel, ruled)

    def mesh_rest(rest):
        if ruled:
            _premesh_cylinders(rest, prm)
            if _planes_left(rest):
                planar = _params(request, angular_tol, parallel, ruled)
                planar.MeshAlgo = IMeshTools_MeshAlgoType_Delabella
                if BRepMesh_IncrementalMesh(rest, planar).IsDone() and next(_bare_faces(rest), None) is None:
                    return
                BRepTools.Clean_s(rest)
                _premesh_cylinders(rest, prm)
        if not BRepMesh_IncrementalMesh(rest, prm).IsDone():
            raise RuntimeError("BRepMesh failed")

    return prism_mesh.mesh_sides_apart(shape, mesh_rest, twins)


def refine_faces(shape, chord_tol, angular_tol, parallel, chord_limit) -> float:
    """Mesh again only the faces of a meshed shape whose achieved deflection exceeds `chord_limit`, with
    the surface deflection controlled on them although they are analytic (OCCT controls it on free-form
    faces only: a cone between two differently divided circles misses the request several times over)
    and no element below `chord_limit` (finer ones fold at a cone's apex).  The edges keep their
    discretisation (the neighbours' triangulations share it), so the mesh stays closed.  A face with a
    degenerate edge (a cone's apex, a sphere's pole) is left as it is: the nodes inserted there crowd
    into slivers that fold once the mesh is written in single precision (STL), and the caller's halving
    takes it on (its deflection measured: :func:`_apex_deflection`).  A face placed twice in a compound (one
    solid at two places) shares its triangulation: cleared at its first place, it is not looked at again at the
    second.  Returns the largest achieved deflection."""
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        tri = BRep_Tool.Triangulation_s(face, TopLoc_Location())
        if tri is not None and tri.Deflection() > chord_limit and not _has_apex(face):
            BRepTools.Clean_s(face)
        ex.Next()
    prm = IMeshTools_Parameters()
    prm.Deflection, prm.Angle, prm.Relative, prm.InParallel = chord_tol, angular_tol, False, parallel
    prm.EnableControlSurfaceDeflectionAllSurfaces = True
    prm.MinSize = chord_limit
    if not BRepMesh_IncrementalMesh(shape, prm).IsDone():
        raise RuntimeError("BRepMesh failed")
    return _worst_deflection(shape, chord_limit)


def _has_apex(face) -> bool:
    """Whether the face has a degenerate edge (a point of its surface that an edge collapses to)."""
    return prism_mesh.edges_of(face) is None


#: barycentric samples per triangle side where a triangulation's distance from its surface is measured
_APEX_SAMPLES = 12


def _apex_deflection(face) -> float | None:
    """The largest distance of a cone's or a sphere's face triangulation from its exact surface (mm), measured
    at its nodes and at (n+1)(n+2)/2 barycentric points of every triangle (n = _APEX_SAMPLES); None for
    other surfaces.

    OCCT estimates a face's deflection in the surface's parameter plane, where the nodes of a degenerate
    edge (a cone's apex, a sphere's pole) are distinct points: the triangles of a fan to the apex span a
    wide range of u there, and the estimate (the surface point at a triangle's parameter centroid against
    the triangle's centroid) misses the flat triangle by far more than the triangle misses the surface —
    the balancer's 118° drill point: 0.0205 mm reported at a request of 0.005 mm, 0.0022 mm measured.
    The distance from a point to a cone or a sphere is closed-form."""
    ad = BRepAdaptor_Surface(face)
    kind = ad.GetType()
    if kind not in (GeomAbs_Cone, GeomAbs_Sphere):
        return None
    loc = TopLoc_Location()
    tri = BRep_Tool.Triangulation_s(face, loc)
    P, T = prism_mesh.nodes_of(tri, loc), prism_mesh.triangles_of(tri)
    n = _APEX_SAMPLES
    ij = np.array([(i, j) for i in range(n + 1) for j in range(n + 1 - i)], float) / n
    B = np.column_stack([ij, 1.0 - ij.sum(axis=1)])
    X = np.vstack([P, np.einsum("bk,tkd->tbd", B, P[T]).reshape(-1, 3)])
    if kind == GeomAbs_Sphere:
        sph = ad.Sphere()
        c = np.array(sph.Location().Coord())
        return float(np.abs(np.linalg.norm(X - c, axis=1) - sph.Radius()).max())
    cone = ad.Cone()
    ax = cone.Axis()
    o, e = np.array(ax.Location().Coord()), np.array(ax.Direction().Coord())
    a = cone.SemiAngle()
    v = X - o
    h = v @ e
    rho = np.linalg.norm(v - np.outer(h, e), axis=1)
    # in the meridian half-plane the cone is the line r = R + h tan a; distance to it (both sides of the apex
    # lie on the surface's own nappe as long as R + h tan a >= 0, which holds on the face)
    return float(np.abs((rho - (cone.RefRadius() + h * np.tan(a))) * np.cos(a)).max())


def _worst_deflection(shape, chord_limit: float | None = None, strips=None) -> float:
    """The largest achieved deflection of a meshed shape: OCCT's own per face, except (when a `chord_limit`
    is given: the meshing of the files) on a cone's or a sphere's face with a degenerate edge, where OCCT's
    estimate is unreliable: measured there (:func:`_apex_deflection`); on a prism's side meshed as strips
    (``strips``, by face index), the strips' own (:func:`propulsor.solids.prism_mesh.side_strip`)."""
    worst = 0.0
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    k = 0
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        if strips and k in strips:
            d = strips[k][2]
        else:
            tri = BRep_Tool.Triangulation_s(face, TopLoc_Location())
            if tri is None:
                raise RuntimeError("a face has no triangulation")
            d = float(tri.Deflection())
            if chord_limit is not None and _has_apex(face):
                measured = _apex_deflection(face)
                d = d if measured is None else measured
        worst = max(worst, d)
        ex.Next()
        k += 1
    return worst


def triangulate(
    solid,
    chord_tol: float = CHORD_TOL_MM,
    angular_tol: float = ANGULAR_TOL_RAD,
    parallel: bool = True,
    chord_limit: float = MESH_CHORD_LIMIT_MM,
):
    """Mesh an OCCT shape; return (vertices (n,3), faces (m,3), deflection_mm).

    BRepMesh aims at `chord_tol`; on curved faces the deflection it achieves can
    exceed the request (a chamfer cone between two differently divided circles).  The
    faces whose achieved deflection exceeds `chord_limit` are meshed again at the same
    request with their surface deflection controlled (:func:`refine_faces`); while it
    still exceeds the limit, the whole shape is meshed again with half the request (at
    most 4 times), each time with the same refinement.  A prism's sides and second cap
    are made from their edges' nodes (:mod:`propulsor.solids.prism_mesh`).  The returned
    deflection is that reported by OCCT, except on a cone or sphere face with a degenerate
    edge: there it is measured against the exact surface (:func:`_apex_deflection`; OCCT's
    estimate can be far off at an apex: a cone r = 8, h = 5 mm meshed at 0.005 mm reports
    0.0205 mm, measured 0.0023 mm; the balancer's drill point 0.0205 mm, measured 0.0022 mm;
    on a sphere it is right).
    """
    if not (chord_tol > 0 and angular_tol > 0):
        raise ValueError(f"chord_tol = {chord_tol!r}, angular_tol = {angular_tol!r}: must be > 0")
    shape = occ_shape(solid)
    request = chord_tol

    ruled = _ruled_only(shape)

    def meshed(request):
        """(achieved deflection, strips and copied caps, the other faces meshed apart or None): the shape meshed at
        `request`, then the faces that miss the limit meshed again alone (:func:`refine_faces`).  The edges keep their
        nodes there, and so the strips on them hold; a copied cap's first cap is a plane (its deflection nil), which
        refine_faces leaves as it is, and so the copy holds too."""
        apart = _mesh_sides_apart(shape, request, angular_tol, parallel, ruled=ruled)
        if apart is not None:
            strips, rest, _ = apart
            achieved = _worst_deflection(shape, chord_limit, strips)
        else:  # no prism side
            strips, rest = {}, None
            achieved = mesh_shape(shape, request, angular_tol, parallel, chord_limit)
        if achieved > chord_limit:
            achieved = max([refine_faces(shape if rest is None else rest, request, angular_tol, parallel, chord_limit)]
                           + [st[2] for st in strips.values()])
        return achieved, strips, rest

    # each halving's mesh has its faces that miss the limit meshed again too: a user's spline prism with a chamfered
    # top edge (B-spline chamfer faces, and so no strips) reports 0.0296 mm at 0.005, 0.0388 once refined, 0.0335
    # at 0.0025 and 0.0053 once refined; halved without refining, it reached 0.047 mm at 0.0003 (222 854 triangles,
    # 8.5 CPU s) and failed the limit
    achieved, strips, rest = meshed(request)
    for _ in range(4):
        if achieved <= chord_limit:
            break
        request *= 0.5
        achieved, strips, rest = meshed(request)
    verts, tris = [], []
    offset = 0
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    k = -1
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        k += 1
        ex.Next()
        if k in strips:  # a prism's side: its strips, on its edges' nodes (prism_mesh.side_strip)
            pts, ids = strips[k][0], strips[k][1]
        else:
            loc = TopLoc_Location()
            tri = BRep_Tool.Triangulation_s(face, loc)
            pts, ids = prism_mesh.nodes_of(tri, loc), prism_mesh.triangles_of(tri)
        if face.Orientation() == TopAbs_REVERSED:
            ids = ids[:, [0, 2, 1]]
        verts.append(pts)
        tris.append(ids + offset)
        offset += len(pts)
    if not verts:
        raise ValueError("shape has no faces")
    v, f = merge_close_vertices(np.vstack(verts), np.vstack(tris))
    return v, f, achieved
