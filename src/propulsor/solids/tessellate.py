"""Tessellation of OCCT solids (part of the kernel adapter, see :mod:`propulsor.solids.kernel`).

The chord error (linear deflection) is policy.CHORD_TOL_MM, the angular deflection
policy.ANGULAR_TOL_RAD.  OCCT's BRepMesh discretises every edge once and shares it between the
two faces, so after merging coincident nodes (KD-tree, POINT_TOL-scale radius) the triangle mesh
of a closed solid is closed.
"""

from __future__ import annotations

import math

import numpy as np
from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Curve2d, BRepAdaptor_Surface
from OCP.BRepGProp import BRepGProp_Face
from OCP.GeomAbs import GeomAbs_Cone, GeomAbs_Cylinder, GeomAbs_Line, GeomAbs_Plane, GeomAbs_Sphere, GeomAbs_SurfaceOfExtrusion
from OCP.IMeshTools import IMeshTools_Parameters
from OCP.BRepMesh import BRepMesh_IncrementalMesh
from OCP.BRepTools import BRepTools
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE, TopAbs_REVERSED
from OCP.TopExp import TopExp, TopExp_Explorer
from OCP.TopLoc import TopLoc_Location
from OCP.TopoDS import TopoDS
from OCP.gp import gp_Pnt, gp_Vec
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from ..geometry.rows import row_ids
from ..policy import ANGULAR_TOL_RAD, CHORD_TOL_MM, MESH_CHORD_LIMIT_MM
from .kernel import occ_shape

__all__ = ["MERGE_TOL_MM", "merge_close_vertices", "mesh_shape", "triangulate"]

#: nodes of different faces closer than this are the same node (mm)
MERGE_TOL_MM = 1e-6


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


#: two nodes of a prism's side face are one above the other when their offset is off the extrusion's line by less
#: than this (mm)
_STRIP_MATCH_MM = 1e-7


def _cross(a, b) -> np.ndarray:
    """a x b of two (n, 3) arrays row by row: numpy's formula (``np.cross``), without its axis handling (0.1 ms a call,
    a fifth of a prism side's strips)."""
    return np.column_stack([a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1], a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
                            a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]])


def _edges(face) -> list | None:
    """The face's edges in the explorer's order, or None if one is degenerate (a cone's apex, a sphere's pole)."""
    out = []
    ex = TopExp_Explorer(face, TopAbs_EDGE)
    while ex.More():
        edge = TopoDS.Edge_s(ex.Current())
        ex.Next()
        if BRep_Tool.Degenerated_s(edge):
            return None
        out.append(edge)
    return out


def _strip(face, polygon) -> tuple[np.ndarray, np.ndarray, float] | None:
    """The triangles of a prism's side face (a linear extrusion of a curve bounded by two copies of the curve's edge
    and two straight edges along the extrusion) as strips between its two curve edges' nodes, node i of the one
    under node i of the other, and their largest distance from the face (mm); None for any other face.
    ``polygon(edge)``: (nodes (n, 3), their parameters on the edge) of an edge's discretisation (the face's own
    triangulation's, or a neighbour's), None if it has none.

    BRepMesh triangulates such a face without interior nodes, but its diagonals join nodes that are not above one
    another: a triangle then cuts across the curve (0.0188 mm from the face of a gear's flank at a request of
    0.005 mm), and the face is meshed again with interior nodes (half as many triangles more).  A strip between
    matching nodes lies in the plane of a chord and the extrusion's direction, which holds the face's rulings: its
    distance from the face is the chord's from the curve, measured here at a quarter, half and three quarters of
    every chord's parameter interval.  The strips use the nodes of the face's edges only, which its neighbours
    share, so the mesh stays closed.  Returns (nodes (2n, 3), triangles (m, 3) into them, oriented as the surface's
    own parameters (as a face triangulation's are), deflection)."""
    ad = BRepAdaptor_Surface(face)
    if ad.GetType() != GeomAbs_SurfaceOfExtrusion or not face.Location().IsIdentity():
        return None
    dd = ad.Direction().Coord()
    d = np.array(dd)
    curves, lines = [], []
    edges = _edges(face)
    if edges is None:
        return None
    for edge in edges:
        cad = BRepAdaptor_Curve(edge)
        if cad.GetType() == GeomAbs_Line:
            u = cad.Line().Direction().Coord()
            if math.hypot(u[1] * dd[2] - u[2] * dd[1], u[2] * dd[0] - u[0] * dd[2], u[0] * dd[1] - u[1] * dd[0]) > 1e-12:
                return None  # a straight edge across the rulings
            lines.append((cad.Value(cad.FirstParameter()).Coord(), cad.Value(cad.LastParameter()).Coord()))
            continue
        got = polygon(edge)
        if got is None:
            return None
        curves.append((got[0], got[1], cad, edge))
    if len(curves) != 2 or len(lines) != 2 or len(curves[0][0]) != len(curves[1][0]) or len(curves[0][0]) < 2:
        return None
    (A, pa, cad, edge), (B, _, _, _) = curves
    if np.linalg.norm(B[0] - A[0] - np.dot(B[0] - A[0], d) * d) > _STRIP_MATCH_MM:
        B = B[::-1]
    off = B - A
    h = off @ d
    if np.abs(off - np.outer(h, d)).max() > _STRIP_MATCH_MM or np.abs(h - h[0]).max() > _STRIP_MATCH_MM:
        return None
    # the straight edges join the curve edges' ends, and nothing else (a divided one: its inner nodes are the mate's)
    for p, q in ((A[0].tolist(), B[0].tolist()), (A[-1].tolist(), B[-1].tolist())):
        if not any(min(math.dist(a, p) + math.dist(b, q), math.dist(a, q) + math.dist(b, p)) <= _STRIP_MATCH_MM
                   for a, b in lines):
            return None
    n = len(A)
    P = np.vstack([A, B])
    i = np.arange(n - 1)
    tris = np.concatenate([np.column_stack([i, i + 1, n + i + 1]), np.column_stack([i, n + i + 1, n + i])])
    # orientation: along the face's normal (BRepGProp_Face: reversed with the face) at every chord's middle, turned
    # back for a reversed face (the caller turns a reversed face's triangles)
    gf, c2 = BRepGProp_Face(face), BRepAdaptor_Curve2d(edge, face)
    nrm = []
    for t in 0.5 * (pa[:-1] + pa[1:]):
        uv, pnt, vec = c2.Value(float(t)), gp_Pnt(), gp_Vec()
        gf.Normal(uv.X(), uv.Y(), pnt, vec)
        nrm.append(vec.Coord())
    own = _cross(P[tris[:n - 1, 1]] - P[tris[:n - 1, 0]], P[tris[:n - 1, 2]] - P[tris[:n - 1, 0]])
    agree = float(np.einsum("ij,ij->i", own, np.array(nrm)).sum())
    if (agree < 0) != (face.Orientation() == TopAbs_REVERSED):
        tris = tris[:, [0, 2, 1]]
    # the chord's distance from the curve edge at 1/4, 1/2, 3/4 of every interval
    fr = np.array([0.25, 0.5, 0.75])
    t = (pa[:-1, None] + fr[None, :] * np.diff(pa)[:, None]).ravel()
    Q = np.array([cad.Value(float(x)).Coord() for x in t]).reshape(-1, 3, 3)
    a0, a1 = A[:-1][:, None, :], A[1:][:, None, :]
    ab = a1 - a0
    s = np.clip(np.einsum("ijk,ijk->ij", Q - a0, ab) / np.maximum(np.einsum("ijk,ijk->ij", ab, ab), 1e-300), 0.0, 1.0)
    dev = float(np.linalg.norm(Q - (a0 + s[:, :, None] * ab), axis=2).max())
    return P, tris, dev


def _polygon_on(tri, loc=None):
    """``polygon(edge)`` of :func:`_strip` read from the triangulation ``tri``."""
    loc = TopLoc_Location() if loc is None else loc
    nodes = {}

    def polygon(edge):
        poly = BRep_Tool.PolygonOnTriangulation_s(edge, tri, loc)
        if poly is None or not poly.HasParameters():
            return None
        if not nodes:
            nn = tri.NbNodes()
            nodes["P"] = np.array([tri.Node(i).Coord() for i in range(1, nn + 1)], float).reshape(nn, 3)
        idx = np.array([poly.Node(i) for i in range(1, poly.NbNodes() + 1)], np.int64) - 1
        par = np.array([poly.Parameter(i) for i in range(1, poly.NbNodes() + 1)], float)
        return nodes["P"][idx], par

    return polygon


def _strips(shape) -> dict:
    """{face index (explorer order): :func:`_strip` of that face} over the faces of a meshed shape that are prism
    sides (each read from its own triangulation)."""
    out = {}
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    k = 0
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        ex.Next()
        tri = BRep_Tool.Triangulation_s(face, TopLoc_Location())
        if tri is not None:
            st = _strip(face, _polygon_on(tri))
            if st is not None:
                out[k] = st
        k += 1
    return out


def _faces_beside(beside, edge) -> list:
    """The faces at `edge` in `beside` (TopExp's map of edges to their faces), in the map's order.  A list of two or
    fewer is read by its ends: OCP's iteration over a TopTools_ListOfShape costs 0.16-0.24 ms an element (the lookup
    1-2 µs), which made 0.3-0.45 s of the seed-002 driven wheel's meshing (two faces beside each of its flanks' 944
    curve edges)."""
    faces = beside.FindFromKey(edge)
    n = faces.Size()
    if n == 2:
        return [faces.First(), faces.Last()]
    if n == 1:
        return [faces.First()]
    return list(faces) if n else []


def _edge_ends(face):
    """(the face's edges, (n, 9) array of each edge's curve at its first, middle and last parameter), or None for a
    face with a degenerate edge."""
    edges = _edges(face)
    if edges is None:
        return None
    keys = []
    for edge in edges:
        c = BRepAdaptor_Curve(edge)
        u0, u1 = c.FirstParameter(), c.LastParameter()
        keys.append(c.Value(u0).Coord() + c.Value(0.5 * (u0 + u1)).Coord() + c.Value(u1).Coord())
    return edges, np.array(keys, float).reshape(-1, 9)


def _cap_twins(faces, skip) -> dict:
    """{index of cap B: (index of cap A, t (3,), [(edge of A, edge of B), ...])} over the planar faces of `faces`
    (not in `skip`): B is A translated by t along their common normal, as a prism's two caps are.  Candidates: the
    two planes have the same frame (normal and x direction) and origins t apart along the normal, and every edge of
    B has its one edge of A whose ends and middle, moved by t, are B's (within :data:`_STRIP_MATCH_MM`).  The copy
    is proven on the nodes once A is meshed (:func:`_cap_copies`)."""
    planes = []
    for k, face in enumerate(faces):
        if k in skip or not face.Location().IsIdentity():
            continue
        ad = BRepAdaptor_Surface(face)
        if ad.GetType() != GeomAbs_Plane:
            continue
        pos = ad.Plane().Position()
        planes.append((k, np.array(pos.Location().Coord()), pos.Direction().Coord(), pos.XDirection().Coord(), face))
    twins, ends, taken = {}, {}, set()
    for j, (kb, ob, nb, xb, fb) in enumerate(planes):
        for ka, oa, na, xa, fa in planes[:j]:
            if ka in taken or ka in twins or na != nb or xa != xb:
                continue
            t = ob - oa
            h = float(t @ np.array(na))
            if abs(h) <= _STRIP_MATCH_MM or np.abs(t - h * np.array(na)).max() > _STRIP_MATCH_MM:
                continue
            for k, f in ((ka, fa), (kb, fb)):
                if k not in ends:
                    ends[k] = _edge_ends(f)
            if ends[ka] is None or ends[kb] is None or len(ends[ka][0]) != len(ends[kb][0]):
                continue
            (ea, Ka), (eb, Kb) = ends[ka], ends[kb]
            close = np.abs(Kb[:, None, :] - (Ka[None, :, :] + np.tile(t, 3))).max(axis=2) <= _STRIP_MATCH_MM
            if not (close.sum(axis=1) == 1).all() or not (close.sum(axis=0) == 1).all():
                continue
            twins[kb] = (ka, t, [(ea[int(i)], eb[r]) for r, i in enumerate(close.argmax(axis=1))])
            taken.add(ka)
            break
    return twins


def _cap_copies(faces, twins, beside, edges):
    """The caps B of `twins` (:func:`_cap_twins`) as A's triangulation moved by t: ({index of B: (nodes, triangles,
    A's deflection)}, {index of an edge of B in `edges`: (its nodes, parameters)}), or None where the copy does not
    hold.  It holds when, for every edge of B, the curve of B's edge at the parameters of its mate's nodes on A is
    those nodes moved by t (within :data:`_STRIP_MATCH_MM`: the copied nodes lie on B's edges where B's own
    discretisation would put them), and a face that has its own nodes on B's edge (a bore's band, meshed with the
    other faces) has these, within :data:`MERGE_TOL_MM` (the mesh stays closed)."""
    copies, polys = {}, {}
    loc = TopLoc_Location()
    for kb, (ka, t, pairs) in twins.items():
        tri = BRep_Tool.Triangulation_s(faces[ka], loc)
        if tri is None:
            return None
        nn, nt = tri.NbNodes(), tri.NbTriangles()
        P = np.array([tri.Node(j).Coord() for j in range(1, nn + 1)], float).reshape(nn, 3)
        T = np.array([tri.Triangle(j).Get() for j in range(1, nt + 1)], np.int64).reshape(nt, 3) - 1
        for ea, eb in pairs:
            poly = BRep_Tool.PolygonOnTriangulation_s(ea, tri, loc)
            if poly is None or not poly.HasParameters():
                return None
            idx = np.array([poly.Node(i) for i in range(1, poly.NbNodes() + 1)], np.int64) - 1
            par = np.array([poly.Parameter(i) for i in range(1, poly.NbNodes() + 1)], float)
            nodes = P[idx] + t
            c = BRepAdaptor_Curve(eb)
            on = np.array([c.Value(float(u)).Coord() for u in par], float).reshape(-1, 3)
            if np.abs(on - nodes).max() > _STRIP_MATCH_MM:
                return None
            for f in _faces_beside(beside, eb):
                other = BRep_Tool.Triangulation_s(TopoDS.Face_s(f), loc)
                if other is None:  # B itself, a side: not meshed
                    continue
                pb = BRep_Tool.PolygonOnTriangulation_s(eb, other, loc)
                if pb is None or pb.NbNodes() != len(nodes):
                    return None
                theirs = np.array([other.Node(pb.Node(j)).Coord() for j in range(1, pb.NbNodes() + 1)], float)
                if np.linalg.norm(theirs - nodes, axis=1).max() > MERGE_TOL_MM \
                        and np.linalg.norm(theirs[::-1] - nodes, axis=1).max() > MERGE_TOL_MM:
                    return None
            polys[edges.FindIndex(eb)] = (nodes, par)
        copies[kb] = (P + t, T, float(tri.Deflection()))
    return copies, polys


def _mesh_sides_apart(shape, request, angular_tol, parallel, twins: bool = True):
    """Every face but a prism's sides meshed by BRepMesh (as :func:`mesh_shape` meshes a ruled shape), then each side
    as strips (:func:`_strip`) on the nodes its edges got from the faces beside it: BRepMesh's own pass over the
    sides (about half its time on a gear) is not made.  With ``twins``, a prism's second cap (a planar face that is
    another one translated along its normal, :func:`_cap_twins`) is not meshed either: it is the first cap's
    triangulation moved (:func:`_cap_copies`; BRepMesh gives the two caps of a gear the same triangles, node for
    node: a third of the gear's meshing time); where the copy does not hold, the shape is meshed again without it.
    Returns ({face index: strip or copied cap}, the compound of the faces BRepMesh meshed, the indices of the copied
    caps), or None (the shape meshed by nobody yet) where a side's edge has no neighbour's nodes or no strip fits:
    the caller meshes the whole shape then."""
    from OCP.BRep import BRep_Builder
    from OCP.TopoDS import TopoDS_Compound
    from OCP.TopTools import TopTools_IndexedDataMapOfShapeListOfShape, TopTools_IndexedMapOfShape

    faces, sides = [], {}
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        ex.Next()
        if BRepAdaptor_Surface(face).GetType() == GeomAbs_SurfaceOfExtrusion and face.Location().IsIdentity():
            sides[len(faces)] = face
        faces.append(face)
    if not sides:
        return None
    caps = _cap_twins(faces, sides) if twins else {}
    BRepTools.Clean_s(shape)
    rest = TopoDS_Compound()
    builder = BRep_Builder()
    builder.MakeCompound(rest)
    for k, face in enumerate(faces):
        if k not in sides and k not in caps:
            builder.Add(rest, face)
    prm = _params(request, angular_tol, parallel, True)
    _premesh_cylinders(rest, prm)
    if not BRepMesh_IncrementalMesh(rest, prm).IsDone():
        raise RuntimeError("BRepMesh failed")
    beside = TopTools_IndexedDataMapOfShapeListOfShape()
    TopExp.MapShapesAndAncestors_s(shape, TopAbs_EDGE, TopAbs_FACE, beside)
    index = TopTools_IndexedMapOfShape()
    TopExp.MapShapes_s(shape, TopAbs_FACE, index)
    copied, polys = {}, {}
    if caps:
        edges = TopTools_IndexedMapOfShape()
        TopExp.MapShapes_s(shape, TopAbs_EDGE, edges)
        got = _cap_copies(faces, caps, beside, edges)
        if got is None:
            BRepTools.Clean_s(shape)
            return _mesh_sides_apart(shape, request, angular_tol, parallel, twins=False)
        copied, polys = got
    on = {}

    def polygon(edge):
        # the faces beside the edge that have a triangulation: not the sides (cleaned, not meshed); a copied cap's
        # edge: the copy's nodes
        if polys:
            got = polys.get(edges.FindIndex(edge))
            if got is not None:
                return got
        for f in _faces_beside(beside, edge):
            i = index.FindIndex(f)
            if i not in on:
                tri = BRep_Tool.Triangulation_s(TopoDS.Face_s(f), TopLoc_Location())
                on[i] = None if tri is None else _polygon_on(tri)
            got = None if on[i] is None else on[i](edge)
            if got is not None:
                return got
        return None

    strips = dict(copied)
    for k, face in sides.items():
        st = _strip(face, polygon)
        if st is None:
            BRepTools.Clean_s(shape)
            return None
        strips[k] = st
    return strips, rest, set(copied)


def refine_faces(shape, chord_tol, angular_tol, parallel, chord_limit, keep=()) -> float:
    """Mesh again only the faces of a meshed shape whose achieved deflection exceeds `chord_limit`, with
    the surface deflection controlled on them although they are analytic (OCCT controls it on free-form
    faces only: a cone between two differently divided circles misses the request several times over)
    and no element below `chord_limit` (finer ones fold at a cone's apex).  The edges keep their
    discretisation (the neighbours' triangulations share it), so the mesh stays closed.  A face with a
    degenerate edge (a cone's apex, a sphere's pole) is left as it is: the nodes inserted there crowd
    into slivers that fold once the mesh is written in single precision (STL), and the caller's halving
    takes it on (its deflection measured: :func:`_apex_deflection`).  ``keep``: the strips of a prism's sides
    (:func:`_strips`, by face index), left as they are and counted with their own deflection.  A face placed twice in
    a compound (one solid at two places) shares its triangulation: cleared at its first place, it is not looked at
    again at the second.  Returns the largest achieved deflection."""
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    k = 0
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        tri = BRep_Tool.Triangulation_s(face, TopLoc_Location())
        if k not in keep and tri is not None and tri.Deflection() > chord_limit and not _has_apex(face):
            BRepTools.Clean_s(face)
        ex.Next()
        k += 1
    prm = IMeshTools_Parameters()
    prm.Deflection, prm.Angle, prm.Relative, prm.InParallel = chord_tol, angular_tol, False, parallel
    prm.EnableControlSurfaceDeflectionAllSurfaces = True
    prm.MinSize = chord_limit
    if not BRepMesh_IncrementalMesh(shape, prm).IsDone():
        raise RuntimeError("BRepMesh failed")
    return _worst_deflection(shape, chord_limit, keep or None)


def _has_apex(face) -> bool:
    """Whether the face has a degenerate edge (a point of its surface that an edge collapses to)."""
    return _edges(face) is None


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
    P = np.array([tri.Node(i).Coord() for i in range(1, tri.NbNodes() + 1)], float).reshape(-1, 3)
    T = np.array([tri.Triangle(i).Get() for i in range(1, tri.NbTriangles() + 1)], np.int64).reshape(-1, 3) - 1
    if not loc.IsIdentity():
        t = loc.Transformation()
        R = np.array([[t.Value(r, c) for c in (1, 2, 3)] for r in (1, 2, 3)])
        P = P @ R.T + np.array([t.Value(r, 4) for r in (1, 2, 3)])
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
    (``strips``, by face index), the strips' own (:func:`_strip`)."""
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
    most 4 times).  The returned deflection is that reported by OCCT, except on a cone
    or sphere face with a degenerate edge: there it is measured against the exact
    surface (:func:`_apex_deflection`; OCCT's estimate can be far off at an apex: a cone
    r = 8, h = 5 mm meshed at 0.005 mm reports 0.0205 mm, measured 0.0023 mm; the
    balancer's drill point 0.0205 mm, measured 0.0022 mm; on a sphere it is right).
    """
    if not (chord_tol > 0 and angular_tol > 0):
        raise ValueError(f"chord_tol = {chord_tol!r}, angular_tol = {angular_tol!r}: must be > 0")
    shape = occ_shape(solid)
    request = chord_tol

    ruled = _ruled_only(shape)

    def meshed(request):
        """(achieved deflection, strips and copied caps, the other faces meshed apart or None)"""
        if ruled:
            apart = _mesh_sides_apart(shape, request, angular_tol, parallel)
            if apart is not None:
                strips, rest, _ = apart
                return _worst_deflection(shape, chord_limit, strips), strips, rest
        achieved = mesh_shape(shape, request, angular_tol, parallel, chord_limit)
        strips = _strips(shape) if ruled else {}
        return (_worst_deflection(shape, chord_limit, strips) if strips else achieved), strips, None

    achieved, strips, rest = meshed(request)
    # the edges keep their nodes (refine_faces), and so the strips on them hold; a copied cap's first cap is a plane
    # (its deflection nil), which refine_faces leaves as it is, and so the copy holds too
    if achieved > chord_limit:
        if rest is not None:
            achieved = max([refine_faces(rest, request, angular_tol, parallel, chord_limit)]
                           + [st[2] for st in strips.values()])
        else:
            achieved = refine_faces(shape, request, angular_tol, parallel, chord_limit, keep=strips)
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
        if k in strips:  # a prism's side: its strips, on its edges' nodes (:func:`_strip`)
            pts, ids = strips[k][0], strips[k][1]
        else:
            loc = TopLoc_Location()
            tri = BRep_Tool.Triangulation_s(face, loc)
            nn, nt = tri.NbNodes(), tri.NbTriangles()
            node, triangle = tri.Node, tri.Triangle
            pts = np.array([node(i).Coord() for i in range(1, nn + 1)], float).reshape(nn, 3)
            if not loc.IsIdentity():
                t = loc.Transformation()
                R = np.array([[t.Value(r, c) for c in (1, 2, 3)] for r in (1, 2, 3)])
                pts = pts @ R.T + np.array([t.Value(r, 4) for r in (1, 2, 3)])
            ids = np.array([triangle(i).Get() for i in range(1, nt + 1)], np.int64).reshape(nt, 3) - 1
        if face.Orientation() == TopAbs_REVERSED:
            ids = ids[:, [0, 2, 1]]
        verts.append(pts)
        tris.append(ids + offset)
        offset += len(pts)
    if not verts:
        raise ValueError("shape has no faces")
    v, f = merge_close_vertices(np.vstack(verts), np.vstack(tris))
    return v, f, achieved
