"""The shortcuts of the 2D sweeps (issue 13) give the very numbers of the full search.

* the disc pruning of ``min_dist_points_to`` (runs of source vertices far from every target
  vertex are skipped before the bounded KD-tree query) returns the same distance, point and foot
  bit for bit;
* ``Outline.winding`` is the ``Positive`` fill of the outline's manifold3d section;
* a step whose bodies are provably apart skips the overlap boolean: the sweep is bit for bit the
  one that runs the boolean at every step, and a body lying wholly inside the other's material
  (boundaries far apart, yet overlapping) is still found.
"""

from __future__ import annotations

import math

import manifold3d as m3d
import numpy as np
import pytest

from propulsor.checks.motion import Outline, Pose, rotation_matrices, sweep_pair
from propulsor.checks.motion import distance, sweep2d
from propulsor.checks.motion.poses import apply_pose


def _star(n_teeth: int, r_root: float, r_tip: float, n: int = 1200) -> np.ndarray:
    """A wavy closed loop (a gear-like body with many vertices)."""
    a = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    r = r_root + (r_tip - r_root) * 0.5 * (1.0 + np.cos(n_teeth * a))
    return np.column_stack([r * np.cos(a), r * np.sin(a)])


def _ring(r_out: float, r_in: float, n: int = 400) -> list[np.ndarray]:
    a = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    u = np.column_stack([np.cos(a), np.sin(a)])
    return [r_out * u, r_in * u[::-1]]


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


def test_winding_number_is_the_positive_fill_of_the_section():
    o = Outline(_ring(10.0, 6.0) + [_star(5, 2.0, 3.0, 300)], 0.2)  # a ring with a star island in the hole
    rng = np.random.default_rng(3)
    P = rng.uniform(-12.0, 12.0, size=(300, 2))
    inside = o.winding(P) > 0
    eps = 1e-4
    for p, w in zip(P, inside):
        sq = m3d.CrossSection([np.ascontiguousarray(p + eps * np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]]))])
        assert w == ((o.section ^ sq).area() > 0.5 * (2 * eps) ** 2)
    assert inside.any() and (~inside).any()


def _sweeps(profile_a, poses_a, profile_b, poses_b, monkeypatch, **kw):
    fast = sweep_pair(profile_a, poses_a, profile_b, poses_b, **kw)
    with monkeypatch.context() as m:
        m.setattr(sweep2d, "_apart", lambda *a: False)
        slow = sweep_pair(profile_a, poses_a, profile_b, poses_b, **kw)
    return fast, slow


def _same(a, b) -> None:
    for f in ("overlap_area", "clearance", "point_a", "point_b"):
        assert getattr(a, f).tobytes() == getattr(b, f).tobytes(), f


def test_apart_steps_skip_the_boolean_and_give_the_same_sweep(monkeypatch):
    calls = []
    real = sweep2d._apart
    monkeypatch.setattr(sweep2d, "_apart", lambda *a: calls.append(real(*a)) or calls[-1])
    # a toothed wheel turning beside another at a varying gap (some steps far, some in contact)
    A, B = [_star(12, 20.0, 23.0)], [_star(9, 14.0, 17.0, 900)]
    phi = np.linspace(0.0, 2.0 * math.pi, 24, endpoint=False)
    Mb = rotation_matrices(phi, np.column_stack([39.0 + 2.5 * np.cos(phi), np.zeros_like(phi)]))
    fast = sweep_pair(A, Pose(), B, Mb, max_segment=0.2)
    assert any(calls) and not all(calls)  # both kinds of steps occur
    assert (fast.overlap_area > 0).any() and (fast.overlap_area == 0).any()
    monkeypatch.setattr(sweep2d, "_apart", lambda *a: False)
    _same(fast, sweep_pair(A, Pose(), B, Mb, max_segment=0.2))


def test_a_body_inside_the_other_is_never_taken_for_apart(monkeypatch):
    """A small disc far from every edge of a thick ring: in the hole it is apart (area 0), in the
    material it overlaps by its whole area although the boundaries are far apart."""
    ring = _ring(30.0, 10.0)
    disc = [_star(1, 2.0, 2.0, 200)]  # a circle of radius 2
    poses = [Pose(0.0, (0.0, 0.0), (x, 0.0)) for x in (0.0, 20.0, 45.0)]  # hole, material, outside
    fast, slow = _sweeps(ring, Pose(), disc, poses, monkeypatch, max_segment=0.5)
    _same(fast, slow)
    assert fast.overlap_area[0] == 0.0 and fast.overlap_area[2] == 0.0
    assert fast.overlap_area[1] == pytest.approx(Outline(disc).area, rel=1e-9)
    assert fast.clearance[1] < 0  # reported as penetration, not as the 8 mm to the ring's edges
