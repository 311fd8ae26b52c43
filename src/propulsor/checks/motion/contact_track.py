"""The measurements of :func:`.contact_events.resolve_contact` in one compiled loop: a run of positions, each searched
from the contact of the one before it (or from a seed of its own), its state (contact kind, driver and driven tooth)
found beside it.

The same operations as the reference search at one position (``tests/contact_reference.py``: ``contact`` and
``kind``), in the same order (a search a margin on the free side of the neighbouring contact, else from the law's
position through widening windows; the contact point put into each body frame, the nearest tooth centre by polar
angle): the same floats, without the Python around each of ten to twenty thousand measurements a cycle (about a third
of their time).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ... import policy
from .contact_kernels import DRIVE, _first_hit_pruned, _nearest_tooth_nb
from .contact_reuse import empty_cache, first_hit_reusing, new_caches
from ...nbcache import bind

__all__ = ["track"]


@njit(cache=True)
def _kind_nb(side, v, e, t, near, corner_dvn, turn_dvn, corner_drv, turn_drv, len_drv, nxt_drv, len_dvn, nxt_dvn):
    """The contact kind (``tests/contact_reference.py``, ``kind``): the vertex's own corner, else a corner of the
    other outline within ``near`` of the hit on its edge (the edge's start, then its end), else flank (0)."""
    if side == 1:  # a driven vertex on a driver edge
        own, own_turn, other, other_turn, seg_len, nxt = corner_dvn, turn_dvn, corner_drv, turn_drv, len_drv, nxt_drv
        own_code, other_code = 2, 1
    else:
        own, own_turn, other, other_turn, seg_len, nxt = corner_drv, turn_drv, corner_dvn, turn_dvn, len_dvn, nxt_dvn
        own_code, other_code = 1, 2
    if own[v]:
        return own_code if own_turn[v] > 0 else own_code + 2
    L = seg_len[e]
    if other[e] and t * L <= near:
        return other_code if other_turn[e] > 0 else other_code + 2
    k = nxt[e]
    if other[k] and (1.0 - t) * L <= near:
        return other_code if other_turn[k] > 0 else other_code + 2
    return 0


@njit(cache=True)
def _track_nb(phis, ths, seeds, seed_phis, chained, sign, m0, m_max, w0, w_max, near, L, dvn_pts, dvn_a, dvn_b,
              drv_pts, driver_teeth, driven_teeth, corner_dvn, turn_dvn, corner_drv, turn_drv, len_drv, nxt_drv,
              len_dvn, nxt_dvn, slots, caches, slack, widen, w_factor, first, keep, kept, args):
    n = len(phis)
    # the candidate vertices of a pose reused at the next poses of its slot while they provably hold (contact_reuse)
    cache1, cache2 = empty_cache(), empty_cache()
    cur = -1
    te = np.full(n, np.nan)
    kind = np.full(n, -1, np.int64)
    tooth_drv = np.full(n, -1, np.int64)
    tooth_dvn = np.full(n, -1, np.int64)
    prev, prev_phi = seeds[0], seed_phis[0]
    for i in range(n):
        if not chained:
            prev, prev_phi = seeds[i], seed_phis[i]
        p, th = phis[i], ths[i]
        found = False
        d = 0.0
        side, v, e, t = 0, -1, -1, 0.0
        if math.isfinite(prev):
            dphi = 0.0 if math.isnan(prev_phi) else p - prev_phi
            m = min(m0 + 0.25 * abs(dphi), m_max)
            slot = slots[i]
            if slot >= 0:
                if slot != cur:
                    if cur >= 0:
                        caches[cur] = (cache1, cache2)
                    cache1, cache2 = caches[slot]
                    cur = slot
                # the nearer part of the window first (from one position to the next the contact moves by about a
                # hundredth of the margin), then the whole of it where that part holds no hit: the first hit within
                # the whole, either way
                r, cache1, cache2 = first_hit_reusing(cache1, cache2, slack, widen, w_factor, 2.0 * m,
                                                      p + prev + sign * m, th, sign, first * m, *args)
                if not math.isfinite(r[0]) and first < 2.0:
                    r, cache1, cache2 = first_hit_reusing(cache1, cache2, slack, widen, w_factor, 2.0 * m,
                                                          p + prev + sign * m, th, sign, 2.0 * m, *args)
                d, side, v, e, t = r
            else:
                d, side, v, e, t = _first_hit_pruned(p + prev + sign * m, th, sign, first * m, *args)
                if not math.isfinite(d) and first < 2.0:
                    d, side, v, e, t = _first_hit_pruned(p + prev + sign * m, th, sign, 2.0 * m, *args)
            if math.isfinite(d) and 0.2 * m < d:
                found = True
                x = prev + sign * (m - d)
        if not found:
            w = w0
            while True:
                d, side, v, e, t = _first_hit_pruned(p, th, sign, w, *args)
                if math.isfinite(d) or w >= w_max:
                    break
                w = min(4.0 * w, w_max)
            if not math.isfinite(d):
                prev, prev_phi = np.nan, np.nan
                if keep:
                    kept.append((cache1, cache2))
                continue
            x = -sign * d
        te[i] = x
        phi_a = p + x
        if side == 1:
            qx, qy = dvn_pts[v, 0], dvn_pts[v, 1]
            # driven body -> world (turned by -phi_a) -> driver body (less (L, 0), turned by -theta)
            c, s = math.cos(-phi_a), math.sin(-phi_a)
            wx, wy = c * qx + (-s) * qy - L, s * qx + c * qy
            c, s = math.cos(-th), math.sin(-th)
            rx, ry = c * wx + (-s) * wy, s * wx + c * wy
        else:
            ax, ay = dvn_a[e, 0], dvn_a[e, 1]
            qx, qy = ax + t * (dvn_b[e, 0] - ax), ay + t * (dvn_b[e, 1] - ay)
            rx, ry = drv_pts[v, 0], drv_pts[v, 1]
        kind[i] = _kind_nb(side, v, e, t, near, corner_dvn, turn_dvn, corner_drv, turn_drv, len_drv, nxt_drv,
                           len_dvn, nxt_dvn)
        tooth_dvn[i] = _nearest_tooth_nb(driven_teeth, math.atan2(qy, qx))
        tooth_drv[i] = _nearest_tooth_nb(driver_teeth, math.atan2(ry, rx))
        prev, prev_phi = x, p
        if keep:
            kept.append((cache1, cache2))
    if cur >= 0:
        caches[cur] = (cache1, cache2)
    return te, kind, tooth_drv, tooth_dvn


def track(pair, phis, thetas, direction: int, seeds, seed_phis, chained: bool, slots=None, caches=None, kept=None):
    """(te, kind, driver tooth, driven tooth) at each of the law phases ``phis`` (driver at ``thetas``), as the
    reference search at one position gives them (``tests/contact_reference.py``): ``chained``, each position searched
    from the contact of the one before it (the first from ``seeds[0]`` at ``seed_phis[0]``); else each from its own
    seed.  A seed of nan:
    the full search from the law's position.  te nan, kind and teeth -1 where nothing touches.

    ``slots``, ``caches`` (:func:`.contact_reuse.new_caches`): the first search at position i reuses the candidate
    vertices kept in ``caches[slots[i]]`` (:mod:`.contact_reuse`: the same values, fewer vertices searched), and
    leaves its own there; a slot of -1 searches afresh.  By default a chained run shares one new slot, separate
    seeds search afresh.  ``kept`` (a list from :func:`.contact_reuse.new_caches`): told the caches as they stand
    after each position, in order (:func:`.contact_reuse.seed_slots` gives them to other slots)."""
    n = len(phis)
    if caches is None:
        caches = new_caches(1)
        slots = np.zeros(n, np.int64) if chained else np.full(n, -1, np.int64)
    ka, pa = pair._kernel_args, pair._prune_args
    sign = 1.0 if direction == DRIVE else -1.0
    return _track_nb(np.ascontiguousarray(phis, np.float64), np.ascontiguousarray(thetas, np.float64),
                     np.ascontiguousarray(seeds, np.float64), np.ascontiguousarray(seed_phis, np.float64),
                     bool(chained), sign, policy.CONTACT_TRACK_MARGIN_RAD, policy.CONTACT_TRACK_MARGIN_MAX_RAD,
                     policy.CONTACT_SEARCH_START_RAD, policy.MOTION_MAX_FREE_ANGLE_RAD, policy.CONTACT_CORNER_NEAR_MM,
                     pair.L, ka[1], np.ascontiguousarray(pair.dvn.seg_a, np.float64),
                     np.ascontiguousarray(pair.dvn.seg_b, np.float64), ka[5],
                     np.ascontiguousarray(pair.driver_teeth, np.float64),
                     np.ascontiguousarray(pair.driven_teeth, np.float64), pair.corner_dvn, pair.turn_dvn,
                     pair.corner_drv, pair.turn_drv, pair.drv.seg_len, pair.drv.nxt, pair.dvn.seg_len, pair.dvn.nxt,
                     np.ascontiguousarray(slots, np.int64), caches, policy.CONTACT_REUSE_SLACK_MM,
                     policy.CONTACT_REUSE_WIDEN_RAD, policy.CONTACT_REUSE_TURN_FACTOR,
                     min(float(policy.CONTACT_TRACK_FIRST_WINDOW), 2.0), kept is not None,
                     new_caches(0) if kept is None else kept, tuple(ka[:11]) + tuple(pa) + tuple(ka[11:]))


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
