"""Arm side outline (smooth majorant, fillets, section depth), revolve helpers, proximity locator."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from propulsor.geometry.arm_outline import arm_outline, section_depth, smooth_majorant
from propulsor.geometry.profile import Arc, Spline


@settings(max_examples=50, deadline=None)
@given(st.lists(st.floats(0.0, 100.0), min_size=5, max_size=200), st.floats(0.5, 10.0))
def test_majorant_never_below(y, w):
    y = np.array(y)
    m = smooth_majorant(y, 0.5, w)
    assert np.all(m >= y - 1e-12)


def test_majorant_keeps_a_plateau_flat():
    x = np.arange(0.0, 200.0, 0.5)
    y = np.where((x >= 80) & (x <= 130), 50.0, 10.0)
    m = smooth_majorant(y, 0.5, 10.0)
    # the dilation widens the plateau by w, the kernel eats w: exactly flat over its own length
    flat = (x >= 80) & (x <= 130)
    assert np.all(m[flat] == pytest.approx(50.0, abs=1e-12))
    assert m[x < 55].max() == pytest.approx(10.0) and m[x > 155].max() == pytest.approx(10.0)


@pytest.fixture(scope="module")
def arm():
    grid = np.arange(-100.0, 480.0, 1.0)
    req = 30.0 + 20.0 * np.exp(-((grid - 150.0) / 60.0) ** 2)
    return arm_outline(360.0, 80.0, 70.0, grid, req, req, 12.0, 15.0, circles=[(160.0, 75.0, 30.0)],
                       plateaus=[(220.0, 260.0, 70.0)], holes=[(160.0, 75.0, 15.0)], tol=1e-5), grid, req


def _tangent(seg, at_end: bool):
    if isinstance(seg, Arc):
        a = seg.a1 if at_end else seg.a0
        t = np.array([-math.sin(a), math.cos(a)]) * np.sign(seg.a1 - seg.a0)
        return t
    P = seg.sample(1e-7)
    d = P[-1] - P[-2] if at_end else P[1] - P[0]
    return d / np.linalg.norm(d)


def test_outline_is_closed_and_tangent_continuous(arm):
    o, _, _ = arm
    segs = o.profile.outer.segments
    assert o.profile.outer.is_closed(1e-7)
    kinds = [type(s).__name__ for s in segs]
    assert kinds.count("Spline") == 2 and kinds.count("Arc") == 6
    for i, s in enumerate(segs):  # G1 everywhere: fillets are tangent to edges and bosses
        t0, t1 = _tangent(s, True), _tangent(segs[(i + 1) % len(segs)], False)
        assert float(np.dot(t0, t1)) == pytest.approx(1.0, abs=2e-4), (i, kinds[i])


def test_fillets_touch_the_bosses(arm):
    o, _, _ = arm
    segs = o.profile.outer.segments
    boss = [s for s in segs if isinstance(s, Arc) and s.radius in (80.0, 70.0)]
    assert len(boss) == 2
    for b in boss:
        for p in (b.start, b.end):
            assert np.linalg.norm(p - np.array(b.center)) == pytest.approx(b.radius, abs=1e-9)


def test_section_depth_covers_the_requirement(arm):
    o, grid, req = arm
    x = np.linspace(0.0, 360.0, 721)
    h = section_depth(o.profile, x, chord_tol=1e-4)
    need = 2.0 * np.interp(x, grid, req)
    assert np.all(h >= need - 1e-3)
    # the pin hole sits above the core: the band about the axis is not cut by it
    assert section_depth(o.profile, [160.0])[0] == pytest.approx(2.0 * o.bottom[np.searchsorted(grid, 160.0)], abs=1e-3)
    # the plateau (stop pad) is flat: the top edge is 70 mm over its length
    assert o.top_y(np.linspace(220.0, 260.0, 41)) == pytest.approx(np.full(41, 70.0), abs=1e-9)


def test_profile_area_against_its_parts(arm):
    o, _, _ = arm
    A = o.profile.area(1e-4)
    # bigger than the two boss discs plus the required band between them, minus the hole
    band = 2 * 30.0 * (360.0 - 80.0 - 70.0)
    assert A > math.pi * 80.0**2 + math.pi * 70.0**2 + band - math.pi * 15.0**2


# ------------------------------------------------------------------ revolve helpers
def test_revolved_section_volume_is_pappus():
    from propulsor.geometry.profile import Profile, polygon_loop
    from propulsor.solids.kernel import cut, cylinder, fuse
    from propulsor.solids.revolve import revolve_section

    sec = Profile(polygon_loop([(20.0, 0.0), (50.0, 0.0), (50.0, 30.0), (20.0, 30.0)]))
    ring = revolve_section(sec, center=(100.0, 5.0))
    assert ring.isValid()
    assert ring.Volume() == pytest.approx(math.pi * (50**2 - 20**2) * 30.0, rel=1e-9)
    bb = ring.BoundingBox()
    assert (bb.xmin, bb.xmax, bb.ymin, bb.ymax) == pytest.approx((50.0, 150.0, -45.0, 55.0), abs=1e-6)
    holed = cut(ring, cylinder(5.0, -1.0, 31.0, center=(135.0, 5.0)))
    assert holed.Volume() == pytest.approx(ring.Volume() - math.pi * 25.0 * 30.0, rel=1e-6)
    both = fuse(ring, cylinder(10.0, 30.0 - 5.0, 60.0, center=(100.0 + 35.0, 5.0)))
    assert both.Volume() == pytest.approx(ring.Volume() + math.pi * 100.0 * 30.0, rel=1e-6)
    side = cylinder(3.0, 0.0, 100.0, center=(0.0, 15.0), axis="x")
    assert side.BoundingBox().xmax == pytest.approx(100.0)


# ------------------------------------------------------------------ proximity locator
def test_nearest_points_between_two_boxes_and_a_cylinder():
    import manifold3d as m3d

    from propulsor.checks.proximity import nearest_points

    A = m3d.Manifold.cube([100.0, 80.0, 20.0])
    B = m3d.Manifold.cube([50.0, 50.0, 30.0]).translate([20.0, 10.0, 37.0])  # 17 mm above A's top face
    assert A.min_gap(B, 50.0) == pytest.approx(17.0)
    d, pa, pb = nearest_points(A, B, 20.0, spacing=1.0)
    assert d == pytest.approx(17.0, abs=1e-4)  # manifold3d meshes hold float32 vertices
    assert pa[2] == pytest.approx(20.0, abs=1e-4) and pb[2] == pytest.approx(37.0, abs=1e-4)
    assert 20.0 - 1e-4 <= pa[0] <= 70.0 + 1e-4 and 10.0 - 1e-4 <= pa[1] <= 60.0 + 1e-4
    C = m3d.Manifold.cylinder(40.0, 10.0, 10.0, 128).translate([150.0, 40.0, -10.0])  # 40 mm from A's +x face
    d, pa, pb = nearest_points(A, C, 45.0, spacing=0.5)
    assert d == pytest.approx(40.0, abs=0.5)
    assert pa[0] == pytest.approx(100.0, abs=1e-4) and pb[0] == pytest.approx(140.0, abs=0.05)
    assert pb[1] == pytest.approx(40.0, abs=1.0)
