"""The road wheel rolling through one revolution on flat ground.

The wheel has no mechanism and no motion proof: the frames are 36 wheel angles 10° apart (one
revolution; with the lightening holes spaced 360°/holes the web is seen to turn).  The tyre stands
flattened on the ground by Kozlov's deflection λ_m at the load per row (seed 004 eq. 76-80, the
values of :func:`.proofs.kozlov_proof`); its contact chord l is drawn in red on the ground line; the
ground's marks move under the axle by the rolling distance R·Δα per frame.
"""

from __future__ import annotations

import math

import numpy as np

from ...checks.motion import rotation_matrices
from ..media import AnimationJob, chord_for_view, wheel_side_view
from .design import RoadWheelDesign

__all__ = ["rolling_animation"]

#: wheel angles per revolution
FRAMES = 36


def rolling_animation(dd: RoadWheelDesign, w, built: dict) -> list:
    """``anim/rolling.gif``: one revolution of the wheel on the ground, the contact chord marked."""
    from ...export.animation import Animation, Mark, Shape

    m = dd.model
    l, lam = float(built["l"]), float(built["lam"])
    R = m.r_tyre
    y_g = -(R - lam)
    chord = chord_for_view(2.6 * R)
    alpha = -2.0 * math.pi * np.arange(FRAMES) / FRAMES      # clockwise: rolling towards +x
    turn = rotation_matrices(alpha)
    parts = wheel_side_view(m, chord)
    (outer, inner), _ = parts[0]
    tyre = (np.column_stack([outer[:, 0], np.maximum(outer[:, 1], y_g)]), inner)  # flattened on the ground
    shapes = [Shape(tyre, "rubber")] + [Shape(loops, col, turn) for loops, col in parts[1:]]
    # ground: the line and its marks every 0.25 R, moving back by the rolling distance R·Δα per frame
    X = 1.3 * R
    step = 0.25 * R
    ticks = tuple(np.array([[x, y_g], [x - 0.06 * R, y_g - 0.08 * R]]) for x in np.arange(-X + step, X + 1e-9, step))
    shift = np.zeros((FRAMES, 2, 3))
    shift[:, 0, 0] = shift[:, 1, 1] = 1.0
    shift[:, 0, 2] = -np.mod(R * 2.0 * math.pi * np.arange(FRAMES) / FRAMES, step)
    shapes += [Shape((np.array([[-X, y_g], [X, y_g]]),), "ink", None, closed=False, width=2),
               Shape(ticks, "grey", shift, closed=False),
               Shape((np.array([[-0.5 * l, y_g], [0.5 * l, y_g]]),), "red", None, closed=False, width=4)]
    marks = [[Mark((0.0, 0.0), "", colour="ink", radius_px=2)] for _ in range(FRAMES)]
    captions = [[f"wheel angle {math.degrees(-a):.0f}° of one revolution; load per row {dd.P_row:.0f} N",
                 f"Kozlov (seed 004 eq. 76-80): contact chord l = {l:.1f} mm (red), deflection λ_m = {lam:.2f} mm"]
                for a in alpha]
    title = (f"Road wheel D = {2 * R:g} mm rolling on flat ground: tyre (dark), rim and web with "
             f"{m.p.lightening_holes} lightening holes (grey)")
    anim = Animation(title, shapes, FRAMES, captions, marks, width_px=520, aspect_range=(0.8, 1.0))
    return [AnimationJob("rolling", anim,
            title="the road wheel rolling through one revolution on flat ground, contact chord marked",
            poses=f"{FRAMES} wheel angles {360 // FRAMES}° apart over one revolution (no mechanism, no motion proof)",
            least_clearance_mm=None, steps=np.arange(FRAMES),
            pose_columns={"wheel_angle_deg": [math.degrees(-a) for a in alpha]})]
