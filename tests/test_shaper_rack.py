"""A shaper is not refused for its rack's fillet radius (gears/cutters.py, ``shaper_rack``): that radius - which a
shaper never uses, rounding its tip by its own rho_a0* - is ISO 53's 0.38 where the rack's tip land holds it (so every
shaper made before is the same) and the largest that fits beyond (alpha >= 24 deg at a depth of 1.25 m).  What still
refuses a steep shaper is its own geometry: its tip rounds meeting (28 deg, rho_a0* 0.1) or no tip land at all
(tan alpha >= pi / 5: 32.1 deg)."""

from __future__ import annotations

import math

import pytest

from propulsor.errors import InputError
from propulsor.gears.catalogue import catalogue_shaper
from propulsor.gears.cutters import ShaperCutter, shaper_rack
from propulsor.gears.involute import BasicRack


@pytest.mark.parametrize("deg", [14.5, 20.0, 22.5])
def test_below_24_degrees_the_rack_is_the_one_shapers_had(deg):
    a = math.radians(deg)
    assert shaper_rack(a, 1.0, 0.25) == BasicRack(alpha=a, c_star=0.25)


@pytest.mark.parametrize("deg", [24.0, 25.0, 26.5])
def test_from_24_degrees_the_fillet_is_the_largest_the_tip_land_holds(deg):
    a = math.radians(deg)
    with pytest.raises(InputError, match="tool tip land"):
        BasicRack(alpha=a, c_star=0.25)                       # what shapers were given: refused
    r = shaper_rack(a, 1.0, 0.25)
    # the tip land of a rack of depth h_a* + c* = 1.25: rho_max = (pi/4 - 1.25 tan a) cos a / (1 - sin a)
    assert r.rho_f_star == pytest.approx((math.pi / 4 - 1.25 * math.tan(a)) * math.cos(a) / (1 - math.sin(a)),
                                         rel=1e-12)
    assert r.rho_f_star < 0.38
    sh = ShaperCutter(25, 3.0, 0.0, r)                         # a shaper of own teeth and shift
    assert sh.r_a0 == pytest.approx(3.0 * 25 / 2 + 1.25 * 3.0, rel=1e-12)
    assert sh.tip_round is not None


def test_a_catalogue_shaper_at_25_degrees_is_made():
    sh = catalogue_shaper(50.0, 2.0, math.radians(25.0))
    assert sh.rack.alpha == pytest.approx(math.radians(25.0))
    assert sh.tip_round is not None


def test_steeper_shapers_are_refused_for_their_own_tooth_naming_it():
    with pytest.raises(InputError, match="rho_a0_star = 0.1: tip rounds of the shaper tooth overlap"):
        ShaperCutter(25, 3.0, 0.0, shaper_rack(math.radians(28.0), 1.0, 0.25)).tip_round
    with pytest.raises(InputError, match=r"c_star = 0.25: tool tooth has no tip land left"):
        shaper_rack(math.radians(33.0), 1.0, 0.25)
