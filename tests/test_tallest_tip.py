"""The tip shortening's search (gears/noncircular_teeth.py, ``_tallest_tip``): the same height, to the last bit, as
the bisection down to ``TIP_HEIGHT_TOL_MM`` it replaces, for a land that falls smoothly with the height, one that
stops (the flank does not reach: land -1) and one that does both; in fewer evaluations where the land is smooth."""

from __future__ import annotations

import math

import pytest

from propulsor.gears.noncircular_teeth import TIP_HEIGHT_TOL_MM, _tallest_tip


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

    got = _tallest_tip(counted, h_lo, at_lo, h_hi, thickness(h_hi), t_min)
    assert got[0] == ref[0] and got[1] == ref[1]
    assert got[1][0] >= t_min and thickness(got[0] + TIP_HEIGHT_TOL_MM)[0] < t_min + 1e-5
    halvings = math.ceil(math.log2((h_hi - h_lo) / TIP_HEIGHT_TOL_MM))
    if kind == "smooth":
        assert len(calls) <= halvings // 2  # the point of it: 21-22 halvings, a third of the evaluations
    else:
        assert len(calls) <= halvings + 1
