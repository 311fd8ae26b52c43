"""A law from the driver's pitch curve (laws/pitch_curve_law.py): an ellipse given as a curve is the
elliptical law; the curve in contact is the one given; curves through the axis are refused by row."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.gears.noncircular import PitchCurves, centre_distance
from propulsor.laws.pitch_curve_law import PitchCurveLaw, parse_pitch_curve
from propulsor.laws.ratio_laws import EllipticalLaw
from propulsor.params import load_params
from propulsor.parts.noncircular_pair import NoncircularPairParams
from propulsor.parts.noncircular_pair.design import _law


def _ellipse(e=0.3, p=30.0, step=2.0):
    a = np.arange(0.0, 360.0, step)
    return tuple(a), tuple(p / (1 + e * np.cos(np.radians(a))))


@pytest.mark.parametrize("k", [1, 2])
def test_an_ellipse_about_its_focus_given_as_a_curve_is_the_elliptical_law(k):
    e, p = 0.3, 30.0
    law, ell = PitchCurveLaw(*_ellipse(e, p), k), EllipticalLaw(e, k)
    assert law.L0 == pytest.approx(p / ell.q, rel=1e-10)  # the curve's own centre distance by closure
    x = np.linspace(-4.0, 4.0, 801)
    assert np.allclose(law.U(x), ell.U(x), rtol=0, atol=1e-9)
    assert np.allclose(law.theta(x), ell.theta(x), rtol=0, atol=1e-10)
    assert centre_distance(law, 2.5, 30 * k) == pytest.approx(centre_distance(ell, 2.5, 30 * k), rel=1e-10)


def test_the_driver_curve_in_contact_is_the_curve_given():
    a = np.arange(0.0, 360.0, 5.0)
    r = 40 + 5 * np.cos(np.radians(a)) + 3 * np.sin(2 * np.radians(a))  # not symmetric
    law = PitchCurveLaw(tuple(a), tuple(r), 1)
    pc = PitchCurves(law, law.L0)
    th = np.linspace(0.0, 2 * math.pi, 73)
    # the driver's angle theta turns against the body's angle a: r(theta) = r_given(-theta)
    given = 40 + 5 * np.cos(-th) + 3 * np.sin(-2 * th)
    assert np.allclose(pc.driver_radius(th), given, rtol=0, atol=1e-6)


def test_a_curve_through_the_axis_is_refused_naming_the_row():
    a, r = _ellipse()
    r = list(r)
    r[7] = 0.0
    with pytest.raises(InputError, match=r"^pitch_curve_file row 8 radius_mm = 0\.0: .*radius > 0 mm"):
        PitchCurveLaw(a, tuple(r), 1)


def test_angles_not_increasing_or_beyond_one_turn_are_refused():
    a, r = _ellipse()
    bad = list(a)
    bad[4] = bad[3]
    with pytest.raises(InputError, match=r"^pitch_curve_file row 5 angle_deg = 6\.0: must be strictly increasing"):
        PitchCurveLaw(tuple(bad), r, 1)
    with pytest.raises(InputError, match=r"^pitch_curve_file row 181 angle_deg = 400\.0: the rows span one turn"):
        PitchCurveLaw(a + (400.0,), r + (30.0,), 1)


def test_parse_refuses_a_wrong_header():
    with pytest.raises(InputError, match="header must be angle_deg,radius_mm"):
        parse_pitch_curve("theta,r\n0,1\n")


def test_part_file_law_pitch_curve_reads_the_file_beside_it(tmp_path):
    a, r = _ellipse()
    rows = "".join(f"{float(x)!r},{float(y)!r}\n" for x, y in zip(a, r))
    (tmp_path / "c.csv").write_text("angle_deg,radius_mm\n" + rows)
    p = load_params(NoncircularPairParams, dict(law="pitch_curve", pitch_curve_file="c.csv", driver_turns=2,
                                                driven_teeth=40, compare_methods=False))
    law = _law(p, tmp_path / "part.toml")
    assert (law.kind, law.n, law.periods) == ("pitch_curve", 2, 2)
    with pytest.raises(InputError, match=r'^pitch_curve_file = .*: is a key of law = "pitch_curve"'):
        load_params(NoncircularPairParams, dict(pitch_curve_file="c.csv"))
