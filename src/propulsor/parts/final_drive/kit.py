"""Print kit of the planetary final drive: ring with its floor as the base, sun on a shaft with a
crank, the planets on the carrier's pins; the carrier turns as the output.

The set is designed anew at the print module (module, face widths, ring rim shrink by S; tooth
counts, shifts and the shaper stay), every tooth thinned by E_sn so that each mesh has the printer's
normal backlash with a margin (raised once by the shortfall when the carrier sweep measures less),
no keyway and no ring bolts (the ring is one piece with its floor).  The proof is the part's own
sweep of all meshes over one carrier turn, on the printed outlines.

Stack (z up, the floor on the desk): ring and floor 0 … t_f + b_ring; sun and planets on the floor
from t_f; the carrier disc above the gears with its pins down into the planets; the shaft through
floor, sun and carrier; the crank pressed on the shaft's top.
"""

from __future__ import annotations

import dataclasses
import math

from ...check import Check
from ...geometry.profile import Arc, Line, Loop, Profile, circle_loop
from ...params import load_params, params_to_dict
from ...printing.fits import Fit, Rim
from ...printing.hardware import dowel, side_pin
from ...printing.kit import Kit, Piece, Placed, place
from ...printing.printers import Printer
from ...printing.scale import check_printable, choose_scale
from .design import body_offsets, design, planetary_set, ring_outer_d
from .params import FinalDriveParams
from .proofs import carrier_sweep

__all__ = ["kit"]

#: floor, carrier and crank thickness, wall round the carrier's pins, gap carrier-gears, crank arm (mm)
FLOOR_T_MM, CARRIER_T_MM, CRANK_T_MM, PIN_WALL_MM, GAP_MM, CRANK_ARM_MM = 4.0, 5.0, 5.0, 6.0, 0.5, 30.0
#: printed shaft / pin diameter range (mm), crank handle diameter and height (mm)
PIN_D_MIN_MM, PIN_D_MAX_MM, HANDLE_D_MM, HANDLE_H_MM = 5.0, 12.0, 8.0, 20.0


def _kit_params(p: FinalDriveParams, ps, S: float, thinning: float, sun_hole: float, planet_hole: float):
    q = dataclasses.replace(
        p, module_mm=p.module_mm / S, width_sun_mm=p.width_sun_mm / S, width_planet_mm=p.width_planet_mm / S,
        width_ring_mm=p.width_ring_mm / S, tooth_thinning_mm=thinning, sun_bore_mm=sun_hole, sun_keyway=False,
        planet_bore_mm=planet_hole, ring_outer_d_mm=ring_outer_d(p, ps) / S, ring_bolts=0,
        x_ring=ps.x_ring, ring_shift_for_coaxiality=False)
    return load_params(FinalDriveParams, params_to_dict(q))


def _stadium(length: float, r: float) -> Loop:
    return Loop([Line((0.0, -r), (length, -r)), Arc((length, 0.0), r, -math.pi / 2, math.pi / 2),
                 Line((length, r), (0.0, r)), Arc((0.0, 0.0), r, math.pi / 2, 3 * math.pi / 2)])


def kit(p: FinalDriveParams, printer: Printer, scale: float | None = None, source=None) -> Kit:
    from ...gears.planetary_kinematics import PlanetaryKinematics
    from ...solids.build import extrude_profile
    from ...solids.kernel import cylinder, fuse

    ps = planetary_set(p)
    D = ring_outer_d(p, ps)
    bed = (printer.bed_x_mm, printer.bed_y_mm, printer.bed_z_mm)
    extents = {"ring": (D, D, p.width_ring_mm), "sun": (ps.d_a_sun, ps.d_a_sun, p.width_sun_mm),
               "planet": (ps.d_a_planet, ps.d_a_planet, p.width_planet_mm),
               "carrier": (2 * ps.a_w + ps.d_a_planet, 2 * ps.a_w + ps.d_a_planet, p.width_planet_mm)}
    choice = choose_scale(extents, bed, scale, margin=printer.margin_mm)
    S = choice.S
    check_printable(S, p.module_mm, printer.min_module_mm, choice=choice)
    clear, under, press = printer.running_clearance_mm, printer.hole_undersize_mm, printer.press_fit_mm
    shaft_d = min(PIN_D_MAX_MM, max(PIN_D_MIN_MM, (p.sun_bore_mm or 0.4 * ps.sun.d_f) / S))
    pin_d = min(PIN_D_MAX_MM, max(PIN_D_MIN_MM, (p.planet_bore_mm or 0.4 * ps.planet.d_f) / S))
    sun_hole = shaft_d - 2 * press + under
    planet_hole = pin_d + 2 * clear + under
    run_hole = shaft_d + 2 * clear + under
    alpha = math.radians(20.0)
    thinning = 1.1 * printer.backlash_mm / (2 * math.cos(alpha))
    for attempt in range(2):
        q = _kit_params(p, ps, S, thinning, sun_hole, planet_hole)
        dd = design(q)
        sweeps = carrier_sweep(q, dd.ps, dd.outlines)
        overlap = max(float(s.overlap_mm2.max()) for s in sweeps)
        least = min(float(s.clearance_mm.min()) for s in sweeps)
        if 2 * least >= printer.backlash_mm or attempt == 1:
            break
        thinning *= printer.backlash_mm / (2 * least) * 1.05
    qs = dd.ps
    sun_o, planet_o, ring_o = dd.outlines
    t_f, b_r, b_s, b_p = FLOOR_T_MM, q.width_ring_mm, q.width_sun_mm, q.width_planet_mm
    Dq = ring_outer_d(q, qs)
    ch = printer.chamfer_mm
    # ring and floor, one piece
    floor = extrude_profile(Profile(circle_loop(Dq / 2), [circle_loop(run_hole / 2, ccw=False)], "floor"), t_f)
    ring = fuse(floor, extrude_profile(ring_o.profile, t_f + b_r), name="ring with floor")
    sun = extrude_profile(sun_o.profile, b_s)
    planet = extrude_profile(planet_o.profile, b_p)
    # carrier, printed disc down and pins up; assembled the other way round
    kin = PlanetaryKinematics(q.z_sun, q.z_planet, q.z_ring, q.n_planets, qs.a_w)
    R_c = min(qs.a_w + pin_d / 2 + PIN_WALL_MM, 0.5 * abs(qs.d_a_ring) - 1.0)
    pin_len = b_p - 1.0
    #: the planets' pins on the carrier, as drawn (x, y) mm
    pins_at = tuple(tuple(float(v) for v in kin.planet_centre(0.0, k)) for k in range(q.n_planets))
    pins = [cylinder(pin_d / 2, CARRIER_T_MM - 0.01, CARRIER_T_MM + pin_len, center=c) for c in pins_at]
    disc = extrude_profile(Profile(circle_loop(R_c), [circle_loop(run_hole / 2, ccw=False)], "carrier"), CARRIER_T_MM)
    carrier = fuse(disc, *pins, name="carrier with pins")
    # shaft through floor, sun, carrier; crank pressed on its top
    shaft_len = t_f + b_s + GAP_MM + CARRIER_T_MM + CRANK_T_MM
    shaft = side_pin(shaft_d, shaft_len)
    arm = Profile(_stadium(CRANK_ARM_MM, shaft_d / 2 + 5.0), [circle_loop(sun_hole / 2, ccw=False)], "crank")
    crank = fuse(extrude_profile(arm, CRANK_T_MM),
                                cylinder(HANDLE_D_MM / 2, CRANK_T_MM - 0.01, CRANK_T_MM + HANDLE_H_MM,
                                         center=(CRANK_ARM_MM, 0.0)), name="crank")
    pieces = [Piece("ring", ring, genus=1, what=f"ring, {q.z_ring} teeth, with its floor (the base)"),
              Piece("sun", sun, genus=1, what=f"sun, {q.z_sun} teeth"),
              Piece("planet", planet, count=q.n_planets, genus=1, what=f"planet, {q.z_planet} teeth"),
              Piece("carrier", carrier, genus=1, what=f"carrier with {q.n_planets} pins ⌀{pin_d:g}"),
              Piece("shaft", shaft, genus=0, what=f"sun shaft ⌀{shaft_d:g}", chamfer_mm=0.0),
              Piece("crank", crank, genus=1, what="crank with handle")]
    off_ext, off_ring = body_offsets(q.z_ring)
    z_top = t_f + b_p + GAP_MM
    assembly = [Placed("ring", "ring", place(rot_z=kin.ring_rotation + off_ring), "0.7"),
                Placed("sun", "sun", place(dz=t_f, rot_z=off_ext), "tab:orange")]
    for k in range(q.n_planets):
        c = kin.planet_centre(0.0, k)
        assembly.append(Placed(f"planet_{k + 1}", "planet", place(dx=float(c[0]), dy=float(c[1]), dz=t_f,
                                                                  rot_z=float(kin.planet_angle(0.0, k)) + off_ext),
                               "tab:green"))
    assembly += [Placed("carrier", "carrier", place(flip="x", z_top=z_top + CARRIER_T_MM + pin_len), "tab:blue"),
                 Placed("shaft", "shaft", place(), "0.3"),
                 Placed("crank", "crank", place(dz=shaft_len - CRANK_T_MM), "tab:red")]
    checks = [Check.at_most("mesh.overlap_area", overlap, 1e-6, "mm^2",
                            f"largest overlap of the {len(sweeps)} printed meshes over one carrier turn "
                            f"({len(sweeps[0].psi)} steps)"),
              Check.at_least("mesh.print_backlash_min", 2 * least, printer.backlash_mm, "mm",
                             f"twice the least flank clearance at the nominal positions ({least:.4f} mm): a lower "
                             f"bound of the normal backlash of every printed mesh; E_sn = {thinning:.4f} mm per gear"),
              Check.greater_than("fit.carrier_inside_ring", 0.5 * abs(qs.d_a_ring) - R_c, 0.0, "mm",
                                 f"carrier radius {R_c:.2f} mm inside the ring's tip circle")]
    fits = [Fit(f"planet_on_pin_{k + 1}", "carrier", "planet", (0.0, 0.0), "running", "each planet turns on its pin",
                pin_at=pins_at[k], pin_z=(CARRIER_T_MM, CARRIER_T_MM + pin_len))
            for k in range(q.n_planets)]
    fits.append(Rim("pins_on_carrier", "carrier", pins_at, disc_z=(0.0, CARRIER_T_MM),
                    pin_z=(CARRIER_T_MM, CARRIER_T_MM + pin_len), what="the carrier's rim outside its pins"))
    fits += [Fit("shaft_in_floor", "shaft", "ring", (0.0, 0.0), "running", "the shaft turns in the ring's floor"),
             Fit("shaft_in_carrier", "shaft", "carrier", (0.0, 0.0), "running", "the carrier turns on the shaft"),
             Fit("sun_on_shaft", "shaft", "sun", (0.0, 0.0), "press", "the sun pressed on the shaft"),
             Fit("crank_on_shaft", "shaft", "crank", (0.0, 0.0), "press", "the crank pressed on the shaft")]
    return Kit(
        fits=fits,
        hardware=[dowel(shaft_d, shaft_len, 1, "shaft", "the sun's shaft")],
        step_parts=[["sun", "shaft"], ["ring"], [f"planet_{k + 1}" for k in range(q.n_planets)], ["carrier"], ["crank"],
                    []],
        part="planetary_final_drive", printer=printer, scale=choice, pieces=pieces, assembly=assembly, checks=checks,
        derived={"print_module_mm": q.module_mm, "print_a_w_mm": qs.a_w, "print_ring_outer_d_mm": Dq,
                 "print_tooth_thinning_mm": thinning, "print_least_flank_clearance_mm": least,
                 "shaft_d_mm": shaft_d, "pin_d_mm": pin_d},
        allowances=[("gear backlash (normal, each mesh)", 2 * thinning * math.cos(alpha),
                     f"every tooth thinned by E_sn = {thinning:.4f} mm, axes at the design a_w"),
                    ("running clearance", clear, f"planets on ⌀{pin_d:g} pins, shaft in floor and carrier"),
                    ("press fit", press, "sun and crank on the shaft (radial)"),
                    ("hole undersize", under, "added to every hole's diameter"),
                    ("bed-side chamfer", ch, "45° round the face each piece lies on, made layer by layer as the slicer sees it")],
        steps=["Press the shaft into the sun from below until its end is flush with the sun's bottom face.",
               "Put the shaft through the hole in the ring's floor: the sun sits on the floor.",
               f"Put the {q.n_planets} planets into the ring, each meshing with the sun and the ring "
               f"(the tooth counts satisfy the assembly condition: (z_sun + z_ring)/{q.n_planets} is whole).",
               "Lower the carrier, pins down, over the shaft so that each pin enters a planet.",
               "Press the crank onto the shaft's top.",
               f"Turn the crank: the carrier turns i_1H = {qs.ratio:.4g} times slower, the same way round."])
