"""Generated (conjugate) teeth of the non-circular walking-drive pair (seeds 000 and 002).

Pure math (numpy/scipy).  Millimetres, radians.  Method: Litvin & Fuentes-Aznar, *Noncircular
Gears* (2009), ch. 4 and 6; docs/architecture.md, "tooth generator".

Both pitch curves are parametrised by the driven angle phi and share ONE arc-length frame
s(phi) = integral sqrt(r_H^2 + r_H'^2) dphi (``ArcFrame``; rolling without slip: the driver's arc
over the same phi is equal; :mod:`.pitch_frame`).  An ISO 53 rack cutter (``cutters.RackCutter``) rolls on each pitch
curve (``envelope.envelope_points``: meshing equation solved in closed form per cutter point), the
driver's tool shifted by +x m, the driven wheel's by -x m (one imaginary rack between the two
centrodes: its reference line is x m off both pitch curves, so the generated pair keeps the
centre distance and is conjugate: at each instant the two tool flanks touch the gears at the same
point of the line of action through the pitch point).  Tooth k of the driver is centred at
s = k p, tooth k of the driven wheel at s = (k + 1/2) p, p = pi m: the pair is phased by
construction.  Where a pitch curve is concave (or within ``SHAPER_MARGIN_PITCHES`` pitches of a
concave stretch) the side is cut by a shaper (pinion) cutter z0 rolling on the outside of the
pitch curve with its pitch circle, profile shift x0 = -x_gear (it meshes with the same imaginary
rack, so its involute generates the same flank; only the fillet differs).  Tip and root are the
equidistants of the pitch curve at (h_a* + x) m and (h_a* + c* - x) m (the envelope of the tool's
tip land, resp. the shaper's tip circle); tips are shortened tooth by tooth where the tip land
would be thinner than a given minimum (:mod:`.tip_search`).  Undercut is detected per tooth side (cusp of the flank
envelope) and trimmed.  ``geometry.noncircular_outline`` fits and chains the pieces into a
closed outline.

Body frames (the pair's assembly frame at phi = theta = 0): the driven wheel's axis at the
origin, its pitch point of polar angle phi is the contact point when the driven wheel has
turned by -phi (clockwise); the driver's axis at its own origin (at (L, 0) in the assembly),
the pitch point of law angle theta sits at body polar angle pi - theta (contact on the line
of centres when the driver has turned by +theta, counter-clockwise).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize_scalar

from ..errors import InputError, require
from ..policy import FD_STEP_ARC_RAD, MINIMIZE_XATOL, ROOT_BRIDGE_MAX_MODULE, ROOT_XTOL_FINE
from . import tip_search
from .cutters import CutterSide, RackCutter, ShaperCutter
from .envelope import (EnvelopeCurve, ExternalCircleCentrode, PitchCurveCentrode, ShaperOnRackCentrode, envelope_points,
                       round_envelope)
from .undercut import trim_crossing
from .involute import BasicRack
from .noncircular import PitchCurves, whole_pitches
from .pitch_frame import ArcFrame, BodyPitchCurve

__all__ = [
    "ArcFrame", "BodyPitchCurve", "ToothSpec", "ToothSide", "make_side", "GeneratedTooth", "GeneratedTeeth",
    "generate_teeth", "SHAPER_MARGIN_PITCHES",
]

#: a tooth side is cut by the shaper when a concave stretch of its pitch curve lies within this
#: many pitches of the tooth centre (the rack's neighbouring teeth would gouge there)
SHAPER_MARGIN_PITCHES = 1.5


@dataclass(frozen=True)
class ToothSpec:
    """Teeth of one gear of the pair.

    m: module (mm); x: profile shift coefficient; thinning_mm: arc tooth-thickness reduction on
    the pitch curve (a normal backlash j_n split evenly is j_n / (2 cos alpha) per gear);
    rack: ISO 53 basic rack; z0: shaper teeth for concave stretches (None: none allowed);
    tip_min_mm: least tip-land thickness before the tip is shortened; tip_floor: the tip may be
    shortened down to (tip_floor + x) m above the pitch curve, else the teeth are pointed
    (InputError); tip_max_mm: the largest tip height above the pitch curve (0: none), a tip shortening of
    every tooth whose tool would cut it higher (GOST 19274's cure of tip interference in an internal mesh:
    where the mate's pitch curve is concave the tips meet the mate's teeth outside the line of action)."""

    m: float
    x: float = 0.0
    thinning_mm: float = 0.0
    rack: BasicRack = BasicRack()
    z0: int | None = None
    tip_min_mm: float = 0.0
    tip_floor: float = 0.5
    shaper: ShaperCutter | None = None
    tip_max_mm: float = 0.0

    @property
    def h_tip(self) -> float:
        return (self.rack.h_a_star + self.x) * self.m

    @property
    def h_tip_cut(self) -> float:
        """The tip height the teeth are cut to before any shortening of a pointed tip: (h_a* + x) m, at most
        ``tip_max_mm`` when that is given."""
        return min(self.h_tip, self.tip_max_mm) if self.tip_max_mm > 0 else self.h_tip

    @property
    def h_root(self) -> float:
        return (self.rack.h_fP_star - self.x) * self.m

    def rack_tools(self) -> tuple[CutterSide, CutterSide]:
        """Right (+xi, clockwise side of the tooth) and left sides of the ISO 53 rack, its space of
        width w - thinning centred at xi = 0 (``cutters.RackCutter``)."""
        ca = math.cos(self.rack.alpha)
        u_top = (1.5 * (self.rack.h_a_star + abs(self.x)) + 0.5) * self.m / ca
        return RackCutter(self.m, self.x, self.rack, self.thinning_mm).sides(u_top)

    def shaper_tools(self) -> tuple[CutterSide, CutterSide]:
        """Right and left sides of the shaper, its space centred on the bottom of its rolling
        circle; thinning widens the shaper teeth by thinning/(2 r0) of rotation per flank.

        ``shaper`` given (a catalogue cutter, ``gears.catalogue``): the shaper keeps its own x0 and
        meshes with the gear's imaginary rack from the line e = (x + x0) m above the rack's
        rolling line (``envelope.ShaperOnRackCentrode``), one flank per pass.  Otherwise a shaper
        z0 with x0 = -x rolls on the pitch curve itself (``envelope.ExternalCircleCentrode``)."""
        if self.shaper is not None:
            return self._own_shift_shaper_tools()
        require(self.z0 is not None, "z0", self.z0, "a concave pitch curve needs a shaper cutter")
        try:
            sh = ShaperCutter(int(self.z0), self.m, -self.x, self.rack)
            R0 = sh.r0
            sh.tip_round  # the tip round must fit the shaper tooth (InputError otherwise)
        except InputError as exc:
            raise InputError("z0", self.z0,
                             f"the shaper z0 = {self.z0} with x0 = {-self.x:+g} (-x of the gear it cuts) cannot be made: "
                             f"{exc}", "use a smaller profile shift (driver_shift) or another shaper") from None
        ang = -math.pi + math.pi / sh.z0 - self.thinning_mm / (2.0 * R0)
        base = sh.side(ExternalCircleCentrode(R0))
        return tuple(base.placed(ang, (0.0, R0), mir) for mir in (False, True))

    def _own_shift_shaper_tools(self) -> tuple[CutterSide, CutterSide]:
        sh = self.shaper
        require(abs(sh.m - self.m) <= 1e-9 * self.m, "m", self.m, f"must equal the shaper's module {sh.m:g} mm")
        try:
            sh.tip_round  # the tip round must fit the shaper tooth (InputError otherwise)
        except InputError as exc:
            raise InputError("z0", sh.z0, f"the shaper z0 = {sh.z0}, x0 = {sh.x0:+g} cannot be made: {exc}") from None
        R0 = sh.r0
        e = (self.x + sh.x0) * self.m
        c = e / math.tan(self.rack.alpha)
        ang = -math.pi + math.pi / sh.z0 - self.thinning_mm / (2.0 * R0)
        base = sh.side(ExternalCircleCentrode(R0))
        out = []
        for mir, cut in ((False, ShaperOnRackCentrode(R0, e, c)), (True, ShaperOnRackCentrode(R0, e, -c))):
            b = base.placed(ang, (0.0, R0), mir)
            out.append(CutterSide(b.fillet, b.fillet_range, b.flank, b.flank_range, cut, "shaper"))
        return tuple(out)


@dataclass
class ToothSide:
    """One generated side of a tooth: fillet and flank envelopes, the cutter kind ("rack" or
    "shaper"), whether the side is undercut (trimmed) and the driven angle phi_root of its root.

    root_gap_mm: distance from the fillet start to the root equidistant (0 for the rack and for a
    shaper of x0 = -x, whose tip circle generates that equidistant exactly).  A shaper with its
    own x0 cuts each flank in its own pass with its pitch point ahead of the rack's by
    c = e cot(alpha) (``envelope.ShaperOnRackCentrode``); its tip circle then generates a root a few
    hundredths of a mm off the equidistant, and phi_root is the foot of the fillet start on the
    equidistant (the outline lifts the root linearly in phi between the fillet starts of a space,
    ``geometry.noncircular_outline``)."""

    fillet: EnvelopeCurve
    flank: EnvelopeCurve
    kind: str
    undercut: bool
    phi_root: float  # driven angle of the root point (on the root equidistant) where the fillet starts
    root_gap_mm: float = 0.0
    fillet_is_flank: bool = False  # no fillet: the flank reaches the root equidistant (outline: one piece)


def _flank_has_cusp(flank: EnvelopeCurve, u1: float, n: int = 48) -> bool:
    P = flank(np.linspace(flank.u0, u1, n))
    d = np.diff(P, axis=0)
    return bool(np.any(np.einsum("ij,ij->i", d[:-1], d[1:]) < 0))


def make_side(tool: CutterSide, cen: PitchCurveCentrode, h_root: float | None = None) -> ToothSide:
    """One tooth side generated by ``tool`` on the gear centrode ``cen`` (not yet trimmed).  For a
    shaper with its own x0 (``ShaperOnRackCentrode``) and the root depth ``h_root``, phi_root is
    the foot of the fillet start on the root equidistant and root_gap_mm its distance."""
    fil, fla = tool.envelopes(cen)
    if h_root is None or not isinstance(tool.cutter, ShaperOnRackCentrode) or tool.cutter.e == 0.0:
        _, s0 = envelope_points(tool.fillet, np.array([fil.u0]), tool.cutter, cen)
        return ToothSide(fil, fla, tool.kind, False, float(cen.phi(s0)[0]))
    # re-phased shaper: the tip round's envelope followed in the rolling arc from the involute
    a_tip, a_flank = tool.fillet_range
    fil = round_envelope(tool.fillet, a_tip, a_flank, tool.fillet.piece.rho, tool.cutter, cen)
    ph0 = float(cen.phi(np.array([fil.u0]))[0])
    curve = cen.curve
    span = 4.0 * abs(tool.cutter.c) / float(cen.frame.pc.ds_dphi(np.array([ph0]))[0]) + FD_STEP_ARC_RAD
    grid = ph0 + np.linspace(-span, span, 201)
    E = curve.offset(grid, -h_root)

    def foot(X):
        """(phi of the foot on the root equidistant, signed height of X above it)."""
        j = int(np.clip(np.argmin(np.linalg.norm(E - X[None, :], axis=1)), 1, len(grid) - 2))
        dist = lambda ph: float(np.linalg.norm(curve.offset(np.array([ph]), -h_root)[0] - X))
        ph = float(minimize_scalar(dist, bounds=(grid[j - 1], grid[j + 1]), method="bounded",
                                   options={"xatol": MINIMIZE_XATOL}).x)
        F = curve.offset(np.array([ph]), -h_root)[0]
        return ph, float(np.dot(X - F, curve.normal(np.array([ph]))[0]))

    def heights_of(P):
        """``foot``'s heights of many points at once, where only their signs decide (which samples lie above the
        equidistant)."""
        return curve.heights(P, -h_root, grid, E)

    # the tip circle of a re-phased shaper digs below the equidistant: the fillet is trimmed where it
    # crosses it (the outline keeps the equidistant, a little more material than cut); where it
    # stays above, the gap is bridged
    u = np.linspace(fil.u0, fil.u1, 64)
    heights = heights_of(fil(u))
    if heights[0] < 0.0 and np.any(heights > 0.0):
        k = int(np.argmax(heights > 0.0))
        from scipy.optimize import brentq

        uc = brentq(lambda t: foot(fil.at(t))[1], u[k - 1], u[k], xtol=ROOT_XTOL_FINE)
        fil = fil.with_range(uc, fil.u1)
        ph, h = foot(fil.at(uc))
        return ToothSide(fil, fla, tool.kind, False, ph, abs(h))
    if heights[-1] < 0.0:
        # the whole round lies below the equidistant (the re-phased shaper digs deeper there): the flank
        # is trimmed where it crosses the equidistant, its first hundredth standing in for the fillet
        uf = np.linspace(fla.u0, fla.u1, 64)
        hf = heights_of(fla(uf))
        up = np.nonzero(hf > 0.0)[0]
        if len(up) and up[0] > 0:
            k = int(up[0])
            from scipy.optimize import brentq

            uc = brentq(lambda t: foot(fla.at(t))[1], uf[k - 1], uf[k], xtol=ROOT_XTOL_FINE)
            um = uc + 0.01 * (fla.u1 - uc)
            ph, h = foot(fla.at(uc))
            return ToothSide(fla.with_range(uc, um), fla.with_range(um, fla.u1), tool.kind, False, ph, abs(h),
                             fillet_is_flank=True)
    # otherwise the round starts above the equidistant: the outline bridges the gap from its start straight down
    # to its foot (root_gap_mm, refused by generate_teeth above ROOT_BRIDGE_MAX_MODULE m).  (Following the
    # shaper's tip circle on from the round was tried and never taken: its envelope runs back over the round at
    # the junction (a cusp) on every part built; seed 002's re-phased shaper after 2 of 161 samples.)
    ph, h = foot(fil.at(fil.u0))
    return ToothSide(fil, fla, tool.kind, False, ph, abs(h))


def _trim_undercut(side: ToothSide, u_tip: float) -> None:
    """Undercut per tooth: the flank envelope below the tip turns back
    (cusp) and the fillet trochoid crosses it; keep the outer boundary (``trim_crossing``)."""
    if side.fillet_is_flank or not _flank_has_cusp(side.flank, u_tip):
        return
    cross = trim_crossing(side.fillet, side.flank.with_range(side.flank.u0, u_tip))
    if cross is not None:
        side.fillet = side.fillet.with_range(side.fillet.u0, cross[0])
        side.flank = side.flank.with_range(cross[1], side.flank.u1)
        side.undercut = True


@dataclass
class GeneratedTooth:
    s_centre: float
    phi_centre: float
    right: str
    left: str
    undercut: bool
    tip_height_mm: float
    tip_thickness_mm: float
    shortened: bool

@dataclass
class GeneratedTeeth:
    """The generated teeth of one gear before fitting: per tooth its two sides (right, left:
    ``ToothSide``), its tip (height h, (u, phi) of the right and left flank ends) and its record."""

    role: str
    curve: BodyPitchCurve
    z: int
    n: int
    sides: list
    tips: list
    teeth: list
    #: the wheel cut as one lobe (``generate_teeth(..., lobe=True)``): ``sides`` and ``tips`` are those of its first
    #: ``z // lobes`` teeth, tooth k + j z / lobes being tooth k turned by j lobes; 1: every tooth's own
    lobes: int = 1


def _concave_zones(curve: BodyPitchCurve) -> list[tuple[float, float]]:
    """Concave stretches of the pitch curve as intervals of the driven angle (all periods (legs) of
    the law over one turn, with one more on each side)."""
    side = "driven" if curve.role == "driven" else "driver"
    cs = curve.pc.curvature(side)
    law = curve.pc.law
    P = law.period
    out = []
    for a, b in cs.concave_intervals:
        for k in range(-1, law.periods + 2):
            out.append((a + k * P, b + k * P))
    return out


def generate_teeth(pc: PitchCurves, role: str, spec: ToothSpec, frame: ArcFrame | None = None,
                   tick=None, lobe: bool = False) -> GeneratedTeeth:
    """Generated teeth on the pitch curve of one gear of the pair (see the module docstring):
    every tooth side generated and trimmed, every tip placed (shortened where too thin).  ``tick(done, z)``, when
    given, is told each tooth whose two sides are generated (progress only).

    Teeth: driven z_H = perimeter / (pi m), centres at s = (k + 1/2) p; driver z = z_H / n,
    centres at s = k p (k = 0 .. z-1 covers the driver's first turn, phi in [0, 2 pi / n)).

    ``lobe``: a wheel of equal lobes is cut as one.  The law's ratio U = theta' repeats every period P = 2 pi /
    ``periods`` of phi (``laws.law``), so the driven pitch curve (r_H = L U / (1 + U); seed 000 eq. 3) has
    ``periods`` lobes, and the driver's, whose theta advances 2 pi n / periods a period, periods / n lobes a turn.
    The arc of a period holds z_H / periods pitches, so when that is whole, tooth k + j z / lobes is tooth k turned
    by one lobe j times (the driven wheel on, the driver back: its body angle is pi - theta): the sides and tips of
    the first z / lobes teeth are generated (``GeneratedTeeth.lobes``), every tooth's record kept (its own s and
    phi, its lobe tooth's kinds, tip and thickness).  Cut so, the wheel repeats
    exactly, as the pair's one-period proofs take it to (``parts.noncircular_pair.as_built.period_span``); each
    tooth cut on its own repeats to within the B-spline fits' tolerance.  A refusal names the same first tooth
    either way (a tooth that fails has its like in the first lobe, nearer phi = 0)."""
    frame = frame or ArcFrame(pc)
    curve = BodyPitchCurve(pc, role)
    m = spec.m
    p = math.pi * m
    n = pc.law.n
    z_H = whole_pitches(frame.perimeter, m)
    if role == "driven":
        z, centres = z_H, (np.arange(z_H) + 0.5) * p
    else:
        require(z_H % n == 0, "z_H", z_H, f"must be a multiple of n = {n}")
        z, centres = z_H // n, np.arange(z_H // n) * p
    phic = frame.phi(centres)
    # the wheel's equal lobes (laws.law: the driven curve has ``periods``, the driver's repeats every n periods)
    lobes = pc.law.periods // (1 if role == "driven" else n) if lobe else 1
    if lobes < 1 or z % lobes:
        lobes = 1
    z_cut = z // lobes  # the teeth generated: one lobe's, or every tooth
    span = 1.5 * p / float(np.min(pc.ds_dphi(np.linspace(0, math.pi / 2, 200))))  # phi of 1.5 pitches
    zones = _concave_zones(curve)
    rack_r, rack_l = spec.rack_tools()
    shaper = None
    teeth_sides = []
    for s_k, ph_k in zip(centres[:z_cut], phic[:z_cut]):
        sides = []
        for which, rack_tool in ((0, rack_r), (1, rack_l)):
            tool = rack_tool
            if zones:
                margin = SHAPER_MARGIN_PITCHES * p
                for a, b in zones:
                    sa_, sb_ = frame.s(np.array([a, b]))
                    if sa_ - margin <= s_k <= sb_ + margin:
                        if shaper is None:
                            shaper = spec.shaper_tools()
                        tool = shaper[which]
                        break
            side = make_side(tool, PitchCurveCentrode(curve, frame, s_k), spec.h_root)
            if side.root_gap_mm > ROOT_BRIDGE_MAX_MODULE * m:
                raise InputError("z0", int(round(tool.cutter.R * 2.0 / m)),
                                 f"{role} tooth at phi = {float(frame.phi(np.array([s_k]))[0]):.4f} rad: the re-phased "
                                 f"shaper leaves its fillet {side.root_gap_mm:.3f} mm off the root (more than "
                                 f"{ROOT_BRIDGE_MAX_MODULE:g} m)", "a larger shaper or a wider blend")
            sides.append(side)
        teeth_sides.append(sides)
        if tick is not None:
            tick(len(teeth_sides), z_cut)

    # tips: nominal height, shortened where the tip land is too thin
    teeth, tips = [], []
    flat = [sd for pair in teeth_sides for sd in pair]
    h_cut = spec.h_tip_cut
    nominal = tip_search.tip_hits_batch(flat, np.repeat(centres[:z_cut], 2), np.repeat(phic[:z_cut], 2), curve, frame,
                                        h_cut, span)
    for k, ((s_k, ph_k), (R, Lf)) in enumerate(zip(zip(centres, phic), teeth_sides)):
        thickness = tip_search.ToothLand(R, Lf, curve, frame, s_k, ph_k, span, h_cut,
                                         (nominal[2 * k], nominal[2 * k + 1]))
        h = h_cut
        t, hr, hl = thickness(h)
        shortened = False
        if t < spec.tip_min_mm:
            # tip shortening: the largest height (bisection to 1 nm) with a tip land >= the minimum
            h_lo = (spec.tip_floor + spec.x) * m
            t_lo, hr_lo, hl_lo = thickness(h_lo)
            if not t_lo >= spec.tip_min_mm:
                why = (f"the {'shaper' if 'shaper' in (R.kind, Lf.kind) else 'rack'} flank envelope does not reach "
                       f"{spec.tip_floor + spec.x:.2f} m above the pitch curve (generating limit of the cutter)"
                       if hr_lo is None or hl_lo is None else
                       f"tip land {max(t_lo, 0.0):.3f} mm < {spec.tip_min_mm:.3f} mm even with the tip shortened to "
                       f"{spec.tip_floor + spec.x:.2f} m")
                raise InputError(
                    "m", m, f"{role} tooth at phi = {ph_k:.4f} rad is pointed or cannot be cut: {why}",
                    "use a smaller profile shift, a larger shaper, more teeth or a wider smoothing")
            h, (t, hr, hl) = tip_search.tallest_tip(thickness, h_lo, (t_lo, hr_lo, hl_lo), h, (t, hr, hl),
                                                    spec.tip_min_mm,
                                                    lambda: tip_search.flank_reach((R, Lf), curve, ph_k, span))
            shortened = True
        _trim_undercut(R, hr[0])
        _trim_undercut(Lf, hl[0])
        tips.append((h, hr, hl))
        teeth.append(GeneratedTooth(float(s_k), float(ph_k), R.kind, Lf.kind, R.undercut or Lf.undercut,
                                    float(h), float(t), shortened))
    # the other lobes' records: each tooth at its own centre, cut as its lobe tooth
    teeth += [dataclasses.replace(teeth[k % z_cut], s_centre=float(centres[k]), phi_centre=float(phic[k]))
              for k in range(z_cut, z)]
    return GeneratedTeeth(role, curve, z, n, teeth_sides, tips, teeth, lobes)
