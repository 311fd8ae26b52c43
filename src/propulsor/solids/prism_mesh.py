"""A prism's faces meshed from its neighbours' nodes (part of the kernel adapter, used by
:mod:`propulsor.solids.tessellate`).

A gear or a plate is a prism: a profile extruded along a line.  BRepMesh meshes its side faces (linear extrusions
of a curve) with diagonals across the curve and then again with interior nodes, and Delaunay-meshes both its
planar caps, which come out the same node for node.  Here a side is strips between the nodes its two curve edges
share with the caps (:func:`side_strip`), and the second cap is the first one's triangulation moved
(:func:`cap_twins`, :func:`cap_copies`); :func:`mesh_sides_apart` has BRepMesh mesh only the rest.  Every node used
is one of an edge's discretisation that the neighbouring faces share, so the mesh stays closed.  A face placed by
a location (a solid moved by CadQuery's ``moved``, a part of a fuse with one) is taken where it is placed: OCCT's
adaptors place its surface and curves, and a triangulation's nodes are placed by the location it is stored with
(:func:`placed`).
"""

from __future__ import annotations

import math

import numpy as np
from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Curve2d, BRepAdaptor_Surface
from OCP.BRepGProp import BRepGProp_Face
from OCP.BRepTools import BRepTools
from OCP.GeomAbs import GeomAbs_Line, GeomAbs_Plane, GeomAbs_SurfaceOfExtrusion
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE, TopAbs_REVERSED
from OCP.TopExp import TopExp, TopExp_Explorer
from OCP.TopLoc import TopLoc_Location
from OCP.TopoDS import TopoDS
from OCP.gp import gp_Pnt, gp_Vec

from ..policy import MERGE_TOL_MM

__all__ = ["STRIP_MATCH_MM", "cap_copies", "cap_twins", "edges_of", "faces_beside", "mesh_sides_apart", "nodes_of",
           "placed", "polygon_on", "side_strip", "side_strips", "triangles_of"]

#: two nodes of a prism's side face are one above the other when their offset is off the extrusion's line by less
#: than this (mm); a copied cap's node lies on its edge within it too
STRIP_MATCH_MM = 1e-7


def placed(P: np.ndarray, loc) -> np.ndarray:
    """Points P (n, 3) of a face's triangulation (stored in the face's own frame) where the location ``loc`` (the one
    ``BRep_Tool.Triangulation_s`` returned with it) puts them."""
    if loc.IsIdentity():
        return P
    t = loc.Transformation()
    R = np.array([[t.Value(r, c) for c in (1, 2, 3)] for r in (1, 2, 3)])
    return P @ R.T + np.array([t.Value(r, 4) for r in (1, 2, 3)])


def nodes_of(tri, loc) -> np.ndarray:
    """The nodes (n, 3) of a triangulation, placed by its location (:func:`placed`)."""
    n, node = tri.NbNodes(), tri.Node
    return placed(np.array([node(i).Coord() for i in range(1, n + 1)], float).reshape(n, 3), loc)


def triangles_of(tri) -> np.ndarray:
    """The triangles (m, 3) of a triangulation, as 0-based indices into :func:`nodes_of`."""
    m, triangle = tri.NbTriangles(), tri.Triangle
    return np.array([triangle(i).Get() for i in range(1, m + 1)], np.int64).reshape(m, 3) - 1


def _polygon_arrays(poly) -> tuple[np.ndarray, np.ndarray]:
    """(0-based node indices into its triangulation, parameters on the edge) of an edge's polygon on a
    triangulation."""
    n = poly.NbNodes()
    return (np.array([poly.Node(i) for i in range(1, n + 1)], np.int64) - 1,
            np.array([poly.Parameter(i) for i in range(1, n + 1)], float))


def _triangulation(face):
    """(the face's triangulation or None, the location its nodes are placed by)."""
    loc = TopLoc_Location()
    return BRep_Tool.Triangulation_s(face, loc), loc


def _cross(a, b) -> np.ndarray:
    """a x b of two (n, 3) arrays row by row: numpy's formula (``np.cross``), without its axis handling (0.1 ms a call,
    a fifth of a prism side's strips)."""
    return np.column_stack([a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1], a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
                            a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]])


def edges_of(face) -> list | None:
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


def side_strip(face, polygon) -> tuple[np.ndarray, np.ndarray, float] | None:
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
    if ad.GetType() != GeomAbs_SurfaceOfExtrusion:
        return None
    dd = ad.Direction().Coord()
    d = np.array(dd)
    curves, lines = [], []
    edges = edges_of(face)
    if edges is None:
        return None
    for edge in edges:
        cad = BRepAdaptor_Curve(edge)
        if cad.GetType() == GeomAbs_Line:
            u = cad.Line().Direction().Coord()
            off = math.hypot(u[1] * dd[2] - u[2] * dd[1], u[2] * dd[0] - u[0] * dd[2], u[0] * dd[1] - u[1] * dd[0])
            if off > 1e-12:
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
    if np.linalg.norm(B[0] - A[0] - np.dot(B[0] - A[0], d) * d) > STRIP_MATCH_MM:
        B = B[::-1]
    off = B - A
    h = off @ d
    if np.abs(off - np.outer(h, d)).max() > STRIP_MATCH_MM or np.abs(h - h[0]).max() > STRIP_MATCH_MM:
        return None
    # the straight edges join the curve edges' ends, and nothing else (a divided one: its inner nodes are the mate's)
    for p, q in ((A[0].tolist(), B[0].tolist()), (A[-1].tolist(), B[-1].tolist())):
        if not any(min(math.dist(a, p) + math.dist(b, q), math.dist(a, q) + math.dist(b, p)) <= STRIP_MATCH_MM
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


def polygon_on(tri, loc):
    """``polygon(edge)`` of :func:`side_strip` read from a face's triangulation ``tri`` placed by ``loc`` (as
    ``BRep_Tool.Triangulation_s`` returned them: an edge's polygon on it is found by that location, and its nodes
    are placed by it)."""
    nodes = {}

    def polygon(edge):
        poly = BRep_Tool.PolygonOnTriangulation_s(edge, tri, loc)
        if poly is None or not poly.HasParameters():
            return None
        if not nodes:
            nodes["P"] = nodes_of(tri, loc)
        idx, par = _polygon_arrays(poly)
        return nodes["P"][idx], par

    return polygon


def side_strips(shape) -> dict:
    """{face index (explorer order): :func:`side_strip` of that face} over the faces of a meshed shape that are prism
    sides (each read from its own triangulation)."""
    out = {}
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    k = 0
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        ex.Next()
        tri, loc = _triangulation(face)
        if tri is not None:
            st = side_strip(face, polygon_on(tri, loc))
            if st is not None:
                out[k] = st
        k += 1
    return out


def faces_beside(beside, edge) -> list:
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
    edges = edges_of(face)
    if edges is None:
        return None
    keys = []
    for edge in edges:
        c = BRepAdaptor_Curve(edge)
        u0, u1 = c.FirstParameter(), c.LastParameter()
        keys.append(c.Value(u0).Coord() + c.Value(0.5 * (u0 + u1)).Coord() + c.Value(u1).Coord())
    return edges, np.array(keys, float).reshape(-1, 9)


def _one_to_one(Kb: np.ndarray, Ka: np.ndarray, tol: float) -> np.ndarray | None:
    """For each row of `Kb`, the index of the one row of `Ka` (as many rows) within `tol` of it in every coordinate,
    or None unless each row of either has exactly one such row in the other.  The candidates from a k-d tree (the
    search radius a little wider), each then tested as ``np.abs(b - a).max() <= tol``: the pairs of the full
    (n, n) comparison, without its n^2 x 9 array (a gear's cap: thousands of edges)."""
    from scipy.spatial import cKDTree

    candidates = cKDTree(Ka).query_ball_point(Kb, tol * (1.0 + 1e-6) + 1e-12, p=np.inf)
    match = np.empty(len(Kb), np.int64)
    for r, js in enumerate(candidates):
        hits = [j for j in js if np.abs(Kb[r] - Ka[j]).max() <= tol]
        if len(hits) != 1:
            return None
        match[r] = hits[0]
    return match if len(np.unique(match)) == len(Ka) else None


def cap_twins(faces, skip) -> dict:
    """{index of cap B: (index of cap A, t (3,), [(edge of A, edge of B), ...])} over the planar faces of `faces`
    (not in `skip`): B is A translated by t along their common normal, as a prism's two caps are.  Candidates: the
    two planes have the same frame (normal and x direction) and origins t apart along the normal, and every edge of
    B has its one edge of A whose ends and middle, moved by t, are B's (within :data:`STRIP_MATCH_MM`).  The copy
    is proven on the nodes once A is meshed (:func:`cap_copies`)."""
    planes = []
    for k, face in enumerate(faces):
        if k in skip:
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
            if abs(h) <= STRIP_MATCH_MM or np.abs(t - h * np.array(na)).max() > STRIP_MATCH_MM:
                continue
            for k, f in ((ka, fa), (kb, fb)):
                if k not in ends:
                    ends[k] = _edge_ends(f)
            if ends[ka] is None or ends[kb] is None or len(ends[ka][0]) != len(ends[kb][0]):
                continue
            (ea, Ka), (eb, Kb) = ends[ka], ends[kb]
            match = _one_to_one(Kb, Ka + np.tile(t, 3), STRIP_MATCH_MM)
            if match is None:
                continue
            twins[kb] = (ka, t, [(ea[int(i)], eb[r]) for r, i in enumerate(match)])
            taken.add(ka)
            break
    return twins


def cap_copies(faces, twins, beside, edges):
    """The caps B of `twins` (:func:`cap_twins`) as A's triangulation moved by t: ({index of B: (nodes, triangles,
    A's deflection)}, {index of an edge of B in `edges`: (its nodes, parameters)}), or None where the copy does not
    hold.  It holds when, for every edge of B, the curve of B's edge at the parameters of its mate's nodes on A is
    those nodes moved by t (within :data:`STRIP_MATCH_MM`: the copied nodes lie on B's edges where B's own
    discretisation would put them), and a face that has its own nodes on B's edge (a bore's band, meshed with the
    other faces) has these, within :data:`MERGE_TOL_MM` (the mesh stays closed)."""
    copies, polys = {}, {}
    for kb, (ka, t, pairs) in twins.items():
        tri, loc = _triangulation(faces[ka])
        if tri is None:
            return None
        P, T = nodes_of(tri, loc), triangles_of(tri)
        for ea, eb in pairs:
            poly = BRep_Tool.PolygonOnTriangulation_s(ea, tri, loc)
            if poly is None or not poly.HasParameters():
                return None
            idx, par = _polygon_arrays(poly)
            nodes = P[idx] + t
            c = BRepAdaptor_Curve(eb)
            on = np.array([c.Value(float(u)).Coord() for u in par], float).reshape(-1, 3)
            if np.abs(on - nodes).max() > STRIP_MATCH_MM:
                return None
            for f in faces_beside(beside, eb):
                other, lo = _triangulation(TopoDS.Face_s(f))
                if other is None:  # B itself, a side: not meshed
                    continue
                pb = BRep_Tool.PolygonOnTriangulation_s(eb, other, lo)
                if pb is None or pb.NbNodes() != len(nodes):
                    return None
                ib = _polygon_arrays(pb)[0]
                theirs = placed(np.array([other.Node(int(j) + 1).Coord() for j in ib], float).reshape(-1, 3), lo)
                if np.linalg.norm(theirs - nodes, axis=1).max() > MERGE_TOL_MM \
                        and np.linalg.norm(theirs[::-1] - nodes, axis=1).max() > MERGE_TOL_MM:
                    return None
            polys[edges.FindIndex(eb)] = (nodes, par)
        copies[kb] = (P + t, T, float(tri.Deflection()))
    return copies, polys


def mesh_sides_apart(shape, mesh_rest, twins: bool = True):
    """Every face but a prism's sides meshed by ``mesh_rest(compound)`` (the caller's BRepMesh pass, as
    :func:`propulsor.solids.tessellate.mesh_shape` meshes the shape), then each side as strips (:func:`side_strip`)
    on the nodes its edges got from the faces beside it: BRepMesh's own pass over the sides (about half its time on a
    gear) is not made.  A side no strip fits (a hole through it; the shape's other faces not ruled, a chamfer's edge
    discretised differently) is meshed by ``mesh_rest`` after the others, alone, on the nodes its edges already
    have.  With ``twins``, a prism's second cap (a planar face that is another one translated along its normal,
    :func:`cap_twins`) is not meshed either: it is the first cap's triangulation moved (:func:`cap_copies`; BRepMesh
    gives the two caps of a gear the same triangles, node for node: a third of the gear's meshing time); where the
    copy does not hold, or a side meshed by BRepMesh borders it, the shape is meshed again without it.  Returns
    ({face index: strip or copied cap}, the compound of the faces BRepMesh meshed, the indices of the copied caps),
    or None (the shape meshed by nobody yet) where it has no prism side: the caller meshes the whole shape then."""
    from OCP.BRep import BRep_Builder
    from OCP.TopoDS import TopoDS_Compound
    from OCP.TopTools import TopTools_IndexedDataMapOfShapeListOfShape, TopTools_IndexedMapOfShape

    faces, sides = [], {}
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        face = TopoDS.Face_s(ex.Current())
        ex.Next()
        if BRepAdaptor_Surface(face).GetType() == GeomAbs_SurfaceOfExtrusion:
            sides[len(faces)] = face
        faces.append(face)
    if not sides:
        return None
    caps = cap_twins(faces, sides) if twins else {}
    BRepTools.Clean_s(shape)
    rest = TopoDS_Compound()
    builder = BRep_Builder()
    builder.MakeCompound(rest)
    for k, face in enumerate(faces):
        if k not in sides and k not in caps:
            builder.Add(rest, face)
    mesh_rest(rest)
    beside = TopTools_IndexedDataMapOfShapeListOfShape()
    TopExp.MapShapesAndAncestors_s(shape, TopAbs_EDGE, TopAbs_FACE, beside)
    index = TopTools_IndexedMapOfShape()
    TopExp.MapShapes_s(shape, TopAbs_FACE, index)
    copied, polys = {}, {}
    if caps:
        edges = TopTools_IndexedMapOfShape()
        TopExp.MapShapes_s(shape, TopAbs_EDGE, edges)
        got = cap_copies(faces, caps, beside, edges)
        if got is None:
            BRepTools.Clean_s(shape)
            return mesh_sides_apart(shape, mesh_rest, twins=False)
        copied, polys = got
    on = {}

    def polygon(edge):
        # the faces beside the edge that have a triangulation: not the sides (cleaned, not meshed); a copied cap's
        # edge: the copy's nodes
        if polys:
            got = polys.get(edges.FindIndex(edge))
            if got is not None:
                return got
        for f in faces_beside(beside, edge):
            i = index.FindIndex(f)
            if i not in on:
                tri, loc = _triangulation(TopoDS.Face_s(f))
                on[i] = None if tri is None else polygon_on(tri, loc)
            got = None if on[i] is None else on[i](edge)
            if got is not None:
                return got
        return None

    strips, left = dict(copied), []
    for k, face in sides.items():
        st = side_strip(face, polygon)
        if st is None:
            left.append(k)
        else:
            strips[k] = st
    if left:
        # the sides no strip fits (a hole through one, an edge no neighbour has discretised): BRepMesh's, on the
        # nodes their edges already have.  One beside a copied cap would discretise the cap's edge afresh: then no
        # copy.  An edge one shares with a strip is straight (the strip's end), which BRepMesh does not divide, as
        # with the other faces beside a strip
        at = {index.FindIndex(face): k for k, face in enumerate(faces)}  # a face of the map -> its place in faces
        if copied and any(at.get(index.FindIndex(f)) in copied for k in left for e in edges_of(faces[k]) or ()
                          for f in faces_beside(beside, e)):
            BRepTools.Clean_s(shape)
            return mesh_sides_apart(shape, mesh_rest, twins=False)
        more = TopoDS_Compound()
        builder.MakeCompound(more)
        for k in left:
            builder.Add(more, faces[k])
            builder.Add(rest, faces[k])
        mesh_rest(more)
    return strips, rest, set(copied)
