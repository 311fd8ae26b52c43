"""Printer profiles as a user gives them: a built-in name, the path of their own profile file, or a
bed alone (--bed); the refusals name the key, and the kit's report names the printer used."""

from __future__ import annotations

from pathlib import Path

import pytest

from propulsor.cli import main
from propulsor.errors import InputError
from propulsor.printing.printers import load_printer, parse_bed, printer_names

ROOT = Path(__file__).resolve().parents[1]
#: the built-in beds (x, y, z) of the printers makers name most
BEDS = {"prusa_mini": (180, 180, 180), "prusa_mk4": (250, 210, 220), "prusa_xl": (360, 360, 360),
        "bambu_a1_mini": (180, 180, 180), "bambu_a1": (256, 256, 256), "bambu_p1": (256, 256, 256),
        "bambu_x1": (256, 256, 256), "creality_ender3": (220, 220, 250), "voron_24_350": (350, 350, 340)}


@pytest.mark.parametrize("name", sorted(BEDS))
def test_built_in_profiles_have_their_printer_s_bed(name):
    p = load_printer(name)
    assert p.bed == BEDS[name] and p.name == name and p.title and p.margin_mm == 8.0  # the default skirt's room


def test_every_built_in_profile_loads():
    for name in printer_names():
        assert load_printer(name).bed_x_mm >= 50


def test_a_profile_file_of_the_user_s_own_printer(tmp_path):
    f = tmp_path / "my_printer.toml"
    f.write_text('title = "my MINI+"\nbed_x_mm = 180\nbed_y_mm = 175\nbed_z_mm = 170\nmargin_mm = 3\n'
                 'nozzle_mm = 0.6\n')
    p = load_printer(str(f), {"backlash_mm": 0.35})
    assert p.bed == (180.0, 175.0, 170.0) and p.margin_mm == 3.0 and p.nozzle_mm == 0.6
    assert p.name == "my_printer" and p.backlash_mm == 0.35 and "my MINI+" in p.label


@pytest.mark.parametrize("text, key, fragment", [
    ("bed_x_mm = 180\nbed_z_mm = 180\n", "printer.bed_y_mm", "missing"),
    ("bed_x_mm = 180\nbed_y_mm = -180\nbed_z_mm = 180\n", "printer.bed_y_mm", "positive"),
    ("bed_x_mm = 0\nbed_y_mm = 180\nbed_z_mm = 180\n", "printer.bed_x_mm", "positive"),
    ("bed_x_mm = 180\nbed_y_mm = 180\nbed_z_mm = 'tall'\n", "printer.bed_z_mm", "number"),
    ("bed_x_mm = 180\nbed_y_mm = 180\nbed_z_mm = 180\nshape = 'circle'\n", "printer.shape", "rectangle"),
    ("bed_x_mm = 180\nbed_y_mm = 180\nbed_z_mm = 180\ncolour = 1\n", "printer.colour", "unknown printer setting"),
])
def test_a_bad_profile_file_exits_2_naming_the_key(tmp_path, capsys, text, key, fragment):
    f = tmp_path / "printer.toml"
    f.write_text(text)
    out = tmp_path / "kit"
    rc = main(["print", str(ROOT / "parts" / "road_wheel.toml"), "--printer", str(f), "--out", str(out), "-q"])
    err = [line for line in capsys.readouterr().err.splitlines() if line.strip()]
    assert rc == 2 and len(err) == 1 and err[0].startswith(f"propulsor: error: {key} = ") and fragment in err[0], err
    assert not out.exists()


def test_bed_gives_a_quick_profile():
    p = load_printer("generic", bed="180x180x180")
    assert p.bed == (180.0, 180.0, 180.0) and "--bed 180x180x180" in p.label
    assert parse_bed("250 × 210 × 220")["bed_y_mm"] == 210.0
    for bad in ("180", "180x", "axbxc", "180x180x180x1"):
        with pytest.raises(InputError, match="--bed = "):
            parse_bed(bad)
    with pytest.raises(InputError, match=r"printer\.bed_x_mm = 40\.0: must be >= 50"):
        load_printer("generic", bed="40x180x180")


def test_an_unknown_printer_says_how_to_give_one():
    with pytest.raises(InputError, match="or the path of your own profile.*--bed 180x180x180"):
        load_printer("prusa_mini_plus")
    with pytest.raises(InputError, match="no such profile file"):
        load_printer("nowhere/my_printer.toml")


# --- kits on a 180 mm bed: one fast case here; every part file on every profile in make check -----------

import json  # noqa: E402
import shutil  # noqa: E402

needs_slicer = pytest.mark.skipif(shutil.which("prusa-slicer") is None,
                                  reason="PrusaSlicer is not installed (apt-get install prusa-slicer)")


def _kit(tmp_path, part: str, *args) -> tuple[int, Path, dict | None]:
    out = tmp_path / f"{part}_kit"
    rc = main(["print", str(ROOT / "parts" / f"{part}.toml"), "--out", str(out), "-q", "--slice", "no", *args])
    m = json.loads((out / "manifest.json").read_text()) if rc == 0 else None
    return rc, out, m


def _assert_sound(m: dict) -> None:
    bad = [c["name"] for c in m["checks"] if not c["passed"] and c["name"] not in m.get("expected_failures", [])]
    assert bad == []


def test_the_seed_002_pair_prints_on_a_180_mm_bed_with_unequal_pins(tmp_path):
    rc, out, m = _kit(tmp_path, "ncg_seed002", "--printer", "prusa_mini")
    assert rc == 0
    _assert_sound(m)
    d, checks = m["derived"], {c["name"]: c for c in m["checks"]}
    assert d["scale_S"] == 1.5 and d["printer"] == "prusa_mini" and d["bed_mm"] == [180.0, 180.0, 180.0]
    # the bores 16 / 40 mm: pins of unequal standard diameters, each measured in its own hole
    assert (d["pin_driver_d_mm"], d["pin_driven_d_mm"]) == (10.0, 12.0)
    for name in ("pin_driver_in_base", "pin_driven_in_base", "driver_on_pin", "driven_on_pin", "handle_in_driver"):
        assert checks[f"fit.{name}"]["passed"] and "measured" in checks[f"fit.{name}"]["message"]
    guide = (out / "print_guide.md").read_text()
    assert "Prusa MINI+" in guide and "⌀10 mm steel dowel pin" in guide and "clearance" in guide
    assert "Prusa MINI+, 180 × 180 mm bed" in (out / "print_report.md").read_text()
    for pic in ("assembled_side", "exploded", "step_1", "step_2", "step_3"):
        assert (out / "plots" / f"{pic}.png").is_file()


@pytest.mark.slicer
@needs_slicer
def test_road_wheel_on_a_quick_180_bed_and_its_coupon_plate_slices(tmp_path):
    from propulsor.printing.slicer import slice_plate

    rc, out, m = _kit(tmp_path, "road_wheel", "--bed", "180x180x180")
    assert rc == 0
    _assert_sound(m)
    assert m["derived"]["scale_S"] == 4.0 and m["derived"]["printer"] == "bed_180x180x180"
    p = load_printer("generic", bed="180x180x180")
    r = slice_plate(out / "plate_1.3mf", p.bed_shape(), tmp_path / "p1.gcode", args=p.slicer_args())
    assert r.ok and r.all_manifold and r.off_bed(180.0, 180.0) == [] and r.stats["time_s"] > 0


PART_FILES = sorted(f.stem for f in (ROOT / "parts").glob("*.toml"))


def _sweep_profiles():
    """The sweep's profiles: every one, or those named in PROPULSOR_SWEEP_PROFILES (comma-separated labels,
    e.g. bed180,prusa_mini,bambu_a1_mini: the 180 mm beds)."""
    import os

    from kit_sweep import profiles

    wanted = [w.strip() for w in os.environ.get("PROPULSOR_SWEEP_PROFILES", "").split(",") if w.strip()]
    every = profiles()
    unknown = sorted(set(wanted) - {label for label, _, _ in every})
    assert not unknown, f"PROPULSOR_SWEEP_PROFILES names no profile {unknown}"
    return [pr for pr in every if not wanted or pr[0] in wanted]


@pytest.mark.sweep
@pytest.mark.slicer
@needs_slicer
@pytest.mark.parametrize("part", PART_FILES)
def test_every_part_file_prints_on_every_profile_and_slices(tmp_path, monkeypatch, part):
    """Every profile builds its own kit of the part file (exit 0, its checks pass, every plate on its bed);
    then every plate slices in PrusaSlicer with every object manifold and on that profile's bed.  What
    cannot differ between profiles is computed once (tests/kit_sweep.py): run it all with
    `.venv/bin/python -m pytest -q -n 2 -m sweep tests/test_print_kits_printers.py` (make check), a few part files
    with -k, a few profiles with PROPULSOR_SWEEP_PROFILES."""
    import time

    from kit_sweep import KitMemo, SharedSlicer

    memo, slicer = KitMemo(monkeypatch), SharedSlicer(tmp_path)
    failures, t0, n_kits, n_plates = [], time.perf_counter(), 0, 0
    # the smallest beds first: a plate sliced on a bed is not sliced again for a profile whose bed holds it
    took = []
    for label, args, printer in sorted(_sweep_profiles(), key=lambda pr: (pr[2].bed_x_mm * pr[2].bed_y_mm, pr[0])):
        t = time.perf_counter()
        rc, out, m = _kit(tmp_path / label, part, *args)
        took.append(f"{label} {time.perf_counter() - t:.0f} s")
        if rc != 0:
            failures.append(f"{label}: propulsor print exited {rc}")
            continue
        bad = [c["name"] for c in m["checks"] if not c["passed"] and c["name"] not in m.get("expected_failures", [])]
        on_bed = [c for c in m["checks"] if c["name"].startswith("plate_") and c["name"].endswith(".on_bed")]
        if bad or not on_bed or m["derived"]["printer"] != printer.name:
            failures.append(f"{label}: failed checks {bad}, {len(on_bed)} plates")
        n_kits += 1
        n_plates += slicer.add(label, out, printer)
    t1 = time.perf_counter()
    sliced = slicer.failures()
    print(f"\n{part}: {n_kits} kits built in {t1 - t0:.0f} s (shared: {memo.hits}); {n_plates} plates, "
          f"{len(slicer.runs)} slicer runs, done {time.perf_counter() - t1:.0f} s after the last kit; kits: "
          + ", ".join(took))
    assert failures + sliced == []


def test_a_printer_setting_is_named_where_it_was_written(tmp_path):
    """The part file's [print] table names its keys print.<key>; a profile file's are printer.<key> (the trial met
    both prefixes for keys it had written in one place)."""
    from propulsor.errors import InputError
    from propulsor.printing.printers import load_printer

    cases = [(dict(name="generic", overrides={"bed_x_mm": 40.0}), "print.bed_x_mm"),
             (dict(name="generic", overrides={"backlsh_mm": 0.1}), "print.backlsh_mm"),
             (dict(name="generic", overrides={"layer_mm": -1.0}), "print.layer_mm")]
    f = tmp_path / "mine.toml"
    f.write_text("bed_x_mm = 40\nbed_y_mm = 180\nbed_z_mm = 180\n")
    cases.append((dict(name=str(f)), "printer.bed_x_mm"))
    g = tmp_path / "other.toml"
    g.write_text("bed_x_mm = 180\nbed_y_mm = 180\nbed_z_mm = 180\nbacklsh_mm = 0.1\n")
    cases.append((dict(name=str(g)), "printer.backlsh_mm"))
    for kw, named in cases:
        with pytest.raises(InputError) as exc:
            load_printer(**kw)
        assert exc.value.parameter == named, (kw, exc.value.parameter)
