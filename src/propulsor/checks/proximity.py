"""Where two solids come closest (manifold3d + a k-d tree).

manifold3d's ``min_gap`` gives the least distance between two solids but not where it is.
``nearest_points`` locates it: both meshes are refined so that no edge is longer than
``spacing`` (``Manifold.refine_to_length``: the surfaces stay the same, only subdivided), the
vertices near the other body are kept and a k-d tree gives the closest pair of vertices.  That
pair lies within about ``spacing`` of the true closest points and its distance exceeds the
true gap by at most about ``spacing``: use it for the location, ``min_gap`` for the value.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.spatial import cKDTree

__all__ = ["nearest_points"]


def _clip(man, lo, hi):
    import manifold3d as m3d

    size = np.maximum(np.asarray(hi, float) - np.asarray(lo, float), 1e-3)
    return man ^ m3d.Manifold.cube(size.tolist()).translate(np.asarray(lo, float).tolist())


def _box(man):
    b = man.bounding_box()
    return np.asarray(b[:3], float), np.asarray(b[3:], float)


def _pair(A, B, box_a, box_b, spacing: float, pad: float):
    """Closest vertex pair of A clipped to box_a and B clipped to box_b, both refined to spacing."""
    PA = np.asarray(_clip(A, *box_a).refine_to_length(spacing).to_mesh().vert_properties)[:, :3]
    PB = np.asarray(_clip(B, *box_b).refine_to_length(spacing).to_mesh().vert_properties)[:, :3]
    if len(PA) == 0 or len(PB) == 0:
        return math.inf, None, None
    d, j = cKDTree(PB).query(PA, distance_upper_bound=pad)
    i = int(np.argmin(d))
    if not np.isfinite(d[i]):
        return math.inf, None, None
    return float(d[i]), PA[i], PB[int(j[i])]


def nearest_points(A, B, bound: float, spacing: float = 2.0, coarse: float | None = None):
    """Approximate closest points of two manifold3d solids known to be within ``bound`` mm.

    Two passes: both bodies clipped to their common neighbourhood and refined to ``coarse``
    (default max(10 mm, bound / 5)); then each clipped to a box of ±2 coarse around its point of
    that pair and refined to ``spacing``.  Returns (distance of the vertex pair, point on A, point
    on B), or (inf, None, None) when nothing lies within reach.
    """
    coarse = max(10.0, 0.2 * float(bound)) if coarse is None else float(coarse)
    pad = float(bound) + 2.0 * coarse
    (la, ha), (lb, hb) = _box(A), _box(B)
    lo, hi = np.maximum(la, lb) - pad, np.minimum(ha, hb) + pad
    if np.any(lo > hi):
        return math.inf, None, None
    d, pa, pb = _pair(A, B, (lo, hi), (lo, hi), coarse, pad)
    if pa is None:
        return d, pa, pb
    r = 2.0 * coarse
    d2, qa, qb = _pair(A, B, (pa - r, pa + r), (pb - r, pb + r), spacing, d + 2.0 * coarse)
    return (d2, qa, qb) if qa is not None and d2 <= d else (d, pa, pb)
