"""Parameter loading and the command line's contract for bad input (exit 2, one line, nothing written)."""

from __future__ import annotations

import dataclasses
import math
import re
import subprocess
import sys
from pathlib import Path

import pytest

from propulsor.errors import InputError
from propulsor.params import describe_params, load_params, param, read_part_file

ROOT = Path(__file__).resolve().parents[1]


@dataclasses.dataclass
class _P:
    module_mm: float = param(2.0, "mm", "module", min=0, min_exclusive=True)
    z: int = param(20, "", "teeth", min=5, integer=True)
    method: str = param("generated", "", "tooth method", choices=["generated", "sectors"])
    keep: bool = param(False)

    def validate(self):
        if self.z * self.module_mm > 1000:
            raise InputError("z", self.z, f"z·m must be <= 1000 mm (module_mm = {self.module_mm})")


def test_load_params_defaults_and_values():
    p = load_params(_P, {"module_mm": 3, "z": 30})
    assert p.module_mm == 3.0 and isinstance(p.module_mm, float)
    assert p.z == 30 and p.method == "generated"


@pytest.mark.parametrize(
    "mapping, name, fragment",
    [
        ({"module_mm": -1.0}, "module_mm", "> 0"),
        ({"module_mm": 0.0}, "module_mm", "> 0"),
        ({"module_mm": math.nan}, "module_mm", "finite"),
        ({"z": 3}, "z", ">= 5"),
        ({"z": 20.5}, "z", "whole"),
        ({"method": "drawn"}, "method", "one of"),
        ({"keep": 1}, "keep", "true or false"),
        ({"zz": 1}, "zz", "unknown parameter"),
        ({"z": 600}, "z", "<= 1000"),
    ],
)
def test_load_params_rejects(mapping, name, fragment):
    with pytest.raises(InputError) as ei:
        load_params(_P, mapping)
    msg = str(ei.value)
    assert msg.startswith(name + " = ") and fragment in msg and "\n" not in msg


def test_describe_params_lists_units_and_limits():
    rows = {r["name"]: r for r in describe_params(_P)}
    assert rows["module_mm"]["unit"] == "mm" and rows["module_mm"]["limits"] == "> 0"
    assert rows["z"]["limits"].startswith("whole") and rows["method"]["limits"].startswith("one of")


def test_read_part_file_requires_type(tmp_path):
    f = tmp_path / "x.toml"
    f.write_text("module_mm = 2\n")
    with pytest.raises(InputError, match="type"):
        read_part_file(f)
    f.write_text('type = "planetary_final_drive"\nmodule_mm = 2\n[meta]\ntitle = "t"\n')
    assert read_part_file(f) == ("planetary_final_drive", {"module_mm": 2})


def _run(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "propulsor.cli", *args], capture_output=True, text=True,
                          cwd=cwd or ROOT, timeout=600)


def test_cli_unknown_part_type_exit2_nothing_written(tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text('type = "warp_drive"\n')
    out = tmp_path / "out"
    r = _run("build", str(f), "--out", str(out))
    assert r.returncode == 2
    # the one line of the refusal (the progress lines before it, "[  t s] …", are not counted)
    lines = [l for l in r.stderr.splitlines() if l.strip() and not re.match(r"\[ *\d+\.\d s\] ", l)]
    assert len(lines) == 1 and "warp_drive" in lines[0]
    assert not out.exists() and not any(tmp_path.glob(".out*"))


def test_cli_missing_file_exit2(tmp_path):
    r = _run("build", str(tmp_path / "nope.toml"), "--out", str(tmp_path / "o"))
    assert r.returncode == 2 and "does not exist" in r.stderr


def test_cli_list_names_part_files():
    r = _run("list")
    assert r.returncode == 0
    for f in sorted((ROOT / "parts").glob("*.toml")):
        assert f.name in r.stdout


def test_version_on_the_command_line_and_in_python():
    import propulsor
    from propulsor.version import __version__

    out = subprocess.run([sys.executable, "-m", "propulsor", "--version"], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == f"propulsor {__version__}" and propulsor.__version__ == __version__


def test_a_mistyped_key_is_answered_with_the_closest_names():
    from propulsor.parts import get_part_type

    with pytest.raises(InputError) as e:
        load_params(get_part_type("noncircular_pair").params_cls, {"modul_mm": 3})
    assert e.value.parameter == "modul_mm"
    n = len(dataclasses.fields(get_part_type("noncircular_pair").params_cls))
    assert e.value.limit == f"unknown parameter for this part (did you mean module_mm? `propulsor params <part type>` lists all {n})"
    with pytest.raises(InputError) as e:
        load_params(get_part_type("noncircular_pair").params_cls, {"zzzz": 3})
    assert e.value.limit.startswith("unknown parameter for this part (known: ")
    # a mistyped choice: the choices listed and the closest named (trial 2: law = 'pitchcurve')
    with pytest.raises(InputError) as e:
        load_params(get_part_type("noncircular_pair").params_cls, {"law": "pitchcurve"})
    assert (e.value.parameter, e.value.value, e.value.hint) == ("law", "pitchcurve", "did you mean pitch_curve?")
    assert e.value.limit == "must be one of walking, elliptical, fourier, table, pitch_curve"
    with pytest.raises(InputError) as e:
        load_params(get_part_type("noncircular_pair").params_cls, {"law": "zzz"})
    assert e.value.hint == ""


def test_params_of_a_printer_profile_and_the_law_keys_first():
    out = subprocess.run([sys.executable, "-m", "propulsor", "params", "printer"], capture_output=True, text=True,
                         check=True).stdout.splitlines()
    assert out[0].startswith("printer: a printer profile") and any(l.split()[0] == "backlash_mm" for l in out[2:])
    out = subprocess.run([sys.executable, "-m", "propulsor", "params", "noncircular_pair"], capture_output=True,
                         text=True, check=True).stdout.splitlines()
    names = [l.split()[0] for l in out[2:]]
    assert names[:2] == ["law", "driver_turns"] and names.index("pitch_curve_file") < names.index("a_mm")


def test_a_missing_part_file_is_said_once():
    out = subprocess.run([sys.executable, "-m", "propulsor", "build", "/nonexistent/x.toml"], capture_output=True,
                         text=True)
    assert out.returncode == 2
    assert out.stderr.strip().splitlines()[-1] == "propulsor: error: part file = '/nonexistent/x.toml': does not exist"
    assert out.stderr.count("does not exist") == 1


def test_a_mistyped_printer_setting_is_answered_with_the_closest_names():
    from propulsor.printing.printers import load_printer

    with pytest.raises(InputError) as e:
        load_printer("generic", {"backlash": 0.3})
    assert (e.value.parameter, e.value.hint) == ("print.backlash", "did you mean backlash_mm?")


def test_a_refused_default_is_said_to_be_the_default_and_a_written_value_is_not():
    from propulsor.building import default_named
    from propulsor.parts import get_part_type

    cls = get_part_type("noncircular_pair").params_cls
    exc = InputError("driver_shift", 0.5, "not generable", "driver_shift <= -0.337")
    said = default_named(exc, {"law": "elliptical"}, cls)
    assert (said.parameter, said.value, said.limit) == ("driver_shift", 0.5, "not generable")
    assert said.hint == "driver_shift <= -0.337; driver_shift is not in the part file: 0.5 is its default"
    assert default_named(exc, {"driver_shift": 0.5}, cls) is exc  # written in the part file: as it is
    other = InputError("center_distance_band_mm x", 1, "x")  # not a field of the part: as it is
    assert default_named(other, {}, cls) is other


@pytest.mark.parametrize("m, refused", [(0.0001, True), (0.049, True), (0.05, False), (0.0, False)])
def test_a_module_below_the_smallest_standard_one_is_refused_before_the_build(m, refused):
    from propulsor.parts import get_part_type

    cls = get_part_type("noncircular_pair").params_cls
    mapping = {"law": "elliptical", "eccentricity": 0.3, "driver_turns": 1, "module_mm": m, "driven_teeth": 30,
               "center_distance_mm": 0.0 if m else 80.0}
    if refused:
        with pytest.raises(InputError) as e:
            load_params(cls, mapping)
        assert (e.value.parameter, e.value.value, e.value.limit) == (
            "module_mm", m, "must be 0 (from center_distance_mm) or >= 0.05 mm, the smallest module of ISO 54 / "
                            "GOST 9563")
    else:
        try:
            load_params(cls, mapping)
        except InputError as exc:
            assert exc.parameter != "module_mm", exc
