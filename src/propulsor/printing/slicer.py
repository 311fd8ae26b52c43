"""PrusaSlicer as the judge of a plate and its planner: does it slice, is every object manifold and on
the bed, how long does it print and how much filament does it take.

Runs the command-line ``prusa-slicer`` (Debian package ``prusa-slicer``) when installed:
``--export-gcode --dont-arrange`` with the printer's bed and print settings
(:meth:`.printers.Printer.slicer_args`) must exit 0 and write G-code, and ``--info`` must report
``manifold = yes`` for every object.  The G-code's own comments give the print time (normal mode)
and the filament (mm, cm³, g): :func:`gcode_stats`.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

#: PrusaSlicer may take this long for one plate (s)
SLICE_TIMEOUT_S = 600


def slicer_path() -> str | None:
    return shutil.which("prusa-slicer")


@dataclass
class SliceResult:
    ok: bool
    message: str
    gcode_bytes: int = 0
    objects: list[dict] = field(default_factory=list)  # --info per object: name, manifold, size_*
    #: from the G-code's comments: time_s, filament_mm, filament_cm3, filament_g (:func:`gcode_stats`)
    stats: dict = field(default_factory=dict)

    @property
    def all_manifold(self) -> bool:
        return bool(self.objects) and all(o.get("manifold") == "yes" for o in self.objects)

    def off_bed(self, bed_x: float, bed_y: float, tol: float = 1e-3) -> list[str]:
        """Objects (by their place in the file, 1-based) not lying on the bed inside its outline."""
        bad = []
        for k, o in enumerate(self.objects, 1):
            try:
                lo = [float(o[f"min_{a}"]) for a in "xyz"]
                hi = [float(o[f"max_{a}"]) for a in "xy"]
            except (KeyError, ValueError):
                bad.append(f"object {k}: no extents")
                continue
            if lo[0] < -tol or lo[1] < -tol or hi[0] > bed_x + tol or hi[1] > bed_y + tol or abs(lo[2]) > tol:
                bad.append(f"object {k}")
        return bad


def _run(args: list[str]) -> subprocess.CompletedProcess:
    return subprocess.run(args, capture_output=True, text=True, timeout=SLICE_TIMEOUT_S,
                          env={"PATH": "/usr/bin:/bin", "HOME": "/tmp", "LC_ALL": "C"})


def info(path: Path) -> list[dict]:
    """`prusa-slicer --info`: one dict per object section ([name] then key = value lines)."""
    r = _run([slicer_path() or "prusa-slicer", "--info", str(path)])
    objects, cur = [], None
    for line in r.stdout.splitlines():
        m = re.match(r"^\[(.+)\]$", line.strip())
        if m:
            cur = {"name": m.group(1)}
            objects.append(cur)
        elif cur is not None and "=" in line:
            k, v = (s.strip() for s in line.split("=", 1))
            cur[k] = v
    return objects


_TIME = re.compile(r"^; estimated printing time \(normal mode\) = (.+)$", re.M)
_USED = {"filament_mm": r"filament used \[mm\]", "filament_cm3": r"filament used \[cm3\]",
         "filament_g": r"total filament used \[g\]"}


def duration_s(text: str) -> int:
    """PrusaSlicer's '1d 2h 3m 4s' (any of the parts) in seconds."""
    units = {"d": 86400, "h": 3600, "m": 60, "s": 1}
    found = re.findall(r"(\d+)\s*([dhms])", text)
    if not found:
        raise ValueError(f"not a PrusaSlicer duration: {text!r}")
    return sum(int(n) * units[u] for n, u in found)


def gcode_stats(text: str) -> dict:
    """Print time (s) and filament (mm, cm³, g) from the comments PrusaSlicer writes at a G-code's end;
    a value it did not write is left out."""
    out = {}
    m = _TIME.search(text)
    if m:
        out["time_s"] = duration_s(m.group(1))
    for key, pat in _USED.items():
        m = re.search(rf"^; {pat} = ([0-9.]+)\s*$", text, re.M)
        if m:
            out[key] = float(m.group(1))
    return out


def slice_plate(path: Path, bed_shape: str, gcode: Path, layer_mm: float = 0.2, nozzle_mm: float = 0.4,
                args: list[str] | None = None) -> SliceResult:
    """Slice one plate with the printer's bed (or with `args`, the printer's slicer_args, which hold the
    bed); the G-code goes to `gcode`."""
    exe = slicer_path()
    if exe is None:
        return SliceResult(False, "prusa-slicer is not installed (Debian package prusa-slicer)")
    opts = args if args is not None else ["--bed-shape", bed_shape, "--layer-height", f"{layer_mm:g}",
                                          "--nozzle-diameter", f"{nozzle_mm:g}"]
    r = _run([exe, "--export-gcode", "--dont-arrange", *opts, "--output", str(gcode), str(path)])
    errors = [line for line in (r.stderr + r.stdout).splitlines()
              if "error" in line.lower() and "[trace]" not in line and "[debug]" not in line]
    ok = r.returncode == 0 and gcode.is_file() and gcode.stat().st_size > 0
    msg = "sliced" if ok else f"exit {r.returncode}: " + ("; ".join(errors[-3:]) or r.stderr.strip()[-300:])
    stats = {}
    if ok:
        with open(gcode, "rb") as fh:  # the comments are at the end
            fh.seek(max(0, gcode.stat().st_size - 64 * 1024))
            stats = gcode_stats(fh.read().decode("utf-8", "replace"))
    return SliceResult(ok, msg, gcode.stat().st_size if gcode.is_file() else 0, info(path), stats)


def slice_kit(folder: Path, printer, work: Path, fullest_only: bool = False) -> list[tuple[str, SliceResult, list[str]]]:
    """Slice the plates of a kit folder with the printer's bed (every plate, or the one holding the most
    pieces by the kit's ``tables/plates.csv``): [(plate file name, result, objects off the bed)]."""
    folder, work = Path(folder), Path(work)
    plates = sorted(folder.glob("plate_*.3mf"))
    if fullest_only:
        rows = [r.split(",") for r in (folder / "tables" / "plates.csv").read_text().splitlines()[1:]]
        plates = [folder / f"plate_{max(rows, key=lambda r: int(r[1]))[0]}.3mf"]
    out = []
    for plate in plates:
        r = slice_plate(plate, printer.bed_shape(), work / f"{plate.stem}.gcode", args=printer.slicer_args())
        out.append((plate.name, r, r.off_bed(printer.bed_x_mm, printer.bed_y_mm)))
    return out
