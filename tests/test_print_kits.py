"""Print kits built as a user would (`propulsor print`), proved on the printed geometry, judged by
PrusaSlicer: the seed-002 non-circular pair and the final drive on the generic printer."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import pytest

from propulsor.cli import main
from propulsor.parts import kit_type_names

ROOT = Path(__file__).resolve().parents[1]
needs_slicer = pytest.mark.skipif(shutil.which("prusa-slicer") is None,
                                  reason="PrusaSlicer is not installed (apt-get install prusa-slicer)")


#: the fits each kit measures on its printed pieces, as the kit's build measured them (fit_mutations.py)
RECORDED: dict[str, dict] = {}


@pytest.fixture(scope="module")
def kits(tmp_path_factory):
    import propulsor.parts.noncircular_pair.kit as ncg
    from fit_mutations import recording

    real = ncg.pair_design

    def counted(p, source=None):
        DESIGNS.append(p.module_mm)
        return real(p, source)

    out = {}
    for name in ("ncg_seed002", "final_drive"):
        folder = tmp_path_factory.mktemp("kits") / f"{name}_kit"
        with recording(RECORDED.setdefault(name, {})), pytest.MonkeyPatch.context() as mp:
            mp.setattr(ncg, "pair_design", counted)
            rc = main(["print", str(ROOT / "parts" / f"{name}.toml"), "--out", str(folder), "-q", "--slice", "no",
                       *BEDS.get(name, [])])
        out[name] = (rc, folder)
    return out


#: the pair designs the seed-002 kit made (their modules)
DESIGNS: list[float] = []
#: the generic printer with a 230 mm bed for the seed-002 pair: its 1:1 driven wheel (204 ... 210 mm) fits the
#: 214 mm within the 8 mm margins the slicer's skirt needs, its padded pitch estimate (215.5 mm) does not.  (On
#: the generic 220 mm bed the wheel and its skirt do not fit at 1:1: the kit prints at 1:1.5 there.)
BEDS = {"ncg_seed002": ["--set", "bed_x_mm=230", "--set", "bed_y_mm=230"]}


def test_the_seed_002_kit_designs_its_printed_pair_once(kits):
    """On the generic printer with a 230 mm bed the seed-002 pair prints at 1:1 although its padded pitch
    estimate does not fit: the printed pair is searched and cut once at 1:1 and its own outlines decide; no
    full-size design is made only to learn the scale."""
    assert kits["ncg_seed002"][0] == 0
    assert _manifest(kits["ncg_seed002"][1])["derived"]["scale_S"] == 1.0
    assert DESIGNS == [2.5]


FITS = {"ncg_seed002": ["driver_on_pin", "driven_on_pin", "pin_driven_in_base", "pin_driver_in_base",
                        "washer_driver_on_pin", "cap_driver_on_pin", "washer_driven_on_pin", "cap_driven_on_pin",
                        "handle_in_driver"],
        "final_drive": ["planet_on_pin_1", "planet_on_pin_2", "planet_on_pin_3", "pins_on_carrier", "shaft_in_floor",
                        "shaft_in_carrier", "sun_on_shaft", "crank_on_shaft"]}


@pytest.mark.parametrize("name, fit", [(n, f) for n, fits in FITS.items() for f in fits])
def test_each_fit_check_fails_under_its_mutation(kits, name, fit):
    """The fit passes on the kit's printed pieces and fails with its pin grown by the running clearance
    (running fits), or shrunk to no interference and grown past what a printed wall takes (press fits)."""
    from fit_mutations import assert_fails_under_mutation

    assert sorted(RECORDED[name]) == sorted(FITS[name])  # every fit the kit measures is listed here
    assert_fails_under_mutation(RECORDED[name], fit)


def test_the_carrier_wall_is_measured_on_the_printed_carrier(kits):
    """The wall between the carrier's pins and its rim is read off the printed carrier: 6 mm as drawn
    (less the tessellated rim's sagitta); a pin moved outward, grown or the disc shrunk by just more than
    the wall beyond two line widths fails it, by just less still passes (the check is sharp)."""
    from fit_mutations import measure, rim_cases

    fit, meshes, printer, check = RECORDED["final_drive"]["pins_on_carrier"]
    assert check.passed and check.value == pytest.approx(6.0, abs=2e-3), check.message
    carrier = meshes["carrier"]
    slack = check.value - printer.min_feature_mm
    for delta, fails in ((slack + 0.02, True), (slack - 0.02, False)):
        for what, mutated in rim_cases(fit, carrier, delta, k=1):
            c = measure(fit, {"carrier": mutated}, printer)
            assert c.passed is not fails, (what, c.message)
            if fails:
                assert c.value == pytest.approx(printer.min_feature_mm - 0.02, abs=2e-3), (what, c.message)
                assert "least at pin 2" in c.message, c.message


def _manifest(folder: Path) -> dict:
    return json.loads((folder / "manifest.json").read_text())


@pytest.mark.parametrize("name", ["ncg_seed002", "final_drive"])
def test_kit_builds_and_proves_on_the_printed_geometry(kits, name):
    rc, folder = kits[name]
    assert rc == 0
    m = _manifest(folder)
    checks = {c["name"]: c for c in m["checks"]}
    assert all(c["passed"] for c in checks.values()), [c["name"] for c in checks.values() if not c["passed"]]
    assert checks["mesh.overlap_area"]["value"] <= 1e-6
    assert checks["mesh.print_backlash_min"]["value"] >= 0.3  # the default profile's backlash
    assert m["derived"]["print_module_mm"] >= 1.0
    files = {e["path"] for e in m["files"]}
    assert "print_report.md" in files and "plots/assembled.png" in files
    plates = sorted(f for f in files if re.fullmatch(r"plate_\d+\.3mf", f))
    assert plates and len(plates) == m["derived"]["plates"]
    for k in range(1, len(plates) + 1):
        assert checks[f"plate_{k}.on_bed"]["passed"]
    # every piece one closed, oriented body of the expected genus, without self-intersection
    pieces = sorted(Path(f).stem for f in files if f.startswith("pieces/") and f.endswith(".stl"))
    assert len(pieces) >= 5
    for piece in pieces:
        for what in ("edges not shared by exactly 2 faces", "directed edges used twice", "bodies", "genus",
                     "self-intersecting triangle pairs"):
            assert checks[f"{piece}: {what}"]["passed"], (piece, what)
    assert main(["check", str(folder)]) == 0


def test_the_seed_002_guide_says_which_material_survives_the_hand_on_the_crank(kits):
    """The kit rates its printed pair under a firm hand on its crank for every printed material: the manifest holds
    the torque (the hand force times the handle's radius) and each material's safeties, the guide says which
    material survives with the same numbers, the report's table lists them."""
    import csv

    from propulsor import policy

    rc, folder = kits["ncg_seed002"]
    m = _manifest(folder)
    v = m["derived"]
    assert v["hand_load_force_N"] == policy.KIT_HAND_FORCE_N
    assert v["hand_load_T1_Nm"] == pytest.approx(v["hand_load_force_N"] * v["hand_load_crank_radius_mm"] / 1000)
    checks = {c["name"]: c for c in m["checks"]}
    assert checks["hand_load.equilibrium"]["passed"], checks["hand_load.equilibrium"]["message"]
    names = ("PLA", "PETG", "nylon")
    assert v["hand_load_survivors"] == [n for n in names if v[f"hand_load_{n}_survives"]]
    guide = (folder / "print_guide.md").read_text().replace("\\", "")
    said = {n: (float(a), float(b)) for n, a, b in re.findall(r"(PLA|PETG|nylon) S_F ([\d.]+), S_H ([\d.]+)", guide)}
    assert set(said) == set(names)
    for n in names:
        assert said[n][0] == pytest.approx(v[f"hand_load_{n}_S_F_min"], abs=0.005)
        assert said[n][1] == pytest.approx(v[f"hand_load_{n}_S_H_min"], abs=0.005)
    assert f"T1 = {v['hand_load_T1_Nm']:.3f} N·m" in guide
    if len(v["hand_load_survivors"]) == 3:
        assert "PLA, PETG and nylon all survive it" in guide
    assert "static limits of flat-printed bars" in guide
    rows = list(csv.DictReader((folder / "tables" / "hand_load.csv").open()))
    assert [r["material"] for r in rows] == list(names)
    assert "hand_load_PLA_S_F_min" in m["glossary"]


def test_final_drive_scale_is_chosen_for_the_ring(kits):
    rc, folder = kits["final_drive"]
    m = _manifest(folder)
    assert m["derived"]["scale_S"] == 4.0
    report = (folder / "print_report.md").read_text()
    assert "Scale 1:4" in report and "ring is" in report and "at 1:3 it does not fit" in report


@pytest.mark.slicer
@needs_slicer
@pytest.mark.parametrize("name", ["ncg_seed002", "final_drive"])
def test_the_fullest_plate_slices(kits, name, slices_cleanly):
    slices_cleanly(kits[name][1], fullest_only=True)


@pytest.mark.sweep
@pytest.mark.slicer
@needs_slicer
@pytest.mark.parametrize("name", ["ncg_seed002", "final_drive"])
def test_every_plate_slices(kits, name, slices_cleanly):
    slices_cleanly(kits[name][1])


@pytest.mark.parametrize("args, fragment", [
    (["--printer", "ender3"], "unknown printer"),
    (["--scale", "1:1.5"], "does not fit"),
    (["--scale", "1:20"], "scaled module 0.5 mm is below"),
    (["--scale", "banana"], "must be auto"),
    (["--set", "backlash_mm=9"], "<= 2.0"),
    (["--set", "bed_x_mm=60", "--set", "bed_y_mm=60"], "too small for this kit: ring is"),
])
def test_bad_print_inputs_exit_2_one_line_nothing_written(tmp_path, capsys, args, fragment):
    out = tmp_path / "kit"
    rc = main(["print", str(ROOT / "parts" / "final_drive.toml"), "--out", str(out), "-q", *args])
    err = [line for line in capsys.readouterr().err.splitlines() if line.strip()]
    assert rc == 2 and len(err) == 1 and fragment in err[0], err
    assert list(tmp_path.iterdir()) == []


def test_makefile_knows_the_kit_types():
    make = (ROOT / "Makefile").read_text()
    kit_types = re.search(r"^KIT_TYPES\s*:=\s*(.*)$", make, re.M).group(1).split()
    assert sorted(kit_types) == kit_type_names()
