"""Print kit of the road wheel: the wheel at 1:S in support-free slabs (:mod:`propulsor.solids.printed_wheel`)
spinning on an axle pressed into a stand: a base disc with a collar the wheel's hub rests on.

The proof on the printed geometry: the wheel turns on its axle with the running clearance, its
lowest point (the inboard tyre row) clears the base by at least the running clearance, and the slabs
stacked back together give the wheel's outer shape (tyre radius and width) at 1:S.
"""

from __future__ import annotations

from ...check import Check
from ...errors import InputError
from ...geometry.profile import Profile, circle_loop
from ...printing.fits import Fit
from ...printing.hardware import dowel, side_pin
from ...printing.kit import Kit, Piece, Placed, place
from ...printing.printers import Printer
from ...printing.scale import check_printable, choose_scale, larger
from .design import design
from .params import RoadWheelParams

__all__ = ["kit"]

#: printed axle diameter range, base plate thickness, collar height above the base (mm)
AXLE_D_MIN_MM, AXLE_D_MAX_MM, BASE_T_MM, COLLAR_H_MM = 6.0, 16.0, 4.0, 3.0
#: axle length above the wheel's top face (mm)
AXLE_TOP_MM = 3.0


def kit(p: RoadWheelParams, printer: Printer, scale: float | None = None, source=None) -> Kit:
    from ...solids.build import extrude_profile
    from ...solids.kernel import cylinder, fuse
    from ...solids.kernel import largest_radius
    from ...solids.printed_wheel import wheel_slabs

    m = design(p).model
    width = max(m.z_outboard, m.rows_z[-1][1]) - m.z_inboard
    choice = choose_scale({"wheel": (2 * m.r_tyre, 2 * m.r_tyre, width)},
                          printer.bed, scale, margin=printer.margin_mm)
    S = choice.S
    check_printable(S, None, printer.min_module_mm, choice=choice, min_feature_mm=printer.min_feature_mm,
                    thinnest={"the web": p.web_thickness_mm / 2, "the rim and tyre ring": p.rim_thickness_mm
                              + p.tyre_thickness_mm})
    clear, under, press = printer.running_clearance_mm, printer.hole_undersize_mm, printer.press_fit_mm
    axle_d = min(AXLE_D_MAX_MM, max(AXLE_D_MIN_MM, p.bearing_outer_d_mm / S))
    bore = axle_d + 2 * clear + under
    r_hub = m.r_hub / S
    if r_hub - bore / 2 < printer.min_feature_mm:
        raise InputError("--scale", choice.label, f"the printed hub (radius {r_hub:.2f} mm) keeps less than two line "
                         f"widths round its ⌀{bore:.2f} mm bore; {larger(choice.S)}")
    slabs = wheel_slabs(m, S, bore)
    ch = printer.chamfer_mm
    # stand: base disc with a collar under the hub, the axle pressed into both
    R_base = max(0.6 * m.r_tyre / S, r_hub + 10.0)
    collar_r = r_hub - 1.0
    hole = axle_d - 2 * press + under
    base = fuse(extrude_profile(Profile(circle_loop(R_base), [circle_loop(hole / 2, ccw=False)], "base"), BASE_T_MM),
                extrude_profile(Profile(circle_loop(collar_r), [circle_loop(hole / 2, ccw=False)], "collar"),
                                BASE_T_MM + COLLAR_H_MM), name="stand")
    base = base
    z_w = BASE_T_MM + COLLAR_H_MM  # the wheel's hub face rests on the collar
    top = slabs[-1].z1
    axle_len = z_w + top + AXLE_TOP_MM
    axle = side_pin(axle_d, axle_len)
    pieces = [Piece(s.name, s.printed, genus=s.genus,
                    what=f"wheel slab z {s.z0:.2f} … {s.z1:.2f} mm, printed on its {s.web_face} face (half web)")
              for s in slabs]
    pieces += [Piece("stand", base, genus=1, what=f"stand: base ⌀{2 * R_base:.1f} with the collar"),
               Piece("axle", axle, genus=0, what=f"axle ⌀{axle_d:g}", chamfer_mm=0.0)]
    colours = ["tab:gray", "0.3", "tab:gray", "0.3"]
    assembly = [Placed("stand", "stand", place(), "0.75"), Placed("axle", "axle", place(), "0.4")]
    assembly += [Placed(s.name, s.name, s.placement(dz=z_w), colours[k % 4]) for k, s in enumerate(slabs)]
    # the slabs restacked: outer shape of the wheel at 1:S
    tyre_r = m.r_tyre / S
    low_row = min(a for a, _ in m.rows_z) / S
    r_max = max(largest_radius(s.solid) for s in slabs)
    checks = [
        Check.at_least("motion.wheel_above_base", COLLAR_H_MM + low_row, clear, "mm",
                       f"the lowest tyre row (z = {low_row:.2f} mm above the hub face) over the base: the collar "
                       f"is {COLLAR_H_MM:g} mm high; the collar (r = {collar_r:.2f}) lies inside the hub (r = "
                       f"{r_hub:.2f}): the wheel turns on the collar's face only"),
        Check.at_most("shape.tyre_radius", abs(r_max - tyre_r), 1e-6, "mm",
                      f"largest radius of the slabs {r_max:.6f} mm (exact bounding boxes) vs R_tyre/S = "
                      f"{tyre_r:.6f} mm"),
        Check.at_most("shape.stacked_length", abs(top - max(m.z_outboard, m.rows_z[-1][1]) / S), 1e-9, "mm",
                      f"{len(slabs)} slabs stacked: {top:.3f} mm"),
    ]
    fits = [Fit(f"{s.name}_on_axle", "axle", s.name, (0.0, 0.0), "running", "the wheel turns on the axle")
            for s in slabs]
    fits.append(Fit("axle_in_stand", "axle", "stand", (0.0, 0.0), "press", "the axle pressed into the stand"))
    return Kit(
        fits=fits,
        hardware=[dowel(axle_d, axle_len, 1, "axle", "the axle")],
        step_parts=[[s.name for s in slabs], ["stand", "axle"], []],
        part="road_wheel", printer=printer, scale=choice, pieces=pieces, assembly=assembly, checks=checks,
        derived={"print_tyre_radius_mm": tyre_r, "print_wheel_length_mm": top, "axle_d_mm": axle_d,
                 "wheel_bore_d_mm": bore, "wheel_slabs": len(slabs)},
        allowances=[("running clearance", clear, f"wheel bore ⌀{bore:.2f} on the ⌀{axle_d:g} axle"),
                    ("press fit", press, "axle in the stand (radial)"),
                    ("hole undersize", under, "added to every hole's diameter"),
                    ("bed-side chamfer", ch, "45° round the face each piece lies on, made layer by layer as the slicer sees it")],
        steps=[f"Glue the {len(slabs)} wheel slabs together in their order (wheel_1 at the inboard side; each "
               "half web against its mate, the lightening holes in line; a pin through the bore keeps them "
               "concentric while the glue sets).",
               "Press the axle into the stand.",
               "Put the wheel on the axle, inboard side down: its hub rests on the collar. Spin it."],
        notes=[f"The wheel is cut at its webs' mid-planes{' and between the rows' if len(m.rows_z) == 2 else ''} "
               "so that every slab prints on a half web without support; rim and tyre print as one ring; the hub "
               "is a plain tube (the bearing seats are in the full-size STEP)."])
