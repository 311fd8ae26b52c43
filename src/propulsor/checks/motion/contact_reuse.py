"""The candidate vertices of one pose of the contact search reused at the poses after it (the chained as-built search:
thousands of positions a cycle, each a fraction of a milliradian from the one before).

At a *refresh* pose the window's vertices (widened by an angle) are sorted into candidates, whose least distance to
the mate's boundary is within a slack ``S`` of their reach (the chord their turn through ``W`` sweeps), and the rest.
A vertex's distance is bounded from below by its nearest vertex of the mate less half the mate's longest edge (every
boundary point lies that close to a vertex), read on the mate's vertex grid; where that leaves it within the slack,
by its exact distance to the mate's edges (:func:`_boundary_distance`: up to that half length more, about half as
many candidates a pose as the vertex bound kept); the rest are bounded per run of ``chunk`` vertices
(:func:`.contact_kernels._pruned_window`'s runs) by their least excess over their reach, ``E``.

At a later pose, a rigid motion ``M`` away in the mate's frame (a turn by ``alpha``), a vertex ``q`` of a run whose
bounding circle (centre ``P0``, radius ``r``) was placed at ``P0`` has moved by at most
``|M(P0) - P0| + 2 |sin(alpha / 2)| r`` (``disp``); its distance to the boundary has fallen by at most that, and its
distance from the turning centre (``rho``) grown by at most that plus the centre's own move ``dC``.  While every run
keeps ``disp (1 + chord_W) + chord_W dC + 1e-6 < E`` no vertex left out can come within reach of the boundary
(``w <= W``; the current window inside the widened one): the candidates are every vertex that can hit.  Of them, those
whose distance bound at the refresh less their own move still exceeds their reach by 1e-6 mm are left out as well.
The rest go to :func:`.contact_kernels._side_hits` in the window's own order (ascending polar-angle position): a
vertex that cannot hit gives no hit, so the first least hit is the one of :func:`.contact_kernels._first_hit_pruned`,
bit for bit.  Where a run fails the test, the candidates are sorted again at the current pose.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from numba.typed import List

from .contact_kernels import (_bound_and_cell, _boundary_bound, _least, _placed, _side_hits, _window_bounds,
                              _window_runs, _window_size)
from .nearest import _edge_distance, _nearest_vertex
from ...nbcache import bind


@njit(cache=True)
def empty_cache():
    """A cache that holds nothing (the first pose refreshes it)."""
    return (np.zeros(12), np.zeros(0, np.int64), np.zeros((0, 4)), np.zeros((0, 2), np.int64), np.zeros((0, 3)))


@njit(cache=True)
def new_caches(n):
    """A list of ``n`` slots, each (driven side's cache, driver side's cache), empty: the caches a search keeps between
    calls (one slot per chain of nearby poses: the sampled run, the bisection of one change of state)."""
    out = List()
    for _ in range(n):
        out.append((empty_cache(), empty_cache()))
    return out


@njit(cache=True)
def seed_slots(caches, first, kept, index):
    """Slot ``first + k`` given the caches ``kept[index[k]]`` (kept by :func:`.contact_track.track` after a position):
    a search near that position reuses its candidates where they still hold (``_still_valid``) and sorts its own
    where they do not, the same hits either way."""
    for k in range(len(index)):
        caches[first + k] = kept[index[k]]


@njit(cache=True)
def add_slots(caches, n):
    """``n`` more empty slots at the end of ``caches``; the index of the first."""
    k = len(caches)
    for _ in range(n):
        caches.append((empty_cache(), empty_cache()))
    return k


@njit(cache=True, inline="always")
def _angle(c1, s1, c2, s2):
    """cos, sin of the placement's turn (turn c1, s1 then c2, s2)."""
    return c2 * c1 - s2 * s1, s2 * c1 + c2 * s1


@njit(cache=True, inline="always")
def _boundary_distance(px, py, tV, seg_b, prev, ox, oy, h, nx, ny, start, items, half_len, nearest, bound):
    """A lower bound of the distance from (px, py) to the target's edges (``tV[v]`` to ``seg_b[v]``): the distance
    itself where it is at most ``bound``, else ``bound``.  ``nearest``: the distance to the nearest vertex (an upper
    bound of the distance).  The nearest point within min(nearest, bound) lies on an edge whose nearer end is within
    that plus half the edge's length (``half_len``: the longest's half): :func:`.nearest._edge_distance` of the
    edges with an end that near (1e-12 mm to spare for the rounding)."""
    reach = min(nearest, bound) + half_len + 1e-12
    return min(_edge_distance(px, py, tV, seg_b, prev, reach, ox, oy, h, nx, ny, start, items), bound)


@njit(cache=True)
def _refresh(order, angs, centre, hw_wide, chunk, cc, cr, V, c1, s1, tx, c2, s2, cx, cy, W, S, ccx, ccy, radius,
             r_min, fx, fy, fh, fnx, fny, fvals, tV, ox, oy, h, nx, ny, start, items, half_len, seg_b, prev):
    """The cache at this pose: (state, run ids, runs' (P0x, P0y, E, |P0| + radius), candidates' (position, vertex),
    candidates' (X0x, X0y, LB0)); state: valid, centre, hw_wide, W, chord_W, cos and sin of the turn, the turning
    centre, the body point at the target's origin."""
    chord_W = 2.0 * math.sin(0.5 * min(W, math.pi))
    bounds = _window_bounds(angs, centre, hw_wide)
    runs = _window_runs(bounds, chunk)
    kj = np.empty(len(runs), np.int64)
    kp = np.empty((len(runs), 4))
    nq = _window_size(bounds)
    qp = np.empty((nq, 2), np.int64)
    qf = np.empty((nq, 3))
    n = 0
    for k in range(len(runs)):
        j = runs[k, 0]
        px, py = _placed(cc[j, 0], cc[j, 1], c1, s1, tx, c2, s2)
        r = cr[j]
        kj[k] = j
        kp[k, 0], kp[k, 1], kp[k, 3] = px, py, math.sqrt(px * px + py * py) + r
        dx, dy = px - cx, py - cy
        e_run = _boundary_bound(px, py, ccx, ccy, radius, r_min, fx, fy, fh, fnx, fny, fvals) - r \
            - chord_W * (math.sqrt(dx * dx + dy * dy) + r)
        if e_run > S:
            kp[k, 2] = e_run
            continue
        E = np.inf
        for p in range(runs[k, 1], runs[k, 2]):
            q = order[p]
            qx, qy = _placed(V[q, 0], V[q, 1], c1, s1, tx, c2, s2)
            dx, dy = qx - cx, qy - cy
            reach = chord_W * math.sqrt(dx * dx + dy * dy)
            lb, c = _bound_and_cell(qx, qy, ccx, ccy, radius, r_min, fx, fy, fh, fnx, fny)
            if c >= 0:  # _boundary_bound, the field read here (no array handed on at every vertex)
                lb = max(lb, fvals[c])
            near = lb - reach <= S
            if near:
                bound = reach + S + half_len
                nn = _nearest_vertex(qx, qy, tV, ox, oy, h, nx, ny, start, items, bound)
                # no vertex within the bound: the boundary is farther than bound - half_len (excess over S)
                near = math.isfinite(nn)
                lb = max(lb, (nn if near else bound) - half_len)
                near = near and lb - reach <= S
            if near:
                # the exact distance to the mate's edges (the nearest vertex less half the longest edge is a bound
                # up to that half length below it): fewer candidates at the poses that reuse this one
                lb = max(lb, _boundary_distance(qx, qy, tV, seg_b, prev, ox, oy, h, nx, ny, start, items, half_len, nn,
                                                reach + S + 1e-6))
                near = lb - reach <= S
            if near:
                qp[n, 0], qp[n, 1] = p, q
                qf[n, 0], qf[n, 1], qf[n, 2] = qx, qy, lb
                n += 1
            else:
                E = min(E, lb - reach)
        kp[k, 2] = E
    ca, sa = _angle(c1, s1, c2, s2)
    st = np.zeros(12)
    st[0], st[1], st[2], st[3], st[4], st[5], st[6], st[7], st[8] = 1.0, centre, hw_wide, W, chord_W, ca, sa, cx, cy
    # the body point that stood at the target's origin (the placement undone: turn c2, s2 back, the shift, c1, s1)
    st[9], st[10] = -tx * c1, tx * s1
    return st, kj, kp, qp[:n].copy(), qf[:n].copy()


@njit(cache=True)
def _still_valid(st, kj, kp, cc, cr, c1, s1, tx, c2, s2, cx, cy, centre, hw, w):
    """Whether the cache's left-out vertices still cannot reach the boundary at this pose (window ``centre`` +-
    ``hw``, turn ``w``): see the module docstring."""
    if st[0] == 0.0 or w > st[3]:
        return False
    if st[2] < math.pi:
        dc = abs((centre - st[1] + math.pi) % (2 * math.pi) - math.pi)
        if dc + hw > st[2]:
            return False
    ca, sa = _angle(c1, s1, c2, s2)
    alpha = math.atan2(sa * st[5] - ca * st[6], ca * st[5] + sa * st[6])
    sfac = 2.0 * abs(math.sin(0.5 * alpha))
    chord_W = st[4]
    dC = math.sqrt((cx - st[7]) ** 2 + (cy - st[8]) ** 2)
    # the motion since the refresh, M(P) = R P + t in the target's frame, moves a run's centre P0 by at most
    # |t| + sfac |P0|: a run whose excess that bound (and sfac times its radius) leaves is held without placing its
    # centre (the runs far from the contact, most of them); 1e-9 mm to spare for the rounding, so that this test holds
    # a run only where the exact one below would
    ox, oy = _placed(st[9], st[10], c1, s1, tx, c2, s2)
    T = math.sqrt(ox * ox + oy * oy)
    base = chord_W * dC + 1e-6 + 1e-9
    for k in range(len(kj)):
        E = kp[k, 2]
        if E == np.inf:
            continue
        if (T + sfac * kp[k, 3]) * (1.0 + chord_W) + base < E:
            continue
        j = kj[k]
        px, py = _placed(cc[j, 0], cc[j, 1], c1, s1, tx, c2, s2)
        disp = math.sqrt((px - kp[k, 0]) ** 2 + (py - kp[k, 1]) ** 2) + sfac * cr[j]
        if not disp * (1.0 + chord_W) + chord_W * dC + 1e-6 < E:
            return False
    return True


@njit(cache=True)
def _reused(qp, qf, bounds, V, c1, s1, tx, c2, s2, cx, cy, chord):
    """The candidates within the window ``bounds`` (positions) that may reach the boundary at this pose, in order."""
    out = np.empty(len(qp), np.int64)
    n = 0
    for k in range(len(qp)):
        p = qp[k, 0]
        inside = False
        for i in range(3):
            if bounds[2 * i] <= p < bounds[2 * i + 1]:
                inside = True
        if not inside:
            continue
        q = qp[k, 1]
        x, y = _placed(V[q, 0], V[q, 1], c1, s1, tx, c2, s2)
        d = math.sqrt((x - qf[k, 0]) ** 2 + (y - qf[k, 1]) ** 2)
        dx, dy = x - cx, y - cy
        if qf[k, 2] - d - chord * math.sqrt(dx * dx + dy * dy) > 1e-6:
            continue
        out[n] = q
        n += 1
    return out[:n]


@njit(cache=True)
def _side(cache, order, angs, centre, hw, w, w_hold, chunk, cc, cr, V, c1, s1, tx, c2, s2, cx, cy, S, widen_rad,
          w_factor, ccx, ccy, radius, r_min, fx, fy, fh, fnx, fny, fvals, tV, ox, oy, h, nx, ny, start, items,
          half_len, seg_b, prev):
    """The vertices of one side to search at this pose (window ``centre`` +- ``hw + w``), and the cache (refreshed
    here when it no longer holds; a refresh holds for turns up to ``w_hold`` times ``w_factor``)."""
    st, kj, kp, qp, qf = cache
    if not _still_valid(st, kj, kp, cc, cr, c1, s1, tx, c2, s2, cx, cy, centre, hw + w, w):
        W = max(w, w_hold) * w_factor
        st, kj, kp, qp, qf = _refresh(order, angs, centre, hw + W + widen_rad, chunk, cc, cr, V, c1, s1, tx, c2, s2,
                                      cx, cy, W, S, ccx, ccy, radius, r_min, fx, fy, fh, fnx, fny, fvals, tV, ox, oy,
                                      h, nx, ny, start, items, half_len, seg_b, prev)
    bounds = _window_bounds(angs, centre, hw + w)
    idx = _reused(qp, qf, bounds, V, c1, s1, tx, c2, s2, cx, cy, 2.0 * math.sin(0.5 * min(w, math.pi)))
    return idx, (st, kj, kp, qp, qf)


@njit(cache=True)
def first_hit_reusing(cache1, cache2, S, widen_rad, w_factor, w_hold, phi_a, theta, sign, w, L, dvn_V, o1, a1,
                      hw_dvn, drv_V, o2, a2, hw_drv, R1, R2, chunk, cc1, cr1, cc2, cr2, f0, f1, f2, f3, f4, f5, g0,
                      g1, g2, g3, g4, g5, t0, t1, t2, t3, t4, t5, t6, t7, t8, t9, t10, t11, t12, t13, t14, t15,
                      u0, u1, u2, u3, u4, u5, u6, u7, u8, u9, u10, u11, u12, u13, u14, u15):
    """:func:`.contact_kernels._first_hit_pruned` (the same hit, bit for bit) with each side's vertices taken from its
    cache (``cache1``: the driven vertices onto the driver, ``cache2``: the driver's onto the driven):
    ((delta, side, vertex, edge, t), cache1, cache2).  A cache sorted again here holds for turns up to ``w_hold``
    (at least ``w``) times ``w_factor``."""
    drv_t = (t0, t1, t2, t3, t4, t5, t6, t7, t8, t9, t10, t11, t12, t13, t14, t15)
    dvn_t = (u0, u1, u2, u3, u4, u5, u6, u7, u8, u9, u10, u11, u12, u13, u14, u15)
    cp, sp = math.cos(-phi_a), math.sin(-phi_a)
    ct, st = math.cos(-theta), math.sin(-theta)
    cx1 = -L * ct + 0.0 * (-st)
    cy1 = -L * st + 0.0 * ct
    keep1 = R1 + w * R2 + 1e-6
    i1, cache1 = _side(cache1, o1, a1, phi_a, hw_dvn, w, w_hold, chunk, cc1, cr1, dvn_V, cp, sp, -L, ct, st, cx1, cy1,
                       S, widen_rad, w_factor, t12, t13, t14, t15, f0, f1, f2, f3, f4, f5, t0, t4, t5, t6, t7, t8,
                       t9, t10, t3, t1, t2)
    k1, d1, e1, q1 = _side_hits(i1, dvn_V, cp, sp, -L, ct, st, sign, w, keep1, cx1, cy1, drv_t)
    cth, sth, cph, sph = math.cos(theta), math.sin(theta), math.cos(phi_a), math.sin(phi_a)
    i2, cache2 = _side(cache2, o2, a2, math.pi - theta, hw_drv, w, w_hold, chunk, cc2, cr2, drv_V, cth, sth, L, cph,
                       sph, 0.0, 0.0, S, widen_rad, w_factor, u12, u13, u14, u15, g0, g1, g2, g3, g4, g5, u0, u4,
                       u5, u6, u7, u8, u9, u10, u3, u1, u2)
    k2, d2, e2, q2 = _side_hits(i2, drv_V, cth, sth, L, cph, sph, -sign, w, R2 + 1e-6, 0.0, 0.0, dvn_t)
    j1, m1 = _least(d1)
    j2, m2 = _least(d2)
    if not (m1 < np.inf or m2 < np.inf):
        return (np.inf, 0, -1, -1, 0.0), cache1, cache2
    if m1 <= m2:
        return (m1, 1, k1[j1], e1[j1], q1[j1]), cache1, cache2
    return (m2, 2, k2[j2], e2[j2], q2[j2]), cache1, cache2


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
