"""Print kit of the composite (polysector) gear: the six sectors, one hub disc carrying both flows, the
solid gear, a base with the wheel's axle and a hole for the gear's axle at every position's centre distance,
press-fit pins, a crank handle.

The gear set is designed anew at the print module (tooth counts, positions and the layout's shape
stay; module, face width, hub, stems and holes shrink by S), every tooth thinned by E_sn so that the
mesh has the printer's normal backlash with a margin (raised once by the shortfall when the proof
measures less), no keyways; the bores run on printed axle pins with the running clearance.  In print
the two flow discs become one disc between the two layers of sectors (flow 1 hangs below it, flow 2
sits on it), so the flows cannot turn against each other; its pin holes serve both flows and every
position.  The proof is the part's own proof of that position (:mod:`.mesh_proof`) on the printed
outlines: overlap 0 in each flow's plane, contact never lost, and the least normal backlash.

Stack (z up, the base on the desk): base 0 … t_b; flow-1 sectors from t_b + gap, the hub disc on
them, flow-2 sectors on the disc; the gear beside them on its own axle from t_b + gap, as wide as
the stack; the crank handle pressed into the disc between a flow-1 and a flow-2 stem.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ...check import Check
from ...errors import InputError
from ...geometry.profile import Arc, Line, Loop, Profile, circle_loop
from ...params import load_params, params_to_dict
from ...printing.fits import Fit
from ...printing.hardware import dowel, side_pin
from ...printing.kit import Kit, Piece, Placed, place
from ...printing.printers import Printer
from ...printing.scale import check_printable, choose_scale, larger
from ...printing.scale import fits as fits_bed
from .params import PolysectorParams

__all__ = ["kit"]

#: base bar thickness, wall round each axle pin, gap base–wheels, handle diameter and its height above the stack
BASE_T_MM, BOSS_WALL_MM, GAP_MM, HANDLE_D_MM, HANDLE_UP_MM = 6.0, 6.0, 0.5, 6.0, 15.0
#: printed axle pin diameter range (mm)
PIN_D_MIN_MM, PIN_D_MAX_MM = 5.0, 12.0
#: least normal backlash measured / designed j_n; the design starts from the target over this
JN_MEASURED_RATIO = 0.95


def _kit_params(p: PolysectorParams, S: float, thinning: float, wheel_bore: float, gear_bore: float):
    q = dataclasses.replace(
        p, module_mm=p.module_mm / S, face_width_mm=p.face_width_mm / S, hub_thickness_mm=p.hub_thickness_mm / S,
        stem_width_mm=p.stem_width_mm / S, shaft_d_mm=wheel_bore, gear_bore_mm=gear_bore, bolt_d_mm=p.bolt_d_mm / S,
        pin_d_mm=p.pin_d_mm / S, web_mm=p.web_mm / S, tooth_thinning_mm=thinning, keyways=False)
    return load_params(PolysectorParams, params_to_dict(q))


def _stadium(L: float, R: float) -> Loop:
    return Loop([Line((0.0, -R), (L, -R)), Arc((L, 0.0), R, -math.pi / 2, math.pi / 2),
                 Line((L, R), (0.0, R)), Arc((0.0, 0.0), R, math.pi / 2, 3 * math.pi / 2)])


def base_holes(centre_distances, hole_d: float, wall: float) -> list[tuple[float, float]]:
    """Centres of the gear axle's holes in the base, one a position: hole k at its centre distance a_k
    from the wheel's axle (at the origin), turned about it so that neighbouring holes keep `wall`
    between them; the last position's on the x axis."""
    a = list(centre_distances)
    need = hole_d + wall
    step = 2.0 * math.asin(min(1.0, 0.5 * need / min(a))) if len(a) > 1 else 0.0
    n = len(a)
    return [(r * math.cos(-(n - 1 - k) * step), r * math.sin(-(n - 1 - k) * step)) for k, r in enumerate(a)]


def _base_extents(centres, R: float) -> tuple[float, float]:
    xs = [0.0] + [c[0] for c in centres]
    ys = [0.0] + [c[1] for c in centres]
    return max(xs) - min(xs) + 2 * R, max(ys) - min(ys) + 2 * R


def _extent(profile: Profile) -> tuple[float, float]:
    pts = profile.outer.polyline(0.05)
    return tuple(float(v) for v in (pts.max(axis=0) - pts.min(axis=0)))


def _sector_pin_fits(lay, kd, pos) -> list[Fit]:
    """The sector pins pressed into their printed holes: the locating pin into the sector's pin hole and
    into the disc's hole of the kit's position, the clamping pin into the sector's slot (where the bolt
    stands at that position) and into the disc's bolt hole.  Every sector prints from the one `sector`
    piece (its holes are measured once); the disc's holes are measured for each sector."""
    e = pos.offset
    fits = [Fit("locating_pin_in_sector", "locating_pin", "sector", (lay.x_pin, lay.y_pin), "press",
                "the locating pin pressed into the sector's pin hole (every sector prints from this piece)"),
            Fit("clamp_pin_in_sector_slot", "clamp_pin", "sector", (0.0, lay.rho_bolt - e), "press",
                f"the clamping pin pressed into the sector's slot where it stands at position {pos.k} (every sector "
                f"prints from this piece)", slot=True)]
    for f in range(1, kd.p.flows + 1):
        for j, ang in enumerate(kd.sector_angles(f), 1):
            c, s = math.cos(ang - math.pi / 2), math.sin(ang - math.pi / 2)

            def rot(x, y):
                return (c * x - s * y, s * x + c * y)

            fits += [Fit(f"locating_pin_in_disc_sector_{f}_{j}", "locating_pin", "hub_disc", rot(lay.x_pin, lay.y_pin + e),
                         "press", f"sector {f}.{j}'s locating pin in the disc's hole of position {pos.k}"),
                     Fit(f"clamp_pin_in_disc_sector_{f}_{j}", "clamp_pin", "hub_disc", rot(0.0, lay.rho_bolt), "press",
                         f"sector {f}.{j}'s clamping pin in the disc's bolt hole")]
    return fits


def kit(p: PolysectorParams, printer: Printer, scale: float | None = None, source=None) -> Kit:
    from ...geometry.polysector_outline import hub_profile
    from ...solids.build import extrude_profile
    from ...solids.kernel import cylinder
    from ..pipeline import design_of
    from .design import design
    from .mesh_proof import prove_position
    from .proofs import chord_for, law_checks

    full = design_of(p, design)
    pos_full = full.positions[-1]
    b, t = p.face_width_mm, p.hub_thickness_mm
    stack = 2 * b + t
    pin_full = [min(PIN_D_MAX_MM, max(PIN_D_MIN_MM, d)) for d in (p.shaft_d_mm, p.gear_bore_mm)]
    R_boss = max(pin_full) / 2 + BOSS_WALL_MM
    extents = {"gear": (2 * full.geo.r_a2, 2 * full.geo.r_a2, stack),
               "hub_disc": (2 * full.layout.R_hub, 2 * full.layout.R_hub, t),
               "sector": (*_extent(full.sector), b),
               "base": (*_base_extents(base_holes([x.a for x in full.positions], max(pin_full), BOSS_WALL_MM),
                                       R_boss), BASE_T_MM)}
    choice = choose_scale(extents, printer.bed, scale, margin=printer.margin_mm)
    S = choice.S
    check_printable(S, p.module_mm, printer.min_module_mm, choice=choice)
    clear, under, press = printer.running_clearance_mm, printer.hole_undersize_mm, printer.press_fit_mm
    pin = [min(PIN_D_MAX_MM, max(PIN_D_MIN_MM, d / S)) for d in (p.shaft_d_mm, p.gear_bore_mm)]
    bores = [d + 2 * clear + under for d in pin]
    alpha = math.radians(p.pressure_angle_deg)
    j_n = printer.backlash_mm / JN_MEASURED_RATIO
    for attempt in range(2):
        q = _kit_params(p, S, j_n / (2 * math.cos(alpha)), bores[0], bores[1])
        kd = design_of(q, design)
        pos = kd.positions[-1]
        proof = prove_position(kd, pos, None, chord_for(kd, pos))
        jn_min = float(np.nanmin(proof.coast_room)) * kd.geo.r_b2
        if jn_min >= printer.backlash_mm or attempt == 1:
            break
        j_n += 1.1 * (printer.backlash_mm - jn_min)
    b, t = q.face_width_mm, q.hub_thickness_mm
    lay, i_s = kd.layout, q.sectors_per_flow
    angles = kd.sector_angles(1) + (kd.sector_angles(2) if q.flows == 2 else [])
    disc = hub_profile(lay, angles, [x.offset for x in kd.positions], keyway=False)
    # the crank handle's hole: between flow 1's first stem and flow 2's first, clear of every flow-2 sector
    r_h = 0.5 * (bores[0] / 2 + lay.R_hub)
    a_h = 0.5 * math.pi / i_s
    c_h = (r_h * math.cos(a_h), r_h * math.sin(a_h))
    handle_hole = HANDLE_D_MM - 2 * press + under
    room = min(float(np.min(np.hypot(*(s.outer.polyline(0.05) - np.array(c_h)).T)))
               for f in (1, 2)[:q.flows] for s in kd.placed_sectors(pos, f))
    room = min(room, lay.R_hub - r_h, r_h - bores[0] / 2)
    for hole in disc.holes[1:]:
        hp = hole.polyline(0.05)
        room = min(room, float(np.min(np.hypot(*(hp - np.array(c_h)).T))))
    if room - HANDLE_D_MM / 2 < printer.min_feature_mm:
        raise InputError("--scale", choice.label, f"the hub disc has no room for the {HANDLE_D_MM:g} mm crank handle "
                         f"({room:.2f} mm from its centre to the nearest edge); {larger(choice.S)}")
    disc = Profile(disc.outer, list(disc.holes) + [circle_loop(handle_hole / 2, c_h, ccw=False)], "hub disc")
    ch = printer.chamfer_mm
    sector = extrude_profile(kd.sector, b)
    hub = extrude_profile(disc, t)
    gear = extrude_profile(kd.gear_profile, 2 * b + t)
    L = pos.a
    R_boss = max(pin) / 2 + BOSS_WALL_MM
    # the gear axle's hole for every position, each at its centre distance from the wheel's axle
    holes_at = base_holes([x.a for x in kd.positions], pin[1], max(printer.min_feature_mm, 2.0))
    bx, by = _base_extents(holes_at, R_boss)
    if not fits_bed((bx, by, BASE_T_MM), (printer.bed_x_mm - 2 * printer.margin_mm,
                                      printer.bed_y_mm - 2 * printer.margin_mm, printer.bed_z_mm)):
        raise InputError("--scale", choice.label, f"the base ({bx:.0f} × {by:.0f} mm) does not fit the bed; a larger "
                         f"reduction fits")
    from ...geometry.profile import hull_of_circles

    base_prof = Profile(hull_of_circles([((0.0, 0.0), R_boss)] + [(c, R_boss) for c in holes_at]),
                        [circle_loop((pin[0] - 2 * press + under) / 2, (0.0, 0.0), ccw=False)]
                        + [circle_loop((pin[1] - 2 * press + under) / 2, c, ccw=False) for c in holes_at], "base")
    base = extrude_profile(base_prof, BASE_T_MM)
    axle_len = BASE_T_MM + GAP_MM + 2 * b + t + 1.0
    axles = [side_pin(d, axle_len) for d in pin]
    # sector pins: each presses through the sector into the disc (the holes print `under` small)
    d_loc = lay.d_pin - under + 2 * press
    d_clamp = lay.d_bolt - under + 2 * press
    pin_len = b + t - GAP_MM
    loc_pin = side_pin(d_loc, pin_len)
    clamp_pin = side_pin(d_clamp, pin_len)
    handle = side_pin(HANDLE_D_MM, t + b + HANDLE_UP_MM)
    n_sec = q.flows * i_s
    n_pos = len(kd.positions)
    pieces = [Piece("gear", gear, genus=1, what=f"solid gear, {q.gear_teeth} teeth, m = {q.module_mm:.4g} mm"),
              Piece("hub_disc", hub, genus=1 + n_sec * (1 + n_pos) + 1,
                    what=f"hub disc of both flows, a pin hole per sector and position ({n_pos} positions)"),
              Piece("sector", sector, count=n_sec, genus=2, what=f"sector of {q.sector_teeth} teeth"),
              Piece("base", base, genus=1 + len(holes_at), what=f"base with the gear axle's hole for each of the "
                    f"{len(holes_at)} positions ({', '.join(f'{x.a:.1f}' for x in kd.positions)} mm from the wheel's)"),
              Piece("axle_wheel", axles[0], genus=0, what=f"wheel axle pin ⌀{pin[0]:g}", chamfer_mm=0.0),
              Piece("axle_gear", axles[1], genus=0, what=f"gear axle pin ⌀{pin[1]:g}", chamfer_mm=0.0),
              Piece("locating_pin", loc_pin, count=n_sec, genus=0, what=f"sector locating pin ⌀{d_loc:.2f}", chamfer_mm=0.0),
              Piece("clamp_pin", clamp_pin, count=n_sec, genus=0, what=f"sector clamping pin ⌀{d_clamp:.2f}", chamfer_mm=0.0),
              Piece("handle", handle, genus=0, what=f"crank handle ⌀{HANDLE_D_MM:g}", chamfer_mm=0.0)]
    z0 = BASE_T_MM + GAP_MM
    assembly = [Placed("base", "base", place(), "0.75"), Placed("axle_wheel", "axle_wheel", place(), "0.4"),
                Placed("axle_gear", "axle_gear", place(dx=L), "0.4"),
                Placed("hub_disc", "hub_disc", place(dz=z0 + b), "0.6"),
                Placed("gear", "gear", place(dx=L, dz=z0), "tab:blue"),
                Placed("handle", "handle", place(dx=c_h[0], dy=c_h[1], dz=z0 + b), "tab:red")]
    for f in range(1, q.flows + 1):
        for j, ang in enumerate(kd.sector_angles(f)):
            at = place(dx=pos.offset * math.cos(ang), dy=pos.offset * math.sin(ang),
                       dz=z0 + (0.0 if f == 1 else b + t), rot_z=ang - math.pi / 2)
            assembly.append(Placed(f"sector_{f}_{j + 1}", "sector", at, "tab:orange" if f == 1 else "tab:green"))
    tol = 1e-6
    checks = [Check.at_most("mesh.overlap_area", float(proof.overlap_flow.max()), tol, "mm^2",
                            f"printed outlines, position {pos.k}, {len(proof.phi)} steps of a sector period, both flows"),
              Check.at_least("mesh.contact_continuity", int(proof.pairs.min()), 1, "pairs",
                             "tooth pairs in contact, both flows together"),
              Check.at_least("mesh.print_backlash_min", jn_min, printer.backlash_mm, "mm",
                             f"least normal backlash of the printed teeth (free turn of the gear × r_b2); designed "
                             f"j_n = {j_n:.4f} mm")]
    checks += law_checks("mesh", proof.law)
    fits = [Fit("wheel_on_axle", "axle_wheel", "hub_disc", (0.0, 0.0), "running", "the wheel turns on its axle"),
            Fit("gear_on_axle", "axle_gear", "gear", (0.0, 0.0), "running", "the gear turns on its axle"),
            Fit("axle_wheel_in_base", "axle_wheel", "base", (0.0, 0.0), "press", "pressed into the base"),
            *[Fit(f"axle_gear_in_base_position_{x.k}", "axle_gear", "base", c, "press",
                  f"the gear axle's hole of position {x.k}") for x, c in zip(kd.positions, holes_at)],
            Fit("handle_in_disc", "handle", "hub_disc", c_h, "press", "the handle pressed into the disc"),
            *_sector_pin_fits(lay, kd, pos)]
    return Kit(
        fits=fits,
        hardware=[dowel(pin[0], axle_len, 1, "axle_wheel", "the wheel's axle"),
                  dowel(pin[1], axle_len, 1, "axle_gear", "the gear's axle"),
                  dowel(HANDLE_D_MM, t + b + HANDLE_UP_MM, 1, "handle", "the crank handle")],
        step_parts=[["base", "axle_wheel", "axle_gear"],
                    ["hub_disc"] + [f"sector_{f}_{j + 1}" for f in range(1, q.flows + 1) for j in range(len(kd.sector_angles(f)))],
                    ["handle"], ["gear"], []],
        part="polysector_gear", printer=printer, scale=choice, pieces=pieces, assembly=assembly, checks=checks,
        derived={"print_module_mm": q.module_mm, "print_center_distance_mm": L, "print_position": pos.k,
                 "print_offset_mm": pos.offset, "print_face_width_mm": b, "print_backlash_n_design_mm": j_n,
                 "print_backlash_n_min_mm": jn_min, "axle_wheel_d_mm": pin[0], "axle_gear_d_mm": pin[1]},
        allowances=[("gear backlash (normal)", j_n, "every tooth thinned by j_n / (2 cos α), axes at the design a"),
                    ("running clearance", clear, f"bores ⌀{bores[0]:.2f} / ⌀{bores[1]:.2f} on pins ⌀{pin[0]:g} / "
                                                 f"⌀{pin[1]:g}"),
                    ("press fit", press, "axle pins in the base, sector pins, handle (radial)"),
                    ("hole undersize", under, "added to every running hole's diameter"),
                    ("bed-side chamfer", ch, "45° round the face each piece lies on, made layer by layer as the slicer sees it")],
        steps=[f"Press the axle pins into the base: ⌀{pin[0]:g} (wheel) into the single hole, ⌀{pin[1]:g} (gear) into "
               f"the hole of position {pos.k}, the last of the row of {len(holes_at)} (one a position, each at its "
               f"centre distance from the wheel's axle).",
               f"Set the sectors at position {pos.k} (offset {pos.offset:.3f} mm): lay a sector on the disc with its "
               f"stem along a row of pin holes, the locating pin through its pin hole into hole {pos.k} of the row "
               f"(counted from the centre), the clamping pin through its slot into the disc's bolt hole. Three "
               f"sectors on the underside (flow 1, the rows with the bolt hole on the first side), three on top "
               f"(flow 2), turned half a sector pitch.",
               "Press the handle into the disc's single hole on the top side.",
               "Put the wheel on its axle (flow 1 down) and the gear on the other; the teeth mesh with both layers.",
               f"Turn the handle: one turn of the wheel turns the gear {1 / pos.ratio_nominal:.4f} times; to change "
               f"the ratio move the sectors to another row hole and the gear axle to that position's hole in the base."])
