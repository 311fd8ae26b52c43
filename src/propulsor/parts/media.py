"""Animations of a part's proven motion, handed to the writer (issue 14, "See it move").

Each part type gathers, in its own ``animation.py``, the poses its proof evaluated (every k-th, always
with the pose of least clearance or backlash) and its outlines placed by them; :func:`publish`
renders the frames (:mod:`propulsor.export.animation`), writes ``anim/<name>.gif``, the table
``tables/anim_<name>.csv`` (which proof step each frame shows, with its pose values), lists the GIF
in the manifest's ``media.animations`` (the gallery's contract) and names it in the report.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["publish", "loops_of", "chord_for_view", "least_text"]

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


def least_text(value, what: str = "least clearance") -> str:
    return f"{what} {value:.4g} mm" if value is not None and math.isfinite(value) else f"{what}: none"


def publish(w, name: str, anim, *, title: str, poses: str, least_clearance_mm, steps, pose_columns: dict,
            least_what: str = "least clearance") -> dict:
    """Render ``anim`` to ``anim/<name>.gif``, write its frame table, add the media entry and a note.

    ``steps``: the proof step (index into the proof's pose list) of each frame; ``pose_columns``:
    {column name: values per frame} written beside them (the pose values the proof evaluated)."""
    from ..export.animation import write_animation

    rel = f"anim/{name}.gif"
    info = write_animation(anim, w.path(rel), max_bytes=MAX_BYTES)
    kept = list(info.frames)
    steps = np.asarray(steps)
    cols = {"frame": list(range(len(kept))), "proof_step": [int(steps[i]) for i in kept]}
    for key, vals in pose_columns.items():
        vals = np.asarray(vals)
        cols[key] = [vals[i].item() for i in kept]
    w.add_table(f"anim_{name}", cols, None)
    least = None if least_clearance_mm is None or not math.isfinite(float(least_clearance_mm)) \
        else float(least_clearance_mm)
    entry = {"path": rel, "title": title, "frames": len(kept), "width_px": info.width_px,
             "height_px": info.height_px, "bytes": info.bytes, "frame_ms": info.frame_ms, "poses": poses,
             "least_clearance_mm": least}
    w.add_media("animations", entry)
    w.add_note(f"Animation `{rel}`: {title} — {len(kept)} frames of {info.width_px} × {info.height_px} px, "
               f"{info.frame_ms} ms each, {info.bytes / 1024:.0f} KiB; poses: {poses} (table tables/anim_{name}.csv)"
               + (f"; {least_what} {least:.4g} mm marked in red." if least is not None else "."))
    return entry
