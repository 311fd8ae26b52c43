"""The generating cutters' geometry (gears/cutters.py) by hand: each outline piece against its closed form, the placed
(rotated, shifted, mirrored) pieces against a rotation written out, the ISO 53 rack cutter's tip round tangent to its
tip line and its flank, the shaper's tip round tangent to its tip circle and its involute, every refusal in full."""
from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.gears.cutters import (ArcPiece, CutterSide, InvolutePiece, LinePiece, PlacedPiece, RackCutter,
                                     ShaperCutter)
from propulsor.gears.envelope import EnvelopeCurve, RackCentrode
from propulsor.gears.involute import BasicRack
from propulsor.policy import INVOLUTE_T_MIN

A20 = math.radians(20.0)


def _refusal(call, text):
    with pytest.raises(InputError) as e:
        call()
    assert str(e.value) == text


def _inv(a):
    return math.tan(a) - a


def _same(vector, scalar):
    """A vectorised piece method at one u and its one-float twin: the same two numbers."""
    assert vector.shape == (1, 2)
    assert tuple(float(v) for v in vector[0]) == pytest.approx(scalar, rel=1e-15, abs=1e-15)


def test_line_piece():
    p = LinePiece((1.5, -2.0), (0.6, 0.8))
    u = np.array([-1.0, 0.0, 2.5])
    assert np.array_equal(p.point(u), np.array([[0.9, -2.8], [1.5, -2.0], [3.0, 0.0]]))
    assert np.array_equal(p.tangent(u), np.array([[0.6, 0.8]] * 3))
    assert p.point(2.5).shape == (1, 2) and p.tangent(2.5).shape == (1, 2)
    assert p.point1(2.5) == (3.0, 0.0) and p.tangent1(2.5) == (0.6, 0.8)
    assert isinstance(p.point1(1)[0], float) and isinstance(p.tangent1(1)[1], float)
    assert LinePiece((1, 2), (0, 1)).point1(3) == (1.0, 5.0)


def test_arc_piece():
    p = ArcPiece((2.0, -1.0), 3.0)
    a = np.array([0.0, math.pi / 2, math.radians(210.0)])
    want = np.column_stack([2.0 + 3.0 * np.cos(a), -1.0 + 3.0 * np.sin(a)])
    assert np.allclose(p.point(a), want, rtol=0, atol=1e-15)
    assert np.allclose(p.tangent(a), np.column_stack([-np.sin(a), np.cos(a)]), rtol=0, atol=1e-15)
    for ai in a:
        _same(p.point(ai), p.point1(ai))
        _same(p.tangent(ai), p.tangent1(ai))
    # the tangent is the derivative's direction (counter-clockwise about the centre)
    h = 1e-6
    d = (p.point(1.0 + h) - p.point(1.0 - h))[0] / (2 * h)
    assert d / np.linalg.norm(d) == pytest.approx(p.tangent(1.0)[0], abs=1e-9)


def test_involute_piece():
    """r = r_b sqrt(1 + t^2) at the roll parameter t = tan alpha_y; its polar angle from +y towards +x is
    beta - inv(alpha_y); the tangent is the derivative's direction (by central differences)."""
    r_b, beta = 30.0, 0.07
    p = InvolutePiece(r_b, beta)
    for t in (0.0, 0.2, 0.55):
        ay = math.atan(t)
        r = r_b / math.cos(ay)
        psi = beta - _inv(ay)
        assert p.point(t)[0] == pytest.approx((r * math.sin(psi), r * math.cos(psi)), rel=1e-14, abs=1e-14)
        _same(p.point(t), p.point1(t))
        _same(p.tangent(t), p.tangent1(t))
        h = 1e-6
        d = (p.point(t + h) - p.point(t - h))[0] / (2 * h)
        if t > 0:
            assert d / np.linalg.norm(d) == pytest.approx(p.tangent(t)[0] / np.linalg.norm(p.tangent(t)[0]), abs=1e-8)
    # at the base circle (t = 0) the tangent is radial: (sin beta, cos beta), regular there
    assert p.tangent(0.0)[0] == pytest.approx((math.sin(beta), math.cos(beta)), abs=1e-15)
    assert InvolutePiece.conjugate_to_rack is True
    assert p.point(np.array([0.1, 0.2])).shape == (2, 2)


def _rot(v, ang):
    c, s = math.cos(ang), math.sin(ang)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


@pytest.mark.parametrize("mirror", [False, True])
def test_placed_piece_rotates_then_shifts_then_mirrors(mirror):
    base = ArcPiece((2.0, 1.0), 0.5)
    ang, off = math.radians(35.0), (3.0, -4.0)
    p = PlacedPiece(base, ang, off, mirror)
    for a in (0.3, 2.0):
        want = _rot(base.point(a)[0], ang) + np.array(off)
        want_t = _rot(base.tangent(a)[0], ang)
        if mirror:
            want, want_t = want * [-1, 1], want_t * [-1, 1]
        assert p.point(a)[0] == pytest.approx(want, abs=1e-14)
        assert p.tangent(a)[0] == pytest.approx(want_t, abs=1e-14)
        _same(p.point(a), p.point1(a))
        _same(p.tangent(a), p.tangent1(a))
    assert p.conjugate_to_rack is False
    assert PlacedPiece(InvolutePiece(20.0, 0.1), ang).conjugate_to_rack is True
    # the defaults: no rotation, no offset, no mirror
    q = PlacedPiece(base)
    assert np.array_equal(q.point(0.3), base.point(0.3)) and q.point1(0.3) == base.point1(0.3)


def test_cutter_side_envelopes_and_placed():
    fil, fla = ArcPiece((1.0, -2.0), 0.4), LinePiece((1.5, 0.0), (-0.3, 0.9))
    cut = RackCentrode()
    side = CutterSide(fil, (-1.5, -2.5), fla, (0.1, 3.0), cut, "rack")
    gear = object()
    f, k = side.envelopes(gear)
    assert isinstance(f, EnvelopeCurve) and isinstance(k, EnvelopeCurve)
    assert (f.piece, f.cutter, f.gear, f.u0, f.u1, f.kind) == (fil, cut, gear, -1.5, -2.5, "fillet")
    assert (k.piece, k.cutter, k.gear, k.u0, k.u1, k.kind) == (fla, cut, gear, 0.1, 3.0, "flank")
    pl = side.placed(0.2, (1.0, 2.0), True)
    assert pl.fillet == PlacedPiece(fil, 0.2, (1.0, 2.0), True)
    assert pl.flank == PlacedPiece(fla, 0.2, (1.0, 2.0), True)
    assert (pl.fillet_range, pl.flank_range, pl.cutter, pl.kind) == ((-1.5, -2.5), (0.1, 3.0), cut, "rack")


@pytest.mark.parametrize("m, x, thinning", [(2.5, 0.0, 0.0), (4.0, 0.35, 0.06), (3.0, -0.4, 0.0)])
def test_rack_cutter_by_iso_53(m, x, thinning):
    """ISO 53 rack, shifted x m from the gear axis: its space w = m (pi/2 + 2 x tan a) - thinning wide on the rolling
    line, tip line at -(h_a* + c* - x) m, tip round rho_f* m tangent to the tip line and to the straight flank; the
    flank ends where the round meets it, the round where it meets the tip line; left side the mirror image."""
    rc = RackCutter(m, x, BasicRack(), thinning)
    w = m * (math.pi / 2 + 2 * x * math.tan(A20)) - thinning
    rho = 0.38 * m
    eta_t = -(1.25 - x) * m
    assert rc.w == pytest.approx(w, rel=1e-14) and rc.rho == pytest.approx(rho, rel=1e-14)
    assert rc.eta_t == pytest.approx(eta_t, rel=1e-14)
    assert rc.eta_f == pytest.approx(eta_t + rho * (1 - math.sin(A20)), rel=1e-14)
    right, left = rc.sides(3.0 * m)
    centre = np.array([rc.xi_c, eta_t + rho])
    # the round's centre is rho from the tip line and rho from the flank line xi = w/2 - eta tan a
    n = np.array([math.cos(A20), math.sin(A20)])                     # unit normal of the flank line
    assert abs(float(np.dot(centre - np.array([w / 2, 0.0]), n))) == pytest.approx(rho, rel=1e-13)
    for side, sgn in ((right, 1.0), (left, -1.0)):
        assert side.kind == "rack" and isinstance(side.cutter, RackCentrode)
        assert side.fillet.c == pytest.approx((sgn * centre[0], centre[1]), rel=1e-14)
        assert side.fillet.rho == pytest.approx(rho, rel=1e-14)
        a0, a1 = side.fillet_range
        u0, u1 = side.flank_range
        assert u0 == pytest.approx(rc.eta_f / math.cos(A20), rel=1e-14) and u1 == 3.0 * m
        # the round starts on the tip line (its lowest point) and ends on the flank, tangent to it
        assert side.fillet.point(a0)[0] == pytest.approx((sgn * centre[0], eta_t), abs=1e-13)
        assert side.fillet.point(a1)[0] == pytest.approx(side.flank.point(u0)[0], abs=1e-13)
        t_arc, t_line = side.fillet.tangent(a1)[0], side.flank.tangent(u0)[0]
        assert abs(t_arc[0] * t_line[1] - t_arc[1] * t_line[0]) < 1e-13
        # the flank: from (±w/2, 0) on the rolling line, away from the gear axis at the pressure angle
        assert side.flank.point(0.0)[0] == pytest.approx((sgn * w / 2, 0.0), abs=1e-14)
        assert side.flank.tangent(0.0)[0] == pytest.approx((-sgn * math.sin(A20), math.cos(A20)), abs=1e-15)
    assert right.fillet_range == pytest.approx((-math.pi / 2, -(math.pi - A20)))
    assert left.fillet_range == pytest.approx((-math.pi / 2, -A20))


def test_rack_cutter_refuses_overlapping_tip_rounds_naming_the_parameter():
    """The round's centre may not pass the middle of the tool's tooth (xi = pi m / 2): a tooth thickened by a
    negative thinning leaves no tip land.  m = 2: xi_c = pi/2 - t/2 + 2.5 tan a - 0.76 (1 - sin a) tan a
    + 0.76 cos a; the limit pi at t = -1.9875 mm."""
    m = 2.0
    ta = math.tan(A20)
    t_lim = 2 * (m * math.pi / 4 + 1.25 * m * ta - 0.38 * m * (1 - math.sin(A20)) * ta + 0.38 * m * math.cos(A20)
                 - math.pi * m / 2)
    assert RackCutter(m, 0.0, BasicRack(), t_lim + 1e-6).sides(6.0)
    _refusal(lambda: RackCutter(m, 0.0, BasicRack(), t_lim - 1e-6).sides(6.0),
             "rho_f_star = 0.38: tool tip rounds overlap (no tip land)")
    _refusal(lambda: RackCutter(m, 0.0, BasicRack(), t_lim - 1e-6).sides(6.0, "rack.rho_f_star"),
             "rack.rho_f_star = 0.38: tool tip rounds overlap (no tip land)")


def test_shaper_cutter_refusals_in_full():
    _refusal(lambda: ShaperCutter(5, 2.0), "z0 = 5: must be a whole number >= 6")
    _refusal(lambda: ShaperCutter(20.5, 2.0), "z0 = 20.5: must be a whole number >= 6")
    assert ShaperCutter(6, 2.0).z0 == 6
    with pytest.raises(InputError) as e:
        ShaperCutter(20, 0.0)
    assert e.value.parameter == "m"
    with pytest.raises(InputError) as e:
        ShaperCutter(20, 2.0, float("nan"))
    assert e.value.parameter == "x0"
    _refusal(lambda: ShaperCutter(20, 2.0, 0.0, BasicRack(), 0.0), "rho_a0_star = 0.0: must be > 0")
    with pytest.raises(InputError) as e:
        ShaperCutter(20, 2.0, 0.0, BasicRack(), float("inf"))
    assert e.value.parameter == "rho_a0_star"


@pytest.mark.parametrize("z0, m, x0, rho_star", [(20, 2.0, 0.0, 0.1), (25, 3.0, 0.3, 0.2), (14, 4.0, -0.2, 0.15)])
def test_shaper_cutter_by_gost_9323(z0, m, x0, rho_star):
    """r0 = m z0 / 2, r_b0 = r0 cos a, r_a0 = r0 + (h_a* + c* + x0) m; the involute's base half angle
    s0 / (2 r0) + inv a with s0 = m (pi/2 + 2 x0 tan a); the tip round rho_a0* m tangent to the tip circle (its
    centre r_a0 - rho from the axis, its tip point on the tip circle) and to the involute at t* (the flank point of
    the round is the involute's point there, the round's radius normal to the involute)."""
    sh = ShaperCutter(z0, m, x0, BasicRack(), rho_star)
    r0 = m * z0 / 2
    r_a0 = r0 + (1.25 + x0) * m
    assert sh.r0 == pytest.approx(r0, rel=1e-15) and sh.r_b0 == pytest.approx(r0 * math.cos(A20), rel=1e-15)
    assert sh.r_a0 == pytest.approx(r_a0, rel=1e-15) and sh.d_a0 == pytest.approx(2 * r_a0, rel=1e-15)
    s0 = m * (math.pi / 2 + 2 * x0 * math.tan(A20))
    assert sh.involute.r_b == pytest.approx(r0 * math.cos(A20), rel=1e-15)
    assert sh.involute.beta == pytest.approx(s0 / (2 * r0) + _inv(A20), rel=1e-14)
    t_s, c, a_flank, a_tip = sh.tip_round
    rho = rho_star * m
    c = np.array(c)
    assert np.linalg.norm(c) == pytest.approx(r_a0 - rho, rel=1e-13)
    tip_point = c + rho * np.array([math.cos(a_tip), math.sin(a_tip)])
    assert np.linalg.norm(tip_point) == pytest.approx(r_a0, rel=1e-13)
    flank_point = c + rho * np.array([math.cos(a_flank), math.sin(a_flank)])
    P = sh.involute.point(t_s)[0]
    assert flank_point == pytest.approx(P, abs=1e-11)
    T = sh.involute.tangent(t_s)[0]
    assert abs(float(np.dot(P - c, T))) / np.linalg.norm(T) < 1e-11        # the radius normal to the involute
    assert 0 < t_s < math.sqrt((r_a0 / sh.r_b0) ** 2 - 1)
    assert c[0] > 0                                                        # right of the tooth's centre line
    side = sh.side("centrode")
    assert side.kind == "shaper" and side.cutter == "centrode"
    assert side.fillet == ArcPiece(tuple(c), rho) and side.fillet_range == (a_tip, a_flank)
    assert side.flank is sh.involute and side.flank_range == (t_s, INVOLUTE_T_MIN)


def test_shaper_tip_round_refusals():
    """z0 = 20, m = 2: a round of 0.3 m fits (its centre 0.053 mm right of the tooth's centre line); 0.4 m would put
    it past the line (the two sides' rounds overlap); 1.8 m no longer touches both the tip circle and the involute."""
    ok = ShaperCutter(20, 2.0, 0.0, BasicRack(), 0.3).tip_round
    assert 0.0 < ok[1][0] < 0.06
    _refusal(lambda: ShaperCutter(20, 2.0, 0.0, BasicRack(), 0.4).tip_round,
             "rho_a0_star = 0.4: tip rounds of the shaper tooth overlap")
    _refusal(lambda: ShaperCutter(20, 2.0, 0.0, BasicRack(), 1.7).tip_round,
             "rho_a0_star = 1.7: tip rounds of the shaper tooth overlap")
    _refusal(lambda: ShaperCutter(20, 2.0, 0.0, BasicRack(), 1.8).tip_round,
             "rho_a0_star = 1.8: tip round does not fit the shaper tooth")
    # a tip circle inside the base circle: r0 + (h_fP* + x0) m <= r0 cos alpha, x0 <= z0 (cos alpha - 1) / 2 - 1.25
    for z0, m in ((8, 2.0), (30, 1.5)):
        x0_min = z0 * (math.cos(A20) - 1.0) / 2.0 - 1.25
        for x0 in (x0_min - 1e-3, x0_min - 0.5):
            d_a0, d_b0 = m * z0 + 2 * (1.25 + x0) * m, m * z0 * math.cos(A20)
            _refusal(lambda: ShaperCutter(z0, m, x0).tip_round,
                     f"x0 = {x0!r}: the shaper's tip circle d_a0 = {d_a0:.3f} mm lies inside its base circle d_b0 = "
                     f"{d_b0:.3f} mm: it has no involute (x0 > {x0_min:.3f} for z0 = {z0})")
        # just above the limit the tip circle clears the base circle; the round is what refuses it then
        with pytest.raises(InputError) as e:
            ShaperCutter(z0, m, x0_min + 1e-6).tip_round
        assert e.value.parameter == "rho_a0_star"


@pytest.mark.parametrize("alpha_deg, m", [(22.5, 1.0), (25.0, 2.5), (28.0, 7.0), (20.0, 3.0)])
def test_rack_cutter_with_the_largest_tip_round_is_accepted(alpha_deg, m):
    """At rho_f* = rho_f*_max the two tip rounds meet on the middle of the tool's tooth: xi_c = pi m / 2, computed
    1 to 8 ulp above it at these angles and modules (1.8e-15 mm at 28 deg, m = 7): within the tip land's tolerance."""
    bare = BasicRack(alpha=math.radians(alpha_deg), rho_f_star=0.0)
    rack = BasicRack(alpha=math.radians(alpha_deg), rho_f_star=bare.rho_f_star_max)
    rc = RackCutter(m, 0.0, rack)
    assert rc.xi_c == pytest.approx(math.pi * m / 2, abs=1e-14)
    right, left = rc.sides(3 * m)
    assert right.fillet.c[0] == pytest.approx(-left.fillet.c[0], abs=0)


def test_shaper_cutter_module_refusal_in_full():
    _refusal(lambda: ShaperCutter(20, 0.0), "m = 0.0: must be > 0 mm")
    _refusal(lambda: ShaperCutter(20, -1.5), "m = -1.5: must be > 0 mm")


def test_shaper_rack_keeps_the_depth_asked_and_its_own_largest_fillet():
    """shaper_rack(alpha, h_a*, c*): the rack of that angle and depth, its fillet ISO 53's 0.38 where the tip land
    holds it, else the largest that fits: rho_f*_max = (pi/4 - (h_a* + c*) tan a) cos a / (1 - sin a), by hand."""
    from propulsor.gears.cutters import shaper_rack

    def rho_max(a, h_fp):
        return (math.pi / 4 - h_fp * math.tan(a)) * math.cos(a) / (1 - math.sin(a))

    r = shaper_rack(A20)
    assert (r.alpha, r.h_a_star, r.c_star, r.rho_f_star) == (A20, 1.0, 0.25, 0.38)
    a = math.radians(26.0)
    r = shaper_rack(a)
    assert (r.h_a_star, r.c_star) == (1.0, 0.25) and r.rho_f_star == pytest.approx(rho_max(a, 1.25), rel=1e-14)
    assert r.rho_f_star < 0.38
    # a shallower tooth (h_a* = 0.8, c* = 0.3: 1.1 deep) keeps 0.38 at 26 deg, where the 1.25-deep one could not
    r = shaper_rack(a, 0.8, 0.3)
    assert (r.alpha, r.h_a_star, r.c_star, r.rho_f_star) == (a, 0.8, 0.3, 0.38) and rho_max(a, 1.1) > 0.38
    # at 30 deg the shallower one's own largest
    a = math.radians(30.0)
    r = shaper_rack(a, 0.8, 0.3)
    assert (r.h_a_star, r.c_star) == (0.8, 0.3) and r.rho_f_star == pytest.approx(rho_max(a, 1.1), rel=1e-14)
