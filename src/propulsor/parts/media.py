"""Animations of a part's proven motion, handed to the writer.

Each part type gathers, in its own ``animation.py``, the poses its proof evaluated (every k-th, always
with the pose of least clearance or backlash) and its outlines placed by them, as
:class:`AnimationJob` s; :func:`start` draws the frames (:mod:`propulsor.export.animation`) and
writes ``anim/<name>.gif`` in a forked worker while the build goes on, :func:`collect` (before the
writer finishes) writes the table ``tables/anim_<name>.csv`` (which proof step each frame shows,
with its pose values), lists the GIF in the manifest's ``media.animations`` (the gallery's
contract) and names it in the report.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

__all__ = ["AnimationJob", "start", "collect", "publish", "pipeline_steps", "loops_of", "chord_for_view",
           "wheel_side_view", "every"]

#: frame duration of every animation (ms)
FRAME_MS = 60
#: GIF width (px)
WIDTH_PX = 600
#: at most this many bytes per GIF (the writer thins frames beyond it)
MAX_BYTES = 2_000_000


def chord_for_view(extent_mm: float, panel_px: float = 0.9 * WIDTH_PX) -> float:
    """Chord tolerance (mm) that keeps a sampled outline within a quarter pixel of its curve when
    ``extent_mm`` fills ``panel_px`` pixels."""
    return 0.25 * extent_mm / panel_px


def loops_of(profile, chord_tol: float) -> tuple:
    """A 2D profile's loops (outer first, then holes) as closed polylines (mm)."""
    return tuple(np.asarray(q, float) for q in profile.polylines(chord_tol))


def every(k: int) -> str:
    """'every', 'every 2nd', 'every 3rd', 'every 4th' … (of a list of poses)."""
    if k == 1:
        return "every one"
    suffix = "th" if 10 <= k % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(k % 10, "th")
    return f"every {k}{suffix}"


@dataclass(frozen=True)
class AnimationJob:
    """One GIF to write: the frames to draw and what the manifest and the report say of it.

    ``steps``: the proof step (index into the proof's pose list) of each frame; ``pose_columns``:
    {column name: values per frame} written beside them (the pose values the proof evaluated)."""

    name: str
    anim: object  # export.animation.Animation
    title: str
    poses: str
    least_clearance_mm: float | None
    steps: object
    pose_columns: dict
    least_what: str = "least clearance"
    #: the same poses in the 3D view: the assembly (its GLB) whose components move, and for each moving
    #: component (its name in the assembly) its (frames, 2, 3) poses in the assembly's x-y plane and the
    #: pose (2, 3) that the assembly shows it at (the component is moved by pose · reference⁻¹)
    assembly: str = ""
    nodes: dict = field(default_factory=dict)


def _render(jobs_and_paths) -> list:
    from ..export.animation import write_animation

    return [write_animation(anim, path, max_bytes=MAX_BYTES) for anim, path in jobs_and_paths]


def start(w, jobs) -> tuple:
    """Draw and write the GIFs of ``jobs`` in one forked worker (inline on a budget of one process);
    :func:`collect` records them.  Returns the pending work."""
    from ..parallel import start as start_in_fork

    jobs = list(jobs)
    w.progress(f"animations: {', '.join(j.name for j in jobs)} ({sum(j.anim.n_frames for j in jobs)} frames)")
    paths = [str(w.path(f"anim/{j.name}.gif")) for j in jobs]
    return start_in_fork(_render, [(j.anim, pth) for j, pth in zip(jobs, paths)]), jobs


def collect(w, pending) -> list:
    """Wait for the GIFs started by :func:`start`; write each one's frame table, list it in the manifest's
    ``media.animations`` and name it in the report.  Returns the media entries."""
    fut, jobs = pending
    return [_record(w, j, info) for j, info in zip(jobs, fut.result())]


def publish(w, job: AnimationJob) -> dict:
    """Draw, write and record one GIF here and now."""
    return collect(w, start(w, [job]))[0]


def pipeline_steps(jobs_fn) -> tuple:
    """(start step, collect step) of a part's pipeline for the animations ``jobs_fn(design, writer, built)``
    returns: the first starts them once the proof's poses are there, the second (last) records them."""

    def start_animations(d, w, built: dict) -> None:
        built["pending_animations"] = start(w, jobs_fn(d, w, built))

    def collect_animations(d, w, built: dict) -> None:
        collect(w, built.pop("pending_animations"))

    return start_animations, collect_animations


def _record(w, job: AnimationJob, info) -> dict:
    rel = f"anim/{job.name}.gif"
    kept = list(info.frames)
    steps = np.asarray(job.steps)
    cols = {"frame": list(range(len(kept))), "proof_step": [int(steps[i]) for i in kept]}
    for key, vals in job.pose_columns.items():
        vals = np.asarray(vals)
        cols[key] = [vals[i].item() for i in kept]
    w.add_table(f"anim_{job.name}", cols, None)
    least = job.least_clearance_mm
    least = None if least is None or not math.isfinite(float(least)) else float(least)
    poses = job.poses
    if len(kept) < job.anim.n_frames:  # thinned to stay under MAX_BYTES
        poses += f"; of these, {len(kept)} of {job.anim.n_frames} kept to stay under {MAX_BYTES / 1e6:g} MB"
    entry = {"path": rel, "title": job.title, "frames": len(kept), "width_px": info.width_px,
             "height_px": info.height_px, "bytes": info.bytes, "frame_ms": info.frame_ms, "poses": poses,
             "least_clearance_mm": least}
    w.add_media("animations", entry)
    if job.assembly and job.nodes:
        w.add_motion(job.assembly, {"name": job.name, "title": job.title, "frame_ms": info.frame_ms,
                                    "steps": cols["proof_step"], "poses": poses},
                     {c: (np.asarray(P, float)[kept], np.asarray(ref, float)) for c, (P, ref) in job.nodes.items()})
    in_3d = f"; the same poses move the 3D view of `{job.assembly}.glb`" if job.assembly and job.nodes else ""
    w.add_note(f"Animation `{rel}`: {job.title} — {len(kept)} frames of {info.width_px} × {info.height_px} px, "
               f"{info.frame_ms} ms each, {info.bytes / 1024:.0f} KiB; poses: {poses} (table "
               f"tables/anim_{job.name}.csv{in_3d})" + (f"; {job.least_what} {least:.4g} mm marked in red."
                                                         if least is not None else "."))
    return entry


def wheel_side_view(m, chord_tol: float) -> list:
    """The road wheel seen along its axis (wheel frame, axis at the origin), as (loops, colour) pairs
    drawn in order: the tyre (rubber annulus), the rim, the web with its lightening holes and the
    bearing seat.  ``m``: the wheel's :class:`~propulsor.solids.road_wheel.WheelModel`."""
    from ..geometry.profile import circle_loop

    def ring(r_out, r_in):
        return (circle_loop(r_out).polyline(chord_tol), circle_loop(r_in, ccw=False).polyline(chord_tol))

    holes = [circle_loop(0.5 * m.p.bearing_inner_D_mm, ccw=False).polyline(chord_tol)]
    for k in range(m.p.lightening_holes):
        a = 2.0 * math.pi * (k + 0.5) / m.p.lightening_holes
        holes.append(circle_loop(0.5 * m.p.lightening_hole_d_mm, (m.hole_circle_r * math.cos(a),
                                                                 m.hole_circle_r * math.sin(a)), ccw=False)
                     .polyline(chord_tol))
    web = (circle_loop(m.r_rim_in).polyline(chord_tol), *holes)
    return [(ring(m.r_tyre, m.r_rim_out), "rubber"), (ring(m.r_rim_out, m.r_rim_in), "steel"), (web, "steel")]
