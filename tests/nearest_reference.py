"""The numpy least distance from points to an outline's edges (cKDTree candidates, exact point-to-edge
refinement) that the 2D sweeps used before it was compiled (propulsor.checks.motion.nearest): kept as the
reference the compiled one is tested against."""

import numpy as np

from propulsor import policy
from propulsor.checks.motion.distance import _CHUNK, _chunk_discs, _point_seg, ball_pairs
from propulsor.checks.motion.outlines import Outline


def _live_points(P: np.ndarray, keep: np.ndarray, tgt: Outline, src: Outline, bound: float) -> np.ndarray:
    """The points of keep whose nearest vertex of tgt may lie within bound: a point of a chunk whose
    first point is farther than bound + rho (+ a rounding margin) from every vertex is farther than
    bound from every vertex too (triangle inequality), so a bounded query would give it inf.  Order
    of keep is kept."""
    reps, rho, rho_max = _chunk_discs(src)
    margin = policy.MOTION_PRUNE_MARGIN_MM
    dr, _ = tgt.tree.query(P[reps], distance_upper_bound=bound + rho_max + 2.0 * margin)
    live = dr - rho <= bound + margin  # inf (beyond the query bound) is dead
    return keep[live[keep // _CHUNK]]


def min_dist_points_to(P: np.ndarray, tgt: Outline, src: Outline | None = None):
    """Least distance from points P (tgt body frame) to tgt's edges: (d, index in P, foot point).

    src: the outline whose vertices P are (rigidly moved, same order), to prune far runs of them
    with discs fixed on it (the result is the same with or without it)."""
    lb = tgt.boundary_lower_bound(P)  # lower bound of each point's distance
    i0 = int(np.argmin(lb))
    ub = float(tgt.tree.query(P[i0])[0])
    keep = np.nonzero(lb <= ub + 1e-9 * (1.0 + ub))[0]  # never empty: holds for i0 up to rounding
    # a tighter upper bound from a subsample, then one bounded query: points farther than
    # ub + half_len from every vertex can never be candidates, and the tree skips them cheaply
    sub = keep[:: max(1, len(keep) // 64)]
    ub = min(ub, float(tgt.tree.query(P[sub])[0].min()))
    bound = ub + tgt.half_len + 1e-9 * (1.0 + ub)
    if src is not None and len(keep) > 4 * _CHUNK:
        keep = _live_points(P, keep, tgt, src, bound)  # drops only points the query would give inf
    dv, _ = tgt.tree.query(P[keep], distance_upper_bound=bound)
    ub = float(dv.min())
    cand = keep[dv <= ub + tgt.half_len]
    pi, si = ball_pairs(tgt, P[cand], ub + tgt.half_len + 1e-12)
    if len(pi) == 0:  # cannot happen (the nearest vertex is always in the ball); be safe
        j = int(np.argmin(dv))
        return float(dv[j]), int(keep[j]), tgt.points[int(tgt.tree.query(P[keep[j]])[1])]
    d, Q = _point_seg(P[cand][pi], tgt.seg_a[si], tgt.seg_b[si])
    j = int(np.argmin(d))
    return float(d[j]), int(cand[pi[j]]), Q[j]
