"""The reference of the as-built contact search at one position, in Python: what the compiled loop
(``checks/motion/contact_track.py``, ``_track_nb``) does at each position, written out step by step.  The tests
compare the compiled loop with it position by position (te to the last bit, contact kind, teeth); it also gives the
contact point, which the compiled loop does not return, so that a test can put the contact on the line of action."""

from __future__ import annotations

import math

import numpy as np

from propulsor import policy
from propulsor.checks.motion.contact_events import DRIVE, _rot
from propulsor.checks.motion.contact_kernels import _first_hit_pruned, _nearest_tooth_nb


def contact(po, phi: float, theta: float, direction: int, prev_te: float | None = None, dphi: float = 0.0, hit=None):
    """(te, kind, driver tooth, driven tooth, contact point in the driven body frame) at law phase phi (driver at
    theta) of the pair ``po`` (:class:`PairOutlines`): the driven wheel turned from the law's position until the
    outlines touch (direction DRIVE: back; REVERSE: on).  te = actual - law (rad); nan where nothing touches within
    the largest free rotation.  ``prev_te``: the te of a sample ``dphi`` away, from which the search starts (a margin
    of ``policy.CONTACT_TRACK_MARGIN_RAD`` + |dphi| / 4 on the free side, at most ``CONTACT_TRACK_MARGIN_MAX_RAD``; a
    contact found within a fifth of it of the start is searched again from the law's position).  ``hit``: the first
    hit's search, ``hit(po, phi_a, theta, sign, w)`` (default :func:`pruned_hit`, the one the compiled loop uses)."""
    hits = hit if hit is not None else pruned_hit
    sign = 1.0 if direction == DRIVE else -1.0
    hit = None
    if prev_te is not None and math.isfinite(prev_te):
        m = min(policy.CONTACT_TRACK_MARGIN_RAD + 0.25 * abs(dphi), policy.CONTACT_TRACK_MARGIN_MAX_RAD)
        h = hits(po, phi + prev_te + sign * m, theta, sign, 2.0 * m)
        if math.isfinite(h[0]) and 0.2 * m < h[0]:
            hit, te = h, prev_te + sign * (m - h[0])
    if hit is None:
        w = policy.CONTACT_SEARCH_START_RAD
        while True:
            h = hits(po, phi, theta, sign, w)
            if math.isfinite(h[0]) or w >= policy.MOTION_MAX_FREE_ANGLE_RAD:
                break
            w = min(4.0 * w, policy.MOTION_MAX_FREE_ANGLE_RAD)
        if not math.isfinite(h[0]):
            return math.nan, -1, -1, -1, np.full(2, np.nan)
        hit, te = h, -sign * h[0]
    _, side, v, e, t = hit
    phi_a = phi + te
    if side == 1:
        p_dvn = po.dvn.points[v]
        p_drv = _rot(-theta) @ (_rot(-phi_a) @ np.asarray(p_dvn, float) - (po.L, 0.0))
    else:
        a, b = po.dvn.seg_a[e], po.dvn.seg_b[e]
        p_dvn = a + t * (b - a)
        p_drv = po.drv.points[v]
    tooth_dvn = int(_nearest_tooth_nb(po.driven_teeth, math.atan2(p_dvn[1], p_dvn[0])))
    tooth_drv = int(_nearest_tooth_nb(po.driver_teeth, math.atan2(p_drv[1], p_drv[0])))
    return te, kind(po, side, v, e, t), tooth_drv, tooth_dvn, np.asarray(p_dvn, float)


def pruned_hit(po, phi_a: float, theta: float, sign: float, w: float):
    """First entering hit when the driven wheel, at actual angle phi_a, turns by sign (+1: back, the drive flanks)
    through at most w rad: (delta, side, vertex, edge, t); side 1: a driven vertex on a driver edge, side 2: a driver
    vertex on a driven edge (the compiled :func:`_first_hit_pruned`, as the compiled loop calls it; its own reference,
    ``contact_hit_reference.py``, takes it from every vertex of the window)."""
    ka = po._kernel_args
    return _first_hit_pruned(float(phi_a), float(theta), float(sign), float(w), *ka[:11], *po._prune_args, *ka[11:])


def kind(po, side: int, v: int, e: int, t: float) -> int:
    """Contact kind code: the vertex's own corner, else a corner of the other outline within
    ``policy.CONTACT_CORNER_NEAR_MM`` of the hit on its edge, else flank."""
    near = policy.CONTACT_CORNER_NEAR_MM
    if side == 1:   # driven vertex v on driver edge e
        own, own_turn, other, other_turn, oo = po.corner_dvn, po.turn_dvn, po.corner_drv, po.turn_drv, po.drv
        own_code, other_code = 2, 1
    else:
        own, own_turn, other, other_turn, oo = po.corner_drv, po.turn_drv, po.corner_dvn, po.turn_dvn, po.dvn
        own_code, other_code = 1, 2
    if own[v]:
        return own_code if own_turn[v] > 0 else own_code + 2
    L = oo.seg_len[e]
    for idx, dist in ((e, t * L), (oo.nxt[e], (1.0 - t) * L)):
        if other[idx] and dist <= near:
            return other_code if other_turn[idx] > 0 else other_code + 2
    return 0


def checked(po, phi: float, theta: float, direction: int, prev_te: float | None = None,
            seed_phi: float | None = None, hit=None):
    """:func:`contact` at one position, seeded from ``prev_te`` found at ``seed_phi`` (none: the full search; no
    ``seed_phi``: dphi = 0), after checking that the compiled search (``contact_track.track``) seeded so gives the
    same te to the last bit, the same contact kind and the same teeth."""
    from propulsor.checks.motion.contact_track import track

    sp = phi if seed_phi is None else seed_phi
    ref = contact(po, phi, theta, direction, prev_te, phi - sp, hit)
    seed = math.nan if prev_te is None else prev_te
    te, k, a, b = track(po, [phi], [theta], direction, [seed], [sp], False)
    assert float(te[0]) == ref[0] or (math.isnan(te[0]) and math.isnan(ref[0])), (float(te[0]), ref[0])
    assert (int(k[0]), int(a[0]), int(b[0])) == tuple(ref[1:4])
    return ref
