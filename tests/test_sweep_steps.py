"""The 2D sweep's compiled loop over the steps where the bodies are apart (``checks/motion/sweep_steps.py``): the same
overlap areas, clearances and closest points, bit for bit, as the sweep taken step by step, through every way it
stops (the boolean's steps, the KD-tree's, a change of grid level), on toothed wheels in mesh and on bodies one of
which passes into the other's hole without touching."""

from __future__ import annotations

import math

import numpy as np
import pytest

import propulsor.checks.motion.sweep2d as s2
from propulsor.checks.motion import Pose, rotation_matrices, sweep_pair, sweep_pair_windowed

from test_motion import involute_gear


def _toothed(z: int, r: float, h: float, n: int = 24) -> np.ndarray:
    t = np.linspace(0.0, 2.0 * math.pi, z * n, endpoint=False)
    rr = r + 0.5 * h * np.cos(z * t)
    return np.column_stack([rr * np.cos(t), rr * np.sin(t)])


def _both_ways(monkeypatch, run):
    """(result with the compiled loop, result step by step, the steps the loop took)."""
    taken = []
    fast = s2.apart_steps

    def counted(A, B, rel_ba, rel_ab, Ma, Mb, k0, *out):
        k = fast(A, B, rel_ba, rel_ab, Ma, Mb, k0, *out)
        taken.append(k - k0)
        return k

    monkeypatch.setattr(s2, "apart_steps", counted)
    a = run()
    monkeypatch.setattr(s2, "apart_steps", lambda A, B, rel_ba, rel_ab, Ma, Mb, k0, *out: k0)
    b = run()
    return a, b, sum(taken)


def _same(a, b):
    for f in ("overlap_area", "clearance", "point_a", "point_b", "angle_a", "angle_b"):
        assert np.array_equal(getattr(a, f), getattr(b, f)), f


def test_wheels_in_mesh_then_pushed_together_then_far_apart(monkeypatch):
    """Two toothed rings turning in mesh (apart), then the driven one moved into the driver (overlap: the boolean's
    steps), then away by ten times its size (the KD-tree's and coarser grids' steps), then back."""
    z1, z2 = 12, 18
    drv, dvn = _toothed(z1, 6.0, 1.6), _toothed(z2, 9.0, 1.6)
    n = 240
    th = np.linspace(0.0, 2 * math.pi / z1 * 3, n)
    L = np.full(n, 17.0)  # tips 0.4 mm apart
    L[60:80] = 15.5  # pushed in: the teeth overlap
    L[120:170] = np.linspace(17.0, 300.0, 50)  # away
    L[170:200] = np.linspace(300.0, 17.0, 30)  # and back
    Ma = rotation_matrices(th, np.column_stack([L, np.zeros(n)]))
    Mb = rotation_matrices(-th * z1 / z2)

    def run():
        return sweep_pair([drv], Ma, [dvn], Mb, max_segment=0.3, name="mesh")

    a, b, taken = _both_ways(monkeypatch, run)
    _same(a, b)
    assert a.max_overlap > 0.01 and a.min_clearance < 0 and a.clearance.max() > 250.0
    assert taken > n // 2  # most steps in the compiled loop


def test_a_body_inside_anothers_hole_without_touching(monkeypatch):
    """A small square slides from outside a plate into its square hole and out again without touching an edge:
    while inside the plate's material (between the outline and the hole) the bodies share area with no crossing,
    which only the loop test sees; in the hole they are apart."""
    plate = [np.array([[0.0, 0.0], [40.0, 0.0], [40.0, 20.0], [0.0, 20.0]]),
             np.array([[25.0, 5.0], [25.0, 15.0], [35.0, 15.0], [35.0, 5.0]])]
    sq = [np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])]
    x = np.linspace(-10.0, 50.0, 241)
    Mb = rotation_matrices(np.zeros(len(x)), np.column_stack([x, np.full(len(x), 10.0)]))

    def run():
        return sweep_pair(plate, Pose(), sq, Mb, max_segment=0.5, name="hole")

    a, b, taken = _both_ways(monkeypatch, run)
    _same(a, b)
    inside_material = (x > 1.5) & (x < 23.5)
    in_hole = (x > 26.5) & (x < 33.5)
    assert np.all(a.overlap_area[inside_material] == pytest.approx(4.0, rel=1e-9))
    assert np.all(a.overlap_area[in_hole] == 0.0) and np.all(a.clearance[in_hole] > 0.0)
    assert taken >= 40


def test_the_windowed_sweep_of_gears_in_mesh(monkeypatch):
    """A ring gear's planet-like wheel turning in mesh, swept in windows (the final drive's sweep)."""
    big = [involute_gear(40, 1.0, j_n=0.1, n_flank=40, sag=1e-3)[0]]
    small = [involute_gear(16, 1.0, j_n=0.1, n_flank=40, sag=1e-3)[0]]
    n = 120
    phi = np.linspace(0.0, 2 * math.pi / 40 * 4, n)
    Ma = rotation_matrices(phi)
    a_w = 0.5 * (40 + 16) * 1.0
    Mb = rotation_matrices(-phi * 40 / 16 + math.pi / 16, np.tile([a_w, 0.0], (n, 1)))

    def run():
        return sweep_pair_windowed(big, Ma, small, Mb, reach=1.0, max_segment=0.1, name="win")

    a, b, taken = _both_ways(monkeypatch, run)
    _same(a, b)
    assert taken > n // 2 and 0.0 < a.min_clearance < 1.0


@pytest.mark.parametrize("case", ["cross", "inside"])
def test_a_jump_from_apart_into_a_crossing_or_into_the_material(monkeypatch, case):
    """Steps apart, then at once across (a vertical bar over a horizontal one: edges cross, no loop's first vertex in
    the other) or inside (a small square within the bar's material: no edge crosses, one loop holds the other),
    then apart again: the loop must hand each such step to the boolean."""
    bar = [np.array([[0.0, 0.0], [40.0, 0.0], [40.0, 4.0], [0.0, 4.0]])]
    other = ([np.array([[-1.0, -10.0], [1.0, -10.0], [1.0, 10.0], [-1.0, 10.0]])] if case == "cross"
             else [np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])])
    xy = [(-20.0, 2.0), (-19.0, 2.0), (20.0, 2.0), (21.0, 2.0), (-20.0, 2.0), (-19.5, 2.0), (10.0, 2.0), (-30.0, 2.0)]
    Mb = rotation_matrices(np.zeros(len(xy)), np.array(xy))

    def run():
        return sweep_pair(bar, Pose(), other, Mb, max_segment=100.0, name=case)

    a, b, taken = _both_ways(monkeypatch, run)
    _same(a, b)
    want = 8.0 if case == "cross" else 4.0
    assert a.overlap_area.tolist() == pytest.approx([0, 0, want, want, 0, 0, want, 0], abs=1e-9)
    assert taken >= 3
