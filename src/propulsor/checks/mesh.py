"""Validity of triangle meshes: closed, oriented, one body, genus, no self-intersection.

trimesh's own flags (is_watertight, is_winding_consistent, is_volume) are
combinatorial: a mesh of two interpenetrating boxes passes them all.  The
self-intersection test here is geometric:

* broad phase: a bounding-volume hierarchy over Morton-ordered triangles
  (implicit complete binary tree), traversed against itself level by level in
  numpy; it yields every pair of triangles whose boxes overlap;
* narrow phase: exact-style triangle-triangle test with an absolute tolerance
  `eps` (1e-10 of the mesh size).  Two non-coplanar triangles intersect iff an
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

#: pairs processed per narrow-phase chunk (bounds memory)
_CHUNK = 400_000


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


def overlapping_pairs(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """All pairs (i < j) whose boxes [lo, hi] overlap (closed), as an (k, 2) array.

    Implicit bounding-volume hierarchy: boxes sorted by the Morton code of their
    centres are the leaves of a complete binary tree (node i of level k covers
    leaves i*2^k ... (i+1)*2^k - 1); the tree is traversed against itself one
    level at a time, keeping node pairs whose boxes overlap.  Bounds are kept in
    float32 rounded outwards (conservative), one array per axis and side.
    """
    lo = np.asarray(lo, float)
    hi = np.asarray(hi, float)
    m = len(lo)
    if m < 2:
        return np.empty((0, 2), np.int64)
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
        n = len(levels[lev][0])
        same = A == B
        As, Ad, Bd = A[same], A[~same], B[~same]
        # children of a self pair: (l,l), (l,r), (r,r); of a distinct pair: all four
        sa = np.concatenate([2 * As, 2 * As + 1])  # self pairs at the child level
        ca = np.concatenate([2 * As, 2 * Ad, 2 * Ad, 2 * Ad + 1, 2 * Ad + 1])
        cb = np.concatenate([2 * As + 1, 2 * Bd, 2 * Bd + 1, 2 * Bd, 2 * Bd + 1])
        ok = cb < n
        ca, cb = ca[ok], cb[ok]
        for a in range(3):
            lo_a, hi_a = levels[lev][a], levels[lev][a + 3]
            keep = (lo_a[ca] <= hi_a[cb]) & (lo_a[cb] <= hi_a[ca])
            ca, cb = ca[keep], cb[keep]
        sa = sa[sa < n]
        A = np.concatenate([sa, ca])
        B = np.concatenate([sa, cb])
    keep = A != B
    i, j = order[A[keep]], order[B[keep]]
    return np.column_stack([np.minimum(i, j), np.maximum(i, j)])


# --- narrow phase -----------------------------------------------------------------
def _dot(a, b):
    return np.einsum("ij,ij->i", a, b)


def _proj2(pts, drop):
    """Drop coordinate `drop` (per row) of (k,3) points -> (k,2)."""
    keep = np.array([[1, 2], [0, 2], [0, 1]])[drop]
    return np.take_along_axis(pts, keep, axis=1)


def _orient2(a, b, c):
    return (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])


def _point_in_tri2(p, a, b, c, eps):
    s = np.sign(_orient2(a, b, c))[:, None]
    out = np.ones(len(p), bool)
    for u, v in ((a, b), (b, c), (c, a)):
        e = v - u
        d = s[:, 0] * _orient2(u, v, p) / np.maximum(np.linalg.norm(e, axis=1), 1e-300)
        out &= d >= -eps
    return out


def _seg_seg2(p, q, a, b, eps):
    """Closed 2D segment intersection with tolerance eps (distances)."""
    lpq = np.maximum(np.linalg.norm(q - p, axis=1), 1e-300)
    lab = np.maximum(np.linalg.norm(b - a, axis=1), 1e-300)
    d1 = _orient2(p, q, a) / lpq
    d2 = _orient2(p, q, b) / lpq
    d3 = _orient2(a, b, p) / lab
    d4 = _orient2(a, b, q) / lab
    straddle = (np.minimum(d1, d2) <= eps) & (np.maximum(d1, d2) >= -eps) & (np.minimum(d3, d4) <= eps) & (np.maximum(d3, d4) >= -eps)
    colinear = (np.abs(d1) <= eps) & (np.abs(d2) <= eps)
    # collinear: overlap of the projections on the segment direction
    t = (q - p) / lpq[:, None]
    s0, s1 = np.zeros(len(p)), lpq
    ta, tb = _dot(a - p, t), _dot(b - p, t)
    col_ov = (np.minimum(ta, tb) <= s1 + eps) & (np.maximum(ta, tb) >= s0 - eps)
    return np.where(colinear, col_ov, straddle)


def _seg_tri_coplanar(p, q, a, b, c, n, eps):
    drop = np.argmax(np.abs(n), axis=1)
    p2, q2, a2, b2, c2 = (_proj2(x, drop) for x in (p, q, a, b, c))
    # projected distances shrink by |n_drop|/|n| >= 1/sqrt(3): scale eps accordingly
    hit = _point_in_tri2(p2, a2, b2, c2, eps) | _point_in_tri2(q2, a2, b2, c2, eps)
    for u, v in ((a2, b2), (b2, c2), (c2, a2)):
        hit |= _seg_seg2(p2, q2, u, v, eps)
    return hit


def seg_tri(p, q, a, b, c, eps: float) -> np.ndarray:
    """Does the closed segment pq meet the closed triangle abc (tolerance eps, mm)?"""
    n = np.cross(b - a, c - a)
    nn = np.linalg.norm(n, axis=1)
    nh = n / np.maximum(nn, 1e-300)[:, None]
    dp = _dot(p - a, nh)
    dq = _dot(q - a, nh)
    res = np.zeros(len(p), bool)
    cop = (np.abs(dp) <= eps) & (np.abs(dq) <= eps)
    cross = ~cop & ~((dp > eps) & (dq > eps)) & ~((dp < -eps) & (dq < -eps))
    if cross.any():
        i = np.nonzero(cross)[0]
        dpi, dqi = dp[i], dq[i]
        den = dpi - dqi
        t = np.where(np.abs(den) > 0, dpi / np.where(den == 0, 1.0, den), 0.0)
        t = np.clip(t, 0.0, 1.0)
        x = p[i] + t[:, None] * (q[i] - p[i])
        # if an end lies on the plane (within eps) take that end exactly
        x = np.where((np.abs(dpi) <= eps)[:, None], p[i], x)
        x = np.where(((np.abs(dqi) <= eps) & (np.abs(dpi) > eps))[:, None], q[i], x)
        inside = np.ones(len(i), bool)
        nhi = nh[i]
        for u, v in ((a[i], b[i]), (b[i], c[i]), (c[i], a[i])):
            e = v - u
            d = _dot(np.cross(e, x - u), nhi) / np.maximum(np.linalg.norm(e, axis=1), 1e-300)
            inside &= d >= -eps
        res[i] = inside
    if cop.any():
        i = np.nonzero(cop)[0]
        res[i] = _seg_tri_coplanar(p[i], q[i], a[i], b[i], c[i], n[i], eps)
    return res


def _plane_separated(V, F, N, D, I, J, shared_j, eps):
    """Vertices of triangle J not shared with I all strictly on one side of I's plane."""
    d = np.einsum("kij,kj->ki", V[F[J]], N[I]) - D[I][:, None]
    pos = np.all((d > eps) | shared_j, axis=1)
    neg = np.all((d < -eps) | shared_j, axis=1)
    return (pos | neg) & ~np.all(shared_j, axis=1)


def _within_plane(V, F, N, D, I, J, eps):
    """All three vertices of triangle J within eps of the plane of triangle I."""
    d = np.einsum("kij,kj->ki", V[F[J]], N[I]) - D[I][:, None]
    return np.all(np.abs(d) <= eps, axis=1)


def _coplanar_overlap(ti, tj, n, share_vertex, eps):
    """Coplanar triangles (k,3,3): separating-axis test in the plane over the six edge normals.

    Without a shared vertex the closed triangles meet unless an axis shows a gap > eps (as the
    edge tests of the general path); sharing a vertex they always touch there, and meet only if
    no axis separates them with a gap >= -eps (interiors or an opposite edge overlap).
    """
    drop = np.argmax(np.abs(n), axis=1)
    keep = np.array([[1, 2], [0, 2], [0, 1]])[drop]  # (k,2)
    A = np.take_along_axis(ti, keep[:, None, :], axis=2)
    B = np.take_along_axis(tj, keep[:, None, :], axis=2)
    # projected lengths shrink by at most 1/sqrt(3): compare gaps on unit axes in the projection
    e = np.concatenate([np.roll(A, -1, axis=1) - A, np.roll(B, -1, axis=1) - B], axis=1)  # (k,6,2)
    ax = np.stack([-e[:, :, 1], e[:, :, 0]], axis=2)
    ax /= np.maximum(np.linalg.norm(ax, axis=2), 1e-300)[:, :, None]
    pa = np.einsum("kvd,kad->kva", A, ax)
    pb = np.einsum("kvd,kad->kva", B, ax)
    gap = np.maximum(pb.min(axis=1) - pa.max(axis=1), pa.min(axis=1) - pb.max(axis=1)).max(axis=1)
    return np.where(share_vertex, gap < -eps, gap <= eps)


def _pairs_intersect(V, F, I, J, eps, N=None, D=None):
    """Narrow phase for candidate pairs (I[k], J[k]); returns bool per pair.

    N, D: unit normals and plane offsets of all faces; when given, pairs that a
    plane separates (Moeller's early rejection, shared vertices ignored: a
    triangle touching the other's plane only at a shared vertex or edge does not
    cross it) are rejected before the exact tests.
    """
    hit = np.zeros(len(I), bool)
    fi, fj = F[I], F[J]
    eq = fi[:, :, None] == fj[:, None, :]  # (k,3,3)
    if N is not None:
        sep = _plane_separated(V, F, N, D, I, J, eq.any(axis=1), eps)
        sep |= _plane_separated(V, F, N, D, J, I, eq.any(axis=2), eps)
        # coplanar pairs sharing at most a vertex (the bulk on the planar faces of a prism): 2D test
        nsh = eq.any(axis=2).sum(axis=1)
        cop = ~sep & (nsh <= 1) & _within_plane(V, F, N, D, I, J, eps) & _within_plane(V, F, N, D, J, I, eps)
        k = np.nonzero(cop)[0]
        if len(k):
            hit[k] = _coplanar_overlap(V[fi[k]], V[fj[k]], N[I[k]], nsh[k] == 1, eps)
        live = np.nonzero(~sep & ~cop)[0]
        if len(live) < len(I):
            hit[live] = _pairs_intersect(V, F, I[live], J[live], eps)
            return hit
    nshared = eq.any(axis=2).sum(axis=1)
    hit[nshared == 3] = True

    # no shared vertex: any edge of one meets the other triangle
    k = np.nonzero(nshared == 0)[0]
    if len(k):
        ti, tj = V[fi[k]], V[fj[k]]
        h = np.zeros(len(k), bool)
        for s, t in ((ti, tj), (tj, ti)):
            for e0, e1 in ((0, 1), (1, 2), (2, 0)):
                todo = ~h
                if not todo.any():
                    break
                h[todo] = seg_tri(s[todo, e0], s[todo, e1], t[todo, 0], t[todo, 1], t[todo, 2], eps)
        hit[k] = h

    # one shared vertex: the edge opposite it in each triangle vs the other triangle
    k = np.nonzero(nshared == 1)[0]
    if len(k):
        e = eq[k]
        ia = np.argmax(e.any(axis=2), axis=1)  # index of the shared vertex in fi
        ja = np.argmax(e.any(axis=1), axis=1)
        ti, tj = V[fi[k]], V[fj[k]]
        r = np.arange(len(k))
        pi, qi = ti[r, (ia + 1) % 3], ti[r, (ia + 2) % 3]
        pj, qj = tj[r, (ja + 1) % 3], tj[r, (ja + 2) % 3]
        h = seg_tri(pi, qi, tj[:, 0], tj[:, 1], tj[:, 2], eps)
        todo = ~h
        if todo.any():
            h[todo] = seg_tri(pj[todo], qj[todo], ti[todo, 0], ti[todo, 1], ti[todo, 2], eps)
        hit[k] = h

    # shared edge: intersect only if folded onto each other (coplanar, same side)
    k = np.nonzero(nshared == 2)[0]
    if len(k):
        e = eq[k]
        ri = np.argmin(e.any(axis=2), axis=1)  # the unshared vertex of fi
        rj = np.argmin(e.any(axis=1), axis=1)
        r = np.arange(len(k))
        ti, tj = V[fi[k]], V[fj[k]]
        a = ti[r, ri]
        v0, v1 = ti[r, (ri + 1) % 3], ti[r, (ri + 2) % 3]
        b = tj[r, rj]
        n = np.cross(v1 - v0, a - v0)
        nh = n / np.maximum(np.linalg.norm(n, axis=1), 1e-300)[:, None]
        coplanar = np.abs(_dot(b - v0, nh)) <= eps
        same_side = _dot(np.cross(v1 - v0, a - v0), np.cross(v1 - v0, b - v0)) > 0
        hit[k] = coplanar & same_side
    return hit


def self_intersections(vertices, faces, eps: float | None = None, max_report: int = 100) -> tuple[int, np.ndarray]:
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
    pairs = ok[overlapping_pairs(lo, hi)]
    N = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    N /= np.maximum(np.linalg.norm(N, axis=1), 1e-300)[:, None]
    D = np.einsum("ij,ij->i", N, T[:, 0])
    count = 0
    found = []
    for s in range(0, len(pairs), _CHUNK):
        P = pairs[s : s + _CHUNK]
        h = _pairs_intersect(V, F, P[:, 0], P[:, 1], eps, N, D)
        count += int(h.sum())
        if len(found) < max_report:
            found.extend(P[h][: max_report - len(found)].tolist())
    return count, np.array(found, np.int64).reshape(-1, 2)


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
) -> list[Check]:
    """All validity checks of a closed triangle mesh (trimesh.Trimesh or (V, F)).

    chord_deflection: the tessellation's achieved deflection (mm); when not
    given it is taken from mesh.metadata['chord_deflection_mm'] if present.
    brep_volume: same as expected_volume (the B-rep volume the mesh must match).
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
    nx, pairs = self_intersections(V, F)
    msg = "no two triangles intersect (BVH + triangle-triangle test)"
    if nx:
        msg = f"{nx} intersecting triangle pairs, e.g. faces {pairs[:3].tolist()}"
    out.append(Check.equals(f"{name}: self-intersecting triangle pairs", nx, 0, "pairs", msg))
    if chord_deflection is None and not isinstance(mesh, tuple):
        chord_deflection = getattr(mesh, "metadata", {}).get("chord_deflection_mm")
    if chord_deflection is not None:
        out.append(Check.at_most(f"{name}: chord deflection", chord_deflection, MESH_CHORD_LIMIT_MM, "mm", "tessellation chord error (OCCT achieved deflection)"))
    if expected_volume is not None:
        out.append(
            Check.equal_within(f"{name}: volume vs B-rep", vol, expected_volume, rel_tol=volume_rel_tol, unit="mm^3")
        )
    return out
