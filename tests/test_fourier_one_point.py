"""The Fourier law's one-point inversion compiled (laws/fourier_kernels.py): ``theta1`` and ``U_derivs1`` are their
Python paths' (``_theta1_py``, ``_U_derivs1_py``) to the last bit, on random laws (1 to 6 terms, cos and sin, 1 to 4
lobes) and angles over several periods either way; a phi not finite still takes the Python path (its error)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.laws.ratio_laws import FourierLaw


def _laws(seed, count):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < count:
        k = int(rng.integers(1, 5))
        J = int(rng.integers(1, 7))
        scale = 0.25 / (k * J)  # keeps d phi / d theta > 0 (1 / k - sum j (|c_j| + |s_j|) > 0)
        c = tuple(float(x) for x in rng.uniform(-scale, scale, J) * (rng.random(J) < 0.6))
        s = tuple(float(x) for x in rng.uniform(-scale, scale, J))
        out.append(FourierLaw(k, c, s))
    return out, rng


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_the_compiled_one_point_path_is_the_python_one_bit_for_bit(seed):
    laws, rng = _laws(seed, 6)
    for law in laws:
        phis = np.concatenate([rng.uniform(-3 * law.period, 3 * law.period, 400),
                               law.period * np.arange(-2, 3), [0.0, -0.0, 1e-300, law.period * (1 - 1e-16)]])
        for phi in phis.tolist():
            ref_th = law._theta1_py(phi)
            ref_u = law._U_derivs1_py(phi)
            object.__setattr__(law, "_last", (math.nan, math.nan))  # no remembered phi: the compiled path runs
            assert law.theta1(phi) == ref_th
            object.__setattr__(law, "_last", (math.nan, math.nan))
            assert law.U_derivs1(phi) == ref_u


def test_the_one_point_path_is_the_array_path():
    """Arrays of a few points take the one-point path (``laws.law.one_point_values``), larger ones numpy's: both agree to rounding."""
    (law,), rng = _laws(7, 1)
    phi = rng.uniform(-law.period, 2 * law.period, 64)
    assert np.allclose(law.theta(phi), [law.theta1(p) for p in phi.tolist()], rtol=0, atol=1e-13)
    assert np.allclose(law.U(phi), [law.U_derivs1(p)[0] for p in phi.tolist()], rtol=1e-13)


def test_a_phi_not_finite_raises_as_before():
    (law,), _ = _laws(9, 1)
    with pytest.raises(ValueError):
        law.theta1(math.nan)
