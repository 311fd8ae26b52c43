"""A profile moved or scaled keeps its loops' sense without sampling them again (geometry/profile.py
``Profile.transformed`` / ``scaled``): the outer loop counter-clockwise and every hole clockwise, as a profile built anew
from the same loops orients them, on a real generated gear (B-spline flanks, arcs, a bore) and a square with a spline
side, at every quarter turn and between."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.geometry.profile import Line, Loop, Profile, Spline, circle_loop


def _square_with_a_spline_side() -> Profile:
    # a square whose top side is a B-spline bulging up, with a round hole; given clockwise, with a CCW hole:
    # the profile turns both
    bulge = Spline(np.array([0, 0, 0, 0, 1, 1, 1, 1.0]), np.array([[10, 10], [7, 14], [3, 14], [0, 10.0]]))
    outer = Loop([Line((0, 0), (0, 10)), bulge.reversed(), Line((10, 10), (10, 0)), Line((10, 0), (0, 0))])
    return Profile(outer, [circle_loop(2.0, (5, 5), ccw=True)], "square")


@pytest.fixture(scope="module")
def gear() -> Profile:
    """The driven wheel of the two-lobe elliptical pair as designed (B-spline flanks and arcs, a bore)."""
    import propulsor

    return propulsor.part(Path(__file__).resolve().parents[1] / "parts" / "ncg_elliptical_2lobe.toml").shapes.profiles["driven"][0]


def _senses(p: Profile) -> tuple:
    return (p.outer.signed_area() > 0, *(h.signed_area() < 0 for h in p.holes))


@pytest.mark.parametrize("angle", [0.0, 0.3, 0.5 * math.pi, 2.0, math.pi, 1.5 * math.pi, -0.7, 7.0])
def test_a_moved_profile_keeps_its_loops_sense_as_one_built_anew(angle):
    p = _square_with_a_spline_side()
    assert _senses(p) == (True, True)
    q = p.transformed(angle, (120.0, -35.5))
    assert _senses(q) == (True, True)
    anew = Profile(q.outer, list(q.holes), q.name)  # oriented from the samples, as before
    assert anew.outer is q.outer and all(a is b for a, b in zip(anew.holes, q.holes)) and q.name == "square"
    for k in (0.1, 1.0, 25.0):
        s = p.scaled(k)
        assert _senses(s) == (True, True)
        assert math.isclose(s.area(1e-7), k * k * p.area(1e-7), rel_tol=1e-6)


def test_scale_must_be_positive():
    with pytest.raises(InputError, match="k"):
        _square_with_a_spline_side().scaled(0.0)


def test_a_generated_gear_moved_keeps_its_sense_and_its_points(gear):
    assert len(gear.holes) == 1 and any(isinstance(g, Spline) for g in gear.outer.segments)
    assert _senses(gear) == (True, True)
    for angle in (0.25, 0.5 * math.pi, math.pi, 4.0):
        q = gear.transformed(angle, (3.0, -4.0))
        assert _senses(q) == (True, True)
        c, s = math.cos(angle), math.sin(angle)
        want = gear.outer.polyline(0.01) @ np.array([[c, s], [-s, c]]) + np.array([3.0, -4.0])
        got = q.outer.polyline(0.01)
        assert got.shape == want.shape and np.allclose(got, want, atol=1e-9)
    assert _senses(gear.scaled(0.5)) == (True, True)
