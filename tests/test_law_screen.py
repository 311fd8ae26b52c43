"""``propulsor build --dry-run`` screens every law: a part file whose law no catalogue cutter can generate is
refused by the dry run with the very line the build refuses it with (what would make it generable), and
the shipped part files of the other laws are valid."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from propulsor.cli import main

PARTS = Path(__file__).resolve().parent.parent / "parts"

_COMMON = ('type = "noncircular_pair"\npressure_angle_deg = 20.0\nlaw_search = true\nface_width_mm = 15.0\n'
           'driver_bore_mm = 12.0\ndriven_bore_mm = 12.0\ncompare_methods = false\n')


def _pitch_curve_csv() -> str:
    """A 3-lobed driver r = 30 (1 + 0.3 cos 3a): its conjugate's convex stretches are too sharp for m = 2.5."""
    return "angle_deg,radius_mm\n" + "".join(f"{a},{30 * (1 + 0.3 * math.cos(math.radians(3 * a))):.6f}\n"
                                             for a in range(0, 360, 5))


def _table_csv() -> str:
    """theta = 2 phi + 0.2 sin 2 phi over one lobe of 180 deg (the law of parts/ncg_table.toml)."""
    return "driver_deg,driven_deg\n" + "".join(
        f"{2 * x + math.degrees(0.2 * math.sin(math.radians(2 * x)))!r},{float(x)!r}\n" for x in range(0, 181, 5))


#: (law keys, the file the law names, its text, words of the refusal)
BAD = {
    "elliptical": ('law = "elliptical"\neccentricity = 0.6\ndriver_turns = 1\nmodule_mm = 2.5\ndriven_teeth = 16\n'
                   'driver_shift = 0.0\n', None, None, r"works with driver_shift >= 0\.337, or driven_teeth >= 25"),
    "fourier": ('law = "fourier"\ndriver_turns = 4\nfourier_sin = [-0.12, 0.0, 0.0, 0.0]\nmodule_mm = 2.5\n'
                'driven_teeth = 80\ndriver_shift = 0.5\n', None, None, r"works with driver_shift <= -0\.304, or driven_teeth >= 176"),
    "table": ('law = "table"\nlaw_file = "law.csv"\nmodule_mm = 2.0\ndriven_teeth = 60\ndriver_shift = -0.8\n',
              "law.csv", _table_csv, r"works with driver_shift >= -0\.632, or driven_teeth >= 68"),
    "pitch_curve": ('law = "pitch_curve"\npitch_curve_file = "curve.csv"\ndriver_turns = 1\nmodule_mm = 2.5\n'
                    'driven_teeth = 40\ndriver_shift = 0.5\n', "curve.csv", _pitch_curve_csv,
                    # the catalogue shaper rolls e = 1.25 mm out: 7 teeth (r0 + e = 10.0 mm) fit inside the concave
                    # 10.364 mm, 8 (11.25 mm) do not
                    r"concave \|rho\|_min 10\.364 mm needs a shaper with shaper_teeth <= 7 "
                    r"\(r0 < \|rho\| - e, e = \+1\.250 mm\)"),
}


def _run(capsys, *argv) -> tuple[int, list[str]]:
    rc = main(list(argv))
    return rc, capsys.readouterr().err.strip().splitlines()


@pytest.mark.parametrize("law", sorted(BAD))
def test_dry_run_refuses_what_the_build_refuses_with_the_same_line(law, tmp_path, capsys, monkeypatch):
    keys, name, text, remedy = BAD[law]
    folder = tmp_path / "parts"
    folder.mkdir()
    part = folder / "bad.toml"
    part.write_text(_COMMON + keys)
    if name:
        (folder / name).write_text(text())
    monkeypatch.chdir(tmp_path)  # the law's file is read relative to the part file, not the current folder
    rc_dry, err_dry = _run(capsys, "build", "--dry-run", str(part), "--out", str(tmp_path / "dry"), "-q")
    rc, err = _run(capsys, "build", str(part), "--out", str(tmp_path / "out"), "-q")
    assert rc == rc_dry == 2
    assert len(err_dry) == 1 and err_dry == err
    import re

    assert re.match(rf"propulsor: error: \w+ = .*: the {law} law's pitch curves are not generable at m = ", err[0])
    assert re.search(remedy, err[0])
    assert not (tmp_path / "out").exists() and not (tmp_path / "dry").exists()


def test_the_build_without_the_screen_refuses_with_the_same_line(tmp_path):
    """The screen's refusal is the design's own (a fresh parameter object: nothing cached)."""
    from propulsor.errors import InputError
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams, pair_design
    from propulsor.parts.noncircular_pair.feasibility import screen

    keys = BAD["fourier"][0]
    part = tmp_path / "bad.toml"
    part.write_text(_COMMON + keys)
    p = load_params(NoncircularPairParams, read_part_file(part)[1])
    with pytest.raises(InputError) as screened:
        screen(p, source=part)
    q = load_params(NoncircularPairParams, read_part_file(part)[1])
    with pytest.raises(InputError) as built:
        pair_design(q, source=part)
    assert str(screened.value) == str(built.value)


@pytest.mark.parametrize("name", ["ncg_elliptical", "ncg_elliptical_2lobe", "ncg_fourier_seed002", "ncg_table"])
def test_the_shipped_part_files_of_other_laws_pass_the_dry_run(name, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)  # ncg_table.toml's CSV beside it, not in the current folder
    rc = main(["build", "--dry-run", str(PARTS / f"{name}.toml"), "--out", str(tmp_path / "out")])
    out = capsys.readouterr()
    assert rc == 0, out.err
    assert " is valid; would build into " in out.out


def test_speed_ratio_plot_shows_the_law_beside_the_speed_the_teeth_deliver():
    """A law without a hub: the output speed plot has the law's 1/U and the measured d phi / d theta."""
    from types import SimpleNamespace

    import numpy as np

    from propulsor.laws.ratio_laws import EllipticalLaw
    from propulsor.parts.noncircular_pair.law_outputs import speed_ratio_plot

    law = EllipticalLaw(0.3, 1)
    x = np.linspace(0.0, 2 * math.pi, 41)[:-1]
    pr = SimpleNamespace(ratio_actual=lambda: (x, law.U(x) * 1.01))
    plots = {}
    w = SimpleNamespace(add_plot=lambda name, fig: plots.setdefault(name, fig))
    speed_ratio_plot(w, SimpleNamespace(law=law, run_law=law), pr)
    lines = plots["speed_ratio"].axes[0].get_lines()
    assert len(lines) == 2
    xs, ys = lines[1].get_data()
    assert len(xs) == 40 and np.allclose(ys, 1.0 / (1.01 * law.U(x)))
