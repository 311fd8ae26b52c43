"""Closed outlines of the papers' sector teeth (seed 000 eqs. 16-52, seed 002 Tables 2-4; the
sector table and the tooth points are in ``gears.sectors``).

Each sector is a piece of a circular gear of radius r_k with one driver tooth / one driven space,
involute flanks with the papers' base radius r_b = r - m from r_b to the tip r + m, a radial
flank foot down to the root r - 1.25 m, backlash as the angular correction j_n / (4 r_b) per
flank.  Transitions the papers leave open are closed as follows (ours): a driven-wheel tooth
between spaces i and i+1 has the tip radius of sector i+1 (the papers' 6th point of Table 4
extends the flank of space i to it); a driver space straddling two sectors has a root whose
radius passes from r_f(i) to r_f(i+1) by the quintic smoothstep 6t^5 - 15t^4 + 10t^3 of the
angle across the space (C2 in the angle).  Body frames as in ``gears.noncircular_teeth``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..gears.sectors import SectorTable, involute
from ..laws.walking import LEG_PERIOD
from ..policy import RADIUS_EQUAL_TOL_MM, SPLINE_FIT_TOL_MM
from .noncircular_outline import fit_piece
from .profile import Arc, Line, Loop, Profile, Spline

__all__ = ["SectorGear", "sector_driver_gear", "sector_driven_gear"]


@dataclass
class SectorGear:
    role: str
    profile: Profile
    tip_thickness_min: float
    root_min_radius: float


def _legs(table: SectorTable, role: str) -> list[int]:
    n = table.law.n
    return list(range(4)) if role == "driven" else list(range(4 // n))


def _flank_fun(r_b: float, base: float, sign: float):
    """Involute flank of base r_b as a function of the roll parameter t: polar angle base + sign*(t - atan t)."""
    def f(t):
        t = np.atleast_1d(np.asarray(t, float))
        r = r_b * np.sqrt(1.0 + t * t)
        a = base + sign * (t - np.arctan(t))
        return np.column_stack([r * np.cos(a), r * np.sin(a)])
    return f


def _t_of_r(r_b: float, r: float) -> float:
    return math.sqrt(max((r / r_b) ** 2 - 1.0, 0.0))


def _polar_pt(r, a):
    return (float(r * math.cos(a)), float(r * math.sin(a)))


def sector_driver_gear(table: SectorTable, m: float, j_n: float, tol: float = SPLINE_FIT_TOL_MM) -> SectorGear:
    """Driver outline of the sector method (seed 002 Table 3 flanks), body frame of the module docstring."""
    n = table.law.n
    segs = []
    r_all = table.r
    feet = []  # per tooth: (first-flank foot angle, second-flank foot angle, r_f), in theta
    units = []
    for k in _legs(table, "driver"):
        shift = k * n * LEG_PERIOD
        for i in range(table.i):
            r = float(r_all[i])
            rb, rf, ra = r - m, r - 1.25 * m, r + m
            th, dth = float(table.theta[i]) + shift, float(table.dtheta[i])
            nu3 = float(involute(math.acos(rb / r)))
            d = j_n / (4 * rb)
            b1 = th + 0.25 * dth + d - nu3  # first flank: theta = b1 + nu(r)
            b2 = th + 0.75 * dth - d + nu3  # second flank: theta = b2 - nu(r)
            ta = _t_of_r(rb, ra)
            f1, f2 = _flank_fun(rb, b1, 1.0), _flank_fun(rb, b2, -1.0)
            a1 = b1 + ta - math.atan(ta)
            a2 = b2 - (ta - math.atan(ta))
            unit = [Line(_polar_pt(rf, b1), _polar_pt(rb, b1)), fit_piece(f1, 0.0, ta, tol),
                    Arc((0.0, 0.0), ra, a1, a2), fit_piece(f2, ta, 0.0, tol), Line(_polar_pt(rb, b2), _polar_pt(rf, b2))]
            units.append(unit)
            feet.append((b1, b2, rf, ra * (a2 - a1)))
    for j, unit in enumerate(units):
        segs.extend(unit)
        b1n = feet[(j + 1) % len(feet)][0] + (2 * math.pi if j + 1 == len(feet) else 0.0)
        a0, rf0 = feet[j][1], feet[j][2]
        rf1 = feet[(j + 1) % len(feet)][2]
        if abs(rf1 - rf0) < RADIUS_EQUAL_TOL_MM:
            segs.append(Arc((0.0, 0.0), rf0, a0, b1n))
        else:
            def root(a, a0=a0, a1=b1n, r0=rf0, r1=rf1):
                a = np.atleast_1d(np.asarray(a, float))
                t = (a - a0) / (a1 - a0)
                rr = r0 + (r1 - r0) * t ** 3 * (10 - 15 * t + 6 * t * t)
                return np.column_stack([rr * np.cos(a), rr * np.sin(a)])
            segs.append(fit_piece(root, a0, b1n, tol))
    loop = Loop(segs)
    # theta frame -> driver body frame: beta = pi - theta, i.e. mirror x -> -x
    mir = Loop([_mirror_seg(s) for s in loop.segments])
    prof = Profile(mir, name=f"driver sectors i={table.i}")
    return SectorGear("driver", prof, float(min(f[3] for f in feet)), float(min(f[2] for f in feet)))


def _mirror_seg(s):
    if isinstance(s, Line):
        return Line((-s.p0[0], s.p0[1]), (-s.p1[0], s.p1[1]))
    if isinstance(s, Arc):
        return Arc((-s.center[0], s.center[1]), s.radius, math.pi - s.a0, math.pi - s.a1)
    return Spline(s.knots.copy(), s.poles * np.array([-1.0, 1.0]), s.degree)


def sector_driven_gear(table: SectorTable, m: float, j_n: float, tol: float = SPLINE_FIT_TOL_MM) -> SectorGear:
    """Driven-wheel outline of the sector method (seed 002 Table 4 spaces; the tooth between
    spaces i and i+1 reaches the tip radius r_H(i+1) + m, the papers' 6th point)."""
    rH = table.r_H
    spaces = []
    for k in range(4):
        shift = k * LEG_PERIOD
        for i in range(table.i):
            r = float(rH[i])
            rb, rf = r - m, r - 1.25 * m
            ph, dph = float(table.phi[i]) + shift, float(table.dphi[i])
            nu3 = float(involute(math.acos(rb / r)))
            d = j_n / (4 * rb)
            b1 = ph + 0.25 * dph - d + nu3  # first flank phi = b1 - nu(r)
            b2 = ph + 0.75 * dph + d - nu3  # second flank phi = b2 + nu(r)
            spaces.append((rb, rf, r + m, b1, b2))
    segs = []
    N = len(spaces)
    tmin, rfmin = math.inf, math.inf
    for j in range(N):
        rb, rf, ra, b1, b2 = spaces[j]
        rbn, rfn, ran, b1n, b2n = spaces[(j + 1) % N]
        if j + 1 == N:
            b1n += 2 * math.pi
        r_top = ran  # tip of the next sector (seed 002 Table 4, point 6)
        t_top = _t_of_r(rb, r_top)
        t_top_n = _t_of_r(rbn, ran)
        a_end = b2 + (t_top - math.atan(t_top))
        a_next = b1n - (t_top_n - math.atan(t_top_n))
        tmin = min(tmin, r_top * (a_next - a_end))
        rfmin = min(rfmin, rf)
        if j == 0:
            segs.append(fit_piece(_flank_fun(rb, b1, -1.0), _t_of_r(rb, ra), 0.0, tol))
            segs.append(Line(_polar_pt(rb, b1), _polar_pt(rf, b1)))
        segs.append(Arc((0.0, 0.0), rf, b1, b2))
        if r_top <= rf:
            raise InputError("z_H", 4 * len(table.phi),
                             f"sector method: the tip radius of sector {(j + 1) % table.i + 1} ({r_top:.3f} mm) lies below "
                             f"the root of sector {j % table.i + 1} ({rf:.3f} mm): the driven notch is deeper than a tooth",
                             "use fewer sectors (a larger module) or the generated method")
        if r_top <= rb + RADIUS_EQUAL_TOL_MM:  # the 6th point of Table 4 lies below the base circle: radial flank only
            segs.append(Line(_polar_pt(rf, b2), _polar_pt(r_top, b2)))
        else:
            segs.append(Line(_polar_pt(rf, b2), _polar_pt(rb, b2)))
            segs.append(fit_piece(_flank_fun(rb, b2, 1.0), 0.0, t_top, tol))
        segs.append(Arc((0.0, 0.0), r_top, a_end, a_next))
        if j + 1 < N:
            segs.append(fit_piece(_flank_fun(rbn, b1n, -1.0), t_top_n, 0.0, tol))
            segs.append(Line(_polar_pt(rbn, b1n), _polar_pt(rfn, b1n)))
    # the last tip arc ends where the first flank begins (a_first + 2 pi)
    prof = Profile(Loop(segs), name=f"driven sectors i={table.i}")
    return SectorGear("driven", prof, float(tmin), float(rfmin))
