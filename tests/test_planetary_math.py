"""Planetary set conditions (gears/planetary.py), seed 004 ch. 4 eq. 30–35, on the thesis set
(z 16/20/56, m 10, x 0.5/0.5/1.417, shaper z0 14 / x0 0.04) and variations."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from propulsor.errors import InputError
from propulsor.gears.gear_pair import GearPair
from propulsor.gears.involute import SpurGear
from propulsor.gears.planetary import Condition, PlanetarySet
from propulsor.policy import PLANETARY_COAXIALITY_TOL_MM

THESIS = PlanetarySet()  # printed ring shift 1.417
FIXED = THESIS.with_coaxial_ring()


def test_willis_ratio_eq32():
    assert THESIS.ratio == 4.5  # 1 + 56/16
    assert THESIS.z_ring / THESIS.z_sun == 3.5


def test_thesis_set_is_not_coaxial_and_the_fix_is_x3_1_5():
    """Sun–planet a_w = 188.643 (Table 6); planet–ring with x3 = 1.417 gives 187.997 (Table 7 prints 188):
    the carrier cannot sit on both.  x3 = 1.5 restores coaxiality (z3 − z2 = z1 + z2, so the internal
    mesh needs the same shift sum: x3 − x2 = x1 + x2)."""
    assert THESIS.a_w == pytest.approx(188.643, abs=5e-4)
    assert THESIS.mesh_planet_ring.a_w == pytest.approx(187.997, abs=5e-4)
    assert THESIS.coaxiality_mismatch == pytest.approx(-0.6457, abs=1e-4)
    assert THESIS.a_w - 188.0 == pytest.approx(0.643, abs=5e-4)  # against the printed 188
    assert THESIS.ring_shift_for_coaxiality() == pytest.approx(1.5, abs=1e-12)
    assert abs(FIXED.coaxiality_mismatch) < 1e-9
    assert FIXED.mesh_planet_ring.alpha_w == pytest.approx(FIXED.mesh_sun_planet.alpha_w, abs=1e-14)
    # the failing record carries the numbers
    coax = {c.name: c for c in THESIS.conditions()}["coaxiality"]
    assert not coax.passed and coax.value == pytest.approx(0.6457, abs=1e-4)
    assert coax.limit == PLANETARY_COAXIALITY_TOL_MM and coax.unit == "mm"


def test_only_coaxiality_fails_for_the_thesis_set_and_nothing_for_the_fixed_one():
    assert [c.name for c in THESIS.failures()] == ["coaxiality"]
    assert FIXED.failures() == [] and FIXED.valid
    assert not THESIS.valid


def test_neighbour_condition_eq30_in_the_seed_form_for_unshifted_gears():
    """Zero shifts: a_w = m(z1+z2)/2, d_a,planet = m(z2+2): the gap is m(z1+z2) sin(π/k) − m(z2+2) and the
    condition is the seed's sin(π/k) > (z2+2)/(z1+z2)."""
    for k in (3, 4, 5, 6):
        s = PlanetarySet(x_sun=0.0, x_planet=0.0, x_ring=0.0, n_planets=k)
        gap = 10 * 36 * math.sin(math.pi / k) - 10 * 22
        assert s.neighbour_gap == pytest.approx(gap, abs=1e-9)
        assert (s.neighbour_gap > 0) == (math.sin(math.pi / k) > 22 / 36)


def test_neighbour_condition_with_the_shortened_planet_tip():
    # planet tip as made: shortened in the sun mesh (227.286), unshortened (230) in the ring mesh
    assert THESIS.d_a_planet == pytest.approx(227.286, abs=5e-4)
    assert THESIS.mesh_planet_ring.d_a1 == pytest.approx(230.0, abs=1e-9)
    assert THESIS.neighbour_gap == pytest.approx(2 * 188.64294 * math.sin(math.pi / 4) - 227.28587, abs=1e-4)
    assert PlanetarySet(n_planets=3).neighbour_gap == pytest.approx(99.453, abs=5e-4)
    five = {c.name: c for c in PlanetarySet(n_planets=5).conditions()}["neighbour"]
    assert not five.passed and five.value == pytest.approx(-5.523, abs=5e-4)


def test_thesis_eq34_numbers_are_wrong_but_the_condition_holds():
    """Eq. 34 prints 0.866 > (20+2)/(16+36) = 0.4231 for k = 4: 0.866 is sin(π/3), and 16+36 is not z1+z2.
    Right: sin(π/4) = 0.7071 > 22/36 = 0.6111 — still satisfied."""
    assert math.sin(math.pi / 3) == pytest.approx(0.866, abs=5e-4)
    assert 22 / 52 == pytest.approx(0.4231, abs=5e-5)
    assert math.sin(math.pi / 4) > 22 / 36 == pytest.approx(0.6111, abs=5e-5)
    assert PlanetarySet(x_sun=0.0, x_planet=0.0, x_ring=0.0, n_planets=4).neighbour_gap > 0


@pytest.mark.parametrize("k, whole", [(1, True), (2, True), (3, True), (4, True), (5, False), (6, True),
                                      (7, False), (8, True), (9, True)])
def test_assembly_condition_eq31(k, whole):
    s = PlanetarySet(n_planets=k)
    assert s.assembly_ok is whole
    rec = {c.name: c for c in s.conditions()}["assembly"]
    assert rec.passed is whole and rec.value == pytest.approx(72 / k)


@given(z1=st.integers(12, 40), z3=st.integers(40, 120), k=st.integers(1, 8), p=st.integers(0, 5))
@settings(max_examples=100, deadline=None)
def test_eq31_with_any_p_is_the_whole_quotient_rule(z1, z3, k, p):
    """z1 i_1H (1 + k p)/k whole ⇔ (z1 + z3)/k whole (i_1H = 1 + z3/z1): p drops out."""
    lhs_whole = ((z1 + z3) * (1 + k * p)) % k == 0
    assert lhs_whole == ((z1 + z3) % k == 0)


def test_contact_ratios_of_both_meshes_use_the_planet_as_made():
    sp, pr = THESIS.mesh_sun_planet, THESIS.mesh_planet_ring
    assert THESIS.epsilon_alpha_sun_planet == pytest.approx(sp.epsilon_alpha(), abs=1e-12)  # both tips shortened
    assert THESIS.epsilon_alpha_sun_planet == pytest.approx(1.2270, abs=1e-4)
    # in the ring mesh the planet's tip is the shortened 227.286, not the nominal 230
    assert THESIS.epsilon_alpha_planet_ring == pytest.approx(pr.epsilon_alpha(227.28587198, None), abs=1e-8)
    assert THESIS.epsilon_alpha_planet_ring < pr.epsilon_alpha()
    assert THESIS.epsilon_alpha_planet_ring == pytest.approx(1.3481, abs=1e-4)


def test_condition_records_are_complete():
    recs = FIXED.conditions()
    assert all(isinstance(c, Condition) for c in recs)
    names = [c.name for c in recs]
    assert len(names) == len(set(names))
    for must in ("willis_ratio", "coaxiality", "neighbour", "assembly", "contact_ratio_sun_planet",
                 "contact_ratio_planet_ring", "undercut_sun", "undercut_planet", "tip_thickness_sun",
                 "tip_thickness_planet", "tip_thickness_ring", "tip_interference_planet_ring",
                 "ring_tip_cut_by_shaper"):
        assert must in names
    for c in recs:
        assert isinstance(c.passed, bool) and math.isfinite(c.value) and math.isfinite(c.limit)
        assert c.unit and c.message


def test_failing_sets_are_detected():
    # undercut sun (x = 0 on 12 teeth) with involute interference and a ring tip cut by the shaper
    s = PlanetarySet(z_sun=12, z_planet=18, z_ring=48, x_sun=0.0, x_planet=0.0, x_ring=0.0)
    names = {c.name for c in s.failures()}
    assert {"undercut_sun", "involute_interference_sun_planet_pinion"} <= names
    assert "coaxiality" not in names
    # too much shift on the planet: contact ratio of the sun mesh below 1.2
    s = PlanetarySet(x_sun=0.8, x_planet=0.6).with_coaxial_ring()
    assert [c.name for c in s.failures()] == ["contact_ratio_sun_planet"]
    # thin sun tip after shortening (s_na < 0.4 m)
    s = PlanetarySet(x_sun=0.8, x_planet=0.0).with_coaxial_ring()
    assert [c.name for c in s.failures()] == ["tip_thickness_sun"]
    # target ratio check (seed condition b)
    assert not {c.name: c for c in PlanetarySet(ratio_target=4.6, ratio_tol=0.05).conditions()}["willis_ratio"].passed
    assert {c.name: c for c in PlanetarySet(ratio_target=4.52, ratio_tol=0.05).conditions()}["willis_ratio"].passed


def test_ring_from_the_set_matches_a_standalone_pair():
    pr = GearPair(SpurGear(20, 10.0, 0.5), SpurGear(56, 10.0, 1.5, internal=True, z0=14, x0=0.04))
    assert FIXED.mesh_planet_ring.a_w == pytest.approx(pr.a_w, abs=1e-12)
    assert FIXED.d_a_ring == pytest.approx(pr.d_a2, abs=1e-12)
    assert FIXED.ring.d_f == pytest.approx(pr.gear2.d_f, abs=1e-12)


@pytest.mark.parametrize("kwargs, param", [
    (dict(n_planets=0), "n_planets"),
    (dict(n_planets=2.5), "n_planets"),
    (dict(n_planets=float("nan")), "n_planets"),
    (dict(m=-10.0), "m"),
    (dict(z_ring=20), "z_ring"),
    (dict(b_planet=0.0), "b_planet"),
    (dict(ratio_target=4.5, ratio_tol=-1.0), "ratio_tol"),
    (dict(z_sun=15.5), "z"),
    (dict(x_ring=float("nan")), "x"),
])
def test_invalid_sets_raise_input_error(kwargs, param):
    with pytest.raises(InputError) as e:
        PlanetarySet(**kwargs)
    assert e.value.parameter == param
