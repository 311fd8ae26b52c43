"""Least distances between outline boundaries (points to segments), and the check records of the sweeps."""

from __future__ import annotations

from itertools import chain

import numpy as np

from ... import policy
from ...check import Check
from .outlines import Outline

__all__ = ['ball_pairs', 'min_dist_points_to', 'dist_each_point', 'within', 'check_record']

_CHUNK = 32  # consecutive source vertices per pruning disc (nearest.py)


def _point_seg(P: np.ndarray, A: np.ndarray, B: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    d = B - A
    dd = np.einsum("ij,ij->i", d, d)
    t = np.clip(np.einsum("ij,ij->i", P - A, d) / np.where(dd > 0, dd, 1.0), 0.0, 1.0)
    Q = A + t[:, None] * d
    return np.linalg.norm(P - Q, axis=1), Q


def ball_pairs(tgt: Outline, P: np.ndarray, r) -> tuple[np.ndarray, np.ndarray]:
    """(point index, edge index) pairs: edges of tgt with an end within r of each point."""
    lists = tgt.tree.query_ball_point(P, r)
    counts = np.fromiter(map(len, lists), int, len(lists))
    total = int(counts.sum())
    if total == 0:
        return np.empty(0, int), np.empty(0, int)
    verts = np.fromiter(chain.from_iterable(lists), int, total)
    pi = np.repeat(np.arange(len(P)), counts)
    return np.concatenate([pi, pi]), np.concatenate([verts, tgt.prev[verts]])


def _chunk_discs(src: Outline) -> tuple[np.ndarray, np.ndarray, float]:
    """Pruning discs of a source outline (cached on it): every run of _CHUNK consecutive vertices
    lies within rho[c] of its first vertex reps[c] (body frame; a rigid motion keeps the distances)."""
    cached = getattr(src, "_chunk_discs", None)
    if cached is None:
        reps = np.arange(0, len(src.points), _CHUNK)
        chunk = np.arange(len(src.points)) // _CHUNK
        dist = np.linalg.norm(src.points - src.points[reps][chunk], axis=1)
        rho = np.zeros(len(reps))
        np.maximum.at(rho, chunk, dist)
        cached = src._chunk_discs = (reps, rho, float(rho.max()))
    return cached


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
    # every point within ub + half the longest edge of a vertex may be nearest to an edge (the middle of a long
    # edge lies farther from its ends than the point is from it): lb at most that   (never empty: i0)
    keep = np.nonzero(lb <= ub + tgt.half_len + 1e-9 * (1.0 + ub))[0]
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


def dist_each_point(P: np.ndarray, tgt: Outline) -> np.ndarray:
    """Distance from every point of P (tgt body frame) to tgt's boundary (the reference of the compiled
    :func:`.nearest.dist_each`, the same floats)."""
    if len(P) == 0:
        return np.empty(0)
    dv, _ = tgt.tree.query(P)
    pi, si = ball_pairs(tgt, P, dv + tgt.half_len + 1e-12)
    d, _ = _point_seg(P[pi], tgt.seg_a[si], tgt.seg_b[si])
    out = np.full(len(P), np.inf)
    np.minimum.at(out, pi, d)
    return out


def within(P: np.ndarray, tgt: Outline, tol: float) -> np.ndarray:
    """Indices of the points of P (tgt body frame) within ``tol`` of tgt's boundary: :func:`dist_each_point` of only
    the points whose nearest vertex lies within ``tol`` plus half the longest edge (every boundary point lies
    that close to a vertex: the others are farther than ``tol``), each point's distance the same."""
    if len(P) == 0:
        return np.empty(0, int)
    dv, _ = tgt.tree.query(P, distance_upper_bound=tol + tgt.half_len + 1e-9 * (1.0 + tol))
    cand = np.nonzero(np.isfinite(dv))[0]
    return cand[dist_each_point(P[cand], tgt) <= tol]


def check_record(name: str, passed: bool, value, limit, unit: str, message: str) -> Check:
    return Check(name, bool(passed), None if value is None else float(value),
                 None if limit is None else float(limit), unit, message)
