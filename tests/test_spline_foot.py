"""The spline fit's foot-point distances, compiled (geometry/spline_foot.py): the same Newton iteration as the one
written on scipy's BSpline and its derivative splines (``foot_distances_scipy``, the fit's method before), and the true
normal distance where the iteration has converged."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import make_interp_spline

from propulsor.geometry.spline_foot import foot_distances, foot_distances_scipy as _scipy_newton


def _spline(n, seed):
    rng = np.random.default_rng(seed)
    u = np.sort(rng.uniform(0.0, 3.0, n))
    u[0] = 0.0
    P = 20.0 * np.column_stack([np.cos(u), np.sin(2 * u)]) + rng.normal(0.0, 0.2, (n, 2))
    t = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(P, axis=0), axis=1))])
    return make_interp_spline(t, P, k=3 if n >= 4 else n - 1), t, rng


@pytest.mark.parametrize("n", [3, 4, 5, 9, 31])
def test_the_compiled_iteration_is_the_scipy_one(n):
    """Degree 2 (three points) and 3, interior and end parameters, points off the curve both ways."""
    for seed in range(5):
        bs, t, rng = _spline(n, seed)
        t0 = np.concatenate([[t[0], t[-1]], rng.uniform(t[0], t[-1], 60)])
        Q = bs(t0) + rng.normal(0.0, 0.3, (len(t0), 2))
        ref = _scipy_newton(bs, Q, t0, t[0], t[-1])
        got = foot_distances(bs.t, bs.c, bs.k, Q, t0, t[0], t[-1])
        assert np.allclose(got, ref, rtol=0.0, atol=1e-9), np.max(np.abs(got - ref))


def test_the_distance_is_the_normal_distance_to_the_curve():
    """Points set off along the normal by a known amount, started a little away from their foot: the distance is the
    offset (a dense sampling of the curve agrees)."""
    bs, t, rng = _spline(12, 7)
    s = rng.uniform(t[1], t[-2], 40)
    d = bs.derivative(1)(s)
    nrm = np.column_stack([-d[:, 1], d[:, 0]]) / np.linalg.norm(d, axis=1)[:, None]
    off = rng.uniform(-0.05, 0.05, 40)
    Q = bs(s) + off[:, None] * nrm
    got = foot_distances(bs.t, bs.c, bs.k, Q, s + 0.01, t[0], t[-1])
    assert np.allclose(got, np.abs(off), atol=1e-9)
    dense = bs(np.linspace(t[0], t[-1], 200_001))
    brute = np.array([np.min(np.linalg.norm(dense - q, axis=1)) for q in Q])
    # no nearer point elsewhere: the sampled least distance is never below it, and above it only by the sampling
    assert np.all(got <= brute + 1e-12) and np.all(brute - got < 1e-5)


def test_degree_one_is_the_polyline():
    """Two points (degree 1: no second derivative): the distance to the segment."""
    P = np.array([[0.0, 0.0], [10.0, 0.0]])
    bs = make_interp_spline(np.array([0.0, 10.0]), P, k=1)
    Q = np.array([[3.0, 2.0], [7.5, -0.5]])
    got = foot_distances(bs.t, bs.c, bs.k, Q, np.array([5.0, 5.0]), 0.0, 10.0)
    assert np.allclose(got, [2.0, 0.5], atol=1e-12)


def test_a_fit_through_two_or_three_points():
    """fit_points of two points (a straight segment, degree 1) and three (degree 2): the distances of a spline of
    degree below 2 have no second derivative to ask scipy for (before the compiled distances it raised ValueError
    there); the spline passes through the points."""
    from propulsor.geometry.bspline import fit_points

    two = fit_points(np.array([[0.0, 0.0], [3.0, 4.0]]))
    assert two.degree == 1 and np.array_equal(two.poles, [[0.0, 0.0], [3.0, 4.0]])
    P = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]])
    three = fit_points(P)
    assert three.degree == 2
    from scipy.interpolate import BSpline

    bs = BSpline(three.knots, three.poles, three.degree)
    t = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(P, axis=0), axis=1))])
    assert np.allclose(bs(t), P, atol=1e-12)
