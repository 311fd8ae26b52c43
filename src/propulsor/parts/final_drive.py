"""Planetary final drive of the 50 t tracked carrier (seed 004, ch. 4; SPEC §6).

Wires the parameters to the library: the ISO 21771 / GOST 16532 / GOST 19274 sheet of both meshes
(:mod:`propulsor.gears.involute`), the four conditions of the set (eq. 30–35,
:mod:`propulsor.gears.planetary`), generated outlines (rack for sun and planets, shaper for the
ring, :mod:`propulsor.geometry.gear_outline`), prismatic solids, the assembly at the mesh positions,
and an interference sweep over one full carrier turn on the finished outlines
(:func:`propulsor.checks.motion.sweep_pair`, manifold3d booleans).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..parallel import start as start_in_fork
from .. import policy
from ..check import Check
from ..errors import InputError
from ..params import param
from . import PartType

__all__ = ["FinalDriveParams", "PART_TYPE", "build", "planetary_set", "gear_outlines", "carrier_sweep"]


@dataclass
class FinalDriveParams:
    """Parameters of the planetary final drive (ring fixed, sun in, carrier out)."""

    module_mm: float = param(10.0, "mm", "module m", min=0.5, max=50.0)
    z_sun: int = param(16, "", "sun teeth z1", min=7, max=300, integer=True)
    z_planet: int = param(20, "", "planet teeth z2", min=7, max=300, integer=True)
    z_ring: int = param(56, "", "ring teeth z3", min=12, max=600, integer=True)
    x_sun: float = param(0.5, "", "sun profile shift x1", min=-1.0, max=2.0)
    x_planet: float = param(0.5, "", "planet profile shift x2", min=-1.0, max=2.0)
    x_ring: float = param(1.417, "", "ring profile shift x3 (GOST 19274 sign)", min=-1.0, max=3.0)
    ring_shift_for_coaxiality: bool = param(
        False, "", "replace x_ring by the shift that makes both operating centre distances equal")
    n_planets: int = param(3, "", "number of planets k", min=1, max=12, integer=True)
    shaper_z0: int = param(14, "", "teeth of the shaper cutter that cuts the ring", min=6, max=200, integer=True)
    shaper_x0: float = param(0.04, "", "profile shift of the shaper cutter", min=-1.5, max=1.5)
    width_sun_mm: float = param(80.0, "mm", "face width of the sun", min=0, min_exclusive=True)
    width_planet_mm: float = param(75.0, "mm", "face width of a planet", min=0, min_exclusive=True)
    width_ring_mm: float = param(80.0, "mm", "face width of the ring", min=0, min_exclusive=True)
    tooth_thinning_mm: float = param(
        0.15, "mm", "tooth thickness allowance E_sn of every gear (ring: space widening); "
        "normal backlash of a mesh ≈ 2·E_sn·cos α", min=0.0, max=2.0)
    sun_bore_mm: float = param(80.0, "mm", "sun bore diameter (0: no bore)", min=0.0)
    sun_keyway: bool = param(True, "", "DIN 6885-1 keyway in the sun bore")
    planet_bore_mm: float = param(110.0, "mm", "planet bore (bearing seat) diameter (0: no bore)", min=0.0)
    ring_outer_d_mm: float = param(0.0, "mm", "ring outside diameter (0: root diameter + 8 modules)", min=0.0)
    ring_bolts: int = param(12, "", "mounting holes in the ring rim (0: none)", min=0, max=72, integer=True)
    ring_bolt_d_mm: float = param(18.0, "mm", "mounting hole diameter", min=0, min_exclusive=True)
    sweep_steps_per_deg: float = param(float(policy.PLANETARY_SWEEP_STEPS_PER_DEG), "1/deg",
                                       "interference sweep steps per degree of carrier turn",
                                       min=float(policy.PLANETARY_SWEEP_STEPS_PER_DEG), max=20.0)

    def validate(self) -> None:
        ps = planetary_set(self)  # raises InputError for gears that cannot be made
        if not ps.assembly_ok:
            raise InputError("n_planets", self.n_planets,
                             f"assembly condition (seed 004 eq. 31): (z_sun + z_ring)/n_planets = "
                             f"{self.z_sun + self.z_ring}/{self.n_planets} must be whole")
        if ps.n_planets > 1 and ps.neighbour_gap <= 0.0:
            raise InputError("n_planets", self.n_planets,
                             f"neighbour condition (seed 004 eq. 30): planet tip circles overlap by "
                             f"{-ps.neighbour_gap:.3f} mm at a_w = {ps.a_w:.3f} mm")
        if self.sun_bore_mm > 0 and self.sun_bore_mm >= ps.sun.d_f - 2 * self.module_mm:
            raise InputError("sun_bore_mm", self.sun_bore_mm,
                             f"must be < d_f − 2m = {ps.sun.d_f - 2 * self.module_mm:.3f} mm")
        if self.planet_bore_mm > 0 and self.planet_bore_mm >= ps.planet.d_f - 2 * self.module_mm:
            raise InputError("planet_bore_mm", self.planet_bore_mm,
                             f"must be < d_f − 2m = {ps.planet.d_f - 2 * self.module_mm:.3f} mm")
        if self.ring_outer_d_mm > 0 and self.ring_outer_d_mm <= ps.ring.d_f + 4 * self.module_mm:
            raise InputError("ring_outer_d_mm", self.ring_outer_d_mm,
                             f"must be > d_f + 4m = {ps.ring.d_f + 4 * self.module_mm:.3f} mm (rim under the bolts)")


def planetary_set(p: FinalDriveParams):
    """The :class:`PlanetarySet` of the parameters (with the coaxiality correction when asked)."""
    from ..gears.planetary import PlanetarySet

    ps = PlanetarySet(z_sun=p.z_sun, z_planet=p.z_planet, z_ring=p.z_ring, m=p.module_mm,
                      x_sun=p.x_sun, x_planet=p.x_planet, x_ring=p.x_ring, n_planets=p.n_planets,
                      z0=p.shaper_z0, x0=p.shaper_x0, b_sun=p.width_sun_mm, b_planet=p.width_planet_mm,
                      b_ring=p.width_ring_mm)
    return ps.with_coaxial_ring() if p.ring_shift_for_coaxiality else ps


def ring_outer_d(p: FinalDriveParams, ps) -> float:
    return p.ring_outer_d_mm if p.ring_outer_d_mm > 0 else ps.ring.d_f + 8.0 * p.module_mm


def gear_outlines(p: FinalDriveParams, ps):
    """Generated outlines (sun, planet, ring) as :class:`GearOutline` with bores and ring holes."""
    from ..geometry.gear_outline import external_gear_profile, internal_gear_profile
    from ..geometry.profile import Profile, circle_loop

    m = p.module_mm
    sun = external_gear_profile(p.z_sun, m, p.x_sun, d_a=ps.d_a_sun, thinning_n_mm=p.tooth_thinning_mm,
                                bore_d=p.sun_bore_mm or None, keyway=(True if p.sun_keyway else None))
    planet = external_gear_profile(p.z_planet, m, p.x_planet, d_a=ps.d_a_planet,
                                   thinning_n_mm=p.tooth_thinning_mm, bore_d=p.planet_bore_mm or None)
    ring = internal_gear_profile(p.z_ring, m, ps.x_ring, ps.d_a_ring, p.shaper_z0, p.shaper_x0,
                                 outer_d=ring_outer_d(p, ps), thinning_n_mm=p.tooth_thinning_mm)
    if p.ring_bolts:
        D = ring_outer_d(p, ps)
        r_bc = 0.5 * (0.5 * D + 0.5 * ps.ring.d_f)
        rim = 0.5 * D - 0.5 * ps.ring.d_f
        if p.ring_bolt_d_mm >= 0.6 * rim:
            raise InputError("ring_bolt_d_mm", p.ring_bolt_d_mm,
                             f"must be < 0.6 × rim width = {0.6 * rim:.3f} mm")
        pitch = 2.0 * r_bc * math.sin(math.pi / p.ring_bolts)
        if p.ring_bolts > 1 and pitch <= 1.5 * p.ring_bolt_d_mm:
            raise InputError("ring_bolts", p.ring_bolts,
                             f"holes of {p.ring_bolt_d_mm} mm on a {2 * r_bc:.1f} mm bolt circle need a pitch "
                             f"> 1.5 d: at most {int(math.pi / math.asin(min(1.0, 0.75 * p.ring_bolt_d_mm / r_bc)))} holes")
        holes = list(ring.profile.holes)
        for k in range(p.ring_bolts):
            a = 2.0 * math.pi * (k + 0.5) / p.ring_bolts
            holes.append(circle_loop(0.5 * p.ring_bolt_d_mm, (r_bc * math.cos(a), r_bc * math.sin(a)), ccw=False))
        ring.profile = Profile(ring.profile.outer, holes, name=ring.profile.name)
    return sun, planet, ring


# --- outline frames: the kinematics convention is "tooth centred on +x at rotation 0" -------------------
def _body_offsets(z_ring: int) -> tuple[float, float]:
    """Rotation that brings an outline of gear_outline into the kinematics convention.

    External gears are generated with tooth 0 on +y; the ring with a space on +y (its neighbouring
    tooth at +y + π/z)."""
    return -0.5 * math.pi, -0.5 * math.pi - math.pi / z_ring


@dataclass
class MeshSweep:
    name: str
    psi: np.ndarray
    overlap_mm2: np.ndarray
    clearance_mm: np.ndarray
    result: object


def carrier_sweep(p: FinalDriveParams, ps, outlines, steps_per_deg: float | None = None) -> list[MeshSweep]:
    """Overlap area and least clearance of every mesh (sun–planet k, planet k–ring) over one carrier turn.

    Each planet is swept on its own positions: sun at i_1H·ψ, planet k at its orbit position and
    absolute rotation, ring fixed (seed 004 eq. 32; phasing in
    :mod:`propulsor.gears.planetary_kinematics`).  manifold3d boolean per step.
    """
    from ..checks.motion import outline, sweep_pair_windowed
    from ..gears.planetary_kinematics import PlanetaryKinematics

    spd = steps_per_deg or p.sweep_steps_per_deg
    n = int(math.ceil(360.0 * spd))
    psi = np.arange(n) * (2.0 * math.pi / n)
    kin = PlanetaryKinematics(p.z_sun, p.z_planet, p.z_ring, p.n_planets, ps.a_w)
    off_ext, off_ring = _body_offsets(p.z_ring)
    sun_o, planet_o, ring_o = outlines
    # outlines within 1 µm of the true curves; long edges split for the tree search (module-scaled)
    tol, seg = policy.PLANETARY_SWEEP_CHORD_TOL_MM, max(0.1, 0.05 * p.module_mm)
    A_sun = outline(sun_o.profile, tol, seg)
    A_pl = outline(planet_o.profile, tol, seg)
    A_ring = outline(ring_o.profile, tol, seg)

    def mats(angles, centres):
        c, s = np.cos(angles), np.sin(angles)
        M = np.zeros((len(angles), 2, 3))
        M[:, 0, 0], M[:, 0, 1], M[:, 1, 0], M[:, 1, 1] = c, -s, s, c
        M[:, :, 2] = centres
        return M

    M_sun = mats(kin.sun_angle(psi) + off_ext, np.zeros((n, 2)))
    M_ring = mats(np.full(n, kin.ring_rotation + off_ring), np.zeros((n, 2)))
    out = []
    for k in range(p.n_planets):
        M_pl = mats(kin.planet_angle(psi, k) + off_ext, kin.planet_centre(psi, k))
        for tag, A, MA in (("sun", A_sun, M_sun), ("ring", A_ring, M_ring)):
            name = f"mesh_{tag}_planet{k + 1}" if tag == "sun" else f"mesh_planet{k + 1}_ring"
            r = sweep_pair_windowed(A, MA, A_pl, M_pl, reach=p.module_mm, chord_tol=tol, max_segment=seg,
                                    name=name, clearance_limit=0.0)
            out.append(MeshSweep(name, psi, r.overlap_area, r.clearance, r))
    return out


# --- the part -------------------------------------------------------------------------------------
def _dms(angle_rad: float) -> str:
    s = math.degrees(angle_rad) * 3600.0
    d, rem = divmod(s, 3600.0)
    mnt, sec = divmod(rem, 60.0)
    return f"{int(d)}°{int(mnt):02d}'{sec:05.2f}\""


def _build_solids(p: FinalDriveParams, outlines, w) -> dict:
    """Prismatic solids of sun, planet and ring; each written and checked by the writer."""
    from ..solids.build import extrude_profile

    sun_o, planet_o, ring_o = outlines
    w.progress("solids")
    solids = {
        "sun": (extrude_profile(sun_o.profile, p.width_sun_mm), 1 if p.sun_bore_mm else 0),
        "planet": (extrude_profile(planet_o.profile, p.width_planet_mm), 1 if p.planet_bore_mm else 0),
        "ring": (extrude_profile(ring_o.profile, p.width_ring_mm), 1 + p.ring_bolts),
    }
    for name, (solid, genus) in solids.items():
        w.add_solid(name, solid, expected_genus=genus)
    return {k: v[0] for k, v in solids.items()}


def build(p: FinalDriveParams, w) -> None:
    ps = planetary_set(p)
    sp, pr = ps.mesh_sun_planet, ps.mesh_planet_ring
    w.progress("planetary set: sheet and conditions")
    d = w.derived
    d.update({
        "ratio_i_1H": ps.ratio,
        "n_planets": p.n_planets,
        "x_ring_used": ps.x_ring,
        "x_ring_for_coaxiality": ps.ring_shift_for_coaxiality(),
        "a_w_sun_planet_mm": sp.a_w,
        "a_w_planet_ring_mm": pr.a_w,
        "alpha_w_sun_planet_deg": math.degrees(sp.alpha_w),
        "alpha_w_sun_planet_dms": _dms(sp.alpha_w),
        "alpha_w_planet_ring_deg": math.degrees(pr.alpha_w),
        "alpha_w_planet_ring_dms": _dms(pr.alpha_w),
        "coaxiality_mismatch_mm": ps.coaxiality_mismatch,
        "neighbour_gap_mm": ps.neighbour_gap,
        "assembly_quotient": ps.assembly_quotient,
    })
    for tag, g, da in (("sun", ps.sun, ps.d_a_sun), ("planet", ps.planet, ps.d_a_planet), ("ring", ps.ring, ps.d_a_ring)):
        d.update({f"d_{tag}_mm": g.d, f"d_b_{tag}_mm": g.d_b, f"d_a_{tag}_mm": da, f"d_f_{tag}_mm": g.d_f,
                  f"s_n_{tag}_mm": g.s_n, f"k_W_{tag}": g.k_W, f"W_k_{tag}_mm": g.W_k,
                  f"D_roller_{tag}_mm": g.D_recommended, f"M_{tag}_mm": g.M(g.D_recommended)})
        if da >= g.d_b:
            d[f"s_na_{tag}_mm"] = g.tip_thickness(da)
    d.update({"d_w_sun_mm": sp.d_w1, "d_w_planet_sun_mesh_mm": sp.d_w2, "d_w_planet_ring_mesh_mm": pr.d_w1,
              "d_w_ring_mm": pr.d_w2})
    for c in ps.conditions():
        w.add_checks([Check(c.name, c.passed, c.value, c.limit, c.unit, c.message)])
    try:
        d["epsilon_alpha_sun_planet"] = ps.epsilon_alpha_sun_planet
        d["epsilon_alpha_planet_ring"] = ps.epsilon_alpha_planet_ring
    except InputError:
        pass
    cols = ["quantity", "symbol", "unit", "gear_1", "gear_2"]
    w.add_table("sheet_sun_planet", cols, [list(r) for r in sp.sheet()])
    w.add_table("sheet_planet_ring", cols, [list(r) for r in pr.sheet()])
    w.add_table("conditions", ["name", "passed", "value", "limit", "unit", "message"],
                [[c.name, c.passed, c.value, c.limit, c.unit, c.message] for c in ps.conditions()])

    w.progress("generated outlines (rack: sun, planets; shaper: ring)")
    outlines = gear_outlines(p, ps)
    sun_o, planet_o, ring_o = outlines
    d.update({"d_f_sun_generated_mm": sun_o.d_f, "d_f_planet_generated_mm": planet_o.d_f,
              "d_f_ring_generated_mm": ring_o.d_f, "d_Ff_sun_mm": sun_o.d_Ff, "d_Ff_planet_mm": planet_o.d_Ff,
              "ring_outer_d_mm": ring_outer_d(p, ps)})
    for tag, o in (("sun", sun_o), ("planet", planet_o)):
        w.add_checks([Check.flag(f"undercut_{tag}_generated", not any(o.undercut),
                                 f"rack envelope {'undercuts' if any(o.undercut) else 'does not undercut'} "
                                 f"the {tag} (form diameter d_Ff = {o.d_Ff:.4f} mm)")])

    w.progress(f"interference sweep over one carrier turn ({int(math.ceil(360 * p.sweep_steps_per_deg))} steps), "
               f"in a second process while the solids are built")
    pending = start_in_fork(carrier_sweep, p, ps, outlines)
    solids = _build_solids(p, outlines, w)
    sweeps = pending.result()
    w.progress("interference sweep done")
    rows = []
    psi = sweeps[0].psi
    for j in range(len(psi)):
        rows.append([math.degrees(psi[j])] + [v for s in sweeps for v in (s.overlap_mm2[j], s.clearance_mm[j])])
    w.add_table("carrier_sweep", ["psi_deg"] + [f"{s.name}_{q}" for s in sweeps for q in ("overlap_mm2", "clearance_mm")],
                rows)
    for s in sweeps:
        w.add_checks(s.result.checks())
        d[f"{s.name}_min_clearance_mm"] = float(s.clearance_mm.min())
        d[f"{s.name}_max_overlap_mm2"] = float(s.overlap_mm2.max())
    from ..export.plots import line_plot, new_figure

    fig, ax = new_figure()
    for s in sweeps:
        ax.plot(np.degrees(s.psi), s.clearance_mm, lw=0.8, label=s.name)
    ax.set_xlabel("carrier angle ψ, deg")
    ax.set_ylabel("least clearance, mm (negative: penetration)")
    ax.set_title("Planetary final drive: clearance of every mesh over one carrier turn")
    ax.legend(fontsize=7)
    w.add_plot("mesh_clearance", fig)

    from ..gears.planetary_kinematics import PlanetaryKinematics

    kin = PlanetaryKinematics(p.z_sun, p.z_planet, p.z_ring, p.n_planets, ps.a_w)
    off_ext, off_ring = _body_offsets(p.z_ring)
    zc = lambda width: 0.5 * (p.width_ring_mm - width)  # noqa: E731  (centre every face width on the ring's)
    comps = [("sun", solids["sun"], (0.0, 0.0, zc(p.width_sun_mm)), off_ext)]
    for k in range(p.n_planets):
        c = kin.planet_centre(0.0, k)
        comps.append((f"planet_{k + 1}", solids["planet"], (float(c[0]), float(c[1]), zc(p.width_planet_mm)),
                      float(kin.planet_angle(0.0, k)) + off_ext))
    comps.append(("ring", solids["ring"], (0.0, 0.0, 0.0), kin.ring_rotation + off_ring))
    w.add_assembly("assembly", comps)

    def refs(g, da, dw=()):
        out = [("circle", {"radius": 0.5 * g.d}), ("circle", {"radius": 0.5 * g.d_b}), ("circle", {"radius": 0.5 * da})]
        out += [("circle", {"radius": 0.5 * x}) for x in dw]
        return out

    w.add_dxf("sun", [sun_o.profile], refs(ps.sun, ps.d_a_sun, [sp.d_w1]))
    w.add_dxf("planet", [planet_o.profile], refs(ps.planet, ps.d_a_planet, [sp.d_w2, pr.d_w1]))
    w.add_dxf("ring", [ring_o.profile], refs(ps.ring, ps.d_a_ring, [pr.d_w2]))

    from ..export.plots import outline_plot

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

    # the plain account
    fails = [c for c in ps.conditions() if not c.passed]
    w.add_note(
        f"Willis ratio i_1H = 1 + z3/z1 = {ps.ratio:.4f} (seed 004 eq. 32). Sun–planet mesh: a_w = {sp.a_w:.3f} mm, "
        f"α_w = {_dms(sp.alpha_w)}; planet–ring mesh: a_w = {pr.a_w:.3f} mm, α_w = {_dms(pr.alpha_w)}. "
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


PART_TYPE = PartType(
    name="planetary_final_drive",
    summary="planetary final drive: sun, planets, fixed ring (seed 004 ch. 4, ISO 21771)",
    params_cls=FinalDriveParams,
    build=build,
)
