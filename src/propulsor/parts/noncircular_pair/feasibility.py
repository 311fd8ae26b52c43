"""The non-circular pair's own feasibility: every refusal of its inputs that needs no outline (generability of
the given or smallest blend, the law search within its band, the catalogue shaper at the module and the one a
concave stretch needs, the sector teeth's tip land, the installed centre distance; a law without corners through
:func:`.smooth_law.screen_smooth`).  One module that both the dry run (``parts.vet``, through the part type's
``feasible``) and the design (:mod:`.design`) call, below both; the design reuses its result
(``pipeline.design_of``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...errors import InputError, input_names
from ...gears.generability import CutterSpec, SmoothingDesign, check_generable, choose_smoothing
from ...gears.noncircular import PitchCurves, SmoothedWalkingLaw, hub_speed_ripple, perimeter_per_mm
from ...gears.sectors import sector_radii, sector_table
from ...laws.law import is_walking
from ...laws.walking import WalkingLaw
from .cutting import TOOTH_KEYS, TOOTH_KEYS_D0, law_of, mounting_fits, rack_of, shaper_of, thinning
from .params import NoncircularPairParams

__all__ = ["Screen", "screen", "screened", "feasible", "sector_design_table"]


def _smoothing(p, law: WalkingLaw, m: float):
    """The blend: given (smoothing_deg > 0) or the smallest generable (choose_smoothing)."""
    sh = shaper_of(p, m)
    cutter = CutterSpec(m=m, alpha=math.radians(p.pressure_angle_deg), x=p.driver_shift, x_H=-p.driver_shift,
                        z0=p.shaper_teeth if sh is None else sh.z0, shaper_x0=None if sh is None else sh.x0)
    z_H = p.driven_teeth
    if p.smoothing_deg > 0:
        with input_names({"u_h": "blend_hand_over"}):
            sl = SmoothedWalkingLaw(law, math.radians(p.smoothing_deg),
                                    u_h=p.blend_hand_over * law.u if p.blend_hand_over > 0 else None)
        L = math.pi * m * z_H / perimeter_per_mm(sl)
        g = check_generable(PitchCurves(sl, L), cutter)
        if not g.ok:
            best = _smallest_generable(law, cutter, z_H)
            raise InputError("smoothing_deg", p.smoothing_deg, "the pitch curves are not generable with this blend: "
                             + "; ".join(c.reason for c in (g.driver, g.driven) if not c.ok), best)
        return SmoothingDesign(law=sl, delta=sl.delta, L=L, z_H=z_H, z=z_H // law.n, cutter=cutter,
                               generability=g, ripple=hub_speed_ripple(sl))
    try:
        from .smooth_law import PART_KEYS, generability_limits

        return choose_smoothing(law, cutter, z_H, delta_max=math.radians(p.smoothing_max_deg),
                                limits=generability_limits(p), keys={**PART_KEYS, "delta": "smoothing_max_deg"})
    except InputError as exc:
        best = _smallest_generable(law, cutter, z_H) if p.smoothing_max_deg < 45.0 else "no blend up to 45 deg works"
        raise InputError(
            "smoothing_max_deg", p.smoothing_max_deg,
            f"no C2 smoothing up to {p.smoothing_max_deg:g} deg keeps both pitch curves generable: "
            f"{str(exc).split(': ', 1)[-1]}",
            best) from None


def _smallest_generable(law, cutter, z_H) -> str:
    try:
        d = choose_smoothing(law, cutter, z_H, delta_max=math.pi / 4)
    except InputError as exc:
        return "no blend up to 45 deg works either"
    return (f"a blend of {math.degrees(d.delta):.3f} deg would work "
            f"(smoothing_max_deg >= {math.degrees(d.delta):.3f}; hub speed ripple {100 * d.ripple.ripple:.2f} %)")


@dataclass(frozen=True)
class Screen:
    """What the design settles before any outline is made (:func:`screen`): the module, the blend and the
    catalogue shaper (generated teeth), the ranked points of the law search, the sector table."""

    m: float
    smoothing: object = None  # SmoothingDesign (generated, no law search)
    shaper: object = None     # the shaper of ``shaper_of`` (None: shaper_teeth with x0 = -x)
    search: object = None     # gears.law_search.LawSearch (law_search = true)
    entries: tuple = ()       # catalogue.ShaperEntry at the module (law_search = true)
    sector: tuple = ()        # (SectorTable, L, m) of the sector method
    smooth: object = None     # smooth_law.SmoothScreen of a law without corners


def screen(p: NoncircularPairParams, source=None) -> Screen:
    """Every refusal of the inputs that needs no outline: the generability screen (rack undercut limit,
    shaper against concave stretches) of the given or smallest blend, the law search within
    center_distance_band_mm, the catalogue shaper at the module, the shaper the concave stretches need, the
    sector teeth's tip land, the installed centre distance.  ``propulsor build --dry-run`` runs it (so a file
    it calls valid is not refused later for these), and the build uses its result (``pipeline.design_of``).
    A law without corners is screened by ``smooth_law.screen_smooth`` (its files relative to ``source``)."""
    law = law_of(p, source)
    if not is_walking(law):
        from .smooth_law import screen_smooth

        scr = screen_smooth(p, law)
        return Screen(scr.m, smooth=scr)
    if p.method == "sectors":
        return _screen_sectors(p)
    rack_of(p)
    if p.law_search:
        return _screen_search(p, law)
    m = p.module_mm if p.module_mm > 0 else 1.0
    sm = _smoothing(p, law, m)
    if p.center_distance_mm > 0:  # module from L: the design is scale invariant (rho and limits ~ m)
        m *= p.center_distance_mm / sm.L
        sm = _smoothing(p, law, m)  # the blend reads the module it is given, never the file's module or L
    sh = shaper_of(p, m)
    common = dict(m=m, thinning_mm=thinning(p), rack=rack_of(p), z0=p.shaper_teeth if sh is None else sh.z0,
                  tip_min_mm=p.tip_land_min_module * m, shaper=sh,
                  tip_max_mm=p.tip_height_max_module * m)
    from ...gears.noncircular_teeth import ToothSpec

    g = sm.generability
    with input_names(TOOTH_KEYS if sh is None else TOOTH_KEYS_D0):
        for chk, x in ((g.driver, p.driver_shift), (g.driven, -p.driver_shift)):
            if chk.concave:  # the shaper this gear needs must exist
                ToothSpec(x=x, **common).shaper_tools()
    mounting_fits(p, sm.L)
    return Screen(m, smoothing=sm, shaper=sh)


def _screen_search(p: NoncircularPairParams, law: WalkingLaw) -> Screen:
    """The law search's refusals: no module, no catalogue shaper at it, no generable blend within the band."""
    from ...gears.catalogue import shaper_diameters, shaper_entry
    from ...gears.law_search import search_law
    from ...gears.noncircular import centre_distance

    if not p.module_mm > 0:
        raise InputError("module_mm", p.module_mm, "the law search needs the module (catalogue cutters)")
    m = p.module_mm
    alpha = math.radians(p.pressure_angle_deg)
    entries = []
    for d0 in shaper_diameters():
        try:
            entries.append(shaper_entry(d0, m))
        except InputError:
            continue
    if not entries:
        raise InputError("module_mm", m, "the cutter catalogue lists no shaper at this module")
    L_ref = centre_distance(law, m, p.driven_teeth)
    with input_names({"L_band": "center_distance_band_mm"}):
        res = search_law(law, m, p.driven_teeth, p.driver_shift, [(e.d0_mm, e.cutter(alpha)) for e in entries], L_ref,
                         p.center_distance_band_mm, alpha)
    mounting_fits(p, min(q.L for q in res.points))  # the candidate built has one of these L
    return Screen(m, search=res, entries=tuple(entries))


def _screen_sectors(p: NoncircularPairParams) -> Screen:
    """The sector method's refusals: radii, pointed tips, the installed centre distance."""
    from ...gears.sectors import sector_tip_thickness

    table, L, m = sector_design_table(p)
    sector_radii(table, m)
    t_drv, t_dvn = sector_tip_thickness(table, m, p.backlash_mm)
    if not min(t_drv, t_dvn) > 0:
        m_ok = _largest_sector_module(table, p.backlash_mm, m)
        raise InputError("module_mm", m,
                         f"sector teeth are pointed at the tip: tip land {min(t_drv, t_dvn):.3f} mm <= 0 "
                         f"(driver {t_drv:.3f}, driven {t_dvn:.3f} mm) at L = {L:.4f} mm",
                         f"the largest module with a tip land > 0 at this L is {m_ok:.4f} mm")
    mounting_fits(p, L)
    return Screen(m, sector=(table, L, m))


def screened(p: NoncircularPairParams, source=None) -> Screen:
    """:func:`screen` once per parameter values (the dry run's result is the build's); a law read from a
    file is screened once per part file ``source`` too."""
    from ..pipeline import design_of

    if p.law in ("table", "pitch_curve"):
        return design_of(p, screen, None if source is None else str(source))
    return design_of(p, screen)


def sector_design_table(p: NoncircularPairParams):
    """(SectorTable, L, m) of the papers' method for these parameters: L given, or from the
    module so that the sector arc r_Hk dphi_k is pi m (the arcs are linear in L)."""
    law = law_of(p)
    i = p.driven_teeth // 4
    m = p.module_mm
    if p.center_distance_mm > 0:
        L = p.center_distance_mm
    else:
        L = math.pi * m / sector_table(law, 1.0, i).arc
    return sector_table(law, L, i), L, m


def _largest_sector_module(table, j_n, m_hi) -> float:
    from ...gears.sectors import sector_tip_thickness

    lo, hi = 0.0, m_hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if min(sector_tip_thickness(table, mid, j_n)) > 0:
            lo = mid
        else:
            hi = mid
    return lo


def _candidate_curves(p: NoncircularPairParams, scr: Screen) -> list:
    """The pitch curves of every blend the law search ranked (the design builds one of them)."""
    law = law_of(p)
    return [PitchCurves(SmoothedWalkingLaw(law, pt.delta, u_h=pt.u_h_rel * law.u), pt.L) for pt in scr.search.points]


def feasible(p: NoncircularPairParams, source=None) -> None:
    """The part type's feasibility (``parts.vet``): :func:`screened`, its result kept for the design; a bore the part
    file gives that surely reaches the root (``bores.check_given_on_pitch_curves``, where the screen settles the pitch
    curves: a law without corners, the walking law's given or smallest blend, every blend the law search ranked), or
    that reaches the sector method's cut root (its outlines are quick: the build's own check on them)."""
    from .bores import check_given_on_pitch_curves

    scr = screened(p, source)
    if scr.smooth is not None:
        check_given_on_pitch_curves(p, scr.smooth.pc, scr.smooth.m)
    elif scr.smoothing is not None:
        check_given_on_pitch_curves(p, PitchCurves(scr.smoothing.law, scr.smoothing.L), scr.m)
    elif scr.search is not None and (p.driver_bore_mm or p.driven_bore_mm):
        check_given_on_pitch_curves(p, _candidate_curves(p, scr), scr.m)
    # the sector method's bores: on its cut root (``design.feasible``, which runs this first)
