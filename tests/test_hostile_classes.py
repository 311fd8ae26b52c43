"""The classes of defects found on the newer surfaces, beyond the critical ones (test_hostile_surfaces.py):
numbers (one parser for every number that enters), studies, `check` under memory pressure, messages that name
what is at fault, the Python API from several threads.  Every refusal is one line, exit 2 naming the key or 3
naming the path, never a traceback."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from test_hostile_surfaces import (ONE_VARIANT, ROOT, SMALL_WHEEL, WHEEL_PART, _cli, _one_error_line,  # noqa: F401
                                   _popen)


# -- Numbers: one parser for every number that enters ------------------------------------------------

@pytest.mark.parametrize("value, named", [
    ("1" + "0" * 400, "load_N"),       # an integer beyond any float
    ("1" + "0" * 5000, "part file"),   # past Python's 4300-digit conversion limit
    ("5e-324", "load_N"),              # subnormal
    ("1e308", "load_N"),
    ("nan", "load_N"),
])
def test_a_part_file_number_out_of_the_computable_range_is_one_line(tmp_path, value, named):
    part = tmp_path / "p.toml"
    part.write_text(f'type = "road_wheel"\nload_N = {value}\n')
    r = _cli("build", str(part), "--dry-run", timeout=120)
    assert r.returncode == 2, r.stderr
    assert _one_error_line(r.stderr).startswith(f"propulsor: error: {named}")


@pytest.mark.parametrize("option, value", [
    ("--scale", "١٨٠"), ("--scale", "1_8_0"), ("--scale", "inf"), ("--bed", "١٨٠x180x180"), ("--bed", "1_8_0x180x180"),
    ("--set", "backlash_mm=٠.٣"), ("--set", "backlash_mm=0_3"), ("--set", "backlash_mm=1e999"),
    ("--set", "a=" + "[" * 3000 + "]" * 3000), ("--set", "backlash_mm=" + "9" * 5000),
])
def test_a_command_line_number_is_plain_ascii_and_finite(option, value):
    r = _cli("print", str(WHEEL_PART), f"{option}={value}", "--slice", "no", "--out", "/nonexistent/kit", timeout=120)
    assert r.returncode == 2, r.stderr
    line = _one_error_line(r.stderr)
    assert option in line, line


@pytest.mark.parametrize("option", ["--out", "--printer", "--scale", "--set"])
def test_an_option_given_the_end_of_options_as_its_value_is_one_line(option):
    r = _cli("print", str(WHEEL_PART), f"{option}=--", "--slice", "no", timeout=60)
    assert r.returncode == 2 and option in _one_error_line(r.stderr), r.stderr


@pytest.mark.parametrize("row, why", [
    ("1_0.0,10.0", "plain digits"), ("١٠.٠,10.0", "plain digits"), ("1e308,10.0", "within"),
    ("5e-324,10.0", "too small"), ('"' + "x" * 200_000 + '",1', "CSV"),
])
def test_a_law_table_cell_is_a_plain_finite_number(tmp_path, row, why):
    from propulsor.errors import InputError
    from propulsor.laws.table_law import parse_law_table

    text = "driver_deg,driven_deg\n0.0,0.0\n" + row + "\n20.0,20.0\n"
    with pytest.raises(InputError, match=why) as exc:
        parse_law_table(text)
    assert str(exc.value).startswith("law_file")


def test_law_table_rows_closer_than_rounding_are_refused():
    from propulsor.errors import InputError
    from propulsor.laws.table_law import TableLaw

    th = [0.0, 10.0, 10.0 + 1e-11, 20.0, 30.0, 40.0, 50.0, 60.0, 360.0]
    ph = [0.0, 5.0, 5.0 + 1e-12, 10.0, 15.0, 20.0, 25.0, 30.0, 180.0]
    with pytest.raises(InputError, match="strictly increasing"):
        TableLaw(tuple(th), tuple(ph))


def test_a_file_that_is_not_a_table_echoes_nothing_of_it(tmp_path):
    from propulsor.errors import InputError
    from propulsor.laws.pitch_curve_law import parse_pitch_curve
    from propulsor.laws.table_law import parse_law_table

    secret = "AWS_SECRET=hunter2\x00PATH=/usr/bin\x00"
    for parse in (parse_law_table, parse_pitch_curve):
        with pytest.raises(InputError) as exc:
            parse(secret)
        assert "hunter2" not in str(exc.value) and "AWS" not in str(exc.value)


def test_the_api_takes_numpy_numbers_and_byte_paths_and_copies_lists():
    import numpy as np

    import propulsor

    p = propulsor.part(os.fsencode(str(WHEEL_PART)), tyre_width_mm=np.float64(80.0), lightening_holes=np.int64(0))
    assert p.params.tyre_width_mm == 80.0 and type(p.params.lightening_holes) is int
    teeth = [36, 42, 48]
    q = propulsor.part("polysector_gear", conditional_teeth=teeth)
    teeth.append(54)
    assert q.params.conditional_teeth == [36, 42, 48]
    for bad in (np.bool_(True), np.array([1.0, 2.0]), 10 ** 400, 5e-324):
        with pytest.raises(propulsor.InputError, match="load_N"):
            propulsor.part("road_wheel", load_N=bad)


@pytest.mark.parametrize("vary", [
    "tyre_width_mm = { from = 70.0, to = 90.0, step = 5e-324 }",
    "tyre_width_mm = { from = [70.0], to = 90.0, step = 10.0 }",
    "tyre_width_mm = { from = 'a', to = 90.0, step = 10.0 }",
    "tyre_width_mm = { from = true, to = 90.0, step = 10.0 }",
    "tyre_width_mm = [70.0, 1" + "0" * 400 + "]",
])
def test_a_study_range_that_is_no_range_of_numbers_is_exit_2_before_any_work(tmp_path, vary, capsys):
    from propulsor.cli import main

    study = tmp_path / "s.toml"
    study.write_text(ONE_VARIANT.replace("tyre_width_mm = [70.0]", vary))
    assert main(["explore", str(study), "--out", str(tmp_path / "out"), "-q"]) == 2
    assert "tyre_width_mm" in _one_error_line(capsys.readouterr().err)
    assert not (tmp_path / "out").exists()


# -- Studies ---------------------------------------------------------------------------------------

def test_a_design_depth_variant_of_a_law_without_a_hub_is_a_row_of_values():
    from propulsor.params import read_part_file
    from propulsor.study.evaluate import evaluate

    part = ROOT / "parts" / "ncg_elliptical.toml"
    _, base = read_part_file(part)
    row = evaluate("noncircular_pair", base, str(part), {}, "design", ("center_distance_mm", "ratio_min", "eccentricity"))
    assert row["status"] == "ok", row["reason"]
    assert round(row["values"]["center_distance_mm"], 4) == 76.7573 and row["values"]["eccentricity"] == 0.3


def test_a_tex_like_title_or_name_is_drawn_as_written(tmp_path):
    from propulsor.study import load_study
    from propulsor.study.page import write_page
    from propulsor.study.results import plot_front, ranked

    study_file = tmp_path / "s.toml"
    study_file.write_text(ONE_VARIANT.replace("[study]", '[study]\ntitle = "$\\\\x$ and $\\\\frac{a}{$"'))
    study = load_study(study_file)
    rows = [{"variant": k, "key": f"k{k}", "tyre_width_mm": 70.0 + k, "T_at_V_max_C": 100.0 + k, "status": "ok"}
            for k in (1, 2)]
    rank = ranked(study, rows)
    assert plot_front(tmp_path, study, rows, rank)
    page = write_page(tmp_path, study, rows, rank).read_text()
    assert "Content-Security-Policy" in page and "$\\x$" in page


def test_a_local_cluster_leaves_no_scratch_space_even_when_interrupted(tmp_path):
    import signal

    study = tmp_path / "s.toml"
    study.write_text(ONE_VARIANT.replace("tyre_width_mm = [70.0]", "tyre_width_mm = [70.0, 75.0, 80.0, 85.0, 90.0]"))
    scratch = tmp_path / "tmp"
    scratch.mkdir()
    env = dict(os.environ, TMPDIR=str(scratch))
    out = tmp_path / "out"
    p = _popen("explore", str(study), "--out", str(out), "--workers", "1", env=env)
    t0 = time.monotonic()
    while p.poll() is None and time.monotonic() - t0 < 240:
        if (out / "results.csv").is_file() and len((out / "results.csv").read_text().splitlines()) >= 2:
            break
        time.sleep(0.2)
    p.send_signal(signal.SIGINT)
    _, err = p.communicate(timeout=120)
    assert p.returncode == 130, err
    time.sleep(1.0)
    left = [q for q in scratch.rglob("*") if "dirlock" in q.name or q.name.startswith(("dask", "propulsor-dask"))]
    assert not left, left


@pytest.mark.parametrize("what", ["fifo", "link out", "not finished"])
def test_the_gallery_says_why_it_does_not_show_a_study(tmp_path, what):
    from propulsor.export.gallery import render_gallery

    study = tmp_path / "st"
    study.mkdir()
    if what == "fifo":
        os.mkfifo(study / "study.json")
        (study / "study.html").write_text("<p>x</p>")
    elif what == "link out":
        (tmp_path / "elsewhere.json").write_text("{}")
        (study / "study.json").symlink_to(tmp_path / "elsewhere.json")
        (study / "study.html").write_text("<p>x</p>")
    else:
        (study / "study.json").write_text('{"title": "t"}')
    page = render_gallery(tmp_path)
    assert "st: " in page and ("not readable" in page or "no study.html yet" in page), what


# -- check ---------------------------------------------------------------------------------------------

def test_a_glb_of_hundreds_of_thousands_of_primitives_is_invalid_not_a_memory_error(tmp_path):
    import json
    import struct

    blob = bytes(36)
    prims = [{"attributes": {"POSITION": 0}}] * 330_000
    doc = {"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": prims}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
           "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [{"byteLength": 36}]}
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    glb = (struct.pack("<4sII", b"glTF", 2, 20 + len(js) + 8 + len(blob)) + struct.pack("<I4s", len(js), b"JSON")
           + js + struct.pack("<I4s", len(blob), b"BIN\0") + blob)
    (tmp_path / "many.glb").write_bytes(glb)
    r = _cli("check", str(tmp_path / "many.glb"), timeout=300)
    assert r.returncode == 1 and "Traceback" not in r.stderr + r.stdout, r.stderr
    assert "primitives" in r.stdout, r.stdout


def test_a_dxf_that_needs_too_much_memory_says_out_of_memory(tmp_path, monkeypatch):
    import ezdxf

    from propulsor.checks.files import check_file

    (tmp_path / "a.dxf").write_text("0\nEOF\n")

    def no_memory(*a, **k):
        raise MemoryError()

    monkeypatch.setattr(ezdxf, "readfile", no_memory)
    (c,) = check_file(tmp_path / "a.dxf")
    assert not c.passed and c.message.startswith("out of memory"), c.message


def test_a_design_depth_objective_the_part_does_not_compute_is_refused_up_front(tmp_path, capsys):
    from propulsor.cli import main

    study = tmp_path / "s.toml"
    study.write_text(f"""
[study]
part = "{ROOT / 'parts' / 'ncg_elliptical.toml'}"
depth = "design"
[vary]
face_width_mm = [15.0]
[objectives]
minimize = ["speed_ripple"]
""")
    assert main(["explore", str(study), "--out", str(tmp_path / "out"), "-q"]) == 2
    line = _one_error_line(capsys.readouterr().err)
    assert "objectives.minimize = 'speed_ripple'" in line and "not computed at depth design" in line, line


def test_part_write_from_two_threads_builds_both_and_leaves_stderr_alone(tmp_path):
    import threading

    import propulsor

    part = tmp_path / "wheel.toml"
    part.write_text(SMALL_WHEEL)
    saved = sys.stderr
    errors, outs = [], []

    def write(k):
        try:
            outs.append(propulsor.part(part).write(tmp_path / f"out{k}"))
        except BaseException as exc:  # noqa: BLE001
            errors.append(exc)

    threads = [threading.Thread(target=write, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=600)
    assert not errors, errors
    assert sys.stderr is saved
    assert all((o / "manifest.json").is_file() for o in outs) and len(outs) == 2


@pytest.mark.parametrize("out", ["long", "not utf-8"])
def test_a_study_out_that_no_writer_can_use_is_refused_before_any_cluster(tmp_path, out):
    study = tmp_path / "s.toml"
    study.write_text(ONE_VARIANT)
    target = str(tmp_path) + ("/" + "x" * 200) * 25 if out == "long" else os.fsdecode(bytes(tmp_path) + b"/o\xff")
    t0 = time.monotonic()
    r = subprocess.run([sys.executable, "-m", "propulsor.cli", "explore", str(study), "--out", target, "-q"],
                       capture_output=True, cwd=ROOT, timeout=120)
    err = r.stderr.decode("utf-8", "replace")
    assert r.returncode == 2, err
    assert "--out" in _one_error_line(err) and time.monotonic() - t0 < 20


def test_a_study_on_a_full_disk_is_exit_3_naming_its_folder_and_leaves_no_empty_page(tmp_path):
    if os.geteuid() != 0:
        pytest.skip("mounting a small tmpfs needs root")
    mnt = tmp_path / "disk"
    mnt.mkdir()
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=24k", "tmpfs", str(mnt)], capture_output=True, text=True)
    if r.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {r.stderr.strip()}")
    try:
        study = tmp_path / "s.toml"
        study.write_text(ONE_VARIANT.replace("tyre_width_mm = [70.0]", "tyre_width_mm = [70.0, 80.0]"))
        r = _cli("explore", str(study), "--out", str(mnt / "st"), "--workers", "1", "-q", timeout=300)
        assert r.returncode == 3, r.stderr
        line = _one_error_line(r.stderr)
        assert "[ENOSPC]" in line and str(mnt) in line and "?:" not in line, line
        page = mnt / "st" / "study.html"
        assert not page.exists() or page.stat().st_size > 0
    finally:
        subprocess.run(["umount", "-l", str(mnt)], capture_output=True)


# -- Messages that name what is at fault -------------------------------------------------------------

def test_a_fourier_law_refusal_names_the_series_at_fault():
    from propulsor.errors import InputError
    from propulsor.laws.ratio_laws import FourierLaw

    with pytest.raises(InputError) as exc:
        FourierLaw(1, (0.01,), (2.0,))  # the sine terms turn the driven wheel back
    assert exc.value.parameter == "fourier_sin", exc.value
    with pytest.raises(InputError) as exc:
        FourierLaw(1, (2.0,), (0.01,))
    assert exc.value.parameter == "fourier_cos", exc.value


def test_a_pitch_curve_refusal_names_no_row_the_file_does_not_have(monkeypatch):
    import math

    from propulsor.errors import InputError
    from propulsor.laws import pitch_curve_law

    def refuse(self, *a, **k):  # the law of the conjugate wheel refused at one of its own samples
        raise InputError("pitch_curve_file row 1324 driven_deg", 123.4, "the spline through the rows has a ratio "
                         "U = -0.1 <= 0 near it: more rows or a smoother table")

    monkeypatch.setattr(pitch_curve_law.TableLaw, "__init__", refuse)
    angles = [5.0 * k for k in range(72)]
    radii = [40.0 + 5.0 * math.cos(math.radians(a)) for a in angles]
    with pytest.raises(InputError) as exc:
        pitch_curve_law.PitchCurveLaw(angles, radii, 1)
    assert exc.value.parameter == "pitch_curve_file" and "1324" not in str(exc.value) \
        and "driven_deg" not in str(exc.value), exc.value
