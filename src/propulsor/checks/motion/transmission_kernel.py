"""The steps of :func:`.transmission.transmission_sweep` in one compiled loop: at each step the two bodies' poses,
each body's vertices in the other's frame, whether they are certainly apart (:func:`.crossing._apart`), and the free
rotations of the driven body both ways (:func:`.backlash._free_rotations_nb`).  The same operations in the same order
as the Python loop it replaced (``tests/transmission_reference.py``), so the same floats: the poses as numpy's
``Pose.matrix``, ``inverse_pose`` and ``compose_poses`` compute them (their 2x2 products by OpenBLAS, each sum of
two products one fused multiply-add, the second product fused into the first rounded: :func:`propulsor.fused.fma`).

A step whose bodies are not certainly apart is handed back: the loop stops there and its caller takes their common
area from the boolean (manifold3d), then goes on from that step (with the area at most the tolerance) or the next.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ... import policy
from .backlash import _free_rotations_nb, _rot_bounds_nb, _target, _zone_args
from .crossing import _apart, apart_args
from .poses import _apply_pose_nb
from ...fused import fma
from ...nbcache import bind

__all__ = ["pose_pair", "sweep_steps"]


@njit(cache=True)
def _pose(angle, ox, oy):
    """``Pose(angle, (0, 0), (ox, oy)).matrix()``: [R | p + o - R p] with p = 0 (R p a matrix-vector product)."""
    c, s = math.cos(angle), math.sin(angle)
    M = np.empty((2, 3))
    M[0, 0], M[0, 1], M[1, 0], M[1, 1] = c, -s, s, c
    M[0, 2] = (0.0 + ox) - fma(-s, 0.0, c * 0.0)
    M[1, 2] = (0.0 + oy) - fma(c, 0.0, s * 0.0)
    return M


@njit(cache=True)
def _inverse(M):
    """``inverse_pose(M)``: [R^T | (-R^T) t]."""
    out = np.empty((2, 3))
    out[0, 0], out[0, 1], out[1, 0], out[1, 1] = M[0, 0], M[1, 0], M[0, 1], M[1, 1]
    out[0, 2] = fma(-M[1, 0], M[1, 2], (-M[0, 0]) * M[0, 2])
    out[1, 2] = fma(-M[1, 1], M[1, 2], (-M[0, 1]) * M[0, 2])
    return out


@njit(cache=True)
def _compose(A, B):
    """``compose_poses(A, B)`` (B first): [R_A R_B | R_A t_B + t_A]."""
    out = np.empty((2, 3))
    for i in range(2):
        for j in range(3):
            out[i, j] = fma(A[i, 1], B[1, j], A[i, 0] * B[0, j])
        out[i, 2] = out[i, 2] + A[i, 2]
    return out


@njit(cache=True)
def _pose_pair(s1, theta, s2, phi, c1x, c1y, c2x, c2y):
    """(M2, rel21, rel12): the driven body's pose, driven body -> driver body, and back."""
    M1 = _pose(s1 * theta, c1x, c1y)
    M2 = _pose(s2 * phi, c2x, c2y)
    rel21 = _compose(_inverse(M1), M2)
    return M2, rel21, _inverse(rel21)


def pose_pair(s1: float, theta: float, s2: float, phi: float, c1, c2):
    """(M2, rel21, rel12) of one step (:func:`_pose_pair`), for the step the caller takes the boolean of."""
    return _pose_pair(float(s1), float(theta), float(s2), float(phi), float(c1[0]), float(c1[1]), float(c2[0]),
                      float(c2[1]))


@njit(cache=True)
def _sweep_nb(k0, known_free, phis, theta, s1, s2, c1x, c1y, c2x, c2y, drv_pts, dvn_pts, drv_box, dvn_box, ap,
              tg_drv, tg_dvn, zone, w, w_max, tol, merge, area, fwd, back, pd, pc, ptd, ptc):
    """The steps from k0 on, each written to the output arrays, until one whose bodies are not certainly apart
    (returned; ``known_free``: step k0's common area is known, at most the tolerance: not tested again); len(phis)
    once done.  ``w``: the two first windows (forwards, backwards), carried from step to step and updated here;
    ``drv_box``, ``dvn_box``: (centre x, y, radius, r_min) of each outline's annulus."""
    n = len(phis)
    for k in range(k0, n):
        M2, rel21, rel12 = _pose_pair(s1, theta[k], s2, phis[k], c1x, c1y, c2x, c2y)
        P1 = _apply_pose_nb(rel21, dvn_pts)
        P2 = _apply_pose_nb(rel12, drv_pts)
        if not (k == k0 and known_free):
            if not _apart(-1.0, P1, P2, *ap):
                return k
            area[k] = 0.0
        C1x, C1y = rel21[0, 2], rel21[1, 2]
        rho1, lb1 = _rot_bounds_nb(P1, C1x, C1y, drv_box[0], drv_box[1], drv_box[2], drv_box[3])
        rho2, lb2 = _rot_bounds_nb(P2, 0.0, 0.0, dvn_box[0], dvn_box[1], dvn_box[2], dvn_box[3])
        f, b = _free_rotations_nb(P1, C1x, C1y, P2, rho1, lb1, rho2, lb2, M2, s2, w[0], w[1], w_max, tol, merge,
                                  tg_drv, tg_dvn, zone)
        fwd[k], pc[k], ptc[k, 0], ptc[k, 1] = f
        back[k], pd[k], ptd[k, 0], ptd[k, 1] = b
        # start the next step's search just above this step's answer
        if math.isfinite(f[0]):
            w[0] = min(max(1.25 * f[0], 1e-6), w_max)
        if math.isfinite(b[0]):
            w[1] = min(max(1.25 * b[0], 1e-6), w_max)
    return n


def sweep_steps(drv, dvn, phis, theta, senses, c1, c2, w_max: float, tol: float, merge: float, out: tuple,
                boolean) -> None:
    """Every step of the sweep into ``out`` = (area, fwd, back, pairs drive, pairs coast, point drive, point coast),
    the compiled loop (:func:`_sweep_nb`) run from step to step where the bodies may overlap: ``boolean(rel21)`` gives
    their common area there (mm^2); above ``policy.OVERLAP_AREA_TOL_MM2`` a step's rotations and contact points are
    nan and its pairs 0, as the loop it replaced left them."""
    area, fwd, back, pd, pc, ptd, ptc = out
    n = len(phis)
    s1, s2 = float(senses[0]), float(senses[1])
    c1x, c1y, c2x, c2y = float(c1[0]), float(c1[1]), float(c2[0]), float(c2[1])
    w = np.full(2, min(1e-3, w_max))
    args = (np.ascontiguousarray(phis, np.float64), np.ascontiguousarray(theta, np.float64), s1, s2, c1x, c1y, c2x,
            c2y, drv.points, dvn.points, _box(drv), _box(dvn), apart_args(drv, dvn), _target(drv), _target(dvn),
            _zone_args(dvn), w, float(w_max), float(tol), float(merge), area, fwd, back, pd, pc, ptd, ptc)
    k, known = 0, False
    while k < n:
        k = _sweep_nb(k, known, *args)
        known = False
        if k >= n:
            break
        area[k] = boolean(pose_pair(s1, theta[k], s2, phis[k], (c1x, c1y), (c2x, c2y))[1])
        if area[k] > policy.OVERLAP_AREA_TOL_MM2:  # interfering: free rotations have no meaning
            fwd[k] = back[k] = np.nan
            ptc[k] = ptd[k] = np.nan
            k += 1
        else:
            known = True


def _box(o) -> np.ndarray:
    """(centre x, y, radius, r_min) of the outline's annulus, as the step reads it."""
    return np.array([float(o.center[0]), float(o.center[1]), float(o.radius), float(o.r_min)])


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
