"""Plates a slicer takes as they are: each plate's pieces centred on the bed with room for the slicer's skirt,
and the kit's print settings inside the plate file (``Metadata/Slic3r_PE.config``).

The judge is PrusaSlicer itself: every plate of a kit is sliced with PrusaSlicer's own default skirt (read from
the installed ``prusa-slicer --help-fff``) on its profile's bed, and every move of the G-code that extrudes — the
skirt as well as the pieces — must lie on the bed, half its line width included.
"""

from __future__ import annotations

import functools
import re
import random
import shutil
import subprocess
import zipfile
from pathlib import Path

import pytest
import trimesh

from propulsor.cli import main
from propulsor.export.mesh import SLICER_CONFIG_ENTRY, write_3mf_objects
from propulsor.printing.layout import lay_flat, pack, placed
from propulsor.printing.printers import load_printer
from propulsor.printing.slicer import extrusion_extents

ROOT = Path(__file__).resolve().parents[1]
needs_slicer = pytest.mark.skipif(shutil.which("prusa-slicer") is None,
                                  reason="PrusaSlicer is not installed (apt-get install prusa-slicer)")


# --- the G-code reader -------------------------------------------------------------------------------------------

def test_extrusion_extents_follow_absolute_and_relative_e_and_line_widths():
    gcode = """G90
M82
G92 E0
G1 X-5 Y-5 F9000 ; travel off the bed: not an extrusion
G1 X10 Y10
G1 E-1 ; retract
G1 E0 ; unretract: filament pushed back out where the nozzle stands (10, 10)
;WIDTH:0.6
G1 X20 Y10 E1.5
G1 X20 Y30 E2.5
G92 E0
G1 X50 Y30 E0 ; E equal to the reset: travel
M83
;WIDTH:0.4
G1 X50 Y40 E0.5
G1 X90 Y90 E-0.5 ; relative retract while moving: not laid
""".splitlines(keepends=True)
    e = extrusion_extents(gcode)
    assert e["moves"] == 4 and e["unplaced"] == 0
    assert (e["min_x"], e["max_x"]) == pytest.approx((10 - 0.3, 50 + 0.2))
    assert (e["min_y"], e["max_y"]) == pytest.approx((10 - 0.3, 40 + 0.2))
    assert e["max_y_line"] == 15 and e["min_x_line"] == 9
    assert extrusion_extents(["M83\n", "G1 E5\n"]) == {"moves": 1, "unplaced": 1}
    # each extreme at the start of a move after a travel (the line of the move that lays it)
    moves = ["G1 X0 Y100\n", ";WIDTH:0.4\n", "G1 X50 Y20 E1\n", "G1 X200 Y-50 F7800\n", "G1 X60 Y30 E2\n"]
    h = 0.2
    assert extrusion_extents(moves) == {"moves": 2, "unplaced": 0, "min_x": 0 - h, "min_x_line": 3,
                                        "max_x": 200 + h, "max_x_line": 5, "min_y": -50 - h, "min_y_line": 5,
                                        "max_y": 100 + h, "max_y_line": 3}


def _printer_like_gcode(rng: random.Random, n: int) -> list[str]:
    """Lines as PrusaSlicer writes them: moves ``G1 X.. Y..`` with an E or an F or neither, retracts, resets,
    width comments, mode changes, travels off the bed."""
    num = lambda: rng.choice(["%.3f" % rng.uniform(-20, 220), "%d" % rng.randint(-5, 250), ".%d" % rng.randint(1, 9),
                              "-.%d" % rng.randint(1, 9)])
    e = 0.0
    out = []
    for _ in range(n):
        k = rng.random()
        if k < 0.6:
            e += rng.choice([0.0, 0.02, 0.5, -0.3])
            tail = rng.choice([f" E{e:.5f}", f" E{e:.5f} F1800", " F7800", "", " E-.8"])
            out.append(f"G1 X{num()} Y{num()}{tail}\n")
        elif k < 0.7:
            out.append(rng.choice(["G1 E-.8 F2100\n", "G1 E.8 F2100\n", "G1 Z.4 F720\n", "G1 X5 E1\n", "G0 Y3 E2\n"]))
        elif k < 0.8:
            out.append(f";WIDTH:{rng.choice(['0.45', '0.6', '.42'])}\n")
        elif k < 0.9:
            out.append(rng.choice(["G92 E0\n", "G92 E5.5\n", "M82\n", "M83\n", ";TYPE:Skirt/Brim\n", "M106 S255\n"]))
        else:
            out.append(rng.choice(["G1 X-5 Y-5\n", f"G1 X{num()} Y{num()} E{e + 1:.4f}\n", "G1 F9000\n"]))
    return out


def test_the_printer_s_own_move_lines_read_as_any_line_with_the_same_words():
    """The line PrusaSlicer writes for nearly every move (``G1 X.. Y.. E..``) is matched whole; with a comment after
    it (or its letters in lower case) the same line takes the reading of every other line: the same extents, moves
    and lines, over runs of printer-like G-code."""
    rng = random.Random(8)
    for trial in range(300):
        lines = _printer_like_gcode(rng, rng.randint(1, 80))
        want = extrusion_extents(lines)
        commented = [ln if ln.startswith(";") else ln.rstrip("\n") + " ; as written\n" for ln in lines]
        lower = [ln.lower() if ln.startswith("G1 ") else ln for ln in lines]
        assert extrusion_extents(commented) == want, lines
        assert extrusion_extents(lower) == want, lines
    assert want["moves"] > 0


# --- layout and plate file ----------------------------------------------------------------------------------------

def test_a_plate_is_centred_with_the_skirt_s_margin_and_carries_the_kit_s_settings(tmp_path):
    p = load_printer("prusa_mini")
    assert p.margin_mm >= 6.0 + 0.7 and p.skirt() == (1, 6.0)
    flat = {"block": lay_flat(trimesh.creation.box(extents=(40.0, 20.0, 5.0)))[0],
            "plate": lay_flat(trimesh.creation.box(extents=(30.0, 30.0, 4.0)))[0]}
    plates = pack({n: tuple((m.bounds[1] - m.bounds[0])[:2]) for n, m in flat.items()}, p.bed_x_mm, p.bed_y_mm,
                  p.piece_gap_mm, p.margin_mm)
    assert len(plates) == 1
    objects = [(pl.name, placed(flat[pl.name], pl)) for pl in plates[0].placements]
    lo = min(m.bounds[0][0] for _, m in objects), min(m.bounds[0][1] for _, m in objects)
    hi = max(m.bounds[1][0] for _, m in objects), max(m.bounds[1][1] for _, m in objects)
    # 40 + 5 + 30 mm wide, 30 mm deep: centred on the 180 mm bed
    assert lo == pytest.approx((52.5, 75.0)) and hi == pytest.approx((127.5, 105.0))
    a = write_3mf_objects(objects, tmp_path / "a.3mf", p.slicer_config())
    b = write_3mf_objects(objects, tmp_path / "b.3mf", p.slicer_config())
    assert a.read_bytes() == b.read_bytes()  # deterministic, settings and all
    with zipfile.ZipFile(a) as z:
        assert all(i.date_time == (1980, 1, 1, 0, 0, 0) for i in z.infolist())
        text = z.read(SLICER_CONFIG_ENTRY).decode()
    got = dict(re.findall(r"^; (\w+) = (.*)$", text, re.M))
    assert got == p.slicer_config()
    assert got["bed_shape"] == "0x0,180x0,180x180,0x180" and got["perimeters"] == "3" and got["fill_density"] == "15%"
    assert got["skirts"] == "1" and got["skirt_distance"] == "6" and got["brim_width"] == "0"


def test_a_margin_too_small_for_the_default_skirt_brings_it_in_or_drops_it():
    assert load_printer("generic", {"margin_mm": 5.0}).skirt() == (1, 3.0)
    assert load_printer("generic", {"margin_mm": 2.0}).skirt() == (0, 0.0)
    assert "--no-support-material" in load_printer("generic").slicer_args()


# --- every plate of a kit, sliced by PrusaSlicer with its default skirt --------------------------------------------

@functools.cache
def _slicer_help() -> str:
    return subprocess.run(["prusa-slicer", "--help-fff"], capture_output=True, text=True, timeout=120,
                          env={"PATH": "/usr/bin:/bin", "HOME": "/tmp", "LC_ALL": "C"}).stdout


def _slicer_default(option: str) -> str:
    """The installed PrusaSlicer's default of a command-line option (its --help-fff)."""
    text = _slicer_help()
    m = re.search(rf"^ --{option} N\s.*?default: ([^)]+)\)", text, re.M | re.S)
    assert m, f"prusa-slicer --help-fff names no default of --{option}"
    return m.group(1).strip()


def slice_with_default_skirt(plate: Path, printer, gcode: Path) -> dict:
    """Slice a plate as a maker's PrusaSlicer takes it (its settings from the plate file, the printer's bed) with
    PrusaSlicer's default skirt and brim; the G-code's extrusion extents and the settings it was sliced with."""
    skirt = {o: _slicer_default(o) for o in ("skirts", "skirt-distance", "brim-width")}
    assert skirt == {"skirts": "1", "skirt-distance": "6", "brim-width": "0"}
    args = ["prusa-slicer", "--export-gcode", "--dont-arrange", "--bed-shape", printer.bed_shape()]
    for option, value in skirt.items():
        args += [f"--{option}", value]
    r = subprocess.run(args + ["--output", str(gcode), str(plate)], capture_output=True, text=True, timeout=600,
                       env={"PATH": "/usr/bin:/bin", "HOME": "/tmp", "LC_ALL": "C"})
    assert r.returncode == 0 and gcode.is_file(), (plate.name, r.stderr[-500:])
    text = gcode.read_text(encoding="utf-8", errors="replace")
    settings = dict(re.findall(r"^; (\w+) = (.*)$", text[-200_000:], re.M))
    return {"extrusion": extrusion_extents(text.splitlines(keepends=True)), "settings": settings}


def assert_kit_slices_on_its_bed(tmp_path: Path, part: str, printer_name: str) -> list[str]:
    """Build the kit of `part` on the profile, slice every plate with the default skirt; every extrusion on the
    bed, and the G-code sliced with the kit's settings.  One line a plate: its extrusion extents against the bed."""
    folder = tmp_path / f"{part}_{printer_name}"
    assert main(["print", str(ROOT / "parts" / f"{part}.toml"), "--printer", printer_name, "--out", str(folder),
                 "-q", "--slice", "no"]) == 0
    p = load_printer(printer_name)
    plates = sorted(folder.glob("plate_*.3mf"), key=lambda f: int(f.stem.split("_")[1]))
    assert plates
    want = p.slicer_config()
    lines, bad = [], []
    for plate in plates:
        got = slice_with_default_skirt(plate, p, tmp_path / f"{part}_{plate.stem}.gcode")
        e = got["extrusion"]
        assert e["moves"] > 100 and e["unplaced"] == 0, (plate.name, e)
        line = (f"{part} on {printer_name} {plate.stem}: x {e['min_x']:.2f} … {e['max_x']:.2f}, "
                f"y {e['min_y']:.2f} … {e['max_y']:.2f} mm on {p.bed_x_mm:g} × {p.bed_y_mm:g}")
        lines.append(line)
        if e["min_x"] < 0 or e["min_y"] < 0 or e["max_x"] > p.bed_x_mm or e["max_y"] > p.bed_y_mm:
            bad.append(line)
        # the plate's own settings reached the slicer (nothing but the bed and skirt was given)
        for key in ("perimeters", "fill_density", "layer_height", "top_solid_layers", "bottom_solid_layers",
                    "temperature", "bed_temperature", "filament_type", "support_material"):
            assert got["settings"].get(key) == want[key], (plate.name, key, got["settings"].get(key), want[key])
    print("\n" + "\n".join(lines))
    assert bad == []
    return lines


#: kits of part files that build in well under a minute, on the smallest beds (180 mm) and a wide one
FAST = [("road_wheel", "prusa_mini"), ("cam_linear", "prusa_mini"), ("road_wheel", "prusa_mk4")]


@pytest.mark.slicer
@needs_slicer
@pytest.mark.parametrize("part, printer_name", FAST)
def test_every_plate_of_a_kit_slices_with_the_default_skirt_on_its_bed(tmp_path, part, printer_name):
    assert_kit_slices_on_its_bed(tmp_path, part, printer_name)


PART_FILES = sorted(f.stem for f in (ROOT / "parts").glob("*.toml"))


@pytest.mark.sweep
@pytest.mark.slicer
@needs_slicer
@pytest.mark.parametrize("part", PART_FILES)
def test_every_part_file_s_plates_slice_with_the_default_skirt_on_a_180_mm_bed(tmp_path, part):
    assert_kit_slices_on_its_bed(tmp_path, part, "prusa_mini")
