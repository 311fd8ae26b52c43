"""Every tooth pair that can take load at a phase of a pair, measured on the finished outlines: the as-built contact
of :mod:`.contact_events` (the driven wheel turned from the law's position until the outlines touch) extended to the
pairs that do not touch yet but would under a small further rotation — each with its rotational gap, its contact
point in both body frames, the contact normal and its lever arms about both axes.

At law phase phi (driver at theta(phi)) the driven wheel is placed a margin on the free side of the as-built contact
(te, from the resolved contact law) and turned (drive: back) through margin + ``window``; every vertex of either
outline whose circle enters the other outline within that rotation is a hit (:func:`.backlash._rot_hits`, exact for the
polylines); the hits are grouped by tooth pair (nearest tooth centre by polar angle in each body frame) and each
pair keeps its first hit.  The pair hit first is the one touching (gap 0); another pair's gap is its extra rotation
(rad of the driven wheel).  The force a pair carries acts along the normal of the edge hit (world frame: driven axis
at the origin, driver axis at (L, 0)); its lever arms are l2 = |X × n| about the driven axis and l1 about the driver's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from numba import njit

from ... import policy
from ...nbcache import bind
from .contact_events import DRIVE, PairOutlines, _rot
from .contact_kernels import _nearest_teeth_nb, _pair_hits_pruned

__all__ = ["PairContact", "phase_contacts"]


@dataclass(frozen=True)
class PairContact:
    """One tooth pair that can take load at one phase."""

    driver_tooth: int
    driven_tooth: int
    gap: float            #: rad of the driven wheel beyond the first contact
    p_driver: np.ndarray  #: contact point, driver body frame (mm)
    p_driven: np.ndarray  #: contact point, driven body frame
    x: np.ndarray         #: contact point, world frame
    n: np.ndarray         #: unit normal along the force on the driven tooth, world frame
    l1: float             #: lever arm of the normal about the driver's axis, mm
    l2: float             #: about the driven axis, mm
    edge_of: str          #: "driver" or "driven": whose edge the hit lies on (the other's vertex)
    vertex: int           #: that vertex (index into the other outline's points)


def _all_hits(pair: PairOutlines, phi_a: float, theta: float, sign: float, w: float):
    """Every entering hit within w of the driven wheel turning from phi_a: (delta, side, vertex, edge, t) arrays
    (side 1: a driven vertex on a driver edge, 2: a driver vertex on a driven edge): the hits of
    :func:`.contact_kernels._first_hit_pruned` without the reduction to the first (:meth:`.PairOutlines.hits`: the
    finite hits of :meth:`.PairOutlines._all_hits`, the vertices that cannot reach the mate left out)."""
    (i1, d1, e1, t1), (i2, d2, e2, t2) = pair.hits(phi_a, theta, sign, w)
    k1, k2 = np.isfinite(d1), np.isfinite(d2)
    return (np.concatenate([d1[k1], d2[k2]]), np.concatenate([np.ones(k1.sum(), int), np.full(k2.sum(), 2)]),
            np.concatenate([i1[k1], i2[k2]]), np.concatenate([e1[k1], e2[k2]]), np.concatenate([t1[k1], t2[k2]]))


def _first_of_each_pair(d: np.ndarray, t_drv: np.ndarray, t_dvn: np.ndarray) -> np.ndarray:
    """The hit of least ``d`` of each tooth pair (``t_drv[k]``, ``t_dvn[k]``; the first of equal ones), the pairs in
    the order of those hits: indices into ``d``."""
    order = np.argsort(d, kind="stable")
    keys = (t_drv * (int(t_dvn.max()) + 1) + t_dvn)[order]  # one key a pair (tooth indices >= 0)
    return order[np.sort(np.unique(keys, return_index=True)[1])]


def _nearest(centres: np.ndarray, ang: np.ndarray) -> np.ndarray:
    """The nearest tooth centre (by polar angle, the first on a tie) of each angle: ``argmin`` over the teeth of
    ``|(ang - centre + pi) mod 2 pi - pi|``, compiled (:func:`.contact_kernels._nearest_teeth_nb`, numpy's own
    floor-mod: the same index)."""
    return _nearest_teeth_nb(np.ascontiguousarray(centres, np.float64), np.ascontiguousarray(ang, np.float64))


@njit(cache=True)
def _phase_hits(phi, theta, te, sign, margin, window, dvn_pts, dvn_a, dvn_b, drv_pts, drv_a, drv_b, args):
    """The hits of :func:`phase_contacts` in one compiled call: the driven wheel placed ``margin`` (else 4, 16 margins)
    on the free side of ``te`` until the first hit lies beyond a fifth of it, every finite hit of that window
    (:func:`_all_hits`: the driven vertices' first, then the driver's, each in the search's order) and its contact
    point in both body frames, the same elementwise operations as numpy's there.  (start, d, side, vertex, edge,
    p_driven, p_driver); ``args``: the pruned search's arguments after its window (:meth:`.PairOutlines.hits`)."""
    n = 0
    start = 0.0
    d = np.empty(0)
    side = v = e = np.empty(0, np.int64)
    t = np.empty(0)
    for r in range(3):
        mg = margin if r == 0 else (4.0 * margin if r == 1 else 16.0 * margin)
        start = phi + te + sign * mg
        i1, d1, e1, t1, i2, d2, e2, t2 = _pair_hits_pruned(start, theta, sign, mg + window, *args)
        # the finite hits gathered in one pass into arrays sized for all of them
        size = len(d1) + len(d2)
        d, t = np.empty(size), np.empty(size)
        side, v, e = np.empty(size, np.int64), np.empty(size, np.int64), np.empty(size, np.int64)
        n = 0
        for k in range(len(d1)):
            if np.isfinite(d1[k]):
                d[n], side[n], v[n], e[n], t[n] = d1[k], 1, i1[k], e1[k], t1[k]
                n += 1
        for k in range(len(d2)):
            if np.isfinite(d2[k]):
                d[n], side[n], v[n], e[n], t[n] = d2[k], 2, i2[k], e2[k], t2[k]
                n += 1
        if n > 0 and np.min(d[:n]) > 0.2 * mg:
            break
    d, side, v, e, t = d[:n], side[:n], v[:n], e[:n], t[:n]
    p_dvn = np.empty((n, 2))
    p_drv = np.empty((n, 2))
    for k in range(n):
        if side[k] == 1:  # a driven vertex on a driver edge
            p_dvn[k, 0], p_dvn[k, 1] = dvn_pts[v[k], 0], dvn_pts[v[k], 1]
            j = e[k]
            p_drv[k, 0] = drv_a[j, 0] + t[k] * (drv_b[j, 0] - drv_a[j, 0])
            p_drv[k, 1] = drv_a[j, 1] + t[k] * (drv_b[j, 1] - drv_a[j, 1])
        else:  # a driver vertex on a driven edge
            j = e[k]
            p_dvn[k, 0] = dvn_a[j, 0] + t[k] * (dvn_b[j, 0] - dvn_a[j, 0])
            p_dvn[k, 1] = dvn_a[j, 1] + t[k] * (dvn_b[j, 1] - dvn_a[j, 1])
            p_drv[k, 0], p_drv[k, 1] = drv_pts[v[k], 0], drv_pts[v[k], 1]
    return start, d, side, v, e, p_dvn, p_drv


@njit(cache=True)
def _firsts_nb(d, t_drv, t_dvn):
    """:func:`_first_of_each_pair` compiled: the hit of least d of each tooth pair (the first of equal ones: a
    stable sort), the pairs in the order of those hits."""
    order = np.argsort(d, kind="mergesort")
    base = 0
    for k in range(len(t_dvn)):
        base = max(base, t_dvn[k])
    base += 1
    seen = set()
    out = np.empty(len(d), np.int64)
    n = 0
    for q in range(len(order)):
        j = order[q]
        key = t_drv[j] * base + t_dvn[j]
        if key not in seen:
            seen.add(key)
            out[n] = j
            n += 1
    return out[:n]


def _hit_args(pair: PairOutlines) -> tuple:
    """What :func:`_phase_hits` takes after the window: both outlines' points and edges, the pruned search's
    arguments (kept on the pair)."""
    h = pair.__dict__.get("_phase_args")
    if h is None:
        ka, drv, dvn = pair._kernel_args, pair.drv, pair.dvn
        h = pair.__dict__["_phase_args"] = (
            ka[1], np.ascontiguousarray(dvn.seg_a, np.float64), np.ascontiguousarray(dvn.seg_b, np.float64), ka[5],
            np.ascontiguousarray(drv.seg_a, np.float64), np.ascontiguousarray(drv.seg_b, np.float64),
            tuple(ka[:11]) + tuple(pair._prune_args) + tuple(ka[11:]))
    return h


def phase_contacts(pair: PairOutlines, phi: float, theta: float, te: float, window: float,
                   direction: int = DRIVE, margin: float = policy.CONTACT_TRACK_MARGIN_RAD):
    """(te as measured, [PairContact ...] sorted by gap) at law phase phi with the driver at theta; ``te``: the
    as-built contact's driven offset there (a start value, e.g. interpolated from the resolved contact law);
    ``window``: the largest gap (rad) a pair may have to be listed.  (nan, []) where nothing touches.  The window's
    hits and their points are gathered in one compiled call (:func:`_phase_hits`), the teeth named by polar angle
    (numpy's ``arctan2``, then the compiled nearest centre) and each pair's first hit chosen compiled
    (:func:`_firsts_nb`): the values of the numpy steps they replace (:func:`_all_hits`, :func:`_first_of_each_pair`),
    bit for bit."""
    sign = 1.0 if direction == DRIVE else -1.0
    drv, dvn = pair.drv, pair.dvn
    start, d, side, v, e, p_dvn, p_drv = _phase_hits(float(phi), float(theta), float(te), sign, float(margin),
                                                     float(window), *_hit_args(pair))
    if not len(d):
        return math.nan, []
    dmin = float(np.min(d))
    t_dvn = _nearest(pair.driven_teeth, np.arctan2(p_dvn[:, 1], p_dvn[:, 0]))
    t_drv = _nearest(pair.driver_teeth, np.arctan2(p_drv[:, 1], p_drv[:, 0]))
    res = []
    L = pair.L
    for k in _firsts_nb(d, t_drv, t_dvn).tolist():
        a, b = int(t_drv[k]), int(t_dvn[k])
        phi_c = start - sign * float(d[k])
        R_dvn = _rot(-phi_c)
        x = R_dvn @ p_dvn[k]
        if side[k] == 1:   # the driver's edge: its left normal points into the driver; the force on the driven is -
            s = drv.seg_b[e[k]] - drv.seg_a[e[k]]
            nb = -np.array([-s[1], s[0]]) / math.hypot(s[0], s[1])
            n = _rot(theta) @ nb
        else:              # the driven edge: its left normal points into the driven wheel, along the force
            s = dvn.seg_b[e[k]] - dvn.seg_a[e[k]]
            n = R_dvn @ (np.array([-s[1], s[0]]) / math.hypot(s[0], s[1]))
        tau2 = float(x[0] * n[1] - x[1] * n[0])
        r1 = x - (L, 0.0)
        tau1 = float(r1[0] * n[1] - r1[1] * n[0])
        # drive (sign +1): the force turns the driven wheel on (clockwise, tau2 < 0) and holds the driver back
        # (its reaction -n turns the driver clockwise against its counter-clockwise running: tau1 > 0)
        l2, l1 = -sign * tau2, sign * tau1
        if l2 <= 0 or l1 <= 0:
            continue    # a force that would not pass torque from the driver to the driven wheel
        res.append(PairContact(a, b, float(d[k]) - dmin, p_drv[k].copy(), p_dvn[k].copy(), x, n, l1, l2,
                               "driver" if side[k] == 1 else "driven", int(v[k])))
    res.sort(key=lambda c: c.gap)
    return (start - sign * dmin) - phi, res


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
