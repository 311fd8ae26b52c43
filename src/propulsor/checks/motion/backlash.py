"""Free rotation of a body about a centre until first contact (the backlash search): every boundary
vertex runs on a circle; its first crossing of the other boundary is a circle-segment intersection."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from ...planar import norms
from .outlines import Outline
from .poses import _apply_pose_nb
from .nearest import disc_cells, grid_of
from ...npmath import atan2
from ...nbcache import bind

__all__ = ['free_rotation', 'free_rotations', 'rot_bounds']


_ANG_EPS = 1e-10  # rad: a hit this close to 0 is a touching contact, not a full turn


def _rot_hits(P: np.ndarray, C: np.ndarray, tgt: Outline, sign: float, w: float, rho: np.ndarray, lb: np.ndarray):
    """First entering hit of points P rotating by sign·δ about C (all in tgt's body frame) on tgt's boundary.

    rho: distance of each point from C; lb: lower bound of its distance from tgt's
    boundary (Outline.boundary_lower_bound).  Returns (delta, edge, t) per point: delta
    in [0, w] or inf when no entering hit happens within the window w; edge index
    and parameter of the hit (-1 and 0 with none).  An entering hit is one where the point's velocity
    points into tgt's material (material lies left of each edge), so exits and
    grazing touches do not count.

    A point is a candidate when a vertex of tgt lies within its reach (the chord its
    rotation by w sweeps, plus half the longest edge); its hits are sought on the two
    edges at every vertex within that reach whose distance from C is within an edge's length of the point's
    (compiled: :func:`_ring_pairs`, :func:`_rot_reduce`; the numpy formulation it reproduces bit for bit, every
    delta and the edge and t of every hit, is ``tests/rot_hits_reference.py``).
    """
    return _rot_hits_both(P, C, tgt, sign, w, None, rho, lb)[0]


def _target(tgt: Outline) -> tuple:
    """What the compiled rotation hits need of a target outline: its vertices, edges and vertex grid (level 0), as one
    tuple (cached on the outline)."""
    k = getattr(tgt, "_rot_target", None)
    if k is None:
        g = grid_of(tgt)
        k = tgt._rot_target = (tgt.points, g.seg_b, tgt.prev, float(tgt.half_len), float(g.origin[0]),
                               float(g.origin[1]), float(g.h), int(g.nx), int(g.ny), g.start, g.items, g.near)
    return k


def _rot_hits_both(P: np.ndarray, C: np.ndarray, tgt: Outline, sign: float, w: float, w_other: float | None,
                   rho: np.ndarray, lb: np.ndarray):
    """:func:`_rot_hits` of the points turning by ``sign`` within ``w`` and, where ``w_other`` is given, of the same
    points turning the other way within ``w_other``, from one search of their pairs: ((delta, edge, t), the other
    sense's or None).  The pairs are sought within the wider window and each sense keeps its entering roots within
    its own: a hit within the narrower window lies on an edge with an end within that window's reach, so the wider
    reach adds only pairs whose hits lie beyond it, never taken (and in the same order of the pairs, so the same
    first pair on a tie); the two senses' roots are the same, only which of them enter differs.  So each sense's
    hits are :func:`_rot_hits`'s of its own window, bit for bit (tests/test_backlash_kernel.py).  Compiled:
    :func:`_rot_hits_nb`."""
    both = w_other is not None
    d, e, t, d2, e2, t2 = _rot_hits_nb(np.ascontiguousarray(P, np.float64), float(C[0]), float(C[1]), _target(tgt),
                                       float(sign), float(w), float(w_other) if both else 0.0, both,
                                       np.ascontiguousarray(rho, np.float64), np.ascontiguousarray(lb, np.float64))
    return (d, e, t), ((d2, e2, t2) if both else None)


@njit(cache=True)
def _rot_hits_nb(P, cx, cy, tg, sign, w, w_other, both, rho, lb):
    """The hits of :func:`_rot_hits_both` (``both``: of the other sense too, within ``w_other``; else its arrays are
    empty), on the target ``tg`` (:func:`_target`): the pairs (:func:`_ring_pairs`), each root's angle numpy's
    arctan2 of its sine and cosine terms (:func:`propulsor.npmath.atan2`, the floats ``np.arctan2`` gives them), each
    sense's least entering hit (:func:`_rot_reduce`)."""
    wide = max(w, w_other) if both else w
    chord_factor = 2.0 * math.sin(0.5 * min(wide, math.pi))
    V, seg_b, prev, half_len, ox, oy, h, nx, ny, start, items, near = tg
    offs, seg, Y, X, T, ok, ok2 = _ring_pairs(P, cx, cy, V, seg_b, prev, half_len, ox, oy, h, nx, ny, start, items,
                                              near, sign, rho, lb, chord_factor, both)
    A = np.empty_like(Y)
    for k in range(len(Y)):
        for r in range(2):
            A[k, r] = atan2(Y[k, r], X[k, r])
    d, e, t = _rot_reduce(offs, seg, sign * A, T, ok, w)
    if both:
        d2, e2, t2 = _rot_reduce(offs, seg, -sign * A, T, ok2, w_other)
    else:
        d2, e2, t2 = np.empty(0), np.empty(0, np.int64), np.empty(0)
    return d, e, t, d2, e2, t2


@njit(cache=True, inline="always")
def _room(near, ix0, ix1, iy0, iy1, ny, start):
    """``near``, or a larger array, with room for every vertex of the cells ix0..ix1 x iy0..iy1: grown before a scan
    of the cells, not during it (an array variable reassigned inside a loop costs numba a reference count update
    at every turn of that loop: for the vertex scan, two atomic operations a vertex)."""
    total = 0
    for gx in range(ix0, ix1 + 1):
        for gy in range(iy0, iy1 + 1):
            c = gx * ny + gy
            total += start[c + 1] - start[c]
    if total <= len(near):
        return near
    return np.empty(max(total, 2 * len(near)), np.int64)


@njit(cache=True, inline="always")
def _edge_quadratic(ax, ay, dx, dy, r2):
    """The circle of radius² r2 about the origin against the edge a + t d (a relative to the centre): qa t² + qb t + qc
    = 0; (qa, qb, its discriminant)."""
    qa = dx * dx + dy * dy
    qb = 2.0 * (ax * dx + ay * dy)
    qc = (ax * ax + ay * ay) - r2
    return qa, qb, qb * qb - 4.0 * qa * qc


@njit(cache=True, inline="always")
def _edge_root(qa, qb, sq, real, r, ax, ay, dx, dy, sign):
    """Root r (0: the lesser) of :func:`_edge_quadratic` (sq: the discriminant's square root, 0 where not real): (t
    clipped to the edge, the point q = a + t d, whether it is an entering hit on the edge: a real root within the edge
    (1e-12 to spare) where the point turning by sign runs into the material, perp(q)·perp(d) = q·d of that sign)."""
    t = ((-qb - sq) if r == 0 else (-qb + sq)) / (2.0 * qa)
    valid = real and t >= -1e-12 and t <= 1.0 + 1e-12
    t = min(max(t, 0.0), 1.0)
    qx, qy = ax + t * dx, ay + t * dy
    return t, qx, qy, valid and sign * (qx * dx + qy * dy) > 0.0


@njit(cache=True, inline="always")
def _sort_few(near, n):
    """near[:n] in ascending order: an insertion sort for a few vertices (no allocation), numpy's sort for many (a
    window of many degrees: hundreds of vertices, n log n)."""
    if n <= 16:
        for a in range(1, n):
            x = near[a]
            b = a - 1
            while b >= 0 and near[b] > x:
                near[b + 1] = near[b]
                b -= 1
            near[b + 1] = x
    else:
        near[:n].sort()


@njit(cache=True)
def _ring_pairs(P, cx, cy, V, seg_b, prev, half_len, ox, oy, h, nx, ny, start, items, near_cell, sign, rho, lb,
                chord_factor, both):
    """The rotation hits' (point, edge) pairs of the backlash search (windows of up to a pitch, hundreds of vertices a
    point).

    For each point, the edges starting at each vertex within its reach (ascending), then the edges ending there
    (the order of ``tests/rot_hits_reference.py``); for each pair and both roots of the circle-edge intersection: the
    angle's sine and cosine terms (Y, X), the edge parameter (clipped) and whether the root is an entering hit on the
    edge (its angle is checked against the window afterwards).  A point whose reach is at most a cell and whose cell
    has no vertex within one cell (``near_cell``, :class:`.nearest.VertexGrid`) has none within its reach: skipped
    without a search.

    Two filters, neither of which can drop a hit.  The ring: the point's circle about (cx, cy) can meet an edge only
    near its radius rho: a root Q on an edge is within the edge's length (at most 2 ``half_len``) of both its ends, so
    a vertex (and a grid cell) whose distance from the centre differs from rho by more than that (1e-6 mm to spare)
    has no root on either of its edges, and is left out.  In a window of many degrees this leaves the vertices near
    one circle instead of a disc of them; it is tested only where the reach is wider than that annulus.  Entering
    only: a pair with no entering root is never taken (:func:`_rot_reduce`), so it is not kept.  (The as-built contact
    search's windows, a fraction of a milliradian and a few vertices a point, nearly all of them hitting, take the
    same pairs without the filters, which cost more there than they leave out, one point at a time:
    :func:`.contact_kernels._side_hits`.)

    ``both``: the pairs with an entering root for either sense kept, and ``ok2`` whether each root enters turning by
    -sign (else ``ok2`` is empty)."""
    m = len(P)
    offs = np.zeros(m + 1, np.int64)
    cap = 4096
    seg = np.empty(cap, np.int64)
    near = np.empty(min(len(V), 256), np.int64)  # grown on demand (an outline's size each call: a page mapping)
    band = 2.0 * half_len + 1e-6
    n_pairs = 0
    for i in range(m):
        offs[i] = n_pairs
        if not lb[i] <= chord_factor * rho[i]:
            continue
        reach = chord_factor * rho[i] + half_len + 1e-12
        px, py = P[i, 0], P[i, 1]
        if reach <= h:
            c0 = (min(max(int(math.floor((px - ox) / h)), 0), nx - 1) * ny
                  + min(max(int(math.floor((py - oy) / h)), 0), ny - 1))
            if not near_cell[c0]:
                continue
        ring = reach > 2.0 * band
        r_hi = rho[i] + band
        r_lo = max(rho[i] - band, 0.0)
        hi2, lo2 = r_hi * r_hi, r_lo * r_lo
        ix0, ix1, iy0, iy1 = disc_cells(px, py, reach, ox, oy, h, nx, ny)
        near = _room(near, ix0, ix1, iy0, iy1, ny, start)
        n = 0
        r2reach = reach * reach
        dx_lo = dx_hi = 0.0
        for gx in range(ix0, ix1 + 1):
            if ring:
                # the cell's distances from the centre (its box 1e-6 mm larger: a vertex on its border may be
                # filed in it)
                x0, x1 = ox + gx * h - 1e-6 - cx, ox + (gx + 1) * h + 1e-6 - cx
                dx_lo = x0 if x0 > 0.0 else (-x1 if x1 < 0.0 else 0.0)
                dx_hi = max(-x0, x1)
            for gy in range(iy0, iy1 + 1):
                if ring:
                    y0, y1 = oy + gy * h - 1e-6 - cy, oy + (gy + 1) * h + 1e-6 - cy
                    dy_lo = y0 if y0 > 0.0 else (-y1 if y1 < 0.0 else 0.0)
                    dy_hi = max(-y0, y1)
                    if dx_lo * dx_lo + dy_lo * dy_lo > hi2 or dx_hi * dx_hi + dy_hi * dy_hi < lo2:
                        continue
                c = gx * ny + gy
                for kk in range(start[c], start[c + 1]):
                    v = items[kk]
                    ex, ey = px - V[v, 0], py - V[v, 1]
                    if ex * ex + ey * ey <= r2reach:
                        if ring:
                            fx, fy = V[v, 0] - cx, V[v, 1] - cy
                            f2 = fx * fx + fy * fy
                            if f2 > hi2 or f2 < lo2:
                                continue
                        near[n] = v
                        n += 1
        if n == 0:
            continue
        _sort_few(near, n)
        if n_pairs + 2 * n > cap:
            while n_pairs + 2 * n > cap:
                cap *= 2
            grown = np.empty(cap, np.int64)
            grown[:n_pairs] = seg[:n_pairs]
            seg = grown
        for j in range(n):
            seg[n_pairs + j] = near[j]
            seg[n_pairs + n + j] = prev[near[j]]
        n_pairs += 2 * n
    offs[m] = n_pairs
    Y = np.empty((n_pairs, 2))
    X = np.empty((n_pairs, 2))
    T = np.empty((n_pairs, 2))
    ok = np.zeros((n_pairs, 2), np.bool_)
    ok2 = np.zeros((n_pairs if both else 0, 2), np.bool_)
    kept = 0
    for i in range(m):
        ppx, ppy = P[i, 0] - cx, P[i, 1] - cy
        r2 = rho[i] * rho[i]
        first = offs[i]
        offs[i] = kept
        for k in range(first, offs[i + 1]):
            s = seg[k]
            ax, ay = V[s, 0] - cx, V[s, 1] - cy
            dx, dy = seg_b[s, 0] - V[s, 0], seg_b[s, 1] - V[s, 1]
            qa, qb, disc = _edge_quadratic(ax, ay, dx, dy, r2)
            real = disc >= 0.0
            if not real:
                continue  # no root: no hit on this edge
            sq = math.sqrt(disc)
            any_ok = False
            for r in range(2):
                t, qx, qy, e = _edge_root(qa, qb, sq, real, r, ax, ay, dx, dy, sign)
                Y[kept, r] = ppx * qy - ppy * qx
                X[kept, r] = ppx * qx + ppy * qy
                T[kept, r] = t
                ok[kept, r] = e
                any_ok = any_ok or e
                if both:
                    e2 = _edge_root(qa, qb, sq, real, r, ax, ay, dx, dy, -sign)[3]
                    ok2[kept, r] = e2
                    any_ok = any_ok or e2
            if any_ok:
                seg[kept] = s
                kept += 1
    offs[m] = kept
    return offs, seg[:kept], Y[:kept], X[:kept], T[:kept], ok[:kept], ok2[:kept if both else 0]


@njit(cache=True)
def _rot_reduce(offs, seg, ang, T, ok, w):
    """Per point: the least entering hit within the window over its pairs (the first pair on a tie); inf, edge -1
    and t 0 with none."""
    m = len(offs) - 1
    delta = np.full(m, np.inf)
    edge = np.full(m, -1, np.int64)
    tpar = np.zeros(m)
    for i in range(m):
        best, best_e, best_t = np.inf, -1, 0.0
        for k in range(offs[i], offs[i + 1]):
            pb, pt = np.inf, 0.0
            for r in range(2):
                a = ang[k, r]
                if a != a:
                    continue
                a = a + 2.0 * math.pi if a < -_ANG_EPS else (a if a > 0.0 else 0.0)
                if ok[k, r] and a <= w and a < pb:
                    pb, pt = a, T[k, r]
            if pb < best:
                best, best_e, best_t = pb, seg[k], pt
        if best_e >= 0:
            delta[i], edge[i], tpar[i] = best, best_e, best_t
    return delta, edge, tpar


@njit(cache=True)
def _rot_bounds_nb(P, cx, cy, ox, oy, radius, r_min):
    """(rho, lb) of :func:`rot_bounds`, one pass over the points: the operations of ``norms(P - C)`` and
    ``Outline.boundary_lower_bound`` (each difference squared, the squares added, the root; the annulus' two
    gaps and the greater), so the same floats without their temporary arrays."""
    n = len(P)
    rho = np.empty(n)
    lb = np.empty(n)
    for i in range(n):
        x, y = P[i, 0], P[i, 1]
        dx, dy = x - cx, y - cy
        rho[i] = math.sqrt(dx * dx + dy * dy)
        ex, ey = x - ox, y - oy
        d = math.sqrt(ex * ex + ey * ey)
        a, b = d - radius, r_min - d
        lb[i] = a if a >= b else b
    return rho, lb


def rot_bounds(P: np.ndarray, C, tgt: Outline) -> tuple[np.ndarray, np.ndarray]:
    """The two arrays :func:`free_rotation` takes for points P turning about C (both in ``tgt``'s body frame): each
    point's distance from C (``norms(P - C)``) and the lower bound of its distance from ``tgt``'s boundary
    (``tgt.boundary_lower_bound(P)``), the same floats, compiled for the float64 (n, 2) arrays the proofs pass (a
    whole-cycle proof asks for them at every step, for thousands of vertices a side)."""
    P = np.asarray(P)
    if P.dtype != np.float64 or P.ndim != 2 or P.shape[1] != 2:
        return norms(P - np.asarray(C, float)), tgt.boundary_lower_bound(P)
    return _rot_bounds_nb(np.ascontiguousarray(P), float(C[0]), float(C[1]), float(tgt.center[0]),
                          float(tgt.center[1]), float(tgt.radius), float(tgt.r_min))


@dataclass
class _FreeRotation:
    delta: float  # free rotation (rad, >= 0), inf if none within the search limit
    n_pairs: int  # distinct contact zones within the contact tolerance at the touching position
    point: np.ndarray  # world point of the first contact (nan if none)


@njit(cache=True)
def _zones_nb(d1, rho1, d2, rho2, e2, t2, dmin, tol, arclen, seg_len, loop_id, perimeter, merge):
    """The contact zones of :func:`free_rotation` at its touching position, one compiled pass: the points whose gap
    (the arc at their radius, ``(d - dmin) rho``) is within ``tol``, placed by arc length along the driven outline
    (side 1 its vertices, side 2 their hits on its edges), and counted: each loop's positions sorted, their gaps
    with the wrap-around, a group for each gap beyond ``merge``, at least one a loop (``tests/test_backlash_kernel.py``
    holds it to the numpy formulation it replaced)."""
    pos = np.empty(len(d1) + len(d2))
    loop = np.empty(len(d1) + len(d2), np.int64)
    m = 0
    for i in range(len(d1)):
        if math.isfinite(d1[i]) and (d1[i] - dmin) * rho1[i] <= tol:
            pos[m], loop[m] = arclen[i], loop_id[i]
            m += 1
    for i in range(len(d2)):
        if math.isfinite(d2[i]) and (d2[i] - dmin) * rho2[i] <= tol:
            e = e2[i]
            pos[m], loop[m] = arclen[e] + t2[i] * seg_len[e], loop_id[e]
            m += 1
    pos, loop = pos[:m], loop[:m]
    order = np.argsort(loop, kind="mergesort")
    n = 0
    a = 0
    while a < m:
        lid = loop[order[a]]
        b = a
        while b < m and loop[order[b]] == lid:
            b += 1
        s = np.sort(pos[order[a:b]])
        k = 0
        for q in range(b - a - 1):
            if s[q + 1] - s[q] > merge:
                k += 1
        if (s[0] + perimeter[lid]) - s[b - a - 1] > merge:
            k += 1
        n += max(k, 1)
        a = b
    return n


def _zone_args(dvn: Outline) -> tuple:
    """What the compiled free rotation needs of the driven outline beyond its target: its vertices and edges, and
    the arc-length places of :func:`_zones_nb` (one tuple, cached on the outline)."""
    k = getattr(dvn, "_zone_args", None)
    if k is None:
        k = dvn._zone_args = (dvn.points, dvn.seg_a, dvn.seg_b, dvn.arclen, dvn.seg_len, dvn.loop_id, dvn.perimeter)
    return k


@njit(cache=True)
def _free_rotation_nb(given, first, P1, c1x, c1y, P2, rho1, lb1, rho2, lb2, M2, body_sign, w0, w_max, tol, merge,
                      tg_drv, tg_dvn, zone):
    """:func:`free_rotation`, compiled: (delta, pairs, world point x, y); ``given``: ``first`` holds the two sides'
    hits within w0 ((d1, e1, t1, d2, e2, t2), :func:`free_rotations`)."""
    pts, seg_a, seg_b, arclen, seg_len, loop_id, perimeter = zone
    w = w0
    d1, e1, t1, d2, e2, t2 = first
    while True:
        if given:
            given = False
        else:
            d1, e1, t1, _a, _b, _c = _rot_hits_nb(P1, c1x, c1y, tg_drv, body_sign, w, 0.0, False, rho1, lb1)
            d2, e2, t2, _a, _b, _c = _rot_hits_nb(P2, 0.0, 0.0, tg_dvn, -body_sign, w, 0.0, False, rho2, lb2)
        dmin = min(d1.min(), d2.min())
        if not math.isfinite(dmin):
            if w >= w_max:
                return math.inf, 0, math.nan, math.nan
            w = min(4.0 * w, w_max)
            continue
        r1 = np.inf
        for i in range(len(d1)):
            if math.isfinite(d1[i]) and rho1[i] < r1:
                r1 = rho1[i]
        r2 = np.inf
        for i in range(len(d2)):
            if math.isfinite(d2[i]) and rho2[i] < r2:
                r2 = rho2[i]
        rmin = max(min(r1, r2), 1e-9)
        need = dmin + 2.0 * tol / rmin
        if need > w and w < w_max:
            w = min(need, w_max)
            continue
        break
    # contact zones at the touching position: gap (arc at the point's radius) within tol
    n_pairs = _zones_nb(d1, rho1, d2, rho2, e2, t2, dmin, tol, arclen, seg_len, loop_id, perimeter, merge)
    # world point of the first contact (driven rotated into contact)
    if d1.min() <= d2.min():
        i = np.argmin(d1)
        px, py = pts[i, 0], pts[i, 1]
    else:
        i = np.argmin(d2)
        k = e2[i]
        px = seg_a[k, 0] + t2[i] * (seg_b[k, 0] - seg_a[k, 0])
        py = seg_a[k, 1] + t2[i] * (seg_b[k, 1] - seg_a[k, 1])
    ang = body_sign * dmin
    c, s = math.cos(ang), math.sin(ang)
    q = np.empty((1, 2))
    q[0, 0], q[0, 1] = c * px - s * py, s * px + c * py
    pw = _apply_pose_nb(M2, q)
    return dmin, n_pairs, pw[0, 0], pw[0, 1]


_NO_HITS = (np.empty(0), np.empty(0, np.int64), np.empty(0), np.empty(0), np.empty(0, np.int64), np.empty(0))


def free_rotation(drv: Outline, dvn: Outline, P1: np.ndarray, C1: np.ndarray, P2: np.ndarray,
                   rho1: np.ndarray, lb1: np.ndarray, rho2: np.ndarray, lb2: np.ndarray,
                   M2: np.ndarray, body_sign: float, w0: float, w_max: float, tol: float, merge: float,
                   first: tuple | None = None) -> _FreeRotation:
    """Free rotation of the driven body (body sense body_sign) until first contact with the driver.

    P1: driven vertices in the driver frame, C1: driven centre in the driver frame;
    P2: driver vertices in the driven frame (driven centre at its origin);
    rho*/lb*: their distances from the rotation centre / lower bounds of their
    distances from the other body; M2: the driven body's pose (2x3).
    Side 1: driven vertices hit driver edges, rotating by +body_sign about C1.
    Side 2: driver vertices hit driven edges, rotating by −body_sign about 0.
    The window grows from w0 (x4 up to w_max) until it holds a hit and the contact zones' tolerance past it.
    ``first``: the two sides' hits within the window w0, when already found (:func:`free_rotations`).
    Compiled: :func:`_free_rotation_nb` (the Python formulation it replaced, bit for bit:
    tests/transmission_reference.py).
    """
    f64 = lambda a: np.ascontiguousarray(a, np.float64)  # noqa: E731
    hits = _NO_HITS if first is None else tuple(first[0]) + tuple(first[1])
    d, n, x, y = _free_rotation_nb(first is not None, hits, f64(P1), float(C1[0]), float(C1[1]), f64(P2), f64(rho1),
                                   f64(lb1), f64(rho2), f64(lb2), f64(M2), float(body_sign), float(w0), float(w_max),
                                   float(tol), float(merge), _target(drv), _target(dvn), _zone_args(dvn))
    return _FreeRotation(float(d), int(n), np.array([x, y]))


def free_rotations(drv: Outline, dvn: Outline, P1: np.ndarray, C1: np.ndarray, P2: np.ndarray,
                   rho1: np.ndarray, lb1: np.ndarray, rho2: np.ndarray, lb2: np.ndarray, M2: np.ndarray,
                   body_sign: float, w_this: float, w_other: float, w_max: float, tol: float,
                   merge: float) -> tuple[_FreeRotation, _FreeRotation]:
    """:func:`free_rotation` of the driven body both ways at one position: turning by ``body_sign`` (first window
    ``w_this``) and by ``-body_sign`` (``w_other``), the same results, each side's pairs of the first windows sought
    once for both (:func:`_rot_hits_both`: where a window must grow, that sense searches on alone).  Compiled:
    :func:`_free_rotations_nb`."""
    f64 = lambda a: np.ascontiguousarray(a, np.float64)  # noqa: E731
    got = _free_rotations_nb(f64(P1), float(C1[0]), float(C1[1]), f64(P2), f64(rho1), f64(lb1), f64(rho2), f64(lb2),
                             f64(M2), float(body_sign), float(w_this), float(w_other), float(w_max), float(tol),
                             float(merge), _target(drv), _target(dvn), _zone_args(dvn))
    return tuple(_FreeRotation(float(d), int(n), np.array([x, y])) for d, n, x, y in got)


@njit(cache=True)
def _free_rotations_nb(P1, c1x, c1y, P2, rho1, lb1, rho2, lb2, M2, body_sign, w_this, w_other, w_max, tol, merge,
                       tg_drv, tg_dvn, zone):
    """:func:`free_rotations`, compiled: the two senses' (delta, pairs, x, y)."""
    a1, b1, c1, a2, b2, c2 = _rot_hits_nb(P1, c1x, c1y, tg_drv, body_sign, w_this, w_other, True, rho1, lb1)
    a3, b3, c3, a4, b4, c4 = _rot_hits_nb(P2, 0.0, 0.0, tg_dvn, -body_sign, w_this, w_other, True, rho2, lb2)
    one = _free_rotation_nb(True, (a1, b1, c1, a3, b3, c3), P1, c1x, c1y, P2, rho1, lb1, rho2, lb2, M2, body_sign,
                            w_this, w_max, tol, merge, tg_drv, tg_dvn, zone)
    other = _free_rotation_nb(True, (a2, b2, c2, a4, b4, c4), P1, c1x, c1y, P2, rho1, lb1, rho2, lb2, M2, -body_sign,
                              w_other, w_max, tol, merge, tg_drv, tg_dvn, zone)
    return one, other


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
