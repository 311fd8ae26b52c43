"""The balancer's solid: arm plate ∪ upper axle ∪ spindle, minus the torsion-bar socket, the bolt bore
and the lubrication cross hole; the meshes of the travel sweep.

* arm plate: the side outline extruded to the arm width;
* upper axle (hull-bearing journal, involute spline socket for the torsion bar, GOST 6033-80
  :mod:`propulsor.geometry.involute_spline`, retaining-bolt bore and its boss);
* lower axle (road-wheel spindle with the bearing seats of ``road_wheel.toml`` and a lubrication bore).

Frame of the balancer (mm): origin on the upper-axle axis in the arm's mid-plane; x along the arm
to the wheel axis (|x| = R_b); y across the arm, positive the way the wheel force turns it; z along
the axles, outboard positive.
"""

from __future__ import annotations

import math

from .design import BalancerModel

__all__ = ["upper_section", "spindle_section", "balancer_solid", "sweep_mesh"]


# ------------------------------------------------------------------------------------------------
# solids
# ------------------------------------------------------------------------------------------------
def upper_section(m: BalancerModel):
    """Half section (x = r, y = z) of the upper axle, solid to the axis (bores are cut later)."""
    from ...geometry.profile import Arc, Line, Loop, Profile

    p = m.p
    b = p.arm_width_mm
    rj, Rc, rf = 0.5 * p.d_upper_mm, 0.5 * p.D_upper_mm, p.r_upper_mm
    z_in, z_c0 = p.upper_z_in, -0.5 * b - p.upper_collar_mm
    z_emb, z_p0, z_p1 = -0.5 * b + 5.0, 0.5 * b - 5.0, 0.5 * b + p.plug_length_mm
    B = p.hull_bearing_B_mm
    s1 = (-p.a1_mm - 0.5 * B, -p.a1_mm + 0.5 * B)
    s2 = (-p.a2_mm - 0.5 * B, -p.a2_mm + 0.5 * B)
    rr = rj - 1.5  # relief between the seats
    pts = [(0.0, z_in), (rj, z_in), (rj, s2[1]), (rr, s2[1] + 1.5), (rr, s1[0] - 1.5), (rj, s1[0]),
           (rj, z_c0 - rf)]
    segs = [Line(pts[i], pts[i + 1]) for i in range(len(pts) - 1)]
    segs.append(Arc((rj + rf, z_c0 - rf), rf, math.pi, math.pi / 2))  # fillet, concave corner
    pts2 = [(rj + rf, z_c0), (Rc, z_c0), (Rc, z_emb), (rj, z_emb), (rj, z_p0), (p.plug_r_mm, z_p0),
            (p.plug_r_mm, z_p1), (0.0, z_p1), (0.0, z_in)]
    if p.plug_length_mm <= 0:
        pts2 = [(rj + rf, z_c0), (Rc, z_c0), (Rc, z_emb), (rj, z_emb), (rj, z_p0), (0.0, z_p0), (0.0, z_in)]
    segs += [Line(pts2[i], pts2[i + 1]) for i in range(len(pts2) - 1)]
    return Profile(Loop(segs), name="upper_axle")


def spindle_section(m: BalancerModel):
    """Half section of the wheel spindle with the seats of the road wheel's bearings and the lube bore."""
    from ...geometry.profile import Arc, Line, Loop, Profile

    p, wp = m.p, m.wheel_p
    b = p.arm_width_mm
    Rc, rf = 0.5 * p.D_lower_mm, p.r_lower_mm
    r1, r2 = 0.5 * wp.bearing_inner_d_mm, 0.5 * wp.bearing_outer_d_mm
    z0, zb1 = 0.5 * b - 5.0, m.z_hub
    x = m.extras  # seats, end, relief and cross-hole station: design.spindle_dims
    s1, s2, rr, z_end, z_cross = (x["spindle_seat_1"], x["spindle_seat_2"], x["spindle_relief_r"], x["spindle_end"],
                                  x["z_cross"])
    rn = r2 - 4.0  # nut zone
    rl = 0.5 * p.lube_bore_d_mm
    z_lb = z_cross - 0.5 * p.lube_cross_d_mm - 2.0
    tip = rl * math.tan(math.radians(31.0))  # 118° drill point
    segs = [Line((0.0, z0), (Rc, z0)), Line((Rc, z0), (Rc, zb1)), Line((Rc, zb1), (r1 + rf, zb1)),
            Arc((r1 + rf, zb1 + rf), rf, -math.pi / 2, -math.pi)]
    pts = [(r1, zb1 + rf), (r1, s1[1]), (rr, s1[1] + (r1 - rr)), (rr, s2[0] - (rr - r2)), (r2, s2[0]),
           (r2, s2[1]), (rn, s2[1] + (r2 - rn)), (rn, z_end), (rl, z_end), (rl, z_lb), (0.0, z_lb - tip),
           (0.0, z0)]
    segs += [Line(pts[i], pts[i + 1]) for i in range(len(pts) - 1)]
    return Profile(Loop(segs), name="spindle")


def balancer_solid(m: BalancerModel):
    """The balancer as one solid (plate ∪ upper axle ∪ spindle, minus socket, bolt bore, cross hole)."""
    from ...geometry.profile import Profile
    from ...solids.build import extrude_profile
    from ...solids.kernel import cut, cylinder, fuse, moved
    from ...solids.revolve import revolve_section

    p = m.p
    b = p.arm_width_mm
    plate = moved(extrude_profile(m.outline.profile, b), dz=-0.5 * b)
    upper = revolve_section(upper_section(m))
    spindle = revolve_section(spindle_section(m), center=(p.R_b_mm, 0.0))
    body = fuse(plate, upper, spindle, name="balancer body")
    z_in = p.upper_z_in
    socket = moved(extrude_profile(Profile(m.spline.hub_hole_loop()), p.spline_length_mm + 1.0), dz=z_in - 1.0)
    z_top = 0.5 * b + max(p.plug_length_mm, 0.0)
    bolt = cylinder(0.5 * p.bolt_bore_d_mm, z_in + p.spline_length_mm - 1.0, z_top + 1.0)
    cross = cylinder(0.5 * p.lube_cross_d_mm, 0.0, m.extras["spindle_relief_r"] + 2.0,
                     center=(p.R_b_mm, m.extras["z_cross"]), axis="y")
    return cut(body, socket, bolt, cross, name="balancer bores")


def sweep_mesh(solid, chord):
    """(vertices, faces) of a solid at the sweep's chord (single-threaded BRepMesh), refined until OCCT's
    achieved deflection is within that chord (not within the exported files' 0.01 mm)."""
    from ...solids.tessellate import triangulate

    V, F, _ = triangulate(solid, chord, 0.2, parallel=False, chord_limit=chord)
    return V, F
