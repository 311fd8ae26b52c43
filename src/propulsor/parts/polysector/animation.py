"""The composite wheel and the solid gear at each position, at the poses of the position's mesh proof
: one GIF per position, ``anim/position_<k>.gif``.

Poses: the proof's wheel angles φ over one sector period (:mod:`.mesh_proof`; the turn repeats the
period: the sectors are one outline turned by exactly that angle and the gear advances whole pitches)
and the gear's angle θ(φ) the proof found from contact — the wheel turned by φ about its axis, the
gear by −θ about its axis at (a_k, 0), as the proof placed them.  Every k-th step (every step for
a short period), the grid through the step of least backlash.  Every tooth pair in contact at the
proof's pose is marked; the least backlash of the engaged sectors (the room of their other flanks,
on the gear's base circle) is written, and marked in red at its step.
"""

from __future__ import annotations

import math

import numpy as np

from ...checks.motion import rotation_matrices
from ..media import AnimationJob, chord_for_view, every, loops_of
from .design import PolysectorDesign

__all__ = ["position_animations"]

#: at most this many frames per position (one sector period)
MAX_FRAMES = 60


def position_animations(dd: PolysectorDesign, w, built: dict) -> list:
    """``anim/position_<k>.gif`` for every position."""
    from ...export.animation import Animation, Mark, Shape

    p, geo = dd.p, dd.geo
    proofs = built["proofs"]
    jobs = []
    R_wheel = geo.r_a + max(q.offset for q in dd.positions)
    for j, q in enumerate(dd.positions):
        pr = proofs[j]
        N = len(pr.phi)
        room_mm = pr.coast_room * pr.r_ref
        least_step = int(np.nanargmin(room_mm))
        least = float(room_mm[least_step])
        k = max(1, int(math.ceil(N / MAX_FRAMES)))
        idx = np.arange(least_step % k, N, k)
        n = len(idx)
        extent = q.a + geo.r_a2 + R_wheel
        chord = chord_for_view(extent)
        wheel = rotation_matrices(pr.phi[idx])
        gear = rotation_matrices(-pr.theta[idx], np.tile([q.a, 0.0], (n, 1)))
        # the 3D view of the position's assembly (at phase zero): hubs and sectors turn with the wheel
        still = rotation_matrices([0.0])[0]
        nodes = {c: (wheel, still) for c in ["hub_flow1"] + (["hub_flow2"] if p.flows == 2 else [])
                 + [f"sector_flow{f}_{i + 1}" for f in range(1, p.flows + 1) for i in range(len(dd.sector_angles(f)))]}
        nodes["gear"] = (gear, rotation_matrices([0.0], [[q.a, 0.0]])[0])
        shapes = [Shape(loops_of(dd.hubs[0], chord), "steel", wheel)]
        for f, colour in ((2, "purple"), (1, "blue")):
            if f <= p.flows:
                shapes += [Shape(loops_of(s, chord), colour, wheel) for s in dd.placed_sectors(q, f)]
        shapes.append(Shape(loops_of(dd.gear_profile, chord), "orange", gear))
        marks, captions = [], []
        for s in idx:
            mk = [Mark((float(pt[0]), float(pt[1])), "", radius_px=4) for _, pt in pr.contacts[s]]
            if s == least_step:
                pt = pr.contact_points[s]
                mk.append(Mark((float(pt[0]), float(pt[1])), f"LEAST backlash {least:.4f} mm", radius_px=8))
            marks.append(mk)
            captions.append([f"wheel φ = {math.degrees(pr.phi[s]):.2f}° (proof step {s + 1} of {N}, one sector "
                             f"period of {math.degrees(pr.period):.0f}°); gear θ = {math.degrees(pr.theta[s]):.3f}°; "
                             f"tooth pairs in contact {int(pr.pairs[s])} (red), sector {int(pr.driver[s]) + 1} drives; "
                             f"backlash {room_mm[s]:.4f} mm",
                             ("!" if s == least_step else "") + f"least backlash over the period {least:.4f} mm "
                             f"(φ = {math.degrees(pr.phi[least_step]):.2f}°)"])
        title = (f"Composite gear, position {q.k} (z_cond = {q.z_cond}, e = {q.offset:g} mm, a = {q.a:g} mm): "
                 f"flow 1 sectors (blue), flow 2 (purple), hub disc (grey), solid gear z2 = {p.gear_teeth} (orange)")
        anim = Animation(title, shapes, n, captions, marks, width_px=600,
                         keep=(int(np.nonzero(idx == least_step)[0][0]),), aspect_range=(0.5, 0.8))
        jobs.append(AnimationJob(f"position_{q.k}", anim,
                title=f"position {q.k} (e = {q.offset:g} mm): the composite wheel driving the solid gear over one "
                      f"sector period (the turn repeats it)",
                poses=(f"all {N} steps" if k == 1 else f"{every(k)} of the {N} steps") + " of the position's proof "
                      "over one sector period (grid through the step of least backlash)",
                least_clearance_mm=least, least_what="least backlash", steps=idx,
                pose_columns={"phi_rad": pr.phi[idx], "theta_rad": pr.theta[idx],
                              "backlash_mm": room_mm[idx], "pairs_in_contact": pr.pairs[idx]},
                assembly=f"assembly_{q.k}", nodes=nodes))
    return jobs
