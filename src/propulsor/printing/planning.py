"""Print planning: how long each plate prints and how much filament it takes, at the stated settings.

Where PrusaSlicer is installed (and the kit is sliced), each plate is sliced with the printer's bed
and print settings (:meth:`.printers.Printer.slicer_args`) and the time and filament are read from the
G-code's comments; the plate must slice with every object manifold and on the bed (checks).  Without
it, the filament is estimated from the pieces at the stated infill: the walls (perimeters × line
width over the surface, at most the volume) solid, the rest at the infill density — and the report
says that the plate was not sliced.
"""

from __future__ import annotations

import tempfile
from dataclasses import dataclass
from pathlib import Path

from ..check import Check


@dataclass
class PlatePlan:
    plate: int
    pieces: int
    volume_cm3: float  # the pieces' solid volume
    estimate_g: float  # filament at the stated infill, estimated from the pieces
    names: str
    time_s: int | None = None  # sliced: PrusaSlicer's normal-mode estimate
    filament_g: float | None = None  # sliced
    filament_m: float | None = None  # sliced


def estimate_g(meshes, printer) -> float:
    """Filament (g) of pieces at the printer's infill: a solid shell, the rest at the infill density.  The shell
    as a slicer lays it: under the faces that look up the top layers, over those that look down the bottom layers
    (a face within 60° of level), behind the others the perimeters × line width — less those walls' share within the
    top and bottom layers, counted there already; at most the piece's volume.  (Before: the thicker of the two over
    every face, 12-20 % over PrusaSlicer's grams on the trial's plates of flat gears.)"""
    import numpy as np

    total = 0.0
    # PrusaSlicer's own perimeter width where the profile gives none: 1.125 nozzle diameters (its auto width)
    t_wall = printer.perimeters * (printer.line_width_mm or 1.125 * printer.nozzle_mm)
    t_top, t_bottom = printer.top_layers * printer.layer_mm, printer.bottom_layers * printer.layer_mm
    for m in meshes:
        vol = float(m.volume)
        nz, area = np.asarray(m.face_normals)[:, 2], np.asarray(m.area_faces)
        up, down = nz > 0.5, nz < -0.5
        walls = float(area[~(up | down)].sum()) * t_wall
        height = float(m.extents[2]) if len(area) else 0.0
        walls *= max(0.0, 1.0 - (t_top + t_bottom) / height) if height > 0 else 0.0
        shell = min(vol, float(area[up].sum()) * t_top + float(area[down].sum()) * t_bottom + walls)
        total += shell + printer.infill_percent / 100.0 * (vol - shell)
    return total / 1000.0 * printer.density_g_cm3


def hours(seconds: int | None) -> str:
    """A print time as a maker reads it: 3 h 25 min, 45 min."""
    if seconds is None:
        return "—"
    h, m = divmod(int(round(seconds / 60.0)), 60)
    return f"{h} h {m:02d} min" if h else f"{m} min"


def slice_plates(plans: list[PlatePlan], plate_paths: list[Path], printer, progress) -> list[Check]:
    """Slice every plate with the printer's settings; fill each plan's time and filament; the checks:
    each plate slices, every object manifold and on the bed, every extrusion of its G-code on the bed."""
    import time

    from .slicer import slice_plate

    checks = []
    t0 = time.perf_counter()
    from ..progress import counter

    tick = counter(progress, "slicing the plates with PrusaSlicer (--slice no skips it)", len(plans), "plate")
    with tempfile.TemporaryDirectory(prefix="propulsor-slice-") as work:
        for k, (plan, path) in enumerate(zip(plans, plate_paths), 1):
            r = slice_plate(path, printer.bed_shape(), Path(work) / f"plate_{plan.plate}.gcode",
                            args=printer.slicer_args())
            off = r.off_bed(printer.bed_x_mm, printer.bed_y_mm)
            if r.ok:  # the skirt and brim too: every line the G-code lays lies on the bed
                off += r.extrusions_off_bed(printer.bed_x_mm, printer.bed_y_mm)
            ok = r.ok and r.all_manifold and not off and "time_s" in r.stats and "filament_g" in r.stats
            checks.append(Check.flag(f"plate_{plan.plate}.sliced", ok,
                                     f"PrusaSlicer: {r.message}; {len(r.objects)} object(s), manifold: "
                                     f"{'all' if r.all_manifold else 'not all'}; off the bed: {off or 'none'}"))
            if ok:
                plan.time_s = int(r.stats["time_s"])
                plan.filament_g = float(r.stats["filament_g"])
                plan.filament_m = float(r.stats.get("filament_mm", 0.0)) / 1000.0
            tick(k)
    progress(f"PrusaSlicer sliced {len(plans)} plate(s) in {time.perf_counter() - t0:.0f} s")
    return checks


def table_rows(plans: list[PlatePlan]) -> list[tuple]:
    return [(p.plate, p.pieces, p.volume_cm3, p.estimate_g, "" if p.time_s is None else p.time_s,
             "" if p.filament_g is None else p.filament_g, "" if p.filament_m is None else p.filament_m, p.names)
            for p in plans]


TABLE_COLUMNS = ["plate", "pieces", "volume_cm3", "estimate_g", "sliced_time_s", "sliced_filament_g",
                 "sliced_filament_m", "names"]
