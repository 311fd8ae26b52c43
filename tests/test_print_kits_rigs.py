"""Print kits of the cam mover, the balancer and the road wheel (`propulsor print`): each rig proved on
its printed geometry, every piece one closed body, every plate judged by PrusaSlicer."""

from __future__ import annotations

import json
import math
import re
import shutil
from pathlib import Path

import pytest

from propulsor.cli import main

ROOT = Path(__file__).resolve().parents[1]
NAMES = ["cam_mover", "balancer", "road_wheel"]
needs_slicer = pytest.mark.skipif(shutil.which("prusa-slicer") is None,
                                  reason="PrusaSlicer is not installed (apt-get install prusa-slicer)")


#: the fits each kit measures on its printed pieces, as the kit's build measured them (fit_mutations.py)
RECORDED: dict[str, dict] = {}


@pytest.fixture(scope="module")
def kits(tmp_path_factory):
    from fit_mutations import recording

    out = {}
    for name in NAMES:
        folder = tmp_path_factory.mktemp("kits") / f"{name}_kit"
        with recording(RECORDED.setdefault(name, {})):
            rc = main(["print", str(ROOT / "parts" / f"{name}.toml"), "--out", str(folder), "-q", "--slice", "no"])
        out[name] = (rc, folder, json.loads((folder / "manifest.json").read_text()) if rc == 0 else None)
    return out


FITS = {"cam_mover": ["roller_on_pin", "carrier_on_axle", "spacer_on_axle", "axle_in_cam", "handle_in_carrier"],
        "balancer": ["arm_on_boss", "wheel_1_on_spindle", "wheel_2_on_spindle", "wheel_3_on_spindle",
                     "wheel_4_on_spindle"],
        "road_wheel": ["wheel_1_on_axle", "wheel_2_on_axle", "wheel_3_on_axle", "wheel_4_on_axle", "axle_in_stand"]}


@pytest.mark.parametrize("name, fit", [(n, f) for n, fits in FITS.items() for f in fits])
def test_each_fit_check_fails_under_its_mutation(kits, name, fit):
    """The fit passes on the kit's printed pieces and fails with its pin grown by the running clearance
    (running fits), or shrunk to no interference and grown past what a printed wall takes (press fits)."""
    from fit_mutations import assert_fails_under_mutation

    assert sorted(RECORDED[name]) == sorted(FITS[name])  # every fit the kit measures is listed here
    assert_fails_under_mutation(RECORDED[name], fit)


def _checks(m: dict) -> dict:
    return {c["name"]: c for c in m["checks"]}


@pytest.mark.parametrize("name", NAMES)
def test_rig_builds_every_piece_closed_every_check_passes(kits, name):
    rc, folder, m = kits[name]
    assert rc == 0
    checks = _checks(m)
    assert all(c["passed"] for c in checks.values()), [c["name"] for c in checks.values() if not c["passed"]]
    files = {e["path"] for e in m["files"]}
    pieces = sorted(Path(f).stem for f in files if f.startswith("pieces/") and f.endswith(".stl"))
    assert len(pieces) >= 4
    for piece in pieces:
        for what in ("edges not shared by exactly 2 faces", "bodies", "genus", "self-intersecting triangle pairs"):
            assert checks[f"{piece}: {what}"]["passed"], (piece, what)
    plates = sorted(f for f in files if re.fullmatch(r"plate_\d+\.3mf", f))
    assert len(plates) == m["derived"]["plates"] and all(checks[f"plate_{k}.on_bed"]["passed"]
                                                         for k in range(1, len(plates) + 1))
    assert "plots/assembled.png" in files and "print_report.md" in files


def test_cam_mover_kit_runs_in_its_channel_with_the_running_clearance(kits):
    _, _, m = kits["cam_mover"]
    d, c = m["derived"], _checks(m)
    assert d["scale_S"] == 2.0  # the 406 mm cam on the 220 mm bed
    assert math.isclose(d["print_hub_height_mm"], (90 + 20 + 210) / 2)
    # the roller prints smaller by clearance + half the channel's undersize + the drawing margin
    assert math.isclose(d["print_roller_radius_mm"], 20 / 2 - 0.25 - 0.075 - 0.01)
    for key in ("roller_working", "roller_outer", "leg_carrier", "shoe_carrier", "neighbours", "opposite"):
        assert c[f"motion.{key}.overlap_area"]["value"] <= 1e-6
        assert c[f"motion.{key}.least_clearance"]["value"] >= 0.25
    # the working wall: exactly the drawn clearance (the roller centre runs on the design path)
    assert c["motion.roller_working.least_clearance"]["value"] == pytest.approx(0.26, abs=2e-3)
    # the outer wall adds the part's own channel clearance at 1:2
    assert c["motion.roller_outer.least_clearance"]["value"] == pytest.approx(0.26 + 0.2 / 2, abs=2e-3)


def test_balancer_kit_swings_from_post_to_post(kits):
    _, _, m = kits["balancer"]
    d, c = m["derived"], _checks(m)
    assert d["scale_S"] == 4.0  # the 630 mm wheel decides: 210 mm at 1:3 leaves no room for the slicer's skirt
    assert d["print_travel_deg"] == pytest.approx([18.796, 114.839], abs=1e-3)
    # the posts stop the arm at both ends of the travel and nowhere inside it
    assert c["motion.arm_vs_posts.overlap_area"]["value"] <= 1e-6
    assert d["print_arm_post_clearance_min_mm"] == pytest.approx(0.26, abs=1e-3)
    assert d["print_arm_post_clearance_ends_mm"] == pytest.approx([0.26, 0.26], abs=1e-3)
    assert d["print_arm_post_clearance_inside_min_mm"] > 0.26
    assert math.isclose(d["print_R_b_mm"], 90.0)


def test_road_wheel_kit_slabs_restack_to_the_wheel(kits):
    from propulsor.export.mesh import load_mesh
    from propulsor.solids.kernel import manifold

    _, folder, m = kits["road_wheel"]
    d = m["derived"]
    # 1:4: the 630 mm wheel at 1:3 (210 mm) does not fit the 220 mm bed less the 8 mm margins of the slicer's skirt
    assert d["scale_S"] == 4.0 and d["wheel_slabs"] == 4  # two rows: cut at both webs and between the rows
    assert d["print_tyre_radius_mm"] == pytest.approx(630.0 / 2 / 4)
    assert d["print_wheel_length_mm"] == pytest.approx(265.0 / 4)
    # every slab stands on a half web: the bed-side layer is a full annulus from the hub to the tyre
    heights = []
    for k in range(1, 5):
        mesh = load_mesh(folder / "pieces" / f"wheel_{k}.stl")
        lo, hi = mesh.bounds
        heights.append(hi[2] - lo[2])
        layer = manifold(mesh, f"wheel_{k}").slice(float(lo[2]) + 0.5)  # above the 0.4 mm chamfer
        assert len(layer.decompose()) == 1  # one region: the half web joins hub and ring on the first layers
        x0, y0, x1, y1 = layer.bounds()
        assert (x1 - x0) / 2 == pytest.approx(78.75, abs=0.05) and (y1 - y0) / 2 == pytest.approx(78.75, abs=0.05)
        # the bore and the six lightening holes go through that layer
        assert len(layer.to_polygons()) == 1 + 1 + 6
    assert sum(heights) == pytest.approx(265.0 / 4, abs=1e-6)


@pytest.mark.slicer
@needs_slicer
@pytest.mark.parametrize("name", NAMES)
def test_the_fullest_plate_slices(kits, name, slices_cleanly):
    slices_cleanly(kits[name][1], fullest_only=True)


@pytest.mark.sweep
@pytest.mark.slicer
@needs_slicer
@pytest.mark.parametrize("name", NAMES)
def test_every_plate_slices(kits, name, slices_cleanly):
    slices_cleanly(kits[name][1])
