"""A law without corners (elliptical, Fourier, table, pitch curve): no blend.  Closure fixes the
centre distance (or the module); both pitch curves must be generable with the module, the teeth and
the cutters (``law_search = true``: the catalogue shapers at this module, largest first, where a pitch
curve is concave); then the teeth.

:func:`screen_smooth` settles everything that needs no outline (the dry run's screen, so a file it calls
valid is not refused for generability seconds later); :func:`design_smooth` generates the teeth of the
screened cutters in turn until both gears can be cut.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...errors import InputError, input_names

__all__ = ["SmoothScreen", "screen_smooth", "design_smooth"]


@dataclass(frozen=True)
class SmoothScreen:
    """What the screen of a law without corners settles: the law, module, centre distance and pitch
    curves, and the cutters in the order the build tries them, each with its refusal ("" if generable)."""

    law: object
    m: float
    L: float
    pc: object                # gears.noncircular.PitchCurves
    candidates: tuple         # (catalogue entry or None, shaper or None, CutterSpec, Generability, refusal)

    @property
    def generable(self) -> tuple:
        return tuple(c for c in self.candidates if not c[4])


def _cutters(p, law, m: float, pc) -> list:
    """(entry, shaper) in the order tried: the part file's own, or with law_search and a concave pitch
    curve every catalogue shaper at this module, largest first."""
    from ...gears.catalogue import shaper_diameters, shaper_entry
    from .cutting import entry_of, shaper_of

    alpha = math.radians(p.pressure_angle_deg)
    own = shaper_of(p, m)
    cands = [(None if p.shaper_d0_mm <= 0 else entry_of(p, m), own)]
    concave = pc.curvature("driver").concave or pc.curvature("driven").concave
    if p.law_search and concave:  # a shaper only where a pitch curve is concave
        entries = []
        for d0 in sorted(shaper_diameters(), reverse=True):
            try:
                entries.append(shaper_entry(d0, m))
            except InputError:
                continue
        cands = [(e, e.cutter(alpha)) for e in entries] or cands
    return cands


#: the part file's keys of the quantities a generability remedy names (the driven wheel's shift is -driver_shift)
PART_KEYS = {"x": "driver_shift", "x_H": "-driver_shift", "z_H": "driven_teeth", "m": "module_mm",
             "z0": "shaper_teeth"}


def generability_limits(p) -> dict:
    """The ranges of the parameters a generability hint may name (their fields' limits): the driver's
    profile shift x (the driven wheel's x_H = -x), the driven teeth z_H, the module m, the shaper's z0."""
    import dataclasses

    meta = {f.name: f.metadata for f in dataclasses.fields(p)}

    def rng(name):
        return (meta[name]["min"], meta[name]["max"])

    x_lo, x_hi = rng("driver_shift")
    return {"x": (x_lo, x_hi), "x_H": (-x_hi, -x_lo), "z_H": rng("driven_teeth"), "m": rng("module_mm"),
            "z0": rng("shaper_teeth")}


def _tooth_common(p, m: float, cutter, sh) -> dict:
    from .cutting import rack_of, thinning

    return dict(m=m, thinning_mm=thinning(p), rack=rack_of(p), z0=cutter.z0, tip_min_mm=p.tip_land_min_module * m,
                shaper=sh, tip_max_mm=p.tip_height_max_module * m)


def screen_smooth(p, law) -> SmoothScreen:
    """Closure, the pitch curves' generability with each cutter in turn (rack undercut limit on convex
    stretches, the shaper against concave ones, the shaper's own tip), the installed centre distance.
    InputError, naming what would make the law generable, when no cutter can generate it."""
    from ...gears.generability import CutterSpec, check_generable, remedies
    from ...gears.noncircular import PitchCurves, centre_distance, module_for
    from ...gears.noncircular_teeth import ToothSpec
    from .cutting import TOOTH_KEYS, TOOTH_KEYS_D0, mounting_fits, rack_of

    z_H = p.driven_teeth
    with input_names({"z_H": "driven_teeth", "m": "module_mm", "L": "center_distance_mm"}):
        if p.module_mm > 0:
            m = p.module_mm
            L = centre_distance(law, m, z_H)
        else:
            L = p.center_distance_mm
            m = module_for(law, L, z_H)
    rack_of(p)
    pc = PitchCurves(law, L)
    alpha = math.radians(p.pressure_angle_deg)
    out = []
    for entry, sh in _cutters(p, law, m, pc):
        cutter = CutterSpec(m=m, alpha=alpha, x=p.driver_shift, x_H=-p.driver_shift,
                            z0=p.shaper_teeth if sh is None else sh.z0, shaper_x0=None if sh is None else sh.x0)
        g = check_generable(pc, cutter)
        why = "" if g.ok else "; ".join(remedies(g, cutter, z_H, law.n, L, generability_limits(p), PART_KEYS))
        if not why:  # the shaper the concave stretches need must exist
            try:
                with input_names(TOOTH_KEYS if entry is None else TOOTH_KEYS_D0):
                    for chk, x in ((g.driver, p.driver_shift), (g.driven, -p.driver_shift)):
                        if chk.concave:
                            ToothSpec(x=x, **_tooth_common(p, m, cutter, sh)).shaper_tools()
            except InputError as exc:
                if not p.law_search:
                    raise
                why = f"shaper d0 {entry.d0_mm:g}: {str(exc).split(': ', 1)[-1]}" if entry else str(exc)
        out.append((entry, sh, cutter, g, why))
    scr = SmoothScreen(law, m, L, pc, tuple(out))
    if not scr.generable:
        raise _not_generable(p, scr, [c[4] for c in out])
    mounting_fits(p, L)
    return scr


def _not_generable(p, scr: SmoothScreen, tries: list) -> InputError:
    """The refusal of a law no cutter generates: the key of the first limit met, what would make it work."""
    convex = not tries or "convex" in tries[0]
    z_H = p.driven_teeth
    return InputError("driver_shift" if convex else "shaper_teeth", p.driver_shift if convex else p.shaper_teeth,
                      f"the {scr.law.kind} law's pitch curves are not generable at m = {scr.m:g}, "
                      f"z {z_H // scr.law.n}/{z_H}, L = {scr.L:.3f} mm with the catalogue cutters",
                      " | ".join(dict.fromkeys(tries)))  # one line per distinct limit, not per shaper


def design_smooth(p, scr: SmoothScreen, progress):
    """The teeth of the screened cutters in turn (law_search: the next one where a generator refuses)."""
    from ...gears.generability import SmoothingDesign
    from ...gears.noncircular_teeth import ArcFrame, ToothSpec
    from .cutting import TOOTH_KEYS, TOOTH_KEYS_D0, Design, generate_pair

    law, m, L, pc = scr.law, scr.m, scr.L, scr.pc
    z_H = p.driven_teeth
    progress(f"generated: generability of the {law.kind} law at m = {m:g}, z {z_H // law.n}/{z_H}")
    frame = None
    tries = []
    for entry, sh, cutter, g, why in scr.candidates:
        if why:
            tries.append(why)
            continue
        frame = frame or ArcFrame(pc)
        common = _tooth_common(p, m, cutter, sh)
        progress(f"generated: the teeth of both wheels ({z_H // law.n} and {z_H}), rack/shaper envelopes")
        try:
            with input_names(TOOTH_KEYS if entry is None else TOOTH_KEYS_D0):
                drv, dvn = generate_pair(pc, ToothSpec(x=p.driver_shift, **common),
                                          ToothSpec(x=-p.driver_shift, **common), frame, progress)
        except (InputError, RuntimeError, ValueError) as exc:
            if not p.law_search or not (g.driver.concave or g.driven.concave):
                raise
            tries.append(f"shaper d0 {entry.d0_mm:g}: {str(exc).split(': ', 1)[-1]}")
            continue
        sm = SmoothingDesign(law=law, delta=0.0, L=L, z_H=z_H, z=z_H // law.n, cutter=cutter, generability=g,
                             ripple=None)
        return Design("generated", law, law, L, m, z_H, z_H // law.n, pc, smoothing=sm, driver=drv, driven=dvn,
                      closure_error=sm.closure_error, shaper=entry)
    raise _not_generable(p, scr, tries)
