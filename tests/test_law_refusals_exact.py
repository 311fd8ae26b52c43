"""Every refusal of a law table, a pitch curve and an elliptical law with the whole of its answer (parameter, value,
limit), and the tables that are taken at their edges.  The cases `make mutation MODULE=laws` found no test for
(mutation/README.md)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.laws.pitch_curve_law import PitchCurveLaw, parse_pitch_curve, read_pitch_curve
from propulsor.laws.ratio_laws import E_MAX, EllipticalLaw
from propulsor.laws.table_law import (ANGLE_MAX_DEG, FIELD_MAX_CHARS, MAX_BYTES, parse_law_table, read_law_table,
                                      read_table_text, row_numbers, table_rows)


def _err(fn, *a, **kw):
    with pytest.raises(InputError) as e:
        fn(*a, **kw)
    return e.value.parameter, e.value.value, e.value.limit


HEAD = "driver_deg,driven_deg\n"


@pytest.mark.parametrize("text, want", [
    ("", ("law_file", "(empty)", "a table needs the header driver_deg,driven_deg and its rows")),
    ("\n , \n", ("law_file", "(empty)", "a table needs the header driver_deg,driven_deg and its rows")),
    ("a,b\n1,2\n", ("law_file", "(its first line)", "the header must be driver_deg,driven_deg: not a table of this "
                                                    "kind")),
    (HEAD + "1,2,3\n", ("law_file row 1", "1,2,3", "two columns: driver_deg,driven_deg")),
    (HEAD + "0,0\n1\n", ("law_file row 2", "1", "two columns: driver_deg,driven_deg")),
    (HEAD + "0,0\nx,1\n", ("law_file row 2 driver_deg", "x", "must be a number")),
    (HEAD + "0,0\n1, y \n", ("law_file row 2 driven_deg", "y", "must be a number")),
    (HEAD + f"0,0\n{ANGLE_MAX_DEG * 1.5:g},1\n", ("law_file row 2 driver_deg", 150000.0, "an angle within ±100000 deg")),
    (HEAD + f"0,0\n1,{-ANGLE_MAX_DEG * 1.5:g}\n", ("law_file row 2 driven_deg", -150000.0,
                                                   "an angle within ±100000 deg")),
])
def test_each_refusal_of_a_law_tables_text(text, want):
    got = _err(parse_law_table, text)
    assert got[:2] == want[:2] and got[2].startswith(want[2]), got


def test_header_with_spaces_and_blank_rows_is_a_table():
    th, ph = parse_law_table(" driver_deg , driven_deg \n\n0,0\n ,\n 10.5 ,2.5\n")
    assert (th, ph) == ((0.0, 10.5), (0.0, 2.5))
    assert row_numbers("k", 3, [str(ANGLE_MAX_DEG), "-1"], ("driver_deg", "driven_deg")) == (ANGLE_MAX_DEG, -1.0)


def test_too_many_rows_and_too_long_a_field():
    assert _err(table_rows, HEAD + "0,0\n" * 4, "k", ("driver_deg", "driven_deg"), 3) == (
        "k", "more than 3 rows", "at most 3 rows")
    assert len(table_rows(HEAD + "0,0\n" * 3, "k", ("driver_deg", "driven_deg"), 3)) == 3
    p, v, limit = _err(table_rows, HEAD + "0," + "1" * (FIELD_MAX_CHARS + 1) + "\n", "k",
                       ("driver_deg", "driven_deg"), 10)
    assert (p, v) == ("k", "row 2") and limit.startswith("is not a CSV table driver_deg,driven_deg (field larger")


def test_a_table_file_that_cannot_be_read(tmp_path):
    f = tmp_path / "law.csv"
    f.write_bytes(b"\xef\xbb\xbf" + (HEAD + "0,0\n").encode())  # a BOM is read past
    assert read_table_text(f, "law_file", "a law table").startswith("driver_deg")
    f.write_bytes(b"driver_deg,driven_deg\n\xff,0\n")
    assert _err(read_law_table, f) == ("law_file", str(f), "must be UTF-8 text")
    assert _err(read_law_table, tmp_path / "none.csv", "k")[:2] == ("k", str(tmp_path / "none.csv"))
    assert _err(read_law_table, tmp_path / "none.csv", "k")[2].startswith("cannot be read: ")
    f.write_bytes(b"#" * (MAX_BYTES + 1))
    p, v, limit = _err(read_law_table, f)
    assert (p, v) == ("law_file", str(f)) and limit.endswith(f"; a law table is a CSV file of at most {MAX_BYTES} "
                                                             "bytes")


# ---- pitch curves --------------------------------------------------------------------------------------------

def _ellipse_rows(n=16, e=0.2, p=40.0, closed=False):
    a = np.linspace(0.0, 360.0, n + (1 if closed else 0), endpoint=closed)
    return [float(x) for x in a], [float(y) for y in p / (1 + e * np.cos(np.radians(a)))]


@pytest.mark.parametrize("change, want", [
    (lambda a, r: (a[:7], r[:7]), ("pitch_curve_file", "7 rows", "a pitch curve needs at least 8 rows over one turn")),
    (lambda a, r: (a, r[:3] + [0.0] + r[4:]), ("pitch_curve_file row 4 radius_mm", 0.0,
                                              "the pitch curve must not reach or cross the axis: radius > 0 mm")),
    (lambda a, r: (a[:3] + [a[2]] + a[4:], r), ("pitch_curve_file row 4 angle_deg", 45.0,
                                               "must be strictly increasing (row 3: 45) by more than 3.6e-07 deg")),
    (lambda a, r: (a[:-1] + [361.0], r), ("pitch_curve_file row 16 angle_deg", 361.0,
                                         "the rows span one turn: angles up to 360 deg (that row only to close the "
                                         "curve, with the first row's radius)")),
    (lambda a, r: (a + [360.0], r + [r[0] * 1.01]), ("pitch_curve_file row 17 angle_deg", 360.0,
                                                     "the rows span one turn: angles up to 360 deg (that row only to "
                                                     "close the curve, with the first row's radius)")),
])
def test_each_refusal_of_a_pitch_curve(change, want):
    a, r = change(*_ellipse_rows())
    assert _err(PitchCurveLaw, a, r, 1) == want


@pytest.mark.parametrize("k", [0, 13, 1.5])
def test_lobes_of_a_pitch_curve(k):
    a, r = _ellipse_rows()
    assert _err(PitchCurveLaw, a, r, k) == ("driver_turns", k, "driver turns per driven turn must be a whole number "
                                                               "1 .. 12")


def test_a_pitch_curve_of_exactly_its_least_rows_and_closed_or_open():
    a, r = _ellipse_rows(8)
    law = PitchCurveLaw(a, r, 1)
    assert law.rows == 8 and law.first_angle == 0.0  # the rows as given (the closing one added is not counted)
    ac, rc = _ellipse_rows(8, closed=True)
    closed = PitchCurveLaw(ac, rc, 1)
    assert closed.L0 == law.L0 and closed.rows == 9  # its closing row is one of its rows
    phi = np.linspace(-2.0, 2.0, 9)
    np.testing.assert_array_equal(closed.U(phi), law.U(phi))
    # the first row's angle is the curve's start: turned rows, the same curve turned
    shifted = PitchCurveLaw([x + 30.0 for x in a], r, 1)
    assert shifted.first_angle == pytest.approx(math.radians(30.0))
    assert shifted.L0 == pytest.approx(law.L0, rel=1e-12)


def test_a_pitch_curve_file(tmp_path):
    a, r = _ellipse_rows(8)
    f = tmp_path / "curve.csv"
    f.write_text("angle_deg,radius_mm\n" + "".join(f"{x!r},{y!r}\n" for x, y in zip(a, r)), encoding="utf-8")
    assert read_pitch_curve(f) == (tuple(a), tuple(r))
    assert parse_pitch_curve(f.read_text()) == (tuple(a), tuple(r))
    assert _err(parse_pitch_curve, "angle_deg,radius_mm\n0,x\n") == (
        "pitch_curve_file row 1 radius_mm", "x", "must be a number in plain digits (0-9, '.', an exponent e±NNN)")
    assert _err(parse_pitch_curve, "driver_deg,driven_deg\n0,1\n") == (
        "pitch_curve_file", "(its first line)", "the header must be angle_deg,radius_mm: not a table of this kind")
    assert _err(read_pitch_curve, tmp_path / "none.csv")[:2] == ("pitch_curve_file", str(tmp_path / "none.csv"))


# ---- elliptical law ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("e, k, want", [
    (-0.1, 1, ("eccentricity", -0.1, "an ellipse has 0 <= e < 1")),
    (1.0, 1, ("eccentricity", 1.0, "an ellipse has 0 <= e < 1")),
    (E_MAX + 1e-9, 1, ("eccentricity", E_MAX + 1e-9, f"must be <= {E_MAX}: the driven wheel's radius L - r1 nearly "
                                                     "vanishes at the driver's far vertex")),
    (0.3, 0, ("driver_turns", 0, "lobes of the driven wheel must be a whole number 1 .. 12")),
    (0.3, 2.5, ("driver_turns", 2.5, "lobes of the driven wheel must be a whole number 1 .. 12")),
    (math.nan, 1, ("eccentricity", math.nan, "must be a finite number")),
])
def test_each_refusal_of_an_ellipse(e, k, want):
    got = _err(EllipticalLaw, e, k)
    assert got[0] == want[0] and got[2] == want[2]
    assert got[1] == want[1] or (isinstance(want[1], float) and math.isnan(want[1]) and math.isnan(got[1]))


@pytest.mark.parametrize("k", range(1, 13))
def test_every_ellipse_keeps_the_driven_radius_at_the_far_vertex(k):
    """L (1 - q - e) > 0 for every lobe count up to the largest eccentricity: (1 - e)^2 / 2 at least."""
    law = EllipticalLaw(E_MAX, k)
    assert 1 - law.q - E_MAX >= (1 - E_MAX) ** 2 / 2 - 1e-15


def test_the_largest_ellipse_and_its_fields():
    law = EllipticalLaw(E_MAX, 1)
    assert (law.e, law.k, law.n, law.periods) == (E_MAX, 1, 1, 1)
    assert law.q == pytest.approx((1 - E_MAX ** 2) / 2)
    law2 = EllipticalLaw(0.5, 2.0)
    assert law2.k == 2 and isinstance(law2.k, int)
    assert law2.period == pytest.approx(math.pi) and law2.period_start == pytest.approx(-math.pi / 2)
    assert law2.breakpoints == pytest.approx((-math.pi / 2, math.pi / 2))


# ---- a law table's rows as a law (TableLaw) ---------------------------------------------------------------------

from propulsor.laws.table_law import MIN_ROWS, PIECES, TableLaw  # noqa: E402


def _rows(n=13, span_ph=90.0, turns=1.0, wobble=0.02):
    """n rows of one period: driven 0 .. span_ph, driver 0 .. 360 turns span_ph / 90 ... a smooth ratio."""
    ph = np.linspace(0.0, span_ph, n)
    th = ph * (360.0 * turns / span_ph) + np.degrees(wobble * np.sin(2 * np.pi * ph / span_ph))
    return [float(x) for x in th], [float(y) for y in ph]


def test_each_refusal_of_a_law_tables_rows_in_full():
    th, ph = _rows()
    assert _err(TableLaw, tuple(th[:6]), tuple(ph[:6])) == ("law_file", "6 rows",
                                                            f"a law table needs at least {MIN_ROWS} rows over one period")
    assert _err(TableLaw, tuple(th), tuple(ph[:-1]), "k") == ("k", "13 rows",
                                                              f"a law table needs at least {MIN_ROWS} rows over one period")
    bad = th[:4] + [th[2]] + th[5:]
    assert _err(TableLaw, tuple(bad), tuple(ph)) == (
        "law_file row 5 driver_deg", th[2], f"must be strictly increasing (row 4: {th[3]:g}): the ratio must stay > 0")
    close = ph[:4] + [ph[3] + 1e-9] + ph[5:]
    assert _err(TableLaw, tuple(th), tuple(close)) == (
        "law_file row 5 driven_deg", ph[3] + 1e-9,
        f"must be strictly increasing (row 4: {ph[3]:g}) by more than {1e-9 * 90:.3g} deg: the ratio must stay > 0")
    assert _err(TableLaw, tuple(th), tuple(ph[:-1] + [100.0])) == (
        "law_file row 13 driven_deg", 100.0, "the last row closes the period: the driven span 100 deg must divide "
                                             "360 deg")
    assert _err(TableLaw, tuple(th[:-1] + [350.0]), tuple(ph)) == (
        "law_file row 13 driver_deg", 350.0, "over 4 periods of 90 deg the driver must make whole turns, not 3.88889")
    th3, ph3 = _rows(span_ph=120.0, turns=2 / 3)  # 3 periods, 2 driver turns: 2 does not divide 3
    assert _err(TableLaw, tuple(th3), tuple(ph3)) == (
        "law_file row 13 driver_deg", 240.0, "2 driver turns per driven turn must divide the 3 periods (the driver "
                                             "curve closes)")


def test_a_law_table_that_is_just_taken():
    th, ph = _rows(n=MIN_ROWS)
    law = TableLaw(tuple(th), tuple(ph))
    assert (law.n, law.periods) == (4, 4) and law.period == pytest.approx(math.pi / 2)
    # the driven span off the period by less than the closing tolerance is the period
    ph2 = ph[:-1] + [90.0 + 2e-7]
    law2 = TableLaw(tuple(th), tuple(ph2))
    assert law2.period == pytest.approx(math.pi / 2, abs=1e-15)
    # the breakpoints: every row, at most PIECES + 1 of them, the period's ends included
    assert law.breakpoints == pytest.approx(tuple(np.radians(ph)))
    big = TableLaw(*map(tuple, _rows(n=4 * PIECES + 1)))
    assert len(big.breakpoints) == PIECES + 1 and big.breakpoints[0] == 0.0
    assert big.breakpoints[-1] == pytest.approx(math.pi / 2)
    # the law wraps: theta(phi + P) = theta(phi) + 2 pi n / periods, also far out and below 0
    phi = np.array([-10.0, -0.3, 0.2, 7.5, 40.0])
    np.testing.assert_allclose(big.theta(phi + big.period) - big.theta(phi), 2 * math.pi, atol=1e-12)
    np.testing.assert_allclose(big.phi_of_theta(big.theta(phi)), phi, atol=1e-10)


def test_a_two_turn_table():
    th, ph = _rows(span_ph=180.0, turns=0.5)  # 2 periods of 180 deg, half a driver turn each: n = 1
    law = TableLaw(tuple(th), tuple(ph))
    assert (law.n, law.periods) == (1, 2)
    np.testing.assert_allclose(law.theta(np.array([2 * math.pi])), 2 * math.pi, atol=1e-12)


def test_a_law_table_file_names_its_key_in_a_row_refusal(tmp_path):
    f = tmp_path / "law.csv"
    f.write_text("driver_deg,driven_deg\n0,x\n", encoding="utf-8")
    assert _err(read_law_table, f, "my_key")[0] == "my_key row 1 driven_deg"


# ---- the law interface (laws/law.py) ---------------------------------------------------------------------------

from propulsor.laws.law import is_walking, require_law  # noqa: E402


class _Fake:
    kind = "fake"
    period_start = 0.0
    breakpoints = (0.0, 1.0)
    corner_phis = ()
    scalar_path = False

    def __init__(self, n, periods, period):
        self.n, self.periods, self.period = n, periods, period

    def U(self, phi): ...
    def dU_dphi(self, phi): ...
    def d2U_dphi2(self, phi): ...
    def theta(self, phi): ...
    def phi_of_theta(self, theta): ...
    def U_derivs1(self, phi): ...
    def theta1(self, phi): ...


def test_require_law_in_full():
    assert _err(require_law, object()) == ("law", "object", "must be a drive law (laws.law.Law: U, theta, period, n)")
    assert _err(require_law, _Fake(2, 3, 2 * math.pi / 3)) == (
        "n", 2, "the driver pitch curve repeats every n periods of the law and closes only if n divides its 3 periods "
                "per driven turn")
    assert _err(require_law, _Fake(1, 0, 1.0))[0] == "n"
    assert _err(require_law, _Fake(2, 4, math.pi / 2 + 1e-9)) == (
        "period", math.pi / 2 + 1e-9, "4 periods must make one driven turn (2 pi)")
    require_law(_Fake(2, 4, math.pi / 2))


def test_is_walking():
    from propulsor.laws.walking import WalkingLaw

    assert is_walking(WalkingLaw(100.0, 50.0, 236.5, 4))
    assert not is_walking(EllipticalLaw(0.3)) and not is_walking(object()) and not is_walking(_Fake(1, 1, 1.0))


def test_pitch_curve_rows_at_their_edges():
    a, r = _ellipse_rows(8)
    # a radius past the largest a wheel has
    text = "angle_deg,radius_mm\n" + "".join(f"{x!r},{y!r}\n" for x, y in zip(a, r[:2] + [2e4] + r[3:]))
    assert _err(parse_pitch_curve, text) == ("pitch_curve_file row 3 radius_mm", 20000.0,
                                             "a radius of at most 10000 mm")
    # a tiny curve (radii under 1 mm) is a curve
    tiny = PitchCurveLaw(a, [y / 50.0 for y in r], 1)
    assert tiny.L0 == pytest.approx(PitchCurveLaw(a, r, 1).L0 / 50.0, rel=1e-9)
    # rows 3.605e-7 deg apart are two rows (the curve's spline then swings between them: the conjugate wheel is
    # refused, naming no row); 3e-7 apart, one (the row is named)
    a2 = a[:3] + [a[2] + 3.605e-7] + a[4:]
    assert _err(PitchCurveLaw, a2, r, 1) == (
        "pitch_curve_file", "8 rows", "the conjugate wheel's angles would not increase (between the curve's rows): a "
                                      "smoother curve, or rows where its radius turns fastest")
    assert _err(PitchCurveLaw, a[:3] + [a[2] + 3e-7] + a[4:], r, 1)[0] == "pitch_curve_file row 4 angle_deg"
    # a closing row's radius must be the first row's to 1e-9 of it
    closed_a = a + [a[0] + 360.0]
    PitchCurveLaw(closed_a, r + [r[0] * (1 + 0.5e-9)], 1)
    assert _err(PitchCurveLaw, closed_a, r + [r[0] * (1 + 2e-9)], 1)[0] == "pitch_curve_file row 9 angle_deg"


def test_a_pitch_curve_starting_elsewhere_closed_or_open():
    a, r = _ellipse_rows(12)
    a30 = [x + 30.0 for x in a]
    open_ = PitchCurveLaw(a30, r, 1)
    closed = PitchCurveLaw(a30 + [390.0], r + [r[0]], 1)
    phi = np.linspace(-2.0, 2.0, 9)
    np.testing.assert_allclose(closed.U(phi), open_.U(phi), rtol=1e-12)
    assert closed.L0 == pytest.approx(open_.L0, rel=1e-12) and closed.first_angle == pytest.approx(math.radians(30))
