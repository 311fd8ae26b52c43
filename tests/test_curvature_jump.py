"""curvature_at where the curvature jumps without a corner (gears/tooth_load.py): two smooth pieces joined with a
common tangent but different radii (an involute's start meeting its fillet).  The centred window reaching across the
junction mixed both pieces (the circular pair's first contact: 411 mm where the involute gives 5.4 mm, sigma_H
402 MPa instead of about 860); each vertex must get the curvature of the piece it lies on.  Fast: synthetic outlines,
and the circular pair (z 20/40) built through the non-circular path (about 3 s)."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from propulsor.gears import tooth_load as tlm
from propulsor.gears.tooth_load import DenseOutline

H = 0.005          # vertex spacing of the synthetic outlines, mm
FIT = 0.3          # the half length used by the load per tooth (0.12 m at m = 2.5)


def _arc(cx, cy, R, a0, a1):
    """Vertices of the CCW arc a0 .. a1 (end excluded) about (cx, cy), about H apart."""
    n = max(int(math.ceil(R * (a1 - a0) / H)), 1)
    t = a0 + (a1 - a0) * np.arange(n) / n
    return np.column_stack([cx + R * np.cos(t), cy + R * np.sin(t)])


def _lens(R=5.0, r=0.5, c=3.0):
    """A closed convex outline without corners: arcs of radius R about (0, -c) above and (0, c) below, joined at
    either end by arcs of radius r about (+-d, 0) internally tangent to both (d^2 + c^2 = (R - r)^2).  Returns the
    points and the junction angle alpha (the small right arc spans -alpha .. alpha about (d, 0))."""
    d = math.sqrt((R - r) ** 2 - c * c)
    al = math.atan2(c, d)
    pts = np.vstack([_arc(d, 0.0, r, -al, al), _arc(0.0, -c, R, al, math.pi - al),
                     _arc(-d, 0.0, r, math.pi - al, math.pi + al), _arc(0.0, c, R, math.pi + al, 2 * math.pi - al)])
    return pts, d, c, al


def _stadium(R, L=4.0):
    """Two half circles of radius R joined by straight sides of length L (tangent: no corner)."""
    pts = np.vstack([_arc(0.0, 0.0, R, -math.pi / 2, math.pi / 2),
                     np.column_stack([-np.arange(0.0, L, H), np.full(int(math.ceil(L / H)), R)]),
                     _arc(-L, 0.0, R, math.pi / 2, 3 * math.pi / 2),
                     np.column_stack([-L + np.arange(0.0, L, H), np.full(int(math.ceil(L / H)), -R)])])
    return pts


def _near(o, p):
    return int(np.argmin(np.hypot(*(o.points - np.asarray(p)).T)))


@pytest.mark.parametrize("s", [0.02, 0.08, 0.15, 0.25])
def test_arc_of_5_mm_meeting_an_arc_of_1_5_mm_without_a_corner(s):
    """At s mm of arc from the junction, on either piece, that piece's curvature (1/5 and 1/1.5 per mm, about the
    teeth's fillet radius) within 3 %.  (An arc of 0.5 mm is below the fit's resolution at a half length of 0.3 mm:
    a whole circle of 0.5 mm already measures 8 % off, and one side's window turns by 34 deg.)"""
    R, r = 5.0, 1.5
    pts, d, c, al = _lens(R, r, 2.0)
    o = DenseOutline(pts)
    assert not o.corner.any()
    big = _near(o, (R * math.cos(al + s / R), -c + R * math.sin(al + s / R)))
    small = _near(o, (d + r * math.cos(al - s / r), r * math.sin(al - s / r)))
    assert tlm.curvature_at(o, big, FIT) == pytest.approx(1.0 / R, rel=0.03)
    assert tlm.curvature_at(o, small, FIT) == pytest.approx(1.0 / r, rel=0.03)


@pytest.mark.parametrize("R", [5.0, 1.5])
@pytest.mark.parametrize("s", [0.03, 0.1, 0.2])
def test_arc_meeting_a_straight_line_without_a_corner(R, s):
    """A stadium: at s mm from the arc's end, 1/R within 3 %; on the straight side s mm from it, flat (|kappa| under
    3 % of 1/R)."""
    o = DenseOutline(_stadium(R))
    assert not o.corner.any()
    on_arc = _near(o, (R * math.cos(math.pi / 2 - s / R), R * math.sin(math.pi / 2 - s / R)))
    on_line = _near(o, (-s, R))
    assert tlm.curvature_at(o, on_arc, FIT) == pytest.approx(1.0 / R, rel=0.03)
    assert abs(tlm.curvature_at(o, on_line, FIT)) < 0.03 / R


def test_without_a_jump_the_centred_fit_is_kept_bit_for_bit():
    """A circle and a piece of one smooth curve (a spiral): the centred window's fit, unchanged."""
    n = 20000
    t = 2 * math.pi * np.arange(n) / n
    for pts in (np.column_stack([10 * np.cos(t), 10 * np.sin(t)]),
                np.column_stack([(6 + 0.3 * np.sin(t)) * np.cos(t), (6 + 0.3 * np.sin(t)) * np.sin(t)])):
        o = DenseOutline(pts)
        for i in (0, 1234, 7000, 15000):
            K = int(math.ceil(2.0 * FIT / float(o.seg_len[i]))) + 2
            idx = (i + np.arange(-K, K + 1)) % n
            s = np.concatenate([[0.0], np.cumsum(o.seg_len[idx])])[:-1]
            s = s - s[K]
            assert tlm.curvature_at(o, i, FIT) == tlm._fit(o, i, idx[np.abs(s) <= FIT], o.tangent[i])


def test_circular_pair_involute_start_has_the_involutes_radius():
    """The circular pair's driver (z 20, m 2.5, x +0.5; base radius 23.49 mm): on every flank between 0.04 and
    0.3 mm above the involute's start (r 24.05 .. 24.3 mm, where the first contact lies at r = 24.10 mm) the
    measured radius is sqrt(r^2 - r_b^2) within 3 % (it was 411 mm at r = 24.09 mm)."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from test_ncg_exact import _circular_pair

    from propulsor import policy

    _, dd = _circular_pair()
    o = DenseOutline(dd.d.driver.profile.outer.polyline(policy.TOOTH_LOAD_DENSE_CHORD_MM))
    r = np.hypot(*o.points.T)
    rb = 25.0 * math.cos(math.radians(20.0))
    band = np.nonzero((r > 24.05) & (r < 24.3))[0]
    assert len(band) > 20 * 2 * 10
    fit = policy.TOOTH_LOAD_FLANK_FIT_MODULE * 2.5
    rho = np.array([1.0 / tlm.curvature_at(o, int(i), fit) for i in band])
    want = np.sqrt(r[band] ** 2 - rb ** 2)
    assert np.max(np.abs(rho / want - 1.0)) < 0.03


def test_curvatures_fitted_together_are_those_fitted_one_at_a_time():
    """curvatures_at (the load per tooth's curvatures solved in stacks, gears/tooth_load.py) keeps for each vertex the
    value _curvature_at gives alone, to the last bit: smooth pieces, a jump without a corner, corners (a toothed
    outline's tip edges), windows cut short below five vertices, several half lengths and vertices asked twice."""
    rng = np.random.default_rng(5)
    pts, *_ = _lens(5.0, 1.5, 2.0)
    t = np.linspace(0.0, 2.0 * math.pi, 2400, endpoint=False)
    rr = 20.0 + 1.2 * np.sign(np.cos(12 * t)) * np.abs(np.cos(12 * t)) ** 0.3  # flat tips and roots with corners
    toothed = np.column_stack([rr * np.cos(t), rr * np.sin(t)])
    seen = {}
    for P in (pts, toothed, _stadium(1.5)):
        for half in (FIT, 0.05, 0.012):
            o = DenseOutline(P)
            idx = rng.integers(0, len(o), 300)
            tlm.curvatures_at(o, np.concatenate([idx, idx[:20]]), half)
            alone = DenseOutline(P)
            got = np.array([o._curvatures[(int(i), half)] for i in idx])
            want = np.array([tlm._curvature_at(alone, int(i), half) for i in idx])
            assert np.array_equal(got.view(np.int64), want.view(np.int64))
            assert np.any(o.corner) == (P is toothed)
            seen.setdefault(half, []).append(np.isnan(want))
            again = np.array([tlm.curvature_at(o, int(i), half) for i in idx[:20]])  # kept: the same values
            assert np.array_equal(again.view(np.int64), got[:20].view(np.int64))
    nan = {h: np.concatenate(v) for h, v in seen.items()}
    assert np.any(nan[0.012]) and all(np.mean(v) < 0.5 for v in nan.values())  # short windows (nan) among them
