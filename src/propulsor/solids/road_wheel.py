"""The road wheel's geometry and solids (seed 004 ch. 5, 7), shared by the road-wheel and balancer parts.

Wheel frame (mm): axis = z, origin on the axis at the hub's inboard face, +z outboard.  Solids,
each a solid of revolution built from an exact half section (:mod:`propulsor.solids.revolve`):
``disc`` (hub tube with the two bearing seats and one web per row, ``lightening_holes`` holes
through every web: genus 1 + rows × holes), ``rim_<k>`` (steel ring per row, genus 1),
``tyre_<k>`` (solid rubber ring on the rim, genus 1).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError

__all__ = ["WheelModel", "wheel_model", "wheel_solids", "mass_properties"]


@dataclass
class WheelModel:
    """Derived wheel geometry, wheel frame (mm)."""

    p: object  # the road wheel's parameters (RoadWheelParams)
    r_tyre: float
    r_rim_out: float
    r_rim_in: float
    r_hub: float
    rows_z: list = field(default_factory=list)  # (z0, z1) of each row
    web_z: list = field(default_factory=list)  # (z0, z1) of each web
    z_mid: float = 0.0  # wheel mid-plane (load line)
    hole_circle_r: float = 0.0

    @property
    def z_inboard(self) -> float:
        """Most inboard z of the wheel (hub face or inner row)."""
        return min(0.0, self.rows_z[0][0])

    @property
    def z_outboard(self) -> float:
        return max(self.p.hub_length_mm, self.rows_z[-1][1])

    def disc_section(self):
        """Half section (x = r, y = z) of hub + webs."""
        from ..geometry.profile import Profile, polygon_loop

        p = self.p
        L, B1, B2 = p.hub_length_mm, p.bearing_inner_B_mm, p.bearing_outer_B_mm
        R1, R2, Rr = p.bearing_inner_D_mm / 2, p.bearing_outer_D_mm / 2, p.hub_relief_d_mm / 2
        pts = [(R1, 0.0), (self.r_hub, 0.0)]
        for (w0, w1) in self.web_z:
            pts += [(self.r_hub, w0), (self.r_rim_in, w0), (self.r_rim_in, w1), (self.r_hub, w1)]
        pts += [(self.r_hub, L), (R2, L), (R2, L - B2), (Rr, L - B2), (Rr, B1), (R1, B1)]
        return Profile(polygon_loop(pts), name="disc")

    def ring_section(self, r0: float, r1: float, z0: float, z1: float, name: str):
        from ..geometry.profile import Profile, polygon_loop

        return Profile(polygon_loop([(r0, z0), (r1, z0), (r1, z1), (r0, z1)]), name=name)

    def sections(self) -> dict:
        """Name -> half section of every solid."""
        out = {"disc": self.disc_section()}
        for k, (z0, z1) in enumerate(self.rows_z, 1):
            out[f"rim_{k}"] = self.ring_section(self.r_rim_in, self.r_rim_out, z0, z1, f"rim_{k}")
            out[f"tyre_{k}"] = self.ring_section(self.r_rim_out, self.r_tyre, z0, z1, f"tyre_{k}")
        return out

    def genus(self, name: str) -> int:
        return 1 + (len(self.rows_z) * self.p.lightening_holes if name == "disc" else 0)

def wheel_model(p) -> WheelModel:
    """Derived geometry of the road wheel's parameters ``p`` (RoadWheelParams); InputError naming the
    parameter for geometry that cannot be made."""
    R, H, b = p.tyre_radius_mm, p.tyre_thickness_mm, p.tyre_width_mm
    if not H < 0.5 * R:
        raise InputError("tyre_thickness_mm", H, f"must be < R/2 = {0.5 * R:g} mm")
    r_rim_out = R - H
    r_rim_in = r_rim_out - p.rim_thickness_mm
    r_hub = 0.5 * p.hub_outer_d_mm
    for nm, d, D, B in (("inner", p.bearing_inner_d_mm, p.bearing_inner_D_mm, p.bearing_inner_B_mm),
                        ("outer", p.bearing_outer_d_mm, p.bearing_outer_D_mm, p.bearing_outer_B_mm)):
        if not D > d + 10.0:
            raise InputError(f"bearing_{nm}_D_mm", D, f"must exceed the bore d = {d:g} mm by > 10 mm")
        if not D + 20.0 <= p.hub_outer_d_mm:
            raise InputError("hub_outer_d_mm", p.hub_outer_d_mm, f"must leave a 10 mm wall around the {nm} "
                             f"bearing seat: >= {D + 20.0:g} mm")
    if not p.hub_relief_d_mm < min(p.bearing_inner_D_mm, p.bearing_outer_D_mm) - 4.0:
        raise InputError("hub_relief_d_mm", p.hub_relief_d_mm, "must be < the smaller bearing D − 4 mm "
                         "(shoulders for the outer rings)")
    if not p.hub_relief_d_mm > max(p.bearing_inner_d_mm, p.bearing_outer_d_mm) + 10.0:
        raise InputError("hub_relief_d_mm", p.hub_relief_d_mm, "must exceed the larger bearing bore d + 10 mm "
                         "(the spindle passes through)")
    if not p.bearing_inner_B_mm + p.bearing_outer_B_mm + 10.0 <= p.hub_length_mm:
        raise InputError("hub_length_mm", p.hub_length_mm, "must hold both bearings and 10 mm between them")
    if not r_rim_in > r_hub + 20.0:
        raise InputError("hub_outer_d_mm", p.hub_outer_d_mm, f"hub must end 20 mm inside the rim (rim bore "
                         f"{2 * r_rim_in:g} mm)")
    z0 = p.row_offset_mm
    rows = [(z0, z0 + b)]
    if p.rows == 2:
        rows.append((z0 + b + p.row_gap_mm, z0 + 2 * b + p.row_gap_mm))
    if p.rows == 2 and not p.row_gap_mm > 0:
        raise InputError("row_gap_mm", p.row_gap_mm, "two rows need a gap > 0 mm")
    webs = []
    for (a, c) in rows:
        zc = 0.5 * (a + c)
        w0, w1 = zc - 0.5 * p.web_thickness_mm, zc + 0.5 * p.web_thickness_mm
        if not p.web_thickness_mm < b:
            raise InputError("web_thickness_mm", p.web_thickness_mm, f"must be < the tyre width {b:g} mm")
        if not (w0 > 0.5 and w1 < p.hub_length_mm - 0.5):
            raise InputError("hub_length_mm", p.hub_length_mm, f"every web must sit on the hub: web from "
                             f"{w0:g} to {w1:g} mm, hub from 0 to {p.hub_length_mm:g} mm (row_offset_mm, rows)")
        webs.append((w0, w1))
    if len(webs) == 2 and not webs[1][0] > webs[0][1] + 1.0:
        raise InputError("row_gap_mm", p.row_gap_mm, "the webs overlap")
    hc = 0.5 * (r_hub + r_rim_in)
    if p.lightening_holes:
        rh = 0.5 * p.lightening_hole_d_mm
        if not (hc - rh > r_hub + 5.0 and hc + rh < r_rim_in - 5.0):
            raise InputError("lightening_hole_d_mm", p.lightening_hole_d_mm,
                             f"must be < {2 * (0.5 * (r_rim_in - r_hub) - 5.0):g} mm (5 mm to hub and rim)")
        if p.lightening_holes > 1 and 2 * hc * math.sin(math.pi / p.lightening_holes) <= p.lightening_hole_d_mm + 5.0:
            raise InputError("lightening_holes", p.lightening_holes, "holes overlap: fewer or smaller holes")
    z_mid = 0.5 * (rows[0][0] + rows[-1][1])
    return WheelModel(p, R, r_rim_out, r_rim_in, r_hub, rows, webs, z_mid, hc)

def wheel_solids(m: WheelModel) -> dict:
    """Name -> cadquery Solid of every wheel part, in the wheel frame."""
    from .kernel import cut, cylinder
    from .revolve import revolve_section

    out = {}
    for name, sec in m.sections().items():
        sol = revolve_section(sec)
        if name == "disc" and m.p.lightening_holes:
            z0, z1 = m.web_z[0][0] - 1.0, m.web_z[-1][1] + 1.0
            tools = []
            for k in range(m.p.lightening_holes):
                a = 2.0 * math.pi * (k + 0.5) / m.p.lightening_holes
                tools.append(cylinder(0.5 * m.p.lightening_hole_d_mm, z0, z1,
                                      (m.hole_circle_r * math.cos(a), m.hole_circle_r * math.sin(a))))
            sol = cut(sol, *tools, name="disc lightening holes")
        out[name] = sol
    return out

def mass_properties(m: WheelModel, solids: dict) -> dict:
    """Mass (kg) and centre of mass (mm, wheel frame) of every solid and of the whole wheel."""
    from .kernel import mass_properties as solid_mass

    p = m.p
    out = {}
    tot, mom = 0.0, np.zeros(3)
    for name, sol in solids.items():
        rho = (p.rho_rubber_kg_m3 if name.startswith("tyre") else p.rho_steel_kg_m3) * 1e-9
        mk, ck = solid_mass(sol, rho)
        out[name] = (mk, ck)
        tot += mk
        mom += mk * ck
    out["wheel"] = (tot, mom / tot)
    return out
