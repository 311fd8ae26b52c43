"""Print kit of the non-circular pair: the two gears at print scale with FDM backlash in their
teeth, a base bar holding the axles at the centre distance, press-fit pins, a crank handle on the
driver and n index marks on the driven wheel (one per driver turn).

The printed pair is designed anew at the print module (the law, closure and teeth are scale
invariant; module, centre distance and face width shrink by S), with the tooth thinning set for the
printer's normal backlash (``backlash_mm`` of the pair = the printer's; raised once by the shortfall
when the full-cycle proof measures less), no keyways, bores for the pins with the running clearance
and the holes' undersize.  The proof runs on the printed outlines over the whole cycle.  The hand on the crank
(:mod:`.kit_load`): the torque a firm hand puts on the handle at its radius, rated on that printed pair for every
printed material; the guide says which material survives it.
"""

from __future__ import annotations

import dataclasses
import math

from ...check import Check
from ...errors import InputError
from ...geometry.profile import Profile, circle_loop
from ...params import load_params, params_to_dict
from ...printing.fits import Fit
from ...printing.kit import Kit, Piece, Placed, place
from ...printing.printers import Printer
from ...printing.hardware import PRINTED_PIN_MIN_MM, STANDARD_PIN_D, Hardware, dowel, mm, standard_at_most, side_pin
from ...printing.scale import ScaleChoice, check_printable, choose_scale, larger
from ..pipeline import design_of
from .design import pair_design
from .kit_load import TABLE_COLUMNS as HAND_TABLE_COLUMNS, hand_load
from .params import NoncircularPairParams
from .proofs import checks_common, prove

__all__ = ["kit"]

#: base bar thickness, wall round each pin, handle diameter and height above the gear, mark hole (mm)
BASE_T_MM, BOSS_WALL_MM, HANDLE_D_MM, HANDLE_UP_MM, MARK_D_MM = 6.0, 6.0, 6.0, 15.0, 3.0
#: least normal backlash measured over the cycle / designed j_n (seed 002 at print scale: 0.959); the design
#: starts from the target over this, the proof checks and corrects once
JN_MEASURED_RATIO = 0.95
#: least and largest printed pin diameter (mm): stiff enough, and no larger than needed
PIN_D_MIN_MM, PIN_D_MAX_MM = 5.0, 12.0
#: washer under each wheel, cap pressed on each pin's top above it, the wheels' axial play (mm)
WASHER_T_MM, CAP_H_MM, PLAY_MM = 1.0, 3.0, 0.3
#: least handle: printed, and a steel pin below it (mm)
HANDLE_PRINTED_MIN_MM, HANDLE_STEEL_MIN_MM = 4.0, 2.0


def _pin(wanted: float, least: float = PIN_D_MIN_MM) -> float:
    """A printed axle pin: the standard diameter at most min(12, max(least, wanted))."""
    return standard_at_most(min(PIN_D_MAX_MM, max(least, wanted)))


def rig_sizes(R_root: float, m: float, wanted: float, printer: Printer):
    """(driver pin, handle diameter, handle radius) that fit inside the driver's root circle R_root
    (print size): the largest standard pin down to the printable least whose bore leaves room for a
    handle (the profile's 6 mm, else the largest standard one, printed down to 4 mm, steel below); None
    when none does."""
    clear, under, minf = printer.running_clearance_mm, printer.hole_undersize_mm, printer.min_feature_mm
    start = _pin(wanted)
    for d in [s for s in reversed(STANDARD_PIN_D) if PRINTED_PIN_MIN_MM <= s <= start]:
        rb = (d + 2 * clear + under) / 2
        r_h = 0.5 * (rb + R_root)
        if r_h - HANDLE_D_MM / 2 - rb >= minf and R_root - m - r_h - HANDLE_D_MM / 2 >= minf:
            return d, HANDLE_D_MM, r_h
        h = standard_at_most(R_root - m - rb - 2 * minf)
        if h is not None and h >= HANDLE_STEEL_MIN_MM:
            return d, min(h, HANDLE_D_MM), 0.5 * (rb + R_root - m)
    return None


def _extent(profile: Profile) -> tuple[float, float]:
    pts = profile.outer.polyline(0.05)
    return tuple(float(v) for v in (pts.max(axis=0) - pts.min(axis=0)))


def _pitch_extents(p: NoncircularPairParams, source=None):
    """(m, L, extents) of the pair from its unblended pitch curves (seed 000 eqs. 12-13) at the module:
    each gear's bounding box of its pitch curve grown by the addendum m (1 + |x|) and 2 % (the blend
    and the search move the curves by less), without cutting a tooth."""
    import numpy as np

    from ...gears.noncircular import PitchCurves, centre_distance
    from .design import _law

    law, m = _law(p, source), p.module_mm
    L = centre_distance(law, m, p.driven_teeth)
    pc = PitchCurves(law, L)
    phi = np.linspace(0.0, 2.0 * math.pi, 4001)
    r_H = pc.r_H(phi)
    theta = law.theta(phi)
    grow = m * (1.0 + abs(p.driver_shift))
    out = {}
    for name, r, a in (("driven", r_H, phi), ("driver", L - r_H, theta)):
        pts = np.column_stack([r * np.cos(a), r * np.sin(a)])
        ext = (pts.max(axis=0) - pts.min(axis=0) + 2.0 * grow) * 1.02
        out[name] = (float(ext[0]), float(ext[1]), p.face_width_mm)
    return m, L, out


def _kit_params(p: NoncircularPairParams, m: float, S: float, pr: Printer, j_n: float, bores) -> NoncircularPairParams:
    walking = {} if p.law != "walking" else dict(a_mm=p.a_mm / S, b_mm=p.b_mm / S, c_mm=p.c_mm / S)
    q = dataclasses.replace(
        p, module_mm=m / S, center_distance_mm=0.0, **walking,
        face_width_mm=p.face_width_mm / S, backlash_mm=j_n, keyway=False, mounting_distance_mm=0.0,
        compare_methods=False, driver_bore_mm=bores[0], driven_bore_mm=bores[1],
        tip_land_min_module=max(p.tip_land_min_module, pr.min_feature_mm / (m / S)))
    return load_params(NoncircularPairParams, params_to_dict(q))


def _found_law(p: NoncircularPairParams, d) -> NoncircularPairParams:
    """The law and shaper the full-size design found (law_search), fixed for the print scale: the
    catalogue lists no shaper at a print module, the shaper is the same one scaled (z0 and its own x0)."""
    if d.search is None and d.shaper is not None and p.law != "walking":  # a smooth law's catalogue shaper
        return dataclasses.replace(p, law_search=False, shaper_d0_mm=0.0, shaper_teeth=d.shaper.z0,
                                   shaper_own_x0=True, shaper_x0=d.shaper.x0)
    if d.search is None:
        return p
    pt = d.search_tries[-1][0]
    deg = math.degrees(pt.delta)
    return dataclasses.replace(p, law_search=False, smoothing_deg=deg, smoothing_max_deg=max(p.smoothing_max_deg, deg),
                               blend_hand_over=pt.u_h_rel, shaper_d0_mm=0.0, shaper_teeth=d.shaper.z0,
                               shaper_own_x0=True, shaper_x0=d.shaper.x0)


def _as_printed(p: NoncircularPairParams, kd, printer: Printer, progress=None) -> tuple[list, list[str]]:
    """With the part file's tolerance_grade set: the printed pair within the printer's xy accuracy and the pins'
    running clearance (``tolerance.printed``), its worst-case corners and Monte Carlo cases: (checks, guide text).
    `progress`: told the cases run (a count)."""
    from ... import policy
    from ...progress import counter
    from .as_built_outputs import tolerance_check
    from .tolerance import monte_carlo_cases, printed, run_case, worst_cases

    if not p.tolerance_grade or kd.d.method != "generated":
        return [], []
    tol = printed(policy.PRINT_XY_ACCURACY_MM, printer.running_clearance_mm)
    corners, draws = worst_cases(tol), monte_carlo_cases(tol, p.tolerance_samples, p.tolerance_seed)
    tick = counter(progress, "kit: the printed pair within the printer's tolerances", len(corners) + len(draws),
                   "case")

    def run(k: int, c):
        r = run_case(kd.d, kd.mount, c)
        tick(k + 1)
        return r

    worst = [run(k, c) for k, c in enumerate(corners)]
    mc = [run(len(corners) + k, c) for k, c in enumerate(draws)]
    chk = tolerance_check(tol, worst, p.speed_step_max)
    text = [f"The printed pair within {tol.source}: least backlash {min(r.backlash_min_mm for r in worst):.3f} mm "
            f"at the worst case ({'; '.join(f'{r.case.name} {r.backlash_min_mm:.3f} mm' for r in worst)})."]
    if mc:
        bl = sorted(r.backlash_min_mm for r in mc)
        jams = sum(r.jam for r in mc)
        text.append(f"Of {len(mc)} printed pairs drawn within these tolerances (seed {p.tolerance_seed}) {jams} jam; "
                    f"their least backlash runs from {bl[0]:.3f} to {bl[-1]:.3f} mm.")
    text.append("It runs as drawn at every corner." if chk.passed else
                f"At the worst case it does not: {chk.message}. Print the clearance coupon first (section 3); where "
                f"it shows your printer over-sizing, give the gears more backlash (--set backlash_mm=...).")
    return [chk], text


def _documented_jam(source, prefix: str) -> list[str]:
    """The kit's motion checks, when the part file documents that its teeth jam ([meta] expected_failures
    holds <prefix>.runs_without_jam): the printed pair overlaps for the same reason."""
    from ...params import read_part_meta

    if source is None:
        return []
    documented = set(read_part_meta(source).get("expected_failures", []))
    if f"{prefix}.runs_without_jam" not in documented:
        return []
    return [f"{prefix}.overlap_area", f"{prefix}.print_backlash_min"]


#: the wheels as the guide names them
_WHEEL = {"driver": "driver", "driven": "driven wheel"}


def _keep_on_step(capped) -> str:
    """The assembly step that keeps the wheels on their pins: a printed cap where there is room for one, else the
    push-on retaining washer the hardware lists (``capped``: (driver, driven))."""
    if all(capped):
        return (f"Press a cap onto each pin until it is flush with the pin's top: it stands {PLAY_MM:g} mm above the "
                f"wheel, which turns freely and stays on when the model is lifted.")
    keepers = [f"press the cap onto the {role}'s pin until it is flush with the pin's top" if c else
               f"push the retaining washer (starlock, in the hardware) onto the {role}'s pin down to {PLAY_MM:g} mm "
               f"above the wheel" for role, c in zip(("driver", "driven wheel"), capped)]
    return (keepers[0][0].upper() + keepers[0][1:] + "; " + keepers[1] + ": each wheel turns freely and stays on when "
            "the model is lifted.")


def _with_holes(profile: Profile, holes) -> Profile:
    return Profile(profile.outer, list(profile.holes) + list(holes), profile.name)


def _pitch_fits(p: NoncircularPairParams, extents: dict, printer: Printer) -> bool:
    """The pitch curves alone (the estimate's extents less its 2 % and addendum) fit the bed at 1:1: the
    printed pair may then fit at full size although the padded estimate does not."""
    from ...printing.scale import fits

    grow = p.module_mm * (1.0 + abs(p.driver_shift))
    usable = (printer.bed_x_mm - 2 * printer.margin_mm, printer.bed_y_mm - 2 * printer.margin_mm, printer.bed_z_mm)
    return all(fits((e[0] / 1.02 - 2 * grow, e[1] / 1.02 - 2 * grow, e[2]), usable) for e in extents.values())


def kit(p: NoncircularPairParams, printer: Printer, scale: float | None = None, source=None,
        full_size_first: bool = True, progress=None) -> Kit:
    """The kit; full_size_first: where only the padded estimate keeps a searched pair from 1:1, the
    printed pair is searched and cut at 1:1 first and its own outlines decide (the full-size design is
    made only when they do not fit: then the kit is made again without this shortcut).  `progress`: told the
    steps (the designs, the printed pair's proof and its phases)."""
    say = progress or (lambda msg: None)
    from ...solids.build import extrude_profile
    from ...solids.kernel import cylinder

    bed = (printer.bed_x_mm, printer.bed_y_mm, printer.bed_z_mm)
    full = None
    at_1_first = False
    # a bore the part file does not give is sized from the full-size gear: its design is then made first
    sized = p.driver_bore_mm is None or p.driven_bore_mm is None
    if p.law_search and p.module_mm > 0 and not sized:
        # the searched law at full size is also the one at 1:1: the scale from the pitch curves, and at
        # 1:1 the printed pair searched and cut once (a print module has no catalogue shaper)
        m, L_est, extents = _pitch_extents(p, source)
        choice = choose_scale(extents, bed, scale, margin=printer.margin_mm)
        if choice.S != 1.0 and scale is None and full_size_first and _pitch_fits(p, extents, printer):
            choice, at_1_first = ScaleChoice(1.0, "every piece fits the bed at full size"), True
        elif choice.S != 1.0:
            say("kit: the full-size pair's design")
            full = design_of(p, pair_design, source)  # the part's own design (Part.design), made once
    else:
        say("kit: the full-size pair's design")
        full = design_of(p, pair_design, source)
    if full is not None:
        m, L_est = full.d.m, full.mount
        extents = {"driver": (*_extent(full.profiles[0]), p.face_width_mm),
                   "driven": (*_extent(full.profiles[1]), p.face_width_mm)}
        choice = choose_scale(extents, bed, scale, margin=printer.margin_mm)
    def rig_at(S):
        """The pins and the base bar's length at reduction S."""
        given = p if full is None else full.p  # the full-size bores (a sized one's diameter where not given)
        pin = [_pin(b / S) for b in (given.driver_bore_mm, given.driven_bore_mm)]
        if full is not None:  # the driver's pin sized for the handle beside it (the root radius scales as 1/S)
            rig = rig_sizes(full.d.driver.root_min_radius / S, m / S, given.driver_bore_mm / S, printer)
            if rig is not None:
                pin[0] = rig[0]
        return pin, L_est / S + 2 * (max(pin) / 2 + BOSS_WALL_MM)

    longest = max(printer.bed_x_mm, printer.bed_y_mm) - 2 * printer.margin_mm
    pin, base_len = rig_at(choice.S)
    if base_len > longest:
        if at_1_first:
            return kit(p, printer, scale, source, full_size_first=False, progress=progress)
        from ...printing.scale import STANDARD_SCALES

        # the rig's base bar (the centre distance and two bosses) is a piece too: the scale that fits it
        works = next((T for T in STANDARD_SCALES if T > choice.S and rig_at(T)[1] <= longest), None)
        if scale is not None or works is None:
            bar = f"the rig's base bar ({base_len:.1f} mm at {choice.label}) does not fit the bed's {longest:g} mm " \
                  f"(its longer side less {printer.margin_mm:g} mm margins)"
            if scale is not None:
                raise InputError("--scale", choice.label, bar + (f"; it fits at 1:{works:g}" if works else
                                                                 "; a larger printer"))
            raise InputError("printer", printer.name, bar + f" even at 1:{STANDARD_SCALES[-1]:g}; a larger printer")
        pieces_bed = choice.bed_at

        def bed_at(T):
            """The least bed at 1:T: the pieces', its side at least the base bar with the margins."""
            x, y, z = pieces_bed(T) if pieces_bed is not None else (0.0, 0.0, 0.0)
            side = max(x, rig_at(T)[1] + 2 * printer.margin_mm)
            return side, side, z

        choice = ScaleChoice(works, f"the rig's base bar is {base_len:.1f} mm at {choice.label}, longer than the "
                                    f"bed's {longest:g} mm; at 1:{works:g} it fits", bed=bed, bed_at=bed_at)
        pin, base_len = rig_at(works)
    S = choice.S
    R_boss = max(pin) / 2 + BOSS_WALL_MM
    check_printable(S, m, printer.min_module_mm, choice=choice)
    clear, under, press = printer.running_clearance_mm, printer.hole_undersize_mm, printer.press_fit_mm
    bores = [d + 2 * clear + under for d in pin]
    # the pair at print scale, thinned for the printer's backlash; once more if the proof measures less
    j_n = printer.backlash_mm / JN_MEASURED_RATIO
    alpha = math.radians(p.pressure_angle_deg)
    for attempt in range(2):
        q = _kit_params(p if full is None else _found_law(p, full.d), m, S, printer, j_n, bores)
        say(f"kit: the printed pair's design at 1:{S:g}" + (" (thinned again)" if attempt else ""))
        kd = pair_design(q, source)
        proof = prove(kd.d, q.proof_phases_per_tooth, 4, say, mount=kd.mount)
        s = proof.summary()
        jn_min = s["backlash_min_mm"] * math.cos(alpha)
        if not (jn_min < printer.backlash_mm and math.isfinite(jn_min)) or attempt == 1:
            break
        j_n += 1.1 * (printer.backlash_mm - jn_min)
    d, L = kd.d, kd.mount
    w = q.face_width_mm
    drv_prof, dvn_prof = kd.profiles
    # the crank handle's hole in the driver, the index marks in the driven wheel
    rig = rig_sizes(d.driver.root_min_radius, d.m, pin[0], printer)
    if at_1_first:
        real = {"driver": (*_extent(drv_prof), w), "driven": (*_extent(dvn_prof), w)}
        if choose_scale(real, bed, None, margin=printer.margin_mm).S != 1.0 or rig is None or rig[0] != pin[0]:
            return kit(p, printer, scale, source, full_size_first=False, progress=progress)  # the printed pair does not fit at 1:1
    if rig is None or rig[0] != pin[0]:
        raise InputError("--scale", choice.label, f"the driver (root radius {mm(d.driver.root_min_radius)} mm) has no "
                         f"room for a ⌀{HANDLE_STEEL_MIN_MM:g} mm handle beside a ⌀{PRINTED_PIN_MIN_MM:g} mm pin; "
                         f"{larger(S)}")
    handle_d, r_h = rig[1], rig[2]
    handle_printed = handle_d >= HANDLE_PRINTED_MIN_MM
    handle_hole = handle_d - 2 * press + under
    drv_prof = _with_holes(drv_prof, [circle_loop(handle_hole / 2, (r_h, 0.0), ccw=False)])
    r_mark = 0.5 * (bores[1] / 2 + d.driven.root_min_radius)  # the index marks' radius
    n = q.driver_turns
    marks = [circle_loop(MARK_D_MM / 2, (r_mark * math.cos(a), r_mark * math.sin(a)), ccw=False)
             for a in (math.pi + 2 * math.pi * k / n for k in range(n))]
    dvn_prof = _with_holes(dvn_prof, marks)
    ch = printer.chamfer_mm
    say("kit: solids (the pair, the base, pins, washers and caps)")
    driver = extrude_profile(drv_prof, w)
    driven = extrude_profile(dvn_prof, w)
    base_prof = _base_profile(L, R_boss, [d_ - 2 * press + under for d_ in pin])
    base = extrude_profile(base_prof, BASE_T_MM)
    pin_len = BASE_T_MM + WASHER_T_MM + w + PLAY_MM + CAP_H_MM
    pins = [side_pin(d_, pin_len) for d_ in pin]
    handle = side_pin(handle_d, w + HANDLE_UP_MM)
    # a washer under each wheel (it runs on the pin), a cap pressed on the pin above it (keeps the wheel on);
    # the driver's cap clears the handle, the driven's the index marks
    cap_od = [min(pin[0] + 6.0, 2 * (r_h - handle_d / 2 - 0.5)), min(pin[1] + 6.0, 2 * (r_mark - MARK_D_MM / 2 - 0.5))]
    cap_id = [d_ - 2 * press + under for d_ in pin]
    # a cap with no room for its wall beside the handle or the marks is left out (a push-on washer instead)
    capped = [(o - i) / 2 >= printer.min_feature_mm for o, i in zip(cap_od, cap_id)]
    rings = []
    for k, role in enumerate(("driver", "driven")):
        washer = extrude_profile(Profile(circle_loop(pin[k] / 2 + 3.0), [circle_loop(bores[k] / 2, ccw=False)],
                                         "washer"), WASHER_T_MM)
        cap = extrude_profile(Profile(circle_loop(cap_od[k] / 2), [circle_loop(cap_id[k] / 2, ccw=False)], "cap"),
                              CAP_H_MM)
        rings += [Piece(f"washer_{role}", washer, genus=1, what=f"washer under the {_WHEEL[role]}, {WASHER_T_MM:g} mm",
                        chamfer_mm=0.0),
                  Piece(f"cap_{role}", cap, genus=1, what=f"cap pressed on the {_WHEEL[role]}'s pin", chamfer_mm=0.0)][:2 if capped[k] else 1]
    pieces = [Piece("driver", driver, genus=2, what=f"driver, {d.z} teeth, m = {d.m:.4g} mm"),
              Piece("driven", driven, genus=1 + n, what=f"driven wheel, {d.z_H} teeth, {n} index mark{'s' if n != 1 else ''}"),
              Piece("base", base, genus=2, what=f"base bar, axles {L:.3f} mm apart"),
              Piece("pin_driver", pins[0], genus=0, what=f"driver axle pin ⌀{pin[0]:g}", chamfer_mm=0.0),
              Piece("pin_driven", pins[1], genus=0, what=f"driven axle pin ⌀{pin[1]:g}", chamfer_mm=0.0),
              Piece("handle", handle, genus=0, what=f"crank handle ⌀{handle_d:g}", chamfer_mm=0.0)][:6 if handle_printed else 5]
    pieces += rings
    hardware = [dowel(pin[0], pin_len, 1, "pin_driver", "the driver's axle"),
                dowel(pin[1], pin_len, 1, "pin_driven", "the driven wheel's axle")]
    hardware += [Hardware(f"DIN 125 / ISO 7089 washer for M{d_:g} — runs under the "
                          f"{_WHEEL[role]} on its pin", 1, f"washer_{role}") for d_, role in zip(pin, ("driver", "driven"))
                 if d_ == int(d_)]
    hardware += [Hardware(f"push-on retaining washer (starlock) for a ⌀{d_:g} mm steel pin — keeps the {_WHEEL[role]} on "
                          f"(no room for a printed cap beside the {'handle' if role == 'driver' else 'marks'})", 1, "")
                 for d_, role, c in zip(pin, ("driver", "driven"), capped) if not c]
    if handle_printed:
        hardware.append(dowel(handle_d, w + HANDLE_UP_MM, 1, "handle", "the crank handle"))
    else:
        hardware.append(Hardware(f"⌀{handle_d:g} mm steel pin {mm(w + HANDLE_UP_MM)} mm long — the crank handle "
                                 f"(needed: no printed handle this thin holds)", 1, ""))
    z0 = BASE_T_MM + WASHER_T_MM
    z_cap = z0 + w + PLAY_MM
    rings_at = [Placed("washer_driven", "washer_driven", place(dz=BASE_T_MM), "0.5"),
                Placed("washer_driver", "washer_driver", place(dx=L, dz=BASE_T_MM), "0.5"),
                Placed("cap_driven", "cap_driven", place(dz=z_cap), "0.3"),
                Placed("cap_driver", "cap_driver", place(dx=L, dz=z_cap), "0.3")]
    rings_at = [r for r in rings_at if not (r.label == "cap_driver" and not capped[0])
                and not (r.label == "cap_driven" and not capped[1])]
    assembly = [Placed("base", "base", place(), "0.75"), Placed("pin_driven", "pin_driven", place(), "0.4"),
                Placed("pin_driver", "pin_driver", place(dx=L), "0.4"),
                Placed("driven", "driven", place(dz=z0), "tab:blue"),
                Placed("driver", "driver", place(dx=L, dz=z0), "tab:orange"),
                Placed("handle", "handle", place(dx=L + r_h, dz=z0), "tab:red")][:6 if handle_printed else 5]
    assembly += rings_at
    prefix = "mesh" if d.method == "generated" else "sectors"
    printed_tol = _as_printed(p, kd, printer, progress)
    say("kit: the hand on the crank")
    hand, hand_text = _hand_on_crank(q, kd, proof, r_h, progress)
    checks = [Check.at_most(f"{prefix}.overlap_area", s["overlap_law_max_mm2"], 1e-6, "mm^2",
                            f"printed outlines over {s['steps']} phases of the whole cycle, "
                            f"{proof.measured_text()}")]
    checks += checks_common(proof, prefix)
    checks += printed_tol[0]
    checks += hand.checks() if hand is not None else []
    checks.append(Check.at_least(f"{prefix}.print_backlash_min", jn_min, printer.backlash_mm, "mm",
                                 f"least normal backlash of the printed teeth over the cycle (circumferential "
                                 f"{s['backlash_min_mm']:.4f} mm × cos α); designed j_n = {j_n:.4f} mm"))
    fits = [Fit("driver_on_pin", "pin_driver", "driver", (0.0, 0.0), "running", "the driver turns on its pin"),
            Fit("driven_on_pin", "pin_driven", "driven", (0.0, 0.0), "running", "the driven wheel turns on its pin"),
            Fit("pin_driven_in_base", "pin_driven", "base", (0.0, 0.0), "press", "pressed into the base"),
            Fit("pin_driver_in_base", "pin_driver", "base", (L, 0.0), "press", "pressed into the base")]
    for k, role in enumerate(("driver", "driven")):
        fits += [Fit(f"washer_{role}_on_pin", f"pin_{role}", f"washer_{role}", (0.0, 0.0), "running",
                     f"the washer under the {_WHEEL[role]}"),
                 Fit(f"cap_{role}_on_pin", f"pin_{role}", f"cap_{role}", (0.0, 0.0), "press",
                     f"the cap keeps the {_WHEEL[role]} on its pin")][:2 if capped[k] else 1]
    if handle_printed:
        fits.append(Fit("handle_in_driver", "handle", "driver", (r_h, 0.0), "press", "pressed into the driver"))
    return Kit(
        part="noncircular_pair", printer=printer, scale=choice, pieces=pieces, assembly=assembly, checks=checks,
        hardware=hardware, fits=fits,
        step_parts=[["base", "pin_driven", "pin_driver"], ["washer_driven", "washer_driver"], ["driver", "handle"],
                    ["driven"], [r.label for r in rings_at if r.label.startswith("cap")], []],
        derived={"print_module_mm": d.m, "print_center_distance_mm": L, "print_face_width_mm": w,
                 "print_backlash_n_design_mm": j_n, "print_backlash_n_min_mm": jn_min,
                 "print_backlash_t_max_mm": s["backlash_max_mm"], "pin_driver_d_mm": pin[0], "pin_driven_d_mm": pin[1],
                 **(hand.derived() if hand is not None else {})},
        allowances=[("gear backlash (normal)", j_n, "teeth thinned by j_n / (2 cos α) each, axes at the design L"),
                    ("running clearance", clear, f"bores ⌀{bores[0]:.2f} / ⌀{bores[1]:.2f} on pins ⌀{pin[0]:g} / ⌀{pin[1]:g}"),
                    ("press fit", press, "pins and handle interference (radial)"),
                    ("hole undersize", under, "added to every hole's diameter"),
                    ("bed-side chamfer", ch, "45° round the face each piece lies on, made layer by layer as the slicer sees it")],
        steps=[f"Press the two pins into the base bar (⌀{pin[1]:g} into the hole at the bar's wide-spaced end, the "
               f"driven axle; ⌀{pin[0]:g} into the other), flat faces down.",
               "Put a washer over each pin (the larger hole on the larger pin).",
               "Press the handle into the small hole of the driver.",
               "Put the driven wheel on its pin with its mark 1 (the index hole on the line of centres, away from "
               "the driver) and the driver on its pin with the handle towards the driven wheel; the teeth mesh.",
               _keep_on_step(capped),
               (f"Turn the handle: each driver turn the next of the driven wheel's {n} marks reaches the line of centres; "
                f"{n} turns bring the driven wheel once round, its speed varying as the law asks." if n != 1 else
                "Turn the handle: one driver turn brings the driven wheel once round (its mark back on the line of "
                "centres), its speed varying as the law asks.")],
        expected_failures=_documented_jam(source, prefix),
        guide_notes=printed_tol[1],
        material_notes=hand_text, material_table=hand.guide_table() if hand is not None else None,
        tables=[("hand_load", HAND_TABLE_COLUMNS, hand.table_rows())] if hand is not None else [],
        notes=([] if not _documented_jam(source, prefix) else [
            "The part file documents that the papers' sector teeth jam (its [meta] expected_failures); the kit "
            "prints those teeth at print scale with the printer's backlash, and they still overlap: printed, the "
            "pair shows the jam the generated teeth (ncg_seed000.toml / ncg_seed002.toml) remove."])
        + ([hand.note()] if hand is not None else hand_text))


def _hand_on_crank(q: NoncircularPairParams, kd, proof, r_h: float, progress=None):
    """(HandLoad or None, the guide's paragraphs): the torque a hand puts on the crank, rated on the printed pair
    for every printed material (:mod:`.kit_load`); not rated for the papers' sector teeth (no tooth record) nor a
    pair the proof finds jammed (no running position to load)."""
    import numpy as np

    if kd.d.method != "generated":
        return None, ["The hand on the crank is not rated: the papers' sector teeth have no tooth record for the load "
                      "per tooth (the generated teeth have)."]
    if proof.jams or not np.all(np.isfinite(proof.phi_drive)):
        return None, ["The hand on the crank is not rated: the printed pair jams (no running position to load)."]
    from ...progress import count_to

    hand = hand_load(q, kd, r_h, count=count_to(progress, "kit: the hand on the crank", "rating"))
    return hand, hand.guide_lines()


def _base_profile(L: float, R: float, holes_d) -> Profile:
    """A stadium bar of radius R round the two axles (0, 0) and (L, 0) with the pins' holes."""
    from ...geometry.profile import Arc, Line, Loop

    outer = Loop([Line((0.0, -R), (L, -R)), Arc((L, 0.0), R, -math.pi / 2, math.pi / 2),
                  Line((L, R), (0.0, R)), Arc((0.0, 0.0), R, math.pi / 2, 3 * math.pi / 2)])
    return Profile(outer, [circle_loop(holes_d[1] / 2, (0.0, 0.0), ccw=False),
                           circle_loop(holes_d[0] / 2, (L, 0.0), ccw=False)], "base")
