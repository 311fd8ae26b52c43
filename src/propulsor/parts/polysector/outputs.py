"""The composite gear's remaining output steps (solids, assemblies, DXF, layout) and `build`."""

from __future__ import annotations

import math

from ..pipeline import Pipeline, design_of
from ..media import pipeline_steps
from .animation import position_animations
from .design import PolysectorDesign, design
from .proofs import dynamics_step, efficiency_step, position_error_step, proof_results, start_proofs, synthesis_step

__all__ = ["build", "solids", "assemblies_and_drawings"]


def solids(dd: PolysectorDesign, w, built: dict) -> None:
    """Prismatic solids: one sector (every sector is this part), one hub flow disc (flow 2's is the same
    disc turned by π/i_s), the solid gear."""
    from ...solids.build import extrude_profile

    p = dd.p
    w.progress("solids: sector, hub disc, gear")
    n_holes_hub = 1 + p.sectors_per_flow * (1 + len(dd.positions))
    s = {
        "sector": (extrude_profile(dd.sector, p.face_width_mm), 2),
        "hub_disc": (extrude_profile(dd.hubs[0], p.hub_thickness_mm), n_holes_hub),
        "gear": (extrude_profile(dd.gear_profile, p.flows * p.face_width_mm), 1),
    }
    for name, (solid, genus) in s.items():
        w.add_solid(name, solid, expected_genus=genus)
    built["solids"] = {k: v[0] for k, v in s.items()}


def assemblies_and_drawings(dd: PolysectorDesign, w, built: dict) -> None:
    """An assembly STEP per position (phase zero), DXF of sector, hub, gear and of each position's flows."""
    from ...export.plots import outline_plot

    p, geo = dd.p, dd.geo
    sol = built["solids"]
    b, th = p.face_width_mm, p.hub_thickness_mm
    i_s = p.sectors_per_flow
    for q in dd.positions:
        comps = [("hub_flow1", sol["hub_disc"], (0.0, 0.0, 0.0), 0.0)]
        for f in range(1, p.flows + 1):
            for j, ang in enumerate(dd.sector_angles(f)):
                comps.append((f"sector_flow{f}_{j + 1}", sol["sector"],
                              (q.offset * math.cos(ang), q.offset * math.sin(ang), th + (f - 1) * b), ang - math.pi / 2))
        if p.flows == 2:
            comps.append(("hub_flow2", sol["hub_disc"], (0.0, 0.0, th + 2 * b), math.pi / i_s))
        comps.append(("gear", sol["gear"], (q.a, 0.0, th), 0.0))
        w.add_assembly(f"assembly_{q.k}", comps)
        for f in range(1, p.flows + 1):
            w.add_dxf(f"composite_{q.k}_flow{f}", dd.placed_sectors(q, f) + [dd.hubs[f - 1]],
                      [("circle", {"radius": geo.r + q.offset}), ("circle", {"radius": geo.r_a + q.offset})])
    w.add_dxf("gear", [dd.gear_profile], [("circle", {"radius": geo.r2}), ("circle", {"radius": geo.r_b2}),
                                          ("circle", {"radius": geo.r_a2})])
    w.add_dxf("sector", [dd.sector], [("circle", {"radius": geo.r}), ("circle", {"radius": geo.r_b})])
    w.add_dxf("hub", [dd.hubs[0]], [("circle", {"radius": dd.layout.rho_bolt})])
    q = dd.positions[-1]
    loops = []
    for f in range(1, p.flows + 1):
        for s in dd.placed_sectors(q, f):
            loops += s.polylines(0.05)
    loops += dd.hubs[0].polylines(0.05)
    loops += dd.gear_profile.transformed(0.0, (q.a, 0.0)).polylines(0.05)
    outline_plot(w.path("plots/layout.png"), loops, title=f"Composite gear at position {q.k} (e = {q.offset:g} mm), "
                 f"phase zero (mm)")
    w.plots.append("plots/layout.png")


start_animations, collect_animations = pipeline_steps(position_animations)

build = Pipeline(lambda p, w: design_of(p, design),
                 (synthesis_step, start_proofs, solids, position_error_step, assemblies_and_drawings, proof_results,
                  start_animations, efficiency_step, dynamics_step, collect_animations))
