"""A law as a table of angles (laws/table_law.py): same law -> same pitch curves; refusals name the row."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.gears.noncircular import PitchCurves, SmoothedWalkingLaw, centre_distance
from propulsor.laws.table_law import TableLaw, parse_law_table, read_law_table
from propulsor.laws.walking import SEED_000, SEED_002, WalkingLaw
from outline_points import dense


def _csv(th_deg, ph_deg) -> str:
    return "driver_deg,driven_deg\n" + "".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(th_deg, ph_deg))


@pytest.mark.parametrize("seed", [SEED_002, SEED_000])
def test_table_of_the_walking_laws_samples_gives_its_pitch_curves_within_1_um(tmp_path, seed):
    sl = SmoothedWalkingLaw(WalkingLaw(**seed), 0.2)
    ph = np.linspace(0.0, math.pi / 2, 721)  # one leg, every 1/8 deg
    f = tmp_path / "law.csv"
    f.write_text(_csv(np.degrees(sl.theta(ph)), np.degrees(ph)))
    tl = TableLaw(*read_law_table(f))
    assert (tl.n, tl.periods) == (seed["n"], 4)
    m, z_H = 2.5, 80
    L = centre_distance(sl, m, z_H)
    assert centre_distance(tl, m, z_H) == pytest.approx(L, abs=1e-6)
    a, b = PitchCurves(sl, L), PitchCurves(tl, L)
    x = np.linspace(0.0, 2 * math.pi, 20001)
    assert np.max(np.abs(a.r_H(x) - b.r_H(x))) < 1e-3 * 1e-3 * 1e3  # mm: 1 um
    assert np.max(np.abs(a.driver_radius(x) - b.driver_radius(x))) < 1e-3
    assert float(tl.theta(2 * math.pi)) == pytest.approx(2 * math.pi * seed["n"], abs=1e-12)


def test_table_law_derivatives_and_periodicity():
    ph = np.linspace(0.0, 360.0, 37)
    th = ph + 10.0 * np.sin(np.radians(ph))  # 1:1, U = 1 + (10 pi/180) cos phi
    law = TableLaw(tuple(th), tuple(ph))
    x = np.linspace(-7.0, 7.0, 41)
    h = 1e-5
    assert np.allclose((law.theta(x + h) - law.theta(x - h)) / (2 * h), law.U(x), atol=1e-8)
    assert np.allclose((law.U(x + h) - law.U(x - h)) / (2 * h), law.dU_dphi(x), atol=1e-6)
    assert np.allclose((law.dU_dphi(x + h) - law.dU_dphi(x - h)) / (2 * h), law.d2U_dphi2(x), atol=1e-4)
    assert np.allclose(law.U(x), 1 + math.radians(10.0) * np.cos(x), atol=1e-5)
    assert np.allclose(law.phi_of_theta(law.theta(x)), x, atol=1e-12)


def _rows(n=10):
    ph = np.linspace(0.0, 90.0, n)
    return list(2 * ph), list(ph)  # n = 2 driver turns per driven turn, 4 periods


@pytest.mark.parametrize("col", [0, 1])
def test_a_table_not_increasing_is_refused_naming_the_first_bad_row(col):
    th, ph = _rows()
    cols = [th, ph]
    cols[col][5] = cols[col][4]  # data row 6 repeats row 5
    cols[col][8] = cols[col][2]  # and a later one goes back: the first is named
    name = ("driver_deg", "driven_deg")[col]
    with pytest.raises(InputError, match=rf"^law_file row 6 {name} = [0-9.]+: must be strictly increasing \(row 5: "):
        TableLaw(tuple(th), tuple(ph))


def test_a_table_that_does_not_close_is_refused_at_its_last_row():
    th, ph = _rows()
    ph[-1] = 100.0
    with pytest.raises(InputError, match=r"^law_file row 10 driven_deg = 100.0: .*must divide 360"):
        TableLaw(tuple(th), tuple(ph))
    th, ph = _rows()
    th[-1] = 170.0
    with pytest.raises(InputError, match=r"^law_file row 10 driver_deg = 170.0: .*whole turns, not 1\.88"):
        TableLaw(tuple(th), tuple(ph))


def test_a_table_whose_spline_ratio_dips_below_zero_is_refused():
    ph = [0.0, 10.0, 20.0, 30.0, 30.001, 40.0, 50.0, 60.0, 70.0, 80.0, 90.0]
    th = [0.0, 10.0, 20.0, 30.0, 60.0, 60.001, 61.0, 62.0, 70.0, 80.0, 90.0]
    with pytest.raises(InputError, match=r"^law_file row \d+ driven_deg = [0-9.]+: .*ratio U = .* <= 0"):
        TableLaw(tuple(th), tuple(ph))


@pytest.mark.parametrize("text, match", [
    ("theta,phi\n0,0\n", r"header must be driver_deg,driven_deg"),
    ("driver_deg,driven_deg\n0,0\n1,x\n", r"^law_file row 2 driven_deg = 'x': must be a number in plain digits"),
    ("driver_deg,driven_deg\n0,0\n1,nan\n", r"^law_file row 2 driven_deg = 'nan': must be a number in plain digits"),
    ("driver_deg,driven_deg\n0,0,3\n", r"^law_file row 1 = '0,0,3': two columns"),
])
def test_malformed_tables_are_refused(text, match):
    with pytest.raises(InputError, match=match):
        parse_law_table(text)


def test_table_of_the_walking_laws_samples_gives_the_walking_driver_within_1_um():
    """Same law -> same teeth: the seed-002 driver (20 teeth, x = +0.5) generated on the blended walking
    law and on the table of its samples every 1/16 deg of one leg, at the same centre distance."""
    from scipy.spatial import cKDTree

    from propulsor.gears.noncircular_teeth import ToothSpec
    from propulsor.geometry.noncircular_outline import generate_gear

    sl = SmoothedWalkingLaw(WalkingLaw(**SEED_002), 0.2)
    ph = np.linspace(0.0, math.pi / 2, 1441)
    tl = TableLaw(tuple(np.degrees(sl.theta(ph))), tuple(np.degrees(ph)))
    L = centre_distance(sl, 2.5, 80)
    walking, table = (generate_gear(PitchCurves(law, L), "driver", ToothSpec(m=2.5, x=0.5, z0=20)).profile
                      for law in (sl, tl))
    d = cKDTree(dense(walking.polylines(0.0001), 0.0005)).query(np.vstack(table.polylines(0.0001)))[0]
    assert float(np.max(d)) < 1e-3
