"""The Fourier law's one-point inversion compiled (laws/fourier_kernels.py): ``theta1`` and ``U_derivs1`` are their
Python paths' (``_theta1_py``, ``_U_derivs1_py``) to the last bit, on random laws (1 to 6 terms, cos and sin, 1 to 4
lobes) and angles over several periods either way; a phi not finite still takes the Python path (its error).  The
law's array functions are the one-point path at each angle, bit for bit (the law is ``elementwise``)."""

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


@pytest.mark.parametrize("seed", [7, 8])
def test_the_array_path_is_the_one_point_path_bit_for_bit(seed):
    """Arrays of a few points take the one-point path (``laws.law.one_point_values``), larger ones the compiled loop
    over it (``fourier_kernels.theta_many``, ``derivs_many``): each angle's theta, U, dU/dphi and d2U/dphi2 are its
    one-point values to the last bit (the powers of the derivatives by C ``pow`` as Python's ``**``), in an array of
    any shape; phi of theta is ``_g01``'s sum; an angle not finite gives nan."""
    laws, rng = _laws(seed, 4)
    for law in laws:
        phi = rng.uniform(-3 * law.period, 3 * law.period, 3000)
        ref = np.array([[law.theta1(p), *law.U_derivs1(p)] for p in phi.tolist()])
        for col, f in enumerate((law.theta, law.U, law.dU_dphi, law.d2U_dphi2)):
            assert f(phi).tobytes() == ref[:, col].tobytes()
            assert f(phi.reshape(50, 60)).tobytes() == ref[:, col].tobytes()
            assert f(phi[::-3]).tobytes() == ref[::-3, col].tobytes()
        # the last array's theta and derivatives kept: each function in any order, an array changed in place
        for col in (3, 1, 0, 2, 2, 1):
            f = (law.theta, law.U, law.dU_dphi, law.d2U_dphi2)[col]
            assert f(phi).tobytes() == ref[:, col].tobytes()
        out = law.U(phi)
        out[:] = 0.0  # a caller's copy
        assert law.U(phi).tobytes() == ref[:, 1].tobytes()
        moved = phi.copy()
        moved[7] += 1e-3
        assert law.dU_dphi(moved)[7] == law.U_derivs1(float(moved[7]))[1]
        th = ref[:, 0]
        assert law.phi_of_theta(th).tobytes() == np.array([law._g01(t)[0] for t in th.tolist()]).tobytes()
        assert np.max(np.abs(law.phi_of_theta(th) - phi)) < 1e-12
        bad = np.array([0.1, math.nan, math.inf, -math.inf, 0.2] * 3)
        got = law.theta(bad)
        assert np.isnan(got[1::5]).all() and np.isnan(got[2::5]).all() and np.isnan(got[3::5]).all()
        assert got[0] == law.theta1(0.1) and got[4] == law.theta1(0.2)


def test_a_phi_not_finite_raises_as_before():
    (law,), _ = _laws(9, 1)
    with pytest.raises(ValueError):
        law.theta1(math.nan)
