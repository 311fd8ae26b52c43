"""The planetary final drive's design: the set's sheet and conditions, the generated outlines.

The ISO 21771 / GOST 16532 / GOST 19274 sheet of both meshes (:mod:`propulsor.gears.involute`),
the four conditions of the set (seed 004 eq. 30-35, :mod:`propulsor.gears.planetary`), generated
outlines (rack for sun and planets, shaper for the ring, :mod:`propulsor.geometry.gear_outline`)
with bores, keyway and the ring's mounting holes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...errors import InputError
from .params import FinalDriveParams

__all__ = ["feasible", "FinalDriveDesign", "design", "planetary_set", "ring_outer_d", "gear_outlines", "body_offsets"]


@dataclass(frozen=True)
class FinalDriveDesign:
    p: FinalDriveParams
    ps: object  # gears.planetary.PlanetarySet
    outlines: tuple  # (sun, planet, ring) GearOutline


def design(p: FinalDriveParams) -> FinalDriveDesign:
    """The set and its outlines; InputError for a set that cannot be made or assembled."""
    ps = planetary_set(p)  # raises InputError for gears that cannot be made
    if not ps.assembly_ok:
        raise InputError("n_planets", p.n_planets,
                         f"assembly condition (seed 004 eq. 31): (z_sun + z_ring)/n_planets = "
                         f"{p.z_sun + p.z_ring}/{p.n_planets} must be whole")
    if ps.n_planets > 1 and ps.neighbour_gap <= 0.0:
        raise InputError("n_planets", p.n_planets,
                         f"neighbour condition (seed 004 eq. 30): planet tip circles overlap by "
                         f"{-ps.neighbour_gap:.3f} mm at a_w = {ps.a_w:.3f} mm")
    if p.sun_bore_mm > 0 and p.sun_bore_mm >= ps.sun.d_f - 2 * p.module_mm:
        raise InputError("sun_bore_mm", p.sun_bore_mm,
                         f"must be < d_f − 2m = {ps.sun.d_f - 2 * p.module_mm:.3f} mm")
    if p.planet_bore_mm > 0 and p.planet_bore_mm >= ps.planet.d_f - 2 * p.module_mm:
        raise InputError("planet_bore_mm", p.planet_bore_mm,
                         f"must be < d_f − 2m = {ps.planet.d_f - 2 * p.module_mm:.3f} mm")
    if p.ring_outer_d_mm > 0 and p.ring_outer_d_mm <= ps.ring.d_f + 4 * p.module_mm:
        raise InputError("ring_outer_d_mm", p.ring_outer_d_mm,
                         f"must be > d_f + 4m = {ps.ring.d_f + 4 * p.module_mm:.3f} mm (rim under the bolts)")
    return FinalDriveDesign(p, ps, gear_outlines(p, ps))


def planetary_set(p: FinalDriveParams):
    """The :class:`PlanetarySet` of the parameters (with the coaxiality correction when asked)."""
    from ...gears.planetary import PlanetarySet

    ps = PlanetarySet(z_sun=p.z_sun, z_planet=p.z_planet, z_ring=p.z_ring, m=p.module_mm,
                      x_sun=p.x_sun, x_planet=p.x_planet, x_ring=p.x_ring, n_planets=p.n_planets,
                      z0=p.shaper_z0, x0=p.shaper_x0, b_sun=p.width_sun_mm, b_planet=p.width_planet_mm,
                      b_ring=p.width_ring_mm)
    return ps.with_coaxial_ring() if p.ring_shift_for_coaxiality else ps


def ring_outer_d(p: FinalDriveParams, ps) -> float:
    return p.ring_outer_d_mm if p.ring_outer_d_mm > 0 else ps.ring.d_f + 8.0 * p.module_mm


def gear_outlines(p: FinalDriveParams, ps):
    """Generated outlines (sun, planet, ring) as :class:`GearOutline` with bores and ring holes."""
    from ...geometry.gear_outline import external_gear_profile, internal_gear_profile
    from ...geometry.profile import Profile, circle_loop

    m = p.module_mm
    sun = external_gear_profile(p.z_sun, m, p.x_sun, d_a=ps.d_a_sun, thinning_n_mm=p.tooth_thinning_mm,
                                bore_d=p.sun_bore_mm or None, keyway=(True if p.sun_keyway else None))
    planet = external_gear_profile(p.z_planet, m, p.x_planet, d_a=ps.d_a_planet,
                                   thinning_n_mm=p.tooth_thinning_mm, bore_d=p.planet_bore_mm or None)
    ring = internal_gear_profile(p.z_ring, m, ps.x_ring, ps.d_a_ring, p.shaper_z0, p.shaper_x0,
                                 outer_d=ring_outer_d(p, ps), rho_a0_star=p.shaper_tip_radius_star,
                                 thinning_n_mm=p.tooth_thinning_mm)
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
def body_offsets(z_ring: int) -> tuple[float, float]:
    """Rotation that brings an outline of gear_outline into the kinematics convention.

    External gears are generated with tooth 0 on +y; the ring with a space on +y (its neighbouring
    tooth at +y + π/z)."""
    return -0.5 * math.pi, -0.5 * math.pi - math.pi / z_ring


def feasible(p, source=None) -> None:
    """InputError (parameter, value, limit) when the set cannot be made: the design computed once (the
    build reuses it, :func:`~propulsor.parts.pipeline.design_of`).  What the parameters cannot tell from their
    fields; run by the dry run and the Python API after ``validate()`` (``parts.vet``)."""
    from ..pipeline import design_of

    design_of(p, design)
