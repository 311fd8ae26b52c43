"""Drive law of the driving wheel-walking propulsor (seeds 000, 002; SPEC §3)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, assume
from hypothesis import strategies as st
from scipy.integrate import quad

from propulsor.errors import InputError
from propulsor.laws.walking import SEED_000, SEED_002, WalkingLaw, leg_index, wrap_leg


def test_wrap_into_leg():
    phi = np.array([0.0, math.pi / 4, -math.pi / 4, math.pi / 2, 3.0, -3.0, 2 * math.pi])
    w = wrap_leg(phi)
    assert np.all(w >= -math.pi / 4) and np.all(w < math.pi / 4)
    assert np.allclose(w + leg_index(phi) * math.pi / 2, phi, atol=1e-15)
    assert wrap_leg(math.pi / 4) == pytest.approx(-math.pi / 4)


def test_seed_constants():
    law = WalkingLaw(**SEED_000)
    assert law.A == 320.0 and law.Y01 == 320.0
    # seed 000 eq. 10: u = 2 pi A / (A pi + 6 b)
    assert law.u == pytest.approx(2 * math.pi * 320 / (320 * math.pi + 600), rel=1e-15)
    law2 = WalkingLaw(**SEED_002)
    assert law2.A == 286.5
    assert law2.u == pytest.approx(4 * math.pi * 286.5 / (286.5 * math.pi + 300), rel=1e-15)


@pytest.mark.parametrize("params", [SEED_000, SEED_002])
def test_closure_n_whole_turns(params):
    law = WalkingLaw(**params)
    assert abs(law.theta(2 * math.pi) - 2 * math.pi * law.n) < 1e-9
    # every leg gives n pi/2 of the driver
    phis = np.linspace(-3, 3, 13)
    assert np.allclose(law.theta(phis + math.pi / 2) - law.theta(phis), law.n * math.pi / 2, atol=1e-12)
    # independent: numerical integral of U over the turn, split at the hand-overs
    edges = [0, math.pi / 4, 3 * math.pi / 4, 5 * math.pi / 4, 7 * math.pi / 4, 2 * math.pi]
    total = sum(quad(lambda p: float(law.U(p)), a, b, epsabs=1e-13, epsrel=1e-13)[0]
                for a, b in zip(edges[:-1], edges[1:]))
    assert abs(total - 2 * math.pi * law.n) < 1e-9


def test_trap1_unwrapped_law_gives_125_turns():
    """SPEC Trap 1: cos 2 phi over the whole turn gives 1.25 driver turns in seed 000, the periodic law 2."""
    law = WalkingLaw(**SEED_000)
    wrong = law.theta_unwrapped(2 * math.pi) / (2 * math.pi)
    right = law.theta(2 * math.pi) / (2 * math.pi)
    assert wrong == pytest.approx(1.2525, abs=5e-5)
    assert right == pytest.approx(2.0, abs=1e-12)
    # within the first leg both readings agree (seed 000 eq. 11)
    phi = np.linspace(-math.pi / 4, math.pi / 4 - 1e-9, 50)
    assert np.allclose(law.theta(phi), law.theta_unwrapped(phi), atol=1e-13)
    eq11 = math.pi * (2 * 320 * phi + 300 * np.sin(2 * phi)) / (320 * math.pi + 600)
    assert np.allclose(law.theta(phi), eq11, atol=1e-13)


def test_theta_is_integral_of_U_fd():
    law = WalkingLaw(**SEED_002)
    phi = np.linspace(0.01, 2 * math.pi - 0.01, 400)
    phi = phi[np.abs(wrap_leg(phi - math.pi / 4)) > 1e-3]  # away from the corners
    h = 1e-6
    fd = (law.theta(phi + h) - law.theta(phi - h)) / (2 * h)
    assert np.allclose(fd, law.U(phi), rtol=1e-8)
    fd2 = (law.U(phi + h) - law.U(phi - h)) / (2 * h)
    assert np.allclose(fd2, law.dU_dphi(phi), atol=1e-6)
    fd3 = (law.dU_dphi(phi + h) - law.dU_dphi(phi - h)) / (2 * h)
    assert np.allclose(fd3, law.d2U_dphi2(phi), atol=1e-5)


def test_trap2_derivative_jumps_at_handover():
    law = WalkingLaw(**SEED_000)
    h = math.pi / 4
    assert law.U(h - 1e-12) == pytest.approx(law.U(h + 1e-12), rel=1e-9)  # continuous
    jump = law.dU_dphi(h + 1e-12) - law.dU_dphi(h - 1e-12)
    assert jump == pytest.approx(12 * law.b * law.u / law.A, rel=1e-9)


@pytest.mark.parametrize("params", [SEED_000, SEED_002])
def test_hub_speed_constant(params):
    """Seed 000: v = omega Y01 / u = const for the exact law."""
    law = WalkingLaw(**params)
    phi = np.linspace(0, 2 * math.pi, 1001)
    v = law.hub_speed(phi)
    assert np.ptp(v) < 1e-10 * law.hub_speed_ratio
    assert np.allclose(v, law.Y01 / law.u)


def test_phi_of_theta_inverts():
    law = WalkingLaw(**SEED_000)
    phi = np.linspace(-1.0, 7.0, 77)
    assert np.allclose(law.phi_of_theta(law.theta(phi)), phi, atol=1e-12)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(a=10, b=400, c=100, n=2), "a - b + c"),
        (dict(a=0, b=100, c=100, n=2), "a - b + c"),
        (dict(a=-1, b=100, c=360, n=2), "a"),
        (dict(a=60, b=-1, c=360, n=2), "b"),
        (dict(a=60, b=100, c=-360, n=2), "c"),
        (dict(a=float("nan"), b=100, c=360, n=2), "a"),
        (dict(a=60, b=100, c=float("inf"), n=2), "c"),
        (dict(a=60, b=100, c=360, n=0), "n"),
        (dict(a=60, b=100, c=360, n=2.5), "n"),
        (dict(a=60, b=100, c=360, n=-2), "n"),
        (dict(a=60, b=100, c=360, n=float("nan")), "n"),
    ],
)
def test_bad_input_names_parameter(kwargs, name):
    with pytest.raises(InputError) as e:
        WalkingLaw(**kwargs)
    assert e.value.parameter == name
    assert name in str(e.value)


def test_n_float_whole_is_accepted():
    assert WalkingLaw(a=60, b=100, c=360, n=2.0).n == 2


@settings(max_examples=60, deadline=None)
@given(
    a=st.floats(0, 300), b=st.floats(0, 300), c=st.floats(0, 600), n=st.integers(1, 6),
    phi=st.floats(-20, 20),
)
def test_law_properties(a, b, c, n, phi):
    assume(a - b + c > 1.0)
    law = WalkingLaw(a=a, b=b, c=c, n=n)
    # closure, positivity, periodicity, constant hub speed
    assert abs(law.theta(2 * math.pi) - 2 * math.pi * n) < 1e-9 * max(1, n)
    assert law.U(phi) > 0
    assert law.U(phi) == pytest.approx(law.U(phi + math.pi / 2), rel=1e-9)
    assert law.U_min <= law.U(phi) <= law.U_max * (1 + 1e-12)
    assert law.hub_speed(phi) == pytest.approx(law.A / law.u, rel=1e-9)
    assert law.theta(phi + 2 * math.pi) - law.theta(phi) == pytest.approx(2 * math.pi * n, rel=1e-9)
    # monotone
    assert law.theta(phi + 1e-3) > law.theta(phi)


@pytest.mark.parametrize("a, b, c, n", [(60.0, 100.0, 360.0, 2), (100.0, 50.0, 236.5, 4), (80.0, 0.0, 300.0, 1)])
def test_U_min_and_U_max_are_the_extremes_of_the_law(a, b, c, n):
    """U_min and U_max equal the smallest and largest ratio over a dense sampling of the turn, the
    minimum at hand-over (w = ±π/4), the maximum mid-support; for b > 0, U_min = u and U_max = u (A + 3b)/A."""
    law = WalkingLaw(a=a, b=b, c=c, n=n)
    phi = np.linspace(-math.pi, math.pi, 200001)
    U = law.U(phi)
    assert law.U_min == pytest.approx(float(U.min()), rel=1e-12)
    assert law.U_max == pytest.approx(float(U.max()), rel=1e-12)
    assert law.U_min == pytest.approx(float(law.U(math.pi / 4)), rel=1e-12)
    assert law.U_max == pytest.approx(float(law.U(0.0)), rel=1e-12)
    A = a - b + c
    assert law.U_min == pytest.approx(n * math.pi * A / (A * math.pi + 6 * b), rel=1e-14)
    assert law.U_max == pytest.approx(law.U_min * (A + 3 * b) / A, rel=1e-14)
