"""The motion checks' compiled point product (``checks/motion/poses.py``, ``apply_pose``): each coordinate the
fused multiply-add it names, exactly rounded, and numpy's matrix product bit for bit where numpy's product fuses
the same way (OpenBLAS on a processor with FMA, as on the machine the outputs are proven on)."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from propulsor.checks.motion.poses import _apply_pose_nb, apply_pose


def _fma(a: float, b: float, c: float) -> float:
    return float(Fraction(a) * Fraction(b) + Fraction(c))


def _cases(seed: int = 7):
    rng = np.random.default_rng(seed)
    for n, count in ((1, 200), (2, 30), (3, 10), (17, 6), (400, 6)):
        for k in range(count):
            th = rng.uniform(-7.0, 7.0)
            t = rng.normal(size=2) * 80.0 if k % 2 else np.zeros(2)  # without a translation too: no rounding hides
            M = np.array([[np.cos(th), -np.sin(th), t[0]], [np.sin(th), np.cos(th), t[1]]])
            yield M, rng.normal(size=(n, 2)) * rng.uniform(0.5, 400.0)


def test_each_coordinate_is_one_fused_multiply_add_then_the_translation():
    """Against exact rational arithmetic: two points or more, fma(y, M01, x M00) + M02 (and the row below); one point,
    fma(x, M00, y M01) + M02."""
    for M, P in _cases():
        got = _apply_pose_nb(M, P)
        for i in range(min(len(P), 40)):
            x, y = float(P[i, 0]), float(P[i, 1])
            for r in range(2):
                a, b, t = float(M[r, 0]), float(M[r, 1]), float(M[r, 2])
                want = (_fma(x, a, y * b) if len(P) == 1 else _fma(y, b, x * a)) + t
                assert got[i, r] == want


def _numpy_fuses() -> bool:
    """Whether numpy's matrix product here sums a row's products by one fused multiply-add (x first)."""
    M = np.array([[0.1, 0.7, 0.0], [0.3, 0.9, 0.0]])
    P = np.random.default_rng(3).normal(size=(64, 2)) * 1e3
    ref = P @ M[:, :2].T
    fused = np.array([[_fma(y, M[r, 1], x * M[r, 0]) for r in range(2)] for x, y in P])
    return bool(np.array_equal(ref, fused))


@pytest.mark.skipif(not _numpy_fuses(), reason="numpy's matrix product on this processor rounds each product: the "
                    "compiled product keeps the fused form the outputs were proven with")
def test_the_same_floats_as_numpys_matrix_product():
    for M, P in _cases(11):
        assert np.array_equal(apply_pose(M, P), P @ M[:, :2].T + M[:, 2])


def test_arrays_it_is_not_compiled_for_go_to_numpy(monkeypatch):
    import propulsor.checks.motion.poses as poses

    M = np.array([[0.6, -0.8, 1.5], [0.8, 0.6, -2.5]])
    C = np.arange(12.0).reshape(6, 2) * 1.37
    assert np.array_equal(apply_pose(M, C), _apply_pose_nb(M, C))  # float64 in C order: compiled

    def refused(M, P):
        raise AssertionError("compiled for an array it is not compiled for")

    monkeypatch.setattr(poses, "_apply_pose_nb", refused)
    P = (np.arange(24.0).reshape(6, 4) * 1.37)[:, ::2]  # not in C order
    assert np.array_equal(apply_pose(M, P), P @ M[:, :2].T + M[:, 2])
    Pi = np.arange(12).reshape(6, 2)  # integers
    assert np.array_equal(apply_pose(M, Pi), Pi @ M[:, :2].T + M[:, 2])
    F = np.asfortranarray(M)  # the matrix not in C order
    assert np.array_equal(apply_pose(F, C), C @ F[:, :2].T + F[:, 2])
    with pytest.raises(AssertionError):
        apply_pose(M, C)
