"""The cam's motion read in compiled loops (laws/cam_kernels.py) gives scipy's and numpy's floats to the last bit:
the dense output of a DOP853 integration (either direction, any number of steps, at the steps' own ends, outside them
and in any order) against ``OdeSolution.__call__``; the return quintics' derivatives against the sums
``ReturnCurve.derivs`` made in numpy; a return curve built with the held KKT matrix against one built afresh; and a
cam path's state through ``SupportPath.state`` against its integration's own dense output."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from propulsor.laws.cam_kernels import DenseSolution
from propulsor.laws.cam_return import ReturnCurve, _mono_row, _quintic_gram


def _same(a, b) -> bool:
    a, b = np.asarray(a, np.float64), np.asarray(b, np.float64)
    return a.shape == b.shape and np.array_equal(a.view(np.int64), b.view(np.int64))


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_the_dense_output_is_scipys_bit_for_bit(seed):
    rng = np.random.default_rng(seed)
    for _ in range(40):
        k, w = rng.uniform(-3.0, 3.0), rng.uniform(0.0, 2.0)
        end = float(rng.choice([-1.0, 1.0]) * rng.uniform(0.05, 4.0))
        n = int(rng.integers(1, 4))
        y0 = rng.uniform(-1.0, 1.0, n)
        f = lambda t, y: [y[(i + 1) % n] * math.cos(w * t) - k * y[i] for i in range(n)]
        sol = solve_ivp(f, (0.0, end), y0, method="DOP853", rtol=10 ** rng.uniform(-12, -3), atol=1e-12,
                        dense_output=True).sol
        t = np.concatenate([rng.uniform(min(0.0, end) - 0.2, max(0.0, end) + 0.2, int(rng.integers(1, 400))),
                            sol.ts, np.nextafter(sol.ts, np.inf), np.nextafter(sol.ts, -np.inf), [0.0, -0.0, end]])
        rng.shuffle(t)
        assert _same(DenseSolution(sol)(t), sol(t))


@pytest.mark.parametrize("descending", [False, True])
def test_the_step_of_a_point_is_the_one_scipy_takes(descending):
    """Steps whose ends disagree (random terms, not an integration's: there the two steps of a shared end give the
    same value), so that a point on a step's end shows which step was taken."""
    from scipy.integrate._ivp.common import OdeSolution
    from scipy.integrate._ivp.rk import Dop853DenseOutput

    rng = np.random.default_rng(7)
    for _ in range(20):
        m, n = int(rng.integers(1, 6)), int(rng.integers(1, 3))
        ts = np.cumsum(rng.uniform(0.1, 1.0, m + 1)) * (-1.0 if descending else 1.0)
        steps = [Dop853DenseOutput(ts[i], ts[i + 1], rng.normal(size=n), rng.normal(size=(7, n))) for i in range(m)]
        sol = OdeSolution(ts, steps)
        t = np.concatenate([ts, rng.uniform(ts.min() - 0.5, ts.max() + 0.5, 50)])
        assert _same(DenseSolution(sol)(t), sol(t))


def test_the_dense_output_takes_dop853_steps_only():
    sol = solve_ivp(lambda t, y: [-y[0]], (0.0, 1.0), [1.0], method="RK45", dense_output=True).sol
    with pytest.raises(TypeError):
        DenseSolution(sol)


def _derivs_numpy(curve: ReturnCurve, phi, order):
    """``ReturnCurve.derivs`` as numpy computed it before it was compiled."""
    phi = np.asarray(phi, dtype=float)
    u = (phi - curve.a) / curve.L
    piece = np.clip(np.floor(u), 0, 1).astype(int)
    t = u - piece
    out = []
    for m in range(order + 1):
        val = np.zeros_like(t)
        for k in range(m, 6):
            fk = math.factorial(k) / math.factorial(k - m)
            val = val + curve.coef[piece, k] * fk * t ** (k - m)
        out.append(val / curve.L ** m)
    return out


def _build_afresh(end_a, end_b, a, b, H_top):
    """``ReturnCurve.build`` with its KKT matrix assembled at the call, as before it was held."""
    L = 0.5 * (b - a)
    A, rhs = [], []

    def pad(row, piece):
        full = np.zeros(12)
        full[6 * piece:6 * piece + 6] = row
        return full

    for m in range(3):
        A.append(pad(_mono_row(0.0, m), 0)); rhs.append(end_a[m] * L ** m)
        A.append(pad(_mono_row(1.0, m), 1)); rhs.append(end_b[m] * L ** m)
    for m in range(3):
        A.append(pad(_mono_row(1.0, m), 0) - pad(_mono_row(0.0, m), 1)); rhs.append(0.0)
    if H_top is not None:
        A.append(pad(_mono_row(1.0, 0), 0)); rhs.append(H_top)
    A = np.array(A)
    G = np.zeros((12, 12))
    G[:6, :6] = G[6:, 6:] = _quintic_gram()
    n = A.shape[0]
    kkt = np.zeros((12 + n, 12 + n))
    kkt[:12, :12] = 2.0 * G
    kkt[:12, 12:] = A.T
    kkt[12:, :12] = A
    return ReturnCurve(a, L, np.linalg.solve(kkt, np.concatenate([np.zeros(12), np.array(rhs)]))[:12].reshape(2, 6))


@pytest.mark.parametrize("seed", [1, 2])
def test_the_return_quintics_are_numpys_bit_for_bit(seed):
    rng = np.random.default_rng(seed)
    for _ in range(60):
        a = float(rng.uniform(0.3, 1.5))
        b = 2.0 * math.pi - a
        end_a = tuple(rng.uniform(50.0, 150.0) * np.array([1.0, rng.uniform(-1, 1), rng.uniform(-2, 2)]))
        end_b = tuple(rng.uniform(50.0, 150.0) * np.array([1.0, rng.uniform(-1, 1), rng.uniform(-2, 2)]))
        H_top = None if rng.random() < 0.4 else float(rng.uniform(40.0, 200.0))
        curve = ReturnCurve.build(end_a, end_b, a, b, H_top)
        ref = _build_afresh(end_a, end_b, a, b, H_top)
        assert _same(curve.coef, ref.coef)
        phi = np.concatenate([rng.uniform(a, b, int(rng.integers(0, 500))), [a, b, math.pi, 0.5 * (a + b)]])
        for order in range(4):
            got, want = curve.derivs(phi, order), _derivs_numpy(ref, phi, order)
            assert len(got) == order + 1 and all(_same(g, w) for g, w in zip(got, want))
        grid = phi.reshape(-1, 2) if len(phi) % 2 == 0 else phi[:, None]
        assert all(_same(g, w) for g, w in zip(curve.derivs(grid, 2), _derivs_numpy(ref, grid, 2)))


def test_a_cam_paths_state_is_its_integrations_dense_output():
    from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, solve_support

    mech = CamMechanism()
    for law in (CurvatureLaw("quadratic", 0.017, 0.0, symmetric=True),
                CurvatureLaw("linear", 0.005, 0.0, symmetric=False)):  # the second integrated both ways
        path = solve_support(mech, law, estimate_error=False)
        s = mech.phi_s
        phi = np.linspace(-s, s, 1001)
        H, g = path.state(phi)
        pos, neg = phi >= 0.0, phi < 0.0
        y = path._pos.sol(phi[pos])
        assert _same(H[pos], y[0]) and _same(g[pos], y[1])
        if path._neg is None:
            y = path._pos.sol(-phi[neg])
            assert _same(H[neg], y[0]) and _same(g[neg], -y[1])
        else:
            y = path._neg.sol(phi[neg])
            assert _same(H[neg], y[0]) and _same(g[neg], y[1])


def _crosses_numpy(P) -> bool:
    """The shoe's self-crossing test as all-pairs arrays (``shoe._segments_intersect`` before it was compiled)."""
    a, b = P[:-1], P[1:]
    n = len(a)
    if n < 3:
        return False
    d = b - a

    def cross(u, v):
        return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]

    ai, di = a[:, None, :], d[:, None, :]
    aj, dj = a[None, :, :], d[None, :, :]
    den = cross(di, dj)
    w = aj - ai
    with np.errstate(divide="ignore", invalid="ignore"):
        t = cross(w, dj) / den
        u = cross(w, di) / den
    i, j = np.indices((n, n))
    return bool(np.any((j > i + 1) & (den != 0.0) & (t >= 0) & (t < 1) & (u >= 0) & (u < 1)))


def test_the_shoes_self_crossing_test_is_the_all_pairs_one():
    from propulsor.laws.shoe import _segments_intersect

    rng = np.random.default_rng(11)
    found = {True: 0, False: 0}
    for _ in range(400):
        n = int(rng.integers(1, 40))
        kind = rng.integers(0, 3)
        if kind == 0:  # random walks on a coarse grid: vertices on other segments, collinear and parallel pieces
            P = np.cumsum(rng.integers(-2, 3, (n, 2)), axis=0).astype(float)
        elif kind == 1:  # spirals that may or may not close a loop
            t = np.linspace(0.0, rng.uniform(1.0, 9.0), n)
            P = np.column_stack([(1 + 0.05 * t) * np.cos(t), (1 + 0.05 * t) * np.sin(t) + rng.uniform(0, 0.6) * t])
        else:
            P = rng.normal(size=(n, 2))
        want = _crosses_numpy(P)
        assert _segments_intersect(P) is want, P
        found[want] += 1
    assert min(found.values()) > 50  # both answers among the cases
