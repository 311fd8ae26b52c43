"""The numpy formulation of the rotation hits of the backlash search (checks/motion/backlash.py before it was
compiled): the reference the compiled kernel must match bit for bit (tests/test_backlash_kernel.py)."""

from __future__ import annotations

import math

import numpy as np

from propulsor.checks.motion.distance import ball_pairs
from propulsor.checks.motion.outlines import Outline

_ANG_EPS = 1e-10


def rot_hits(P: np.ndarray, C: np.ndarray, tgt: Outline, sign: float, w: float, rho: np.ndarray, lb: np.ndarray):
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


