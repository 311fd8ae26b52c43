"""The shortcut of the 2D sweeps' clearance (issue 13) gives the very numbers of the full search:
the disc pruning of ``min_dist_points_to`` (runs of source vertices far from every target vertex
are skipped before the bounded KD-tree query) returns the same distance, point and foot bit for
bit, in a single call and over a whole sweep."""

from __future__ import annotations

import math

import numpy as np

from propulsor.checks.motion import Outline, Pose, rotation_matrices, sweep_pair
from propulsor.checks.motion import distance, sweep2d
from propulsor.checks.motion.poses import apply_pose


def _star(n_teeth: int, r_root: float, r_tip: float, n: int = 1200) -> np.ndarray:
    """A wavy closed loop (a gear-like body with many vertices)."""
    a = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    r = r_root + (r_tip - r_root) * 0.5 * (1.0 + np.cos(n_teeth * a))
    return np.column_stack([r * np.cos(a), r * np.sin(a)])


def test_disc_pruning_gives_the_same_answer_bit_for_bit():
    tgt = Outline([_star(12, 20.0, 23.0)], 0.1)
    src = Outline([_star(9, 14.0, 17.0, 900)], 0.1)
    assert len(src.points) > 8 * distance._CHUNK  # many discs, most of them far
    pruned_somewhere = False
    rng = np.random.default_rng(7)
    for k in range(40):
        ang = float(rng.uniform(0, 2 * math.pi))
        gap = float(rng.uniform(0.05, 6.0))
        M = Pose(ang, (0.0, 0.0), (23.0 + 17.0 + gap, float(rng.uniform(-3, 3)))).matrix()
        P = apply_pose(M, src.points)
        full = distance.min_dist_points_to(P, tgt)
        fast = distance.min_dist_points_to(P, tgt, src)
        assert full[0] == fast[0] and full[1] == fast[1] and full[2].tobytes() == fast[2].tobytes()
        lb = tgt.boundary_lower_bound(P)
        keep = np.nonzero(lb <= full[0] + tgt.half_len)[0]
        live = distance._live_points(P, keep, tgt, src, full[0] + tgt.half_len)
        pruned_somewhere |= len(live) < len(keep)
        assert full[1] in live  # the nearest point is never pruned
    assert pruned_somewhere  # the shortcut is exercised, not only bypassed


def test_a_sweep_with_pruning_equals_the_sweep_without(monkeypatch):
    """A toothed wheel turning beside another at a varying gap (far, near and overlapping steps)."""
    A, B = [_star(12, 20.0, 23.0)], [_star(9, 14.0, 17.0, 900)]
    phi = np.linspace(0.0, 2.0 * math.pi, 24, endpoint=False)
    Mb = rotation_matrices(phi, np.column_stack([39.0 + 2.5 * np.cos(phi), np.zeros_like(phi)]))
    fast = sweep_pair(A, Pose(), B, Mb, max_segment=0.2)
    assert (fast.overlap_area > 0).any() and (fast.clearance > 1.0).any()
    full = distance.min_dist_points_to
    monkeypatch.setattr(sweep2d, "min_dist_points_to", lambda P, tgt, src=None: full(P, tgt))
    slow = sweep_pair(A, Pose(), B, Mb, max_segment=0.2)
    for f in ("overlap_area", "clearance", "point_a", "point_b"):
        assert getattr(fast, f).tobytes() == getattr(slow, f).tobytes(), f
