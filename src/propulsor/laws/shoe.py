"""Support shoes of the driven wheel-walking propulsor (seed 001, eq. 1–7, 11–13).

Leg frame: origin at the roller centre (point C of seed 001 fig. 3), Y along the leg
outward (toward the shoe), X across it.  The shoe point B touching flat ground at
carrier angle φ is reached by Y1 along the leg (to point A) and then Y2 along the ground
normal, which makes the angle φ with the leg (seed 001, eq. 11):

    X_B = Y2·sin φ,   Y_B = Y1 + Y2·cos φ,   α = atan(X_B/Y_B),   ρ = √(X_B² + Y_B²)

Constant hub height (eq. 5–7) (H + Y1)·cos φ + Y2 = R0 + r + C together with the
normality condition dY2/dφ = −dY1/dφ·cos φ (eq. 1) give

    Y1 = H'/tan φ − H,   Y2 = R0 + r + C − (H + Y1)·cos φ.

Y1 has a removable singularity at φ = 0 (limit H''(0) − H0).  It is evaluated without
cancellation as Y1 = H·sin(γ − φ)/(cos γ·sin φ) with (γ − φ)/φ = −(1/φ)∫0^φ H·K/cos γ dφ
by Gauss–Legendre quadrature of the dense ODE solution (eq. 20).

The shoe curve's tangent is (cos φ, −sin φ)·σ with σ = Y2 − Y1'·sin φ — the integrand
of eq. 3, i.e. the shoe's radius of curvature and the ground-contact advance per radian.
A cusp (tangent reversal) is σ changing sign; the shoe is also tested for
self-intersection as a polyline.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize_scalar

from propulsor import policy
from propulsor.laws.cam_motion import CamMotion, SupportPath


def _sinc(x):
    """sin x / x (1 at 0)."""
    return np.sinc(np.asarray(x, dtype=float) / math.pi)


def _dsinc(x):
    """d/dx (sin x / x), without cancellation near 0."""
    x = np.asarray(x, dtype=float)
    small = np.abs(x) < policy.SINC_SERIES_BELOW
    xs = np.where(small, 1.0, x)
    big = (xs * np.cos(xs) - np.sin(xs)) / (xs * xs)
    x2 = x * x
    ser = x * (-1.0 / 3.0 + x2 * (1.0 / 30.0 - x2 * (1.0 / 840.0 - x2 / 45360.0)))
    return np.where(small, ser, big)


@dataclass
class ShoeTable:
    """Shoe quantities at support angles φ (arrays; leg frame, mm)."""

    phi: np.ndarray
    Y1: np.ndarray  # eq. 7 (with eq. 1)
    dY1: np.ndarray
    Y2: np.ndarray  # eq. 7
    X_B: np.ndarray  # eq. 11
    Y_B: np.ndarray
    rho: np.ndarray  # eq. 13, distance of B from the roller centre
    alpha: np.ndarray  # eq. 12, from the leg axis (rad)
    radius: np.ndarray  # σ = Y2 − Y1'·sin φ: radius of curvature of the shoe (> 0: convex)


def shoe_table(support: SupportPath, phi) -> ShoeTable:
    """Shoe profile of seed 001 eq. 7, 11–13 at support angles φ (|φ| <= π/n)."""
    m = support.mech
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    d = support.derivs(phi)
    H, H1, gam, gam1, g = d["H"], d["H1"], d["gamma"], d["dgamma"], d["g"]
    q, dq = support.delta_over_phi(phi)
    delta = phi * q
    c = np.cos(gam)
    A = H / c
    dA = H1 / c + H * np.tan(gam) * gam1 / c
    s_phi = _sinc(phi)
    B = _sinc(delta) / s_phi
    dB = _dsinc(delta) * (-g) / s_phi - _sinc(delta) * _dsinc(phi) / (s_phi * s_phi)
    Y1 = A * B * q
    dY1 = dA * B * q + A * dB * q + A * B * dq
    Y2 = m.hub_height - (H + Y1) * np.cos(phi)
    XB = Y2 * np.sin(phi)
    YB = Y1 + Y2 * np.cos(phi)
    return ShoeTable(phi=phi, Y1=Y1, dY1=dY1, Y2=Y2, X_B=XB, Y_B=YB, rho=np.hypot(XB, YB),
                     alpha=np.arctan2(XB, YB), radius=Y2 - dY1 * np.sin(phi))


def _segments_intersect(P: np.ndarray) -> bool:
    """True if the open polyline P (n, 2) crosses itself (non-adjacent segments).

    Each segment is half-open, [start, end): a crossing exactly at a vertex is counted once, by the segment
    that starts there (closed intervals would count it twice, open ones not at all).  The polyline's last
    point touching an earlier segment is not a crossing; an exact fold-back along the previous segment is a
    cusp (σ changes sign), found by :func:`shoe_loop_check`'s radius test.  Compiled
    (:func:`.cam_kernels.polyline_crosses_itself`: each pair's line parameters as the all-pairs arrays gave them)."""
    from .cam_kernels import polyline_crosses_itself

    return bool(polyline_crosses_itself(np.ascontiguousarray(P, np.float64)))


@dataclass(frozen=True)
class ShoeLoopCheck:
    """Loop / cusp check of a shoe profile."""

    radius_min: float  # min σ over the support phase, mm (≤ 0: cusp / tangent reversal)
    phi_at_min: float
    self_intersecting: bool
    ok: bool


def shoe_loop_check(tab: ShoeTable, radius_min_limit: float = 0.0) -> ShoeLoopCheck:
    """Shoe is acceptable if its radius of curvature σ stays > radius_min_limit (no
    tangent reversal) and the profile does not cross itself."""
    i = int(np.argmin(tab.radius))
    inter = _segments_intersect(np.column_stack([tab.X_B, tab.Y_B]))
    rmin = float(tab.radius[i])
    return ShoeLoopCheck(radius_min=rmin, phi_at_min=float(tab.phi[i]), self_intersecting=inter,
                         ok=(rmin > radius_min_limit) and not inter)


def shoe_arc_length(tab: ShoeTable) -> float:
    """Length of the shoe profile ∫σ dφ (= the footprint length on flat ground; eq. 3),
    trapezoid rule on the table (use a fine, sorted φ grid)."""
    return float(np.trapezoid(tab.radius, tab.phi))


def hub_travel_per_step(motion: CamMotion, n: int = 2001) -> float:
    """Horizontal hub travel while one leg supports: ∫ dX02/dφ dφ over the support phase
    (seed 001, eq. 8), Simpson-like by trapezoid on a fine grid."""
    s = motion.mech.phi_s
    phi = np.linspace(-s, s, n)
    return float(np.trapezoid(motion.hub_speed(phi), phi))


def _depth(motion: CamMotion, phi_leg, XB, YB):
    """Depth below the hub of leg-frame points (XB, YB) of a leg at carrier angle φ_leg:
    (H(φ) + Y_B)·cos φ + X_B·sin φ (the placement behind seed 001 eq. 2, 11)."""
    H = motion.H_derivs(phi_leg)[0]
    return (H + YB) * np.cos(phi_leg) + XB * np.sin(phi_leg)


def hub_height_on_flat(motion: CamMotion, phi, n_shoe: int = 1201) -> np.ndarray:
    """Hub height over flat ground at carrier angles φ, found independently of eq. 7:
    every leg's shoe is placed at its carrier angle (H(φ) of the whole turn) and the
    lowest shoe point over all legs is searched (dense samples + bounded refinement)."""
    s = motion.mech.phi_s
    sup = motion.support
    grid = np.linspace(-s, s, n_shoe)
    tab = shoe_table(sup, grid)
    out = []
    for p in np.atleast_1d(np.asarray(phi, dtype=float)):
        best = -np.inf
        for pl in motion.leg_angles(p):
            dep = _depth(motion, np.full_like(grid, pl), tab.X_B, tab.Y_B)
            k = int(np.argmax(dep))
            lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, n_shoe - 1)]

            def f(u, pl=pl):
                t = shoe_table(sup, np.array([u]))
                return -float(_depth(motion, np.array([pl]), t.X_B, t.Y_B)[0])

            if hi > lo:
                res = minimize_scalar(f, bounds=(lo, hi), method="bounded",
                                      options={"xatol": policy.ROOT_XTOL * 10})
                val = max(-res.fun, dep[k])
            else:
                val = dep[k]
            best = max(best, val)
        out.append(best)
    return np.array(out)


def return_ground_clearance(motion: CamMotion, phi, n_shoe: int = 801) -> np.ndarray:
    """Clearance (mm) between flat ground and the lowest shoe of the legs NOT in
    support at carrier angle φ of leg 0 (hub at R0 + r + C).  Zero at hand-over."""
    s = motion.mech.phi_s
    grid = np.linspace(-s, s, n_shoe)
    tab = shoe_table(motion.support, grid)
    out = []
    for p in np.atleast_1d(np.asarray(phi, dtype=float)):
        legs = motion.leg_angles(p)
        w = motion.wrap(legs)
        others = legs[np.argsort(np.abs(w))[1:]]  # all but the supporting leg
        dep = max(float(np.max(_depth(motion, np.full_like(grid, pl), tab.X_B, tab.Y_B))) for pl in others)
        out.append(motion.mech.hub_height - dep)
    return np.array(out)


def footprint_ratio(motion: CamMotion, n: int = 2001) -> float:
    """Shoe footprint length / hub travel per step (1 = continuous track like a wheel;
    < 1 = discrete footprints, the walking mover's passability, seed 001 intro)."""
    s = motion.mech.phi_s
    tab = shoe_table(motion.support, np.linspace(-s, s, n))
    return shoe_arc_length(tab) / hub_travel_per_step(motion, n)


__all__ = ["ShoeTable", "shoe_table", "ShoeLoopCheck", "shoe_loop_check", "shoe_arc_length",
           "hub_travel_per_step", "hub_height_on_flat", "return_ground_clearance", "footprint_ratio"]
