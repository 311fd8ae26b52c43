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
    assert p.bed == BEDS[name] and p.name == name and p.title and p.margin_mm == 5.0


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
    ("bed_x_mm = 180\nbed_y_mm = 180\nbed_z_mm = 180\ncolour = 1\n", "print.colour", "unknown printer setting"),
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
