"""The non-circular pair's design: law, closure, teeth of one tooth method, finished profiles.

Two tooth methods:

* ``generated`` (default): a C2, closure-exact blend of the law around every leg hand-over
  (``gears.noncircular.SmoothedWalkingLaw``) whose half-width is the smallest keeping both pitch
  curves generable (rack undercut limit rho >= (h_a* - x) m / sin^2 alpha on convex parts with the
  driver shifted by +x and the driven wheel by -x; shaper z0 with r0 < |rho| on concave parts), or
  given by the user; conjugate teeth enveloped by the ISO 53 rack / the shaper on one shared
  arc-length frame (``geometry.noncircular_outline``).
* ``sectors``: the papers' own method (seed 000 eqs. 16-52, seed 002 Tables 2-4, ``gears.sectors``)
  on the exact law.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...errors import InputError, input_names
from ...gears.generability import CutterSpec, SmoothingDesign, check_generable, choose_smoothing
from ...gears.involute import BasicRack
from ...gears.noncircular import PitchCurves, SmoothedWalkingLaw, hub_speed_ripple, perimeter_per_mm
from ...gears.sectors import sector_hub_speed, sector_radii, sector_table
from ...laws.law import is_walking
from ...laws.walking import WalkingLaw
from .params import NoncircularPairParams

#: part-file keys of the quantities the tooth generators name in their errors
_TOOTH_KEYS = {"m": "module_mm", "z_H": "driven_teeth", "z0": "shaper_teeth"}
#: the same with a catalogue shaper (its z0 follows from d0 and m)
_TOOTH_KEYS_D0 = {"m": "module_mm", "z_H": "driven_teeth", "z0": "shaper_d0_mm"}

__all__ = ["Design", "PairDesign", "Screen", "screen", "screened", "design", "pair_design", "design_generated",
           "design_sectors", "sector_design_table", "mounting", "gear_profiles"]


# =========================================================================== design
@dataclass(frozen=True)
class Design:
    """Law, closure and teeth of one method (no files)."""

    method: str
    law: object              # the part file's law (laws.law.Law)
    run_law: object          # the law the teeth realise (smoothed for generated, exact for sectors)
    L: float
    m: float
    z_H: int
    z: int
    pc: PitchCurves
    smoothing: object = None  # SmoothingDesign (generated)
    table: object = None      # SectorTable (sectors)
    driver: object = None     # GeneratedGear | SectorGear
    driven: object = None
    ripple: object = None     # HubSpeedRipple
    closure_error: float = math.nan
    search: object = None     # gears.law_search.LawSearch (law_search = true)
    search_tries: tuple = ()  # (LawPoint, refusal or "") in the order tried
    shaper: object = None     # catalogue.ShaperEntry of the shaper used (own x0), or None

    @property
    def smoothing_deg(self) -> float:
        return math.degrees(self.smoothing.delta) if self.smoothing is not None else 0.0


def _law(p: NoncircularPairParams, source=None):
    """The part file's drive law (``laws.law.Law``); a table law's file relative to the part file ``source``."""
    if p.law == "walking":
        return WalkingLaw(a=p.a_mm, b=p.b_mm, c=p.c_mm, n=p.driver_turns)
    if p.law == "elliptical":
        from ...laws.ratio_laws import EllipticalLaw

        return EllipticalLaw(p.eccentricity, p.driver_turns)
    if p.law == "fourier":
        from ...laws.ratio_laws import FourierLaw

        return FourierLaw(p.driver_turns, tuple(float(v) for v in p.fourier_cos), tuple(float(v) for v in p.fourier_sin))
    from pathlib import Path

    from ...laws.pitch_curve_law import PitchCurveLaw, read_pitch_curve
    from ...laws.table_law import TableLaw, read_law_table

    f = Path(p.law_file if p.law == "table" else p.pitch_curve_file)
    if not f.is_absolute():
        f = (Path(source).resolve().parent if source is not None else Path.cwd()) / f
    if p.law == "table":
        return TableLaw(*read_law_table(f))
    return PitchCurveLaw(*read_pitch_curve(f), p.driver_turns)


def _rack(p) -> BasicRack:
    """The ISO 53 rack of the part file's profile at its pressure angle (``gears.catalogue``)."""
    from ...gears.catalogue import rack_profile

    with input_names({"rack_profile": "rack_profile"}):
        return rack_profile(p.rack_profile, math.radians(p.pressure_angle_deg))


def shaper_of(p, m: float):
    """The catalogue shaper (own z0, x0) of ``shaper_d0_mm`` at module m, or None (shaper_teeth, x0 = -x)."""
    from ...gears.catalogue import catalogue_shaper

    alpha = math.radians(p.pressure_angle_deg)
    if p.shaper_d0_mm <= 0:
        if p.shaper_own_x0:
            from ...gears.cutters import ShaperCutter

            with input_names({"z0": "shaper_teeth", "x0": "shaper_x0"}):
                return ShaperCutter(p.shaper_teeth, m, p.shaper_x0, BasicRack(alpha=alpha, c_star=0.25))
        return None
    with input_names({"d0": "shaper_d0_mm"}):
        return catalogue_shaper(p.shaper_d0_mm, m, alpha)


def _thinning(p) -> float:
    """Arc tooth-thickness reduction per gear: j_n split evenly, j_n / (2 cos alpha)."""
    return p.backlash_mm / (2.0 * math.cos(math.radians(p.pressure_angle_deg)))


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
        from .smooth_law import _limits

        return choose_smoothing(law, cutter, z_H, delta_max=math.radians(p.smoothing_max_deg), limits=_limits(p))
    except InputError as exc:
        best = _smallest_generable(law, cutter, z_H) if p.smoothing_max_deg < 45.0 else "no blend up to 45 deg works"
        raise InputError(
            "smoothing_max_deg", p.smoothing_max_deg,
            f"no C2 smoothing up to {p.smoothing_max_deg:g} deg keeps both pitch curves generable: "
            f"{str(exc).split(': ', 1)[-1]} [x = driver_shift, z_H = driven_teeth, z0 = shaper_teeth, m = module_mm]",
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
    law = _law(p, source)
    if not is_walking(law):
        from .smooth_law import screen_smooth

        scr = screen_smooth(p, law)
        return Screen(scr.m, smooth=scr)
    if p.method == "sectors":
        return _screen_sectors(p)
    _rack(p)
    if p.law_search:
        return _screen_search(p, law)
    m = p.module_mm if p.module_mm > 0 else 1.0
    sm = _smoothing(p, law, m)
    if p.center_distance_mm > 0:  # module from L: the design is scale invariant (rho and limits ~ m)
        m *= p.center_distance_mm / sm.L
        sm = _smoothing(_replace(p, module_mm=m, center_distance_mm=0.0), law, m)
    sh = shaper_of(p, m)
    common = dict(m=m, thinning_mm=_thinning(p), rack=_rack(p), z0=p.shaper_teeth if sh is None else sh.z0,
                  tip_min_mm=p.tip_land_min_module * m, shaper=sh,
                  tip_max_mm=p.tip_height_max_module * m)
    from ...gears.noncircular_teeth import ToothSpec

    g = sm.generability
    with input_names(_TOOTH_KEYS if sh is None else _TOOTH_KEYS_D0):
        for chk, x in ((g.driver, p.driver_shift), (g.driven, -p.driver_shift)):
            if chk.concave:  # the shaper this gear needs must exist
                ToothSpec(x=x, **common).shaper_tools()
    _mounting_fits(p, sm.L)
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
    _mounting_fits(p, min(q.L for q in res.points))  # the candidate built has one of these L
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
    _mounting_fits(p, L)
    return Screen(m, sector=(table, L, m))


def _mounting_fits(p: NoncircularPairParams, L: float) -> None:
    if 0 < p.mounting_distance_mm < L - 1e-9:
        raise InputError("mounting_distance_mm", p.mounting_distance_mm,
                         f"must be >= the design centre distance L = {L:.6f} mm (or 0)")


def screened(p: NoncircularPairParams, source=None) -> Screen:
    """:func:`screen` once per parameter values (the dry run's result is the build's); a law read from a
    file is screened once per part file ``source`` too."""
    from ..pipeline import design_of

    if p.law in ("table", "pitch_curve"):
        return design_of(p, screen, None if source is None else str(source))
    return design_of(p, screen)


def _search_design(p: NoncircularPairParams, law: WalkingLaw, progress) -> Design:
    """law_search = true: the ranked generable blends of ``gears.law_search.search_law`` over the
    catalogue shapers at this module; the teeth are generated for each in turn until both gears can be
    cut (the generator refuses with the reason: tip land, generating limit of the cutter)."""
    from ...gears.noncircular_teeth import ArcFrame, ToothSpec
    from ...policy import LAW_SEARCH_TRIES, LAW_SEARCH_TRIES_PER_SHAPER

    progress("law search: catalogue shapers, blend half-width and hand-over value")
    scr = screened(p)
    m, res, entries = scr.m, scr.search, scr.entries
    alpha = math.radians(p.pressure_angle_deg)
    z_H = p.driven_teeth
    rack = _rack(p)
    th = _thinning(p)
    tries = []
    seen = set()
    per_shaper: dict = {}
    for pt in res.points:
        key = (pt.d0_mm, round(pt.ripple, 4))
        if key in seen or per_shaper.get(pt.d0_mm, 0) >= LAW_SEARCH_TRIES_PER_SHAPER:
            continue
        seen.add(key)
        if len(tries) >= LAW_SEARCH_TRIES:
            break
        per_shaper[pt.d0_mm] = per_shaper.get(pt.d0_mm, 0) + 1
        entry = next(e for e in entries if e.d0_mm == pt.d0_mm)
        sh = entry.cutter(alpha)
        sl = SmoothedWalkingLaw(law, pt.delta, u_h=pt.u_h_rel * law.u)
        cutter = CutterSpec(m=m, alpha=alpha, x=p.driver_shift, x_H=-p.driver_shift, z0=sh.z0, shaper_x0=sh.x0)
        pc = PitchCurves(sl, pt.L)
        g = check_generable(pc, cutter)
        sm = SmoothingDesign(law=sl, delta=sl.delta, L=pt.L, z_H=z_H, z=z_H // law.n, cutter=cutter,
                             generability=g, ripple=hub_speed_ripple(sl))
        frame = ArcFrame(pc)
        common = dict(m=m, thinning_mm=th, rack=rack, z0=sh.z0, tip_min_mm=p.tip_land_min_module * m, shaper=sh,
                  tip_max_mm=p.tip_height_max_module * m)
        progress(f"law search: generating the teeth of candidate {len(tries) + 1} (ripple {100 * pt.ripple:.2f} %, "
                 f"shaper d0 {pt.d0_mm:g})")
        try:
            with input_names(_TOOTH_KEYS_D0):
                drv, dvn = _generate_pair(pc, ToothSpec(x=p.driver_shift, **common),
                                          ToothSpec(x=-p.driver_shift, **common), frame)
        except (InputError, RuntimeError, ValueError) as exc:
            tries.append((pt, str(exc).split(": ", 1)[-1]))
            continue
        tries.append((pt, ""))
        return Design("generated", law, sl, pt.L, m, z_H, z_H // law.n, pc, smoothing=sm, driver=drv, driven=dvn,
                      ripple=sm.ripple, closure_error=sm.closure_error, search=res, search_tries=tuple(tries),
                      shaper=entry)
    raise InputError("driver_shift", p.driver_shift,
                     f"none of the {len(tries)} least-ripple generable blends can be cut: "
                     + "; ".join(f"d0 {t.d0_mm:g} ripple {100 * t.ripple:.2f} %: {why}" for t, why in tries),
                     "another driver_shift, more teeth or a wider center_distance_band_mm")


def _generate_pair(pc, spec_driver, spec_driven, frame):
    """(driver, driven) generated outlines: the driver in a forked worker while this process cuts the
    driven wheel (the two are independent; seed 000/002 teeth by the rack/shaper envelope)."""
    from ...geometry.noncircular_outline import generate_gear
    from ...parallel import start
    from ...policy import SPLINE_FIT_TOL_MM

    # each may fit half its teeth in one more forked process (where the budget has a free slot)
    job = start(generate_gear, pc, "driver", spec_driver, frame, SPLINE_FIT_TOL_MM, start)
    dvn = generate_gear(pc, "driven", spec_driven, frame, SPLINE_FIT_TOL_MM, start)
    return job.result(), dvn


def design_generated(p: NoncircularPairParams, progress=lambda s: None, source=None) -> Design:
    """Seed 000/002 law -> C2 blend -> closure -> generated teeth (docs/architecture.md, "Seed equations and their modules")."""
    if p.law != "walking":
        from .smooth_law import design_smooth

        return design_smooth(p, screened(p, source).smooth, progress)
    law = _law(p, source)
    if p.law_search:
        return _search_design(p, law, progress)
    from ...gears.noncircular_teeth import ArcFrame, ToothSpec
    from ...geometry.noncircular_outline import generate_gear

    z_H = p.driven_teeth
    progress("generated: choosing the smoothing of the law")
    scr = screened(p)  # the blend, the module and the shaper; the refusals that need no outline
    m, sm, sh = scr.m, scr.smoothing, scr.shaper
    L = sm.L
    pc = sm.pair
    frame = ArcFrame(pc)
    rack = _rack(p)
    th = _thinning(p)
    common = dict(m=m, thinning_mm=th, rack=rack, z0=p.shaper_teeth if sh is None else sh.z0,
                  tip_min_mm=p.tip_land_min_module * m, shaper=sh,
                  tip_max_mm=p.tip_height_max_module * m)
    with input_names(_TOOTH_KEYS if sh is None else _TOOTH_KEYS_D0):
        progress(f"generated: driver teeth ({z_H // law.n}), rack/shaper envelopes")
        drv, dvn = _generate_pair(pc, ToothSpec(x=p.driver_shift, **common), ToothSpec(x=-p.driver_shift, **common),
                                  frame)
    return Design("generated", law, sm.law, L, m, z_H, z_H // law.n, pc, smoothing=sm, driver=drv, driven=dvn,
                  ripple=sm.ripple, closure_error=sm.closure_error,
                  shaper=None if p.shaper_d0_mm <= 0 else _entry_of(p, m))


def _entry_of(p, m):
    from ...gears.catalogue import shaper_entry

    return shaper_entry(p.shaper_d0_mm, m)


def _replace(p, **kw):
    import dataclasses

    return dataclasses.replace(p, **kw)


def sector_design_table(p: NoncircularPairParams):
    """(SectorTable, L, m) of the papers' method for these parameters: L given, or from the
    module so that the sector arc r_Hk dphi_k is pi m (the arcs are linear in L)."""
    law = _law(p)
    i = p.driven_teeth // 4
    m = p.module_mm
    if p.center_distance_mm > 0:
        L = p.center_distance_mm
    else:
        L = math.pi * m / sector_table(law, 1.0, i).arc
    return sector_table(law, L, i), L, m


def design_sectors(p: NoncircularPairParams, progress=lambda s: None) -> Design:
    """The papers' sector method on the exact law (seed 000 eqs. 16-52, seed 002 Tables 2-4)."""
    from ...geometry.sector_outline import sector_driven_gear, sector_driver_gear

    law = _law(p)
    table, L, m = screened(p).sector
    progress(f"sectors: outlines ({table.i} sectors per leg)")
    with input_names(_TOOTH_KEYS):
        drv = sector_driver_gear(table, m, p.backlash_mm)
        dvn = sector_driven_gear(table, m, p.backlash_mm)
    closure = abs(4 * float(np.sum(table.dtheta)) - 2 * math.pi * law.n)
    return Design("sectors", law, law, L, m, 4 * table.i, 4 * table.i // law.n, PitchCurves(law, L), table=table,
                  driver=drv, driven=dvn, ripple=sector_hub_speed(table), closure_error=closure)


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


def design(p: NoncircularPairParams, progress=lambda s: None, source=None) -> Design:
    return design_generated(p, progress, source) if p.method == "generated" else design_sectors(p, progress)


# =========================================================================== proof
def mounting(p: NoncircularPairParams, d: Design) -> float:
    """Installed centre distance: the design L unless mounting_distance_mm > 0 (>= L)."""
    if p.mounting_distance_mm <= 0:
        return d.L
    if p.mounting_distance_mm < d.L - 1e-9:
        raise InputError("mounting_distance_mm", p.mounting_distance_mm,
                         f"must be >= the design centre distance L = {d.L:.6f} mm (or 0)")
    return p.mounting_distance_mm


# =========================================================================== solids / files
def _with_bore(profile, bore_d: float, keyway: bool, root_min: float, m: float, which: str):
    from ...geometry.gear_outline import bore_loop, keyway_for_shaft
    from ...geometry.profile import Profile

    if bore_d <= 0:
        return profile
    name = f"{which}_bore_mm"
    t2 = keyway_for_shaft(bore_d)[1] if keyway else 0.0
    lim = root_min - m
    if not bore_d / 2 + t2 < lim:
        raise InputError(name, bore_d, f"bore{' + keyway' if keyway else ''} must stay one module inside the root: "
                         f"bore/2 + t2 = {bore_d / 2 + t2:.3f} mm >= {lim:.3f} mm",
                         f"largest bore about {2 * (lim - t2):.1f} mm")
    return Profile(profile.outer, [bore_loop(bore_d, True if keyway else None)], profile.name)


def gear_profiles(p: NoncircularPairParams, d: Design):
    """(driver, driven) profiles with bore and keyway (InputError if they do not fit)."""
    return (_with_bore(d.driver.profile, p.driver_bore_mm, p.keyway, d.driver.root_min_radius, d.m, "driver"),
            _with_bore(d.driven.profile, p.driven_bore_mm, p.keyway, d.driven.root_min_radius, d.m, "driven"))


@dataclass(frozen=True)
class PairDesign:
    """The part's design: the pair of one method, the finished profiles (bore, keyway), the installed
    centre distance."""

    p: NoncircularPairParams
    d: Design
    profiles: tuple  # (driver, driven) Profile
    mount: float


def pair_design(p: NoncircularPairParams, source=None) -> PairDesign:
    """The pair of the part file ``source`` (a table law's file is read relative to it)."""
    d = design(p, source=source)
    return PairDesign(p, d, gear_profiles(p, d), mounting(p, d))
