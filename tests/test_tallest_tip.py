"""The tip shortening's search (gears/tip_search.py, ``tallest_tip``): the same height, to the last bit, as
the bisection down to ``TIP_HEIGHT_TOL_MM`` it replaces, for a land that falls smoothly with the height, one that
stops (the flank does not reach: land -1) and one that does both; in fewer evaluations where the land is smooth."""

from __future__ import annotations

import math

import pytest

from propulsor.gears.tip_search import tallest_tip
from propulsor.policy import TIP_HEIGHT_TOL_MM


def _bisection(thickness, h_lo, at_lo, h_hi, t_min):
    """The search as generate_teeth ran it before (the reference)."""
    lo, hi, best = h_lo, h_hi, at_lo
    while hi - lo > TIP_HEIGHT_TOL_MM:
        mid = 0.5 * (lo + hi)
        res = thickness(mid)
        if res[0] >= t_min:
            lo, best = mid, res
        else:
            hi = mid
    return lo, best


def _land(kind, c):
    def smooth(h):  # a land of 2.9 mm at the root falling like a tooth's (concave), 0.625 at h = c
        return 2.9 - (2.9 - 0.625) * (h / c) ** 1.3

    def thickness(h):
        if kind in ("stops", "both") and h > c * (0.93 if kind == "both" else 1.0):
            return (-1.0, None, None)
        t = smooth(h) if kind != "stops" else 2.8 - 0.05 * h
        return (t, ("right", h), ("left", h))
    return thickness


@pytest.mark.parametrize("kind", ["smooth", "stops", "both"])
@pytest.mark.parametrize("c", [0.2154261170, 1.7, 3.567056308534, 2.0 + 2.0 ** -20])
def test_the_same_height_as_the_bisection_bit_for_bit(kind, c):
    t_min = 0.625
    thickness = _land(kind, c)
    h_lo, h_hi = 0.0 if c < 1 else 1.0, c + 1.25
    at_lo = thickness(h_lo)
    ref = _bisection(thickness, h_lo, at_lo, h_hi, t_min)
    calls = []

    def counted(h):
        calls.append(h)
        return thickness(h)

    got = tallest_tip(counted, h_lo, at_lo, h_hi, thickness(h_hi), t_min)
    assert got[0] == ref[0] and got[1] == ref[1]
    assert got[1][0] >= t_min and thickness(got[0] + TIP_HEIGHT_TOL_MM)[0] < t_min + 1e-5
    halvings = math.ceil(math.log2((h_hi - h_lo) / TIP_HEIGHT_TOL_MM))
    if kind == "smooth":
        assert len(calls) <= halvings // 2  # the point of it: 21-22 halvings, a third of the evaluations
    else:
        assert len(calls) <= halvings + 1


def _counted(thickness):
    calls = []

    def f(h):
        calls.append(h)
        return thickness(h)
    return f, calls


def _falling(kind, c, t_min=0.625):
    """More lands of a tooth falling with the height: convex (an exponential), linear (t_min exactly at h = c), and
    tips lost on one side only above 0.9 c (the right or the left flank stops short)."""
    def thickness(h):
        if kind == "convex":
            return (3.0 * math.exp(-1.6 * h / c), ("right", h), ("left", h))
        if kind == "linear":
            return (t_min + (c - h), ("right", h), ("left", h))
        if h > 0.9 * c:
            return (-1.0, None, ("left", h)) if kind == "right_stops" else (-1.0, ("right", h), None)
        return (2.9 - (2.9 - t_min) * (h / c) ** 1.3, ("right", h), ("left", h))
    return thickness


@pytest.mark.parametrize("kind, c, h_lo, h_hi, most", [
    ("convex", 1.7, 1.0, 2.95, 10),          # the secant keeps the upper end: Illinois halves the lower end's value
    ("convex", 0.2154261170, 0.0, 1.4654261170, 14),
    ("right_stops", 1.7, 1.0, 2.95, 21),     # one flank stops short: bisected from there on, as before
    ("left_stops", 1.7, 1.0, 2.95, 21),
    ("linear", 1.7, 0.0, 3.4, 3),            # the secant lands on the root at once
    ("linear", 1.0 - 5e-9, 0.0, 2.0, 4),     # the first halving's midpoint 1.0 lies 5 nm above the root
    ("linear", 1.0 + 5e-9, 0.0, 2.0, 3),     # ... and 5 nm below it
    ("linear", 1.7, 0.0, 2.0 ** 21 * TIP_HEIGHT_TOL_MM, 4),  # 21 halvings end on exactly the tolerance
])
def test_more_lands_the_same_height_as_the_bisection_in_fewer_evaluations(kind, c, h_lo, h_hi, most):
    t_min = 0.625
    thickness = _falling(kind, c, t_min)
    at_lo, at_hi = thickness(h_lo), thickness(h_hi)
    ref = _bisection(thickness, h_lo, at_lo, h_hi, t_min)
    counted, calls = _counted(thickness)
    got = tallest_tip(counted, h_lo, at_lo, h_hi, at_hi, t_min)
    assert got[0] == ref[0] and got[1] == ref[1]
    assert len(calls) <= most


@pytest.mark.parametrize("c", [1.0, 1.7, 2.0])
def test_a_land_exactly_at_the_minimum_at_the_lower_height_takes_one_evaluation(c):
    """The lower height is the root (land = t_min exactly there, f = 0): the secant lands on it, one evaluation a step
    above closes the bracket.  Taking the midpoint there instead halved the bracket 31 times, half again the
    bisection's own count."""
    thickness = _land("smooth", c)
    h_lo, h_hi = c, c + 1.25
    at_lo = thickness(h_lo)
    assert at_lo[0] == pytest.approx(0.625, abs=1e-15)
    ref = _bisection(thickness, h_lo, at_lo, h_hi, at_lo[0])
    counted, calls = _counted(thickness)
    got = tallest_tip(counted, h_lo, at_lo, h_hi, thickness(h_hi), at_lo[0])
    assert got[0] == ref[0] == h_lo and got[1] == ref[1]
    assert len(calls) == 1 and calls[0] - h_lo == pytest.approx(2.5e-4 * TIP_HEIGHT_TOL_MM, rel=1e-3)


@pytest.mark.parametrize("cap", [0, 1, 3])
def test_the_secant_steps_are_capped_and_the_bisection_still_decides(monkeypatch, cap):
    """TIP_SECANT_STEPS_MAX cuts the Illinois steps short (a crawl cannot hang the build); the bisection then finds the
    same height to the last bit from whatever bracket the secant left.  Cap 0: the plain bisection, one evaluation a
    halving; cap k: k secant steps, then the halvings the bracket cannot decide."""
    import propulsor.gears.tip_search as ts

    monkeypatch.setattr(ts, "TIP_SECANT_STEPS_MAX", cap)
    for kind, c in (("smooth", 1.7), ("convex", 1.7)):
        thickness = _land(kind, c) if kind == "smooth" else _falling(kind, c)
        h_lo, h_hi = 1.0, c + 1.25
        at_lo, at_hi = thickness(h_lo), thickness(h_hi)
        ref = _bisection(thickness, h_lo, at_lo, h_hi, 0.625)
        counted, calls = _counted(thickness)
        got = tallest_tip(counted, h_lo, at_lo, h_hi, at_hi, 0.625)
        assert got[0] == ref[0] and got[1] == ref[1]
        halvings = math.ceil(math.log2((h_hi - h_lo) / TIP_HEIGHT_TOL_MM))
        if cap == 0:
            assert len(calls) == halvings     # every midpoint evaluated, as the bisection does
        else:
            assert cap < len(calls) <= cap + halvings
            # the first `cap` evaluations are the secant's, off the halving grid
            mids = {h_lo + (h_hi - h_lo) * j / 2 ** i for i in range(1, 4) for j in range(1, 2 ** i, 2)}
            assert not set(calls[:cap]) & mids


def _stopping(c_land, c_stop, t_min=0.625):
    """A smooth land reaching t_min at c_land on flanks that stop at c_stop (no tip above: land -1)."""
    def thickness(h):
        if h > c_stop:
            return (-1.0, None, None)
        return (2.9 - (2.9 - t_min) * (h / c_land) ** 1.3, ("right", h), ("left", h))
    return thickness


@pytest.mark.parametrize("c_land, c_stop", [(0.4, 0.2157626903), (1.9, 1.7), (2.0, 1.0 + 2.0 ** -21),
                                            (1.7, 1.9), (0.2154261170, 0.3)])
@pytest.mark.parametrize("error", [0.0, 3e-9, -3e-9, 2e-7, -2e-7, 1e-3, -0.05, 5.0, -5.0])
def test_the_flanks_reach_guessed_gives_the_bisections_height_bit_for_bit_and_few_evaluations_when_close(
        c_land, c_stop, error):
    """``reach``: where the tip leaves a flank, guessed (``flank_reach``) with an error.  Whatever the guess, the
    same height and tip as the bisection (only heights evaluated decide); the flank's end deciding the height (c_stop
    below c_land) and guessed within ``TIP_REACH_PROBE_MM``, a handful of evaluations against the bisection's 21; the
    land deciding it (the flank stops above), the Illinois method's few from a tipped upper end."""
    from propulsor.policy import TIP_REACH_PROBE_MM

    t_min = 0.625
    thickness = _stopping(c_land, c_stop, t_min)
    h_lo, h_hi = 0.0, max(c_land, c_stop) + 1.25
    at_lo, at_hi = thickness(h_lo), thickness(h_hi)
    assert at_hi[1] is None
    ref = _bisection(thickness, h_lo, at_lo, h_hi, t_min)
    counted, calls = _counted(thickness)
    guesses = []
    got = tallest_tip(counted, h_lo, at_lo, h_hi, at_hi, t_min, lambda: guesses.append(1) or c_stop + error)
    assert got[0] == ref[0] and got[1] == ref[1]
    assert guesses == [1]
    halvings = math.ceil(math.log2((h_hi - h_lo) / TIP_HEIGHT_TOL_MM))
    assert len(calls) <= halvings + 2  # a bad guess costs its two probes at most
    if abs(error) < TIP_REACH_PROBE_MM:
        assert len(calls) <= (4 if c_stop < c_land else 12)


@pytest.mark.parametrize("guess", [math.nan, math.inf, "raises"])
def test_no_guess_of_the_flanks_reach_leaves_the_bisection_to_decide(guess):
    """A guess that is not a number, or that fails, evaluates no probe: the bisection's height, its evaluations."""
    thickness = _stopping(1.9, 1.7)
    h_lo, h_hi = 0.0, 1.9 + 1.25
    at_lo, at_hi = thickness(h_lo), thickness(h_hi)
    ref = _bisection(thickness, h_lo, at_lo, h_hi, 0.625)

    def reach():
        if guess == "raises":
            raise ValueError("no foot point")
        return guess

    counted, calls = _counted(thickness)
    got = tallest_tip(counted, h_lo, at_lo, h_hi, at_hi, 0.625, reach)
    plain, plain_calls = _counted(thickness)
    assert got == ref == tallest_tip(plain, h_lo, at_lo, h_hi, at_hi, 0.625)
    assert calls == plain_calls


def test_a_tip_that_vanishes_below_the_flanks_end_sends_the_search_back_to_the_plain_bisection():
    """Next to a flank's cusp a tip can vanish below a height that has one (the seed-002 pair without backlash: none
    0.5 um below the flank's end, one again 1 um below): the probes' bracket then leads the halvings to a height
    without a tip.  The search is made again without the probes: the bisection's height and tip."""
    c = 0.2157115415
    t_min = 0.625

    def thickness(h):
        if h > c or c - 1e-6 < h < c - 1e-8:
            return (-1.0, None, None)
        return (2.9 - 0.5 * h, ("right", h), ("left", h))

    h_lo, h_hi = 0.0, 1.25
    at_lo, at_hi = thickness(h_lo), thickness(h_hi)
    ref = _bisection(thickness, h_lo, at_lo, h_hi, t_min)
    assert ref[1][1] is not None
    got = tallest_tip(thickness, h_lo, at_lo, h_hi, at_hi, t_min, lambda: c)
    assert got == ref
