"""Involute spline (GOST 6033-80 / ISO 4156, 30°, flat root) and its hub outline."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from propulsor.errors import InputError
from propulsor.geometry.involute_spline import InvoluteSpline
from propulsor.geometry.profile import Arc, Profile, Spline


def test_seed_004_carrier_spline_crushing_numbers():
    # seed 004 §4.3: "Эв. 120 x 3.5 x 34": h = 0.8 m = 2.8, d_sr = D − 1.1 m = 116.15,
    # S_u = 0.5 d_sr h z = 5528.74, σ = M / (S_u L) = 117.164 MPa with M = 90 687.503 N m, L = 140 mm
    s = InvoluteSpline(120.0, 3.5, 34)
    assert s.h_work == pytest.approx(2.8)
    assert s.d_mean == pytest.approx(116.15)
    assert round(s.S_F, 2) == 5528.74
    assert round(s.crushing_stress(90687.503e3, 140.0), 3) == 117.164


def test_gost_6033_diameters():
    s = InvoluteSpline(65.0, 2.0, 31)
    assert s.x == pytest.approx(0.2)                       # (65 − 62 − 2.2) / 4
    assert s.d_a_shaft == pytest.approx(64.6)              # D − 0.2 m
    assert s.D_a_hub == pytest.approx(61.0)                # D − 2 m
    assert s.D_f_hub == pytest.approx(2.0 * (31 + 1.5 + 0.4))
    assert s.e == pytest.approx(math.pi + 2 * 0.2 * 2 * math.tan(math.radians(30)))
    # ISO 4156 basic (x = 0): D_ee = m (z + 1), D_ei = m (z + 1.5), space width π m / 2
    iso = InvoluteSpline(2.0 * 31 + 1.1 * 2.0, 2.0, 31)
    assert iso.x == pytest.approx(0.0, abs=1e-12)
    assert iso.D_f_hub == pytest.approx(2.0 * 32.5) and iso.e == pytest.approx(math.pi)


def test_hub_outline_is_exact():
    s = InvoluteSpline(65.0, 2.0, 31)
    loop = s.hub_hole_loop()
    assert loop.is_closed(1e-9) and len(loop.segments) == 4 * 31
    # space width on the pitch circle = e: the lower flank of space 0 crosses r = d/2 at −e/d
    flank = loop.segments[0]
    assert isinstance(flank, Spline)
    P = flank.sample(1e-6)
    r = np.hypot(P[:, 0], P[:, 1])
    a = np.arctan2(P[:, 1], P[:, 0])
    assert np.interp(s.d / 2, r, a) == pytest.approx(-s.e / s.d, abs=1e-6)
    # every flank point lies on the involute of the base circle: polar angle = −ψ(r)
    assert a == pytest.approx(-s.psi(r), abs=1e-5 / 30.0)
    # radii: the arcs are the minor and major circles
    arcs = [g for g in loop.segments if isinstance(g, Arc)]
    assert {round(g.radius, 9) for g in arcs} == {s.D_a_hub / 2, s.D_f_hub / 2}
    # area of the hole by the exact arcs and the sampled flanks: between the minor and major circles
    A = Profile(loop).area(1e-4)
    assert math.pi * (s.D_a_hub / 2) ** 2 < A < math.pi * (s.D_f_hub / 2) ** 2


@settings(max_examples=40, deadline=None)
@given(m=st.sampled_from([1.25, 2.0, 3.0, 5.0]), z=st.integers(10, 60), x=st.floats(-0.3, 0.8))
def test_any_valid_spline_closes(m, z, x):
    D = m * z + 1.1 * m + 2 * x * m
    try:
        s = InvoluteSpline(D, m, z)
    except InputError:
        return
    loop = s.hub_hole_loop(tol=1e-4)
    assert loop.is_closed(1e-8)
    assert s.hub_tooth_angle(s.D_a_hub / 2) > 0 and float(s.psi(s.D_f_hub / 2)) > 0


@pytest.mark.parametrize("D, m, z, name", [
    (65.0, 2.0, 40, "spline_D"),      # x far below −0.5
    (65.0, 2.0, 5, "spline_z"),
    (float("nan"), 2.0, 31, "spline_D"),
    (65.0, 0.0, 31, "spline_m"),
])
def test_bad_spline(D, m, z, name):
    with pytest.raises(InputError) as e:
        InvoluteSpline(D, m, z)
    assert e.value.parameter == name
