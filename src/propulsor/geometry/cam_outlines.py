"""2D outlines of the driven wheel-walking propulsor with a fixed cam (seed 001, fig. 3).

numpy/scipy only (no cadquery): every outline is a :class:`~propulsor.geometry.profile.Profile`
of exact segments — B-splines fitted to the analytic curves within policy.SPLINE_FIT_TOL_MM
(geometry/bspline.fit_curve), circular arcs and lines.

Frames (ours).  CAD frame: x to the right, y UP, z along the axle O2 (right-handed).  The
seed's cam frame has Y pointing down (seed 001, eq. 9: X = H·sin φ, Y = H·cos φ), so a seed
point (X, Y) is the CAD point (X, −Y); φ (carrier angle from the downward vertical) is then
counter-clockwise about +z and a leg at φ points along u(φ) = (sin φ, −cos φ).

Leg frame (the frame of seed 001 eq. 11 for the shoe): origin at the roller centre C, +Y
along the leg outward (toward the shoe), +X across it.  A leg at carrier angle φ is placed
in the CAD frame by the rotation π + φ about its origin, then the translation H(φ)·u(φ):

    p_cad = R(π + φ)·p_leg + H(φ)·u(φ)

(then the shoe point B of eq. 11 lies straight below the point A = (H + Y1)·u: B − A = (0, −Y2),
the ground normal of eq. 1).  Carrier frame: the carrier at angle 0 has its slot j along
u(2πj/n); it turns by φ about the origin.

Cam channel (closed-track cam, seed 001): the working wall is the roller envelope of eq. 9–10
at exactly r from the roller-centre path (the springs and the ground load press the roller
onto it, so the designed H(φ) is where the roller runs); the outer guide wall is the
envelope at r + channel clearance, on the far side.  The channel is thus 2r + clearance wide.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..errors import InputError, require
from ..laws.cam_motion import CamMotion
from ..laws.shoe import shoe_table
from ..policy import OUTLINE_CLOSED_TOL_MM, PATH_CLOSURE_TOL_MM, ROOT_XTOL_FINE, SPLINE_FIT_TOL_MM
from .bspline import fit_curve
from .profile import Arc, Line, Loop, Profile, Spline, circle_loop

__all__ = [
    "leg_direction", "leg_placement", "to_cad", "cam_wall_loop", "channel_profiles", "cam_plate_profile",
    "bolt_circle_loops", "ShoeGeometry", "shoe_profile", "leg_profile", "roller_profile", "CarrierGeometry",
    "carrier_profile", "radial_extent",
]


# ------------------------------------------------------------------------ frames


def leg_direction(phi) -> np.ndarray:
    """Unit vector u(φ) = (sin φ, −cos φ) of a leg at carrier angle φ, CAD frame."""
    phi = np.asarray(phi, dtype=float)
    return np.stack([np.sin(phi), -np.cos(phi)], axis=-1)


def leg_placement(motion: CamMotion, phi) -> tuple[np.ndarray, np.ndarray]:
    """(rotation angle π + φ, roller-centre position H(φ)·u(φ)) of a leg at carrier angle φ."""
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    H = motion.H_derivs(phi)[0]
    return math.pi + phi, H[:, None] * leg_direction(phi)


def to_cad(X, Y) -> np.ndarray:
    """Seed 001 cam-frame points (Y down) → CAD points (y up)."""
    return np.column_stack([np.asarray(X, float), -np.asarray(Y, float)])


# -------------------------------------------------------------------- cam walls


def _closed_spline_loop(func, breaks, tol: float) -> Loop:
    """Closed loop of B-splines fitted to func(u) piecewise between consecutive breaks; the
    last break is the same point as the first (a periodic curve), snapped exactly."""
    segs = []
    for a, b in zip(breaks[:-1], breaks[1:]):
        segs.append(fit_curve(func, a, b, tol=tol))
    first = segs[0].start
    last = segs[-1]
    gap = float(np.linalg.norm(last.end - first))
    require(gap <= PATH_CLOSURE_TOL_MM, "closed curve gap", gap, "must be <= 1e-6 mm (periodic path)")
    poles = last.poles.copy()
    poles[-1] = first
    segs[-1] = Spline(last.knots, poles, last.degree)
    return Loop(segs)


def _turn_breaks(motion: CamMotion) -> list[float]:
    """Where the roller-centre path has a jump of a higher derivative: the support/return
    joints ±φs (C2), φ = 0 for the even law (K'), φ = π (joint of the two return quintics)."""
    s = motion.mech.phi_s
    return [-s, 0.0, s, math.pi, 2.0 * math.pi - s]


def cam_wall_loop(motion: CamMotion, which: str = "working", tol: float = SPLINE_FIT_TOL_MM) -> Loop:
    """Closed B-spline loop of the cam's working wall (eq. 9–10, roller radius r) or of the
    outer guide wall (offset r + clearance on the far side of the roller-centre path)."""
    require(which in ("working", "outer", "path"), "which", which, "must be 'working', 'outer' or 'path'")

    def func(u):
        t = motion.table(u)
        if which == "working":
            return to_cad(t.X, t.Y)
        if which == "outer":
            return to_cad(t.X_outer, t.Y_outer)
        return to_cad(t.H * np.sin(u), t.H * np.cos(u))

    return _closed_spline_loop(func, _turn_breaks(motion), tol)


def radial_extent(motion: CamMotion, which: str, n: int = 14401) -> tuple[float, float]:
    """(min, max) distance from the cam axis of a cam wall ('working' / 'outer'), dense samples."""
    phi = np.linspace(0.0, 2.0 * math.pi, n)
    t = motion.table(phi)
    P = to_cad(t.X, t.Y) if which == "working" else to_cad(t.X_outer, t.Y_outer)
    d = np.hypot(P[:, 0], P[:, 1])
    return float(d.min()), float(d.max())


def bolt_circle_loops(count: int, circle_diameter: float, hole_diameter: float, phase: float = 0.0) -> list[Loop]:
    """`count` holes of `hole_diameter` on a circle of `circle_diameter`, the first at polar
    angle `phase` (rad, CAD frame)."""
    out = []
    for k in range(int(count)):
        a = phase + 2.0 * math.pi * k / count
        c = (0.5 * circle_diameter * math.cos(a), 0.5 * circle_diameter * math.sin(a))
        out.append(circle_loop(0.5 * hole_diameter, c, ccw=False))
    return out


def channel_profiles(working: Loop, outer: Loop, rim_radius: float, bore_diameter: float,
                     bolt_holes: list[Loop]) -> tuple[Profile, Profile]:
    """The two bodies of the channel layer of a closed-track cam: the core inside the working
    wall (with the axle bore and bolt holes) and the rim ring outside the outer guide wall."""
    core = Profile(working, [circle_loop(0.5 * bore_diameter, ccw=False), *bolt_holes], name="cam core")
    ring = Profile(circle_loop(rim_radius), [outer], name="cam rim")
    return core, ring


def cam_plate_profile(rim_radius: float, bore_diameter: float, bolt_holes: list[Loop]) -> Profile:
    """Back plate (groove floor) of the cam: full disc with the axle bore and bolt holes."""
    return Profile(circle_loop(rim_radius), [circle_loop(0.5 * bore_diameter, ccw=False), *bolt_holes],
                   name="cam plate")


# -------------------------------------------------------------------------- shoe


@dataclass
class ShoeGeometry:
    """The shoe outline (leg frame) and the numbers it was built from."""

    profile: Profile
    psi_boss: tuple[float, float]  # support angles where the inner rim meets the boss sides
    inner_y_at_boss: float  # lowest Y of the inner rim where it meets the boss (mm)
    curve: list  # the spline segments of the ground (outer) curve, ψ from −φs to +φs
    rim: float


def shoe_profile(motion: CamMotion, rim: float, boss_width: float, mount_y: float,
                 tol: float = SPLINE_FIT_TOL_MM) -> ShoeGeometry:
    """Shoe outline in the leg frame (seed 001, eq. 7, 11): the ground curve B(ψ) =
    (X_B, Y_B), ψ ∈ [−φs, φs]; a rim of thickness `rim` inside it (the curve offset along its
    own normal (sin ψ, cos ψ) — the direction of Y2, eq. 1 — so the offset is exact); a boss
    of width `boss_width` from the rim down to the mounting face Y = mount_y, which receives
    the leg end."""
    sup = motion.support
    s = motion.mech.phi_s

    def outer_f(u):
        t = shoe_table(sup, u)
        return np.column_stack([t.X_B, t.Y_B])

    def inner_f(u):
        t = shoe_table(sup, u)
        u = np.asarray(u, float)
        return np.column_stack([t.X_B - rim * np.sin(u), t.Y_B - rim * np.cos(u)])

    half = 0.5 * boss_width
    # X of the inner rim is (Y2 − rim)·sin ψ: monotone while Y2 > rim
    Y2 = shoe_table(sup, np.linspace(-s, s, 721)).Y2
    require(float(Y2.min()) > rim + half, "rim", rim,
            f"must be < Y2_min − boss half width = {float(Y2.min()) - half:.4g} mm (seed 001 eq. 7)")

    def x_inner(u, target):
        return float(inner_f(np.array([u]))[0, 0]) - target

    psi_p = brentq(x_inner, 0.0, s, args=(half,), xtol=ROOT_XTOL_FINE)
    psi_m = brentq(x_inner, -s, 0.0, args=(-half,), xtol=ROOT_XTOL_FINE)
    curve = [fit_curve(outer_f, -s, 0.0, tol=tol), fit_curve(outer_f, 0.0, s, tol=tol)]
    inner_p = fit_curve(inner_f, s, psi_p, tol=tol)  # from the +end down to the boss
    inner_m = fit_curve(inner_f, psi_m, -s, tol=tol)  # from the boss out to the −end
    ip, im = inner_p.end, inner_m.start
    ip[0], im[0] = half, -half  # exactly on the boss sides (brentq to 1e-14 rad)
    inner_p = Spline(inner_p.knots, np.vstack([inner_p.poles[:-1], ip]), inner_p.degree)
    inner_m = Spline(inner_m.knots, np.vstack([im, inner_m.poles[1:]]), inner_m.degree)
    y_boss = float(min(ip[1], im[1]))
    require(mount_y < y_boss, "mount_y", mount_y,
            f"must be < {y_boss:.4g} mm (the inner rim of the shoe at the boss)")
    segs = [*curve,
            Line(tuple(curve[-1].end), tuple(inner_p.start)),
            inner_p,
            Line(tuple(ip), (half, mount_y)),
            Line((half, mount_y), (-half, mount_y)),
            Line((-half, mount_y), tuple(im)),
            inner_m,
            Line(tuple(inner_m.end), tuple(curve[0].start))]
    loop = Loop(segs)
    require(loop.is_closed(OUTLINE_CLOSED_TOL_MM), "shoe outline gap", float(loop.gaps().max()), "must be closed")
    return ShoeGeometry(Profile(loop, [], name="shoe"), (psi_m, psi_p), y_boss, curve, rim)


# ------------------------------------------------------------------ leg, roller


def leg_profile(width: float, back: float, end_y: float) -> Profile:
    """Leg bar in the leg frame: X ∈ [−w/2, w/2], Y from −back (behind the roller axle) to
    end_y (its end face, the mounting face against the shoe)."""
    h = 0.5 * width
    pts = [(-h, -back), (h, -back), (h, end_y), (-h, end_y)]
    return Profile(Loop([Line(pts[i], pts[(i + 1) % 4]) for i in range(4)]), [], name="leg")


def roller_profile(radius: float, bore_diameter: float) -> Profile:
    """Roller: a ring of outer radius r about the leg-frame origin."""
    return Profile(circle_loop(radius), [circle_loop(0.5 * bore_diameter, ccw=False)], name="roller")


# ----------------------------------------------------------------------- carrier


@dataclass
class CarrierGeometry:
    profile: Profile
    slot_half_width: float
    slot_bottom: float  # radius of the slot's inner end
    slot_rim: float  # distance along the slot axis where the slot walls meet the rim


def carrier_profile(n_legs: int, radius: float, slot_width: float, slot_bottom: float,
                    bore_diameter: float, bolt_holes: list[Loop]) -> CarrierGeometry:
    """Carrier disc with `n_legs` radial slides: slots of width slot_width open at the rim,
    from the radius slot_bottom outward, slot j along u(2πj/n) (carrier frame)."""
    h = 0.5 * slot_width
    require(h < radius, "slot_width", slot_width, f"slot must be narrower than the carrier diameter {2 * radius:g} mm")
    L = math.sqrt(radius * radius - h * h)
    require(slot_bottom < L, "radius", radius, f"must reach beyond the slot bottom {slot_bottom:.4g} mm")
    segs = []
    corners = []
    for j in range(n_legs):
        th = 2.0 * math.pi * j / n_legs
        d = np.array([math.sin(th), -math.cos(th)])
        e = np.array([math.cos(th), math.sin(th)])
        corners.append(((-h * e + L * d), (-h * e + slot_bottom * d), (h * e + slot_bottom * d), (h * e + L * d)))
    for j in range(n_legs):
        a_rim, a_bot, b_bot, b_rim = corners[j]
        nxt = corners[(j + 1) % n_legs][0]
        segs += [Line(tuple(a_rim), tuple(a_bot)), Line(tuple(a_bot), tuple(b_bot)), Line(tuple(b_bot), tuple(b_rim))]
        a0 = math.atan2(b_rim[1], b_rim[0])
        a1 = math.atan2(nxt[1], nxt[0])
        while a1 <= a0:
            a1 += 2.0 * math.pi
        segs.append(Arc((0.0, 0.0), radius, a0, a1))  # ends on the next slot's corner (to rounding)
    loop = Loop(segs)
    require(loop.is_closed(OUTLINE_CLOSED_TOL_MM), "carrier outline gap", float(loop.gaps().max()), "must be closed")
    prof = Profile(loop, [circle_loop(0.5 * bore_diameter, ccw=False), *bolt_holes], name="carrier")
    return CarrierGeometry(prof, h, slot_bottom, L)


def point_slot_distance(p, n_legs: int, half_width: float, slot_bottom: float) -> float:
    """Least distance from a point (carrier frame) to the slot regions (|t| <= h, s >= bottom)."""
    p = np.asarray(p, float)
    best = math.inf
    for j in range(n_legs):
        th = 2.0 * math.pi * j / n_legs
        s = p[0] * math.sin(th) - p[1] * math.cos(th)
        t = p[0] * math.cos(th) + p[1] * math.sin(th)
        ds = max(slot_bottom - s, 0.0)
        dt = max(abs(t) - half_width, 0.0)
        best = min(best, math.hypot(ds, dt))
    return best


def check_hole_fits(name: str, value, hole_centers, hole_radius: float, r_in: float, r_out: float,
                    web: float) -> None:
    """InputError unless every hole keeps `web` mm of material to the radii r_in and r_out."""
    for c in hole_centers:
        rho = math.hypot(*c)
        if rho - hole_radius - web < r_in or rho + hole_radius + web > r_out:
            raise InputError(name, value, f"holes must keep {web:g} mm of material between the radii "
                                          f"{r_in:.4g} and {r_out:.4g} mm")
