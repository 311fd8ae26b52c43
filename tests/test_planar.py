"""propulsor.planar: the row-wise norms and the box of plane points are numpy's reductions along the last axis (and
along the rows), to the last bit, on the arrays the motion checks and the tooth generator hand them."""

from __future__ import annotations

import numpy as np
import pytest

from propulsor.planar import box, norms


@pytest.mark.parametrize("scale", [1e-9, 1e-3, 1.0, 73.25, 1e6, 1e140])
def test_norms_and_box_are_numpy_s_to_the_last_bit(scale):
    rng = np.random.default_rng(int(np.log10(scale) + 200))
    for n in (1, 2, 3, 17, 1000, 4099):
        V = rng.normal(size=(n, 2)) * scale
        assert np.array_equal(norms(V), np.linalg.norm(V, axis=1))
        lo, hi = box(V)
        assert np.array_equal(lo, V.min(axis=0)) and np.array_equal(hi, V.max(axis=0)) and lo.dtype == np.float64
        # the (k, m, 2) and (k, m, l, 2) differences of the tip and foot searches
        D = V[None, : min(n, 40), :] - V[: min(n, 30), None, :]
        assert np.array_equal(norms(D), np.linalg.norm(D, axis=2))
        assert np.array_equal(norms(D[:, :, None, :] - D[:, None, :, :]),
                              np.linalg.norm(D[:, :, None, :] - D[:, None, :, :], axis=3))


def test_other_lengths_are_numpy_s_own():
    V = np.random.default_rng(5).normal(size=(200, 3)) * 40.0
    assert np.array_equal(norms(V), np.linalg.norm(V, axis=-1))
    assert norms(np.array([[1.0, 2.0, 2.0, 4.0]])).tolist() == [5.0]


def test_by_hand_and_at_the_edges():
    assert norms(np.array([[3.0, 4.0], [0.0, -0.0], [-5.0, 12.0]])).tolist() == [5.0, 0.0, 13.0]
    lo, hi = box(np.array([[1.0, -2.0], [-3.0, 5.0], [2.0, 0.5]]))
    assert lo.tolist() == [-3.0, -2.0] and hi.tolist() == [2.0, 5.0]
    # overflow to inf and a NaN as numpy has them
    big = np.array([[1e200, 1e200], [np.nan, 1.0]])
    with np.errstate(over="ignore"):
        assert np.array_equal(norms(big), np.linalg.norm(big, axis=1), equal_nan=True)
    lo, hi = box(big)
    assert np.isnan(lo[0]) and np.isnan(hi[0]) and lo[1] == 1.0 and hi[1] == 1e200
    with pytest.raises(ValueError):
        box(np.empty((0, 2)))
