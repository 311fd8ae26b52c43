"""The undercut trim (gears/undercut.py) on curves whose crossings and cusps are known in closed form: a straight
first curve ending where a polynomial second one starts, with one crossing, two crossings, a cusp, none, and curves
whose samples cross where the exact curves do not meet."""
from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.gears import undercut


class Curve:
    """A parametric curve with the interface trim_crossing reads: u0, u1, curve(array of u) -> (n, 2), at(u)."""

    def __init__(self, f, u0=0.0, u1=1.0, offset=(0.0, 0.0)):
        self.f, self.u0, self.u1 = f, u0, u1
        self.offset = np.asarray(offset, float)

    def __call__(self, u):
        x, y = self.f(np.asarray(u, float))
        return np.column_stack([x, y])

    def at(self, u):
        return self(np.array([u]))[0] + self.offset


# first: the straight segment from (0, 2) to the joint J = (2, 0); x + y = 2 along it, u = x / 2
LINE = Curve(lambda u: (2.0 * u, 2.0 - 2.0 * u))


def test_one_crossing_away_from_the_joint():
    """second = (2 - 3u, 4u - 3u^2) leaves J and comes back across x + y = 2 where u - 3u^2 = 0: u = 1/3, at (1, 1),
    which is u = 1/2 on the first curve."""
    second = Curve(lambda u: (2.0 - 3.0 * u, 4.0 * u - 3.0 * u ** 2))
    u_first, u_second = undercut.trim_crossing(LINE, second)
    assert u_first == pytest.approx(0.5, abs=1e-12) and u_second == pytest.approx(1.0 / 3.0, abs=1e-12)


def test_of_two_crossings_the_outermost_loop_is_removed():
    """second = (2 - 3u, 3u + 10 u (u - 0.3)(u - 0.6)) crosses x + y = 2 at u = 0.3 (first's u = 0.55) and u = 0.6
    (first's u = 0.1): the earliest on the first curve, the latest on the second, is taken."""
    second = Curve(lambda u: (2.0 - 3.0 * u, 3.0 * u + 10.0 * u * (u - 0.3) * (u - 0.6)))
    u_first, u_second = undercut.trim_crossing(LINE, second)
    assert u_first == pytest.approx(0.1, abs=1e-12) and u_second == pytest.approx(0.6, abs=1e-12)


def test_only_the_second_curves_range_is_searched():
    """The one-crossing curve of above, its parameter shifted by 1 and cut at 1.3: its crossing (at 1 + 1/3) lies past
    the range's end, so there is none; up to 1.4 it is found."""
    f = lambda u: (2.0 - 3.0 * (u - 1.0), 4.0 * (u - 1.0) - 3.0 * (u - 1.0) ** 2)
    assert undercut.trim_crossing(LINE, Curve(f, 1.0, 1.3)) is None
    u_first, u_second = undercut.trim_crossing(LINE, Curve(f, 1.0, 1.4))
    assert u_first == pytest.approx(0.5, abs=1e-12) and u_second == pytest.approx(4.0 / 3.0, abs=1e-12)


def test_a_curve_that_leaves_the_joint_without_coming_back_has_no_crossing():
    second = Curve(lambda u: (2.0 + u, u ** 2))
    assert undercut.trim_crossing(LINE, second) is None
    # nor one that runs along the first curve's side only near the joint (the joint itself is not a crossing)
    second = Curve(lambda u: (2.0 - 0.5 * u, 2.0 * u))
    assert undercut.trim_crossing(LINE, second) is None


C = 0.3     # the cusp's parameter
K = -2.0    # the first curve of the cusp case: y = K (x - 2), from (1, 2) to J


def _cusped():
    """second = J + ((u - c)^2 - c^2, (u - c)^3 + c^3): a semicubical cusp at u = c (the velocity 0, reversing)."""
    return Curve(lambda u: (2.0 + (u - C) ** 2 - C ** 2, (u - C) ** 3 + C ** 3))


def test_the_cusp_is_found():
    assert undercut._cusp(_cusped()) == pytest.approx(C, abs=1e-6)
    assert undercut._cusp(Curve(lambda u: (2.0 - 3.0 * u, 4.0 * u - 3.0 * u ** 2))) is None
    # a cusp whose position vector points against the branches' direction (|P| is largest at the cusp: the search is
    # for the least speed, not the least |P|)
    assert undercut._cusp(Curve(lambda u: (-2.0 + (u - C) ** 2, (u - C) ** 3))) == pytest.approx(C, abs=1e-6)
    # a cusp near the end of the range (the last reversal window)
    late = Curve(lambda u: ((u - 0.9) ** 2, (u - 0.9) ** 3))
    assert undercut._cusp(late) == pytest.approx(0.9, abs=1e-6)
    # on a range that does not start at 0 and is longer than 1
    shifted = Curve(lambda u: ((u - 3.7) ** 2, (u - 3.7) ** 3), 2.0, 5.0)
    assert undercut._cusp(shifted) == pytest.approx(3.7, abs=1e-6)
    # on a range of negative parameters (the samples run from u0 to u1, not past them)
    negative = Curve(lambda u: ((u + 2.0) ** 2, (u + 2.0) ** 3), -3.0, -0.9)
    assert undercut._cusp(negative) == pytest.approx(-2.0, abs=1e-6)
    # a curve that turns past a right angle before its cusp: the reversal is between neighbouring samples, not
    # against the start's direction (a quarter circle, then a straight leg into a cusp at u = 0.8)
    def turned(u):
        q = np.clip(u, 0.0, 0.5) / 0.5 * 0.75 * math.pi               # 135 deg of a unit arc over u in [0, 0.5]
        s = np.clip(u - 0.5, 0.0, None)
        tx, ty = -math.sin(0.75 * math.pi), math.cos(0.75 * math.pi)  # the arc's end tangent
        w = (0.3 ** 2 - (s - 0.3) ** 2)                                 # out and back along it: a cusp at u = 0.8
        return np.cos(q) + w * tx, np.sin(q) + w * ty
    assert undercut._cusp(Curve(turned)) == pytest.approx(0.8, abs=1e-6)
    # a cusp past the range's end is not the curve's: none
    assert undercut._cusp(Curve(lambda u: ((u - 1.5) ** 2, (u - 1.5) ** 3))) is None
    # a small loop: f = (u - 1/2)^3 - 1e-4 (u - 1/2) runs back over 0.0115 of the range along a line, between its two
    # cusps at 1/2 -+ sqrt(1e-4 / 3); the 2000 samples see it (the first: 0.494227), 50 would step across it
    f = lambda u: (u - 0.5) ** 3 - 1e-4 * (u - 0.5)
    assert undercut._cusp(Curve(lambda u: (f(u), 0.5 * f(u)))) == pytest.approx(0.5 - math.sqrt(1e-4 / 3), abs=1e-6)


def test_after_a_cusp_only_the_branch_beyond_it_bounds_the_cut():
    """With s = u - c, the second curve meets y = K (x - 2) where s^2 - (c + K) s + c^2 + K c = 0 (besides s = -c, the
    joint): s = (c + K + sqrt((c + K)^2 - 4 (c^2 + K c))) / 2; the first curve's u is x - 1."""
    first = Curve(lambda u: (1.0 + u, -K * (1.0 - u)))
    s = ((C + K) + math.sqrt((C + K) ** 2 - 4 * (C ** 2 + K * C))) / 2
    x = 2.0 + s ** 2 - C ** 2
    u_first, u_second = undercut.trim_crossing(first, _cusped())
    assert u_second == pytest.approx(C + s, abs=1e-10) and u_first == pytest.approx(x - 1.0, abs=1e-10)
    assert 0.5 < u_second < 0.6 and 0.97 < u_first < 0.98


def test_samples_that_cross_where_the_exact_curves_do_not_meet_are_refused():
    """The exact first curve 1 mm right and 1 mm above its samples (x + y = 4): the samples cross the second curve,
    whose x + y = 2 + u - 3u^2 never reaches 4 for any u, so the exact curves never meet."""
    first = Curve(LINE.f, offset=(1.0, 1.0))
    second = Curve(lambda u: (2.0 - 3.0 * u, 4.0 * u - 3.0 * u ** 2))
    with pytest.raises(RuntimeError, match="^undercut crossing did not converge$"):
        undercut.trim_crossing(first, second)


def test_segment_crossings_of_two_polylines():
    A = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0]])
    B = np.array([[1.0, -1.0], [1.0, 1.0], [3.0, 1.0]])
    i, j, ta, tb = undercut._segment_crossings(A, B)
    got = sorted(zip(i.tolist(), j.tolist(), ta.tolist(), tb.tolist()))
    assert got == [(0, 0, 0.5, 0.5), (1, 1, 0.5, 0.5)]
    # parallel segments do not cross (and divide by zero silently); an end touching counts (t = 0 or 1)
    P = np.array([[0.0, 0.0], [1.0, 0.0]])
    Q = np.array([[0.0, 1.0], [1.0, 1.0]])
    with np.errstate(all="raise"):
        assert len(undercut._segment_crossings(P, Q)[0]) == 0
    T = np.array([[1.0, 0.0], [1.0, 1.0]])
    i, j, ta, tb = undercut._segment_crossings(P, T)
    assert (i.tolist(), j.tolist(), ta.tolist(), tb.tolist()) == ([0], [0], [1.0], [0.0])
    T = np.array([[0.0, -1.0], [0.0, 0.0]])                      # touching A's start with B's end: ta = 0, tb = 1
    i, j, ta, tb = undercut._segment_crossings(P, T)
    assert (i.tolist(), j.tolist(), ta.tolist(), tb.tolist()) == ([0], [0], [0.0], [1.0])
    # lines that cross beyond a segment's end (tb = 2, ta = 1.5) are no crossing
    assert len(undercut._segment_crossings(np.array([[0.0, 0.0], [2.0, 0.0]]),
                                           np.array([[3.0, 1.0], [3.0, 0.5]]))[0]) == 0
    assert len(undercut._segment_crossings(np.array([[0.0, 0.0], [4.0, 0.0]]),
                                           np.array([[1.0, 1.0], [1.0, 0.5]]))[0]) == 0
    # collinear overlapping segments (0 / 0) are no crossing either, and stay silent
    with np.errstate(all="raise"):
        assert len(undercut._segment_crossings(P, np.array([[0.5, 0.0], [2.0, 0.0]]))[0]) == 0
