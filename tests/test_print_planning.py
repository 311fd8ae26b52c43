"""Print planning (printing/planning.py, slicer.py): the kit's print time and filament are PrusaSlicer's
for the stated settings; without a slicer the filament is estimated at the stated infill."""

from __future__ import annotations

import csv
import re
import shutil
import subprocess

import pytest
import trimesh

from propulsor.printing.planning import estimate_g, hours
from propulsor.printing.printers import load_printer
from propulsor.printing.slicer import duration_s, gcode_stats

needs_slicer = pytest.mark.skipif(shutil.which("prusa-slicer") is None,
                                  reason="PrusaSlicer is not installed (apt-get install prusa-slicer)")

TAIL = """; filament used [mm] = 7028.44
; filament used [cm3] = 16.91
; filament used [g] = 20.96
; total filament used [g] = 20.96
; total filament cost = 0.00
; estimated printing time (normal mode) = 1d 2h 17m 3s
"""


def test_gcode_comments_are_read():
    s = gcode_stats(TAIL)
    assert s == {"time_s": 86400 + 2 * 3600 + 17 * 60 + 3, "filament_mm": 7028.44, "filament_cm3": 16.91,
                 "filament_g": 20.96}
    assert duration_s("45m 0s") == 2700 and duration_s("12s") == 12
    assert gcode_stats("; nothing here\n") == {}
    assert hours(8220) == "2 h 17 min" and hours(2700) == "45 min"


def test_the_estimate_is_at_the_stated_infill_not_solid():
    p = load_printer("generic")  # 15 % infill, 3 perimeters of 0.4 mm
    cube = trimesh.creation.box(extents=(40.0, 40.0, 40.0))
    solid_g = 64.0 * p.density_g_cm3
    g = estimate_g([cube], p)
    # the shell a slicer lays (cm³): 5 top and 4 bottom layers of 0.2 mm over the 40 x 40 faces, and between them
    # (38.2 mm) the ring of 3 perimeters of 0.45 mm inside the 40 mm square (PrusaSlicer's width for a 0.4 mm nozzle)
    shell = (1600.0 * 1.0 + 1600.0 * 0.8 + (40.0 ** 2 - 37.3 ** 2) * 38.2) / 1000.0
    assert g == pytest.approx((shell + 0.15 * (64.0 - shell)) * p.density_g_cm3, rel=0.02)  # the corners: 3 % of the ring
    # a plate 4 mm thick: top and bottom layers are most of it, the walls a thin band
    plate = trimesh.creation.box(extents=(60.0, 60.0, 4.0))
    shell = (3600.0 * 1.0 + 3600.0 * 0.8 + (60.0 ** 2 - 57.3 ** 2) * 2.2) / 1000.0
    assert estimate_g([plate], p) == pytest.approx((shell + 0.15 * (14.4 - shell)) * p.density_g_cm3, rel=0.02)
    assert 0.2 * solid_g < g < 0.5 * solid_g
    full = load_printer("generic", {"infill_percent": 100.0})
    assert estimate_g([cube], full) == pytest.approx(solid_g)
    # a thin pin is all wall: solid whatever the infill
    pin = trimesh.creation.cylinder(radius=1.0, height=20.0, sections=64)
    assert estimate_g([pin], p) == pytest.approx(float(pin.volume) / 1000.0 * p.density_g_cm3)


def _tiny_kit(printer):
    from propulsor.printing.kit import Kit, Piece
    from propulsor.printing.scale import ScaleChoice
    from propulsor.solids.kernel import cylinder

    pieces = [Piece("puck", cylinder(8.0, 0.0, 3.0), genus=0), Piece("peg", cylinder(4.0, 0.0, 6.0), genus=0)]
    return Kit(part="road_wheel", printer=printer, scale=ScaleChoice(1.0, "test"), pieces=pieces)


@pytest.mark.slicer
@needs_slicer
def test_report_time_and_filament_are_prusaslicer_s_for_the_same_settings(tmp_path):
    from propulsor.params import load_params
    from propulsor.parts.road_wheel.params import RoadWheelParams
    from propulsor.parts.writer import OutputWriter
    from propulsor.printing.kit import write_kit

    printer = load_printer("prusa_mini", {"infill_percent": 25.0, "perimeters": 4})
    out = tmp_path / "kit"
    out.mkdir()
    w = OutputWriter(out, "road_wheel", load_params(RoadWheelParams, {}))
    w.report_name = "print_report.md"
    try:
        write_kit(_tiny_kit(printer), w, sliced=True)
        assert w.finish() == []
    finally:
        w.close()
    rows = list(csv.DictReader((out / "tables" / "plates.csv").open()))
    assert len(rows) == 2 and rows[0]["names"] == "coupon, coupon_pin, coupon_key"  # the coupon prints first
    # the same plate sliced here with the settings written out by hand
    gcode = tmp_path / "same.gcode"
    r = subprocess.run(["prusa-slicer", "--export-gcode", "--dont-arrange", "--bed-shape", "0x0,180x0,180x180,0x180",
                        "--nozzle-diameter", "0.4", "--layer-height", "0.2", "--perimeters", "4", "--fill-density",
                        "25%", "--top-solid-layers", "5", "--bottom-solid-layers", "4", "--filament-diameter", "1.75",
                        "--filament-density", "1.24", "--temperature", "210", "--bed-temperature", "60",
                        "--max-print-height", "180", "--first-layer-temperature", "215",
                        "--first-layer-bed-temperature", "60", "--filament-type", "PLA",
                        "--output", str(gcode), str(out / "plate_2.3mf")],
                       capture_output=True, text=True, env={"PATH": "/usr/bin:/bin", "HOME": "/tmp", "LC_ALL": "C"})
    assert r.returncode == 0, r.stderr[-500:]
    text = gcode.read_text()
    t = re.search(r"^; estimated printing time \(normal mode\) = (.+)$", text, re.M).group(1)
    g = float(re.search(r"^; total filament used \[g\] = ([0-9.]+)", text, re.M).group(1))
    assert int(rows[1]["sliced_time_s"]) == duration_s(t) and float(rows[1]["sliced_filament_g"]) == g
    report = (out / "print_report.md").read_text()
    assert f"| plate 2 | 2 | {hours(duration_s(t))} | {g:.0f} g |" in report
    assert "25 % infill" in report and "4 perimeters" in report


def test_the_kit_report_is_maker_first_and_the_full_size_inputs_are_an_appendix(tmp_path):
    """print_report.md opens with what to print (printer, settings, plates with time or filament), then the
    hardware and assembly; the part file's inputs (the full-size design's: a 40 mm bore, an M8 tap drill)
    come last, labelled as such."""
    from propulsor.params import load_params
    from propulsor.parts.road_wheel.params import RoadWheelParams
    from propulsor.parts.writer import OutputWriter
    from propulsor.printing.hardware import Hardware
    from propulsor.printing.kit import write_kit
    from propulsor.printing.scale import ScaleChoice

    kit = _tiny_kit(load_printer("prusa_mini"))
    kit.scale = ScaleChoice(2.0, "the puck is 360 mm; at 1:1.5 it does not fit")
    kit.steps = ["Put the peg <b>into</b> the puck.", "Turn it."]
    kit.hardware = [Hardware("⌀4 mm steel dowel pin, 6 mm long", 1, "peg")]
    out = tmp_path / "kit"
    out.mkdir()
    w = OutputWriter(out, "road_wheel", load_params(RoadWheelParams, {}))
    w.report_name = "print_report.md"
    try:
        write_kit(kit, w, sliced=False)
        assert w.finish() == []
    finally:
        w.close()
    text = (out / "print_report.md").read_text()
    heads = [line for line in text.splitlines() if line.startswith("## ")]
    assert heads[:3] == ["## What to print", "## Assembly", "## Summary"], heads
    assert [h for h in heads if h != "## References"][-1] == "## Appendix: the full-size design's inputs (the part file; the model prints at 1:2)"
    lead = text.split("## Summary")[0]
    assert "Prusa MINI+, 180 × 180 mm bed" in lead and "Scale 1:2: the puck is 360 mm" in lead
    assert "15 % infill" in lead and "| plate 2 | 2 | not sliced | about " in lead
    assert "1. Put the peg &lt;b&gt;into&lt;/b&gt; the puck." in lead and "2. Turn it." in lead
    assert "- 1 × ⌀4 mm steel dowel pin, 6 mm long (instead of the printed `peg`)" in lead
    # the full-size inputs are not where a maker starts reading
    first_input = min(text.index(f"| {f} |") for f in ("tyre_radius_mm", "tyre_width_mm"))
    assert first_input > text.index("## Appendix")
    assert "<h2>What to print</h2>" in (out / "print_report.html").read_text()
