"""The compiled kernels of the contact search (:mod:`.contact_events`): the vertices within a window of polar angle
about the line of centres, the runs of them that cannot reach the mate left out (bounding circles against a distance
field), each left vertex turned about its axis onto the mate's edges (:func:`_side_hits`), and the first
entering hit.  numba, ``cache=True`` (:mod:`propulsor.checks.kernels` compiles them ahead).  Each rotation of a point
is written out (x c - y s, x s + y c), the same on every machine.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .backlash import _ANG_EPS, _edge_quadratic, _edge_root, _room, _sort_few
from .nearest import disc_cells
from ...nbcache import bind

#: the two directions of the loaded contact: the driver's loaded flanks pushing (the driven wheel turned back onto
#: them), and the other flanks (turned on)
DRIVE, REVERSE = 1, -1


@njit(cache=True)
def _nearest_tooth_nb(centres, angle):
    best, k = np.inf, -1
    for i in range(len(centres)):
        d = abs((angle - centres[i] + math.pi) % (2 * math.pi) - math.pi)
        if k < 0 or d < best:
            best, k = d, i
    return k


@njit(cache=True)
def _window_bounds(angs, centre, hw):
    """The three ranges [bounds[2i], bounds[2i + 1]) of positions in ``angs`` (sorted polar angles) within centre +-
    hw, wrapped by -2 pi, 0, +2 pi (all of them in the first when hw >= pi)."""
    bounds = np.zeros(6, np.int64)
    if hw >= math.pi:
        bounds[1] = len(angs)
        return bounds
    c = (centre + math.pi) % (2 * math.pi) - math.pi
    for i in range(3):
        k = i - 1
        lo, hi = c - hw + 2 * math.pi * k, c + hw + 2 * math.pi * k
        bounds[2 * i], bounds[2 * i + 1] = np.searchsorted(angs, lo), np.searchsorted(angs, hi)
    return bounds


@njit(cache=True, inline="always")
def _window_size(bounds):
    """How many positions the three ranges of :func:`_window_bounds` hold."""
    n = 0
    for i in range(3):
        n += max(bounds[2 * i + 1] - bounds[2 * i], 0)
    return n


@njit(cache=True)
def _window_runs(bounds, chunk):
    """The runs of ``chunk`` positions the ranges of :func:`_window_bounds` cover, in order: (run, its first position
    in the range, the position after its last), one row each (a run cut by a range's end holds only its part)."""
    n = 0
    for i in range(3):
        lo, hi = bounds[2 * i], bounds[2 * i + 1]
        if hi > lo:
            n += (hi - 1) // chunk - lo // chunk + 1
    out = np.empty((n, 3), np.int64)
    k = 0
    for i in range(3):
        lo, hi = bounds[2 * i], bounds[2 * i + 1]
        if hi <= lo:
            continue
        for j in range(lo // chunk, (hi - 1) // chunk + 1):
            out[k, 0], out[k, 1], out[k, 2] = j, max(lo, j * chunk), min(hi, (j + 1) * chunk)
            k += 1
    return out


@njit(cache=True)
def _window_nb(order, angs, centre, hw):
    """The vertices (of ``order``, sorted by their polar angles ``angs``) whose polar angle lies within centre +- hw
    (wrapped), in that order."""
    if hw >= math.pi:
        return order.copy()
    bounds = _window_bounds(angs, centre, hw)
    out = np.empty(_window_size(bounds), np.int64)
    n = 0
    for i in range(3):
        for j in range(bounds[2 * i], bounds[2 * i + 1]):
            out[n] = order[j]
            n += 1
    return out


@njit(cache=True, inline="always")
def _among(near, k, v):
    """Whether v is one of near[:k] (ascending): a binary search."""
    lo, hi = 0, k
    while lo < hi:
        mid = (lo + hi) // 2
        if near[mid] < v:
            lo = mid + 1
        else:
            hi = mid
    return lo < k and near[lo] == v


@njit(cache=True)
def _side_hits(idx, V, c1, s1, tx, c2, s2, sign, w, r_keep, cx, cy, tgt):
    """The hits of one side: the vertices ``V[idx]`` placed by a turn (c1, s1), a shift (tx, 0) and a turn (c2, s2)
    into the target's body frame, those within ``r_keep`` of its axis kept, each turned by sign·δ about (cx, cy)
    until it enters the target: (vertex, delta, edge, t).

    The pairs and roots of the backlash search (:func:`.backlash._ring_pairs`, without its filters: here a window of
    a fraction of a milliradian, a few vertices a point, nearly all of them hitting), the angle of each entering root
    within the window and the least of them (:func:`.backlash._rot_reduce`'s), one point at a time: a point's pairs
    (the edges starting at each vertex within its reach, ascending, then the edges ending there) are searched as they
    are found, without arrays of every pair handed from pass to pass.  An edge ending at a vertex within reach that
    also starts at one (most of them: the vertices within reach are neighbours along the outline) is searched once,
    among the first: a second search of it gives the same least angle, which never replaces the first (a strictly
    lesser one does)."""
    (tV, seg_b, prev, half_len, ox, oy, h, nx, ny, start, items, near_cell, ccx, ccy, radius, r_min) = tgt
    m = len(idx)
    P = np.empty((m, 2))
    keep = np.empty(m, np.int64)
    n = 0
    for j in range(m):
        x, y = V[idx[j], 0], V[idx[j], 1]
        u = x * c1 + y * (-s1) + tx
        v = x * s1 + y * c1
        px = u * c2 + v * (-s2)
        py = u * s2 + v * c2
        if math.sqrt(px * px + py * py) <= r_keep:
            P[n, 0], P[n, 1] = px, py
            keep[n] = idx[j]
            n += 1
    chord_factor = 2.0 * math.sin(0.5 * min(w, math.pi))
    # a root's angle is taken only where it is entering and not plainly outside 0 .. w (a margin of 1e-6 of the
    # angle: far beyond atan2's rounding); the others are never taken
    tw = math.tan(w) * (1.0 + 1e-6) if w < 1.5 else np.inf
    delta = np.full(n, np.inf)
    edge = np.full(n, -1, np.int64)
    tpar = np.zeros(n)
    near = np.empty(min(len(tV), 256), np.int64)  # grown on demand (before a scan of the cells)
    for i in range(n):
        pxi, pyi = P[i, 0], P[i, 1]
        dx, dy = pxi - cx, pyi - cy
        rho = math.sqrt(dx * dx + dy * dy)
        ex, ey = pxi - ccx, pyi - ccy
        d = math.sqrt(ex * ex + ey * ey)
        lb = max(d - radius, r_min - d)
        if not lb <= chord_factor * rho:
            continue
        reach = chord_factor * rho + half_len + 1e-12
        if reach <= h:
            c0 = (min(max(int(math.floor((pxi - ox) / h)), 0), nx - 1) * ny
                  + min(max(int(math.floor((pyi - oy) / h)), 0), ny - 1))
            if not near_cell[c0]:
                continue
        ix0, ix1, iy0, iy1 = disc_cells(pxi, pyi, reach, ox, oy, h, nx, ny)
        near = _room(near, ix0, ix1, iy0, iy1, ny, start)
        k = 0
        r2reach = reach * reach
        for gx in range(ix0, ix1 + 1):
            for gy in range(iy0, iy1 + 1):
                c = gx * ny + gy
                for kk in range(start[c], start[c + 1]):
                    vv = items[kk]
                    fx, fy = pxi - tV[vv, 0], pyi - tV[vv, 1]
                    if fx * fx + fy * fy <= r2reach:
                        near[k] = vv
                        k += 1
        if k == 0:
            continue
        _sort_few(near, k)
        ppx, ppy = pxi - cx, pyi - cy
        r2 = rho * rho
        best, best_e, best_t = np.inf, -1, 0.0
        for jj in range(2 * k):
            if jj < k:
                sg = near[jj]
            else:
                sg = prev[near[jj - k]]
                if _among(near, k, sg):
                    continue  # the edge starts at a vertex within reach too: taken among the first k, the same hit
            ax, ay = tV[sg, 0] - cx, tV[sg, 1] - cy
            ddx, ddy = seg_b[sg, 0] - tV[sg, 0], seg_b[sg, 1] - tV[sg, 1]
            qa, qb, disc = _edge_quadratic(ax, ay, ddx, ddy, r2)
            if not disc >= 0.0:
                continue  # no root: no hit on this edge
            sq = math.sqrt(disc)
            pb, pt = np.inf, 0.0
            for r in range(2):
                t, qx, qy, entering = _edge_root(qa, qb, sq, True, r, ax, ay, ddx, ddy, sign)
                if not entering:
                    continue
                Yr = ppx * qy - ppy * qx
                Xr = ppx * qx + ppy * qy
                sr = sign * Yr
                if w < 1.5 and (Xr < 0.0 or (Xr > 0.0 and (sr > Xr * tw or sr < -Xr * 1e-6))):
                    continue
                an = sign * math.atan2(Yr, Xr)
                if an != an:
                    continue
                an = an + 2.0 * math.pi if an < -_ANG_EPS else (an if an > 0.0 else 0.0)
                if an <= w and an < pb:
                    pb, pt = an, t
            if pb < best:
                best, best_e, best_t = pb, sg, pt
        if best_e >= 0:
            delta[i], edge[i], tpar[i] = best, best_e, best_t
    return keep[:n], delta, edge, tpar


@njit(cache=True)
def _pair_hits(phi_a, theta, sign, w, L, dvn_V, o1, a1, hw_dvn, drv_V, o2, a2, hw_drv, R1, R2,
               t0, t1, t2, t3, t4, t5, t6, t7, t8, t9, t10, t11, t12, t13, t14, t15,
               u0, u1, u2, u3, u4, u5, u6, u7, u8, u9, u10, u11, u12, u13, u14, u15):
    """:meth:`PairOutlines._all_hits` compiled: the driven vertices within the window about the line of centres put
    into the driver's frame (turned by -phi_a, shifted by -L, turned by -theta) turning about the driven axis there
    (sign) onto the driver's edges, and the driver vertices put into the driven frame turning the other way onto
    the driven edges.  Each rotation of a point is written out (x c - y s, x s + y c), the same on every machine."""
    drv_t = (t0, t1, t2, t3, t4, t5, t6, t7, t8, t9, t10, t11, t12, t13, t14, t15)
    dvn_t = (u0, u1, u2, u3, u4, u5, u6, u7, u8, u9, u10, u11, u12, u13, u14, u15)
    i1 = _window_nb(o1, a1, phi_a, hw_dvn + w)
    i2 = _window_nb(o2, a2, math.pi - theta, hw_drv + w)
    cp, sp = math.cos(-phi_a), math.sin(-phi_a)
    ct, st = math.cos(-theta), math.sin(-theta)
    # the driven axis in the driver's frame: (-L, 0) turned by -theta
    cx1 = -L * ct + 0.0 * (-st)
    cy1 = -L * st + 0.0 * ct
    k1, d1, e1, q1 = _side_hits(i1, dvn_V, cp, sp, -L, ct, st, sign, w, R1 + w * R2 + 1e-6, cx1, cy1, drv_t)
    k2, d2, e2, q2 = _side_hits(i2, drv_V, math.cos(theta), math.sin(theta), L, math.cos(phi_a), math.sin(phi_a),
                                -sign, w, R2 + 1e-6, 0.0, 0.0, dvn_t)
    return k1, d1, e1, q1, k2, d2, e2, q2


@njit(cache=True, inline="always")
def _placed(x, y, c1, s1, tx, c2, s2):
    """A body-frame point placed into the target's frame (turn c1, s1; shift tx; turn c2, s2)."""
    u = x * c1 - y * s1 + tx
    v = x * s1 + y * c1
    return u * c2 - v * s2, u * s2 + v * c2


@njit(cache=True, inline="always")
def _bound_and_cell(px, py, ccx, ccy, radius, r_min, fx, fy, fh, fnx, fny):
    """The annulus's lower bound of the distance of (px, py) to the target's boundary (ccx, ccy, radius, r_min), and
    the index of the distance field's cell where the point lies (-1 off the grid): ``max(lb, fvals[cell])`` is
    :func:`_boundary_bound`.  Scalars only: an array handed to a function inside a loop costs numba a reference
    count update (two atomic operations) at every call, so the hot loops read the field themselves."""
    ex, ey = px - ccx, py - ccy
    d = math.sqrt(ex * ex + ey * ey)
    lb = max(d - radius, r_min - d)
    ix = int(math.floor((px - fx) / fh))
    iy = int(math.floor((py - fy) / fh))
    if 0 <= ix < fnx and 0 <= iy < fny:
        return lb, ix * fny + iy
    return lb, -1


@njit(cache=True, inline="always")
def _boundary_bound(px, py, ccx, ccy, radius, r_min, fx, fy, fh, fnx, fny, fvals):
    """A lower bound of the distance of (px, py) to the target's boundary: its annulus (ccx, ccy, radius, r_min), and
    the distance field's cell where the point lies in the grid."""
    lb, c = _bound_and_cell(px, py, ccx, ccy, radius, r_min, fx, fy, fh, fnx, fny)
    if c >= 0:
        lb = max(lb, fvals[c])
    return lb


@njit(cache=True)
def _pruned_window(order, angs, centre, hw, chunk, cc, cr, V, c1, s1, tx, c2, s2, r_keep, cx, cy, chord, ccx, ccy,
                   radius, r_min, fx, fy, fh, fnx, fny, fvals):
    """The vertices of :func:`_window_nb` (the same, in the same order) less every run of ``chunk`` positions whose
    bounding circle (``cc``, ``cr``: body frame), placed into the target's frame as :func:`_side_hits` places the
    vertices (turn c1, s1; shift tx; turn c2, s2), lies wholly beyond ``r_keep`` of the target's axis, or farther
    from the target's boundary (the annulus ccx, ccy, radius, r_min and the distance field fx .. fvals:
    :func:`distance_field`) than ``chord`` times its farthest distance from the turning centre (cx, cy): no vertex
    of such a run is kept, or can reach the boundary within the window (1e-6 mm to spare on either test); of the
    runs left, each vertex ``V[q]`` by the same test."""
    bounds = _window_bounds(angs, centre, hw)
    out = np.empty(_window_size(bounds), np.int64)
    n = 0
    runs = _window_runs(bounds, chunk)
    for k in range(len(runs)):
        j = runs[k, 0]
        px, py = _placed(cc[j, 0], cc[j, 1], c1, s1, tx, c2, s2)
        r = cr[j]
        if math.sqrt(px * px + py * py) - r > r_keep + 1e-6:
            continue
        dx, dy = px - cx, py - cy
        reach = chord * (math.sqrt(dx * dx + dy * dy) + r)
        lb = _boundary_bound(px, py, ccx, ccy, radius, r_min, fx, fy, fh, fnx, fny, fvals)
        if lb - r > reach + 1e-6:
            continue
        for p in range(runs[k, 1], runs[k, 2]):
            q = order[p]
            px, py = _placed(V[q, 0], V[q, 1], c1, s1, tx, c2, s2)
            dx, dy = px - cx, py - cy
            reach = chord * math.sqrt(dx * dx + dy * dy)
            lb, c = _bound_and_cell(px, py, ccx, ccy, radius, r_min, fx, fy, fh, fnx, fny)
            if c >= 0:  # _boundary_bound, the field read here (no array handed on at every vertex)
                lb = max(lb, fvals[c])
            if lb > reach + 1e-6:
                continue
            out[n] = q
            n += 1
    return out[:n]


@njit(cache=True)
def _least(d):
    """(index, value) of the first least of d; (-1, inf) when d is empty."""
    k1, m1 = -1, np.inf
    for k in range(len(d)):
        if k1 < 0 or d[k] < m1:
            k1, m1 = k, d[k]
    return k1, m1


@njit(cache=True)
def _pair_hits_pruned(phi_a, theta, sign, w, L, dvn_V, o1, a1, hw_dvn, drv_V, o2, a2, hw_drv, R1, R2,
                      chunk, cc1, cr1, cc2, cr2, f0, f1, f2, f3, f4, f5, g0, g1, g2, g3, g4, g5,
                      t0, t1, t2, t3, t4, t5, t6, t7, t8, t9, t10, t11, t12, t13, t14, t15,
                      u0, u1, u2, u3, u4, u5, u6, u7, u8, u9, u10, u11, u12, u13, u14, u15):
    """:func:`_pair_hits` less the window's vertices that cannot reach the mate within w, each side's window pruned
    before any per-vertex work (:func:`_pruned_window`; ``f*``: the driver's distance field, ``g*``: the driven's):
    every vertex left out would have had no hit (delta inf), so the finite hits are the same, bit for bit, in the same
    order (the per-tooth load's search, :mod:`.mesh_load`, and :func:`_first_hit_pruned`)."""
    drv_t = (t0, t1, t2, t3, t4, t5, t6, t7, t8, t9, t10, t11, t12, t13, t14, t15)
    dvn_t = (u0, u1, u2, u3, u4, u5, u6, u7, u8, u9, u10, u11, u12, u13, u14, u15)
    chord = 2.0 * math.sin(0.5 * min(w, math.pi))
    cp, sp = math.cos(-phi_a), math.sin(-phi_a)
    ct, st = math.cos(-theta), math.sin(-theta)
    cx1 = -L * ct + 0.0 * (-st)
    cy1 = -L * st + 0.0 * ct
    keep1 = R1 + w * R2 + 1e-6
    i1 = _pruned_window(o1, a1, phi_a, hw_dvn + w, chunk, cc1, cr1, dvn_V, cp, sp, -L, ct, st, keep1, cx1, cy1, chord,
                        t12, t13, t14, t15, f0, f1, f2, f3, f4, f5)
    k1, d1, e1, q1 = _side_hits(i1, dvn_V, cp, sp, -L, ct, st, sign, w, keep1, cx1, cy1, drv_t)
    cth, sth, cph, sph = math.cos(theta), math.sin(theta), math.cos(phi_a), math.sin(phi_a)
    i2 = _pruned_window(o2, a2, math.pi - theta, hw_drv + w, chunk, cc2, cr2, drv_V, cth, sth, L, cph, sph, R2 + 1e-6,
                        0.0, 0.0, chord, u12, u13, u14, u15, g0, g1, g2, g3, g4, g5)
    k2, d2, e2, q2 = _side_hits(i2, drv_V, cth, sth, L, cph, sph, -sign, w, R2 + 1e-6, 0.0, 0.0, dvn_t)
    return k1, d1, e1, q1, k2, d2, e2, q2


@njit(cache=True)
def _first_hit_pruned(phi_a, theta, sign, w, L, dvn_V, o1, a1, hw_dvn, drv_V, o2, a2, hw_drv, R1, R2,
                      chunk, cc1, cr1, cc2, cr2, f0, f1, f2, f3, f4, f5, g0, g1, g2, g3, g4, g5,
                      t0, t1, t2, t3, t4, t5, t6, t7, t8, t9, t10, t11, t12, t13, t14, t15,
                      u0, u1, u2, u3, u4, u5, u6, u7, u8, u9, u10, u11, u12, u13, u14, u15):
    """The first entering hit (delta, side, vertex, edge, t) of :func:`_pair_hits` (the first least on a tie, side 1
    before side 2), bit for bit, with the window's vertices that cannot reach the mate within w left out before
    any per-vertex work (:func:`_pair_hits_pruned`; ``f*``: the driver's distance field, ``g*``: the driven's).  A
    vertex left out would have had no hit (delta inf): the least, and the first on a tie, are the same."""
    k1, d1, e1, q1, k2, d2, e2, q2 = _pair_hits_pruned(
        phi_a, theta, sign, w, L, dvn_V, o1, a1, hw_dvn, drv_V, o2, a2, hw_drv, R1, R2, chunk, cc1, cr1, cc2, cr2,
        f0, f1, f2, f3, f4, f5, g0, g1, g2, g3, g4, g5, t0, t1, t2, t3, t4, t5, t6, t7, t8, t9, t10, t11, t12, t13, t14,
        t15, u0, u1, u2, u3, u4, u5, u6, u7, u8, u9, u10, u11, u12, u13, u14, u15)
    j1, m1 = _least(d1)
    j2, m2 = _least(d2)
    if not (m1 < np.inf or m2 < np.inf):
        return np.inf, 0, -1, -1, 0.0
    if m1 <= m2:
        return m1, 1, k1[j1], e1[j1], q1[j1]
    return m2, 2, k2[j2], e2[j2], q2[j2]


@njit(cache=True)
def _nearest_teeth_nb(centres, angles):
    """:func:`_nearest_tooth_nb` of each angle (the first nearest tooth centre by polar angle)."""
    out = np.empty(len(angles), np.int64)
    for j in range(len(angles)):
        out[j] = _nearest_tooth_nb(centres, angles[j])
    return out


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
