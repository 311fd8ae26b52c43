"""The final drive over one carrier turn at the poses of its interference sweep.

Poses: the sweep's carrier angles ψ (:func:`.proofs.carrier_sweep`, ``sweep_steps_per_deg``), the
members placed by :func:`.proofs.member_poses`, the same placement the sweep used (seed 004 eq. 32):
sun at i_1H·ψ, each planet on its orbit with its absolute rotation, the ring fixed, the carrier (its
cheek and the planet pins, :mod:`.carrier`) at ψ.  Every k-th step, k chosen so that the sun advances
well under half a tooth per frame, the grid shifted onto the step where the sweep found its least
clearance.  In every frame the mesh of least clearance at that step is marked with its value (the
sweep's closest points); the least over the turn is written under the picture.
"""

from __future__ import annotations

import math

import numpy as np

from ...checks.motion import rotation_matrices
from ...geometry.profile import circle_loop
from ..media import AnimationJob, chord_for_view, every, loops_of
from .carrier import PIN_D_MM, _pin_centres, carrier_layout
from .design import FinalDriveDesign, ring_outer_d
from .proofs import member_poses

__all__ = ["carrier_turn_animation"]

#: at most this many frames per carrier turn
MAX_FRAMES = 180
#: the sun advances at most this many of its teeth per frame (so that its teeth are seen to turn forward)
SUN_TEETH_PER_FRAME = 0.4
#: GIF width (px): 180 frames of the whole drive stay well under 2 MB
WIDTH_PX_FD = 540


def carrier_turn_animation(dd: FinalDriveDesign, w, built: dict) -> list:
    """``anim/carrier_turn.gif``: sun, planets, ring and carrier over one carrier turn."""
    from ...export.animation import Animation, Mark, Shape

    p, ps = dd.p, dd.ps
    sweeps = built["sweeps"]
    psi = sweeps[0].psi
    N = len(psi)
    C = np.array([s.clearance_mm for s in sweeps])          # (meshes, steps)
    mesh_at = np.argmin(C, axis=0)
    least_step = int(np.argmin(C.min(axis=0)))
    least_mesh = int(mesh_at[least_step])
    ratio = 1.0 + p.z_ring / p.z_sun
    step_deg = 360.0 / N
    k_sun = max(1, int(SUN_TEETH_PER_FRAME * (360.0 / p.z_sun) / (ratio * step_deg)))
    k = max(k_sun, int(math.ceil(N / MAX_FRAMES)))
    idx = np.arange(least_step % k, N, k)
    n = len(idx)
    M_sun, M_ring, M_pl = member_poses(p, ps, psi[idx])
    # the 3D view of the assembly (at carrier angle 0): the same poses; the ring stands still
    R_sun, _, R_pl = member_poses(p, ps, np.zeros(1))
    nodes = {"sun": (M_sun, R_sun[0])}
    nodes.update({f"planet_{j + 1}": (M, R[0]) for j, (M, R) in enumerate(zip(M_pl, R_pl))})
    if "carrier" in built.get("solids", {}):
        nodes["carrier"] = (rotation_matrices(psi[idx]), rotation_matrices([0.0])[0])
    R = 0.5 * ring_outer_d(p, ps)
    chord = chord_for_view(2.0 * R, 0.95 * WIDTH_PX_FD)
    sun_o, planet_o, ring_o = dd.outlines
    lay = carrier_layout(dd)
    car = rotation_matrices(psi[idx])
    cheek = Shape((circle_loop(lay["R_cheek"]).polyline(chord),), "green", car)
    pins = [Shape((circle_loop(0.5 * PIN_D_MM, c).polyline(chord),), "green", car) for c in _pin_centres(dd)[1]]
    shapes = [Shape(loops_of(ring_o.profile, chord), "steel", M_ring), cheek,
              Shape(loops_of(sun_o.profile, chord), "orange", M_sun)]
    shapes += [Shape(loops_of(planet_o.profile, chord), "blue", M) for M in M_pl]
    shapes += pins
    least = float(C[least_mesh, least_step])
    least_name = sweeps[least_mesh].name
    captions, marks = [], []
    for j, s in enumerate(idx):
        m = int(mesh_at[s])
        r = sweeps[m].result
        pt = 0.5 * (r.point_a[s] + r.point_b[s])
        here = float(C[m, s])
        is_least = s == least_step
        what = f"{here:.4f} mm" if here >= 0 else f"penetration {-here:.4f} mm"  # the sweep's sign
        marks.append([Mark((float(pt[0]), float(pt[1])), f"{'LEAST ' if is_least else ''}{what}",
                           radius_px=8 if is_least else 5)])
        line2 = (f"least clearance over the turn {least:.4f} mm ({least_name}, ψ = {math.degrees(psi[least_step]):.1f}°)")
        captions.append([f"carrier ψ = {math.degrees(psi[s]):.1f}° (sweep step {s + 1} of {N}); least clearance now "
                         f"{here:.4f} mm ({sweeps[m].name})", ("!" if is_least else "") + line2])
    title = (f"Planetary final drive: sun (orange, z = {p.z_sun}), {p.n_planets} planets (blue, z = {p.z_planet}), "
             f"fixed ring (grey, z = {p.z_ring}), carrier with the planet pins (green)")
    anim = Animation(title, shapes, n, captions, marks, width_px=WIDTH_PX_FD, keep=(int(np.nonzero(idx == least_step)[0][0]),),
                     aspect_range=(0.8, 1.0))
    return [AnimationJob("carrier_turn", anim,
            title=f"sun, {p.n_planets} planets, fixed ring and carrier over one carrier turn (i_1H = {ratio:.4g})",
            poses=f"{every(k)} of the interference sweep's {N} carrier angles (grid through the step of least clearance)",
            least_clearance_mm=least, steps=idx,
            pose_columns={"psi_deg": [math.degrees(x) for x in psi[idx]], "least_clearance_mm": C.min(axis=0)[idx],
                          "mesh_of_least_clearance": [sweeps[int(mesh_at[s])].name for s in idx]},
            assembly="assembly", nodes=nodes)]
