"""The return phase of the fixed cam's roller-centre path (seed 001; ours, the seed leaves it open): for
φ ∈ [π/n, 2π − π/n], a C2 closure by two quintic pieces joined at φ = π that minimise the jerk ∫(H''')² dφ and match
H, H', H'' of the support phase at both ends (:class:`ReturnCurve`), H(π) chosen for the smallest pressure angle
(:func:`_min_gamma_return`), free (minimum jerk) or given.  The support phase and the whole turn:
:mod:`propulsor.laws.cam_motion`.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from propulsor import policy

__all__ = ["ReturnCurve"]


def _quintic_gram() -> np.ndarray:
    """∫0^1 p'''(t)·q'''(t) dt for monomials t^k, t^l (k, l = 0..5)."""
    G = np.zeros((6, 6))
    for k in range(3, 6):
        for m in range(3, 6):
            G[k, m] = (k * (k - 1) * (k - 2)) * (m * (m - 1) * (m - 2)) / (k + m - 5)
    return G


def _mono_row(t: float, order: int) -> np.ndarray:
    """Row giving the order-th t-derivative of Σ c_k t^k at t."""
    row = np.zeros(6)
    for k in range(order, 6):
        row[k] = math.factorial(k) / math.factorial(k - order) * t ** (k - order)
    return row


class ReturnCurve:
    """H over the return phase [φs, 2π − φs]: two quintics joined at φ = π, C2 at both
    support ends and at the joint, minimum ∫(H''')² dφ (ours)."""

    def __init__(self, a: float, L: float, coef: np.ndarray):
        self.a = a  # start of the return phase
        self.L = L  # length of each piece
        self.coef = coef  # (2, 6) monomial coefficients in local t ∈ [0, 1]

    @classmethod
    def build(cls, end_a: tuple, end_b: tuple, a: float, b: float, H_top: float | None):
        """end_a = (H, H', H'') at φ = a, end_b at φ = b."""
        L = 0.5 * (b - a)
        rhs = []
        for m in range(3):
            rhs.append(end_a[m] * L ** m)
            rhs.append(end_b[m] * L ** m)
        rhs.extend((0.0, 0.0, 0.0))  # C2 joint at φ = π
        if H_top is not None:
            rhs.append(H_top)
        sol = np.linalg.solve(_return_kkt(H_top is not None), np.concatenate([np.zeros(12), np.array(rhs)]))
        return cls(a, L, sol[:12].reshape(2, 6))

    def derivs(self, phi, order: int = 3):
        """[H, H', ..., H^(order)] at φ ∈ [a, a + 2L]."""
        return self.derivs_on(_ReturnBasis(phi, self.a, self.L), order)

    def derivs_on(self, basis: "_ReturnBasis", order: int):
        """:meth:`derivs` at the angles of ``basis`` (made with this curve's a and L): the sums of
        :func:`.cam_kernels.quintic_derivs`, ``coef[piece, k] * fk * t ** (k - m)`` term by term as numpy would
        add them."""
        from .cam_kernels import quintic_derivs

        Lm = np.array([self.L ** m for m in range(order + 1)])
        rows = quintic_derivs(np.ascontiguousarray(self.coef, np.float64), basis.piece, basis.powers,
                              _derivative_factors(order), Lm)
        return [r.reshape(basis.shape) for r in rows]


class _ReturnBasis:
    """What :meth:`ReturnCurve.derivs` computes of the angles alone (each point's piece and the powers of its local
    t), kept for many curves of one return phase at the same angles (:func:`_min_gamma_return`'s search)."""

    def __init__(self, phi, a: float, L: float):
        phi = np.asarray(phi, dtype=float)
        self.shape = phi.shape
        u = (phi.ravel() - a) / L
        self.piece = np.clip(np.floor(u), 0, 1).astype(np.int64)
        t = u - self.piece
        self.powers = np.ascontiguousarray(np.stack([t ** e for e in range(6)]))  # t ** (k - m), 0 <= k - m <= 5


@lru_cache(maxsize=None)
def _derivative_factors(order: int) -> np.ndarray:
    """fks[m, k] = k! / (k - m)!, the factor of t ** (k - m) in the m-th derivative of t ** k (m <= order, k <= 5).
    Shared: not to be written (left writable, as the compiled kernel it goes to was compiled for)."""
    fks = np.zeros((order + 1, 6))
    for m in range(order + 1):
        for k in range(m, 6):
            fks[m, k] = math.factorial(k) / math.factorial(k - m)
    return fks


@lru_cache(maxsize=2)
def _return_kkt(with_top: bool) -> np.ndarray:
    """The KKT matrix of :meth:`ReturnCurve.build` (the least jerk integral under the end, joint and top
    conditions).  The conditions' rows hold only the monomials' derivatives at t = 0 and 1, so the matrix is the
    same for every return phase; ``build`` solves it with the phase's right-hand side.  Read-only."""

    def pad(row, piece):
        full = np.zeros(12)
        full[6 * piece:6 * piece + 6] = row
        return full

    A = []
    for m in range(3):
        A.append(pad(_mono_row(0.0, m), 0))
        A.append(pad(_mono_row(1.0, m), 1))
    for m in range(3):  # C2 joint at φ = π
        A.append(pad(_mono_row(1.0, m), 0) - pad(_mono_row(0.0, m), 1))
    if with_top:
        A.append(pad(_mono_row(1.0, 0), 0))
    A = np.array(A)
    G = np.zeros((12, 12))
    G[:6, :6] = G[6:, 6:] = _quintic_gram()
    n = A.shape[0]
    kkt = np.zeros((12 + n, 12 + n))
    kkt[:12, :12] = 2.0 * G
    kkt[:12, 12:] = A.T
    kkt[12:, :12] = A
    kkt.setflags(write=False)
    return kkt


def _min_gamma_return(end_a: tuple, end_b: tuple, a: float, b: float) -> ReturnCurve:
    """Return closure with the smallest pressure angle (8-norm of γ over the return
    phase) over H_top: bounded scalar search between 0.5·min(H_ends) and the top of
    the minimum-jerk quintic."""
    from scipy.optimize import minimize_scalar

    phi = np.linspace(a, b, 721)
    basis = _ReturnBasis(phi, a, 0.5 * (b - a))  # with ReturnCurve.build's L

    def peak(h):
        H, H1 = ReturnCurve.build(end_a, end_b, a, b, h).derivs_on(basis, 1)
        if np.any(H <= 0.0):
            return math.pi
        return float(np.mean(np.arctan2(H1, H) ** 8) ** 0.125)

    lo = min(end_a[0], end_b[0])
    free = ReturnCurve.build(end_a, end_b, a, b, None)
    hi = max(float(free.derivs(np.array([math.pi]), 0)[0][0]), lo)
    res = minimize_scalar(peak, bounds=(0.5 * lo, hi + policy.RETURN_TOP_SLACK), method="bounded",
                          options={"xatol": policy.RETURN_TOP_XATOL})
    return ReturnCurve.build(end_a, end_b, a, b, float(res.x))
