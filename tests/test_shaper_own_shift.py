"""A shaper with its own profile shift x0 cuts the flank of the rack (issue 10, acceptance 3).

The reference is a circular internal gear computed here from the ISO 21771 / GOST 16532 sheet:
ring z = 60, m = 2 mm, x = +0.2, alpha = 20 deg; its space width on the reference circle is
e = m (pi/2 + 2 x tan alpha), so the right flank of the space on +y has the polar angle (from +y)
psi(r_y) = e / (2 r) + inv(alpha) - inv(alpha_y), cos(alpha_y) = r_b / r_y.  Catalogue shapers
(GOST 9323 d0 = 38 and 50 mm, x0 = 0, and x0 = +0.45, -0.1 made up to move far from x0 = -x)
generate it with the cutting position e = (x_r + x0) m of ``envelope.ShaperOnRackCentrode``;
the flank must lie on the analytic involute, on the flank the GOST 19274 cutting centre distance
gives (``generation.generate_internal_side``), and on the flank the rack cuts, within 0.5 um.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.gears.catalogue import catalogue_shaper, rack_profile, rack_profiles, shaper_entry
from propulsor.gears.cutters import CutterSide, RackCutter, ShaperCutter
from propulsor.gears.envelope import ExternalCircleCentrode, InternalCircleCentrode, ShaperOnRackCentrode
from propulsor.gears.generation import generate_internal_side
from propulsor.gears.involute import BasicRack, inv

Z, M, X = 60, 2.0, 0.2
ALPHA = math.radians(20.0)
R = M * Z / 2
RB = R * math.cos(ALPHA)
TOL_MM = 0.5e-3


def _space_angle(ry):
    """ISO 21771: polar angle of the right flank of the ring space on +y at radius ry."""
    e = M * (math.pi / 2 + 2 * X * math.tan(ALPHA))
    a_y = np.arccos(RB / ry)
    return e / (2 * R) + float(inv(ALPHA)) - (np.tan(a_y) - a_y)


def _normal_distance(P, space_centre=0.0):
    """Distance along the involute normal from points P to the nearest flank of the ISO 21771 ring
    (either flank of any space; one space centred at the polar angle ``space_centre`` from +y):
    r_b times the angular offset between two involutes of one base."""
    ry = np.hypot(P[:, 0], P[:, 1])
    pitch = 2 * math.pi / Z
    pol = np.arctan2(P[:, 0], P[:, 1]) - space_centre
    best = np.full(len(P), np.inf)
    for sgn in (1.0, -1.0):  # right flank of a space, or a left flank (mirror)
        d = sgn * pol - _space_angle(ry)
        d = (d + pitch / 2) % pitch - pitch / 2
        best = np.minimum(best, np.abs(d))
    return RB * best


def _flank_inside(curve, r_lo, r_hi, n=300):
    X_ = curve(np.linspace(curve.u0, curve.u1, n))
    r = np.hypot(X_[:, 0], X_[:, 1])
    return X_[(r > r_lo) & (r < r_hi)]


def _own_shift_sides(sh: ShaperCutter, x_rack: float):
    """Right and left sides of the shaper meshing with the rack of shift x_rack rolling inside the ring."""
    R0 = sh.r0
    e = (x_rack + sh.x0) * M
    c = e / math.tan(ALPHA)
    base = sh.side(ExternalCircleCentrode(R0))
    out = []
    for mir, cut in ((False, ShaperOnRackCentrode(R0, e, c)), (True, ShaperOnRackCentrode(R0, e, -c))):
        b = base.placed(-math.pi + math.pi / sh.z0, (0.0, R0), mir)
        out.append(CutterSide(b.fillet, b.fillet_range, b.flank, b.flank_range, cut, "shaper"))
    return out


@pytest.mark.parametrize("shaper", [
    catalogue_shaper(38.0, M), catalogue_shaper(50.0, M),
    ShaperCutter(19, M, 0.45), ShaperCutter(25, M, -0.1),
], ids=lambda s: f"z0={s.z0},x0={s.x0:+g}")
def test_own_shift_shaper_cuts_the_iso_ring_flank(shaper):
    assert abs(shaper.x0 - X) >= 0.2  # far from the tied x0 = -x_rack of the old generator
    d_a = M * (Z - 2 * (1.0 - X))
    gost = generate_internal_side(Z, M, X, d_a, shaper)
    r_lo, r_hi = gost.r_a + 1e-3, gost.r_Ff - 1e-3
    ring = InternalCircleCentrode(R)
    # the GOST 19274 cut (cutting centre distance a_w0 from inv alpha_w0) is the reference's flank
    assert np.max(_normal_distance(_flank_inside(gost.flank, r_lo, r_hi))) < TOL_MM
    for side in _own_shift_sides(shaper, -X):
        P = _flank_inside(side.envelopes(ring)[1], r_lo, r_hi)
        assert len(P) > 100
        # analytic involute of the ISO sheet within 0.5 um (measured: ~1e-11 mm); these tools
        # leave a ring TOOTH on +y (envelope.InternalCircleCentrode), so a space at half a pitch
        assert np.max(_normal_distance(P, math.pi / Z)) < TOL_MM
        # the rack that both tools stand for cuts the same flank
    for side in RackCutter(M, -X, BasicRack()).sides(3 * M):
        P = _flank_inside(side.envelopes(ring)[1], r_lo, r_hi)
        assert np.max(_normal_distance(P, math.pi / Z)) < TOL_MM


def test_wrong_phase_misses_the_flank():
    """The per-flank phase c = e cot(alpha) matters: without it the flank is off (measured 4.9 um,
    ten times the tolerance; second order in e on a circle, first order where the curvature varies)."""
    sh = catalogue_shaper(38.0, M)
    e = (-X + sh.x0) * M
    base = sh.side(ExternalCircleCentrode(sh.r0)).placed(-math.pi + math.pi / sh.z0, (0.0, sh.r0), False)
    side = CutterSide(base.fillet, base.fillet_range, base.flank, base.flank_range,
                      ShaperOnRackCentrode(sh.r0, e, 0.0), "shaper")
    P = _flank_inside(side.envelopes(InternalCircleCentrode(R))[1], R - 1.0, R + 1.0)
    assert np.min(_normal_distance(P, math.pi / Z)) > 4 * TOL_MM


def test_catalogue():
    assert rack_profiles() == ("A", "B", "C", "D")
    a, d = rack_profile("A"), rack_profile("D")
    assert (a.rho_f_star, a.h_fP_star) == (0.38, 1.25)      # ISO 53 profile A
    assert d.h_fP_star == pytest.approx(1.40) and d.rho_f_star == 0.39
    e = shaper_entry(25.0, 2.0)
    assert e.z0 * e.m == pytest.approx(24.0)                  # d0 = m z0 near the nominal 25 mm
    assert catalogue_shaper(100.0, 2.5).r_a0 == pytest.approx(50.0 + 1.25 * 2.5)
    with pytest.raises(InputError, match="nominal d0"):
        shaper_entry(30.0, 2.0)
    with pytest.raises(InputError, match="modules listed"):
        shaper_entry(25.0, 7.0)
