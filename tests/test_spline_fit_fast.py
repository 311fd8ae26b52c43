"""The spline fit's interpolation without ``make_interp_spline``'s checks (geometry/bspline.py ``_not_a_knot_spline``):
the same knots and poles as scipy's function to the last bit, on chord-length parameters of random point sets (4 to
300 points, even, uneven and nearly coincident spacing, as the fits meet them), and its special cases and errors
still scipy's."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import make_interp_spline

from propulsor.geometry.bspline import _interp, _not_a_knot_spline


def _points(rng, n, kind):
    if kind == "even":
        u = np.linspace(0.0, 1.0, n)
    elif kind == "uneven":
        u = np.cumsum(rng.uniform(0.01, 1.0, n))
    else:  # two points nearly on top of each other, the rest spread
        u = np.sort(rng.uniform(0.0, 1.0, n))
        i = int(rng.integers(1, n))
        u[i] = u[i - 1] + 1e-9
    r = 10.0 + rng.uniform(-2.0, 2.0)
    return np.column_stack([r * np.cos(u) + rng.normal(0, 1e-3, n), r * np.sin(u) + rng.normal(0, 1e-3, n)])


@pytest.mark.parametrize("kind", ["even", "uneven", "close"])
def test_the_lean_interpolation_is_make_interp_spline_bit_for_bit(kind):
    rng = np.random.default_rng({"even": 1, "uneven": 2, "close": 3}[kind])
    for n in list(range(4, 40)) + [57, 121, 300]:
        P = _points(rng, n, kind)
        bs, t = _interp(P)
        ref = make_interp_spline(t, P, k=3)
        assert bs.k == ref.k == 3
        assert bs.t.tobytes() == ref.t.tobytes() and bs.c.tobytes() == ref.c.tobytes(), (kind, n)
        assert bs.c.flags.c_contiguous and bs.c.shape == (n, 2)
        assert _not_a_knot_spline(t, P, 3).c.tobytes() == ref.c.tobytes()
        # even degree too (not a fit's, the same steps)
        assert _not_a_knot_spline(t, P, 2).c.tobytes() == make_interp_spline(t, P, k=2).c.tobytes()


def test_few_points_and_bad_points_are_scipys():
    P = np.array([[0.0, 0.0], [1.0, 0.5], [2.0, 0.0]])
    bs, t = _interp(P)  # three points: degree 2 by scipy's own function
    assert bs.k == 2 and bs.c.tobytes() == make_interp_spline(t, P, k=2).c.tobytes()
    bs, t = _interp(P[:2])  # two: a line
    assert bs.k == 1 and bs.c.tobytes() == make_interp_spline(t, P[:2], k=1).c.tobytes()
    bad = np.array([[0.0, 0.0], [1.0, 0.5], [2.0, np.nan], [3.0, 0.0], [4.0, 1.0]])
    with pytest.raises(ValueError, match="must not contain infs or nans"):
        _interp(bad)
    with pytest.raises(ValueError, match="coincident consecutive points"):
        _interp(np.array([[0.0, 0.0], [1.0, 0.5], [1.0, 0.5], [3.0, 0.0]]))
