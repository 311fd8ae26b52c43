"""Limits and paths of the laws that the mutation run of 2026-11-28 found untested (TEST-GAPS.md T*, P*, R*)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.laws.pitch_curve_law import PitchCurveLaw
from propulsor.laws.ratio_laws import EllipticalLaw, FourierLaw
from propulsor.laws.table_law import MIN_ROWS as TABLE_MIN_ROWS, TableLaw
from propulsor.laws.pitch_curve_law import MIN_ROWS as CURVE_MIN_ROWS


# ---- table_law -------------------------------------------------------------------------------------------------

def _table(rows):
    ph = np.linspace(0.0, 90.0, rows)  # 4 periods of 90 deg, 2 driver turns per driven turn: theta = 2 phi
    return tuple(2 * ph), tuple(ph)


def test_table_of_exactly_min_rows_is_accepted_and_one_fewer_refused():  # T1
    assert TABLE_MIN_ROWS == 7
    law = TableLaw(*_table(7))
    assert (law.n, law.periods) == (2, 4)
    # theta = 2 phi exactly, so U = 2 everywhere
    assert np.allclose(law.U(np.linspace(-3.0, 3.0, 25)), 2.0, rtol=0, atol=1e-9)
    with pytest.raises(InputError, match=r"6 rows.*at least 7 rows"):
        TableLaw(*_table(6))


def test_table_whose_driver_makes_no_turn_is_refused_naming_driver_deg():  # T3
    ph = np.linspace(0.0, 90.0, 10)
    th = 1e-8 * np.arange(10)  # strictly increasing, but 4 periods make ~0 driver turns
    with pytest.raises(InputError, match=r"driver_deg.*whole turns"):
        TableLaw(tuple(th), tuple(ph))


def test_table_last_row_a_rounding_off_the_period_keeps_theta_continuous():  # T5
    # last driven row 90 + 2e-7 deg: within CLOSE_TOL_DEG = 1e-6 deg of the period (|360/90.0000002 - 4| * 90 =
    # 8e-7 deg), so accepted as a 90 deg period; theta must not jump at the period boundary
    ph = np.linspace(0.0, 90.0, 13)
    th = 2 * ph + 5.0 * np.sin(np.radians(4 * ph))
    ph[-1] += 2e-7
    th[-1] = 180.0
    law = TableLaw(tuple(th), tuple(ph))
    P = math.pi / 2
    assert law.period == P
    eps = 1e-9
    for m in range(-2, 3):
        x = m * P
        # across each boundary theta is continuous to rounding: its step over 2 eps is U * 2 eps
        # (U(0) = 2 + 20 cos 0 * pi/180 = 2.349)
        assert float(law.theta(x + eps) - law.theta(x - eps)) == pytest.approx(float(law.U(x)) * 2 * eps, abs=1e-12)
        assert float(law.U(x)) == pytest.approx(2 + math.radians(20.0), abs=1e-5)  # spline of 13 rows
        assert float(law.theta(x + P / 3)) - float(law.theta(x - P + P / 3)) == pytest.approx(2 * P, abs=1e-12)


# ---- pitch_curve_law -------------------------------------------------------------------------------------------

def _curve(rows, e=0.3, p=30.0, closed=False):
    a = np.linspace(0.0, 360.0, rows + (1 if closed else 0), endpoint=closed)
    return tuple(a), tuple(p / (1 + e * np.cos(np.radians(a))))


def test_pitch_curve_of_exactly_min_rows_is_accepted_and_one_fewer_refused():  # P1
    assert CURVE_MIN_ROWS == 8
    law = PitchCurveLaw(*_curve(8), 1)
    assert law.rows == 8  # the 8 rows given (the closing row added is not counted: the report names the file's rows)
    with pytest.raises(InputError, match=r"7 rows.*at least 8 rows"):
        PitchCurveLaw(*_curve(7), 1)


def test_closed_pitch_curve_is_the_same_law_as_the_open_one():  # P3
    a, r = _curve(36, closed=True)
    assert a[-1] == 360.0 and r[-1] == r[0]
    closed, open_ = PitchCurveLaw(a, r, 1), PitchCurveLaw(a[:-1], r[:-1], 1)
    assert closed.L0 == pytest.approx(open_.L0, rel=1e-14)
    x = np.linspace(-4.0, 4.0, 101)
    assert np.allclose(closed.theta(x), open_.theta(x), rtol=0, atol=1e-13)


def test_pitch_curve_accepts_12_lobes_and_refuses_13():  # P5
    a, r = _curve(72)
    law = PitchCurveLaw(a, r, 12)
    assert law.n == 12
    with pytest.raises(InputError, match=r"driver_turns.*1 \.\. 12"):
        PitchCurveLaw(a, r, 13)


# ---- ratio_laws ------------------------------------------------------------------------------------------------

def test_lobes_up_to_12_accepted_and_13_refused():  # R1
    assert FourierLaw(12, (0.001,), ()).n == 12
    assert EllipticalLaw(0.2, 12).k == 12
    with pytest.raises(InputError, match=r"driver_turns.*1 \.\. 12"):
        FourierLaw(13, (0.001,), ())
    with pytest.raises(InputError, match=r"driver_turns"):
        EllipticalLaw(0.2, 13)


def test_circle_is_the_elliptical_law_of_e_zero():  # R2
    law = EllipticalLaw(0.0)
    x = np.linspace(-4.0, 4.0, 41)
    assert np.allclose(law.U(x), 1.0, rtol=0, atol=1e-12)  # a circle about its centre: 1:1 throughout
    assert np.allclose(law.theta(x), x, rtol=0, atol=1e-12)


def test_eccentricity_limit_0_9_accepted_and_beyond_refused():  # R3
    law = EllipticalLaw(0.9)
    # 1:1 ellipse about its focus: U ranges over (1 - e)/(1 + e) .. (1 + e)/(1 - e) = 1/19 .. 19
    assert law.U_max == pytest.approx(19.0, rel=1e-6)
    with pytest.raises(InputError, match=r"eccentricity.*<= 0\.9"):
        EllipticalLaw(0.9 + 1e-9)


def test_fourier_scalar_derivatives_are_those_of_u():  # R10
    law = FourierLaw(2, (0.03, -0.01), (0.02, 0.0, 0.005))
    h = 1e-5
    for phi in (-1.1, -0.3, 0.0, 0.45, 1.2, 2.9):
        U, dU, d2U = law.U_derivs1(phi)
        Up, Um = law.U_derivs1(phi + h)[0], law.U_derivs1(phi - h)[0]
        assert dU == pytest.approx((Up - Um) / (2 * h), abs=1e-7)
        assert d2U == pytest.approx((Up - 2 * U + Um) / h ** 2, abs=1e-4)
        # the small-array path (<= 8 points) agrees with the large-array one
        big = np.full(20, phi)
        assert float(law.dU_dphi(np.array([phi]))[0]) == pytest.approx(float(law.dU_dphi(big)[0]), abs=1e-12)
        assert float(law.d2U_dphi2(np.array([phi]))[0]) == pytest.approx(float(law.d2U_dphi2(big)[0]), abs=1e-10)
