"""Print-kit building blocks: printer profiles, the choice of scale, laying pieces flat, plates."""

from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh

from propulsor.errors import InputError
from propulsor.printing.layout import lay_flat, pack, placed
from propulsor.printing.printers import load_printer, printer_names
from propulsor.printing.scale import STANDARD_SCALES, check_printable, choose_scale, fits


def test_printer_profiles():
    assert {"generic", "prusa_mini", "prusa_mk4", "prusa_xl", "bambu_a1_mini", "bambu_a1", "bambu_p1", "bambu_x1",
            "creality_ender3", "voron_24_350"} <= set(printer_names())
    g = load_printer("generic")
    assert (g.bed_x_mm, g.bed_y_mm, g.bed_z_mm) == (220.0, 220.0, 250.0)
    assert g.min_feature_mm == pytest.approx(0.8) and g.backlash_mm == 0.3
    mk4 = load_printer("prusa_mk4", {"backlash_mm": 0.35})
    assert (mk4.bed_x_mm, mk4.bed_y_mm) == (250.0, 210.0) and mk4.backlash_mm == 0.35
    assert mk4.bed_shape() == "0x0,250x0,250x210,0x210"
    for name, overrides, fragment in [("ender", {}, "unknown printer"), ("generic", {"colour": 1}, "unknown printer setting"),
                                      ("generic", {"backlash_mm": 5.0}, "<= 2.0"), ("generic", {"name": "x"}, "profile's own")]:
        with pytest.raises(InputError, match=fragment):
            load_printer(name, overrides)


def test_auto_scale_is_the_largest_standard_scale_that_fits():
    bed = (220.0, 220.0, 250.0)
    # the final drive's ring: about 600 mm across, 80 mm thick
    pieces = {"ring": (600.0, 600.0, 80.0), "sun": (190.0, 190.0, 80.0)}
    c = choose_scale(pieces, bed)
    assert c.S == 3.0 and c.label == "1:3" and "ring" in c.reason and "1:2.5" in c.reason
    assert all(fits([v / c.S for v in e], bed) for e in pieces.values())
    assert not fits([v / 2.5 for v in pieces["ring"]], bed)
    assert choose_scale({"gear": (60.0, 55.0, 20.0)}, bed).S == 1.0
    # turned by 90 degrees fits
    assert fits((240.0, 200.0, 10.0), (210.0, 250.0, 100.0))
    with pytest.raises(InputError, match="does not fit"):
        choose_scale(pieces, bed, requested=2.0)
    with pytest.raises(InputError, match="larger printer"):
        choose_scale({"hull": (1e6, 1.0, 1.0)}, bed)
    assert STANDARD_SCALES[:7] == (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0)


def test_printable_limits():
    check_printable(3.0, 10.0, 1.0, {"tip land": 4.0})
    with pytest.raises(InputError, match="scaled module 0.5 mm"):
        check_printable(5.0, 2.5, 1.0)
    with pytest.raises(InputError, match="tip land is 0.4 mm"):
        check_printable(10.0, 10.0, 1.0, {"tip land": 4.0})


def test_lay_flat_puts_the_largest_face_down():
    box = trimesh.creation.box(extents=(10.0, 40.0, 100.0))  # largest faces: 40 x 100
    box.apply_transform(trimesh.transformations.rotation_matrix(0.3, [1, 1, 0]))
    flat, T = lay_flat(box)
    ext = flat.bounds[1] - flat.bounds[0]
    assert ext[2] == pytest.approx(10.0, abs=1e-9)
    assert flat.bounds[0] == pytest.approx([0, 0, 0], abs=1e-9)
    assert sorted(ext[:2]) == pytest.approx([40.0, 100.0], rel=1e-9)
    assert flat.volume == pytest.approx(box.volume)
    cyl = trimesh.creation.cylinder(radius=30.0, height=8.0, sections=64)  # a gear blank: flat
    flat, _ = lay_flat(cyl)
    assert (flat.bounds[1] - flat.bounds[0])[2] == pytest.approx(8.0)


def test_shelf_packing_keeps_pieces_apart_and_on_the_bed():
    rng = np.random.default_rng(1)
    feet = {f"p{k}": (float(w), float(d)) for k, (w, d) in enumerate(rng.uniform(10, 120, size=(25, 2)))}
    plates = pack(feet, 220.0, 220.0, 5.0)
    assert sum(len(p.placements) for p in plates) == 25 and len(plates) <= 6
    for plate in plates:
        rects = []
        for pl in plate.placements:
            w, d = feet[pl.name][::-1] if pl.turned else feet[pl.name]
            assert pl.x >= 5.0 - 1e-9 and pl.y >= 5.0 - 1e-9
            assert pl.x + w <= 215.0 + 1e-9 and pl.y + d <= 215.0 + 1e-9
            rects.append((pl.x, pl.y, pl.x + w, pl.y + d))
        # the plate's block of pieces centred on the bed: as much room left as right, in front as behind
        lo = np.min([r[:2] for r in rects], axis=0)
        hi = np.max([r[2:] for r in rects], axis=0)
        assert lo == pytest.approx(220.0 - hi, abs=1e-9)
        for i, a in enumerate(rects):
            for b in rects[i + 1:]:
                gap = max(b[0] - a[2], a[0] - b[2], b[1] - a[3], a[1] - b[3])
                assert gap >= 5.0 - 1e-9
    with pytest.raises(InputError, match="does not fit"):
        pack({"ring": (300.0, 300.0)}, 220.0, 220.0, 5.0)
    assert pack(feet, 220.0, 220.0, 5.0)[0].placements == plates[0].placements  # deterministic


def test_placed_turns_and_moves():
    flat, _ = lay_flat(trimesh.creation.box(extents=(30.0, 10.0, 5.0)))
    from propulsor.printing.layout import Placement

    m = placed(flat, Placement("b", 7.0, 9.0, True))
    ext = m.bounds[1] - m.bounds[0]
    assert m.bounds[0] == pytest.approx([7.0, 9.0, 0.0], abs=1e-9)
    assert sorted(ext[:2]) == pytest.approx([10.0, 30.0])
    assert math.isclose(ext[2], 5.0)


needs_slicer = pytest.mark.skipif(__import__("shutil").which("prusa-slicer") is None,
                                  reason="PrusaSlicer is not installed (apt-get install prusa-slicer)")


@pytest.mark.slicer
@needs_slicer
def test_a_packed_plate_slices_in_prusaslicer(tmp_path):
    """Two named objects laid flat and packed on one 3MF plate: PrusaSlicer slices it, reports every
    object manifold and on the bed."""
    from propulsor.export.mesh import write_3mf_objects
    from propulsor.printing.slicer import slice_plate

    printer = load_printer("prusa_mk4")
    pieces = {"block": trimesh.creation.box(extents=(20.0, 30.0, 10.0)),
              "disc": trimesh.creation.cylinder(radius=15.0, height=8.0, sections=48)}
    flat = {n: lay_flat(m)[0] for n, m in pieces.items()}
    plates = pack({n: tuple((m.bounds[1] - m.bounds[0])[:2]) for n, m in flat.items()}, printer.bed_x_mm,
                  printer.bed_y_mm, printer.piece_gap_mm)
    assert len(plates) == 1
    objs = [(p.name, placed(flat[p.name], p)) for p in plates[0].placements]
    path = write_3mf_objects(objs, tmp_path / "plate_1.3mf")
    r = slice_plate(path, printer.bed_shape(), tmp_path / "plate_1.gcode", printer.layer_mm, printer.nozzle_mm)
    assert r.ok and r.gcode_bytes > 1000, r.message
    assert len(r.objects) == 2 and r.all_manifold
    assert r.off_bed(printer.bed_x_mm, printer.bed_y_mm) == []
    # a plate moved off the bed is seen
    off = write_3mf_objects([("block", objs[0][1].copy().apply_translation([300.0, 0, 0]))], tmp_path / "off.3mf")
    r2 = slice_plate(off, printer.bed_shape(), tmp_path / "off.gcode")
    assert not r2.ok or r2.off_bed(printer.bed_x_mm, printer.bed_y_mm) == ["object 1"]


def test_the_clearance_coupon_fits_an_80_mm_bed_inside_its_margins():
    """The coupon's plate (bar, test pin, key; each laid on its largest face) packs on one 80 × 80 mm plate with
    policy.PLATE_MARGIN_MM to every edge, and keeps its five holes and slots at their pitch."""
    from propulsor import policy
    from propulsor.export.mesh import to_trimesh
    from propulsor.printing import coupon

    pr = load_printer("generic", bed="80x80x80")
    assert pr.margin_mm == policy.PLATE_MARGIN_MM
    flat = {pc.name: lay_flat(to_trimesh(pc.solid))[0] for pc in coupon.coupon_pieces(pr)}
    feet = {n: tuple((m.bounds[1] - m.bounds[0])[:2]) for n, m in flat.items()}
    bar = sorted(feet["coupon"])
    assert bar[1] == pytest.approx(coupon.bar_length(), abs=1e-3)
    assert coupon.bar_length() <= 80 - 2 * policy.PLATE_MARGIN_MM
    plates = pack(feet, pr.bed_x_mm, pr.bed_y_mm, pr.piece_gap_mm, pr.margin_mm)
    assert len(plates) == 1
    for pl in plates[0].placements:
        lo, hi = placed(flat[pl.name], pl).bounds
        assert lo[0] >= pr.margin_mm - 1e-6 and lo[1] >= pr.margin_mm - 1e-6
        assert hi[0] <= 80 - pr.margin_mm + 1e-6 and hi[1] <= 80 - pr.margin_mm + 1e-6
    # the bar keeps its five through holes (genus 5) and its five slots open at its edge
    assert flat["coupon"].euler_number == 2 - 2 * len(coupon.STEPS)
