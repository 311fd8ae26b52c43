"""Validity of triangle meshes: closed, oriented, one body, genus, no self-intersection.

trimesh's own flags (is_watertight, is_winding_consistent, is_volume) are
combinatorial: a mesh of two interpenetrating boxes passes them all.  The
self-intersection test here is geometric:

* broad phase: a bounding-volume hierarchy over Morton-ordered triangles
  (implicit complete binary tree), traversed against itself level by level in
  numpy; it yields every pair of triangles whose boxes overlap;
* narrow phase (:mod:`propulsor.checks.tri_tri`, compiled with numba): exact-style
  triangle-triangle test with an absolute tolerance `eps` (1e-10 of the mesh size).  Two non-coplanar triangles intersect iff an
  edge of one meets the other (the ends of their common segment lie on edges);
  coplanar pairs are tested in the plane.  Triangles sharing a vertex intersect
  only if an edge opposite the shared vertex meets the other triangle; triangles
  sharing an edge intersect only when folded onto each other (coplanar, third
  vertices on the same side); duplicated faces always intersect.

Topology: a closed orientable surface has Euler characteristic
chi = V - E + F = 2 - 2 g per connected body.
"""

from __future__ import annotations

import numpy as np

from ..policy import MESH_CHORD_LIMIT_MM, MESH_VOLUME_REL_TOL
from ..check import Check
from .box_pairs import child_pairs
from .tri_tri import pairs_intersect

#: what the chord deflection of a mesh from :func:`propulsor.solids.tessellate.triangulate` is (the value
#: :func:`propulsor.export.mesh.to_trimesh` keeps as ``metadata['chord_deflection_mm']``): the largest of each face's,
#: which is measured on a prism's side meshed as strips and on a cone's or sphere's face with an apex, and OCCT's own
#: estimate on the faces BRepMesh meshes (larger than the distance measured on the exported files: the balancer
#: 0.00707 against 0.00466 mm)
CHORD_NOTE = ("tessellation chord error: measured on a prism's side strips and at a cone's or sphere's apex, "
              "OCCT's estimate on the faces BRepMesh meshes")


# --- topology -----------------------------------------------------------------
def edge_counts(faces: np.ndarray):
    """(undirected edge keys, how many faces use each, directed duplicates count)."""
    f = np.asarray(faces, np.int64)
    n = int(f.max()) + 1 if len(f) else 0
    u = f[:, [0, 1, 2]].ravel()
    v = f[:, [1, 2, 0]].ravel()
    directed = u * n + v
    _, dcount = np.unique(directed, return_counts=True)
    und = np.minimum(u, v) * n + np.maximum(u, v)
    keys, ucount = np.unique(und, return_counts=True)
    return keys, ucount, int(np.sum(dcount > 1))


def body_labels(faces: np.ndarray, n_vertices: int) -> np.ndarray:
    """Connected component of each face (faces connected through shared vertices)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    f = np.asarray(faces, np.int64)
    r = np.concatenate([f[:, 0], f[:, 1]])
    c = np.concatenate([f[:, 1], f[:, 2]])
    g = coo_matrix((np.ones(len(r)), (r, c)), shape=(n_vertices, n_vertices))
    _, lab = connected_components(g, directed=False)
    return lab[f[:, 0]]


def signed_volume(vertices: np.ndarray, faces: np.ndarray) -> float:
    """Divergence theorem: sum of signed tetrahedra (origin shifted to the centroid)."""
    v = np.asarray(vertices, float)
    v = v - v.mean(axis=0)
    t = v[np.asarray(faces)]
    return float(np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum() / 6.0)


def euler_genus(vertices: np.ndarray, faces: np.ndarray) -> tuple[int, int, int]:
    """(Euler characteristic, number of bodies, total genus) of a closed mesh."""
    f = np.asarray(faces, np.int64)
    used = np.unique(f)
    keys, _, _ = edge_counts(f)
    chi = len(used) - len(keys) + len(f)
    bodies = len(np.unique(body_labels(f, len(vertices))))
    genus = (2 * bodies - chi) // 2
    return int(chi), int(bodies), int(genus)


# --- broad phase ----------------------------------------------------------------
def _morton(c: np.ndarray) -> np.ndarray:
    lo, hi = c.min(axis=0), c.max(axis=0)
    q = ((c - lo) / np.maximum(hi - lo, 1e-300) * 1023.0).astype(np.int64)
    code = np.zeros(len(c), np.int64)
    for bit in range(10):
        for ax in range(3):
            code |= ((q[:, ax] >> bit) & 1) << (3 * bit + ax)
    return code


def _f32_down(x):
    y = x.astype(np.float32)
    return np.where(y > x, np.nextafter(y, np.float32(-np.inf)), y)


def _f32_up(x):
    y = x.astype(np.float32)
    return np.where(y < x, np.nextafter(y, np.float32(np.inf)), y)


class TooManyPairs(ValueError):
    """More overlapping box pairs than the caller allows (a hostile or degenerate mesh)."""


def overlapping_pairs(lo: np.ndarray, hi: np.ndarray, max_pairs: int | None = None) -> np.ndarray:
    """All pairs (i < j) whose boxes [lo, hi] overlap (closed), as an (k, 2) array (:func:`overlapping_ij`'s
    two columns)."""
    return np.column_stack(overlapping_ij(lo, hi, max_pairs))


def overlapping_ij(lo: np.ndarray, hi: np.ndarray, max_pairs: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """All pairs (i[k] < j[k]) whose boxes [lo, hi] overlap (closed), as two index arrays (int64), in the order of
    :func:`overlapping_pairs`'s rows.

    Implicit bounding-volume hierarchy: boxes sorted by the Morton code of their
    centres are the leaves of a complete binary tree (node i of level k covers
    leaves i*2^k ... (i+1)*2^k - 1); the tree is traversed against itself one
    level at a time, keeping node pairs whose boxes overlap.  Bounds are kept in
    float32 rounded outwards (conservative), one array per axis and side.  With `max_pairs`, more
    node pairs than that at any level raise TooManyPairs (memory stays bounded).
    """
    lo = np.asarray(lo, float)
    hi = np.asarray(hi, float)
    m = len(lo)
    if m < 2:
        return np.empty(0, np.int64), np.empty(0, np.int64)
    order = np.argsort(_morton(0.5 * (lo + hi)), kind="stable")
    levels = [[_f32_down(lo[order, a]) for a in range(3)] + [_f32_up(hi[order, a]) for a in range(3)]]
    while len(levels[-1][0]) > 1:
        nxt = []
        for a, arr in enumerate(levels[-1]):
            if len(arr) % 2:
                arr = np.append(arr, arr[-1])
            nxt.append(np.minimum(arr[0::2], arr[1::2]) if a < 3 else np.maximum(arr[0::2], arr[1::2]))
        levels.append(nxt)
    A = np.zeros(1, np.int32)
    B = np.zeros(1, np.int32)
    for lev in range(len(levels) - 2, -1, -1):
        # compiled: the children of each pair whose boxes overlap
        A, B = child_pairs(A, B, np.column_stack(levels[lev]))
        if max_pairs is not None and len(A) > max_pairs:
            raise TooManyPairs(f"more than {max_pairs} pairs of overlapping triangle boxes")
    keep = A != B
    i, j = order[A[keep]], order[B[keep]]
    return np.minimum(i, j), np.maximum(i, j)


def self_intersections(vertices, faces, eps: float | None = None, max_report: int = 100,
                       max_pairs: int | None = None) -> tuple[int, np.ndarray]:
    """Count pairs of intersecting triangles; return (count, first pairs (k,2)).

    Degenerate (zero-area) triangles are skipped.  `eps` defaults to 1e-10 of
    the bounding-box diagonal.
    """
    V = np.ascontiguousarray(vertices, float)
    F = np.ascontiguousarray(faces, np.int64)
    if len(F) < 2:
        return 0, np.empty((0, 2), np.int64)
    diag = float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))
    if eps is None:
        eps = max(1e-10 * diag, 1e-15)
    T = V[F]
    area2 = np.linalg.norm(np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0]), axis=1)
    ok = np.nonzero(area2 > (eps * eps))[0]
    lo = T[ok].min(axis=1) - eps
    hi = T[ok].max(axis=1) + eps
    i, j = overlapping_ij(lo, hi, max_pairs)
    I, J = ok[i], ok[j]  # contiguous: the kernel reads them as they are
    del i, j
    N = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    N /= np.maximum(np.linalg.norm(N, axis=1), 1e-300)[:, None]
    D = np.einsum("ij,ij->i", N, T[:, 0])
    h = pairs_intersect(V, F, I, J, N, D, eps)
    hit = np.flatnonzero(h)[:max_report]
    return int(np.count_nonzero(h)), np.column_stack([I[hit], J[hit]]).astype(np.int64).reshape(-1, 2)


# --- the checks -------------------------------------------------------------------
def mesh_checks(
    mesh,
    name: str = "mesh",
    expected_volume: float | None = None,
    expected_genus: int | None = None,
    expected_bodies: int | None = 1,
    volume_rel_tol: float = MESH_VOLUME_REL_TOL,
    chord_deflection: float | None = None,
    brep_volume: float | None = None,
    max_box_pairs: int | None = None,
) -> list[Check]:
    """All validity checks of a closed triangle mesh (trimesh.Trimesh or (V, F)).

    chord_deflection: the tessellation's achieved deflection (mm); when not
    given it is taken from mesh.metadata['chord_deflection_mm'] if present.
    brep_volume: same as expected_volume (the B-rep volume the mesh must match).
    max_box_pairs: the self-intersection test fails, untested, past this many overlapping pairs of
    triangle boxes (files under check: policy.MESH_BOX_PAIRS_MAX).
    """
    if expected_volume is None:
        expected_volume = brep_volume
    if isinstance(mesh, tuple):
        V, F = mesh
    else:
        V, F = mesh.vertices, mesh.faces
    V = np.asarray(V, float)
    F = np.asarray(F, np.int64)
    out: list[Check] = []
    if len(F) == 0:
        return [Check.flag(f"{name}: has triangles", False, "mesh is empty")]
    _, ucount, dup_directed = edge_counts(F)
    open_edges = int(np.sum(ucount != 2))
    out.append(Check.equals(f"{name}: edges not shared by exactly 2 faces", open_edges, 0, "edges", "watertight: every edge has two faces"))
    out.append(Check.equals(f"{name}: directed edges used twice", dup_directed, 0, "edges", "consistent winding: each directed edge once"))
    vol = signed_volume(V, F)
    out.append(Check.greater_than(f"{name}: mesh volume", vol, 0.0, "mm^3", "positive enclosed volume (outward normals)"))
    chi, bodies, genus = euler_genus(V, F)
    if expected_bodies is None:
        out.append(Check(f"{name}: bodies", True, bodies, None, "", f"connected bodies, not prescribed (Euler characteristic {chi})"))
    else:
        out.append(Check.equals(f"{name}: bodies", bodies, expected_bodies, "", f"connected bodies (Euler characteristic {chi})"))
    if expected_genus is not None:
        out.append(Check.equals(f"{name}: genus", genus, expected_genus, "", f"genus from chi = V - E + F = {chi}"))
    try:
        nx, pairs = self_intersections(V, F, max_pairs=max_box_pairs)
    except TooManyPairs as exc:
        nx, pairs = -1, None
        msg = f"not tested: {exc}"
    else:
        msg = "no two triangles intersect (BVH + triangle-triangle test)"
    if nx > 0:
        msg = f"{nx} intersecting triangle pairs, e.g. faces {pairs[:3].tolist()}"
    out.append(Check.equals(f"{name}: self-intersecting triangle pairs", nx, 0, "pairs", msg))
    if chord_deflection is None and not isinstance(mesh, tuple):
        chord_deflection = getattr(mesh, "metadata", {}).get("chord_deflection_mm")
    if chord_deflection is not None:
        out.append(Check.at_most(f"{name}: chord deflection", chord_deflection, MESH_CHORD_LIMIT_MM, "mm", CHORD_NOTE))
    if expected_volume is not None:
        # every triangle lies within the deflection of the exact surface: the volumes differ by at most
        # deflection × area (the limit the files are held to where the achieved deflection is not known)
        deflection = chord_deflection if chord_deflection is not None else MESH_CHORD_LIMIT_MM
        area = float(0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum())
        bound = deflection * area
        out.append(
            Check.equal_within(f"{name}: volume vs B-rep", vol, expected_volume, rel_tol=volume_rel_tol,
                               abs_tol=bound, unit="mm^3",
                               message=f"mesh volume {vol:.9g} vs B-rep {expected_volume:.9g} mm^3 (deviation "
                                       f"{abs(vol - expected_volume):.3g}; allowed: deflection {deflection:.3g} mm "
                                       f"× area {area:.6g} mm^2 = {bound:.3g} mm^3, or {volume_rel_tol:g} of the "
                                       "volume)")
        )
    return out
