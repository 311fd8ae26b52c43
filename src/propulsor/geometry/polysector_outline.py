"""Closed outlines of the composite (polysector) gear: toothed sectors, the hub's flow discs, the
solid mating gear (seed 003).

numpy/scipy only.  The sector's teeth are the blank's generated teeth (ISO 53 rack envelope,
:func:`propulsor.geometry.gear_outline.external_gear_profile`): the same fitted fillet and
flank B-splines, z_c of them patterned by exact rotation about the blank's centre O'.

Sector (its own frame: O' at the origin, mid-line on +y; the teeth centred on the mid-line):
z_c teeth, cut faces radial from the end of the extreme teeth's root fillets down to the rim radius
r_rim, a rim, and a stem of width w_stem along the mid-line down to y_end.  The
stem carries a radial slot (the clamping bolt, fixed in the hub, slides in it: the sector is
adjustable) and a locating pin hole beside the slot; the hub has one pin hole per position.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import require
from .gear_outline import GearOutline, bore_loop, external_gear_profile
from .profile import Arc, Line, Loop, Profile, circle_loop

__all__ = ["SectorLayout", "sector_profile", "hub_profile", "place", "slot_loop"]


@dataclass(frozen=True)
class SectorLayout:
    """Dimensions of a sector body and the hub (mm), in the sector frame (O' origin, mid-line +y).

    r_rim: inner radius of the toothed rim about O'; w_stem: stem width; y_end: stem end;
    slot (bolt d_bolt) from y_slot0 to y_slot1 on the mid-line; pin hole d_pin at (x_pin, y_pin);
    hub: disc radius R_hub, bore d_bore, bolt at radius rho_bolt, pin holes at y_pin + e_k."""

    r_rim: float
    w_stem: float
    y_end: float
    d_bolt: float
    y_slot0: float
    y_slot1: float
    d_pin: float
    x_pin: float
    y_pin: float
    R_hub: float
    d_bore: float
    rho_bolt: float


def slot_loop(x: float, y0: float, y1: float, d: float) -> Loop:
    """A rounded slot (hole, clockwise) of width d along x = const from y0 to y1 (centres)."""
    rr = d / 2.0
    if y1 - y0 <= 1e-9:
        return circle_loop(rr, (x, y0), ccw=False)
    return Loop([Line((x + rr, y0), (x + rr, y1)), Arc((x, y1), rr, 0.0, math.pi),
                 Line((x - rr, y1), (x - rr, y0)), Arc((x, y0), rr, math.pi, 2 * math.pi)]).reversed()


def sector_profile(gear: GearOutline, z_c: int, lay: SectorLayout) -> Profile:
    """Closed outline of one sector (its frame) from the blank's generated outline ``gear``."""
    side = gear.side
    z = gear.z
    p = 2.0 * math.pi / z
    fil, fla = gear.fillet_spline, gear.flank_spline
    from .gear_outline import _mirror

    fil_l, fla_l = _mirror(fil).reversed(), _mirror(fla).reversed()
    pt, pr = side.tip_angle, side.root_angle
    h = math.pi / 2
    segs = []
    c = [(j - (z_c - 1) / 2.0) * p for j in range(z_c)]
    r_f, r_a = side.r_f, side.r_a
    # the cut faces run radially from the fillets' ends on the root circle (no sliver of root arc)
    a_start = h + c[0] - pr
    a_end = h + c[-1] + pr
    require(lay.r_rim < r_f - 1e-6, "r_rim", lay.r_rim, f"must be below the root radius {r_f:.4f} mm")
    # cut face up from the rim at the right end, then the teeth
    segs.append(Line((lay.r_rim * math.cos(a_start), lay.r_rim * math.sin(a_start)),
                     (r_f * math.cos(a_start), r_f * math.sin(a_start))))
    for j, cj in enumerate(c):
        segs += [s.transformed(cj) for s in (fil, fla)]
        segs.append(Arc((0.0, 0.0), r_a, h + cj - pt, h + cj + pt))
        segs += [s.transformed(cj) for s in (fla_l, fil_l)]
        if j < z_c - 1:
            segs.append(Arc((0.0, 0.0), r_f, h + cj + pr, h + cj + p - pr))
    segs.append(Line((r_f * math.cos(a_end), r_f * math.sin(a_end)),
                     (lay.r_rim * math.cos(a_end), lay.r_rim * math.sin(a_end))))
    # rim inner arc (clockwise) to the stem, the stem, the rim arc on to the start
    hw = lay.w_stem / 2.0
    require(hw < lay.r_rim, "w_stem", lay.w_stem, f"must be < 2 r_rim = {2 * lay.r_rim:.3f} mm")
    ys = math.sqrt(lay.r_rim ** 2 - hw * hw)
    a_l, a_r = math.atan2(ys, -hw), math.atan2(ys, hw)
    require(lay.y_end < ys - 1e-6, "y_end", lay.y_end, f"must be below the rim ({ys:.3f} mm)")
    segs.append(Arc((0.0, 0.0), lay.r_rim, a_end, a_l))
    segs.append(Line((-hw, ys), (-hw, lay.y_end)))
    segs.append(Line((-hw, lay.y_end), (hw, lay.y_end)))
    segs.append(Line((hw, lay.y_end), (hw, ys)))
    segs.append(Arc((0.0, 0.0), lay.r_rim, a_r, a_start))
    holes = [slot_loop(0.0, lay.y_slot0, lay.y_slot1, lay.d_bolt),
             circle_loop(lay.d_pin / 2.0, (lay.x_pin, lay.y_pin), ccw=False)]
    return Profile(Loop(segs), holes, name=f"sector z_c={z_c} of z={z} m={gear.m}")


def hub_profile(lay: SectorLayout, sector_angles, offsets, keyway=True) -> Profile:
    """One flow disc of the hub: disc R_hub, bore (DIN 6885-1 keyway), per sector (mid-line at each
    angle of ``sector_angles``, from +x) the clamping bolt hole at rho_bolt and one locating pin
    hole per position (y_pin + e_k beside the mid-line)."""
    holes = [bore_loop(lay.d_bore, keyway)]
    for ang in sector_angles:
        rot = ang - math.pi / 2.0  # sector frame (+y) -> mid-line at ang
        holes.append(circle_loop(lay.d_bolt / 2.0, _rot((0.0, lay.rho_bolt), rot), ccw=False))
        for e in offsets:
            holes.append(circle_loop(lay.d_pin / 2.0, _rot((lay.x_pin, lay.y_pin + e), rot), ccw=False))
    return Profile(circle_loop(lay.R_hub), holes, name="hub flow disc")


def _rot(p, a):
    c, s = math.cos(a), math.sin(a)
    return (c * p[0] - s * p[1], s * p[0] + c * p[1])


def place(profile: Profile, mid_angle: float, offset: float) -> Profile:
    """A sector profile (its frame) placed on the wheel: mid-line at ``mid_angle`` (from +x), O' at
    ``offset`` from the wheel axis on the mid-line."""
    return profile.transformed(mid_angle - math.pi / 2.0, (offset * math.cos(mid_angle), offset * math.sin(mid_angle)))


def blank_outline(z: int, m: float, thinning: float) -> GearOutline:
    """The blank gear (generated by the ISO 53 rack) whose teeth the sectors carry."""
    return external_gear_profile(z, m, 0.0, thinning_n_mm=thinning)


def mating_gear(z2: int, m: float, thinning: float, bore_d: float, phase: float,
                keyway: bool = True) -> tuple[GearOutline, Profile]:
    """The solid gear (rack-generated, bore with a DIN 6885-1 keyway unless ``keyway`` is False) and its
    profile turned by ``phase`` (tooth 0 of the generator is on +y)."""
    g = external_gear_profile(z2, m, 0.0, thinning_n_mm=thinning, bore_d=bore_d, keyway=True if keyway else None)
    return g, g.profile.transformed(phase)
