"""Side outline of a lever arm between two bosses, drawn around a required depth (numpy/scipy only).

Frame: the arm's axis is the x axis from the first boss centre (0, 0) to the second (L, 0);
y across the arm.  Inputs are the required half depths along the arm (top and bottom edges,
e.g. an equal-strength depth from a beam model) and features the top edge must enclose:
circles (a lug around a pin hole) and plateaus (a flat pad).

Construction:

1. Each edge's requirement, sampled on a uniform grid, is replaced by a smooth majorant:
   a running maximum over ±w, then a convolution with the C² kernel (1 − t²)³ of half width w.
   Every smoothed value is a weighted mean of running maxima whose windows contain the point,
   so the edge never falls below its requirement on the grid; a plateau wider than 2w stays
   exactly flat over its own length.  A cubic interpolant of the grid values is the edge y(x).
2. Each edge meets each boss circle through a concave fillet of radius r_f, tangent to both:
   its centre lies at distance R + r_f from the boss centre and r_f from the edge along the
   edge's outer normal (solved by Brent's method).
3. Outline: boss arcs, fillet arcs (exact circles) and the edges between the fillets
   (clamped cubic B-splines within ``policy.SPLINE_FIT_TOL_MM`` of y(x)).  Holes: circles.

``section_depth`` measures, on the finished outline, the depth of the largest band about the
axis contained in the material at a station (the section a beam check may use).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.ndimage import convolve1d, maximum_filter1d
from scipy.optimize import brentq

from ..errors import InputError, require, require_positive
from ..policy import GRID_UNIFORM_TOL, OUTLINE_CLOSED_TOL_MM, ROOT_XTOL, ROOT_XTOL_FINE, SPLINE_FIT_TOL_MM
from .bspline import fit_curve
from .profile import Arc, Loop, Profile, circle_loop

__all__ = ["smooth_majorant", "ArmOutline", "arm_outline", "section_depth", "material_intervals"]


def smooth_majorant(y: np.ndarray, ds: float, w: float) -> np.ndarray:
    """Smooth upper envelope of samples y on a uniform grid of spacing ds (see module docstring)."""
    y = np.asarray(y, float)
    k = max(1, int(math.ceil(w / ds)))
    dil = maximum_filter1d(y, size=2 * k + 1, mode="nearest")
    t = np.arange(-k, k + 1) / (k + 1.0)
    ker = (1.0 - t * t) ** 3
    ker /= ker.sum()
    return convolve1d(dil, ker, mode="nearest")


@dataclass
class ArmOutline:
    """The finished outline and the data behind it (all mm)."""

    profile: Profile
    length: float
    grid: np.ndarray
    top: np.ndarray  # smoothed top half depth on the grid (>= 0, above the axis)
    bottom: np.ndarray  # smoothed bottom half depth on the grid (>= 0, below the axis)
    tangent_x: dict = field(default_factory=dict)  # where the edges leave the fillets
    fillet_centres: dict = field(default_factory=dict)

    def top_y(self, x):
        return CubicSpline(self.grid, self.top)(x)

    def bottom_y(self, x):
        return -CubicSpline(self.grid, self.bottom)(x)


def _fillet(f: CubicSpline, sign: float, C, R: float, rf: float, x_lo: float, x_hi: float, from_hi: bool):
    """Fillet between the edge y = sign·f(x) and the circle (C, R), found scanning from one end.

    Returns (x on the edge, centre of the fillet, tangent point on the circle)."""
    C = np.asarray(C, float)
    df = f.derivative()

    def centre(x):
        d = float(df(x)) * sign
        n = np.array([-d, 1.0]) / math.hypot(d, 1.0) * sign  # outer normal (away from the axis)
        return np.array([x, sign * float(f(x))]) + rf * n

    def g(x):
        return float(np.linalg.norm(centre(x) - C)) - (R + rf)

    xs = np.linspace(x_hi, x_lo, 2001) if from_hi else np.linspace(x_lo, x_hi, 2001)
    gv = np.array([g(x) for x in xs])
    require(gv[0] < 0, "boss", R, "the edge must start inside the boss circle (depth exceeds the boss)")
    j = np.nonzero(gv > 0)[0]
    require(len(j) > 0, "fillet", rf, "no fillet between the edge and the boss: the edge stays inside the boss")
    a, b = xs[j[0] - 1], xs[j[0]]
    x = brentq(g, min(a, b), max(a, b), xtol=ROOT_XTOL, rtol=ROOT_XTOL_FINE)
    c = centre(x)
    q = C + (c - C) * (R / float(np.linalg.norm(c - C)))
    return float(x), c, q


def _arc(center, p_from, p_to, ccw: bool) -> Arc:
    c = np.asarray(center, float)
    a0 = math.atan2(p_from[1] - c[1], p_from[0] - c[0])
    a1 = math.atan2(p_to[1] - c[1], p_to[0] - c[0])
    r = float(np.linalg.norm(np.asarray(p_from, float) - c))
    if ccw:
        while a1 <= a0:
            a1 += 2 * math.pi
    else:
        while a1 >= a0:
            a1 -= 2 * math.pi
    return Arc((float(c[0]), float(c[1])), r, a0, a1)


def arm_outline(length: float, r_boss0: float, r_boss1: float, grid: np.ndarray, top_req: np.ndarray,
                bottom_req: np.ndarray, fillet_r: float, smooth_w: float, circles=(), plateaus=(),
                holes=(), tol: float = SPLINE_FIT_TOL_MM) -> ArmOutline:
    """Outline of an arm from (0, 0) to (length, 0), bosses of radius r_boss0 / r_boss1.

    grid: uniform stations covering [0, length]; top_req / bottom_req: required half depths
    (>= 0) above / below the axis at the stations; circles: (x, y, r) the top edge must
    enclose; plateaus: (x0, x1, y) flat stretches of the top edge; holes: (x, y, r) circles cut
    out of the plate.
    """
    L = require_positive("length", length, "mm")
    grid = np.asarray(grid, float)
    ds = float(grid[1] - grid[0])
    require(np.allclose(np.diff(grid), ds, rtol=GRID_UNIFORM_TOL, atol=GRID_UNIFORM_TOL), "grid", "non-uniform", "stations must be uniform")
    require(grid[0] <= 0.0 and grid[-1] >= L, "grid", (grid[0], grid[-1]), f"must cover [0, {L:g}] mm")
    top = np.maximum(np.asarray(top_req, float), 0.0)
    bot = np.maximum(np.asarray(bottom_req, float), 0.0)
    for (cx, cy, r) in circles:
        d = np.abs(grid - cx)
        inside = d < r
        top[inside] = np.maximum(top[inside], cy + np.sqrt(r * r - d[inside] ** 2))
    for (x0, x1, y) in plateaus:
        require(x1 - x0 > 2 * smooth_w, "plateau", x1 - x0, f"must be longer than 2 w = {2 * smooth_w:g} mm")
        on = (grid >= x0 - smooth_w) & (grid <= x1 + smooth_w)
        top[on] = np.maximum(top[on], y)
    top_s = smooth_majorant(top, ds, smooth_w)
    bot_s = smooth_majorant(bot, ds, smooth_w)
    ft, fb = CubicSpline(grid, top_s), CubicSpline(grid, bot_s)
    rf = require_positive("fillet_r", fillet_r, "mm")
    C0, C1 = np.array([0.0, 0.0]), np.array([L, 0.0])
    # fillets: (x on edge, centre, point on boss)
    xb0, cb0, qb0 = _fillet(fb, -1.0, C0, r_boss0, rf, 0.0, L, from_hi=False)
    xb1, cb1, qb1 = _fillet(fb, -1.0, C1, r_boss1, rf, 0.0, L, from_hi=True)
    xt0, ct0, qt0 = _fillet(ft, 1.0, C0, r_boss0, rf, 0.0, L, from_hi=False)
    xt1, ct1, qt1 = _fillet(ft, 1.0, C1, r_boss1, rf, 0.0, L, from_hi=True)
    if not (xb0 < xb1 and xt0 < xt1):
        raise InputError("length", length, "the bosses' fillets overlap: the arm is too short for its bosses")
    bottom_curve = fit_curve(lambda x: np.column_stack([x, -fb(x)]), xb0, xb1, tol=tol)
    top_curve = fit_curve(lambda x: np.column_stack([x, ft(x)]), xt1, xt0, tol=tol)
    pb0, pb1 = bottom_curve.start, bottom_curve.end
    pt1, pt0 = top_curve.start, top_curve.end
    segs = [
        _arc(cb0, qb0, pb0, ccw=False),
        bottom_curve,
        _arc(cb1, pb1, qb1, ccw=False),
        _arc(C1, qb1, qt1, ccw=True),
        _arc(ct1, qt1, pt1, ccw=False),
        top_curve,
        _arc(ct0, pt0, qt0, ccw=False),
        _arc(C0, qt0, qb0, ccw=True),
    ]
    loop = Loop(segs)
    require(loop.is_closed(OUTLINE_CLOSED_TOL_MM), "outline", float(loop.gaps().max()), "arm outline does not close")
    hole_loops = [circle_loop(r, (x, y), ccw=False) for (x, y, r) in holes]
    prof = Profile(loop, hole_loops, name="arm")
    return ArmOutline(prof, L, grid, top_s, bot_s,
                      {"bottom_0": xb0, "bottom_1": xb1, "top_0": xt0, "top_1": xt1},
                      {"bottom_0": cb0, "bottom_1": cb1, "top_0": ct0, "top_1": ct1})


def _intervals(polys, x: float) -> list[tuple[float, float]]:
    ys = []
    for poly in polys:
        a, b = poly, np.roll(poly, -1, axis=0)
        cross = (a[:, 0] - x) * (b[:, 0] - x) < 0
        on = (a[:, 0] == x) & (b[:, 0] != x)
        for i in np.nonzero(cross | on)[0]:
            t = (x - a[i, 0]) / (b[i, 0] - a[i, 0])
            ys.append(a[i, 1] + t * (b[i, 1] - a[i, 1]))
    ys = np.sort(np.asarray(ys, float))
    if len(ys) % 2:
        ys = ys[:-1]
    return [(float(ys[i]), float(ys[i + 1])) for i in range(0, len(ys), 2)]


def material_intervals(profile: Profile, x: float, chord_tol: float = 0.002) -> list[tuple[float, float]]:
    """Intervals of y where the vertical line at x lies in the material (outer minus holes)."""
    return _intervals(profile.polylines(chord_tol), float(x))


def section_depth(profile: Profile, xs, chord_tol: float = 0.002) -> np.ndarray:
    """Depth 2·min(y_top, −y_bottom) of the material band about the axis at each station (0 if the
    axis itself is not in the material)."""
    polys = profile.polylines(chord_tol)
    out = []
    for x in np.atleast_1d(np.asarray(xs, float)):
        d = 0.0
        for lo, hi in _intervals(polys, float(x)):
            if lo <= 0.0 <= hi:
                d = 2.0 * min(hi, -lo)
        out.append(d)
    return np.array(out)
