"""The cam mover walking at the poses of its motion proofs.

Poses: the proof's carrier angles φ (``sweep_steps`` per turn, :func:`.proofs.motion_proofs`): the fixed
cam with its channel, the carrier turned by φ, each leg j (with its roller and shoe) placed by
:func:`.proofs.leg_poses` at φ + 2πj/n — the placement the sweeps used — and the ground line at the
hub height the proof found at that step from the exported shoe outline (seed 001 eq. 3): the ground
is where the lowest shoe stands, y = −hub height below the axle.  Every k-th step, the grid shifted
onto the step of least clearance; in every frame the pair of least clearance at that step (roller to
the channel's outer wall, legs in their slides, shoes to the carrier, neighbouring and opposite
legs) is marked with its value.
"""

from __future__ import annotations

import math

import numpy as np

from ...checks.motion import rotation_matrices
from ..media import AnimationJob, chord_for_view, every, loops_of
from .design import Plan
from .proofs import leg_poses

__all__ = ["walking_animation"]

#: about this many frames per carrier turn
TARGET_FRAMES = 120
#: the sweeps whose least clearance is marked (the working wall is in rolling contact by design)
CLEARANCES = (("roller_outer", "roller to the outer wall"), ("leg_carrier", "leg in its slide"),
              ("shoe_carrier", "shoe to the carrier"), ("neighbours", "neighbouring legs"),
              ("opposite", "opposite legs"))


def walking_animation(dd: Plan, w, built: dict) -> list:
    """``anim/walking.gif``: one carrier turn of the mover at the proof's steps."""
    from ...export.animation import Animation, Mark, Shape

    pl, p = dd, dd.params
    pr = built["proofs"]
    phi = pr["phi"]
    hub = pr["hub"]["hub"]
    N = len(phi)
    n_legs = int(p.n_legs)
    names = [(key, what) for key, what in CLEARANCES if key in pr]
    C = np.array([pr[key].clearance for key, _ in names])      # (pairs, steps)
    pair_at = np.argmin(C, axis=0)
    least_step = int(np.argmin(C.min(axis=0)))
    k = max(1, int(math.ceil(N / TARGET_FRAMES)))
    idx = np.arange(least_step % k, N, k)
    n = len(idx)
    R = max(pl.rim_radius, float(np.max(hub)) + 10.0)
    chord = chord_for_view(2.2 * R)
    car = rotation_matrices(phi[idx])
    shapes = [Shape(loops_of(pl.plate, chord), "steel"), Shape(loops_of(pl.ring, chord), "brown"),
              Shape(loops_of(pl.core, chord), "brown")]
    legs = [leg_poses(pl, phi[idx] + 2.0 * math.pi * j / n_legs) for j in range(n_legs)]
    # the 3D view of the assembly (carrier at assembly_angle_deg): carrier, legs, rollers, shoes at the same poses
    a0 = math.radians(p.assembly_angle_deg)
    nodes = {"carrier": (car, rotation_matrices([a0])[0])}
    for j, M in enumerate(legs):
        ref = leg_poses(pl, np.array([a0 + 2.0 * math.pi * j / n_legs]))[0]
        nodes.update({f"{what}_{j + 1}": (M, ref) for what in ("leg", "roller", "shoe")})
    # drawn as seen through the carrier: its outline, the legs, the rollers (in the channel, under the legs)
    shapes.append(Shape(loops_of(pl.carrier.profile, chord), "green", car, fill=False, width=2))
    shapes += [Shape(loops_of(pl.leg, chord), "blue", M) for M in legs]
    shapes += [Shape(loops_of(pl.roller, chord), "purple", M) for M in legs]
    shapes += [Shape(loops_of(pl.shoe.profile, chord), "orange", M) for M in legs]
    ground = np.zeros((n, 2, 3))
    ground[:, 0, 0] = ground[:, 1, 1] = 1.0
    ground[:, 1, 2] = -hub[idx]
    shapes.append(Shape((np.array([[-1.1 * R, 0.0], [1.1 * R, 0.0]]),), "ink", ground, closed=False, width=2))
    drop = np.zeros_like(ground)  # the hub height: axle (origin) down to the ground
    drop[:, 0, 0] = 1.0
    drop[:, 1, 1] = hub[idx]
    shapes.append(Shape((np.array([[0.0, 0.0], [0.0, -1.0]]),), "ink", drop, closed=False))
    least = float(C[pair_at[least_step], least_step])
    least_what = names[int(pair_at[least_step])][1]
    hmin, hmax = float(np.min(hub)), float(np.max(hub))
    captions, marks = [], []
    for s in idx:
        m = int(pair_at[s])
        r = pr[names[m][0]]
        pt = 0.5 * (r.point_a[s] + r.point_b[s])
        is_least = s == least_step
        marks.append([Mark((float(pt[0]), float(pt[1])), f"{'LEAST ' if is_least else ''}{C[m, s]:.3f} mm",
                           radius_px=8 if is_least else 5),
                      Mark((0.0, float(-hub[s])), f"hub height {hub[s]:.4f} mm", colour="ink", radius_px=3)])
        captions.append([f"carrier φ = {math.degrees(phi[s]):.1f}° (proof step {s + 1} of {N}); leg "
                         f"{int(pr['hub']['leg'][s]) + 1} supports; least clearance now {C[m, s]:.3f} mm "
                         f"({names[m][1]})",
                         ("!" if is_least else "") + f"hub height over the turn {hmin:.4f} … {hmax:.4f} mm; least "
                         f"clearance {least:.3f} mm ({least_what}, φ = {math.degrees(phi[least_step]):.1f}°)"])
    title = (f"Cam mover walking: fixed cam and channel (brown), carrier (green), {n_legs} legs (blue) with "
             f"rollers (purple) and shoes (orange), ground at the hub height (black)")
    anim = Animation(title, shapes, n, captions, marks, width_px=560,
                     keep=(int(np.nonzero(idx == least_step)[0][0]),), aspect_range=(0.8, 1.0))
    return [AnimationJob("walking", anim,
            title=f"the mover over one carrier turn: carrier, {n_legs} legs sliding, rollers in the channel, shoes "
                  f"on the ground at the hub height",
            poses=f"{every(k)} of the motion proof's {N} carrier angles (grid through the step of least clearance)",
            least_clearance_mm=least, steps=idx,
            pose_columns={"phi_deg": [math.degrees(x) for x in phi[idx]], "hub_height_mm": hub[idx],
                          "least_clearance_mm": C.min(axis=0)[idx],
                          "least_clearance_between": [names[int(pair_at[s])][1] for s in idx]},
            assembly="assembly", nodes=nodes)]
