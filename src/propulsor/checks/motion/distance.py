"""Least distances between outline boundaries (points to segments), and the check records of the sweeps."""

from __future__ import annotations

from itertools import chain

import numpy as np

from ...check import Check
from .outlines import Outline

__all__ = ['ball_pairs', 'dist_each_point', 'check_record']

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
