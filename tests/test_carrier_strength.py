"""Bearings (ISO 76, seed 004 eq. 48-50, Table 8), spline (eq. 51-53) and carrier shaft (§4.3):
every printed number, or its contradiction with numbers."""

import math

import pytest

from propulsor.errors import InputError
from propulsor.geometry.involute_spline import InvoluteSpline
from propulsor.laws.carrier_strength import (CARRIER_BEARING_004, PLANET_BEARING_004, shaft_equivalent_stress,
                                             spline_allowable, spline_crushing_stress,
                                             static_capacity_radial_roller)


def test_eq48_planet_bearing_C0_and_safety_of_table8():
    assert PLANET_BEARING_004.C0 == pytest.approx(128700.0, abs=1e-6)          # Table 8: 128 700 N
    S0 = PLANET_BEARING_004.S0(92000.0)
    assert math.floor(S0 * 100) / 100 == 1.39                                  # printed 1,39 (1.3989 truncated)
    assert round(S0, 2) == 1.40


def test_eq49_carrier_bearing_C0_differs_from_table8():
    C0 = CARRIER_BEARING_004.C0
    assert round(C0) == 1415838                                                # eq. 49 with its printed inputs
    assert (C0 - 1398120.0) / 1398120.0 == pytest.approx(0.01267, abs=1e-5)    # Table 8 lists 1 398 120 N
    assert round(1398120.0 / 858508.0, 3) == 1.629                             # Table 8's safety: its C0 / its load
    assert round(C0 / 858508.0, 3) == 1.649
    assert round(1398120.0 / 522000.0, 2) == 2.68                              # with the R = 522 000 N of the text


def test_iso76_formula_properties():
    # contact angle 0 and rollers at the pitch circle's limit
    assert static_capacity_radial_roller(10, 100, 1, 10, 10, 0.0) == pytest.approx(44 * 0.9 * 10 * 10 * 10)
    with pytest.raises(InputError, match="D_pw"):
        static_capacity_radial_roller(10, 0, 1, 10, 10, 0.0)


def test_eq51_53_spline_as_printed_and_with_the_hub_steel():
    s = InvoluteSpline(120.0, 3.5, 34)
    assert s.h_work == pytest.approx(2.8)
    assert s.d_mean == pytest.approx(116.15)
    assert round(s.S_F, 2) == 5528.74
    assert round(2.65 * 1 * 1.4, 2) == 3.71                                    # eq. 52
    allow_printed = spline_allowable(785.0, 1.4, 2.65, 1.0, 1.4)
    assert round(allow_printed, 3) == 151.136
    sigma = spline_crushing_stress(90687.503, s.S_F, 140.0)
    assert round(sigma, 3) == 117.164
    assert round(allow_printed / sigma, 2) == 1.29
    # the printed "·2π" (with 3.14) would give 0.736 MPa
    assert round(90687.503 * 2 * 3.14 / (5528.74 * 140), 3) == 0.736
    # the hub (the weaker part the check is said to be made for) is 630 MPa
    allow_hub = spline_allowable(630.0, 1.4, 2.65, 1.0, 1.4)
    assert round(allow_hub, 3) == 121.294
    assert round(allow_hub / sigma, 3) == 1.035


def test_shaft_equivalent_stress_plus_not_times():
    sh = shaft_equivalent_stress(303896.739, 222.0, 169646.003, 90687.503, 272271.363, 970.0)
    assert round(sh.sigma_b, 3) == 397.681
    assert round(sh.tau, 3) == 333.078
    assert round(sh.sigma_eq, 3) == 775.831
    assert round(sh.margin, 2) == 1.25
    assert math.sqrt(397.681 ** 2 * 4 * 333.078 ** 2) == pytest.approx(264918, rel=1e-5)   # printed "σ²·4τ²"
    # W_i is the solid 120 mm section; W_k is not its polar modulus
    assert round(math.pi * 120 ** 3 / 32, 3) == 169646.003
    assert round(2 * 169646.003, 3) == 339292.006
    assert round((272271.363 * 16 / math.pi) ** (1 / 3), 3) == 111.513


def test_table8_second_carrier_bearing_224_cannot_have_the_printed_C0():
    """Table 8 lists bearing 224 (GOST 8338: single-row ball bearing 120 × 215 × 40) with C0 = 706 336 N and no
    load; the text gives no inputs for it ("по методике").  ISO 76 for radial ball bearings, C0 = f0·i·Z·D_w²·cos α:
    with a generous f0 = 20 (ISO 76's table for radial ball bearings stays below it), one row, balls as large as the
    whole radial section (D_w = (215 − 120)/2) and as many as fit the pitch circle, C0 stays near 500 kN."""
    d, D = 120.0, 215.0
    D_w = (D - d) / 2.0
    D_pw = (D + d) / 2.0
    Z_max = math.pi * D_pw / D_w
    bound = 20.0 * 1 * Z_max * D_w ** 2
    assert round(bound) == 499906
    assert bound < 706336.0                  # the printed C0 needs a roller bearing (e.g. 2224 of GOST 8328)
    # the roller formula of eq. 48 reaches it in the same envelope (width 40 mm): a roller bearing fits the number
    roller = static_capacity_radial_roller(30.0, D_pw, 1, int(math.pi * D_pw / 30.0), 40.0, 0.0)
    assert roller > 706336.0
