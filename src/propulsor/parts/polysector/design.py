"""The composite gear's design: synthesis (seed 003 eq. 1–4), positions, the layout of sectors and
hub, and the finished outlines (:mod:`propulsor.geometry.polysector_outline`).

Refuses (InputError, exit 2, one line with the numbers): z_c too large for the gaps (eq. 2), a
position whose offset is past the largest offset of eq. 1/3, whose ε_s (eq. 4, both flows) is below
1.05, whose conditional tooth count is not a multiple of flows·i_s (sectors out of tooth phase),
sectors of one flow that would collide with each other or with the shaft, and a hub that cannot
carry the slot and the pin holes of every position.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...errors import InputError, input_names
from .params import PolysectorParams

__all__ = ["feasible", "Position", "PolysectorDesign", "design", "synthesis"]


@dataclass(frozen=True)
class Position:
    k: int  # 1-based
    z_cond: int
    offset: float
    a: float
    ratio_nominal: float
    eps_s_flow: float
    eps_s: float
    u_exit: float


@dataclass(frozen=True)
class PolysectorDesign:
    p: PolysectorParams
    geo: object  # gears.polysector.PolysectorGeometry
    positions: tuple
    e_max: float
    layout: object  # geometry.polysector_outline.SectorLayout
    blank: object  # GearOutline of the blank
    sector: object  # Profile, sector frame
    hubs: tuple  # Profile per flow (wheel frame)
    gear: object  # GearOutline
    gear_profile: object  # Profile at phase zero (its axis at the origin)
    gear_phase: float

    def sector_angles(self, flow: int) -> list[float]:
        """Mid-line angles (from +x, phase zero) of the sectors of flow 1 or 2."""
        i_s = self.p.sectors_per_flow
        base = 0.0 if flow == 1 else math.pi / i_s
        return [base + 2.0 * math.pi * j / i_s for j in range(i_s)]

    def placed_sectors(self, pos: Position, flow: int) -> list:
        from ...geometry.polysector_outline import place

        return [place(self.sector, ang, pos.offset) for ang in self.sector_angles(flow)]


def synthesis(p: PolysectorParams):
    """The geometry object and the positions (eq. 1–4); InputError for positions that cannot be made."""
    from ...gears.polysector import EPS_S_MIN, PolysectorGeometry

    with input_names({"z": "blank_teeth", "z_c": "sector_teeth", "flows": "flows"}):
        geo = PolysectorGeometry(m=p.module_mm, z=p.blank_teeth, z_c=p.sector_teeth, i_s=p.sectors_per_flow,
                                 z2=p.gear_teeth, alpha=math.radians(p.pressure_angle_deg), flows=p.flows,
                                 thinning=p.tooth_thinning_mm)
    if not p.conditional_teeth:
        raise InputError("conditional_teeth", [], "needs at least one position")
    with input_names({"z_c": "sector_teeth", "offset": "conditional_teeth"}):
        e_max = geo.max_offset(EPS_S_MIN)
    mult = p.flows * p.sectors_per_flow
    positions = []
    for k, zc in enumerate(p.conditional_teeth, 1):
        if isinstance(zc, bool) or not isinstance(zc, int):
            raise InputError(f"conditional_teeth[{k}]", zc, "must be a whole number")
        if zc < p.blank_teeth:
            raise InputError(f"conditional_teeth[{k}]", zc, f"must be >= the blank's z = {p.blank_teeth} (offset >= 0)")
        if zc % mult:
            raise InputError(f"conditional_teeth[{k}]", zc, f"must be a multiple of flows·i_s = {mult} (all sectors in "
                             f"tooth phase with the gear); nearest {zc - zc % mult} or {zc - zc % mult + mult}")
        e = geo.offset_for(zc)
        if e > e_max + 1e-9:
            raise InputError(f"conditional_teeth[{k}]", zc, f"offset e = {e:.4g} mm is past the largest offset of "
                             f"eq. 1/3 (ε_s >= {EPS_S_MIN}): e_max = {e_max:.4f} mm (z_усл <= "
                             f"{p.blank_teeth + 2 * e_max / p.module_mm:.2f})")
        ef, eb = geo.epsilon_s(e)
        if eb < EPS_S_MIN:  # cannot happen below e_max; kept for the message
            raise InputError(f"conditional_teeth[{k}]", zc, f"ε_s = {eb:.4f} < {EPS_S_MIN} (eq. 4)")
        positions.append(Position(k, zc, e, geo.center_distance(e), geo.ratio_nominal(e), ef, eb, geo.exit_angle(e)))
    return geo, tuple(positions), e_max


def layout(p: PolysectorParams, geo, positions) -> object:
    """Sector body and hub dimensions: the slot, the pin and the hub disc sized so that every position
    fits (InputError naming the parameter to change otherwise)."""
    from ...geometry.polysector_outline import SectorLayout

    m, web = p.module_mm, p.web_mm
    r_f = geo.r - 1.25 * m
    r_rim = r_f - p.rim_modules * m
    e_lo = min(q.offset for q in positions)
    e_hi = max(q.offset for q in positions)
    # hub disc: inside the gear's tip circle at the least offset (a − r_a2 = r + e − m), with the
    # bottom clearance c* m = 0.25 m
    R_hub = geo.r + e_lo - 1.25 * m
    bore_r = p.shaft_d_mm / 2.0
    y_end = bore_r + web - e_lo + web  # the stem end clears the shaft at the least offset
    # clamping bolt fixed in the hub at rho_bolt; the slot spans rho_bolt − e_hi … rho_bolt − e_lo
    rb = p.bolt_d_mm / 2.0
    rho_bolt = R_hub - web - rb
    y_slot0, y_slot1 = rho_bolt - e_hi, rho_bolt - e_lo
    if y_slot0 - rb < y_end + web:
        raise InputError("conditional_teeth", list(p.conditional_teeth),
                         f"offset range {e_hi - e_lo:.4g} mm too large for the hub: the slot would reach the stem end "
                         f"(needs R_hub − shaft/2 = {R_hub - bore_r:.3f} mm >= {e_hi - e_lo + 2 * rb + 4 * web:.3f} mm)")
    # the slot's outer end lies a web below the roots by construction: y_slot1 + d_bolt/2 = R_hub − web − e_lo =
    # r_f − web (its refusal, "the slot reaches the tooth roots", could only fire on rounding: a web of 3.1 mm at a
    # least offset of 18 mm put the end 7e-15 mm too far out and refused a sound design)
    # pin beside the slot; its hub holes at y_pin + e_k must stay on the disc
    rp = p.pin_d_mm / 2.0
    x_pin = rb + web + rp
    hw = p.stem_width_mm / 2.0
    if x_pin + rp + web > hw:
        raise InputError("stem_width_mm", p.stem_width_mm, f"must be >= {2 * (x_pin + rp + web):.3f} mm "
                         f"(slot, pin and webs side by side)")
    y_pin = y_end + web + rp
    if math.hypot(x_pin, y_pin + e_hi) + rp + web > R_hub:
        raise InputError("conditional_teeth", list(p.conditional_teeth),
                         f"the pin hole of offset {e_hi:.4g} mm falls off the hub disc (R_hub = {R_hub:.3f} mm)")
    offs = sorted(q.offset for q in positions)
    for a, b in zip(offs, offs[1:]):
        if b - a < 2 * rp + web:
            raise InputError("conditional_teeth", list(p.conditional_teeth),
                             f"offsets {a:.4g} and {b:.4g} mm: pin holes closer than d_pin + web = {2 * rp + web:g} mm")
    # the stems end 2 web outside the bore at the least offset (y_end + e_lo = shaft/2 + 2 web) and the pin hole
    # beyond them: neither can reach the shaft
    return SectorLayout(r_rim=r_rim, w_stem=p.stem_width_mm, y_end=y_end, d_bolt=p.bolt_d_mm, y_slot0=y_slot0,
                        y_slot1=y_slot1, d_pin=p.pin_d_mm, x_pin=x_pin, y_pin=y_pin, R_hub=R_hub,
                        d_bore=p.shaft_d_mm, rho_bolt=rho_bolt)


def _one_flow_collisions(d: "PolysectorDesign") -> None:
    """Sectors of one flow must not touch each other (at every position; the least offset is the
    closest), nor the shaft: InputError with the overlap found (outline polygons)."""
    for pos in d.positions:
        secs = d.placed_sectors(pos, 1)
        polys = [s.outer.polyline(0.01) for s in secs]
        for i in range(len(polys)):
            j = (i + 1) % len(polys)
            if i == j:
                continue
            gap = _poly_gap(polys[i], polys[j])
            if gap < d.p.web_mm / 2:
                raise InputError("sector_teeth", d.p.sector_teeth,
                                 f"sectors of one flow {'collide' if gap <= 0 else 'nearly touch'} at offset "
                                 f"{pos.offset:.4g} mm (gap {gap:.3f} mm < {d.p.web_mm / 2:g} mm)")


def _poly_gap(A, B) -> float:
    """Least distance between the vertices of two closed polylines (sampled finely enough that two
    crossing outlines give a distance below the sampling step)."""
    from scipy.spatial import cKDTree

    return float(cKDTree(B).query(A)[0].min())


def design(p: PolysectorParams) -> PolysectorDesign:
    from ...geometry.polysector_outline import blank_outline, hub_profile, mating_gear, sector_profile

    geo, positions, e_max = synthesis(p)
    lay = layout(p, geo, positions)
    blank = blank_outline(p.blank_teeth, p.module_mm, p.tooth_thinning_mm)
    sector = sector_profile(blank, p.sector_teeth, lay)
    offsets = [q.offset for q in positions]
    i_s = p.sectors_per_flow
    hubs = tuple(hub_profile(lay, [(0.0 if f == 1 else math.pi / i_s) + 2 * math.pi * j / i_s for j in range(i_s)],
                             offsets, p.keyways) for f in range(1, p.flows + 1))
    # phase zero: flow 1's first sector on +x.  z_c even: a space of the sector on the mid-line, so a
    # tooth of the gear faces −x; z_c odd: a space of the gear faces −x
    phase = math.pi / 2.0 + (0.0 if p.sector_teeth % 2 == 0 else math.pi / p.gear_teeth)
    with input_names({"bore_d": "gear_bore_mm"}):
        gear, gear_prof = mating_gear(p.gear_teeth, p.module_mm, p.tooth_thinning_mm, p.gear_bore_mm, phase,
                                      p.keyways)
    d = PolysectorDesign(p, geo, positions, e_max, lay, blank, sector, hubs, gear, gear_prof, phase)
    _one_flow_collisions(d)
    return d


def feasible(p, source=None) -> None:
    """InputError (parameter, value, limit) when the positions (synthesis, eq. 1-4) cannot be made: the design computed once (the
    build reuses it, :func:`~propulsor.parts.pipeline.design_of`).  What the parameters cannot tell from their
    fields; run by the dry run and the Python API after ``validate()`` (``parts.vet``)."""
    from ..pipeline import design_of

    design_of(p, design)
