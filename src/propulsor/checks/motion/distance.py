"""Least distances between outline boundaries (points to segments), and the check records of the sweeps."""

from __future__ import annotations

from itertools import chain

import numpy as np

from ...check import Check
from .outlines import Outline

__all__ = ['ball_pairs', 'min_dist_points_to', 'dist_each_point', 'check_record']


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


def min_dist_points_to(P: np.ndarray, tgt: Outline):
    """Least distance from points P (tgt body frame) to tgt's edges: (d, index in P, foot point)."""
    lb = tgt.boundary_lower_bound(P)  # lower bound of each point's distance
    i0 = int(np.argmin(lb))
    ub = float(tgt.tree.query(P[i0])[0])
    keep = np.nonzero(lb <= ub + 1e-9 * (1.0 + ub))[0]  # never empty: holds for i0 up to rounding
    # a tighter upper bound from a subsample, then one bounded query: points farther than
    # ub + half_len from every vertex can never be candidates, and the tree skips them cheaply
    sub = keep[:: max(1, len(keep) // 64)]
    ub = min(ub, float(tgt.tree.query(P[sub])[0].min()))
    dv, _ = tgt.tree.query(P[keep], distance_upper_bound=ub + tgt.half_len + 1e-9 * (1.0 + ub))
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
    """Distance from every point of P (tgt body frame) to tgt's boundary."""
    if len(P) == 0:
        return np.empty(0)
    dv, _ = tgt.tree.query(P)
    pi, si = ball_pairs(tgt, P, dv + tgt.half_len + 1e-12)
    d, _ = _point_seg(P[pi], tgt.seg_a[si], tgt.seg_b[si])
    out = np.full(len(P), np.inf)
    np.minimum.at(out, pi, d)
    return out


def check_record(name: str, passed: bool, value, limit, unit: str, message: str) -> Check:
    return Check(name, bool(passed), None if value is None else float(value),
                 None if limit is None else float(limit), unit, message)
