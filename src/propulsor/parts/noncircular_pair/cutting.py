"""What the non-circular pair's screen (:mod:`.feasibility`), its smooth-law teeth (:mod:`.smooth_law`) and its
design (:mod:`.design`) share: the part-file keys the tooth generators' errors are named by, the design's result
type, the part file's law, the rack and the shaper it names, the tooth thinning, the mounting rule and the
pair generated in two processes.  Below all three, so that none of them reaches into another's private names.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...errors import InputError, input_names
from ...gears.involute import BasicRack
from ...gears.noncircular import PitchCurves
from ...laws.walking import WalkingLaw
from .params import NoncircularPairParams

__all__ = ["TOOTH_KEYS", "TOOTH_KEYS_D0", "Design", "law_of", "rack_of", "shaper_of", "thinning", "entry_of",
           "mounting_fits", "generate_pair"]

#: part-file keys of the quantities the tooth generators name in their errors
TOOTH_KEYS = {"m": "module_mm", "z_H": "driven_teeth", "z0": "shaper_teeth"}
#: the same with a catalogue shaper (its z0 follows from d0 and m)
TOOTH_KEYS_D0 = {"m": "module_mm", "z_H": "driven_teeth", "z0": "shaper_d0_mm"}


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


def law_of(p: NoncircularPairParams, source=None):
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


def rack_of(p) -> BasicRack:
    """The ISO 53 rack of the part file's profile at its pressure angle (``gears.catalogue``; its refusal names the
    part file's key, ``rack_profile``, itself)."""
    from ...gears.catalogue import rack_profile

    return rack_profile(p.rack_profile, math.radians(p.pressure_angle_deg))


def shaper_of(p, m: float):
    """The catalogue shaper (own z0, x0) of ``shaper_d0_mm`` at module m, or None (shaper_teeth, x0 = -x)."""
    from ...gears.catalogue import catalogue_shaper

    alpha = math.radians(p.pressure_angle_deg)
    if p.shaper_d0_mm <= 0:
        if p.shaper_own_x0:
            from ...gears.cutters import ShaperCutter, shaper_rack

            with input_names({"z0": "shaper_teeth", "x0": "shaper_x0"}):
                return ShaperCutter(p.shaper_teeth, m, p.shaper_x0, shaper_rack(alpha, 1.0, 0.25))
        return None
    with input_names({"d0": "shaper_d0_mm"}):
        return catalogue_shaper(p.shaper_d0_mm, m, alpha)


def thinning(p) -> float:
    """Arc tooth-thickness reduction per gear: j_n split evenly, j_n / (2 cos alpha)."""
    return p.backlash_mm / (2.0 * math.cos(math.radians(p.pressure_angle_deg)))


def entry_of(p, m):
    from ...gears.catalogue import shaper_entry

    return shaper_entry(p.shaper_d0_mm, m)


def mounting_fits(p: NoncircularPairParams, L: float) -> None:
    if 0 < p.mounting_distance_mm < L - 1e-9:
        raise InputError("mounting_distance_mm", p.mounting_distance_mm,
                         f"must be >= the design centre distance L = {L:.6f} mm (or 0)")


def generate_pair(pc, spec_driver, spec_driven, frame, progress=None):
    """(driver, driven) generated outlines: the driver in a forked worker while this process cuts the
    driven wheel (the two are independent; seed 000/002 teeth by the rack/shaper envelope).  `progress`: counts the
    driven wheel's teeth generated and fitted (the driver's, beside it, are fewer)."""
    from ...geometry.noncircular_outline import generate_gear
    from ...parallel import start
    from ...policy import SPLINE_FIT_TOL_MM
    from ...progress import count_to

    # each may fit half its teeth in one more forked process (where the budget has a free slot)
    job = start(generate_gear, pc, "driver", spec_driver, frame, SPLINE_FIT_TOL_MM, start)
    dvn = generate_gear(pc, "driven", spec_driven, frame, SPLINE_FIT_TOL_MM, start,
                        count_to(progress, "generated: the driven wheel's teeth cut and fitted", "step"))
    return job.result(), dvn
