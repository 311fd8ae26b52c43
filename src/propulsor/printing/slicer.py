"""PrusaSlicer as the judge of a plate and its planner: does it slice, is every object manifold and on
the bed, how long does it print and how much filament does it take.

Runs the command-line ``prusa-slicer`` (Debian package ``prusa-slicer``) when installed:
``--export-gcode --dont-arrange`` with the printer's bed and print settings
(:meth:`.printers.Printer.slicer_args`) must exit 0 and write G-code, and ``--info`` must report
``manifold = yes`` for every object.  The G-code's own comments give the print time (normal mode)
and the filament (mm, cm³, g): :func:`gcode_stats`; its moves that extrude, where the nozzle lays
filament (skirt and brim too, not only the objects): :func:`extrusion_extents`.
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

    #: where the G-code extrudes (:func:`extrusion_extents`), None when not sliced
    extrusion: dict | None = None

    def extrusions_off_bed(self, bed_x: float, bed_y: float, tol: float = 1e-3) -> list[str]:
        """Where the G-code lays filament off the bed (the lines' half widths counted): a sentence each."""
        e = self.extrusion
        if not e or not e["moves"]:
            return ["no extrusion found"]
        out = [f"{e['unplaced']} extruding move(s) before any X/Y"] if e["unplaced"] else []
        for a, hi in (("x", bed_x), ("y", bed_y)):
            if e[f"min_{a}"] < -tol:
                out.append(f"{a} = {e[f'min_{a}']:.2f} mm < 0 (line {e[f'min_{a}_line']})")
            if e[f"max_{a}"] > hi + tol:
                out.append(f"{a} = {e[f'max_{a}']:.2f} mm > {hi:g} (line {e[f'max_{a}_line']})")
        return out

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


_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)"
_WORD = re.compile(rf"([A-Z])\s*({_NUM})")
#: the move PrusaSlicer writes on almost every line (``G1 X.. Y..``, an ``E`` and an ``F`` after them or not), read
#: at once: the words the general reading of the line finds, in the same strings (anything else, a comment, a
#: lower-case letter, a space more, goes the general way)
_XY_MOVE = re.compile(rf"G1 X({_NUM}) Y({_NUM})(?: E({_NUM}))?(?: F{_NUM})?\n?")


def extrusion_extents(lines) -> dict:
    """Where a G-code lays filament: the least and greatest x and y reached by a G0/G1 move that extrudes
    (E above the last E in absolute mode M82, E > 0 in relative mode M83; G92 resets E), each end of the
    move widened by half its line width (PrusaSlicer's ``;WIDTH:`` comments), with the G-code line of each
    extreme; `moves`: the number of such moves, `unplaced`: those before any X and Y was known.

    Every line is read by its words (a letter and a number, after the code; a comment after ``;`` left out, the
    letters taken in upper case, the last of a letter counting); the line PrusaSlicer writes for nearly every move,
    ``G1 X.. Y.. E..``, is matched whole first (:data:`_XY_MOVE`: the same words, one match instead of a split and
    a search; the seed-002 kit's plate 2, 483 000 lines: 2.3 -> 0.75 CPU s, ``bench/bench_gcode_read.py``)."""
    x = y = None
    e_abs, e_last, width = True, 0.0, 0.0
    moves = unplaced = 0
    inf = float("inf")
    lo_x = lo_y = inf
    hi_x = hi_y = -inf
    lo_x_n = lo_y_n = hi_x_n = hi_y_n = 0
    fast = _XY_MOVE.fullmatch
    for n, raw in enumerate(lines, 1):
        m = fast(raw)
        if m is not None:
            x0, y0 = x, y
            x, y = float(m[1]), float(m[2])
            es = m[3]
            if es is None:
                continue
            e = float(es)
        else:
            line = raw.split(";", 1)[0].strip().upper()
            if not line:
                if raw.startswith(";WIDTH:"):
                    try:
                        width = float(raw[7:])
                    except ValueError:
                        pass
                continue
            words = dict(_WORD.findall(line))
            code = line.split(None, 1)[0]
            if code == "M82":
                e_abs = True
                continue
            if code == "M83":
                e_abs = False
                continue
            if code == "G92":
                if "E" in words:
                    e_last = float(words["E"])
                continue
            if code not in ("G0", "G1", "G00", "G01"):
                continue
            x0, y0 = x, y
            x = float(words["X"]) if "X" in words else x
            y = float(words["Y"]) if "Y" in words else y
            if "E" not in words:
                continue
            e = float(words["E"])
        extrudes = e > e_last + 1e-9 if e_abs else e > 1e-9
        if e_abs:
            e_last = e
        if not extrudes:
            continue
        moves += 1
        if x is None or y is None:
            unplaced += 1
            continue
        h = 0.5 * width
        # the move's start (where the last move ended), then its end; a tie keeps the first line.  The four
        # comparisons are written out for each point: a loop over the two points costs this loop 20-50 % more
        if x0 is not None and y0 is not None:
            if x0 - h < lo_x:
                lo_x, lo_x_n = x0 - h, n
            if x0 + h > hi_x:
                hi_x, hi_x_n = x0 + h, n
            if y0 - h < lo_y:
                lo_y, lo_y_n = y0 - h, n
            if y0 + h > hi_y:
                hi_y, hi_y_n = y0 + h, n
        if x - h < lo_x:
            lo_x, lo_x_n = x - h, n
        if x + h > hi_x:
            hi_x, hi_x_n = x + h, n
        if y - h < lo_y:
            lo_y, lo_y_n = y - h, n
        if y + h > hi_y:
            hi_y, hi_y_n = y + h, n
    ext = {"moves": moves, "unplaced": unplaced}
    for key, v, k in (("min_x", lo_x, lo_x_n), ("max_x", hi_x, hi_x_n), ("min_y", lo_y, lo_y_n),
                      ("max_y", hi_y, hi_y_n)):
        if k:  # reached by a move (a line number counts from 1)
            ext[key], ext[f"{key}_line"] = v, k
    return ext


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
    stats, extrusion = {}, None
    if ok:
        with open(gcode, "rb") as fh:  # the comments are at the end
            fh.seek(max(0, gcode.stat().st_size - 64 * 1024))
            stats = gcode_stats(fh.read().decode("utf-8", "replace"))
        with open(gcode, encoding="utf-8", errors="replace") as fh:
            extrusion = extrusion_extents(fh)
    return SliceResult(ok, msg, gcode.stat().st_size if gcode.is_file() else 0, info(path), stats, extrusion)


def slice_kit(folder: Path, printer, work: Path, fullest_only: bool = False) -> list[tuple[str, SliceResult, list[str]]]:
    """Slice the plates of a kit folder with the printer's bed (every plate, or the one holding the most
    pieces by the kit's ``tables/plates.csv``): [(plate file name, result, objects and extrusions off the bed)]."""
    folder, work = Path(folder), Path(work)
    plates = sorted(folder.glob("plate_*.3mf"))
    if fullest_only:
        rows = [r.split(",") for r in (folder / "tables" / "plates.csv").read_text().splitlines()[1:]]
        plates = [folder / f"plate_{max(rows, key=lambda r: int(r[1]))[0]}.3mf"]
    out = []
    for plate in plates:
        r = slice_plate(plate, printer.bed_shape(), work / f"{plate.stem}.gcode", args=printer.slicer_args())
        off = r.off_bed(printer.bed_x_mm, printer.bed_y_mm)
        out.append((plate.name, r, off + (r.extrusions_off_bed(printer.bed_x_mm, printer.bed_y_mm) if r.ok else [])))
    return out
