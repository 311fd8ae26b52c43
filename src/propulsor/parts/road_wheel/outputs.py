"""The road wheel's outputs: solids, mass properties, assembly, DXF, notes; and its build."""

from __future__ import annotations

import math

from ...solids.road_wheel import WheelModel, mass_properties, wheel_solids
from ..pipeline import Pipeline, design_of
from ..media import pipeline_steps
from .animation import rolling_animation
from .design import RoadWheelDesign, design
from .proofs import RESONANCE_SPEEDS_MPS, kozlov_proof

__all__ = ["build", "section_loops", "web_blank"]


def section_loops(m: WheelModel) -> list:
    """Full cross-section (both sides of the axis) of every solid, x = radius, y = z."""
    from ...geometry.profile import Line, Loop, Profile

    out = []
    for name, sec in m.sections().items():
        out.append(sec)
        segs = [Line((-s.p0[0], s.p0[1]), (-s.p1[0], s.p1[1])) for s in sec.outer.segments]
        out.append(Profile(Loop(segs), name=name + "_mirror"))
    return out


def web_blank(m: WheelModel):
    from ...geometry.profile import Profile, circle_loop

    holes = [circle_loop(m.r_hub, ccw=False)]
    for k in range(m.p.lightening_holes):
        a = 2.0 * math.pi * (k + 0.5) / m.p.lightening_holes
        holes.append(circle_loop(0.5 * m.p.lightening_hole_d_mm,
                                 (m.hole_circle_r * math.cos(a), m.hole_circle_r * math.sin(a)), ccw=False))
    return Profile(circle_loop(m.r_rim_in), holes, name="web")


def solid_outputs(dd: RoadWheelDesign, w, built: dict) -> None:
    """Solids (files and checks by the writer), mass properties, the assembly and the DXF."""
    p, m = dd.p, dd.model
    d = w.derived
    w.progress("solids: disc, rims, tyres (revolved exact sections)")
    solids = wheel_solids(m)
    for name, sol in solids.items():
        w.add_solid(name, sol, expected_genus=m.genus(name))
    mp = mass_properties(m, solids)
    for name, (mk, ck) in mp.items():
        d[f"mass_{name}_kg"] = mk
    d["centre_of_mass_wheel_mm"] = [float(x) for x in mp["wheel"][1]]
    w.add_table("mass_properties", ["solid", "mass_kg", "com_x_mm", "com_y_mm", "com_z_mm"],
                [[k, v[0], *map(float, v[1])] for k, v in mp.items()])
    w.add_assembly("road_wheel_assembly", [(name, sol, (0.0, 0.0, 0.0), 0.0) for name, sol in solids.items()])

    w.progress("DXF: section and web blank")
    refs = [("line", {"p0": (0.0, m.z_inboard - 20.0), "p1": (0.0, m.z_outboard + 20.0)}),
            ("line", {"p0": (-m.r_tyre - 20.0, m.z_mid), "p1": (m.r_tyre + 20.0, m.z_mid)})]
    w.add_dxf("road_wheel_section", section_loops(m), refs)
    w.add_dxf("road_wheel_web", [web_blank(m)],
              [("circle", {"radius": m.hole_circle_r})] if p.lightening_holes else [])


def notes(dd: RoadWheelDesign, w, built: dict) -> None:
    p, m, P_row = dd.p, dd.model, dd.P_row
    l, lam, q_m, q_mean = built["l"], built["lam"], built["q_m"], built["q_mean"]
    T_vmax, T_vmax_printed = built["T_vmax"], built["T_vmax_printed"]
    w.add_note(
        f"Road wheel D = {2 * m.r_tyre:g} mm, {p.rows} row(s) of b = {p.tyre_width_mm:g} mm solid rubber, "
        f"H = {p.tyre_thickness_mm:g} mm, on steel rims; hub seats {p.bearing_inner_D_mm:g} / "
        f"{p.bearing_outer_D_mm:g} mm for bearings of bore {p.bearing_inner_d_mm:g} / {p.bearing_outer_d_mm:g} mm "
        f"(the balancer spindle's seats are taken from these). Seed 004 gives D_k = 630 mm and the double row "
        f"(ch. 5); tyre width, rubber thickness, rubber constants, rim, disc and bearings are ours.")
    w.add_note(
        f"Kozlov (seed 004 eq. 76-80) per row at P = {P_row:.0f} N: contact chord l = {l:.2f} mm, deflection "
        f"λ_m = {lam:.2f} mm, q_m = {q_m:.3f} MPa, mean {q_mean:.3f} MPa; at {p.V_max_kmh:g} km/h T = {T_vmax:.1f} °C "
        f"(admissible {p.t_allow_C:g} °C, ours). Reading taken: n = V/(2πR); the printed n = 60V/(3.6πR) is the wheel "
        f"speed only for R a diameter and would give {T_vmax_printed:.1f} °C. Track pitch t = {p.track_pitch_m:g} m "
        f"(ch. 7 Table 12; ch. 4 prints 0.14 m, ch. 5 0.125 m). The plot marks the seed's parametric-resonance speeds "
        f"{', '.join(f'{v:g}' for v in RESONANCE_SPEEDS_MPS)} m/s (fig. 35) with their track frequencies; Kozlov's "
        f"estimate ignores that dynamic load, which the seed argues can reach the static load (36 kg × 30 g).")


start_animation, collect_animation = pipeline_steps(rolling_animation)

build = Pipeline(lambda p, w: design_of(p, design),
                 (kozlov_proof, start_animation, solid_outputs, notes, collect_animation))
