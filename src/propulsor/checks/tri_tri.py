"""Do two triangles of a mesh intersect?  The narrow phase of the self-intersection check
(:func:`propulsor.checks.mesh.self_intersections`), compiled with numba: one loop over the candidate
pairs the bounding-volume hierarchy gives, every pair decided alone.

A pair intersects when the closed triangles share a point that is not a vertex or an edge they share
in the mesh (tolerance `eps`, a distance in mm):

* no shared vertex: an edge of one meets the other triangle (segment–triangle test; coplanar: in the
  plane of the larger normal component);
* one shared vertex: the edge opposite it in either triangle meets the other;
* a shared edge: only when folded onto each other (the unshared vertices coplanar, same side);
* three shared vertices: a duplicated triangle.

Before those, a pair whose unshared vertices all lie strictly on one side of the other's plane is
apart (Möller's rejection), and a coplanar pair sharing at most a vertex (the bulk on the planar faces
of a prism) is decided by separating axes in the plane (six edge normals): without a shared vertex
they meet unless an axis shows a gap > eps; sharing one, they always touch there and meet only if no
axis separates them with a gap >= -eps.
"""

from __future__ import annotations

import numpy as np
from numba import njit
from ..nbcache import bind

__all__ = ["pairs_intersect"]


@njit(cache=True, inline="always")
def _orient2(ax, ay, bx, by, cx, cy):
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


@njit(cache=True, inline="always")
def _keep_axes(drop):
    """The two coordinates kept when coordinate `drop` is dropped."""
    if drop == 0:
        return 1, 2
    if drop == 1:
        return 0, 2
    return 0, 1


@njit(cache=True, inline="always")
def _argmax_abs(n0, n1, n2):
    a0, a1, a2 = abs(n0), abs(n1), abs(n2)
    if a0 >= a1 and a0 >= a2:
        return 0
    if a1 >= a2:
        return 1
    return 2


@njit(cache=True, inline="always")
def _pit2(px, py, ax, ay, bx, by, cx, cy, eps):
    """Point in the closed triangle abc (2D, tolerance eps)."""
    s = np.sign(_orient2(ax, ay, bx, by, cx, cy))
    ln = max(np.sqrt((bx - ax) ** 2 + (by - ay) ** 2), 1e-300)
    if not (s * _orient2(ax, ay, bx, by, px, py) / ln >= -eps):
        return False
    ln = max(np.sqrt((cx - bx) ** 2 + (cy - by) ** 2), 1e-300)
    if not (s * _orient2(bx, by, cx, cy, px, py) / ln >= -eps):
        return False
    ln = max(np.sqrt((ax - cx) ** 2 + (ay - cy) ** 2), 1e-300)
    return s * _orient2(cx, cy, ax, ay, px, py) / ln >= -eps


@njit(cache=True, inline="always")
def _ss2(px, py, qx, qy, ax, ay, bx, by, eps):
    """Closed 2D segments pq and ab meet (tolerance eps)."""
    lpq = max(np.sqrt((qx - px) ** 2 + (qy - py) ** 2), 1e-300)
    lab = max(np.sqrt((bx - ax) ** 2 + (by - ay) ** 2), 1e-300)
    d1 = _orient2(px, py, qx, qy, ax, ay) / lpq
    d2 = _orient2(px, py, qx, qy, bx, by) / lpq
    if abs(d1) <= eps and abs(d2) <= eps:  # collinear: overlap of the projections on pq
        tx, ty = (qx - px) / lpq, (qy - py) / lpq
        ta = (ax - px) * tx + (ay - py) * ty
        tb = (bx - px) * tx + (by - py) * ty
        return min(ta, tb) <= lpq + eps and max(ta, tb) >= -eps
    d3 = _orient2(ax, ay, bx, by, px, py) / lab
    d4 = _orient2(ax, ay, bx, by, qx, qy) / lab
    return min(d1, d2) <= eps and max(d1, d2) >= -eps and min(d3, d4) <= eps and max(d3, d4) >= -eps


@njit(cache=True, inline="always")
def _edge_side(ux, uy, uz, vx, vy, vz, x0, x1, x2, nx, ny, nz, eps):
    """x on the inner side of the edge uv (within eps) in the plane of unit normal n."""
    ex, ey, ez = vx - ux, vy - uy, vz - uz
    wx, wy, wz = x0 - ux, x1 - uy, x2 - uz
    cx, cy, cz = ey * wz - ez * wy, ez * wx - ex * wz, ex * wy - ey * wx
    ln = max(np.sqrt(ex * ex + ey * ey + ez * ez), 1e-300)
    return (cx * nx + cy * ny + cz * nz) / ln >= -eps


@njit(cache=True)
def _seg_tri(T, s, e0, e1, U, eps):
    """The closed segment T[s][e0] T[s][e1] meets the closed triangle U (tolerance eps).  T: (2, 3, 3)."""
    px, py, pz = T[s, e0, 0], T[s, e0, 1], T[s, e0, 2]
    qx, qy, qz = T[s, e1, 0], T[s, e1, 1], T[s, e1, 2]
    ax, ay, az = T[U, 0, 0], T[U, 0, 1], T[U, 0, 2]
    bx, by, bz = T[U, 1, 0], T[U, 1, 1], T[U, 1, 2]
    cx, cy, cz = T[U, 2, 0], T[U, 2, 1], T[U, 2, 2]
    ux, uy, uz = bx - ax, by - ay, bz - az
    vx, vy, vz = cx - ax, cy - ay, cz - az
    n0, n1, n2 = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    nn = max(np.sqrt(n0 * n0 + n1 * n1 + n2 * n2), 1e-300)
    hx, hy, hz = n0 / nn, n1 / nn, n2 / nn
    dp = (px - ax) * hx + (py - ay) * hy + (pz - az) * hz
    dq = (qx - ax) * hx + (qy - ay) * hy + (qz - az) * hz
    if abs(dp) <= eps and abs(dq) <= eps:  # in the plane: 2D tests in the plane of the larger normal component
        i, j = _keep_axes(_argmax_abs(n0, n1, n2))
        p2x, p2y, q2x, q2y = T[s, e0, i], T[s, e0, j], T[s, e1, i], T[s, e1, j]
        a2x, a2y, b2x, b2y, c2x, c2y = T[U, 0, i], T[U, 0, j], T[U, 1, i], T[U, 1, j], T[U, 2, i], T[U, 2, j]
        if _pit2(p2x, p2y, a2x, a2y, b2x, b2y, c2x, c2y, eps) or _pit2(q2x, q2y, a2x, a2y, b2x, b2y, c2x, c2y, eps):
            return True
        return (_ss2(p2x, p2y, q2x, q2y, a2x, a2y, b2x, b2y, eps) or _ss2(p2x, p2y, q2x, q2y, b2x, b2y, c2x, c2y, eps)
                or _ss2(p2x, p2y, q2x, q2y, c2x, c2y, a2x, a2y, eps))
    if (dp > eps and dq > eps) or (dp < -eps and dq < -eps):
        return False
    if abs(dp) <= eps:  # an end on the plane: that end exactly
        x0, x1, x2 = px, py, pz
    elif abs(dq) <= eps:
        x0, x1, x2 = qx, qy, qz
    else:
        den = dp - dq
        t = dp / den if abs(den) > 0 else 0.0
        t = min(max(t, 0.0), 1.0)
        x0, x1, x2 = px + t * (qx - px), py + t * (qy - py), pz + t * (qz - pz)
    return (_edge_side(ax, ay, az, bx, by, bz, x0, x1, x2, hx, hy, hz, eps)
            and _edge_side(bx, by, bz, cx, cy, cz, x0, x1, x2, hx, hy, hz, eps)
            and _edge_side(cx, cy, cz, ax, ay, az, x0, x1, x2, hx, hy, hz, eps))


@njit(cache=True)
def _coplanar_overlap(T, n0, n1, n2, share_vertex, eps):
    """Coplanar triangles T[0], T[1]: separating axes in the plane over the six edge normals."""
    i, j = _keep_axes(_argmax_abs(n0, n1, n2))
    gap = -np.inf
    for k in range(6):
        t = 0 if k < 3 else 1
        m = k % 3
        ex = T[t, (m + 1) % 3, i] - T[t, m, i]
        ey = T[t, (m + 1) % 3, j] - T[t, m, j]
        ln = max(np.sqrt(ey * ey + ex * ex), 1e-300)
        axx, axy = -ey / ln, ex / ln
        amin, amax, bmin, bmax = np.inf, -np.inf, np.inf, -np.inf
        for v in range(3):
            pa = T[0, v, i] * axx + T[0, v, j] * axy
            pb = T[1, v, i] * axx + T[1, v, j] * axy
            amin, amax = min(amin, pa), max(amax, pa)
            bmin, bmax = min(bmin, pb), max(bmax, pb)
        gap = max(gap, max(bmin - amax, amin - bmax))
    return gap < -eps if share_vertex else gap <= eps


@njit(cache=True, inline="always")
def _pair(V, F, i, j, N, D, eps, T, sh, d):
    """Pair (i, j) of the faces F; T (2, 3, 3), sh (2, 3) bool, d (2, 3): work arrays (I first, J second).  Inlined
    in the loop over the pairs and reading the rows by index (not as views ``F[i]``, ``N[i]``: seven array views a pair,
    each a reference count updated twice): the same operations on the same floats, a pair 1.3-1.8 times faster."""
    for a in range(3):
        for c in range(3):
            T[0, a, c] = V[F[i, a], c]
            T[1, a, c] = V[F[j, a], c]
        sh[0, a] = False
        sh[1, a] = False
    Ni0, Ni1, Ni2, Di = N[i, 0], N[i, 1], N[i, 2], D[i]
    Nj0, Nj1, Nj2, Dj = N[j, 0], N[j, 1], N[j, 2], D[j]
    for a in range(3):
        for b in range(3):
            if F[i, a] == F[j, b]:
                sh[0, a] = True
                sh[1, b] = True
    nsh = int(sh[0, 0]) + int(sh[0, 1]) + int(sh[0, 2])
    if nsh == 3:
        return True
    # Möller's rejection: the unshared vertices of one strictly on one side of the other's plane
    for b in range(3):
        d[1, b] = T[1, b, 0] * Ni0 + T[1, b, 1] * Ni1 + T[1, b, 2] * Ni2 - Di
        d[0, b] = T[0, b, 0] * Nj0 + T[0, b, 1] * Nj1 + T[0, b, 2] * Nj2 - Dj
    within = True
    for t in (1, 0):
        pos = True
        neg = True
        for b in range(3):
            if not (d[t, b] > eps or sh[t, b]):
                pos = False
            if not (d[t, b] < -eps or sh[t, b]):
                neg = False
            if not abs(d[t, b]) <= eps:
                within = False
        if pos or neg:
            return False
    if nsh <= 1 and within:
        return _coplanar_overlap(T, Ni0, Ni1, Ni2, nsh == 1, eps)
    if nsh == 0:
        for s in (0, 1):
            for e in range(3):
                if _seg_tri(T, s, e, (e + 1) % 3, 1 - s, eps):
                    return True
        return False
    if nsh == 1:  # the edge opposite the shared vertex in each against the other
        ia = 0 if sh[0, 0] else (1 if sh[0, 1] else 2)
        ja = 0 if sh[1, 0] else (1 if sh[1, 1] else 2)
        if _seg_tri(T, 0, (ia + 1) % 3, (ia + 2) % 3, 1, eps):
            return True
        return _seg_tri(T, 1, (ja + 1) % 3, (ja + 2) % 3, 0, eps)
    # a shared edge: folded onto each other (coplanar, the unshared vertices on the same side)
    ri = 0 if not sh[0, 0] else (1 if not sh[0, 1] else 2)
    rj = 0 if not sh[1, 0] else (1 if not sh[1, 1] else 2)
    v0, v1 = (ri + 1) % 3, (ri + 2) % 3
    ex, ey, ez = T[0, v1, 0] - T[0, v0, 0], T[0, v1, 1] - T[0, v0, 1], T[0, v1, 2] - T[0, v0, 2]
    ax, ay, az = T[0, ri, 0] - T[0, v0, 0], T[0, ri, 1] - T[0, v0, 1], T[0, ri, 2] - T[0, v0, 2]
    bx, by, bz = T[1, rj, 0] - T[0, v0, 0], T[1, rj, 1] - T[0, v0, 1], T[1, rj, 2] - T[0, v0, 2]
    n0, n1, n2 = ey * az - ez * ay, ez * ax - ex * az, ex * ay - ey * ax
    m0, m1, m2 = ey * bz - ez * by, ez * bx - ex * bz, ex * by - ey * bx
    nn = max(np.sqrt(n0 * n0 + n1 * n1 + n2 * n2), 1e-300)
    return abs((bx * n0 + by * n1 + bz * n2) / nn) <= eps and n0 * m0 + n1 * m1 + n2 * m2 > 0


@njit(cache=True)
def _pairs(V, F, I, J, N, D, eps):
    out = np.zeros(len(I), np.bool_)
    T = np.empty((2, 3, 3))
    sh = np.empty((2, 3), np.bool_)
    d = np.empty((2, 3))
    for k in range(len(I)):
        i, j = I[k], J[k]
        out[k] = _pair(V, F, i, j, N, D, eps, T, sh, d)
    return out


def pairs_intersect(V: np.ndarray, F: np.ndarray, I: np.ndarray, J: np.ndarray, N: np.ndarray, D: np.ndarray,
                    eps: float) -> np.ndarray:
    """For candidate pairs (I[k], J[k]) of triangles of the mesh (V (n, 3) float, F (m, 3) int), with the
    faces' unit normals N and plane offsets D (N·x = D): whether they intersect (see the module)."""
    return _pairs(np.ascontiguousarray(V, np.float64), np.ascontiguousarray(F, np.int64),
                  np.ascontiguousarray(I, np.int64), np.ascontiguousarray(J, np.int64),
                  np.ascontiguousarray(N, np.float64), np.ascontiguousarray(D, np.float64), float(eps))


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
