"""Efficiency (seed 003 eq. 12–14) and torsional dynamics (eq. 9–11) of a drive with a composite gear.

Pure math (numpy/scipy).  SI units inside the dynamics (kg·m², N·m, rad, s); mm only where named.

Friction loss (eq. 12–14)
-------------------------
For involute flanks the sliding speed at a contact at distance l from the pole is
v_s = (ω1 + ω2)·l (external mesh: the relative motion is a rotation about the pole), and the power
carried is F_n·ω1·h1 (h1: distance of the wheel's axis from the line of action; r_b1 for a solid
gear).  The instantaneous loss coefficient is therefore ψ = f·l·(ω1 + ω2)/(ω1·h1); for a solid
pair, with ω2/ω1 = r_b1/r_b2, ψ = f·l·(1/r_b1 + 1/r_b2) = f·l·2/(m cos α)·(1/z1 + 1/z2).  The
contact runs uniformly along the active line from −l1 to +l2 (g_α = l1 + l2), so the mean of |l| is
(l1² + l2²)/(2 g_α) and
    (ψ)_ср = (f/(m cos α_w))·(1/z1 + 1/z2)·(l1² + l2²)/g_α                        (eq. 12).
With l1 = l2 = g_α/2 and ε_α = g_α/(π m cos α) this is (f ε_α π/2)(1/z1 + 1/z2)   (eq. 13, C = 1).
Eq. 13 for the composite gear multiplies by C_внеш = C2/C1·C3; we read it as C2·C3/C1, each factor
where its quantity sits in eq. 12: C1 = cos α_w,eff / cos α with 1/cos α_w,eff the mean of
1/cos α_wt (the angle in the denominator; C1 < 1 when α_wt grows), C2 = mean |l| measured /
mean |l| of the solid pair (distance from the pole, > 1), C3 = the rest of the measured ratio
(the length of the active line and the share of the turn in contact), so that
C2·C3/C1 = (ψ)_ср measured / (ψ)_ср of eq. 13 with C = 1.  Internal mesh (eq. 14): 1/z1 − 1/z2.

Dynamics (eq. 9–11)
-------------------
Generalised coordinates of eq. 9: q1 = φ1, q2 = φ3 − φ2, q3 = φ4 − φ3, with φ2 = Π(q1) the
composite pair's transmission (eq. 9 writes Π(φ1) = φ1 i21; here Π is the *measured* gear angle,
so the ratio error drives the system) and φ5 = i54 φ4.  Kinetic energy
T = ½[J1 q̇1² + J2 φ̇2² + J3 φ̇3² + (J4 + J5 i54²) φ̇4²], potential V = ½(c1 q2² + c2 q3²),
Rayleigh dissipation ½(b1 q̇2² + b2 q̇3²) (the forces R1, R2 of eq. 10), the resisting torque M4
on wheel 4.  Lagrange's equations for q2, q3 with q1 = ω0 t given (eq. 10):
    J3 φ̈3 + J45 φ̈4 + b1 q̇2 + c1 q2 = −M4,
    J45 φ̈4 + b2 q̇3 + c2 q3 = −M4,          J45 = J4 + J5 i54²,
    φ̈3 = Π'' ω0² + q̈2,  φ̈4 = φ̈3 + q̈3,
and for q1 the driving torque (eq. 11):
    M1 = J2 Π' Π'' ω0² + Π' (J3 φ̈3 + J45 φ̈4 + M4).
(The printed eq. 10–11 carry J4 without i21 in the q̈1 terms and M4·i34, M4·i23 on the right: with
Π = i21 q1 linear our equations are theirs with every q̈1 coefficient multiplied by i21 as eq. 9
requires.)  At constant Π' the steady state is q2 = −M4/c1, q3 = −M4/c2, M1 = Π' M4.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["loss_eq12", "loss_eq13", "loss_instant", "TorsionalModel", "DynamicsResult"]


def loss_eq12(f: float, m: float, alpha_w: float, z1: float, z2: float, l1: float, l2: float,
              internal: bool = False) -> float:
    """Eq. 12: (ψ)_ср = f/(m cos α_w)·(1/z1 ± 1/z2)·(l1² + l2²)/g_α, g_α = l1 + l2."""
    s = (1.0 / z1 - 1.0 / z2) if internal else (1.0 / z1 + 1.0 / z2)
    return f / (m * math.cos(alpha_w)) * s * (l1 * l1 + l2 * l2) / (l1 + l2)


def loss_eq13(f: float, eps_alpha: float, z1: float, z2: float, C: float = 1.0, internal: bool = False) -> float:
    """Eq. 13 (eq. 14 internal): (ψ)_ср = f ε_α π/2 (1/z1 ± 1/z2)·C."""
    s = (1.0 / z1 - 1.0 / z2) if internal else (1.0 / z1 + 1.0 / z2)
    return f * eps_alpha * math.pi / 2.0 * s * C


def loss_instant(f: float, l, i_t, h1) -> np.ndarray:
    """Instantaneous loss ψ = f·|l|·(ω1 + ω2)/(ω1 h1) = f |l| (1 + 1/i_t)/h1 (i_t = ω1/ω2)."""
    return f * np.abs(l) * (1.0 + 1.0 / np.asarray(i_t, float)) / np.asarray(h1, float)


@dataclass
class DynamicsResult:
    t: np.ndarray
    q1: np.ndarray
    q2: np.ndarray
    q3: np.ndarray
    M1: np.ndarray
    M1_static: float

    @property
    def torque_factor(self) -> float:
        """Peak dynamic torque factor max|M1| / M1_static."""
        return float(np.max(np.abs(self.M1)) / self.M1_static) if self.M1_static > 0 else math.nan


@dataclass(frozen=True)
class TorsionalModel:
    """Eq. 9–11 with inertias J1…J5 (kg·m²), stiffnesses c1, c2 (N·m/rad), damping ratio ζ of each
    link (b = 2ζ√(c·J_eff)), stage ratio i54, load torque M4 (N·m)."""

    J1: float
    J2: float
    J3: float
    J4: float
    J5: float
    c1: float
    c2: float
    i54: float = 1.0
    zeta: float = 0.05
    M4: float = 0.0

    @property
    def J45(self) -> float:
        return self.J4 + self.J5 * self.i54 ** 2

    def mass_stiffness(self) -> tuple[np.ndarray, np.ndarray]:
        """Mass and stiffness matrices of (q2, q3) at q̈1 = 0: M = [[J3 + J45, J45], [J45, J45]]."""
        J3, J45 = self.J3, self.J45
        return np.array([[J3 + J45, J45], [J45, J45]]), np.diag([self.c1, self.c2])

    def natural_frequencies(self) -> np.ndarray:
        """Undamped natural frequencies of (q2, q3), rad/s (generalised eigenproblem K v = ω² M v)."""
        from scipy.linalg import eigh

        M, K = self.mass_stiffness()
        return np.sqrt(np.sort(eigh(K, M, eigvals_only=True)))

    def damping(self) -> tuple[float, float]:
        """(b1, b2): each link damped at ratio ζ against the inertia it carries."""
        b1 = 2.0 * self.zeta * math.sqrt(self.c1 * (self.J3 * self.J45 / (self.J3 + self.J45) + self.J45))
        b2 = 2.0 * self.zeta * math.sqrt(self.c2 * self.J45)
        return b1, b2

    def state_matrices(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(A, g, h) of eq. 10 as the first-order system y' = A y + g·acc + h, y = (q2, q3, q̇2, q̇3), acc = Π'' ω0²
        (the drive's angular acceleration of gear 2)."""
        J3, J45, c1, c2, M4 = self.J3, self.J45, self.c1, self.c2, self.M4
        b1, b2 = self.damping()
        Minv = np.linalg.inv(np.array([[J3 + J45, J45], [J45, J45]]))
        A = np.zeros((4, 4))
        A[0, 2] = A[1, 3] = 1.0
        A[2:, :] = Minv @ np.array([[-c1, 0.0, -b1, 0.0], [0.0, -c2, 0.0, -b2]])
        g = np.concatenate([[0.0, 0.0], Minv @ np.array([-(J3 + J45), -J45])])
        h = np.concatenate([[0.0, 0.0], Minv @ np.array([-M4, -M4])])
        return A, g, h

    def simulate(self, omega0: float, Pi1, Pi2, t_end: float, n_out: int = 2000, q0=None,
                 breaks=None) -> DynamicsResult:
        """Eq. 10 with q1 = ω0 t from 0 to t_end, sampled at n_out equal steps; Pi1(q1), Pi2(q1): Π' and Π''
        of the transmission (vectorised callables).  Starts from the static deflection at the mean Π'
        (or from q0 = (q2, q3, q̇2, q̇3)).

        breaks: the angles q1 at which Π'' may change its slope, Π'' being linear in between (the second
        derivative of a cubic spline: its knots).  Given, the linear system is solved exactly: on every
        step between two breaks or output times the forcing is a ramp, and the state with the ramp and the
        constant load appended advances by the matrix exponential of that 7 × 7 system.  Without breaks
        scipy's Radau (rtol 1e-8, the constant Jacobian A) integrates it."""
        A, g, h = self.state_matrices()
        J3, J45, M4 = self.J3, self.J45, self.M4
        y0 = np.array([-M4 / self.c1, -M4 / self.c2, 0.0, 0.0] if q0 is None else q0, float)
        t = np.linspace(0.0, t_end, n_out)
        w2 = omega0 * omega0
        if breaks is not None:
            Y = _ramp_forced(A, g, h, y0, t, np.asarray(breaks, float) / omega0, lambda tt: np.asarray(Pi2(omega0 * tt), float) * w2)
        else:
            from scipy.integrate import solve_ivp

            def rhs(tt, y):
                return A @ y + g * (float(Pi2(omega0 * tt)) * w2) + h

            sol = solve_ivp(rhs, (0.0, t_end), y0, method="Radau", t_eval=t, rtol=1e-8, atol=1e-12,
                            max_step=t_end / n_out * 4, jac=lambda tt, y: A)
            Y = sol.y.T
        q2, q3 = Y[:, 0], Y[:, 1]
        q1 = omega0 * t
        P1, P2 = np.asarray(Pi1(q1), float), np.asarray(Pi2(q1), float)
        acc = P2 * w2
        a = Y @ A[2:].T + np.outer(acc, g[2:]) + h[2:]  # (q̈2, q̈3)
        ph3 = acc + a[:, 0]
        ph4 = ph3 + a[:, 1]
        M1 = self.J2 * P1 * acc + P1 * (J3 * ph3 + J45 * ph4 + M4)
        return DynamicsResult(t, q1, q2, q3, M1, float(np.mean(P1)) * M4)


def _ramp_forced(A: np.ndarray, g: np.ndarray, h: np.ndarray, y0: np.ndarray, t_out: np.ndarray,
                 t_breaks: np.ndarray, forcing) -> np.ndarray:
    """Exact solution of y' = A y + g f(t) + h at t_out (ascending, t_out[0] the start) for a forcing f that is
    linear between the times t_breaks: over a step of length H with f = f0 + r τ the augmented state
    z = (y, f, r, 1) obeys z' = M z (f' = r, r' = 0), so z(t + H) = exp(M H) z(t) (scipy.linalg.expm, the
    steps' exponentials in one stacked call)."""
    from scipy.linalg import expm

    n = len(y0)
    t0, t1 = float(t_out[0]), float(t_out[-1])
    inner = t_breaks[(t_breaks > t0) & (t_breaks < t1)]
    T = np.unique(np.concatenate([t_out, inner]))
    H = np.diff(T)
    F = forcing(T)
    M = np.zeros((n + 3, n + 3))
    M[:n, :n] = A
    M[:n, n] = g
    M[:n, n + 2] = h
    M[n, n + 1] = 1.0
    E = expm(H[:, None, None] * M[None])
    slope = np.diff(F) / H
    out_idx = np.searchsorted(T, t_out)
    Y = np.empty((len(T), n))
    Y[0] = y0
    z = np.empty(n + 3)
    for k in range(len(H)):
        z[:n], z[n], z[n + 1], z[n + 2] = Y[k], F[k], slope[k], 1.0
        Y[k + 1] = E[k, :n] @ z
    return Y[out_idx]
