"""Generability of the non-circular pitch curves and the choice of the law's smoothing.

Pure math (numpy/scipy).  A pitch curve is generable by the ISO 53 rack where it is convex with
radius of curvature rho >= (h_a* - x) m / sin^2 alpha (rack undercut limit), and by a shaper of
pitch radius r0 < |rho| where it is concave (docs/architecture.md, "non-circular pair").  The
smoothing of the law near hand-over (``noncircular.SmoothedWalkingLaw``) is the smallest blend
half-width delta that keeps both pitch curves generable; the centre distance follows from closure
at each delta (L = pi m z_H / perimeter); its price is the hub speed ripple.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, require, require_finite, require_positive
from ..laws.walking import HubSpeedRipple, WalkingLaw, check_n_closes
from ..policy import SMOOTHING_DELTA_MIN_RAD, SMOOTHING_DELTA_RTOL
from .involute import BasicRack
from .noncircular import (DELTA_MAX_DEFAULT, CurvatureSummary, PitchCurves, SmoothedWalkingLaw, hub_speed_ripple,
                          perimeter_per_mm, whole_teeth)
from .noncircular_teeth import ToothSpec

#: the fewest teeth of a shaper cutter (``cutters.ShaperCutter`` refuses fewer)
SHAPER_TEETH_MIN = 6

__all__ = ["CutterSpec", "CurveCheck", "Generability", "check_generable", "SmoothingDesign", "choose_smoothing"]


@dataclass(frozen=True)
class CutterSpec:
    """Generating tools: ISO 53 rack (alpha, h_a*) with profile shifts, optional shaper.

    m: module (mm); alpha: pressure angle (rad); h_a: addendum coefficient h_a*
    of the generated tooth; x: profile shift coefficient of the driver, x_H of
    the driven wheel; z0: tooth count of a shaper (pinion) cutter for concave
    parts (None: no shaper, concave parts are not allowed); shaper_x0: the shaper's own
    profile shift (a catalogue cutter; None: x0 = -x of the gear it cuts).  A shaper of own x0
    rolls on the equidistant of the pitch curve at e = (x + x0) m, whose concave radius is
    |rho| - e: it cuts there when r0 < |rho| - e.
    """

    m: float
    alpha: float = math.radians(20.0)
    h_a: float = 1.0
    x: float = 0.0
    x_H: float = 0.0
    z0: int | None = None
    shaper_x0: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "m", require_positive("m", self.m, "mm"))
        a = require_finite("alpha", self.alpha)
        if not 0 < a < math.pi / 2:
            raise InputError("alpha", self.alpha, "pressure angle must be in (0, pi/2) rad")
        object.__setattr__(self, "h_a", require_positive("h_a", self.h_a))
        object.__setattr__(self, "x", require_finite("x", self.x))
        object.__setattr__(self, "x_H", require_finite("x_H", self.x_H))
        if self.z0 is not None:
            z0 = require_finite("z0", self.z0)
            if z0 != round(z0) or z0 < SHAPER_TEETH_MIN:
                raise InputError("z0", self.z0,
                                 f"shaper cutter tooth count must be a whole number >= {SHAPER_TEETH_MIN}")
            object.__setattr__(self, "z0", int(round(z0)))

    def rho_limit(self, x: float) -> float:
        """Rack undercut limit rho >= (h_a* - x) m / sin^2 alpha (docs/architecture.md, «non-circular pair»)."""
        return (self.h_a - x) * self.m / math.sin(self.alpha) ** 2

    @property
    def r0(self) -> float:
        """Shaper cutter pitch radius m z0 / 2 (inf if no shaper)."""
        return math.inf if self.z0 is None else self.m * self.z0 / 2

    def shaper_offset(self, x: float) -> float:
        """Height e = (x + x0) m of the shaper's rolling circle above the pitch curve of a gear of
        shift x (``envelope.ShaperOnRackCentrode``); 0 when the shaper's x0 is tied to -x."""
        return 0.0 if self.shaper_x0 is None else (x + self.shaper_x0) * self.m

    def shift(self, role: str) -> float:
        """Profile shift of one gear of the pair: x of the driver, x_H of the driven wheel."""
        require(role in ("driver", "driven"), "role", role, "must be 'driver' or 'driven'")
        return self.x if role == "driver" else self.x_H

    def tooth_spec(self, role: str, rack: BasicRack, thinning_mm: float = 0.0, tip_min_mm: float = 0.0) -> ToothSpec:
        """The teeth these tools cut on one gear of the pair (``noncircular_teeth.ToothSpec``)."""
        return ToothSpec(m=self.m, x=self.shift(role), thinning_mm=thinning_mm, rack=rack, z0=self.z0,
                         tip_min_mm=tip_min_mm)


@dataclass(frozen=True)
class CurveCheck:
    """Generability of one pitch curve."""

    curve: str
    rho_convex_min: float
    rho_limit: float
    concave: bool
    rho_concave_min: float
    r0: float  #: radius the concave stretch must exceed: shaper r0 plus its cutting offset e
    ok: bool
    reason: str


def _check_curve(cs: CurvatureSummary, cutter: CutterSpec, x: float) -> CurveCheck:
    lim = cutter.rho_limit(x)
    e = cutter.shaper_offset(x)
    reasons = []
    if cs.rho_convex_min < lim:
        reasons.append(f"{cs.curve}: convex rho_min {cs.rho_convex_min:.3f} mm < rack undercut limit {lim:.3f} mm")
    if cs.concave:
        if cutter.z0 is None:
            reasons.append(f"{cs.curve}: concave (|rho| >= {cs.rho_concave_min:.3f} mm) and no shaper cutter z0 given")
        elif not cutter.r0 + e < cs.rho_concave_min:
            reasons.append(f"{cs.curve}: concave |rho|_min {cs.rho_concave_min:.3f} mm <= shaper pitch radius "
                           f"{cutter.r0:.3f} mm" + (f" + cutting offset {e:+.3f} mm" if e else ""))
    return CurveCheck(curve=cs.curve, rho_convex_min=cs.rho_convex_min, rho_limit=lim, concave=cs.concave,
                      rho_concave_min=cs.rho_concave_min, r0=cutter.r0 + e, ok=not reasons,
                      reason="; ".join(reasons))


@dataclass(frozen=True)
class Generability:
    driver: CurveCheck
    driven: CurveCheck

    @property
    def ok(self) -> bool:
        return self.driver.ok and self.driven.ok


def check_generable(pair: PitchCurves, cutter: CutterSpec) -> Generability:
    """Both pitch curves against the rack undercut limit (convex) and shaper / concavity (concave)."""
    return Generability(
        driver=_check_curve(pair.curvature("driver"), cutter, cutter.x),
        driven=_check_curve(pair.curvature("driven"), cutter, cutter.x_H),
    )


@dataclass(frozen=True)
class SmoothingDesign:
    """The chosen smoothing: law, centre distance, checks and the price (hub speed ripple)."""

    law: SmoothedWalkingLaw
    delta: float
    L: float
    z_H: int
    z: int
    cutter: CutterSpec
    generability: Generability
    ripple: HubSpeedRipple

    @property
    def pair(self) -> PitchCurves:
        return PitchCurves(self.law, self.L)

    @property
    def closure_error(self) -> float:
        """|theta_s(2 pi) - 2 pi n| (rad)."""
        return abs(float(self.law.theta(2 * math.pi)) - 2 * math.pi * self.law.n)


def _evaluate(law: WalkingLaw, delta: float, cutter: CutterSpec, z_H: int):
    """The smoothed law, its centre distance and generability at one half-width.  The blend of a walking law
    stays at or above u (U = u + K sin 2|t| >= u, and the blend of U, U', U'' and the window's integral keeps
    p >= u: 18 888 random laws and half-widths, least p/u 1.000003), so SmoothedWalkingLaw never refuses here."""
    sl = SmoothedWalkingLaw(law, delta)
    L = math.pi * cutter.m * z_H / perimeter_per_mm(sl)
    return sl, L, check_generable(PitchCurves(sl, L), cutter)


def choose_smoothing(law: WalkingLaw, cutter: CutterSpec, z_H: int,
                     delta_max: float = DELTA_MAX_DEFAULT,
                     rtol: float = SMOOTHING_DELTA_RTOL, limits: dict | None = None,
                     keys: dict | None = None) -> SmoothingDesign:
    """Smallest blend half-width delta <= delta_max keeping both pitch curves generable.

    The centre distance follows from closure at each delta: L = pi m z_H / perimeter.
    Search: geometric scan of delta, then bisection to rtol between the last
    failing and the first passing delta.  Raises InputError with the numbers
    (curvature reached, limit, the profile shift / tooth count / smoothing that
    would work, within `limits`: :func:`remedies`) when no delta up to delta_max works.
    """
    if not isinstance(law, WalkingLaw):
        raise InputError("law", law, "must be a WalkingLaw")
    check_n_closes(law.n)
    z_H = whole_teeth("z_H", z_H, law.n)
    delta_max = require_positive("delta_max", delta_max, "rad")
    if delta_max > math.pi / 4:
        raise InputError("delta_max", delta_max, f"must be <= pi/4 = {math.pi / 4:.6f} rad")
    grid = np.geomspace(SMOOTHING_DELTA_MIN_RAD, delta_max, 40)
    prev_bad = None
    found = None
    for d in grid:
        sl, L, g = _evaluate(law, float(d), cutter, z_H)
        if g.ok:
            found = float(d)
            break
        prev_bad = float(d)
    if found is None:
        raise _no_smoothing_error(law, cutter, z_H, delta_max, limits, keys)
    lo, hi = prev_bad, found
    # generable at the search's least half-width (a law without a corner, or a mild one): that one (bisecting
    # towards 0 would never end: every narrower blend is generable too)
    while lo is not None and hi - lo > rtol * hi:
        mid = 0.5 * (lo + hi)
        sl, L, g = _evaluate(law, mid, cutter, z_H)
        if g.ok:
            hi = mid
        else:
            lo = mid
    sl, L, g = _evaluate(law, hi, cutter, z_H)
    return SmoothingDesign(law=sl, delta=hi, L=L, z_H=z_H, z=z_H // law.n, cutter=cutter,
                           generability=g, ripple=hub_speed_ripple(sl))


def _no_smoothing_error(law, cutter, z_H, delta_max, limits=None, keys=None) -> InputError:
    """`keys`: the part's names of the quantities (:func:`remedies`; "delta": the blend's half-width key, in deg)."""
    keys = keys or {}
    sl, L, g = _evaluate(law, delta_max, cutter, z_H)
    bits = remedies(g, cutter, z_H, law.n, L, limits, keys)
    # the smallest smoothing that would work beyond delta_max
    more = ""
    if delta_max < math.pi / 4:
        for d in np.linspace(delta_max, math.pi / 4, 25)[1:]:
            s, LL, gg = _evaluate(law, float(d), cutter, z_H)
            if gg.ok:
                more = (f"; {keys['delta']} >= {math.degrees(d):.2f} would work" if "delta" in keys
                        else f"; delta = {d:.4f} rad would work")
                break
        else:
            more = "; no delta up to pi/4 works"
    return InputError("delta_max", delta_max,
                      "no blend half-width up to delta_max makes both pitch curves generable",
                      " | ".join(bits) + more)


def remedies(g: Generability, cutter: CutterSpec, z_H: int, n: int, L: float, limits: dict | None = None,
             keys: dict | None = None) -> list[str]:
    """What would make each failing pitch curve generable: the profile shift, the teeth or the module
    (convex stretches against the rack undercut limit), the shaper's teeth (concave stretches).

    `limits`: {"x": (lo, hi), "x_H": …, "z_H": …, "m": …, "z0": …}, the ranges the part's parameters allow;
    a remedy outside its range (or not a finite number) is not offered, and when none is left the text says
    that no value within the limits works.  `keys`: the names a part file gives these quantities
    ({"x": "driver_shift", "x_H": "-driver_shift", "z_H": "driven_teeth", "m": "module_mm", "z0": "shaper_teeth"};
    a leading "-" is the negative of that key, so x_H >= v reads driver_shift <= -v); None: the symbols."""
    limits = limits or {}
    keys = keys or {}

    def at_least(name, v, fmt):
        """`name >= v` in the part's key (its negative turned round)."""
        key = keys.get(name, name)
        if key.startswith("-"):
            return f"{key[1:]} <= {format(-v, fmt)}"
        return f"{key} >= {format(v, fmt)}"

    def key(name):
        return keys.get(name, name)

    def within(name, v):
        lo, hi = limits.get(name, (-math.inf, math.inf))
        return v is not None and math.isfinite(v) and lo <= v <= hi

    bits = []
    s2 = math.sin(cutter.alpha) ** 2
    for chk, x, name in ((g.driver, cutter.x, "x"), (g.driven, cutter.x_H, "x_H")):
        if chk.ok:
            continue
        if chk.rho_convex_min < chk.rho_limit:
            head = f"{chk.curve}: convex rho_min {chk.rho_convex_min:.3f} mm < undercut limit {chk.rho_limit:.3f} mm"
            options = []
            if chk.rho_convex_min > 0:
                x_need = cutter.h_a - chk.rho_convex_min * s2 / cutter.m
                # rho and L scale with z_H at fixed m: z_H >= z_H * limit / rho_min
                z_need = math.ceil(z_H * chk.rho_limit / chk.rho_convex_min / n) * n
                m_max = chk.rho_convex_min * s2 / (cutter.h_a - x) if cutter.h_a > x else math.inf
                if within(name, x_need):
                    options.append(at_least(name, x_need, ".3f"))
                if within("z_H", z_need):
                    options.append(f"{key('z_H')} >= {z_need} at {key('m')} = {cutter.m:g}")
                if within("m", m_max) and m_max > 0:
                    options.append(f"{key('m')} <= {m_max:.4g} mm at L = {L:.3f} mm")
            if options:
                bits.append(f"{head}; works with {', or '.join(options)}")
            else:
                bits.append(f"{head}; no profile shift, tooth count or module within their limits makes it "
                            "generable (a smoother law)")
        if chk.concave and not chk.r0 < chk.rho_concave_min:
            # the shaper rolls on the equidistant at e = (x + x0) m: it cuts where r0 = m z0 / 2 < |rho| - e
            e = cutter.shaper_offset(x)
            fits = "r0 < |rho|" + (f" - e, e = {e:+.3f} mm" if e else "")
            z0_max = math.ceil(2 * (chk.rho_concave_min - e) / cutter.m) - 1
            if within("z0", z0_max) and z0_max >= SHAPER_TEETH_MIN:
                bits.append(f"{chk.curve}: concave |rho|_min {chk.rho_concave_min:.3f} mm needs a shaper with "
                            f"{key('z0')} <= {z0_max} ({fits})")
            else:
                bits.append(f"{chk.curve}: concave |rho|_min {chk.rho_concave_min:.3f} mm: no shaper within the "
                            f"limits fits inside it ({fits}; a smoother law)")
    return bits
