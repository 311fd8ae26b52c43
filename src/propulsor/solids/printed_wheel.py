"""The road wheel as it prints: the wheel of revolution at 1:S in slabs that each print without support.

The wheel (:class:`~propulsor.solids.road_wheel.WheelModel`) is hub, one web per row at the row's
mid-plane, rims and tyres; printed whole, every rim below its web would start in the air.  It is cut
at every web's mid-plane and, with two rows, at the mid-plane between the rows: each slab then holds
half a web on one of its faces, with the half rims, half tyres and the hub standing on it — printed
on that face, nothing overhangs.  Rim and tyre print as one ring; the hub is a plain tube on the
spindle (the bearing seats are the full-size part's, a printed wheel runs on its bore).  The slabs
are glued back together face to face; their outer shape is the wheel's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..geometry.profile import Profile, polygon_loop
from .road_wheel import WheelModel

__all__ = ["WheelSlab", "wheel_slabs"]


@dataclass
class WheelSlab:
    name: str
    z0: float  # slab in the wheel frame at print scale (mm)
    z1: float
    solid: object  # in the wheel frame
    printed: object  # laid on its web face, z from 0
    web_face: str  # "bottom" | "top": where the half web lies in the wheel frame
    genus: int


def _rect(r0: float, r1: float, z0: float, z1: float) -> Profile:
    return Profile(polygon_loop([(r0, z0), (r1, z0), (r1, z1), (r0, z1)]))


def wheel_slabs(m: WheelModel, S: float, bore_d: float) -> list[WheelSlab]:
    """The wheel `m` (full size) at 1:S with a plain bore `bore_d` (print mm), cut into slabs."""
    from .kernel import cut, cylinder, fuse, moved
    from .printed import flipped
    from .revolve import revolve_section

    k = 1.0 / S
    p = m.p
    r_t, r_ri, r_h = m.r_tyre * k, m.r_rim_in * k, m.r_hub * k
    rows = [(a * k, b * k) for a, b in m.rows_z]
    webs = [(a * k, b * k) for a, b in m.web_z]
    L = p.hub_length_mm * k
    z_end = max(L, rows[-1][1])
    rb = 0.5 * bore_d
    overlap = 0.25 * min(r_ri - r_h, r_t - r_ri)  # the web reaches into hub and rim: no coincident faces
    rects = [(rb, r_h, 0.0, L)] + [(r_ri, r_t, a, b) for a, b in rows] + \
            [(r_h - overlap, r_ri + overlap, a, b) for a, b in webs]
    cuts = [0.5 * (a + b) for a, b in webs]
    if len(rows) == 2:
        cuts.append(0.5 * (rows[0][1] + rows[1][0]))
    planes = sorted([0.0, *cuts, z_end])
    web_mid = set(round(c, 9) for c in cuts[:len(webs)])
    n_holes = p.lightening_holes
    slabs = []
    for j, (z0, z1) in enumerate(zip(planes[:-1], planes[1:]), 1):
        parts = [revolve_section(_rect(r0, r1, max(a, z0), min(b, z1))) for r0, r1, a, b in rects
                 if min(b, z1) - max(a, z0) > 1e-9]
        sol = fuse(*parts, name=f"wheel slab {j}") if len(parts) > 1 else parts[0]
        has_web = any(min(b, z1) - max(a, z0) > 1e-9 for a, b in webs)
        if n_holes and has_web:
            tools = []
            for i in range(n_holes):
                a = 2.0 * math.pi * (i + 0.5) / n_holes
                c = (m.hole_circle_r * k * math.cos(a), m.hole_circle_r * k * math.sin(a))
                tools.append(cylinder(0.5 * p.lightening_hole_d_mm * k, z0 - 1.0, z1 + 1.0, c))
            sol = cut(sol, *tools, name=f"wheel slab {j} lightening holes")
        face = "bottom" if round(z0, 9) in web_mid else "top"
        local = moved(sol, dz=-z0)
        printed = local if face == "bottom" else flipped(local, z1 - z0)
        slabs.append(WheelSlab(f"wheel_{j}", z0, z1, sol, printed, face, 1 + (n_holes if has_web else 0)))
    return slabs
