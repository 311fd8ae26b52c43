"""The spline fit evaluates the exact curve once at each parameter over its refinement rounds
(geometry/bspline.py, ``fit_curve``): the same spline as a fit that evaluates every point anew each round, for a
curve whose points depend on their parameter alone, and each parameter asked for once."""

from __future__ import annotations

import math

import numpy as np

from propulsor.geometry import bspline
from propulsor.policy import SPLINE_FIT_TOL_MM


def _involute(r_b):
    def f(u):
        u = np.asarray(u, float)
        return np.column_stack([r_b * (np.cos(u) + u * np.sin(u)), r_b * (np.sin(u) - u * np.cos(u))])
    return f


def _uncached(func, u0, u1, tol=SPLINE_FIT_TOL_MM, n0=12):
    """The fit as it was before the cache: every point of every round evaluated anew (the reference)."""
    v = np.linspace(0.0, 1.0, n0)
    while True:
        u = u0 + (u1 - u0) * v
        bs, t = bspline._interp(func(u))
        fr = np.array([0.25, 0.5, 0.75])
        uq = (u[:-1, None] + fr[None, :] * np.diff(u)[:, None]).ravel()
        tq = (t[:-1, None] + fr[None, :] * np.diff(t)[:, None]).ravel()
        err = bspline._project(bs, func(uq), tq, t[0], t[-1]).reshape(-1, 3).max(axis=1)
        bad = err > 0.5 * tol
        if not np.any(bad):
            return bspline._to_spline(bs)
        v = np.sort(np.concatenate([v, 0.5 * (v[:-1] + v[1:])[bad]]))


def test_the_fit_asks_each_parameter_once_and_gives_the_same_spline():
    f = _involute(37.5)
    asked = []

    def counted(u):
        asked.extend(np.asarray(u, float).tolist())
        return f(u)

    got = bspline.fit_curve(counted, 0.0, 0.9, tol=1e-4)
    ref = _uncached(f, 0.0, 0.9, tol=1e-4)
    assert np.array_equal(got.knots, ref.knots) and np.array_equal(got.poles, ref.poles)
    assert len(asked) == len(set(asked))          # no parameter twice
    assert len(got.knots) > 12 + 4               # refined: more than one round ran
    # within the tolerance of the exact curve
    assert bspline.spline_deviation(got, f, 0.0, 0.9) <= 1e-4


def test_a_reversed_range_fits_the_same_curve():
    f = _involute(20.0)
    a, b = bspline.fit_curve(f, 0.0, 0.7, tol=1e-4), bspline.fit_curve(f, 0.7, 0.0, tol=1e-4)
    assert np.allclose(a.poles[0], b.poles[-1]) and np.allclose(a.poles[-1], b.poles[0])
    assert math.isclose(bspline.spline_deviation(b, f, 0.7, 0.0), 0.0, abs_tol=1e-4)
