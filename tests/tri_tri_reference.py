"""The vectorised (numpy) narrow phase the self-intersection check used before it was compiled
(propulsor.checks.tri_tri): kept as the reference the compiled one is tested against, pair by pair."""

import numpy as np


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


def _plane_distances(V, F, N, D, I, J):
    """Signed distances (k, 3) of the vertices of triangle J from the plane of triangle I."""
    return np.einsum("kij,kj->ki", V[F[J]], N[I]) - D[I][:, None]


def _plane_separated(d, shared_j, eps):
    """Vertices of triangle J (distances d from I's plane) not shared with I all strictly on one side of it."""
    pos = np.all((d > eps) | shared_j, axis=1)
    neg = np.all((d < -eps) | shared_j, axis=1)
    return (pos | neg) & ~np.all(shared_j, axis=1)


def _within_plane(d, eps):
    """All three vertices of triangle J (distances d from I's plane) within eps of it."""
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
        d_j, d_i = _plane_distances(V, F, N, D, I, J), _plane_distances(V, F, N, D, J, I)
        sep = _plane_separated(d_j, eq.any(axis=1), eps)
        sep |= _plane_separated(d_i, eq.any(axis=2), eps)
        # coplanar pairs sharing at most a vertex (the bulk on the planar faces of a prism): 2D test
        nsh = eq.any(axis=2).sum(axis=1)
        cop = ~sep & (nsh <= 1) & _within_plane(d_j, eps) & _within_plane(d_i, eps)
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
