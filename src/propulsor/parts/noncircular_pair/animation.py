"""The non-circular pair turning through one driven turn at the poses of its full-cycle proof
(:mod:`.pair_proof`), with the ratio U and the hub speed v/ω traced beside it.

Poses: the proof's phases φ_k; the driven wheel (axis at the origin) at its running angle −φ_run
(loaded flanks touching; at a jammed phase the position of least overlap), the driver (axis at
(L, 0)) at +θ_law(φ_k), exactly as the proof placed them.  Every k-th phase, k/(phases per tooth) a
whole number of teeth plus 0.2 … 0.4 (the teeth are seen to advance in the turning sense instead of
standing still; :func:`_stride`), the grid shifted onto the phase of least backlash.  Traces:
U = dθ/dφ and v/ω = (dX01/dφ)/U of the law the teeth realise (seed 000 eq. 2, 3, 15: the blended law for
generated teeth, the staircase of ideal sector teeth for the papers' method), at the same phases.
"""

from __future__ import annotations

import math

import numpy as np

from ...checks.motion import rotation_matrices
from ..media import AnimationJob, chord_for_view, every, loops_of
from ...laws.law import is_walking
from .design import PairDesign

__all__ = ["pair_animation"]

#: about this many frames (one driven turn)
TARGET_FRAMES = 80
#: samples of the traced curves over the turn (besides the proof's phases)
TRACE_SAMPLES = 2881
#: the tooth method as the titles say it
_METHOD = {"generated": "generated teeth", "sectors": "the papers' sector teeth"}
#: the pair and its two traces side by side
WIDTH_PX_PAIR = 640


def _ratio_and_hub_speed(d, phi):
    """U(φ) and v/ω(φ) of the law the teeth realise (seed 000 eq. 2, 3, 15)."""
    if d.method == "sectors":
        from ...gears.sectors import sector_ratio

        U = np.asarray(sector_ratio(d.table, phi), float)
        return U, np.asarray(d.law.dX01_dphi(phi), float) / U
    if not is_walking(d.law):  # no hub: the output speed ratio (driven over driver speed) 1/U
        U = np.asarray(d.run_law.U(phi), float)
        return U, 1.0 / U
    return np.asarray(d.run_law.U(phi), float), np.asarray(d.run_law.hub_speed(phi), float)


def _stride(n_phases: int, per_tooth: int) -> int:
    """Every k-th phase: at most about 2 × TARGET_FRAMES frames, and k/per_tooth teeth per frame a whole
    number plus 0.2 … 0.4 (the teeth are seen to advance in the turning sense, not to stand or run back)."""
    k0 = max(1, math.ceil(n_phases / (2 * TARGET_FRAMES)))
    for k in range(k0, k0 + per_tooth + 1):
        if 0.2 - 1e-9 <= (k / per_tooth) % 1.0 <= 0.4 + 1e-9:
            return k
    return k0


def pair_animation(dd: PairDesign, w, built: dict) -> list:
    """``anim/pair.gif``: the pair over one driven turn at the proof's phases."""
    from ...export.animation import Animation, Mark, Shape, Trace

    d, pr, mount = dd.d, built["proof"], dd.mount
    N = len(pr.phi)
    bl = pr.backlash_mm
    free = np.isfinite(bl)
    least_k = int(np.nanargmin(np.where(free, bl, np.nan))) if free.any() else None
    jam = ~np.isfinite(pr.phi_drive)
    worst_jam = int(np.argmax(np.where(jam, pr.least_overlap, -1.0))) if jam.any() else None
    ppt = max(1, round(N / d.z_H))  # proof phases per driven tooth
    k = _stride(N, ppt)
    start = least_k % k if least_k is not None else 0
    idx = sorted(set(range(start, N, k)) | ({worst_jam} if worst_jam is not None else set()))
    idx = np.array(idx, dtype=int)
    n = len(idx)
    prof_drv, prof_dvn = dd.profiles
    r_dvn = max(float(np.max(np.hypot(*q.T))) for q in loops_of(prof_dvn, 1.0))
    r_drv = max(float(np.max(np.hypot(*q.T))) for q in loops_of(prof_drv, 1.0))
    chord = chord_for_view(mount + r_dvn + r_drv, int(0.64 * WIDTH_PX_PAIR))
    phi_run = pr.phi_run
    driven = Shape(loops_of(prof_dvn, chord), "blue", rotation_matrices(-phi_run[idx]))
    driver = Shape(loops_of(prof_drv, chord), "orange",
                   rotation_matrices(pr.theta_law[idx], np.tile([mount, 0.0], (n, 1))))
    # the 3D view of the pair (assembly at φ = θ = 0: driven at the origin, driver at (L, 0)): the same poses
    nodes = {"driven": (driven.poses, rotation_matrices([0.0])[0]),
             "driver": (driver.poses, rotation_matrices([0.0], [[mount, 0.0]])[0])}
    axes = Shape((np.array([[-0.06 * r_dvn, 0.0], [mount + 0.06 * r_drv, 0.0]]),), "grey", None, closed=False)
    U, hub = _ratio_and_hub_speed(d, pr.phi)
    deg = np.degrees(pr.phi)
    # the curves drawn densely (the proof's phases among them), the marker at the frame's proof phase
    dense = np.union1d(pr.phi, np.linspace(0.0, 2.0 * math.pi, TRACE_SAMPLES))
    at = np.searchsorted(dense, pr.phi[idx])
    U_d, hub_d = _ratio_and_hub_speed(d, dense)
    dd_deg = np.degrees(dense)
    walking = is_walking(d.law)
    traces = [Trace("U = dθ/dφ", dd_deg, U_d, at, "orange", "φ, deg (grey: exact law)", "{:.4f}",
                    ref=(dd_deg, np.asarray(d.law.U(dense), float))),
              Trace("v/ω, mm/rad", dd_deg, hub_d, at, "blue", "φ, deg (grey: exact law)", "{:.2f}",
                    ref=(dd_deg, np.asarray(d.law.hub_speed(dense), float))) if walking else
              Trace("ω_H/ω = 1/U", dd_deg, hub_d, at, "blue", f"φ, deg ({d.law.kind} law)", "{:.4f}")]
    least_txt = (f"least backlash {bl[least_k]:.4f} mm at φ = {deg[least_k]:.2f}°" if least_k is not None
                 else "no free phase: every phase jams")
    captions, marks = [], []
    for j, kk in enumerate(idx):
        pitch_pt = (float(pr.r_ref[kk]), 0.0)
        line1 = (f"φ = {deg[kk]:7.2f}° (proof phase {kk + 1} of {N}), θ = {math.degrees(pr.theta_law[kk]):8.2f}°, "
                 + (f"U = {U[kk]:.4f}, v/ω = {hub[kk]:.2f} mm/rad" if walking else
                    f"U = {U[kk]:.4f}, ω_H/ω = {hub[kk]:.4f}"))
        if jam[kk]:
            line2 = f"!JAM: no free position of the driven wheel; least overlap {pr.least_overlap[kk]:.4g} mm²"
            mk = [Mark(pitch_pt, f"jam {pr.least_overlap[kk]:.3g} mm²")]
        else:
            line2 = (f"backlash {bl[kk]:.4f} mm, tooth pairs in contact {int(pr.pairs_drive[kk])}; " + least_txt)
            mk = [Mark(pitch_pt, f"{'LEAST ' if kk == least_k else ''}backlash {bl[kk]:.4f} mm",
                       radius_px=8 if kk == least_k else 5)]
            if kk == least_k:
                line2 = "!" + line2
        captions.append([line1, line2])
        marks.append(mk)
    title = (f"Non-circular pair, {_METHOD[d.method]}: driven wheel (blue, z_H = {d.z_H}), driver (orange, z = {d.z}, "
             f"{d.law.n} turns per driven turn)")
    keep = tuple(j for j, kk in enumerate(idx) if kk in (least_k, worst_jam))
    anim = Animation(title, [axes, driven, driver], n, captions, marks, traces, width_px=WIDTH_PX_PAIR,
                     keep=keep, aspect_range=(0.62, 0.8))
    what = "one driven turn" + (f", the jammed phase of largest overlap added" if worst_jam is not None else "")
    return [AnimationJob("pair", anim,
            title=f"the pair turning through one driven turn ({_METHOD[d.method]}) with U and "
                  f"{'v/ω' if walking else 'ω_H/ω'} traced",
            poses=f"{every(k)} of the proof's {N} phases ({what}"
                  + ("; grid through the phase of least backlash)" if least_k is not None else ")"),
            least_clearance_mm=None if least_k is None else float(bl[least_k]), least_what="least backlash",
            steps=idx, pose_columns={"phi_rad": pr.phi[idx], "phi_run_rad": phi_run[idx],
                                     "theta_law_rad": pr.theta_law[idx]}, assembly="pair", nodes=nodes)]
