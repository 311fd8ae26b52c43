"""The smoothed drive law of the non-circular pair: the walking law (seeds 000 and 002) with a
C2, closure-exact blend around every leg hand-over (docs/architecture.md, «pitch curves and
smoothing»; ``gears/noncircular.py`` module docstring).

With t = phi - phi_h around the hand-over phi_h = pi/4 + k pi/2 the law is replaced on
|t| < delta by an even degree-6 polynomial matching U, U', U'' at the window ends and keeping
the window integral of U (seed 000 eq. 9/11: n whole driver turns per driven turn).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from propulsor.errors import InputError, require_positive
from propulsor.laws.law import one_point_values
from propulsor.laws.walking import LEG_PERIOD, LEGS, WalkingLaw, invert_theta, wrap_leg, wrap_leg1
from propulsor.laws.walking_kernels import smoothed_many
from propulsor.policy import PHI_OF_THETA_TOL_RAD

__all__ = ["SmoothedWalkingLaw"]


def cubic_min_01(a0: float, a1: float, a2: float, a3: float) -> float:
    """The least value of a0 + a1 w + a2 w^2 + a3 w^3 over 0 <= w <= 1: at w = 0, w = 1 or a real root of the
    derivative a1 + 2 a2 w + 3 a3 w^2 between them."""
    ws = [0.0, 1.0] + [float(r.real) for r in np.roots([3.0 * a3, 2.0 * a2, a1])
                       if r.imag == 0.0 and 0.0 < r.real < 1.0]
    return min(a0 + w * (a1 + w * (a2 + w * a3)) for w in ws)


@dataclass(frozen=True)
class SmoothedWalkingLaw:
    """The walking law with a C2, closure-exact blend around every leg hand-over.

    law: the exact WalkingLaw; delta: half-width of the blend window (rad of
    the driven angle phi) around phi_h = pi/4 + k pi/2, 0 < delta <= pi/4.
    In the window, with t = phi - phi_h, U_s = c0 + c2 t^2 + c4 t^4 + c6 t^6,
    (stored as ``coef`` = (a0..a3) of p = sum a_k (t/delta)^(2k)),
    solved from U_s(delta) = U, U_s'(delta) = U', U_s''(delta) = U'' and
    integral_{-delta}^{delta} U_s = integral U (the exact law is even in t:
    U = u + K sin 2|t|, K = 3 b u / A), so the pair closes exactly.
    """

    law: WalkingLaw
    delta: float
    u_h: float | None = None
    coef: tuple = field(init=False, repr=False)
    eps: float = field(init=False, default=0.0)

    # ---- the law interface (``laws.law.Law``) ---------------------------------------
    kind = "walking"
    #: the array functions give each angle the value it gets alone (law.py: ``elementwise``)
    elementwise = True
    period = LEG_PERIOD
    period_start = -math.pi / 4
    periods = LEGS
    corner_phis = ()
    #: ``U_derivs1`` / ``theta1`` reproduce ``U`` ... / ``theta`` bit for bit: the solvers use them
    scalar_path = True

    @property
    def breakpoints(self) -> tuple:
        return self.leg_breakpoints

    def __post_init__(self):
        if not isinstance(self.law, WalkingLaw):
            raise InputError("law", self.law, "must be a WalkingLaw")
        d = require_positive("delta", self.delta, "rad")
        if d > math.pi / 4:
            raise InputError("delta", self.delta, f"blend half-width must be <= pi/4 = {math.pi / 4:.6f} rad")
        object.__setattr__(self, "delta", d)
        object.__setattr__(self, "_K", 3 * self.law.b * self.law.u / self.law.A)
        u, K = self.law.u, self.K
        # solved in s = t/delta (well conditioned for small delta): p = sum a_k s^(2k)
        M = np.array([
            [1.0, 1.0, 1.0, 1.0],
            [0.0, 2.0, 4.0, 6.0],
            [0.0, 2.0, 12.0, 30.0],
            [1.0, 1.0 / 3, 1.0 / 5, 1.0 / 7],
        ])
        rhs = np.array([
            u + K * math.sin(2 * d),
            d * 2 * K * math.cos(2 * d),
            -d * d * 4 * K * math.sin(2 * d),
            u + K * (1 - math.cos(2 * d)) / (2 * d),
        ])
        if self.u_h is None:
            object.__setattr__(self, "coef", tuple(float(v) for v in np.linalg.solve(M, rhs)))
        else:
            self._scaled_blend(M, rhs)
        # constants of the hot functions, cached by the expressions they use (not dataclass fields)
        object.__setattr__(self, "_1me", 1.0 - self.eps)
        object.__setattr__(self, "_u", self.law.u)
        object.__setattr__(self, "_Pd", float(self._P(d)))
        object.__setattr__(self, "_Fd", float(self._F(d)))
        object.__setattr__(self, "_I_leg", self.law.n * math.pi / 2)
        p_min = self._blend_min()
        if not p_min > 0:
            raise InputError("delta", self.delta, f"blend makes U <= 0 (min {p_min:.4g}); use a smaller delta")

    def _blend_min(self) -> float:
        """The least value of the blend over its window (exact, not sampled): p is a cubic in w = (t/delta)^2 on
        [0, 1]."""
        return cubic_min_01(*self.coef)

    def _scaled_blend(self, M, rhs) -> None:
        """The blend with a free hand-over value U_s(phi_h) = u_h (the depth of the hub-speed dip),
        C2 at the window ends, and closure restored by scaling U by (1 - eps) OUTSIDE the windows
        (the window's excess integral spread over the whole leg instead of a bump beside the dip):
        p = p_A - eps p_B, p_A / p_B matching U, U', U'' at the window end (resp. with u_h / 0 at
        the hand-over), eps = (W_A - E) / (I_leg - E + W_B), W = window integrals, E = that of the
        exact law, I_leg = n pi / 2 (seed 000 eq. 9/11: the driver angle of one leg)."""
        u_h = require_positive("u_h", self.u_h)
        d = self.delta
        M2 = M.copy()
        M2[3] = [1.0, 0.0, 0.0, 0.0]
        a_A = np.linalg.solve(M2, np.array([rhs[0], rhs[1], rhs[2], u_h]))
        a_B = np.linalg.solve(M2, np.array([rhs[0], rhs[1], rhs[2], 0.0]))
        w = np.array([1.0, 1.0 / 3, 1.0 / 5, 1.0 / 7]) * 2 * d
        W_A, W_B = float(w @ a_A), float(w @ a_B)
        E = 2 * d * rhs[3]
        I_leg = self.law.n * math.pi / 2
        eps = (W_A - E) / (I_leg - E + W_B)
        object.__setattr__(self, "eps", float(eps))
        object.__setattr__(self, "coef", tuple(float(v) for v in a_A - eps * a_B))

    # ---- forwarded constants ----------------------------------------------------
    @property
    def n(self) -> int:
        return self.law.n

    @property
    def A(self) -> float:
        return self.law.A

    @property
    def u(self) -> float:
        return self.law.u

    @property
    def K(self) -> float:
        """Slope scale of the exact law at hand-over: U = u + K sin 2|t|, K = 3 b u / A."""
        return self._K

    @property
    def hub_speed_ratio(self) -> float:
        """Time-mean v/omega = A/u (unchanged: the blend keeps the leg's driver angle)."""
        return self.law.hub_speed_ratio

    @property
    def leg_breakpoints(self) -> tuple:
        """Leg-local angles w where U_s is only C2 (window ends), with the leg ends."""
        d = self.delta
        pts = [-math.pi / 4, -math.pi / 4 + d, math.pi / 4 - d, math.pi / 4]
        return tuple(sorted(set(pts)))

    # ---- the blend polynomial -----------------------------------------------------
    def blend(self, t, order: int = 0):
        """Blend polynomial (order 0), or its 1st / 2nd / -1st (antiderivative, odd) derivative in t.

        p(t) = a0 + a1 s^2 + a2 s^4 + a3 s^6, s = t / delta.
        """
        a0, a1, a2, a3 = self.coef
        d = self.delta
        s = np.asarray(t, dtype=float) / d
        s2 = s * s
        if order == 0:
            return a0 + s2 * (a1 + s2 * (a2 + s2 * a3))
        if order == 1:
            return s * (2 * a1 + s2 * (4 * a2 + 6 * a3 * s2)) / d
        if order == 2:
            return (2 * a1 + s2 * (12 * a2 + 30 * a3 * s2)) / (d * d)
        if order == -1:
            return d * s * (a0 + s2 * (a1 / 3 + s2 * (a2 / 5 + s2 * a3 / 7)))
        raise InputError("order", order, "must be -1, 0, 1 or 2")

    def _p(self, t):
        return self.blend(t, 0)

    def _dp(self, t):
        return self.blend(t, 1)

    def _d2p(self, t):
        return self.blend(t, 2)

    def _P(self, t):
        return self.blend(t, -1)

    def _F(self, t):
        """Antiderivative of the exact law near hand-over, odd in t: u t + sgn t K (1 - cos 2t)/2."""
        return self.u * t + np.sign(t) * self.K * (1 - np.cos(2 * t)) / 2

    def _window(self, phi):
        phi = np.asarray(phi, dtype=float)
        t = wrap_leg(phi - math.pi / 4)
        return phi, t, np.abs(t) < self.delta

    # ---- law interface ------------------------------------------------------------
    def U(self, phi):
        """Smoothed ratio U_s(phi) (periodic, period pi/2, C2): in a window the blend ``_p(t)``, elsewhere the
        exact law's U (times 1 - eps with a free hand-over value)."""
        few = one_point_values(self, phi, 0)
        if few is not None:
            return few
        return self._many(phi, 0)

    def dU_dphi(self, phi):
        """dU_s/dphi: in a window ``_dp(t)``, elsewhere the exact law's (times 1 - eps with a free hand-over value)."""
        few = one_point_values(self, phi, 1)
        if few is not None:
            return few
        return self._many(phi, 1)

    def _many(self, phi, what: int):
        """``U`` (what 0) or ``dU_dphi`` (1) of an array of angles, shaped as phi: compiled, each angle by the
        operations numpy does on it (:func:`propulsor.laws.walking_kernels.smoothed_many`)."""
        law = self.law
        a0, a1, a2, a3 = self.coef
        phi = np.asarray(phi, dtype=float)
        return smoothed_many(np.ascontiguousarray(phi.ravel()), what, float(self.delta), a0, a1, a2, a3,
                             self.u_h is not None, self._1me, law._u, law._A, law._3b, law._m6bu).reshape(phi.shape)

    def d2U_dphi2(self, phi):
        few = one_point_values(self, phi, 2)
        if few is not None:
            return few
        phi, t, inw = self._window(phi)
        if self.u_h is not None:
            return np.where(inw, self._d2p(t), self._1me * self.law.d2U_dphi2(phi))
        return np.where(inw, self._d2p(t), self.law.d2U_dphi2(phi))

    def theta(self, phi):
        """theta_s(phi) = integral_0^phi U_s, closed form: exact theta + window correction.

        With a free hand-over value (u_h): (1 - eps) theta + eps I_leg per completed window + the
        partial window integral of p - (1 - eps) U (window h at pi/4 + h pi/2, t = phi - pi/4 - h pi/2)."""
        few = one_point_values(self, phi, -1)
        if few is not None:
            return few
        phi, t, inw = self._window(phi)
        d = self.delta
        if self.u_h is not None:
            e = self.eps
            h = np.round((phi - math.pi / 4 - t) / LEG_PERIOD)
            done = h + np.where(t >= d, 1.0, 0.0)
            part = self._P(t) + self._Pd - self._1me * (self._F(t) + self._Fd)
            return self._1me * self.law.theta(phi) + e * self._I_leg * done + np.where(inw, part, 0.0)
        corr = self._P(t) + self._Pd - self._F(t) - self._Fd
        return self.law.theta(phi) + np.where(inw, corr, 0.0)

    # ---- the same functions of one finite float phi (``math``, bit-identical to the above) ----
    def U_derivs1(self, phi: float) -> tuple[float, float, float]:
        """(``U``, ``dU_dphi``, ``d2U_dphi2``) at one driven angle (float)."""
        t = wrap_leg1(phi - math.pi / 4)
        if abs(t) < self.delta:
            a0, a1, a2, a3 = self.coef
            d = self.delta
            s = t / d
            s2 = s * s
            return (a0 + s2 * (a1 + s2 * (a2 + s2 * a3)), s * (2 * a1 + s2 * (4 * a2 + 6 * a3 * s2)) / d,
                    (2 * a1 + s2 * (12 * a2 + 30 * a3 * s2)) / (d * d))
        U, dU, d2U = self.law.U_derivs1(phi)
        if self.u_h is not None:
            e = self._1me
            return e * U, e * dU, e * d2U
        return U, dU, d2U

    def _PF1(self, t: float) -> float:
        """_P(t) + _P(delta) and _F(t) + _F(delta)-terms of ``theta`` for one float t, as there."""
        a0, a1, a2, a3 = self.coef
        d = self.delta
        s = t / d
        s2 = s * s
        P = d * s * (a0 + s2 * (a1 / 3 + s2 * (a2 / 5 + s2 * a3 / 7)))
        sg = 1.0 if t > 0 else (-1.0 if t < 0 else 0.0)
        F = self._u * t + sg * self._K * (1 - math.cos(2 * t)) / 2
        return P, F

    def theta1(self, phi: float) -> float:
        """``theta`` at one driven angle (float)."""
        t = wrap_leg1(phi - math.pi / 4)
        d = self.delta
        inw = abs(t) < d
        if self.u_h is not None:
            h = float(round((phi - math.pi / 4 - t) / LEG_PERIOD))
            done = h + (1.0 if t >= d else 0.0)
            P, F = self._PF1(t)
            part = P + self._Pd - self._1me * (F + self._Fd)
            return self._1me * self.law.theta1(phi) + self.eps * self._I_leg * done + (part if inw else 0.0)
        P, F = self._PF1(t)
        return self.law.theta1(phi) + ((P + self._Pd - F - self._Fd) if inw else 0.0)

    def phi_of_theta(self, theta, tol: float = PHI_OF_THETA_TOL_RAD):
        """Inverse of theta_s(phi) (``walking.invert_theta``)."""
        theta = np.asarray(theta, dtype=float)
        return invert_theta(self, theta, theta / self.n, tol, 80)

    def dX01_dphi(self, phi):
        """Hub speed analogue of the mechanism (seed 000 eq. 2) - unchanged by the gear."""
        return self.law.dX01_dphi(phi)

    def hub_speed(self, phi):
        """v / omega = (dX01/dphi) / U_s (mm per rad of the driver)."""
        return self.dX01_dphi(phi) / self.U(phi)

    @property
    def windows(self) -> list[tuple[float, float]]:
        """The blend windows over one driven turn [0, 2 pi): (start, end) in rad."""
        out = []
        for k in range(4):
            h = math.pi / 4 + k * LEG_PERIOD
            out.append((h - self.delta, h + self.delta))
        return out
