"""The 2D sweeps skip the manifold3d intersection where the bodies are certainly apart
(checks/motion/crossing.py): never where they share area.  Judged against the boolean itself on
bodies apart, touching, crossing with long edges (vertices far from the other body), nested in a hole and
held whole inside the other's material."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.checks.motion import Outline, Pose, rotation_matrices, sweep_pair
from propulsor.checks.motion import sweep2d
from propulsor.checks.motion.crossing import certainly_apart
from propulsor.checks.motion.poses import apply_pose, compose_poses, inverse_pose


def _star(n_teeth: int, r_root: float, r_tip: float, n: int = 600) -> np.ndarray:
    a = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    r = r_root + (r_tip - r_root) * 0.5 * (1.0 + np.cos(n_teeth * a))
    return np.column_stack([r * np.cos(a), r * np.sin(a)])


def _distance(A: Outline, B: Outline, M: np.ndarray):
    """sweep2d._boundary_distance of A held at the origin and B placed by M (the relative poses as sweep_pair's)."""
    I = np.array(Pose().matrix())
    rel_ba = compose_poses(inverse_pose(I), M)
    return sweep2d._boundary_distance(A, B, I, M, rel_ba, inverse_pose(rel_ba))


def _apart(A: Outline, B: Outline, M: np.ndarray) -> tuple[bool, float]:
    """(certainly_apart, the boolean's common area) of B placed by M in A's frame."""
    d, _, _, PB, PA = _distance(A, B, M)
    return certainly_apart(A, B, PB, PA, d), float((A.section ^ B.section.transform(M)).area())


def test_apart_only_where_the_boolean_finds_no_common_area():
    A = Outline([_star(12, 20.0, 23.0), _star(5, 6.0, 7.0, 300)[::-1]], 0.5)  # a wheel with a hole
    B = Outline([_star(9, 14.0, 17.0, 500)], 0.5)
    rng = np.random.default_rng(3)
    seen = {True: 0, False: 0}
    for _ in range(300):
        M = Pose(float(rng.uniform(0, 2 * math.pi)), (0.0, 0.0), (float(rng.uniform(30.0, 48.0)), float(rng.uniform(-4, 4)))).matrix()
        apart, area = _apart(A, B, M)
        seen[apart] += 1
        if apart:
            assert area == 0.0
    assert seen[True] > 30 and seen[False] > 30  # both kinds of step were met
    small = Outline([_star(4, 2.0, 3.0, 200)], 0.5)
    assert _apart(A, small, Pose(0.3, (0.0, 0.0), (0.5, 0.0)).matrix()) == (True, 0.0)  # in the hole
    inside, area = _apart(A, small, Pose(0.3, (0.0, 0.0), (13.0, 0.0)).matrix())  # whole in the material
    assert not inside and area > 20.0
    ring = Outline([_star(3, 40.0, 41.0, 900), _star(3, 30.0, 31.0, 900)[::-1]], 0.5)
    held, area = _apart(ring, A, np.array(Pose().matrix()))  # the wheel in the ring's hole: apart
    assert held and area == 0.0
    held, area = _apart(A, ring, np.array(Pose().matrix()))  # seen from the wheel
    assert held and area == 0.0


def test_without_the_distance_the_same_answer_with_every_edge_pair_near_the_other_body_tested():
    """d unknown (None: the polysector's contact law asks before any distance is measured): the boundaries'
    crossings are sought everywhere; the answer is the one with d wherever d already decides it, and never apart
    where the boolean finds common area; the bodies touching at a vertex are not apart (in doubt)."""
    A = Outline([_star(12, 20.0, 23.0), _star(5, 6.0, 7.0, 300)[::-1]], 0.5)
    B = Outline([_star(9, 14.0, 17.0, 500)], 0.5)
    rng = np.random.default_rng(5)
    seen = {True: 0, False: 0}
    for _ in range(200):
        M = Pose(float(rng.uniform(0, 2 * math.pi)), (0.0, 0.0), (float(rng.uniform(30.0, 48.0)), float(rng.uniform(-4, 4)))).matrix()
        d, _, _, PB, PA = _distance(A, B, M)
        apart = certainly_apart(A, B, PB, PA, None)
        seen[apart] += 1
        assert apart == certainly_apart(A, B, PB, PA, d) or d <= 1e-6
        if not apart:
            assert float((A.section ^ B.section.transform(M)).area()) > 0.0 or d <= 1e-6
    assert seen[True] > 30 and seen[False] > 30
    sq = Outline([np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])], 10.0)
    corner = Pose(0.0, (0.0, 0.0), (1.0, 1.0)).matrix()  # the squares meet at one corner: area 0, yet in doubt
    P = apply_pose(corner, sq.points)
    assert not certainly_apart(sq, sq, P, apply_pose(inverse_pose(corner), sq.points), None)
    far = Pose(0.0, (0.0, 0.0), (1.5, 0.2)).matrix()
    assert certainly_apart(sq, sq, apply_pose(far, sq.points), apply_pose(inverse_pose(far), sq.points), None)


def test_long_edges_crossing_far_from_every_vertex_are_not_apart():
    """Two thin plates crossing like a plus sign: every vertex is far from the other plate's edges, yet they
    overlap (the least vertex-to-edge distance alone would call them apart)."""
    h = Outline([np.array([[-50.0, -1.0], [50.0, -1.0], [50.0, 1.0], [-50.0, 1.0]])], 1000.0)
    v = Outline([np.array([[-1.0, -50.0], [1.0, -50.0], [1.0, 50.0], [-1.0, 50.0]])], 1000.0)
    apart, area = _apart(h, v, np.array(Pose().matrix()))
    assert not apart and area == pytest.approx(4.0)
    apart, area = _apart(h, v, Pose(0.0, (0.0, 0.0), (60.0, 0.0)).matrix())
    assert apart and area == 0.0


def test_a_sweep_gives_the_same_numbers_with_every_boolean(monkeypatch):
    A, B = [_star(12, 20.0, 23.0)], [_star(9, 14.0, 17.0, 500)]
    phi = np.linspace(0.0, 2.0 * math.pi, 36, endpoint=False)
    Mb = rotation_matrices(phi, np.column_stack([39.0 + 2.5 * np.cos(phi), np.zeros_like(phi)]))
    fast = sweep_pair(A, Pose(), B, Mb, max_segment=0.2)
    assert (fast.overlap_area > 0).any() and (fast.clearance > 1.0).any()
    monkeypatch.setattr(sweep2d, "certainly_apart", lambda *a: False)
    slow = sweep_pair(A, Pose(), B, Mb, max_segment=0.2)
    for f in ("overlap_area", "clearance", "point_a", "point_b"):
        assert getattr(fast, f).tobytes() == getattr(slow, f).tobytes(), f
