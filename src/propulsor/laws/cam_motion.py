"""Fixed cam of the driven wheel-walking propulsor: the roller-centre path H(φ) (seed 001).

Mechanism (seed 001, fig. 3): a cam is fixed on the axle O2, a carrier turns
around it, ``n_legs`` legs slide radially in the carrier, each with a roller of radius
``r`` rolling on the cam (closed track: springs plus a guide channel).  φ is the carrier
angle of a leg counted from the downward vertical; a leg supports the vehicle for
φ ∈ [−π/n, π/n] (n = 4: ±π/4).  All legs ride the same cam, a turn/n apart, so H(φ)
over the whole turn is ONE closed, 2π-periodic curve that every roller centre follows.

Cam frame: X = H·sin φ, Y = H·cos φ (Y points down at φ = 0), as in seed 001 eq. 9.

Support phase — H is designed from a prescribed curvature K(φ) of the roller-centre
path (seed 001, eq. 20):

    dρ/dφ = ρ·tan γ,   dγ/dφ = 1 − ρ·K/cos γ,   ρ = H,   ρ(0) = H0 = R0 + r,   γ(0) = 0

with the laws of seed 001 (after eq. 26): K = k0·φ, K = k0·φ², K = k0·e^(k1·φ), plus
K = 0 (straight roller path, closed form H = H0/cos φ).  The seed writes the laws for
φ ≥ 0 and says nothing of φ < 0; literally K = k0·φ is negative (path bending away
from the cam) on the leading half of the support phase, which makes the hub speed of
eq. 8 jump at leg hand-over.  Ours, by default (``symmetric=True``): the law is used
as K(|φ|), the even extension, so the cam path and the shoes are symmetric and the
propulsor runs the same both ways; ``symmetric=False`` gives the literal law.

Return phase — φ ∈ [π/n, 2π − π/n] (ours; the seed leaves it open): a C2 closure by
two quintic pieces joined at φ = π that minimise the jerk ∫(H''')² dφ and match H, H',
H'' of the support phase at both ends; H(π) chosen for the smallest pressure angle
(default), free (minimum jerk) or given (:class:`ReturnPhase`).

Accuracy: DOP853 at policy.ODE_RTOL/ODE_ATOL; the error of H is measured against a
second integration at policy.CAM_ODE_REF_TOL (SupportPath.H_error_mm, ~1e-9 mm for
our defaults; the limit policy.CAM_H_ERROR_MAX_MM = 1e-6 mm is tested).

Per φ: pressure angle γ = atan(H'/H) (eq. 17), cam working profile (eq. 9–10), outer
channel wall, radius of curvature of the profile R = H/((1 − γ')·cos γ) − r (eq. 16),
Hertz stress σ = 0.418·√(P·E/(b·cos γ)·(1/r + 1/R)) (eq. 14) with E = 2E1E2/(E1 + E2)
(eq. 15), curvature of the roller-centre path (eq. 18), and the horizontal speed analogue
of the hub dX02/dφ = H'·sin φ + R0 + r + C (eq. 8).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from propulsor import policy
from propulsor.errors import InputError, require, require_finite, require_positive
from propulsor.laws.cam_return import ReturnCurve, _min_gamma_return

LAW_KINDS = ("zero", "linear", "quadratic", "exponential")
TWO_PI = 2.0 * math.pi


# --------------------------------------------------------------------------- inputs


@dataclass(frozen=True)
class CamMechanism:
    """Parameters of the driven propulsor (seed 001, eq. 6, 14–15).  Defaults are ours:
    hub height R0 + r + C = 320 mm as the driving propulsor; b, P, E ours.

    R0: radius of the cam's initial circle, mm; r: roller radius, mm; C: shoe stand
    length, mm; n_legs: number of legs (4 in the seed); b: contact line length of the
    roller (roller width), mm; P: force along the leg in the support phase, N (eq. 14
    P_Σ; ours: 5 kN per wheel incl. dynamic factor); P_return: spring force along the
    leg in the return phase, N; E1, E2: Young's moduli of cam and roller, MPa (steel);
    channel_clearance: clearance of the roller in the guide channel, mm.
    """

    R0: float = 90.0
    r: float = 20.0
    C: float = 210.0
    n_legs: int = 4
    b: float = 20.0
    P: float = 5000.0
    P_return: float = 500.0
    E1: float = 2.1e5
    E2: float = 2.1e5
    channel_clearance: float = 0.2

    def __post_init__(self):
        for name in ("R0", "r", "C", "b", "P", "E1", "E2"):
            require_positive(name, getattr(self, name))
        require(float(require_finite("P_return", self.P_return)) >= 0.0,
                "P_return", self.P_return, "must be >= 0 N")
        require(float(require_finite("channel_clearance", self.channel_clearance)) >= 0.0,
                "channel_clearance", self.channel_clearance, "must be >= 0 mm")
        require(isinstance(self.n_legs, (int, np.integer)) and 3 <= int(self.n_legs) <= 12,
                "n_legs", self.n_legs, "must be an integer in [3, 12] (seed 001: 4)")

    @property
    def H0(self) -> float:
        """Initial cam-axis → roller-axis distance H0 = R0 + r (seed 001, eq. 6)."""
        return self.R0 + self.r

    @property
    def hub_height(self) -> float:
        """Constant height of the hub over flat ground Y02 = R0 + r + C (seed 001, eq. 6)."""
        return self.R0 + self.r + self.C

    @property
    def E(self) -> float:
        """Reduced Young's modulus E = 2·E1·E2/(E1 + E2), MPa (seed 001, eq. 15)."""
        return 2.0 * self.E1 * self.E2 / (self.E1 + self.E2)

    @property
    def phi_s(self) -> float:
        """Half-angle of the support phase π/n_legs (π/4 for four legs)."""
        return math.pi / int(self.n_legs)


@dataclass(frozen=True)
class CurvatureLaw:
    """Curvature K(φ) of the roller-centre path in the support phase, 1/mm (seed 001,
    laws 1–3 after eq. 26; 'zero' = straight path).  k0 in 1/mm (per rad^n), k1 in 1/rad.

    symmetric=True (ours, default): K is evaluated at |φ| (even extension).
    """

    kind: str = "quadratic"
    k0: float = 0.0
    k1: float = 0.0
    symmetric: bool = True

    def __post_init__(self):
        require(self.kind in LAW_KINDS, "CurvatureLaw.kind", self.kind, f"must be one of {LAW_KINDS}")
        require_finite("CurvatureLaw.k0", self.k0)
        require_finite("CurvatureLaw.k1", self.k1)
        if self.kind == "zero":
            require(self.k0 == 0.0, "CurvatureLaw.k0", self.k0, "must be 0 for kind 'zero'")
        if self.kind != "exponential":
            require(self.k1 == 0.0, "CurvatureLaw.k1", self.k1, "only the 'exponential' law uses k1")
        require(abs(self.k1) <= 50.0, "CurvatureLaw.k1", self.k1, "must satisfy |k1| <= 50 1/rad")

    @property
    def is_even(self) -> bool:
        """K(−φ) = K(φ): then H is even and γ odd (one integration suffices)."""
        return self.symmetric or self.kind in ("zero", "quadratic")

    def _x(self, phi):
        phi = np.asarray(phi, dtype=float)
        return (np.abs(phi) if self.symmetric else phi), (np.where(phi < 0.0, -1.0, 1.0) if self.symmetric else 1.0)

    def K(self, phi):
        """K(φ), 1/mm."""
        x, _ = self._x(phi)
        if self.kind == "zero":
            return np.zeros_like(x)
        if self.kind == "linear":
            return self.k0 * x
        if self.kind == "quadratic":
            return self.k0 * x * x
        return self.k0 * np.exp(self.k1 * x)

    def dK(self, phi):
        """dK/dφ, 1/(mm·rad); for the even extension the right-hand value at φ = 0."""
        x, sgn = self._x(phi)
        if self.kind == "zero":
            d = np.zeros_like(x)
        elif self.kind == "linear":
            d = self.k0 * np.ones_like(x)
        elif self.kind == "quadratic":
            d = 2.0 * self.k0 * x
        else:
            d = self.k0 * self.k1 * np.exp(self.k1 * x)
        return sgn * d

    def label(self) -> str:
        if self.kind == "zero":
            return "K = 0"
        if self.kind == "linear":
            return f"K = {self.k0:.6g}·|φ|" if self.symmetric else f"K = {self.k0:.6g}·φ"
        if self.kind == "quadratic":
            return f"K = {self.k0:.6g}·φ²"
        return (f"K = {self.k0:.6g}·exp({self.k1:.6g}·|φ|)" if self.symmetric
                else f"K = {self.k0:.6g}·exp({self.k1:.6g}·φ)")


RETURN_MODES = ("min_gamma", "min_jerk", "top")


@dataclass(frozen=True)
class ReturnPhase:
    """Closure of the turn outside the support phase (ours).  Always two quintics joined
    at φ = π, C2 everywhere, minimising the jerk ∫(H''')² dφ for the given H(π):

    mode 'min_jerk': H(π) free — one quintic, the smoothest closure; can lift the leg a lot.
    mode 'top': H(π) = H_top (mm), the return lift set by hand.
    mode 'min_gamma' (default): H(π) chosen to minimise the pressure angle over the
        return phase (8-norm of γ, a smooth maximum); this keeps the lift modest too,
        since a low top makes a steep fall and a high top a steep rise.
    """

    mode: str = "min_gamma"
    H_top: float | None = None

    def __post_init__(self):
        require(self.mode in RETURN_MODES, "ReturnPhase.mode", self.mode, f"must be one of {RETURN_MODES}")
        if self.mode == "top":
            require(self.H_top is not None, "ReturnPhase.H_top", self.H_top, "required by mode 'top'")
            require_positive("ReturnPhase.H_top", self.H_top, "mm")
        else:
            require(self.H_top is None, "ReturnPhase.H_top", self.H_top, "only mode 'top' takes H_top")


# ------------------------------------------------------------------- support phase

_GL_X, _GL_W = np.polynomial.legendre.leggauss(policy.CAM_QUAD_NODES)
_GL_X = 0.5 * (_GL_X + 1.0)  # nodes on [0, 1]
_GL_W = 0.5 * _GL_W


class SupportPath:
    """Solution of seed 001 eq. 20 over the support phase, with dense output.

    Use :func:`solve_support`.  ``H_error_mm`` is the measured integration error
    (max |H − H_ref| against a much tighter integration), or None if not estimated.
    """

    def __init__(self, mech: CamMechanism, law: CurvatureLaw, sol_pos, sol_neg, rtol: float, atol: float):
        self.mech = mech
        self.law = law
        self._pos = sol_pos
        self._neg = sol_neg  # None: mirror of the positive side (even law)
        self.rtol = rtol
        self.atol = atol
        self.H_error_mm: float | None = None

    def state(self, phi):
        """(H, γ) at φ ∈ [−φs, φs] from the dense output."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        s = self.mech.phi_s
        if np.any(np.abs(phi) > s * (1 + policy.REL_ROUNDING_TOL)):
            raise InputError("phi", float(np.max(np.abs(phi))), f"support phase is |φ| <= {s:.6g} rad")
        H = np.empty_like(phi)
        g = np.empty_like(phi)
        pos = phi >= 0.0
        if np.any(pos):
            y = self._dense(0)(np.minimum(phi[pos], s))
            H[pos], g[pos] = y[0], y[1]
        neg = ~pos
        if np.any(neg):
            if self._neg is None:
                y = self._dense(0)(np.minimum(-phi[neg], s))
                H[neg], g[neg] = y[0], -y[1]
            else:
                y = self._dense(1)(np.maximum(phi[neg], -s))
                H[neg], g[neg] = y[0], y[1]
        return H, g

    def _dense(self, side: int):
        """The dense output of the positive (0) or negative (1) integration, compiled
        (:class:`.cam_kernels.DenseSolution`: scipy's values to the last bit); made on first use."""
        made = self.__dict__.setdefault("_dense_made", [None, None])
        if made[side] is None:
            from .cam_kernels import DenseSolution

            made[side] = DenseSolution((self._pos, self._neg)[side].sol)
        return made[side]

    def derivs(self, phi) -> dict:
        """H, H', H'', γ, γ', K, g = H·K/cos γ and g' at φ (eq. 20: H' = H·tan γ,
        γ' = 1 − g, H'' = H'·tan γ + H·γ'/cos²γ)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        H, gam = self.state(phi)
        K = self.law.K(phi)
        dK = self.law.dK(phi)
        t = np.tan(gam)
        c = np.cos(gam)
        H1 = H * t
        g = H * K / c
        gam1 = 1.0 - g
        H2 = H1 * t + H * gam1 / (c * c)
        dg = (H1 * K + H * dK) / c + g * t * gam1
        return dict(phi=phi, H=H, H1=H1, H2=H2, gamma=gam, dgamma=gam1, K=K, g=g, dg=dg)

    def delta_over_phi(self, phi):
        """q = (γ − φ)/φ = −(1/φ)·∫0^φ g dφ and dq/dφ, by Gauss–Legendre quadrature of the
        dense solution (no cancellation at φ → 0; used for the shoe, seed 001 eq. 7)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        nodes = np.outer(phi, _GL_X)
        d = self.derivs(nodes.ravel())
        g = d["g"].reshape(nodes.shape)
        dg = d["dg"].reshape(nodes.shape)
        q = -(g @ _GL_W)
        dq = -(dg @ (_GL_W * _GL_X))
        return q, dq


def _rhs_factory(law: CurvatureLaw):
    kind, k0, k1, sym = law.kind, law.k0, law.k1, law.symmetric

    def K(phi):
        x = abs(phi) if sym else phi
        if kind == "zero":
            return 0.0
        if kind == "linear":
            return k0 * x
        if kind == "quadratic":
            return k0 * x * x
        return k0 * math.exp(k1 * x)

    def rhs(phi, y):
        rho, gam = y
        c = math.cos(gam)
        return [rho * math.tan(gam), 1.0 - rho * K(phi) / c]

    return rhs


def _integrate(mech: CamMechanism, law: CurvatureLaw, end: float, rtol: float, atol: float):
    H0 = mech.H0
    cmin = policy.CAM_COS_GAMMA_MIN

    def ev_cos(phi, y):
        return math.cos(y[1]) - cmin

    def ev_big(phi, y):
        return policy.CAM_RHO_MAX_FACTOR * H0 - y[0]

    def ev_small(phi, y):
        return y[0] - policy.CAM_RHO_MIN_FACTOR * H0

    events = [ev_cos, ev_big, ev_small]
    for e in events:
        e.terminal = True
    from scipy.integrate import solve_ivp  # here: the parameter classes import this module (quick `params`)

    sol = solve_ivp(_rhs_factory(law), (0.0, end), [H0, 0.0], method="DOP853", rtol=rtol, atol=atol,
                    dense_output=True, events=events)
    if sol.status != 0:
        if sol.status == 1:
            which = [i for i, te in enumerate(sol.t_events) if len(te)][0]
            phi_b = float(sol.t_events[which][0])
            what = ("cos γ → 0 (path tangent turns radial)", "ρ → ∞", "ρ → 0")[which]
        else:
            phi_b, what = float(sol.t[-1]), f"integrator failed: {sol.message}"
        name, value = ("CurvatureLaw.k0", law.k0) if law.kind != "exponential" else (
            "CurvatureLaw(k0, k1)", (law.k0, law.k1))
        raise InputError(name, value,
                         f"roller path of eq. 20 must stay regular (cos γ > {cmin:g}, 0 < ρ < ∞) over the "
                         f"support phase |φ| <= {math.degrees(mech.phi_s):.4g}°; it blows up ({what}) at "
                         f"φ = {math.degrees(phi_b):.4g}°", hint=law.label())
    return sol


def solve_support(mech: CamMechanism, law: CurvatureLaw, rtol: float = policy.ODE_RTOL,
                  atol: float = policy.ODE_ATOL, estimate_error: bool = True) -> SupportPath:
    """Integrate seed 001 eq. 20 from φ = 0 to ±φs (DOP853, dense output).

    Raises InputError naming the law coefficient if the path blows up inside the
    support phase.  With estimate_error, the result carries H_error_mm: max |H − H_ref|
    on a fine grid against an integration at rtol = atol = policy.CAM_ODE_REF_TOL.
    """
    s = mech.phi_s
    pos = _integrate(mech, law, s, rtol, atol)
    neg = None if law.is_even else _integrate(mech, law, -s, rtol, atol)
    path = SupportPath(mech, law, pos, neg, rtol, atol)
    if estimate_error:
        tol = policy.CAM_ODE_REF_TOL
        ref = SupportPath(mech, law, _integrate(mech, law, s, tol, tol),
                          None if law.is_even else _integrate(mech, law, -s, tol, tol), tol, tol)
        phi = np.linspace(-s, s, 2001)
        path.H_error_mm = float(np.max(np.abs(path.state(phi)[0] - ref.state(phi)[0])))
    return path


# ----------------------------------------------------------------------- full turn


@dataclass
class CamTable:
    """Per-φ quantities of the cam over any set of carrier angles (arrays)."""

    phi: np.ndarray
    support: np.ndarray  # bool: in the support phase of this leg
    H: np.ndarray
    H1: np.ndarray
    H2: np.ndarray
    gamma: np.ndarray  # pressure angle, eq. 17
    dgamma: np.ndarray
    K_path: np.ndarray  # curvature of the roller-centre path, eq. 18 (signed, + toward the cam axis)
    psi: np.ndarray  # eq. 10
    X: np.ndarray  # working profile, eq. 9
    Y: np.ndarray
    X_outer: np.ndarray  # outer channel wall (offset r + clearance on the far side)
    Y_outer: np.ndarray
    R_profile: np.ndarray  # eq. 16 (signed: > 0 convex, < 0 concave; ±inf straight)
    R_outer: np.ndarray  # outer wall radius seen from the roller (> 0 convex toward the roller)
    sigma_H: np.ndarray  # Hertz stress on the working profile, eq. 14, MPa (nan if undercut)
    hub_speed: np.ndarray  # dX02/dφ of the leg in support at this carrier angle, eq. 8, mm/rad

    @property
    def R_path(self) -> np.ndarray:
        """Radius of curvature of the roller-centre path 1/K = H/((1 − γ')·cos γ), mm
        (seed 001, eq. 19 with r = 0; ±inf where straight)."""
        with np.errstate(divide="ignore"):
            return np.where(self.K_path != 0.0, 1.0 / self.K_path, np.inf)


class CamMotion:
    """Closed roller-centre path H(φ) over the whole turn: support (eq. 20) + return."""

    def __init__(self, mech: CamMechanism, law: CurvatureLaw, support: SupportPath,
                 ret: ReturnCurve, return_phase: ReturnPhase):
        self.mech = mech
        self.law = law
        self.support = support
        self.ret = ret
        self.return_phase = return_phase

    @property
    def H_error_mm(self):
        return self.support.H_error_mm

    def wrap(self, phi):
        """φ mapped into [−φs, 2π − φs)."""
        s = self.mech.phi_s
        return np.mod(np.asarray(phi, dtype=float) + s, TWO_PI) - s

    def H_derivs(self, phi):
        """(H, H', H'', in_support) over the whole turn (2π-periodic)."""
        w = np.atleast_1d(self.wrap(phi))
        s = self.mech.phi_s
        sup = w <= s
        H = np.empty_like(w)
        H1 = np.empty_like(w)
        H2 = np.empty_like(w)
        if np.any(sup):
            d = self.support.derivs(w[sup])
            H[sup], H1[sup], H2[sup] = d["H"], d["H1"], d["H2"]
        if np.any(~sup):
            r0, r1, r2 = self.ret.derivs(w[~sup], order=2)
            H[~sup], H1[~sup], H2[~sup] = r0, r1, r2
        return H, H1, H2, sup

    def leg_angles(self, phi) -> np.ndarray:
        """Carrier angles of all legs when leg 0 is at φ: φ + 2πj/n (j = 0..n−1)."""
        n = int(self.mech.n_legs)
        return np.asarray(phi, dtype=float)[..., None] + TWO_PI * np.arange(n) / n

    def hub_speed(self, phi):
        """dX02/dφ = H'·sin φ + R0 + r + C (seed 001, eq. 8) of whichever leg supports at
        carrier angle φ (period 2π/n)."""
        s = self.mech.phi_s
        w = np.mod(np.asarray(phi, dtype=float) + s, 2 * s) - s
        d = self.support.derivs(np.atleast_1d(w))
        return d["H1"] * np.sin(d["phi"]) + self.mech.hub_height

    def table(self, phi) -> CamTable:
        """All per-φ quantities (eq. 8–10, 14–18) at carrier angles φ (any, periodic)."""
        m = self.mech
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        H, H1, H2, sup = self.H_derivs(phi)
        gam = np.arctan2(H1, H)  # eq. 17
        c = np.cos(gam)
        den = H * H + H1 * H1
        K = (H * H + 2.0 * H1 * H1 - H * H2) / den ** 1.5  # eq. 18, signed
        dgam = 1.0 - H * K / c  # eq. 20 (second line)
        psi = phi - gam  # eq. 10
        sp, cp = np.sin(phi), np.cos(phi)
        ss, cs = np.sin(psi), np.cos(psi)
        X = H * sp - m.r * ss  # eq. 9
        Y = H * cp - m.r * cs
        ro = m.r + m.channel_clearance
        Xo = H * sp + ro * ss
        Yo = H * cp + ro * cs
        with np.errstate(divide="ignore", invalid="ignore"):
            rpath = np.where(K != 0.0, 1.0 / K, np.inf)
            R = rpath - m.r  # eq. 16 ≡ H/((1 − γ')·cos γ) − r
            R_outer = -(rpath + ro)
            inv = 1.0 / m.r + np.where(np.isfinite(R), 1.0 / R, 0.0)
            P = np.where(sup, m.P, m.P_return)
            arg = P * m.E / (m.b * c) * inv
            undercut = (K > 0.0) & (R <= 0.0)
            sig = np.where(undercut | (arg < 0), np.nan, 0.418 * np.sqrt(np.abs(arg)))  # eq. 14
        return CamTable(phi=phi, support=sup, H=H, H1=H1, H2=H2, gamma=gam, dgamma=dgam, K_path=K,
                        psi=psi, X=X, Y=Y, X_outer=Xo, Y_outer=Yo, R_profile=R, R_outer=R_outer,
                        sigma_H=sig, hub_speed=self.hub_speed(phi))


def cam_motion(mech: CamMechanism, law: CurvatureLaw, return_phase: ReturnPhase = ReturnPhase(),
               estimate_error: bool = True, rtol: float = policy.ODE_RTOL,
               atol: float = policy.ODE_ATOL) -> CamMotion:
    """Support path (eq. 20) + C2 return closure → the whole-turn roller-centre path."""
    sup = solve_support(mech, law, rtol=rtol, atol=atol, estimate_error=estimate_error)
    s = mech.phi_s
    da = sup.derivs(np.array([s]))
    db = sup.derivs(np.array([-s]))
    end_a = (float(da["H"][0]), float(da["H1"][0]), float(da["H2"][0]))
    end_b = (float(db["H"][0]), float(db["H1"][0]), float(db["H2"][0]))
    if return_phase.mode == "min_gamma":
        ret = _min_gamma_return(end_a, end_b, s, TWO_PI - s)
    else:
        ret = ReturnCurve.build(end_a, end_b, s, TWO_PI - s, return_phase.H_top)
    return CamMotion(mech, law, sup, ret, return_phase)
