"""Free rotation of a body about a centre until first contact (the backlash search): every boundary
vertex runs on a circle; its first crossing of the other boundary is a circle-segment intersection."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .outlines import Outline
from .poses import apply_pose
from .distance import ball_pairs

__all__ = ['free_rotation']


_ANG_EPS = 1e-10  # rad: a hit this close to 0 is a touching contact, not a full turn


def _rot_hits(P: np.ndarray, C: np.ndarray, tgt: Outline, sign: float, w: float, rho: np.ndarray, lb: np.ndarray):
    """First entering hit of points P rotating by sign·δ about C (all in tgt's body frame) on tgt's boundary.

    rho: distance of each point from C; lb: lower bound of its distance from tgt's
    boundary (Outline.boundary_lower_bound).  Returns (delta, edge, t) per point: delta
    in [0, w] or inf when no entering hit happens within the window w; edge index
    and parameter of the hit.  An entering hit is one where the point's velocity
    points into tgt's material (material lies left of each edge), so exits and
    grazing touches do not count.
    """
    m = len(P)
    delta = np.full(m, np.inf)
    edge = np.full(m, -1)
    tpar = np.zeros(m)
    chord_factor = 2.0 * math.sin(0.5 * min(w, math.pi))
    keep = np.nonzero(lb <= chord_factor * rho)[0]
    if len(keep) == 0:
        return delta, edge, tpar
    reach = chord_factor * rho[keep] + tgt.half_len + 1e-12
    # bounded query: a point farther than its reach from every vertex is no candidate, and one
    # within it gets its exact distance (the bound is a hair above the largest reach)
    dv, _ = tgt.tree.query(P[keep], distance_upper_bound=float(reach.max()) * (1.0 + 1e-9) + 1e-9)
    cand = keep[dv <= reach]
    if len(cand) == 0:
        return delta, edge, tpar
    reach = reach[dv <= reach]
    # candidates in chunks: a wide window (disengaged teeth) must not build a huge pair list at once
    n_near = tgt.tree.query_ball_point(P[cand[:16]], reach[:16], return_length=True)
    chunk = max(1, int(400000 // (float(np.mean(n_near)) + 1.0)))
    for c0 in range(0, len(cand), chunk):
        _rot_hits_chunk(P, C, tgt, sign, w, rho, cand[c0:c0 + chunk], reach[c0:c0 + chunk], delta, edge, tpar)
    return delta, edge, tpar


def _rot_hits_chunk(P, C, tgt: Outline, sign: float, w: float, rho, cand, reach, delta, edge, tpar) -> None:
    """Circle-edge intersections of _rot_hits for one chunk of candidate points (fills delta, edge, tpar)."""
    pi, si = ball_pairs(tgt, P[cand], reach)
    if len(pi) == 0:
        return
    p = P[cand][pi] - C
    r2 = rho[cand][pi] ** 2
    a = tgt.seg_a[si] - C
    d = tgt.seg_b[si] - tgt.seg_a[si]
    qa = np.einsum("ij,ij->i", d, d)
    qb = 2.0 * np.einsum("ij,ij->i", a, d)
    qc = np.einsum("ij,ij->i", a, a) - r2
    disc = qb * qb - 4.0 * qa * qc
    ok = disc >= 0.0
    sq = np.sqrt(np.where(ok, disc, 0.0))
    best = np.full(len(pi), np.inf)
    best_t = np.zeros(len(pi))
    for root in ((-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa)):
        t = root
        valid = ok & (t >= -1e-12) & (t <= 1.0 + 1e-12)
        t = np.clip(t, 0.0, 1.0)
        q = a + t[:, None] * d
        ang = sign * np.arctan2(p[:, 0] * q[:, 1] - p[:, 1] * q[:, 0], np.einsum("ij,ij->i", p, q))
        ang = np.where(ang < -_ANG_EPS, ang + 2.0 * math.pi, np.maximum(ang, 0.0))
        # velocity of the moving point at q: sign * perp(q); material normal of the edge: perp(d)
        entering = sign * (q[:, 0] * d[:, 0] + q[:, 1] * d[:, 1]) > 0.0  # perp(q)·perp(d) = q·d
        valid &= entering & (ang <= w)
        better = valid & (ang < best)
        best = np.where(better, ang, best)
        best_t = np.where(better, t, best_t)
    # reduce per point
    order = np.lexsort((best, pi))
    first = np.ones(len(order), bool)
    first[1:] = pi[order][1:] != pi[order][:-1]
    sel = order[first]
    idx = cand[pi[sel]]
    delta[idx] = best[sel]
    edge[idx] = si[sel]
    tpar[idx] = best_t[sel]


@dataclass
class _FreeRotation:
    delta: float  # free rotation (rad, >= 0), inf if none within the search limit
    n_pairs: int  # distinct contact zones within the contact tolerance at the touching position
    point: np.ndarray  # world point of the first contact (nan if none)


def _cluster_count(pos: np.ndarray, loop: np.ndarray, perimeter: np.ndarray, merge: float) -> int:
    """Number of groups of boundary positions (arc length along driven loops), gaps > merge split groups."""
    n = 0
    for lid in np.unique(loop):
        s = np.sort(pos[loop == lid])
        gaps = np.diff(np.concatenate([s, [s[0] + perimeter[lid]]]))
        k = int(np.count_nonzero(gaps > merge))
        n += max(k, 1)
    return n


def free_rotation(drv: Outline, dvn: Outline, P1: np.ndarray, C1: np.ndarray, P2: np.ndarray,
                   rho1: np.ndarray, lb1: np.ndarray, rho2: np.ndarray, lb2: np.ndarray,
                   M2: np.ndarray, body_sign: float, w0: float, w_max: float, tol: float, merge: float) -> _FreeRotation:
    """Free rotation of the driven body (body sense body_sign) until first contact with the driver.

    P1: driven vertices in the driver frame, C1: driven centre in the driver frame;
    P2: driver vertices in the driven frame (driven centre at its origin);
    rho*/lb*: their distances from the rotation centre / lower bounds of their
    distances from the other body.
    Side 1: driven vertices hit driver edges, rotating by +body_sign about C1.
    Side 2: driver vertices hit driven edges, rotating by −body_sign about 0.
    """
    w = w0
    while True:
        d1, e1, t1 = _rot_hits(P1, C1, drv, body_sign, w, rho1, lb1)
        d2, e2, t2 = _rot_hits(P2, np.zeros(2), dvn, -body_sign, w, rho2, lb2)
        dmin = min(d1.min(), d2.min())
        if not np.isfinite(dmin):
            if w >= w_max:
                return _FreeRotation(math.inf, 0, np.full(2, np.nan))
            w = min(4.0 * w, w_max)
            continue
        rmin = max(min(rho1[np.isfinite(d1)].min(initial=np.inf), rho2[np.isfinite(d2)].min(initial=np.inf)), 1e-9)
        need = dmin + 2.0 * tol / rmin
        if need > w and w < w_max:
            w = min(need, w_max)
            continue
        break
    # contact zones at the touching position: gap (arc at the point's radius) within tol
    f1, f2 = np.isfinite(d1), np.isfinite(d2)
    c1 = np.nonzero(f1)[0][(d1[f1] - dmin) * rho1[f1] <= tol]
    c2 = np.nonzero(f2)[0][(d2[f2] - dmin) * rho2[f2] <= tol]
    pos = np.concatenate([dvn.arclen[c1], dvn.arclen[e2[c2]] + t2[c2] * dvn.seg_len[e2[c2]]])
    loop = np.concatenate([dvn.loop_id[c1], dvn.loop_id[e2[c2]]])
    n_pairs = _cluster_count(pos, loop, dvn.perimeter, merge)
    # world point of the first contact (driven rotated into contact)
    if d1.min() <= d2.min():
        i = int(np.argmin(d1))
        pt_driven_frame = dvn.points[i]
        ang = body_sign * dmin
    else:
        i = int(np.argmin(d2))
        k = e2[i]
        pt_driven_frame = dvn.seg_a[k] + t2[i] * (dvn.seg_b[k] - dvn.seg_a[k])
        ang = body_sign * dmin
    c, s = math.cos(ang), math.sin(ang)
    pw = apply_pose(M2, np.array([[c * pt_driven_frame[0] - s * pt_driven_frame[1], s * pt_driven_frame[0] + c * pt_driven_frame[1]]]))[0]
    return _FreeRotation(float(dmin), n_pairs, pw)
