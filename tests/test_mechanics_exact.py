"""Exact values and refusals of the mechanics laws (mutation target ``mechanics``): every refusal's message in
full, both sides of every limit, formula values computed independently here.  Every law or object is built inside
its test (a law built at collection cannot kill a mutant of its construction)."""

import math

import numpy as np
import pytest

from propulsor.errors import InputError


def refused(fn, *args, **kwargs) -> str:
    """The message of the InputError ``fn(*args, **kwargs)`` raises."""
    with pytest.raises(InputError) as e:
        fn(*args, **kwargs)
    return str(e.value)


# ============================================================== carrier_strength.py (seed 004 eq. 48-53, §4.3)

def test_carrier_static_capacity_refuses_each_input_by_name_and_unit():
    from propulsor.laws.carrier_strength import static_capacity_radial_roller as c0

    good = dict(D_we=15.0, D_pw=80.0, i=1, Z=16, L_we=15.0, alpha_rad=0.0)
    for name, unit in (("D_we", " mm"), ("D_pw", " mm"), ("i", ""), ("Z", ""), ("L_we", " mm")):
        assert refused(c0, **{**good, name: 0}) == f"{name} = 0: must be > 0{unit}"
        assert refused(c0, **{**good, name: -1.0}) == f"{name} = -1.0: must be > 0{unit}"
    # eq. 48 with the planet bearing's rollers: 44 (1 - 15/80) 1 16 15 15 = 128 700 N (Table 8)
    assert c0(**good) == pytest.approx(44 * (1 - 15 / 80) * 16 * 15 * 15, rel=1e-15)
    assert c0(**good) == pytest.approx(128700.0, rel=1e-15)


def test_carrier_bearing_safety_refuses_a_load_of_zero():
    from propulsor.laws.carrier_strength import PLANET_BEARING_004

    assert refused(PLANET_BEARING_004.S0, 0.0) == "bearing_load = 0.0: must be > 0 N"
    assert PLANET_BEARING_004.S0(1e-9) == pytest.approx(128700.0 / 1e-9)


def test_spline_allowable_each_factor_divides():
    from propulsor.laws.carrier_strength import spline_allowable

    # eq. 52-53 with every factor != 1: sigma_T / (n K_pr K_z K_p)
    assert spline_allowable(785.0, 1.4, 2.65, 1.2, 1.4) == pytest.approx(785.0 / (1.4 * 2.65 * 1.2 * 1.4), rel=1e-15)
    assert spline_allowable(630.0, 1.5, 1.1, 2.0, 1.3) == pytest.approx(630.0 / (1.5 * 1.1 * 2.0 * 1.3), rel=1e-15)


def test_spline_crushing_stress_refusals():
    from propulsor.laws.carrier_strength import spline_crushing_stress

    assert refused(spline_crushing_stress, 100.0, 0.0, 140.0) == "S_u = 0.0: must be > 0"
    assert refused(spline_crushing_stress, 100.0, 5528.74, 0.0) == "spline_length = 0.0: must be > 0 mm"
    assert spline_crushing_stress(100.0, 50.0, 4.0) == pytest.approx(100.0 * 1e3 / (50.0 * 4.0), rel=1e-15)


def test_shaft_equivalent_stress_refusals():
    from propulsor.laws.carrier_strength import shaft_equivalent_stress

    assert refused(shaft_equivalent_stress, 1.0, 1.0, 0.0, 1.0, 1.0, 970.0) == "W_i = 0.0: must be > 0 mm³"
    assert refused(shaft_equivalent_stress, 1.0, 1.0, 1.0, 1.0, -2.0, 970.0) == "W_k = -2.0: must be > 0 mm³"
    sh = shaft_equivalent_stress(1000.0, 10.0, 100.0, 2.0, 40.0, 970.0)
    assert (sh.sigma_b, sh.tau) == (100.0, 50.0)
    assert sh.sigma_eq == pytest.approx(math.sqrt(100.0 ** 2 + 4 * 50.0 ** 2), rel=1e-15)
    assert sh.margin == pytest.approx(970.0 / math.sqrt(20000.0), rel=1e-15)
