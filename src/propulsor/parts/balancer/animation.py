"""The balancer with its road wheel through the travel β0 … β_m at the poses of the travel sweep, side
view, against the hull and the neighbouring stations.

Poses: the sweep's angles β (:func:`.proofs.travel_sweep`, ``sweep_steps_per_deg``; β from the downward
vertical, seed 004 eq. 5): the arm's outline turned about the torsion axis by β − 90°, the wheel on its
axis at (R_b sin β, −R_b cos β); each neighbouring station (±pitch) at the travel angle the sweep gave
it at that step (the one that brings its wheel closest).  The hull envelope's bottom plate and fender
are the sweep's slabs seen from the side.  Every k-th step up from β0 to β_m and back down, the grid
through the step of least clearance, where the sweep's closest points are marked with the value.
"""

from __future__ import annotations

import math

import numpy as np

from ...checks.motion import rotation_matrices
from ..media import AnimationJob, chord_for_view, every, loops_of, wheel_side_view
from .design import BalancerModel

__all__ = ["travel_animation"]

#: about this many frames up the travel (as many again back down)
TARGET_FRAMES = 48
_LABELS = {"hull": "hull envelope", "front": "front station", "rear": "rear station"}


def _station(m: BalancerModel, beta: np.ndarray, x0: float, chord: float, colour: str) -> list:
    """Arm and wheel of one station (torsion axis at (x0, 0)) at the angles ``beta``: shapes."""
    from ...export.animation import Shape

    p = m.p
    th = np.asarray(beta, float) - 0.5 * math.pi
    arm = rotation_matrices(th, np.tile([x0, 0.0], (len(th), 1)))
    centre = np.column_stack([x0 + p.R_b_mm * np.sin(beta), -p.R_b_mm * np.cos(beta)])
    wheel = rotation_matrices(np.zeros(len(th)), centre)
    shapes = [Shape(loops, col, wheel) for loops, col in wheel_side_view(m.wheel, chord)]
    shapes.append(Shape(loops_of(m.outline.profile, chord), colour, arm))
    return shapes


def travel_animation(m: BalancerModel, w, built: dict) -> list:
    """``anim/travel.gif``: the station through its travel and back, side view (world: x forward, y up)."""
    from ...export.animation import Animation, Mark, Shape

    p, t = m.p, m.tor
    sw = built["sweep"]
    betas = sw["beta"]
    N = len(betas)
    pairs = sw["pairs"]
    worst = min(pairs, key=lambda nm: float(pairs[nm]["gap_mm"][pairs[nm]["worst_step"]]))
    ks = int(pairs[worst]["worst_step"])
    least = float(pairs[worst]["gap_mm"][ks])
    pa, pb, _ = pairs[worst]["where"]
    k = max(1, int(math.ceil(N / TARGET_FRAMES)))
    up = sorted(set(range(ks % k, N, k)) | {0, N - 1})  # from β0 to β_m
    down = up[-2:0:-1]
    idx = np.array(up + down, dtype=int)
    n = len(idx)
    X = m.pitch + p.R_b_mm + m.wheel.r_tyre
    chord = chord_for_view(2.2 * X)
    H, yf = p.hull_bottom_mm, p.fender_height_mm
    slab = lambda y0, y1: (np.array([[-1.05 * X, y0], [1.05 * X, y0], [1.05 * X, y1], [-1.05 * X, y1]]),)  # noqa: E731
    shapes = [Shape(slab(-H - 30.0, -H), "brown"), Shape(slab(yf, yf + 30.0), "brown")]
    for name, x0 in (("front", m.pitch), ("rear", -m.pitch)):
        if name in pairs:
            shapes += _station(m, pairs[name]["neighbour_beta"][idx], x0, chord, "teal")
    shapes += _station(m, betas[idx], 0.0, chord, "blue")
    # the 3D view of the assembly at β_st: arm and wheel turn together about the torsion axis (z) to each β
    arm = rotation_matrices(betas[idx] - 0.5 * math.pi)
    at_st = rotation_matrices([t.beta_st - 0.5 * math.pi])[0]
    nodes = {c: (arm, at_st) for c in built.get("assembly_components", ())}
    axes = [(0.0, 0.0)] + [(x0, 0.0) for x0 in (m.pitch, -m.pitch)]
    marks, captions = [], []
    for s in idx:
        gaps = []
        for name, dd in pairs.items():
            g = float(dd["gap_mm"][s])
            gaps.append(f"{_LABELS[name]} {'>= ' if dd['capped'][s] else ''}{g:.1f} mm")
        mk = [Mark(a, "", colour="ink", radius_px=2) for a in axes]
        if s == ks and pa is not None and pb is not None:
            q = 0.5 * (np.asarray(pa, float) + np.asarray(pb, float))
            mk.append(Mark((float(q[0]), float(q[1])), f"LEAST {least:.2f} mm ({_LABELS[worst]})", radius_px=8))
        marks.append(mk)
        captions.append([f"β = {math.degrees(betas[s]):.2f}° (sweep step {s + 1} of {N}, β0 = "
                         f"{math.degrees(t.beta0):.2f}°, β_m = {math.degrees(t.beta_m):.2f}°); least gap now: "
                         + ", ".join(gaps),
                         ("!" if s == ks else "") + f"least clearance of the travel {least:.2f} mm ({_LABELS[worst]}, "
                         f"β = {math.degrees(betas[ks]):.2f}°; accepted >= {p.min_clearance_mm:g} mm)"])
    title = ("Balancer (blue) with its road wheel through the travel β0 … β_m and back, side view; neighbouring "
             "stations (teal), hull bottom and fender (brown)")
    keep = tuple(j for j, s in enumerate(idx) if s == ks)
    anim = Animation(title, shapes, n, captions, marks, width_px=640, keep=keep, aspect_range=(0.4, 0.8))
    return [AnimationJob("travel", anim,
            title="the balancer arm with its road wheel through the travel β0 … β_m and back, against the hull "
                  "and the neighbouring stations (side view)",
            poses=f"{every(k)} of the travel sweep's {N} angles β0 … β_m, up and back down (grid through the step "
                  f"of least clearance)",
            least_clearance_mm=least, steps=idx,
            pose_columns={"beta_deg": [math.degrees(b) for b in betas[idx]],
                          **{f"{name}_neighbour_beta_deg": [math.degrees(b) for b in pairs[name]["neighbour_beta"][idx]]
                             for name in ("front", "rear") if name in pairs}},
            assembly="assembly_beta_st", nodes=nodes)]
