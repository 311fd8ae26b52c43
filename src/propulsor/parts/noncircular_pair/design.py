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
from ...gears.generability import CutterSpec, SmoothingDesign, check_generable
from ...gears.noncircular import PitchCurves, SmoothedWalkingLaw, hub_speed_ripple
from ...gears.sectors import sector_hub_speed
from ...laws.walking import WalkingLaw
from .bores import Bore, bores, with_bores
from .cutting import TOOTH_KEYS, TOOTH_KEYS_D0, Design, entry_of, generate_pair, law_of, rack_of, thinning
from .feasibility import Screen, screen, screened, sector_design_table
from .params import NoncircularPairParams

#: the part file's law and rack under their former names (``cutting.law_of``, ``cutting.rack_of``)
_law, _rack = law_of, rack_of

__all__ = ["Design", "PairDesign", "Screen", "screen", "screened", "design", "pair_design", "design_generated",
           "design_sectors", "sector_design_table", "mounting", "gear_profiles", "bores", "feasible"]


# =========================================================================== design
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
    rack = rack_of(p)
    th = thinning(p)
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
            with input_names(TOOTH_KEYS_D0):
                drv, dvn = generate_pair(pc, ToothSpec(x=p.driver_shift, **common),
                                          ToothSpec(x=-p.driver_shift, **common), frame, progress)
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


def design_generated(p: NoncircularPairParams, progress=lambda s: None, source=None) -> Design:
    """Seed 000/002 law -> C2 blend -> closure -> generated teeth (docs/architecture.md, "Seed equations and their modules")."""
    if p.law != "walking":
        from .smooth_law import design_smooth

        return design_smooth(p, screened(p, source).smooth, progress)
    law = law_of(p, source)
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
    rack = rack_of(p)
    th = thinning(p)
    common = dict(m=m, thinning_mm=th, rack=rack, z0=p.shaper_teeth if sh is None else sh.z0,
                  tip_min_mm=p.tip_land_min_module * m, shaper=sh,
                  tip_max_mm=p.tip_height_max_module * m)
    with input_names(TOOTH_KEYS if sh is None else TOOTH_KEYS_D0):
        progress(f"generated: the teeth of both wheels ({z_H // law.n} and {z_H}), rack/shaper envelopes")
        drv, dvn = generate_pair(pc, ToothSpec(x=p.driver_shift, **common), ToothSpec(x=-p.driver_shift, **common),
                                  frame, progress)
    return Design("generated", law, sm.law, L, m, z_H, z_H // law.n, pc, smoothing=sm, driver=drv, driven=dvn,
                  ripple=sm.ripple, closure_error=sm.closure_error,
                  shaper=None if p.shaper_d0_mm <= 0 else entry_of(p, m))


def design_sectors(p: NoncircularPairParams, progress=lambda s: None) -> Design:
    """The papers' sector method on the exact law (seed 000 eqs. 16-52, seed 002 Tables 2-4)."""
    from ...geometry.sector_outline import sector_driven_gear, sector_driver_gear

    law = law_of(p)
    table, L, m = screened(p).sector
    progress(f"sectors: outlines ({table.i} sectors per leg)")
    with input_names(TOOTH_KEYS):
        drv = sector_driver_gear(table, m, p.backlash_mm)
        dvn = sector_driven_gear(table, m, p.backlash_mm)
    closure = abs(4 * float(np.sum(table.dtheta)) - 2 * math.pi * law.n)
    return Design("sectors", law, law, L, m, 4 * table.i, 4 * table.i // law.n, PitchCurves(law, L), table=table,
                  driver=drv, driven=dvn, ripple=sector_hub_speed(table), closure_error=closure)


def design(p: NoncircularPairParams, progress=lambda s: None, source=None) -> Design:
    if p.method == "generated":
        return design_generated(p, progress, source)
    from ..pipeline import design_of

    return design_of(p, design_sectors, progress=progress)  # the dry run's (its bores are checked on the outlines)


# =========================================================================== proof
def feasible(p: NoncircularPairParams, source=None) -> None:
    """The part type's feasibility (``parts.vet``): :func:`.feasibility.feasible`, then a sector pair's given bores
    checked on its cut root as the build checks them (the sector outlines are quick, 0.5-0.9 CPU s, and computed
    once: the build gets them)."""
    from ..pipeline import design_of
    from .bores import check_given_on_design
    from .feasibility import feasible as screen_feasible

    screen_feasible(p, source)
    if screened(p, source).sector:
        check_given_on_design(p, design_of(p, design_sectors))


def mounting(p: NoncircularPairParams, d: Design) -> float:
    """Installed centre distance: the design L unless mounting_distance_mm > 0 (>= L)."""
    if p.mounting_distance_mm <= 0:
        return d.L
    if p.mounting_distance_mm < d.L - 1e-9:
        raise InputError("mounting_distance_mm", p.mounting_distance_mm,
                         f"must be >= the design centre distance L = {d.L:.6f} mm (or 0)")
    return p.mounting_distance_mm


# =========================================================================== solids / files
def _with_bore(profile, bore: Bore):
    from ...geometry.gear_outline import bore_loop
    from ...geometry.profile import Profile

    if bore.d_mm <= 0:
        return profile
    return Profile(profile.outer, [bore_loop(bore.d_mm, True if bore.keyway else None)], profile.name)


def gear_profiles(p: NoncircularPairParams, d: Design, chosen: tuple[Bore, Bore] | None = None):
    """(driver, driven) profiles with bore and keyway: the bores ``chosen`` (default: :func:`.bores.bores`, a given
    bore checked, InputError when it does not fit; a bore not given sized from the gear)."""
    drv, dvn = bores(p, d) if chosen is None else chosen
    return _with_bore(d.driver.profile, drv), _with_bore(d.driven.profile, dvn)


@dataclass(frozen=True)
class PairDesign:
    """The part's design: the pair of one method, the finished profiles (bore, keyway), the installed
    centre distance."""

    p: NoncircularPairParams  # the bores as built (a sized bore's diameter where the part file gives none)
    d: Design
    profiles: tuple  # (driver, driven) Profile
    mount: float
    bores: tuple = ()  # (driver, driven) bores.Bore: given or sized, and why


def pair_design(p: NoncircularPairParams, source=None, progress=lambda s: None) -> PairDesign:
    """The pair of the part file ``source`` (a table law's file is read relative to it); `progress` told its steps."""
    d = design(p, progress, source=source)
    chosen = bores(p, d)
    return PairDesign(with_bores(p, chosen), d, gear_profiles(p, d, chosen), mounting(p, d), chosen)
