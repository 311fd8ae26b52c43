"""The Python formulation of the transmission sweep's steps and of the free rotation (checks/motion/transmission.py
and backlash.py before their loops were compiled, 2026-12-04): the reference the compiled loop
(checks/motion/transmission_kernel.py, backlash._free_rotation_nb) must match bit for bit
(tests/test_transmission_kernel.py).  Its rotation hits are the compiled pairs and reduction with numpy's own
arctan2 between them, as they were."""

from __future__ import annotations

import math

import numpy as np

from propulsor import policy
from propulsor.checks.motion.backlash import _ring_pairs, _rot_reduce, _zones_nb, rot_bounds
from propulsor.checks.motion.crossing import certainly_apart
from propulsor.checks.motion.nearest import grid_of
from propulsor.checks.motion.poses import Pose, apply_pose, compose_poses, inverse_pose


def rot_hits_both(P, C, tgt, sign, w, w_other, rho, lb):
    g = grid_of(tgt)
    both = w_other is not None
    wide = max(w, w_other) if both else w
    chord_factor = 2.0 * math.sin(0.5 * min(wide, math.pi))
    offs, seg, Y, X, T, ok, ok2 = _ring_pairs(np.ascontiguousarray(P, np.float64), float(C[0]), float(C[1]),
                                              tgt.points, g.seg_b, tgt.prev, tgt.half_len, g.origin[0], g.origin[1],
                                              g.h, g.nx, g.ny, g.start, g.items, g.near, float(sign),
                                              np.ascontiguousarray(rho, np.float64),
                                              np.ascontiguousarray(lb, np.float64), chord_factor, both)
    A = np.arctan2(Y, X)  # numpy's own arctan2
    one = _rot_reduce(offs, seg, sign * A, T, ok, float(w))
    return one, (_rot_reduce(offs, seg, -sign * A, T, ok2, float(w_other)) if both else None)


def rot_hits(P, C, tgt, sign, w, rho, lb):
    return rot_hits_both(P, C, tgt, sign, w, None, rho, lb)[0]


def free_rotation(drv, dvn, P1, C1, P2, rho1, lb1, rho2, lb2, M2, body_sign, w0, w_max, tol, merge, first=None,
                  hits=rot_hits):
    """(delta, pairs, world point) of the driven body's free rotation (``hits``: the rotation hits to use)."""
    w = w0
    while True:
        if first is not None:
            (d1, e1, t1), (d2, e2, t2) = first
            first = None
        else:
            d1, e1, t1 = hits(P1, C1, drv, body_sign, w, rho1, lb1)
            d2, e2, t2 = hits(P2, np.zeros(2), dvn, -body_sign, w, rho2, lb2)
        dmin = min(d1.min(), d2.min())
        if not np.isfinite(dmin):
            if w >= w_max:
                return math.inf, 0, np.full(2, np.nan)
            w = min(4.0 * w, w_max)
            continue
        rmin = max(min(rho1[np.isfinite(d1)].min(initial=np.inf), rho2[np.isfinite(d2)].min(initial=np.inf)), 1e-9)
        need = dmin + 2.0 * tol / rmin
        if need > w and w < w_max:
            w = min(need, w_max)
            continue
        break
    n_pairs = _zones_nb(d1, np.ascontiguousarray(rho1, np.float64), d2, np.ascontiguousarray(rho2, np.float64), e2, t2,
                        float(dmin), float(tol), dvn.arclen, dvn.seg_len, dvn.loop_id, dvn.perimeter, float(merge))
    if d1.min() <= d2.min():
        i = int(np.argmin(d1))
        pt = dvn.points[i]
    else:
        i = int(np.argmin(d2))
        k = e2[i]
        pt = dvn.seg_a[k] + t2[i] * (dvn.seg_b[k] - dvn.seg_a[k])
    ang = body_sign * dmin
    c, s = math.cos(ang), math.sin(ang)
    pw = apply_pose(M2, np.array([[c * pt[0] - s * pt[1], s * pt[0] + c * pt[1]]]))[0]
    return float(dmin), n_pairs, pw


def free_rotations(drv, dvn, P1, C1, P2, rho1, lb1, rho2, lb2, M2, body_sign, w_this, w_other, w_max, tol, merge):
    h1, h1o = rot_hits_both(P1, C1, drv, body_sign, w_this, w_other, rho1, lb1)
    h2, h2o = rot_hits_both(P2, np.zeros(2), dvn, -body_sign, w_this, w_other, rho2, lb2)
    geo = (P1, C1, P2, rho1, lb1, rho2, lb2, M2)
    return (free_rotation(drv, dvn, *geo, body_sign, w_this, w_max, tol, merge, first=(h1, h2)),
            free_rotation(drv, dvn, *geo, -body_sign, w_other, w_max, tol, merge, first=(h1o, h2o)))


def steps(drv, dvn, phis, theta, senses, c1, c2, max_angle, contact_tol, contact_merge):
    """(area, fwd, back, pairs drive, pairs coast, point drive, point coast) of every step, as the Python loop of
    ``transmission_sweep`` computed them."""
    s1, s2 = (float(s) for s in senses)
    c1, c2 = np.asarray(c1, float), np.asarray(c2, float)
    N = len(phis)
    area, fwd, back = np.zeros(N), np.zeros(N), np.zeros(N)
    pd, pc = np.zeros(N, int), np.zeros(N, int)
    ptd, ptc = np.zeros((N, 2)), np.zeros((N, 2))
    w_fwd = w_back = min(1e-3, max_angle)
    for k in range(N):
        M1 = Pose(s1 * theta[k], (0.0, 0.0), tuple(c1)).matrix()
        M2 = Pose(s2 * phis[k], (0.0, 0.0), tuple(c2)).matrix()
        rel21 = compose_poses(inverse_pose(M1), M2)
        rel12 = inverse_pose(rel21)
        P1 = apply_pose(rel21, dvn.points)
        P2 = apply_pose(rel12, drv.points)
        apart = certainly_apart(drv, dvn, P1, P2, None)
        area[k] = 0.0 if apart else (drv.section ^ dvn.section.transform(rel21)).area()
        if area[k] > policy.OVERLAP_AREA_TOL_MM2:
            fwd[k] = back[k] = np.nan
            ptc[k] = ptd[k] = np.nan
            continue
        C1 = rel21[:, 2]
        rho1, lb1 = rot_bounds(P1, C1, drv)
        rho2, lb2 = rot_bounds(P2, (0.0, 0.0), dvn)
        f, b = free_rotations(drv, dvn, P1, C1, P2, rho1, lb1, rho2, lb2, M2, s2, w_fwd, w_back, max_angle,
                              contact_tol, contact_merge)
        fwd[k], pc[k], ptc[k] = f
        back[k], pd[k], ptd[k] = b
        if math.isfinite(f[0]):
            w_fwd = min(max(1.25 * f[0], 1e-6), max_angle)
        if math.isfinite(b[0]):
            w_back = min(max(1.25 * b[0], 1e-6), max_angle)
    return area, fwd, back, pd, pc, ptd, ptc
