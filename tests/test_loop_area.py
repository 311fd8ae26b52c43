"""A loop's exact signed area (geometry/profile.py ``Loop.exact_signed_area``: each segment's ``sweep``, Green's
theorem), which orients every profile without sampling it: lines and arcs in closed form, B-splines by
Gauss-Legendre on each knot span (geometry/spline_foot.py ``sweep_area``, exact up to degree 3)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.interpolate import make_interp_spline

from propulsor.geometry.profile import Arc, Line, Loop, Profile, Spline, circle_loop, polygon_loop
from propulsor.geometry.spline_foot import sweep_area


def _shoelace(p: np.ndarray) -> float:
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def _spline(points, k=3) -> Spline:
    P = np.asarray(points, float)
    t = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(P, axis=0), axis=1))])
    bs = make_interp_spline(t, P, k=k)
    return Spline(bs.t, bs.c, k)


def _blob(k: int = 3) -> Loop:
    """A closed loop of two splines of degree k (a wavy bean) and a line, off the origin."""
    a = np.linspace(0.0, math.pi, 9)
    upper = np.column_stack([7.0 + 5.0 * np.cos(a), 3.0 + 2.5 * np.sin(a) + 0.6 * np.sin(3 * a)])
    b = np.linspace(math.pi, 2 * math.pi, 9)
    lower = np.column_stack([7.0 + 5.0 * np.cos(b), 3.0 + 1.5 * np.sin(b) - 0.4 * np.sin(2 * b)])
    s1, s2 = _spline(upper, k), _spline(lower[:-1], k)
    return Loop([s1, s2, Line(tuple(s2.end), tuple(s1.start))])


def test_a_circle_and_a_rectangle_exactly():
    assert math.isclose(circle_loop(10.0).exact_signed_area(), math.pi * 100.0, rel_tol=1e-15)
    assert math.isclose(circle_loop(4.0, (3.0, -7.0), ccw=False).exact_signed_area(), -math.pi * 16.0, rel_tol=1e-14)
    assert polygon_loop([(1, 1), (4, 1), (4, 3), (1, 3)]).exact_signed_area() == 6.0
    # an arc's chord closed by a line, off the origin: the segment r^2 (t - sin t) / 2
    r, t, c = 5.0, 2.0, (2.0, -3.0)
    arc = Arc(c, r, 0.3, 0.3 + t)
    seg = Loop([arc, Line(tuple(arc.end), tuple(arc.start))])
    assert math.isclose(seg.exact_signed_area(), 0.5 * r * r * (t - math.sin(t)), rel_tol=1e-13)


@pytest.mark.parametrize("k", [1, 2, 3])
def test_a_spline_loop_has_the_area_of_its_fine_polyline(k):
    """The exact area against the shoelace area of the loop sampled ever finer: within each sampling's chord tolerance
    times the loop's length of it (each chord lies within the tolerance of its arc), falling with the tolerance; the
    reversed loop has the opposite area."""
    loop = _blob(k)
    exact = loop.exact_signed_area()
    tols = (1e-2, 1e-3, 1e-4)
    errs = [abs(_shoelace(loop.polyline(tol)) - exact) for tol in tols]
    fine = loop.polyline(1e-5)
    length = float(np.sum(np.linalg.norm(np.diff(np.vstack([fine, fine[:1]]), axis=0), axis=1)))
    assert all(e <= tol * length for e, tol in zip(errs, tols)) and errs[2] < errs[1] < errs[0], (exact, errs, length)
    assert loop.reversed().exact_signed_area() == pytest.approx(-exact, rel=1e-13)


def test_the_quadrature_is_exact_on_each_span():
    """A cubic spline's sweep against a 40-point Gauss-Legendre rule on each span (exact to rounding too): three
    points are enough for the degree-5 integrand (a two-point rule is not)."""
    s = _blob().segments[0]
    bs = s._bs
    d1 = bs.derivative(1)
    x, w = np.polynomial.legendre.leggauss(40)
    ref = 0.0
    for lo, hi in zip(s.knots[3:-4], s.knots[4:-3]):
        if hi > lo:
            u = 0.5 * (hi + lo) + 0.5 * (hi - lo) * x
            P, D = bs(u), d1(u)
            ref += 0.5 * (hi - lo) * float(np.dot(w, P[:, 0] * D[:, 1] - P[:, 1] * D[:, 0]))
    assert sweep_area(s.knots, s.poles, 3) == pytest.approx(ref, rel=1e-13, abs=1e-12)
    assert s.sweep() == sweep_area(s.knots, s.poles, 3)


def test_a_profile_is_oriented_by_its_exact_area():
    """A profile made of a clockwise outer loop and a counter-clockwise hole: the outer comes out counter-clockwise and
    the hole clockwise, by the sign of the exact area (the loops' polylines say the same)."""
    outer = _blob().reversed()
    hole = circle_loop(0.8, (7.0, 3.0), ccw=True)
    p = Profile(outer, [hole])
    assert p.outer.exact_signed_area() > 0 and _shoelace(p.outer.polyline(1e-3)) > 0
    assert p.holes[0].exact_signed_area() < 0 and _shoelace(p.holes[0].polyline(1e-3)) < 0
