"""The least hub-speed ripple of the walking-drive pair under generability: a search over the blend
shape and the catalogue shaper.

Pure math (numpy/scipy).  The blend (``noncircular.SmoothedWalkingLaw`` with a free hand-over value
u_h) has two shape parameters: its half-width delta and the value U_s = u_h at hand-over (the depth
of the hub-speed dip, v/omega = (dX01/dphi)/U_s, seed 000 eq. 2-3); closure is restored by scaling U
outside the windows.  For every catalogue shaper the search scans delta and, at each delta, finds
the smallest u_h that keeps both pitch curves generable (``generability.check_generable``: rack
undercut limit on convex stretches, shaper r0 + cutting offset below |rho| on concave ones) by a
coarse scan and bisection; the centre distance follows from closure (L = pi m z_H / perimeter) and
must stay within a band of a reference L.  Every generable point is kept (the table), the Pareto
front ripple vs centre distance and ripple vs curvature margin are marked, and the points are
ranked by ripple (ties: larger margin) for the design to try in order (the tooth generator has
the last word: tip land, generating limit of the cutter).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..laws.walking import WalkingLaw
from ..policy import LAW_SEARCH_DELTA_DEG, LAW_SEARCH_UH_BISECTIONS, LAW_SEARCH_UH_SCAN
from .generability import CutterSpec, Generability, check_generable
from .noncircular import PitchCurves, SmoothedWalkingLaw, hub_speed_ripple, perimeter_per_mm

__all__ = ["LawPoint", "LawSearch", "search_law", "pareto"]


@dataclass(frozen=True)
class LawPoint:
    """One generable blend: shaper (catalogue d0, z0), half-width delta (rad), hand-over value u_h
    (as u_h / u), centre distance L (mm), hub speed ripple, the least curvature margin (mm: the
    smaller of rho_convex_min - rack limit and |rho|_concave_min - (r0 + e) over both curves) and
    which of the four limits binds."""

    d0_mm: float
    z0: int
    delta: float
    u_h_rel: float
    L: float
    ripple: float
    margin_mm: float
    binding: str
    front_L: bool = False
    front_margin: bool = False


@dataclass(frozen=True)
class LawSearch:
    points: tuple          # every generable point (LawPoint), ranked (least ripple first)
    evaluations: int
    L_ref: float
    L_band: float

    @property
    def best(self) -> LawPoint:
        return self.points[0]


def _margins(g: Generability) -> tuple[float, str]:
    out = []
    for c in (g.driver, g.driven):
        out.append((c.rho_convex_min - c.rho_limit, f"{c.curve} convex vs rack undercut limit"))
        if c.concave:
            out.append((c.rho_concave_min - c.r0, f"{c.curve} concave vs shaper r0 + e"))
    return min(out)


def pareto(values: np.ndarray, ripple: np.ndarray, larger_is_better: bool) -> np.ndarray:
    """Mask of the points no other point beats in both ripple (lower) and ``values``."""
    v = values if larger_is_better else -values
    keep = np.ones(len(ripple), bool)
    for i in range(len(ripple)):
        better = (ripple <= ripple[i]) & (v >= v[i]) & ((ripple < ripple[i]) | (v > v[i]))
        keep[i] = not np.any(better)
    return keep


#: the last searches this process made, by their inputs (at most ``_KEPT``, the oldest dropped): a design study that
#: varies what the search does not read (the face width, the load, the material, the backlash) searches once
_SEARCHES: dict = {}
_KEPT = 8


def search_law(law: WalkingLaw, m: float, z_H: int, x: float, shapers, L_ref: float, L_band: float,
               alpha: float = math.radians(20.0), h_a: float = 1.0) -> LawSearch:
    """Scan the blend (delta on ``policy.LAW_SEARCH_DELTA_DEG``, smallest generable u_h by bisection)
    for every shaper of ``shapers`` ((d0_mm, ShaperCutter) pairs, the driven wheel's shift -x, the
    driver's +x).  InputError naming ``L_band`` (its value, the band and L_ref in the limit) when no
    point is generable within the band |L - L_ref| <= L_band.  A search made before with equal inputs (values: the
    law and the shapers are frozen dataclasses) is not made again: its result is returned (``_SEARCHES``)."""
    key = (law, float(m), int(z_H), float(x), tuple((float(d0), sh) for d0, sh in shapers), float(L_ref),
           float(L_band), float(alpha), float(h_a))
    try:
        found = _SEARCHES.pop(key, None)
    except TypeError:  # an input that is not a value (unhashable): searched, not kept
        return _search_law(law, m, z_H, x, shapers, L_ref, L_band, alpha, h_a)
    if found is None:
        found = _search_law(law, m, z_H, x, shapers, L_ref, L_band, alpha, h_a)
    _SEARCHES[key] = found  # the latest last
    while len(_SEARCHES) > _KEPT:
        del _SEARCHES[next(iter(_SEARCHES))]
    return found


def _search_law(law: WalkingLaw, m: float, z_H: int, x: float, shapers, L_ref: float, L_band: float,
                alpha: float, h_a: float) -> LawSearch:
    u = law.u
    pts = []
    n_eval = 0
    # the blend, its centre distance and its pitch curves (with their curvature summaries) depend on (delta, u_h)
    # alone: made once and read by every shaper that tries the same blend (about half the tries of a search)
    made: dict[tuple[float, float], tuple | None] = {}

    def blend(delta: float, q: float):
        key = (delta, q)
        if key not in made:
            try:
                sl = SmoothedWalkingLaw(law, delta, u_h=q * u)
            except InputError:
                made[key] = None
            else:
                L = math.pi * m * z_H / perimeter_per_mm(sl)
                made[key] = (sl, L, PitchCurves(sl, L))
        return made[key]

    for d0, sh in shapers:
        cutter = CutterSpec(m=m, alpha=alpha, h_a=h_a, x=x, x_H=-x, z0=sh.z0, shaper_x0=sh.x0)

        def ev(delta, q):
            nonlocal n_eval
            n_eval += 1
            b = blend(delta, q)
            if b is None:
                return None
            sl, L, pc = b
            g = check_generable(pc, cutter)
            return (sl, L, g) if g.ok and abs(L - L_ref) <= L_band else None

        for delta in np.radians(np.asarray(LAW_SEARCH_DELTA_DEG, float)):
            scan = np.asarray(LAW_SEARCH_UH_SCAN, float)
            prev, hit = None, None
            for q in scan:
                r = ev(float(delta), float(q))
                if r is not None:
                    hit = (float(q), r)
                    break
                prev = float(q)
            if hit is None:
                continue
            lo, (hi, best) = prev, hit
            if lo is not None:
                for _ in range(LAW_SEARCH_UH_BISECTIONS):
                    mid = 0.5 * (lo + hi)
                    r = ev(float(delta), mid)
                    if r is not None:
                        hi, best = mid, r
                    else:
                        lo = mid
            sl, L, g = best
            margin, binding = _margins(g)
            pts.append(LawPoint(float(d0), int(sh.z0), float(delta), float(hi), float(L),
                                float(hub_speed_ripple(sl).ripple), float(margin), binding))
    if not pts:
        d0s = ", ".join(f"{d:g}" for d, _ in shapers)
        raise InputError("L_band", L_band,
                         f"no blend keeps both pitch curves generable with |L - L_exact| <= {L_band:g} mm "
                         f"(L_exact = {L_ref:.3f} mm) for the shapers d0 = {d0s} mm at m = {m:g} mm",
                         "a larger driver_shift, more teeth or a larger band")
    rip = np.array([p.ripple for p in pts])
    fL = pareto(np.array([p.L for p in pts]), rip, larger_is_better=False)
    fM = pareto(np.array([p.margin_mm for p in pts]), rip, larger_is_better=True)
    pts = [LawPoint(**{**p.__dict__, "front_L": bool(a), "front_margin": bool(b)}) for p, a, b in zip(pts, fL, fM)]
    pts.sort(key=lambda p: (round(p.ripple, 12), -p.margin_mm, p.d0_mm, p.delta))
    return LawSearch(tuple(pts), n_eval, float(L_ref), float(L_band))
