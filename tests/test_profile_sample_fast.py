"""A B-spline piece's samples (geometry/profile.Spline.sample) are scipy's BSpline evaluated at the same parameters,
to the last bit: the sampler hands its points to scipy's evaluation routine directly (the routine BSpline.__call__
ends in), not through a BSpline built at every piece."""

from __future__ import annotations

import math

import numpy as np
from scipy.interpolate import BSpline

from propulsor.geometry.profile import Spline
from propulsor.planar import norms


def _reference(sp: Spline, chord_tol: float) -> np.ndarray:
    """The sampler as it stood with scipy's BSpline: the same refinement, each evaluation through BSpline."""
    t0, t1 = sp.knots[sp.degree], sp.knots[-sp.degree - 1]
    bs = BSpline(sp.knots, sp.poles, sp.degree, extrapolate=False)
    n = max(8, 4 * len(sp.poles))
    while True:
        u = np.linspace(t0, t1, n)
        p = bs(u)
        mid = bs(0.5 * (u[:-1] + u[1:]))
        err = np.max(norms(mid - 0.5 * (p[:-1] + p[1:])))
        if err <= chord_tol or n > 200000:
            return p
        n = int(n * max(1.5, math.sqrt(err / chord_tol) * 1.2))


def test_samples_are_scipys_bspline_to_the_last_bit():
    rng = np.random.default_rng(7)
    for degree in (2, 3, 5):
        for count in (degree + 1, 9, 40):
            inner = np.sort(rng.uniform(0.0, 3.0, count - degree - 1))
            knots = np.concatenate([np.zeros(degree + 1), inner, np.full(degree + 1, 3.0)]) + rng.uniform(-1, 1)
            poles = rng.normal(0.0, 20.0, (count, 2))
            for tol in (1e-2, 1e-4, 1e-5):
                got = Spline(knots, poles, degree).sample(tol)
                want = _reference(Spline(knots, poles, degree), tol)
                assert got.shape == want.shape and np.array_equal(got, want), (degree, count, tol)
                assert np.array_equal(got[[0, -1]], BSpline(knots, poles, degree)(knots[[degree, -degree - 1]]))
