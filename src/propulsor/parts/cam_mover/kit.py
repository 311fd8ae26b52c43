"""Print kit of the cam mover (seed 001): the fixed cam plate as the base, the carrier turning on a
pressed-in axle, the legs sliding in its slides with their rollers in the channel, the shoes on
the legs' ends, a crank handle in the carrier.

The mechanism is planned anew at print scale 1:S with the law of the full-size design (the
curvature K scales as 1/length: k0 × S for every family, k1 unchanged; loads ÷ S² keep the Hertz
stress): every length of the part file ÷ S, so the channel, shoes and carrier are the full-size
ones reduced exactly.  The FDM allowances are then put into the geometry:

* the roller is printed smaller by the running clearance plus half the holes' undersize (radius), so
  that with its centre on the design path it clears the working wall by the running clearance once
  the channel prints narrow, and the outer wall by that plus the scaled channel clearance;
* the slides are drawn wider by the running clearance plus half the undersize on each side;
* the rollers run on the legs' pins, the carrier on the axle (bores: running clearance + undersize);
  the axle and the handle are pressed in (press fit), the shoes pushed onto the legs' ends;
* the channel's axial gaps and the cam-to-carrier gap are at least the running clearance, the
  latter kept by a printed spacer ring round the axle.

The proof is the part's own 2D sweep (:func:`.proofs.motion_proofs`) on these printed outlines over
a whole carrier turn: roller against both channel walls, legs in their slides, shoes against the
carrier, neighbouring and opposite legs with their shoes.  Stack on the desk (z up): cam plate
(base) 0 … t_p, channel t_p … t_p + d_g, spacer, carrier with legs and shoes above.
"""

from __future__ import annotations

import dataclasses
import math

from ...check import Check
from ...errors import InputError
from ...geometry import cam_outlines as co
from ...geometry.profile import Profile, circle_loop
from ...params import load_params, params_to_dict
from ...printing.fits import Fit
from ...printing.kit import Kit, Piece, Placed, place
from ...printing.printers import Printer
from ...printing.hardware import PRINTED_PIN_MIN_MM, dowel, mm, pin_diameter, side_pin
from ...printing.scale import STANDARD_SCALES, check_printable, choose_scale, larger
from .design import plan
from .params import MIN_WEB_MM, CamMoverParams
from .proofs import leg_poses, motion_proofs

__all__ = ["kit", "print_params"]

#: printed axle diameter range, handle diameter and height above the carrier, axle stick-out (mm)
AXLE_D_MIN_MM, AXLE_D_MAX_MM, HANDLE_D_MM, HANDLE_UP_MM, AXLE_TOP_MM = 5.0, 12.0, 6.0, 15.0, 2.0
#: least thickness of the printed spacer between cam and carrier (mm): five 0.2 mm layers
SPACER_T_MIN_MM = 1.0
#: added to every drawn running clearance (mm): the sweep measures on polylines within the motion chord
#: tolerance of the exact curves, and the check must not hang on the last digit
DRAW_MARGIN_MM = 0.01
#: sweep steps of the kit's proof per carrier turn (the part's own proof uses its sweep_steps)
KIT_SWEEP_STEPS = 720


def _full_size_extents(pl) -> dict:
    """Laid-flat extents (x, y, z) of the full-size pieces, mm."""
    p = pl.params
    z = pl.z
    shoe = pl.shoe.profile.outer.polyline(0.05)
    sx, sy = (shoe.max(axis=0) - shoe.min(axis=0))
    leg_len = p.leg_back_mm + p.leg_mount_mm + p.socket_depth_mm
    return {"cam": (2 * pl.rim_radius, 2 * pl.rim_radius, z["channel"][1]),
            "carrier": (2 * p.carrier_radius_mm, 2 * p.carrier_radius_mm, p.carrier_thickness_mm),
            "shoe": (float(sx), float(sy), p.shoe_width_mm),
            "leg": (p.leg_width_mm, leg_len, p.carrier_thickness_mm + z["pin"][1] - z["pin"][0])}


def _pin_room(p: CamMoverParams, S: float, printer: Printer) -> float:
    """Room for the roller pin at 1:S: the leg's width less its webs, the roller's less its wall and bore."""
    bore_clear = 2 * printer.running_clearance_mm + printer.hole_undersize_mm
    return min(p.leg_width_mm / S - 2 * MIN_WEB_MM, 2 * p.roller_radius_mm / S - bore_clear - 2 * MIN_WEB_MM)


def roller_pin(p: CamMoverParams, S: float, printer: Printer, choice=None) -> float:
    """The printed roller pin at 1:S: the full-size pin ÷ S as a standard diameter within the leg's and
    the roller's room, at least the printable least; InputError saying at which scale it fits."""
    room = _pin_room(p, S, printer)
    d = pin_diameter(p.roller_pin_mm / S, room)
    if d is None:
        ok = [T for T in STANDARD_SCALES if T < S and _pin_room(p, T, printer) >= PRINTED_PIN_MIN_MM]
        cam_d = 2.0 * (p.R0_mm + 2 * p.roller_radius_mm)
        hint = (f"; it fits at 1:{ok[-1]:g} (a bed of about {mm(cam_d / ok[-1] + 2 * printer.margin_mm)} mm for the "
                f"cam)" if ok else "")
        raise InputError("--scale", f"1:{S:g}", f"the leg ({mm(p.leg_width_mm / S)} mm wide) has room for a "
                         f"⌀{mm(max(room, 0.0))} mm roller pin, below the printable ⌀{PRINTED_PIN_MIN_MM:g} mm "
                         f"(a web of {MIN_WEB_MM:g} mm each side){hint}")
    return d


def print_params(p: CamMoverParams, pl, S: float, printer: Printer) -> CamMoverParams:
    """The part's parameters at print scale 1:S with the law of `pl` and the printer's allowances."""
    clear, under = printer.running_clearance_mm, printer.hole_undersize_mm
    values = params_to_dict(p)
    for name, value in list(values.items()):
        if name.endswith("_mm") and isinstance(value, float):
            values[name] = value / S
    law = pl.law
    values.update(law=law.kind, k0=law.k0 * S, k1=law.k1, symmetric_law=law.symmetric,
                  load_support_N=p.load_support_N / S ** 2, load_return_N=p.load_return_N / S ** 2,
                  sweep_steps=KIT_SWEEP_STEPS,
                  # allowances drawn into the geometry (see the module docstring)
                  slide_clearance_mm=clear + under / 2 + DRAW_MARGIN_MM,
                  roller_bore_clearance_mm=2 * clear + under,
                  groove_axial_gap_mm=max(p.groove_axial_gap_mm / S, clear),
                  carrier_axial_gap_mm=max(p.carrier_axial_gap_mm / S, SPACER_T_MIN_MM),
                  socket_clearance_mm=max(under / 2 - printer.press_fit_mm, 0.0),
                  roller_pin_mm=roller_pin(p, S, printer),
                  axle_diameter_mm=min(AXLE_D_MAX_MM, max(AXLE_D_MIN_MM, p.axle_diameter_mm / S)),
                  # the handle is pressed into the first sprocket hole, the others stay as drawn
                  carrier_bolt_hole_mm=HANDLE_D_MM - 2 * printer.press_fit_mm + under,
                  # the shoes are pushed onto the legs, not bolted: no tapped holes, no bolt holes
                  leg_tap_depth_mm=0.5, leg_tap_drill_mm=0.5, shoe_bolt_hole_mm=0.5)
    values["carrier_bore_mm"] = values["axle_diameter_mm"] + 2 * clear + under
    values["cam_bolt_count"] = p.cam_bolt_count
    return load_params(CamMoverParams, values)


def kit(p: CamMoverParams, printer: Printer, scale: float | None = None, source=None) -> Kit:
    from ...solids.build import extrude_profile
    from ...solids.kernel import cut, cylinder, fuse, moved
    from ...solids.printed import flipped

    full = plan(p)
    choice = choose_scale(_full_size_extents(full), printer.bed, scale, margin=printer.margin_mm)
    S = choice.S
    clear, under, press = printer.running_clearance_mm, printer.hole_undersize_mm, printer.press_fit_mm
    check_printable(S, None, printer.min_module_mm, choice=choice, min_feature_mm=printer.min_feature_mm,
                    thinnest={"the shoe rim": p.shoe_rim_mm, "the cam rim": p.cam_rim_mm,
                              "the roller's wall round its pin": p.roller_radius_mm - p.roller_pin_mm / 2})
    roller_pin(p, S, printer, choice)  # refused with the scale that works
    try:
        q = print_params(p, full, S, printer)
        pl = plan(q)
    except InputError as exc:
        raise InputError("--scale", choice.label, f"the mechanism cannot be drawn at this scale with the printer's "
                         f"allowances: {exc}") from None
    r_print = q.roller_radius_mm - clear - under / 2 - DRAW_MARGIN_MM
    if r_print - q.roller_pin_mm / 2 - q.roller_bore_clearance_mm / 2 < printer.min_feature_mm:
        raise InputError("--scale", choice.label, f"the printed roller (radius {r_print:.2f} mm) keeps less than two "
                         f"line widths round its ⌀{q.roller_pin_mm:.2f} mm pin; {larger(choice.S)}")
    roller_prof = co.roller_profile(r_print, q.roller_pin_mm + q.roller_bore_clearance_mm)
    pl = dataclasses.replace(pl, roller=roller_prof)
    z = pl.z
    tp, dg, t, ws = z["plate"][1], z["channel"][1] - z["channel"][0], q.carrier_thickness_mm, q.shoe_width_mm
    n = int(q.n_legs)
    # --- proof on the printed outlines over a carrier turn
    pr = motion_proofs(pl, [pl.shoe.profile.outer.polyline(0.005)],
                       [lp for prof in (pl.ring, pl.core) for lp in prof.polylines(0.005)])
    # --- pieces
    ch = printer.chamfer_mm
    axle_d = q.axle_diameter_mm
    cam_bore_print = axle_d - 2 * press + under
    plate_prof = co.cam_plate_profile(pl.rim_radius, cam_bore_print,
                                      co.bolt_circle_loops(q.cam_bolt_count, q.cam_bolt_circle_mm, q.cam_bolt_hole_mm))
    core = Profile(pl.core.outer, [circle_loop(cam_bore_print / 2, ccw=False)] + list(pl.core.holes[1:]), "core")
    cam = fuse(extrude_profile(plate_prof, tp), moved(extrude_profile(core, dg), dz=tp),
               moved(extrude_profile(pl.ring, dg), dz=tp), name="cam")
    cam = cam
    carrier = extrude_profile(pl.carrier.profile, t)
    pin_len = z["pin"][1] - z["pin"][0]
    leg = fuse(extrude_profile(pl.leg, t), cylinder(q.roller_pin_mm / 2, t - 0.01, t + pin_len), name="leg")
    leg = leg  # printed bar down, pin up; assembled the other way round
    roller = extrude_profile(roller_prof, q.roller_width_mm)
    hw = 0.5 * q.leg_width_mm + q.socket_clearance_mm
    y0, y1 = q.leg_mount_mm - 1.0, q.leg_mount_mm + q.socket_depth_mm
    socket = Profile(co.leg_profile(2 * hw, -y0, y1).outer, [], "socket")
    # the shoe prints on its top face, the socket open upwards
    shoe_up = cut(extrude_profile(pl.shoe.profile, ws), moved(extrude_profile(socket, t + 1.0), dz=-1.0), name="shoe")
    shoe = flipped(shoe_up, ws)
    gap_c = q.carrier_axial_gap_mm
    axle_len = tp + dg + gap_c + t + AXLE_TOP_MM
    axle = side_pin(axle_d, axle_len)
    core_r = pl.H_min - q.roller_radius_mm
    spacer_D = min(2 * (core_r - 1.0), pl.carrier.slot_bottom * 2 - 2.0, axle_d + 12.0)
    spacer_hole = axle_d + 2 * clear + under
    if spacer_D / 2 - spacer_hole / 2 < printer.min_feature_mm:
        raise InputError("--scale", choice.label, f"the spacer round the ⌀{axle_d:g} mm axle has no room on the cam "
                         f"core (radius {core_r:.2f} mm); {larger(choice.S)}")
    spacer = extrude_profile(Profile(circle_loop(spacer_D / 2), [circle_loop(spacer_hole / 2, ccw=False)], "spacer"),
                             gap_c)
    handle = side_pin(HANDLE_D_MM, t + HANDLE_UP_MM)
    leg_genus = 0
    pieces = [Piece("cam", cam, genus=1 + q.cam_bolt_count, what=f"fixed cam with its channel, the base"),
              Piece("carrier", carrier, genus=1 + q.carrier_bolt_count, what=f"carrier with {n} slides"),
              Piece("leg", leg, count=n, genus=leg_genus, what=f"leg with its roller pin ⌀{q.roller_pin_mm:g}"),
              Piece("roller", roller, count=n, genus=1, what=f"roller ⌀{2 * r_print:.1f}"),
              Piece("shoe", shoe, count=n, genus=0, what="support shoe"),
              Piece("axle", axle, genus=0, what=f"axle ⌀{axle_d:g}", chamfer_mm=0.0),
              Piece("spacer", spacer, genus=1, what=f"spacer ring, {gap_c:.2f} mm"),
              Piece("handle", handle, genus=0, what=f"crank handle ⌀{HANDLE_D_MM:g}", chamfer_mm=0.0)]
    # --- the model assembled at the carrier angle of the part file
    phi0 = math.radians(q.assembly_angle_deg)
    zc = z["carrier"][0]
    assembly = [Placed("cam", "cam", place(), "0.75"), Placed("axle", "axle", place(), "0.35"),
                Placed("spacer", "spacer", place(dz=tp + dg), "0.5"),
                Placed("carrier", "carrier", place(dz=zc, rot_z=phi0), "tab:blue")]
    M = leg_poses(pl, [phi0 + 2 * math.pi * k / n for k in range(n)])
    for k in range(n):
        ang = math.atan2(M[k][1, 0], M[k][0, 0])
        x, y = float(M[k][0, 2]), float(M[k][1, 2])
        assembly += [Placed(f"leg_{k + 1}", "leg", place(dx=x, dy=y, dz=zc - pin_len, rot_z=ang, flip="y",
                                                         z_top=t + pin_len), "tab:orange"),
                     Placed(f"roller_{k + 1}", "roller", place(dx=x, dy=y, dz=z["roller"][0]), "0.2"),
                     Placed(f"shoe_{k + 1}", "shoe", place(dx=x, dy=y, dz=zc, rot_z=ang, flip="x", z_top=ws),
                            "tab:green")]
    hx, hy = _first_hole(q)
    assembly.append(Placed("handle", "handle", place(dz=zc, dx=hx * math.cos(phi0) - hy * math.sin(phi0),
                                                     dy=hx * math.sin(phi0) + hy * math.cos(phi0)), "tab:red"))
    # --- checks on the printed geometry
    tol = 1e-6
    rw, ro = pr["roller_working"], pr["roller_outer"]
    checks = []
    for key, what in (("roller_working", "roller vs working wall"), ("roller_outer", "roller vs outer wall"),
                      ("leg_carrier", "legs in their slides"), ("shoe_carrier", "shoes vs carrier"),
                      ("neighbours", "neighbouring legs + shoes"), ("opposite", "opposite legs + shoes")):
        if key not in pr:
            continue
        res = pr[key]
        # inner features (channel, slides) print narrower by half the undersize on each side
        shrink = under / 2 if key in ("roller_working", "roller_outer", "leg_carrier") else 0.0
        checks.append(Check.at_most(f"motion.{key}.overlap_area", res.max_overlap, tol, "mm^2",
                                    f"{what}: printed outlines over {res.n_steps} steps of a carrier turn"))
        checks.append(Check.at_least(f"motion.{key}.least_clearance", res.min_clearance - shrink, clear, "mm",
                                     f"{what}: least clearance over the turn {res.min_clearance:.4f} mm"
                                     + (f" − {shrink:g} mm (the inner feature prints narrower)" if shrink else "")))
    checks += [
        Check.at_least("fit.roller_axial_gap", q.groove_axial_gap_mm, clear, "mm",
                       "axial gap of the roller to the channel floor and top"),
        Check.at_least("fit.spacer_thickness", gap_c, SPACER_T_MIN_MM, "mm",
                       "the spacer keeps the carrier clear of the cam's top"),
    ]
    fits = [Fit("roller_on_pin", "leg", "roller", (0.0, 0.0), "running", "each roller turns on its leg's pin",
                pin_z=(t, t + pin_len)),
            Fit("carrier_on_axle", "axle", "carrier", (0.0, 0.0), "running", "the carrier turns on the axle"),
            Fit("spacer_on_axle", "axle", "spacer", (0.0, 0.0), "running", "the spacer ring over the axle"),
            Fit("axle_in_cam", "axle", "cam", (0.0, 0.0), "press", "the axle pressed into the cam"),
            Fit("handle_in_carrier", "handle", "carrier", _first_hole(q), "press", "the handle pressed into the carrier")]
    hub = pr["hub"]
    return Kit(
        fits=fits,
        hardware=[dowel(axle_d, axle_len, 1, "axle", "the axle"),
                  dowel(HANDLE_D_MM, t + HANDLE_UP_MM, 1, "handle", "the crank handle")],
        step_parts=[["cam", "axle", "spacer"], [f"{what}_{k + 1}" for k in range(n) for what in ("leg", "roller", "shoe")],
                    ["carrier"], ["handle"], []],
        part="cam_mover", printer=printer, scale=choice, pieces=pieces, assembly=assembly, checks=checks,
        derived={"print_hub_height_mm": pl.mech.hub_height, "print_hub_height_mean_mm": float(hub["hub"].mean()),
                 "print_roller_radius_mm": r_print, "print_channel_width_mm": 2 * q.roller_radius_mm
                 + q.channel_clearance_mm, "print_law": pl.law.label(), "axle_d_mm": axle_d,
                 "roller_pin_d_mm": q.roller_pin_mm,
                 "print_roller_clearance_mm": [rw.min_clearance, ro.min_clearance],
                 "print_leg_slide_clearance_mm": pr["leg_carrier"].min_clearance},
        allowances=[("running clearance", clear, f"roller ⌀{2 * r_print:.2f} in a {2 * q.roller_radius_mm + q.channel_clearance_mm:.2f} mm "
                                                 f"channel; legs in slides {q.leg_width_mm + 2 * q.slide_clearance_mm:.2f} mm "
                                                 f"wide; rollers on pins, carrier on the axle"),
                    ("press fit", press, "axle in the cam, handle in the carrier (radial)"),
                    ("hole undersize", under, "added to every hole's diameter and to the channel's and slides' width"),
                    ("bed-side chamfer", ch, "45° round the face each piece lies on, made layer by layer as the slicer sees it")],
        steps=[f"Press the axle into the cam's bore from above until it stands on the desk; put the spacer ring "
               f"over it onto the cam's core.",
               f"Push each roller onto a leg's pin (the pin points down) and each shoe onto a leg's end (the shoe's "
               f"open socket over the leg's end, its wide face towards the carrier's side).",
               f"Lay the carrier over the axle onto the spacer and drop the {n} legs into its slides, each roller into "
               f"the cam's channel.",
               "Press the handle into the carrier's first sprocket hole.",
               f"Turn the handle: the rollers follow the channel, the legs slide out and in, and the lowest shoe "
               f"keeps the hub {pl.mech.hub_height:.1f} mm above a line (the ground of the model) over its support "
               f"phase — the walk of seed 001 at 1:{S:g}."],
        notes=[f"The law of the full-size design ({full.law.label()}) is kept: K scales as 1/length, so k0 × {S:g} "
               f"at 1:{S:g}; the hub height varies by {float(hub['hub'].max() - hub['hub'].min()):.4f} mm over the "
               f"printed turn on the exact shoe outline."])


def _first_hole(q: CamMoverParams) -> tuple[float, float]:
    """Centre of the first sprocket hole of the carrier (carrier frame), where the handle goes."""
    rc = 0.5 * q.carrier_bolt_circle_mm
    a = -0.5 * math.pi + math.pi / q.n_legs
    return rc * math.cos(a), rc * math.sin(a)
