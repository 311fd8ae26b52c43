"""The planetary final drive's outputs: solids, assembly, DXF, layout plot, notes; and its build."""

from __future__ import annotations

from ..pipeline import Pipeline, design_of
from ..media import pipeline_steps
from .animation import carrier_turn_animation
from .design import FinalDriveDesign, body_offsets, design
from .carrier import carrier, carrier_values, pin_sweep_results, start_pin_sweep
from .strength import strength
from .fatigue import fatigue
from .traction import traction
from .proofs import dms, outline_checks, sheet_and_conditions, start_sweep, sweep_results

__all__ = ["build", "solids", "assembly_and_drawings", "notes"]


def solids(dd: FinalDriveDesign, w, built: dict) -> None:
    """Prismatic solids of sun, planet and ring; each written and checked by the writer."""
    from ...solids.build import extrude_profile

    p = dd.p
    sun_o, planet_o, ring_o = dd.outlines
    w.progress("solids")
    solids = {
        "sun": (extrude_profile(sun_o.profile, p.width_sun_mm), 1 if p.sun_bore_mm else 0),
        "planet": (extrude_profile(planet_o.profile, p.width_planet_mm), 1 if p.planet_bore_mm else 0),
        "ring": (extrude_profile(ring_o.profile, p.width_ring_mm), 1 + p.ring_bolts),
    }
    for name, (solid, genus) in solids.items():
        w.add_solid(name, solid, expected_genus=genus)
    built["solids"] = {k: v[0] for k, v in solids.items()}


def assembly_and_drawings(dd: FinalDriveDesign, w, built: dict) -> None:
    """Assembly at carrier angle 0, DXF of each gear, layout plot."""
    from ...export.plots import outline_plot
    from ...gears.planetary_kinematics import PlanetaryKinematics

    p, ps = dd.p, dd.ps
    sp, pr = ps.mesh_sun_planet, ps.mesh_planet_ring
    sun_o, planet_o, ring_o = dd.outlines
    solids = built["solids"]
    kin = PlanetaryKinematics(p.z_sun, p.z_planet, p.z_ring, p.n_planets, ps.a_w)
    off_ext, off_ring = body_offsets(p.z_ring)
    zc = lambda width: 0.5 * (p.width_ring_mm - width)  # noqa: E731  (centre every face width on the ring's)
    comps = [("sun", solids["sun"], (0.0, 0.0, zc(p.width_sun_mm)), off_ext)]
    for k in range(p.n_planets):
        c = kin.planet_centre(0.0, k)
        comps.append((f"planet_{k + 1}", solids["planet"], (float(c[0]), float(c[1]), zc(p.width_planet_mm)),
                      float(kin.planet_angle(0.0, k)) + off_ext))
    comps.append(("ring", solids["ring"], (0.0, 0.0, 0.0), kin.ring_rotation + off_ring))
    if "carrier" in solids:  # the carrier's body frame is the assembly's at carrier angle 0
        comps.append(("carrier", solids["carrier"], (0.0, 0.0, 0.0), 0.0))
    w.add_assembly("assembly", comps)

    def refs(g, da, dw=()):
        out = [("circle", {"radius": 0.5 * g.d}), ("circle", {"radius": 0.5 * g.d_b}), ("circle", {"radius": 0.5 * da})]
        out += [("circle", {"radius": 0.5 * x}) for x in dw]
        return out

    w.add_dxf("sun", [sun_o.profile], refs(ps.sun, ps.d_a_sun, [sp.d_w1]))
    w.add_dxf("planet", [planet_o.profile], refs(ps.planet, ps.d_a_planet, [sp.d_w2, pr.d_w1]))
    w.add_dxf("ring", [ring_o.profile], refs(ps.ring, ps.d_a_ring, [pr.d_w2]))

    loops = []
    for k, prof in enumerate([sun_o.profile] + [planet_o.profile] * p.n_planets + [ring_o.profile]):
        if k == 0:
            pl = prof.transformed(off_ext, (0.0, 0.0))
        elif k <= p.n_planets:
            c = kin.planet_centre(0.0, k - 1)
            pl = prof.transformed(float(kin.planet_angle(0.0, k - 1)) + off_ext, (float(c[0]), float(c[1])))
        else:
            pl = prof.transformed(kin.ring_rotation + off_ring, (0.0, 0.0))
        loops += pl.polylines(0.05)
    outline_plot(w.path("plots/layout.png"), loops, title="Final drive at carrier angle 0 (mm)")
    w.plots.append("plots/layout.png")


def notes(dd: FinalDriveDesign, w, built: dict) -> None:
    p, ps = dd.p, dd.ps
    sp, pr = ps.mesh_sun_planet, ps.mesh_planet_ring
    sweeps = built["sweeps"]
    psi = sweeps[0].psi
    # the plain account
    fails = [c for c in ps.conditions() if not c.passed]
    w.add_note(
        f"Willis ratio i_1H = 1 + z3/z1 = {ps.ratio:.4f} (seed 004 eq. 32). Sun–planet mesh: a_w = {sp.a_w:.3f} mm, "
        f"α_w = {dms(sp.alpha_w)}; planet–ring mesh: a_w = {pr.a_w:.3f} mm, α_w = {dms(pr.alpha_w)}. "
        f"W_k: sun {ps.sun.W_k:.3f} mm (k = {ps.sun.k_W}), planet {ps.planet.W_k:.3f} mm (k = {ps.planet.k_W}), "
        f"ring {ps.ring.W_k:.3f} mm (k = {ps.ring.k_W}).")
    if p.ring_shift_for_coaxiality:
        w.add_note(f"The ring shift was replaced by the value computed for coaxiality: x3 = {ps.x_ring:.5f} "
                   f"(given {p.x_ring}); with the given value the planet–ring operating centre distance would differ "
                   f"from the sun–planet one.")
    if fails:
        w.add_note("Conditions that do NOT hold for these numbers: " + "; ".join(f"{c.name} ({c.message})" for c in fails) + ".")
    else:
        w.add_note("Every condition of the set holds (Willis, coaxiality, neighbour, assembly, contact ratio, "
                   "undercut, tip thickness, interference, root clearance, ring generation).")
    worst = min(sweeps, key=lambda s: s.clearance_mm.min())
    w.add_note(f"Interference sweep over one carrier turn, {len(psi)} steps ({p.sweep_steps_per_deg:g} per degree), "
               f"{len(sweeps)} meshes on the finished outlines: max overlap "
               f"{max(s.overlap_mm2.max() for s in sweeps):.3g} mm², least clearance {worst.clearance_mm.min():.4f} mm "
               f"({worst.name}); tooth thinning E_sn = {p.tooth_thinning_mm} mm per gear.")


start_animation, collect_animation = pipeline_steps(carrier_turn_animation)

#: the sheet, the set's conditions, strength, fatigue, traction, the generated outlines and both sweeps over one
#: carrier turn (meshes, carrier pins): every check and derived value of the build but the solids' (their
#: volumes and file checks) — from the design and its 2D outlines (Pipeline.prove)
PROOF_STEPS = (sheet_and_conditions, strength, fatigue, traction, outline_checks, start_sweep, start_pin_sweep,
               carrier_values, sweep_results, pin_sweep_results)

build = Pipeline(lambda p, w: design_of(p, design),
                  (sheet_and_conditions, strength, fatigue, traction, outline_checks, start_sweep, start_pin_sweep, solids, carrier,
                   carrier_values, sweep_results, pin_sweep_results, start_animation, assembly_and_drawings, notes,
                   collect_animation), proof_steps=PROOF_STEPS)
