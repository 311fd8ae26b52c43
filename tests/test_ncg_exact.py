"""The non-circular pair's as-built transmission, tolerance study and load per tooth, number by number
(parts/noncircular_pair/as_built.py, tolerance.py, tooth_load_outputs.py): every value computed in the test from
its formula written out, on small inputs built in each test (synthetic contact laws of the real drive laws, polygons
whose tooth centres are known, the elliptical part file's pair where the finished outlines are meant).

Fast and in this process, for mutation testing (mutation/targets.toml, target ``noncircular_pair``): mutmut ties a
test only to the functions it calls itself, so nothing is built at collection or in a module-scoped fixture.
"""

from __future__ import annotations

import bisect
import math
import random
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from propulsor.checks.motion import outline
from propulsor.checks.motion.contact_events import DRIVE, REVERSE, ContactLaw, PairOutlines, resolve_contact
from propulsor.laws.ratio_laws import EllipticalLaw
from propulsor.laws.walking import WalkingLaw
from stand_ins import record_generate_pair

PARTS = Path(__file__).resolve().parent.parent / "parts"


def _elliptical_design():
    """The elliptical part file's pair (e = 0.3, 1:1, z 30/30, m = 2.5): about 1 s."""
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams, design

    _, mapping = read_part_file(PARTS / "ncg_elliptical.toml")
    p = load_params(NoncircularPairParams, mapping)
    return p, design(p)


def _small_design():
    """The elliptical part file with 18 teeth a wheel and e = 0.1 (the fewest it generates: the tooth changes the
    contact bisects are most of a case's cost)."""
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams, design

    _, mapping = read_part_file(PARTS / "ncg_elliptical.toml")
    mapping.update(driven_teeth=18, eccentricity=0.1)
    return design(load_params(NoncircularPairParams, mapping))


def _cl(direction, phi, te, kind=None, theta=None, evaluations=7):
    """A contact law of the given samples (driver angle theta = phi unless given; flank contact unless given)."""
    phi = np.asarray(phi, float)
    n = len(phi)
    return ContactLaw(direction, phi, np.asarray(phi if theta is None else theta, float), np.asarray(te, float),
                      np.asarray(np.zeros(n, int) if kind is None else kind), np.zeros(n, int), np.zeros(n, int),
                      evaluations)


def _speed_by_hand(law, run_law, phi, te, samples):
    """v/omega = dX01/dphi(phi + te) (1 + te') / U(phi), te linear between the samples, on the grid of ``samples``
    equal steps and the samples' mid-points; te' the slope of the interval a point opens (the last: the last's)."""
    phi, te = list(map(float, phi)), list(map(float, te))
    pts = sorted(set(np.linspace(phi[0], phi[-1], samples).tolist())
                 | {0.5 * (a + b) for a, b in zip(phi[:-1], phi[1:])})
    x, slope, shift = [], [], []
    for g in pts:
        k = min(max(bisect.bisect_right(phi, g) - 1, 0), len(phi) - 2)
        s = (te[k + 1] - te[k]) / (phi[k + 1] - phi[k])
        x.append(g)
        slope.append(s)
        shift.append(te[k] + s * (g - phi[k]))
    x, slope, shift = np.array(x), np.array(slope), np.array(shift)
    return x, np.asarray(law.dX01_dphi(x + shift), float) * (1.0 + slope) / np.asarray(run_law.U(x), float)


# =========================================================================== as_built.py
def test_as_built_speed_takes_each_intervals_chord_slope_and_the_law_the_teeth_realise():
    """Walking law (seed 000) for dX01/dphi, a different one for U (the teeth's law); te with a kink at a sample the
    grid holds (the slope there is the next interval's) and the grid's last point (the last interval's)."""
    from propulsor.parts.noncircular_pair.as_built import as_built_speed

    law, run = WalkingLaw(60.0, 100.0, 360.0, 2), WalkingLaw(60.0, 80.0, 360.0, 2)
    node = float(np.linspace(0.0, 0.3, 4)[1])
    phi, te = np.array([0.0, node, 0.3]), np.array([0.0, 0.002, -0.001])
    grid, v = as_built_speed(law, run, phi, te, samples=4)
    x, want = _speed_by_hand(law, run, phi, te, 4)
    assert grid.tolist() == x.tolist()
    assert len(grid) == 5  # 0, 0.1, 0.2, 0.3 and the mid-points 0.05, 0.2 (0.2 once)
    np.testing.assert_allclose(v, want, rtol=1e-13, atol=0)
    # at the kink the next interval's slope: te' = -0.003 / 0.2 = -0.015
    i = int(np.nonzero(grid == node)[0][0])
    assert v[i] == pytest.approx(float(law.dX01_dphi(node + 0.002)) * (1 - 0.015) / float(run.U(node)), rel=1e-14)
    # at the end the last interval's slope
    assert v[-1] == pytest.approx(float(law.dX01_dphi(0.3 - 0.001)) * (1 - 0.015) / float(run.U(0.3)), rel=1e-14)
    # a constant te at the law: the hub speed A/u exactly (seed 000 eq. 2-3)
    _, v0 = as_built_speed(law, law, phi, np.zeros(3), samples=5)
    np.testing.assert_allclose(v0, law.hub_speed_ratio, rtol=1e-13)


def test_as_built_speed_samples_twenty_thousand_and_one_points_by_default():
    from propulsor.parts.noncircular_pair.as_built import as_built_speed

    law = WalkingLaw(60.0, 100.0, 360.0, 2)
    phi, te = np.array([0.0, 0.31234, 1.0]), np.array([0.0, 0.001, 0.0])
    grid, v = as_built_speed(law, law, phi, te)
    x, want = _speed_by_hand(law, law, phi, te, 20001)
    assert len(grid) == 20003 and grid.tolist() == x.tolist()
    np.testing.assert_allclose(v, want, rtol=1e-13, atol=0)


def test_period_span_is_one_period_where_the_periods_hold_whole_driven_teeth():
    from propulsor.parts.noncircular_pair.as_built import period_span

    def span(law, z_H):
        return period_span(SimpleNamespace(run_law=law, z_H=z_H))

    assert span(EllipticalLaw(0.3, 2), 30) == math.pi
    assert span(EllipticalLaw(0.3, 2), 31) == 2 * math.pi
    assert span(EllipticalLaw(0.3, 3), 30) == 2 * math.pi / 3
    assert span(EllipticalLaw(0.3, 3), 32) == 2 * math.pi
    assert span(EllipticalLaw(0.3, 1), 30) == 2 * math.pi
    assert span(WalkingLaw(100.0, 50.0, 236.5, 4), 80) == 2 * math.pi / 4
    assert span(WalkingLaw(100.0, 50.0, 236.5, 4), 82) == 2 * math.pi
    # a law without periods (or periods None) repeats once a turn
    assert span(SimpleNamespace(), 30) == 2 * math.pi
    assert span(SimpleNamespace(periods=None), 30) == 2 * math.pi


def _combine_case():
    """Two directions sampled at different driven angles, one lost sample each."""
    drive = _cl(DRIVE, [0.1, 0.4, 0.9, 1.3], [-0.002, -0.001, math.nan, -0.003], evaluations=11)
    reverse = _cl(REVERSE, [0.2, 0.6, 1.2, 1.5], [0.001, 0.004, math.nan, 0.0005], evaluations=5)
    x = np.array([0.1, 0.2, 0.4, 0.6, 0.9, 1.2, 1.3, 1.5])
    # drive through (0.1, -2e-3), (0.4, -1e-3), (1.3, -3e-3), held beyond the ends
    ted = np.array([-0.002, -0.002 + 0.001 / 3, -0.001, -0.001 - 0.002 * 0.2 / 0.9, -0.001 - 0.002 * 0.5 / 0.9,
                    -0.001 - 0.002 * 0.8 / 0.9, -0.003, -0.003])
    # reverse through (0.2, 1e-3), (0.6, 4e-3), (1.5, 0.5e-3)
    ter = np.array([0.001, 0.001, 0.0025, 0.004, 0.004 - 0.0035 / 3, 0.004 - 0.0035 * 2 / 3,
                    0.004 - 0.0035 * 0.7 / 0.9, 0.0005])
    return drive, reverse, x, ted, ter


def test_combine_the_least_backlash_is_the_two_directions_gap_on_the_driven_pitch_curve():
    """Elliptical law e = 0.3 (no hub): backlash (te_reverse - te_drive) r_H, r_H = L U / (1 + U) with the teeth's
    law (not the mechanism's), on the union of both directions' samples; the span is the drive's."""
    from propulsor.parts.noncircular_pair.as_built import combine

    law, run = EllipticalLaw(0.3, 1), EllipticalLaw(0.2, 1)
    L = 80.0
    drive, reverse, x, ted, ter = _combine_case()
    U = np.asarray(run.U(x), float)
    bl = (ter - ted) * L * U / (1 + U)
    ab = combine(SimpleNamespace(law=law, run_law=run, L=L), drive, reverse)
    assert ab.drive is drive and ab.reverse is reverse and ab.directions == (drive, reverse)
    assert ab.span == pytest.approx(1.2, abs=1e-15)
    assert ab.hub == () and math.isnan(ab.ripple)
    k = int(np.argmin(bl))
    assert k == 1 and int(np.argmax(bl)) not in (0, 1, 7)  # neither end of the union
    assert ab.backlash_min_mm == pytest.approx(bl[k], rel=1e-13)
    assert ab.backlash_max_mm == pytest.approx(np.max(bl), rel=1e-13)
    assert ab.backlash_min_phi == 0.2
    assert ab.evaluations == 16
    # the least backlash inside the span: the drive's te raised at 0.9 .. 1.3
    drive2 = _cl(DRIVE, [0.1, 0.4, 0.9, 1.3], [-0.002, -0.001, 0.0035, -0.003])
    ab2 = combine(SimpleNamespace(law=law, run_law=run, L=L), drive2, reverse)
    ted2 = np.interp(x, [0.1, 0.4, 0.9, 1.3], [-0.002, -0.001, 0.0035, -0.003])
    bl2 = (ter - ted2) * L * U / (1 + U)
    assert int(np.argmin(bl2)) == 4 and bl2[4] == pytest.approx((0.004 - 0.0035 / 3 - 0.0035) * float(
        L * U[4] / (1 + U[4])), rel=1e-12)
    assert (ab2.backlash_min_mm, ab2.backlash_min_phi) == (pytest.approx(bl2[4], rel=1e-13), 0.9)


def _hub_by_hand(law, run, phi, te):
    ok = np.isfinite(te)
    x, v = _speed_by_hand(law, run, np.asarray(phi)[ok], np.asarray(te)[ok], 20001)
    mean = law.A / law.u
    i, j = int(np.argmin(v)), int(np.argmax(v))
    return (v[j] - v[i]) / mean, v[i] / mean, v[j] / mean, x[i], x[j]


def test_combine_of_a_walking_law_gives_each_directions_hub_speed_over_A_over_u():
    """Walking law: (HubSpeed drive, HubSpeed reverse): ripple (max - min) / mean, the least and largest over the
    mean A/u and their driven angles, from each direction's own finite samples."""
    from propulsor.parts.noncircular_pair.as_built import HubSpeed, combine

    law, run = WalkingLaw(60.0, 100.0, 360.0, 2), WalkingLaw(60.0, 90.0, 360.0, 2)
    drive = _cl(DRIVE, [0.0, 0.2, 0.5, 0.7, 0.78], [-0.002, -0.0015, math.nan, -0.003, -0.0021])
    reverse = _cl(REVERSE, [0.0, 0.3, 0.6, 0.78], [0.001, 0.0012, 0.002, math.nan])
    ab = combine(SimpleNamespace(law=law, run_law=run, L=300.0), drive, reverse)
    assert len(ab.hub) == 2 and all(isinstance(h, HubSpeed) for h in ab.hub)
    for h, c in zip(ab.hub, (drive, reverse)):
        ripple, lo, hi, at_lo, at_hi = _hub_by_hand(law, run, c.phi, c.te)
        assert h.ripple == pytest.approx(ripple, rel=1e-12)
        assert (h.v_min_rel, h.v_max_rel) == (pytest.approx(lo, rel=1e-13), pytest.approx(hi, rel=1e-13))
        assert (h.phi_min, h.phi_max) == (at_lo, at_hi)
    assert ab.ripple == max(h.ripple for h in ab.hub) and ab.hub[0].ripple != ab.hub[1].ripple


def test_corner_run_is_the_longer_of_the_two_directions_named_with_its_start():
    """A run of corner samples reaches half-way to its neighbours: drive corners at theta 0.2, 0.3 (neighbours 0.1,
    0.45): 0.1 + 0.05 + 0.075 rad; reverse corners at 0.5 .. 0.9 then the end: 0.4 + 0.05 + 0 rad."""
    from propulsor.parts.noncircular_pair.as_built import combine

    law = EllipticalLaw(0.3, 1)
    d = SimpleNamespace(law=law, run_law=law, L=80.0)
    th = [0.0, 0.1, 0.2, 0.3, 0.45, 0.5, 0.6, 0.9]
    drive = _cl(DRIVE, th, [-1e-3] * 8, kind=[0, 0, 1, 2, 0, 0, 0, 0])
    reverse = _cl(REVERSE, th, [1e-3] * 8, kind=[0, 0, 0, 0, 0, 3, 1, 4])
    run_d, run_r = math.degrees(0.1 + 0.05 + 0.075), math.degrees(0.4 + 0.025 + 0.0)
    assert run_r > run_d
    best, where = combine(d, drive, reverse).corner_run_max_deg()
    assert best == pytest.approx(run_r, rel=1e-13)
    assert where == f"reverse at driver {math.degrees(0.5):.3f} deg" == "reverse at driver 28.648 deg"
    best, where = combine(d, drive, _cl(REVERSE, th, [1e-3] * 8)).corner_run_max_deg()
    assert best == pytest.approx(run_d, rel=1e-13) and where == "drive at driver 11.459 deg"
    # equal runs: the first direction's; none: 0 and nothing named
    best, where = combine(d, drive, _cl(REVERSE, th, [1e-3] * 8, kind=[0, 0, 1, 2, 0, 0, 0, 0])).corner_run_max_deg()
    assert where.startswith("drive at")
    assert combine(d, _cl(DRIVE, th, [0.0] * 8), _cl(REVERSE, th, [0.0] * 8)).corner_run_max_deg() == (0.0, "")


def _polygon(n, r, start):
    t = start + 2 * math.pi * np.arange(n) / n
    return np.column_stack([r * np.cos(t), r * np.sin(t)])


def _mid_pairs(angles):
    a = sorted(math.atan2(math.sin(t), math.cos(t)) for t in angles)
    return [0.5 * (a[i] + a[i + 1]) for i in range(0, len(a) - 1, 2)]


def test_outlines_without_a_tooth_record_take_their_teeth_from_pairs_of_convex_corners():
    """An octagon (corners turning 45 deg: more than the 20 deg of a corner, less than 1 rad) and a heptagon (an odd
    count: the last corner unpaired) as outlines of wheels without a tooth record: the tooth centres are the mid-angles
    of their convex corners sorted and taken in pairs.  A 100-gon (3.6 deg turns) has no corner: one tooth at 0; a
    half disc two corners, one tooth between them."""
    from propulsor.parts.noncircular_pair.as_built import pair_outlines

    law = EllipticalLaw(0.3, 1)
    octagon, heptagon = _polygon(8, 20.0, 0.1), _polygon(7, 15.0, -0.3)
    d = SimpleNamespace(run_law=law, driver=SimpleNamespace(profile=[octagon]),
                        driven=SimpleNamespace(profile=[heptagon], teeth=[]))
    pair = pair_outlines(d, 41.5)
    assert pair.L == 41.5
    np.testing.assert_allclose(pair.driver_teeth, _mid_pairs(0.1 + 2 * math.pi * np.arange(8) / 8), atol=1e-12)
    assert len(pair.driven_teeth) == 3
    np.testing.assert_allclose(pair.driven_teeth, _mid_pairs(-0.3 + 2 * math.pi * np.arange(7) / 7), atol=1e-12)
    np.testing.assert_array_equal(pair.drv.points, outline([octagon]).points)
    np.testing.assert_array_equal(pair.dvn.points, outline([heptagon]).points)
    t = np.linspace(0.0, math.pi, 60)
    half = np.vstack([np.column_stack([10 * np.cos(t + 0.3), 10 * np.sin(t + 0.3)])])
    circle = _polygon(100, 12.0, 0.0)
    # teeth without their centres (sector teeth): the corners too
    d2 = SimpleNamespace(run_law=law, driver=SimpleNamespace(profile=[circle], teeth=[SimpleNamespace()]),
                         driven=SimpleNamespace(profile=[half]))
    pair2 = pair_outlines(d2, 30.0)
    assert pair2.driver_teeth.tolist() == [0.0]
    np.testing.assert_allclose(pair2.driven_teeth, [0.5 * (0.3 + 0.3 + math.pi - 2 * math.pi)], atol=1e-12)


def test_pair_outlines_of_the_generated_pair_name_the_tooth_centres_by_the_law():
    """The generated pair: the outer loops at the motion chord 1e-4 mm; driven teeth at their body angles, driver
    teeth at pi - theta(phi_centre) (the driver faces the driven wheel across the centre line)."""
    from propulsor.parts.noncircular_pair.as_built import pair_outlines

    _, d = _elliptical_design()
    pair = pair_outlines(d, d.L + 0.05)
    assert pair.L == d.L + 0.05
    np.testing.assert_array_equal(pair.driven_teeth, [t.phi_centre for t in d.driven.teeth])
    want = [math.pi - float(d.law.theta(np.array([t.phi_centre]))[0]) for t in d.driver.teeth]
    np.testing.assert_allclose(pair.driver_teeth, want, rtol=0, atol=1e-15)
    assert len(want) == 30 and want[0] == pytest.approx(math.pi)
    np.testing.assert_array_equal(pair.drv.points, outline([d.driver.profile.outer.polyline(1e-4)]).points)
    np.testing.assert_array_equal(pair.dvn.points, outline([d.driven.profile.outer.polyline(1e-4)]).points)


def test_as_built_resolves_both_directions_over_one_period_and_none_after_a_jam(monkeypatch):
    """The elliptical pair at 6 deg of driver: each direction the contact of resolve_contact over 0 .. 2 pi (one
    lobe: the whole turn) of the driven wheel, counted to the build through parallel.tick; a proof with a jam or
    a phase without a running position gives None."""
    from propulsor import job_ticks
    from propulsor.parts.noncircular_pair.as_built import as_built, contact_direction, pair_outlines

    _, d = _elliptical_design()
    step = math.radians(6.0)
    mount = d.L + 0.02
    ticks = []

    def tick(done, total):
        # 6 deg of driver: 61 samples and their bisections; the default 0.05 deg would be 7201 samples (minutes)
        assert total < 3000, f"{total} positions: not the 6 deg step asked for"
        ticks.append((done, total))

    monkeypatch.setattr(job_ticks, "_TICK", tick)
    one = contact_direction(d, mount, REVERSE, step)
    assert ticks and ticks[-1][0] == ticks[-1][1] == one.evaluations
    po = pair_outlines(d, mount)
    want = {k: resolve_contact(po, d.law.theta, 0.0, 2 * math.pi, k, step_driver_rad=step) for k in (DRIVE, REVERSE)}
    np.testing.assert_array_equal(one.te, want[REVERSE].te)
    np.testing.assert_array_equal(one.phi, want[REVERSE].phi)
    ab = as_built(d, mount, SimpleNamespace(jams=[], phi_drive=np.array([0.0, 0.1])), step)
    assert ab.drive.direction == DRIVE and ab.reverse.direction == REVERSE
    for c in (DRIVE, REVERSE):
        got = ab.drive if c == DRIVE else ab.reverse
        np.testing.assert_array_equal(got.phi, want[c].phi)
        np.testing.assert_array_equal(got.te, want[c].te)
    assert ab.span == 2 * math.pi
    x = np.union1d(want[DRIVE].phi, want[REVERSE].phi)
    U = np.asarray(d.law.U(x), float)
    bl = (np.interp(x, want[REVERSE].phi, want[REVERSE].te) - np.interp(x, want[DRIVE].phi, want[DRIVE].te)) \
        * d.L * U / (1 + U)
    assert ab.backlash_min_mm == pytest.approx(float(np.min(bl)), rel=1e-12)
    assert 0.18 < ab.backlash_min_mm < 0.19  # 0.170 at L, 2 tan(20 deg) 0.02 mm more
    assert as_built(d, mount, SimpleNamespace(jams=[(0.1, "x")], phi_drive=np.array([0.0, 0.1])), step) is None
    assert as_built(d, mount, SimpleNamespace(jams=[], phi_drive=np.array([0.0, math.nan])), step) is None


# =========================================================================== tolerance.py
def test_iso_286_standard_tolerance_by_grade_with_its_ends_held():
    """IT_A = mult i, i = 0.45 L^(1/3) + 0.001 L um: at L = 27 mm, i = 1.35 + 0.027 = 1.377 um; IT5 7 i .. IT12 160 i,
    grades below 5 as 5, above 12 as 12, a fractional grade as its whole part."""
    from propulsor.parts.noncircular_pair.tolerance import _it

    i = 1.377e-3
    for grade, mult in ((5, 7), (6, 10), (7, 16), (8, 25), (9, 40), (10, 64), (11, 100), (12, 160), (4, 7), (1, 7),
                        (13, 160), (18, 160), (8.7, 25)):
        assert _it(27.0, grade) == pytest.approx(mult * i, rel=1e-12), grade
    # L = 1000: i = 4.5 + 1 = 5.5 um (the linear term)
    assert _it(1000.0, 8) == pytest.approx(25 * 5.5e-3, rel=1e-12)


def test_iso_1328_radial_runout_by_hand():
    """F_r = 0.8 (0.3 m + 1.25 sqrt(d) + 7) 2^((A - 5)/2) um: m = 2, d = 64: 0.8 (0.6 + 10 + 7) = 14.08 um at grade 5,
    twice at 7, sqrt 2 times at 6."""
    from propulsor.parts.noncircular_pair.tolerance import _runout

    assert _runout(2.0, 64.0, 5) == pytest.approx(14.08e-3, rel=1e-12)
    assert _runout(2.0, 64.0, 7) == pytest.approx(28.16e-3, rel=1e-12)
    assert _runout(2.0, 64.0, 6) == pytest.approx(14.08e-3 * math.sqrt(2), rel=1e-12)
    assert _runout(4.0, 100.0, 5) == pytest.approx(0.8 * (1.2 + 12.5 + 7.0) * 1e-3, rel=1e-12)


def test_iso1328_tolerances_of_each_wheel_and_their_source_in_full():
    """m = 2, driver z 32 (d 64), driven z 50 (d 100), L = 27 mm, grade 7, alpha 25 deg: F_r 28.16 / 32.16 um,
    f_a = IT7/2 = 16 x 1.377 / 2 = 11.016 um, flanks thinner by 0 .. 32.16 tan 25 deg = 14.997 um; the larger run-out
    sets the thinning whichever wheel has it."""
    from propulsor.parts.noncircular_pair.tolerance import Tolerances, iso1328

    D = SimpleNamespace(m=2.0, z=32, z_H=50)
    t = iso1328(D, 27.0, 7, math.radians(25.0))
    thin = 32.16e-3 * math.tan(math.radians(25.0))
    assert t == Tolerances(pytest.approx(11.016e-3, rel=1e-12), pytest.approx(14.08e-3, rel=1e-12),
                           pytest.approx(16.08e-3, rel=1e-12), 0.0, pytest.approx(thin, rel=1e-12), t.source)
    assert t.source == ("ISO 1328 grade 7: F_r 28.2 / 32.2 um (driver / driven), f_a = IT7/2 = 11.0 um, flanks "
                        "thinner by 0 .. 15.0 um")
    # the driver the larger wheel; the defaults grade 8 and alpha 20 deg
    D2 = SimpleNamespace(m=2.0, z=50, z_H=32)
    t8 = iso1328(D2, 27.0)
    F1, F2 = 0.8 * (0.6 + 12.5 + 7.0) * 2 ** 1.5e0 * 1e-3, 0.8 * (0.6 + 10.0 + 7.0) * 2 ** 1.5 * 1e-3
    assert (t8.e_driver, t8.e_driven) == (pytest.approx(F1 / 2, rel=1e-12), pytest.approx(F2 / 2, rel=1e-12))
    assert t8.f_a == pytest.approx(25 * 1.377e-3 / 2, rel=1e-12)
    assert (t8.t_lo, t8.t_hi) == (0.0, pytest.approx(F1 * math.tan(math.radians(20.0)), rel=1e-12))
    assert t8.source == (f"ISO 1328 grade 8: F_r {1e3 * F1:.1f} / {1e3 * F2:.1f} um (driver / driven), f_a = IT8/2 = "
                         f"17.2 um, flanks thinner by 0 .. {1e3 * F1 * 0.36397023426620234:.1f} um")
    assert t8.source.startswith("ISO 1328 grade 8: F_r 45.5 / 39.8 um")


def test_printed_tolerances_and_their_source_in_full():
    from propulsor.parts.noncircular_pair.tolerance import Tolerances, printed

    t = printed(0.15, 0.25)
    assert t == Tolerances(0.15, 0.25, 0.25, -0.15, 0.15, "printed: edges +- 0.15 mm (xy accuracy), run-out 0.25 mm "
                           "(the pins' running clearance), centre distance +- 0.15 mm")


def test_worst_cases_are_the_tight_and_loose_corners_with_the_runouts_in_phase_and_opposed():
    from propulsor.parts.noncircular_pair.tolerance import Case, Tolerances, worst_cases

    tol = Tolerances(0.03, 0.011, 0.017, -0.004, 0.021, "s")
    assert worst_cases(tol) == [
        Case("tight, run-outs in phase", -0.03, 0.011, 0.0, 0.017, 0.0, -0.004, -0.004),
        Case("tight, run-outs opposed", -0.03, 0.011, 0.0, 0.017, math.pi, -0.004, -0.004),
        Case("loose, run-outs in phase", 0.03, 0.011, 0.0, 0.017, 0.0, 0.021, 0.021),
        Case("loose, run-outs opposed", 0.03, 0.011, 0.0, 0.017, math.pi, 0.021, 0.021)]


def test_monte_carlo_cases_draw_each_deviation_uniformly_in_its_range_from_the_seed():
    """uniform(a, b) = a + (b - a) random(): dL, e_driver, psi_driver, e_driven, psi_driven, t_driver, t_driven in
    that order, case after case, from random.Random(seed)."""
    from propulsor.parts.noncircular_pair.tolerance import Case, Tolerances, monte_carlo_cases

    tol = Tolerances(0.03, 0.011, 0.017, -0.004, 0.021, "s")
    r = random.Random(5)

    def u(a, b):
        return a + (b - a) * r.random()

    want = [Case(f"sample {k}", u(-0.03, 0.03), u(0.0, 0.011), u(0.0, 2 * math.pi), u(0.0, 0.017),
                 u(0.0, 2 * math.pi), u(-0.004, 0.021), u(-0.004, 0.021)) for k in (1, 2, 3)]
    got = monte_carlo_cases(tol, 3, 5)
    assert [c.name for c in got] == ["sample 1", "sample 2", "sample 3"]
    for g, w in zip(got, want):
        assert g == Case(w.name, *(pytest.approx(getattr(w, f), rel=1e-14, abs=1e-18) for f in
                                   ("dL", "e_driver", "psi_driver", "e_driven", "psi_driven", "t_driver", "t_driven")))
    assert len(got) == 3 and monte_carlo_cases(tol, 0, 5) == []
    assert monte_carlo_cases(tol, 2, 6)[0] != got[0]


def test_a_changed_outline_is_offset_along_its_normals_and_turns_off_its_axis():
    """A 720-gon of radius 20 thinned by 0.3 mm about a centre 0.5 mm off at psi = 2 rad: every vertex 19.7 mm from
    (0.5 cos 2, 0.5 sin 2) to the polygon's sagitta; thickened by 0.3 mm: 20.3 mm; no thinning: the same vertices
    moved."""
    from propulsor.parts.noncircular_pair.tolerance import _changed

    o = outline([_polygon(720, 20.0, 0.0)])
    c = np.array([0.5 * math.cos(2.0), 0.5 * math.sin(2.0)])
    sag = 20.0 * (1 - math.cos(math.pi / 720))
    for t, r in ((0.3, 19.7), (-0.3, 20.3)):
        q = _changed(o, 0.5, 2.0, t).points
        dist = np.hypot(*(q - c).T)
        assert np.all(np.abs(dist - r) <= sag + 1e-5), (t, dist.min(), dist.max())  # clipper rounds to 1e-6 mm
    np.testing.assert_allclose(_changed(o, 0.5, 2.0, 0.0).points, o.points + c, rtol=0, atol=1e-14)


def _case_by_hand(d, mount, case, step):
    """Both directions of the changed outlines over the whole turn (resolve_contact with the cap of 4 turns' samples
    + 1000), the least backlash on r_H = L U / (1 + U), the larger step, the lost samples."""
    from propulsor.checks.motion.outlines import offset_outline
    from propulsor.parts.noncircular_pair.as_built import pair_outlines

    base = pair_outlines(d, mount)
    drv = offset_outline(base.drv, case.t_driver, (case.e_driver * math.cos(case.psi_driver),
                                                   case.e_driver * math.sin(case.psi_driver)))
    dvn = offset_outline(base.dvn, case.t_driven, (case.e_driven * math.cos(case.psi_driven),
                                                   case.e_driven * math.sin(case.psi_driven)))
    po = PairOutlines(drv, dvn, mount + case.dL, base.driver_teeth, base.driven_teeth)
    cap = int(4 * 360.0 / math.degrees(step)) + 1000
    dr, rv = (resolve_contact(po, d.law.theta, 0.0, 2 * math.pi, k, step_driver_rad=step, max_evals=cap)
              for k in (DRIVE, REVERSE))
    x = np.union1d(dr.phi, rv.phi)
    U = np.asarray(d.law.U(x), float)
    okd, okr = np.isfinite(dr.te), np.isfinite(rv.te)
    bl = (np.interp(x, rv.phi[okr], rv.te[okr]) - np.interp(x, dr.phi[okd], dr.te[okd])) * d.L * U / (1 + U)
    worst = dr if dr.step_max >= rv.step_max else rv
    return dr, rv, float(np.min(bl)), float(x[int(np.argmin(bl))]), worst


def test_a_case_is_both_directions_of_the_changed_outlines_over_the_whole_turn(monkeypatch):
    """The 18-tooth elliptical pair (e = 0.1) made 0.05 mm apart, the driver 0.03 mm off at 1 rad and 0.01 mm
    thinner, the driven 0.02 mm off at 2 rad and 0.02 mm thicker, at 12 deg of driver: every field against the
    contact resolved in the test."""
    from propulsor.parts.noncircular_pair.tolerance import Case, run_case

    d = _small_design()
    step = math.radians(12.0)
    case = Case("a", 0.05, 0.03, 1.0, 0.02, 2.0, 0.01, -0.02)
    r = run_case(d, d.L + 0.01, case, step)
    dr, rv, bl, at, worst = _case_by_hand(d, d.L + 0.01, case, step)
    assert r.case == case
    assert (r.te_pp_drive, r.te_pp_reverse) == (dr.te_pp, rv.te_pp) and r.te_pp_drive != r.te_pp_reverse
    assert r.backlash_min_mm == pytest.approx(bl, rel=1e-12) and r.backlash_min_phi == at
    assert 0.15 < bl < 0.18
    assert r.step_max == worst.step_max == max(dr.step_max, rv.step_max)
    assert r.step_theta == worst.step_at()[1]
    assert r.lost == 0 and not r.jam
    # no step given: policy's TOLERANCE_STEP_DRIVER_DEG (set to 12 deg here: the build's 0.5 deg takes 24 times longer)
    from propulsor import policy

    monkeypatch.setattr(policy, "TOLERANCE_STEP_DRIVER_DEG", 12.0)
    assert run_case(d, d.L + 0.01, case) == r


def test_a_tolerance_study_runs_the_four_corners_then_the_seeded_draws():
    """The 18-tooth elliptical pair within printed tolerances (0.02 mm, run-out 0.01 mm) at 12 deg of driver: the
    corners of worst_cases in order, then monte_carlo_cases(tol, 1, 4), each run as run_case runs it."""
    from propulsor.parts.noncircular_pair.tolerance import (monte_carlo_cases, printed, run_case, tolerance_study,
                                                            worst_cases)

    d = _small_design()
    step = math.radians(12.0)
    tol = printed(0.02, 0.01)
    import time

    t0 = time.perf_counter()
    st = tolerance_study(d, d.L + 0.01, tol, 1, 4, step)
    wall = time.perf_counter() - t0
    assert st.tolerances is tol and st.seed == 4 and 0 < st.seconds <= wall
    assert [r.case for r in st.worst] == worst_cases(tol)
    assert [r.case for r in st.samples] == monte_carlo_cases(tol, 1, 4)
    assert st.samples[0] == run_case(d, d.L + 0.01, monte_carlo_cases(tol, 1, 4)[0], step)
    assert st.worst[2] == run_case(d, d.L + 0.01, worst_cases(tol)[2], step)


def _result(case_name, **kw):
    from propulsor.parts.noncircular_pair.tolerance import Case, CaseResult

    f = dict(te_pp_drive=0.0, te_pp_reverse=0.0, backlash_min_mm=0.1, backlash_min_phi=0.0, step_max=0.0,
             step_theta=0.0, lost=0)
    f.update(kw)
    return CaseResult(Case(case_name), **f)


def test_percentiles_of_the_draws_and_nan_without_draws():
    """numpy's linear percentiles of 1, 2, 3, 4, 5: 5 % 1.2, 50 % 3, 95 % 4.8; other quantiles as asked; no draw:
    nan for each."""
    from propulsor.parts.noncircular_pair.tolerance import ToleranceStudy, printed

    rs = tuple(_result(f"s{k}", backlash_min_mm=float(v)) for k, v in enumerate([3, 1, 5, 2, 4]))
    st = ToleranceStudy(printed(0.1, 0.1), (), rs, 1, 0.0)
    assert st.percentiles("backlash_min_mm") == (pytest.approx(1.2), 3.0, pytest.approx(4.8))
    assert st.percentiles("backlash_min_mm", (0, 25, 100)) == (1.0, 2.0, 5.0)
    empty = ToleranceStudy(printed(0.1, 0.1), rs, (), 1, 0.0).percentiles("backlash_min_mm", (10, 90))
    assert len(empty) == 2 and all(math.isnan(v) for v in empty)
    assert len(ToleranceStudy(printed(0.1, 0.1), rs, (), 1, 0.0).percentiles("lost")) == 3


def test_scaled_tolerances_are_k_times_as_wide_from_the_same_source():
    from propulsor.parts.noncircular_pair.tolerance import Tolerances, scaled

    t = Tolerances(0.03, 0.011, 0.017, -0.004, 0.021, "src")
    assert scaled(t, 3.0) == Tolerances(pytest.approx(0.09), pytest.approx(0.033), pytest.approx(0.051),
                                        pytest.approx(-0.012), pytest.approx(0.063), "src")


# =========================================================================== tooth_load_outputs.py
def _load_params(**kw):
    """The elliptical part file's pair with a load case (real parameters: load_params checks them)."""
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams

    _, mapping = read_part_file(PARTS / "ncg_elliptical.toml")
    mapping.update(dict(load_driver_torque_Nm=20.0, load_K_A=1.25, load_K_v=1.1, load_K_beta=1.2, load_S_Hmin=1.1,
                        load_S_Fmin=1.5, gear_material="steel_case_MQ"))
    mapping.update(kw)
    return load_params(NoncircularPairParams, mapping)


def _section(tooth, s_Fn, rho_lo, rho_hi):
    from propulsor.gears.tooth_load import RootSection

    return RootSection(tooth, np.array([0.0, 0.0]), np.array([0.6 * s_Fn, 0.8 * s_Fn]), rho_lo, rho_hi,
                       np.array([0.0, 1.0]))


def _tooth_load(mat="steel_case_MQ", **kw):
    """Driver: 6 teeth, 4 a period (tooth j stands for j mod 4), tooth 3 not loaded, tooth 2's section measured as
    tooth 6, tooth 1's section failed; driven: 5 teeth, every one its own (repeat 0), 0 and 2 loaded."""
    from propulsor.gears.gear_materials import material
    from propulsor.parts.noncircular_pair.tooth_load_outputs import ToothLoad, _Peak

    nan = math.nan
    f = dict(
        rows=[[1.0, 0.5, 20.0, 21.0, 1, 0, 0, 0.0, 1.0, 1000.0, 20.0, 21.0, 9.0, 11.0, 600.0, 80.0, 90.0],
              [7.5, 3.5, 20.0, 23.0, 2, 1, 2, 1.0, 0.6, 1200.0, 20.0, 21.0, 9.0, 11.0, 650.0, 70.0, 30.0],
              [4.0, 2.0, 20.0, 22.0, 2, 2, 0, 3.0, 0.4, 900.0, 20.0, 21.0, 9.0, 11.0, 620.0, 10.0, 40.0]],
        theta=np.array([0.01, 0.02, 0.05, 0.07]), phi=np.array([0.005, 0.01, 0.025, 0.035]),
        T1=np.array([20.0, 20.0, 20.0, 20.0]), T2=np.array([21.0, 23.0, 22.0, 19.5]), loaded=np.array([1, 2, 2, 1]),
        imbalance=3e-13, lost=0,
        peaks={"driver": {0: _Peak(1000.0, 600.0, 3.0, 80.0, 5.0), 1: _Peak(1200.0, 650.0, 7.5, 70.0, 9.0),
                          2: _Peak(900.0, 620.0, 4.0, 10.0, 4.0)},
               "driven": {0: _Peak(1100.0, 700.0, 2.0, 90.0, 4.0), 2: _Peak(500.0, 300.0, 1.0, 30.0, 1.5)}},
        sections={"driver": {0: _section(0, 5.0, 0.6, 0.5), 1: _section(1, 4.0, -1.0, 0.5),
                             6: _section(6, 4.5, 0.7, 0.9)},
                  "driven": {0: _section(0, 5.5, 0.8, 0.75), 2: _section(2, 5.2, 0.65, 0.66)}},
        load_case="driver torque T1 = 20 N·m, more", material=material(mat), Z_E=189.8, c_prime=(13.1, 14.2),
        K_H=1.65, K_F=1.65, window_rad=1e-4, evaluations=9, teeth={"driver": 6, "driven": 5},
        repeat={"driver": 4, "driven": 0}, cycles={"driver": 2.0, "driven": 1.0})
    f.update(kw)
    return ToothLoad(**f)


def test_a_tooth_of_another_period_is_reported_as_the_tooth_it_repeats():
    from propulsor.parts.noncircular_pair.tooth_load_outputs import _Peak

    tl = _tooth_load()
    assert tl.tooth_peak("driver", 1) == (_Peak(1200.0, 650.0, 7.5, 70.0, 9.0), "measured")
    assert tl.tooth_peak("driver", 5) == (_Peak(1200.0, 650.0, 7.5, 70.0, 9.0), "as tooth 1")
    assert tl.tooth_peak("driver", 4)[1] == "as tooth 0"
    pk, how = tl.tooth_peak("driver", 3)
    assert how == "not loaded" and all(math.isnan(getattr(pk, f)) for f in ("F", "sH", "sH_at", "sF", "sF_at"))
    assert tl.tooth_peak("driven", 2)[1] == "measured" and tl.tooth_peak("driven", 4)[1] == "not loaded"
    # a section by its number, by its number mod the period, or none
    assert tl.section_of("driver", 4) is tl.sections["driver"][0]
    assert tl.section_of("driver", 2) is tl.sections["driver"][6]
    assert tl.section_of("driver", 3) is None
    assert tl.section_of("driven", 2) is tl.sections["driven"][2] and tl.section_of("driven", 1) is None


def test_fold_keeps_each_class_of_teeth_its_largest_force_and_stresses_with_their_angles():
    from propulsor.parts.noncircular_pair.tooth_load_outputs import _Peak, _fold

    peaks = {0: _Peak(100.0, 500.0, 1.0, 50.0, 2.0), 3: _Peak(120.0, 400.0, 3.0, 60.0, 4.0),
             1: _Peak(80.0, 0.0, math.nan, 0.0, math.nan), 4: _Peak(70.0, 450.0, 5.0, 55.0, 6.0)}
    out = _fold(peaks, 3)
    assert out == {0: _Peak(120.0, 500.0, 1.0, 60.0, 4.0), 1: _Peak(80.0, 450.0, 5.0, 55.0, 6.0)}
    # equal stresses keep the first tooth's angle
    eq = _fold({0: _Peak(1.0, 5.0, 1.0, 7.0, 2.0), 2: _Peak(1.0, 5.0, 9.0, 7.0, 9.0)}, 2)
    assert eq == {0: _Peak(1.0, 5.0, 1.0, 7.0, 2.0)}


def test_life_factors_from_the_load_cycles_of_each_gear():
    """100 rpm of the driver, 2 driver turns a driven turn, 1000 h: 3e6 driven turns; the driver's teeth 6e6 cycles,
    the driven's 3e6.  Case-hardened steel: Z_NT = (5e7/N)^0.0756, Y_NT = (3e6/N)^0.02 above 3e6 (ISO 6336-2/-3);
    no life: the endurance limit (1, 1); printed: static (1, 1)."""
    from propulsor.parts.noncircular_pair.tooth_load_outputs import _life

    tl = _tooth_load()
    p = _load_params(load_driver_speed_rpm=100.0, load_life_hours=1000.0)
    N, Z, Y = _life(tl, p, "driver")
    assert N == pytest.approx(6e6, rel=1e-12)
    assert Z == pytest.approx((5e7 / 6e6) ** 0.0756, rel=1e-12) and Y == pytest.approx(0.5 ** 0.02, rel=1e-12)
    N, Z, Y = _life(tl, p, "driven")
    assert N == pytest.approx(3e6, rel=1e-12) and Z == pytest.approx((5e7 / 3e6) ** 0.0756, rel=1e-12)
    assert _life(tl, _load_params(), "driver") == (None, 1.0, 1.0)
    assert _life(_tooth_load("PLA"), p, "driver")[1:] == (1.0, 1.0)


def test_peak_rows_are_every_tooth_of_both_gears_with_its_safeties():
    """Each row: gear, tooth, how measured, cycles a driven turn, peak F_n, sigma_H and where, sigma_F and where,
    s_Fn and the smaller fillet radius of its section (nan without one, or a failed one), S_H = sigma_Hlim Z_NT /
    sigma_H, S_F = sigma_FE Y_NT / sigma_F (nan where unloaded)."""
    from propulsor.parts.noncircular_pair.tooth_load_outputs import peak_rows

    nan = math.nan
    p = _load_params(load_driver_speed_rpm=100.0, load_life_hours=1000.0)
    Zd, Yd = (5e7 / 6e6) ** 0.0756, 0.5 ** 0.02
    Zn, Yn = (5e7 / 3e6) ** 0.0756, 1.0
    want = [
        ["driver", 0, "measured", 2.0, 1000.0, 600.0, 3.0, 80.0, 5.0, 5.0, 0.5, 1500 * Zd / 600, 850 * Yd / 80],
        ["driver", 1, "measured", 2.0, 1200.0, 650.0, 7.5, 70.0, 9.0, nan, nan, 1500 * Zd / 650, 850 * Yd / 70],
        ["driver", 2, "measured", 2.0, 900.0, 620.0, 4.0, 10.0, 4.0, 4.5, 0.7, 1500 * Zd / 620, 850 * Yd / 10],
        ["driver", 3, "not loaded", 2.0, nan, nan, nan, nan, nan, nan, nan, nan, nan],
        ["driver", 4, "as tooth 0", 2.0, 1000.0, 600.0, 3.0, 80.0, 5.0, 5.0, 0.5, 1500 * Zd / 600, 850 * Yd / 80],
        ["driver", 5, "as tooth 1", 2.0, 1200.0, 650.0, 7.5, 70.0, 9.0, nan, nan, 1500 * Zd / 650, 850 * Yd / 70],
        ["driven", 0, "measured", 1.0, 1100.0, 700.0, 2.0, 90.0, 4.0, 5.5, 0.75, 1500 * Zn / 700, 850 * Yn / 90],
        ["driven", 1, "not loaded", 1.0, nan, nan, nan, nan, nan, nan, nan, nan, nan],
        ["driven", 2, "measured", 1.0, 500.0, 300.0, 1.0, 30.0, 1.5, 5.2, 0.65, 1500 * Zn / 300, 850 * Yn / 30],
        ["driven", 3, "not loaded", 1.0, nan, nan, nan, nan, nan, nan, nan, nan, nan],
        ["driven", 4, "not loaded", 1.0, nan, nan, nan, nan, nan, nan, nan, nan, nan]]
    got = peak_rows(_tooth_load(), p)
    assert len(got) == len(want)
    for g, w in zip(got, want):
        assert g[:3] == w[:3]
        np.testing.assert_allclose(np.array(g[3:], float), np.array(w[3:], float), rtol=1e-12, atol=0)
    # a tooth measured without stress: its safeties nan, not inf
    from propulsor.parts.noncircular_pair.tooth_load_outputs import _Peak

    tl = _tooth_load(peaks={"driver": {0: _Peak(10.0, 0.0, math.nan, 0.0, math.nan)}, "driven": {}})
    row = peak_rows(tl, _load_params())[0]
    assert math.isnan(row[11]) and math.isnan(row[12])


def _summary_by_hand(Zd=1.0, Yd=1.0, Zn=1.0, Yn=1.0):
    return {
        "tooth_load_driver_sigma_F_max_MPa": 80.0, "tooth_load_driver_sigma_F_worst_tooth": 0,
        "tooth_load_driver_sigma_F_worst_driver_deg": 5.0, "tooth_load_driver_sigma_H_max_MPa": 650.0,
        "tooth_load_driver_sigma_H_worst_tooth": 1, "tooth_load_driver_sigma_H_worst_driver_deg": 7.5,
        "tooth_load_driver_F_n_max_N": 1200.0, "tooth_load_driver_uneven_F": 1200.0 / 900.0,
        "tooth_load_driver_uneven_sigma_F": 80.0 / 10.0, "tooth_load_driver_S_H_min": 1500.0 * Zd / 650.0,
        "tooth_load_driver_S_F_min": 850.0 * Yd / 80.0, "tooth_load_driver_cycles_per_driven_turn": 2.0,
        "tooth_load_driven_sigma_F_max_MPa": 90.0, "tooth_load_driven_sigma_F_worst_tooth": 0,
        "tooth_load_driven_sigma_F_worst_driver_deg": 4.0, "tooth_load_driven_sigma_H_max_MPa": 700.0,
        "tooth_load_driven_sigma_H_worst_tooth": 0, "tooth_load_driven_sigma_H_worst_driver_deg": 2.0,
        "tooth_load_driven_F_n_max_N": 1100.0, "tooth_load_driven_uneven_F": 1100.0 / 500.0,
        "tooth_load_driven_uneven_sigma_F": 3.0, "tooth_load_driven_S_H_min": 1500.0 * Zn / 700.0,
        "tooth_load_driven_S_F_min": 850.0 * Yn / 90.0, "tooth_load_driven_cycles_per_driven_turn": 1.0,
        "tooth_load_S_H_min": min(1500.0 * Zd / 650.0, 1500.0 * Zn / 700.0),
        "tooth_load_S_F_min": min(850.0 * Yd / 80.0, 850.0 * Yn / 90.0),
        "tooth_load_T1_max_Nm": 20.0, "tooth_load_T1_min_Nm": 20.0, "tooth_load_T2_max_Nm": 23.0,
        "tooth_load_T2_min_Nm": 19.5, "tooth_load_pairs_min": 1, "tooth_load_pairs_max": 2,
        "tooth_load_pairs_mean": 1.5, "tooth_load_c_prime_min": 13.1, "tooth_load_c_prime_max": 14.2,
        "tooth_load_Z_E": 189.8, "tooth_load_phases": 4, "tooth_load_material": "steel_case_MQ",
        "tooth_load_sigma_Hlim_MPa": 1500.0, "tooth_load_sigma_FE_MPa": 850.0}


def test_summary_names_the_worst_tooth_of_each_gear_and_the_least_safeties():
    from propulsor.parts.noncircular_pair.tooth_load_outputs import summary

    got = summary(_tooth_load(), _load_params())
    want = _summary_by_hand()
    assert list(got) == list(want)
    for k, v in want.items():
        assert got[k] == (pytest.approx(v, rel=1e-13) if isinstance(v, float) else v), k
        assert type(got[k]) is not np.ndarray
    assert type(got["tooth_load_pairs_min"]) is int and type(got["tooth_load_phases"]) is int
    # with a life: the life factors of each gear's cycles
    got = summary(_tooth_load(), _load_params(load_driver_speed_rpm=100.0, load_life_hours=1000.0))
    want = _summary_by_hand((5e7 / 6e6) ** 0.0756, 0.5 ** 0.02, (5e7 / 3e6) ** 0.0756, 1.0)
    for k in ("tooth_load_driver_S_H_min", "tooth_load_driver_S_F_min", "tooth_load_driven_S_H_min",
              "tooth_load_driven_S_F_min", "tooth_load_S_H_min", "tooth_load_S_F_min"):
        assert got[k] == pytest.approx(want[k], rel=1e-13), k


def test_summary_of_a_gear_without_a_stressed_tooth_is_nan_and_names_no_tooth():
    from propulsor.parts.noncircular_pair.tooth_load_outputs import _Peak, summary

    tl = _tooth_load(peaks={"driver": {0: _Peak(1000.0, 600.0, 3.0, 80.0, 5.0)},
                            "driven": {0: _Peak(0.0, 0.0, math.nan, 0.0, math.nan)}})
    got = summary(tl, _load_params())
    for k in ("sigma_F_max_MPa", "sigma_F_worst_driver_deg", "sigma_H_max_MPa", "sigma_H_worst_driver_deg",
              "F_n_max_N", "uneven_F", "uneven_sigma_F", "S_H_min", "S_F_min"):
        assert math.isnan(got[f"tooth_load_driven_{k}"]), k
    assert got["tooth_load_driven_sigma_F_worst_tooth"] == got["tooth_load_driven_sigma_H_worst_tooth"] == -1
    assert got["tooth_load_driver_uneven_F"] == 1.0 and got["tooth_load_driver_sigma_F_worst_tooth"] == 0
    assert got["tooth_load_driver_S_H_min"] == pytest.approx(1500 / 600)
    assert math.isnan(got["tooth_load_S_H_min"])  # the least of a nan: nan (its check fails)


def test_checks_of_the_least_safeties_and_the_equilibrium_with_their_messages_in_full():
    from propulsor.parts.noncircular_pair.tooth_load_outputs import checks, summary

    tl, p = _tooth_load(), _load_params()
    vals = summary(tl, p)
    sH, sF, eq = checks(tl, vals, p)
    assert (sH.name, sH.passed, sH.value, sH.limit, sH.unit) == ("tooth_load.S_H", True,
                                                                 pytest.approx(1500 / 700), 1.1, "")
    assert sH.message == ("least contact safety sigma_Hlim Z_NT / sigma_H over every tooth: driver 2.308 (tooth 1, "
                          "sigma_H 650.0 MPa at driver 7.50 deg), driven 2.143 (tooth 0); steel_case_MQ sigma_Hlim = "
                          "1500 MPa")
    assert (sF.name, sF.passed, sF.value, sF.limit, sF.unit) == ("tooth_load.S_F", True, pytest.approx(850 / 90),
                                                                 1.5, "")
    assert sF.message == ("least root safety sigma_FE Y_NT / sigma_F over every tooth: driver 10.625 (tooth 0, "
                          "sigma_F 80.0 MPa at driver 5.00 deg), driven 9.444 (tooth 0, sigma_F 90.0 MPa); "
                          "steel_case_MQ sigma_FE = 850 MPa")
    assert eq.name == "tooth_load.equilibrium" and not eq.passed  # driver tooth 1's section failed
    # a printed material's limits are static; a safety below its requirement fails
    tl = _tooth_load("PLA")
    p = _load_params(gear_material="PLA", load_S_Fmin=5.0)
    vals = summary(tl, p)
    sH, sF, _ = checks(tl, vals, p)
    mat = tl.material
    assert sH.message.endswith(f"PLA sigma_Hlim = {mat.sigma_Hlim_MPa:g} MPa (static limits of a printed material, "
                               f"not a fatigue rating)")
    assert sF.message.endswith(f"PLA sigma_FE = {mat.sigma_FE_MPa:g} MPa (static limits of a printed material, not a "
                               f"fatigue rating)")
    assert sF.passed is (min(mat.sigma_FE_MPa / 80, mat.sigma_FE_MPa / 90) >= 5.0)
    assert sF.limit == 5.0


def test_equilibrium_holds_to_1e_9_with_a_pair_at_every_phase_and_every_section():
    from propulsor.parts.noncircular_pair.tooth_load_outputs import equilibrium

    whole = {"driver": {0: _section(0, 5.0, 0.6, 0.5)}, "driven": {0: _section(0, 5.5, 0.8, 0.75)}}
    ok = equilibrium(_tooth_load(sections=whole, imbalance=1e-9))
    assert (ok.name, ok.passed, ok.value, ok.limit, ok.unit) == ("tooth_load.equilibrium", True, 1e-9, 1e-9, "")
    assert ok.message == ("0 of 4 phases without a loaded pair; 0 teeth without a 30 deg section; largest |sum F l1 - "
                          "T1| / T1 1.00e-09")
    off = equilibrium(_tooth_load(sections=whole, imbalance=1.01e-9), "x.eq", "case B: ")
    assert (off.name, off.passed) == ("x.eq", False) and off.message.startswith("case B: 0 of 4 phases")
    lost = equilibrium(_tooth_load(sections=whole, lost=2, imbalance=0.0))
    assert not lost.passed and lost.value == 2.0 and lost.message.startswith("2 of 4 phases without")
    bad = {"driver": {0: _section(0, 5.0, 0.6, 0.5), 1: _section(1, 4.0, -1.0, 0.5)},
           "driven": {3: _section(3, 5.0, 0.6, math.nan)}}
    miss = equilibrium(_tooth_load(sections=bad, lost=1, imbalance=0.5))
    assert not miss.passed and miss.value == 3.0
    assert miss.message == ("1 of 4 phases without a loaded pair; 2 teeth without a 30 deg section (driver 1, driven "
                            "3); largest |sum F l1 - T1| / T1 5.00e-01")
    assert equilibrium(_tooth_load(sections=whole, imbalance=4.0)).value == 4.0


def test_factor_table_every_factor_its_value_and_source():
    from propulsor.parts.noncircular_pair.tooth_load_outputs import FACTOR_SOURCES, factor_rows, summary

    tl = _tooth_load()
    p = _load_params(load_driver_speed_rpm=100.0, load_life_hours=1000.0)
    vals = summary(tl, p)
    rows = factor_rows(tl, p, vals)
    assert [r[0] for r in rows] == list(FACTOR_SOURCES) and [r[2] for r in rows] == list(FACTOR_SOURCES.values())
    v = {r[0]: r[1] for r in rows}
    Zd, Zn = (5e7 / 6e6) ** 0.0756, (5e7 / 3e6) ** 0.0756
    assert v == {
        "K_A": 1.25, "K_v": 1.1, "K_Hbeta": 1.2, "K_Fbeta": 1.2, "K_Halpha": "",
        "c_prime": "13.1000 .. 14.2000 N/(mm um)", "Z_E": 189.8, "Z_H_Z_eps_Z_B": "",
        "sigma_H": "driver 650.00, driven 700.00 MPa (peaks)", "s_Fn": "per tooth: tables/tooth_peaks.csv",
        "rho_F": "per tooth: tables/tooth_peaks.csv", "h_Fe": "per phase: tables/tooth_load.csv",
        "alpha_Fen": "per phase", "Y_F": "per phase", "Y_S": "per phase", "Y_epsilon": "",
        "sigma_F": "driver 80.00, driven 90.00 MPa (peaks)", "sigma_Hlim": 1500.0, "sigma_FE": 850.0,
        "Z_NT": f"driver {Zd:.4f}, driven {Zn:.4f} (N_L 6e+06 / 3e+06)",
        "Y_NT": f"driver {0.5 ** 0.02:.4f}, driven 1.0000", "Z_L_Z_v_Z_R_Z_W_Z_X": 1.0,
        "Y_deltarelT_Y_RrelT_Y_X": 1.0, "S_H": pytest.approx(vals["tooth_load_S_H_min"]),
        "S_F": pytest.approx(vals["tooth_load_S_F_min"])}
    assert v["Z_NT"] == "driver 1.1739, driven 1.2370 (N_L 6e+06 / 3e+06)"
    v0 = {r[0]: r[1] for r in factor_rows(tl, _load_params(), summary(tl, _load_params()))}
    assert v0["Z_NT"] == "driver 1.0000, driven 1.0000" and v0["Y_NT"] == "driver 1.0000, driven 1.0000"


def test_without_a_load_nothing_and_without_an_as_built_contact_a_failed_check(tmp_path):
    from propulsor.parts.noncircular_pair.tooth_load_outputs import tooth_load_values
    from propulsor.parts.writer import OutputWriter

    p0 = _load_params(load_driver_torque_Nm=0.0)
    w = OutputWriter(tmp_path, "noncircular_pair", p0)
    tooth_load_values(w, SimpleNamespace(p=p0, d=None), {}, None)
    assert (w.checks, w.tables, w.plots, w.derived, w.notes) == ([], [], [], {}, [])
    p = _load_params()
    w = OutputWriter(tmp_path, "noncircular_pair", p)
    tooth_load_values(w, SimpleNamespace(p=p, d=None), {}, None)
    (c,) = w.checks
    assert (c.name, c.passed, c.value, c.limit, c.unit) == ("tooth_load.equilibrium", False, 1.0, 0.0, "")
    assert c.message == "no as-built contact (the proof found a jam): no load per tooth"
    assert (w.tables, w.plots, w.derived) == ([], [], {})


class _Plots:
    def __init__(self):
        self.figs = {}

    def add_plot(self, name, fig):
        self.figs[name] = fig


def test_the_plot_shows_every_tooths_peaks_against_the_allowables_and_every_pairs_stress():
    from propulsor.parts.noncircular_pair.tooth_load_outputs import _plot

    from propulsor.parts.noncircular_pair.tooth_load_outputs import _Peak

    tl, p = _tooth_load(), _load_params()
    # a driven tooth measured without root stress stays out of the most / least ratio (90 / 30)
    tl.peaks["driven"][4] = _Peak(0.0, 0.0, math.nan, 0.0, math.nan)
    w = _Plots()
    _plot(w, tl, p)
    fig = w.figs["tooth_load"]
    assert list(fig.get_size_inches()) == [9.0, 7.0]
    a1, a2, a3 = fig.axes
    assert [a.get_subplotspec().get_geometry() for a in (a1, a2, a3)] == [(3, 1, 0, 0), (3, 1, 1, 1), (3, 1, 2, 2)]
    assert {a.title.get_fontsize() for a in (a1, a2, a3)} == {9.0}
    for ln in a1.get_lines():
        assert (ln.get_linestyle(), ln.get_linewidth()) == ("--", 0.8)
    assert [ln.get_color() for ln in a1.get_lines()] == ["C0", "C1"]
    assert a1.get_legend()._ncols == 2 and a1.get_legend().get_texts()[0].get_fontsize() == 6.0
    assert a3.get_legend().get_texts()[0].get_fontsize() == 6.0 and a3.get_legend().markerscale == 4
    assert {(ln.get_marker(), ln.get_markersize(), ln.get_linestyle()) for ln in a3.get_lines()} == {(".", 1.5,
                                                                                                      "None")}
    assert a1.get_title() == "driver: peak stress of every tooth over the cycle (most / least loaded root 8.000)"
    assert a2.get_title() == "driven: peak stress of every tooth over the cycle (most / least loaded root 3.000)"
    assert (a1.get_xlabel(), a2.get_xlabel(), a1.get_ylabel()) == ("driver tooth", "driven tooth", "MPa")
    bars = [(r.get_x() + r.get_width() / 2, r.get_height(), r.get_width()) for r in a1.patches]
    sF = [80.0, 70.0, 10.0, math.nan, 80.0, 70.0]
    sH = [600.0, 650.0, 620.0, math.nan, 600.0, 650.0]
    want = [(j - 0.2, sF[j], 0.4) for j in range(6)] + [(j + 0.2, sH[j], 0.4) for j in range(6)]
    assert len(bars) == 12
    for (x, h, wd), (x0, h0, w0) in zip(bars, want):
        assert x == pytest.approx(x0) and wd == pytest.approx(w0)
        assert (math.isnan(h) and math.isnan(h0)) or h == pytest.approx(h0)
    lines = {ln.get_label(): ln.get_ydata()[0] for ln in a1.get_lines()}
    assert lines == {"sigma_FE / S_Fmin = 567 MPa": pytest.approx(850 / 1.5),
                     "sigma_Hlim / S_Hmin = 1364 MPa": pytest.approx(1500 / 1.1)}
    assert [t.get_text() for t in a1.get_legend().get_texts()] == [
        "sigma_FE / S_Fmin = 567 MPa", "sigma_Hlim / S_Hmin = 1364 MPa", "peak root stress sigma_F",
        "peak contact stress sigma_H"]
    assert a3.get_xlabel() == "driver angle theta, deg (one period)" and a3.get_ylabel() == "MPa"
    assert a3.get_title() == "stress of every loaded pair over the period (driver torque T1 = 20 N·m)"
    series = {ln.get_label(): (ln.get_xdata().tolist(), ln.get_ydata().tolist()) for ln in a3.get_lines()}
    assert series == {"sigma_F driver tooth": ([1.0, 4.0, 7.5], [80.0, 10.0, 70.0]),
                      "sigma_F driven tooth": ([1.0, 4.0, 7.5], [90.0, 40.0, 30.0]),
                      "sigma_H": ([1.0, 4.0, 7.5], [600.0, 620.0, 650.0])}
    assert [t.get_text() for t in a3.get_legend().get_texts()] == list(series)
    import matplotlib.pyplot as plt

    plt.close(fig)


def _circular_pair(**load):
    """A circular pair built by the non-circular path (a Fourier law with every term zero, k = 2: z 20/40, m 2.5,
    x +-0.5, L = 75 mm, U = 2) under a constant driver torque of 50 N·m: about 2.5 s."""
    from propulsor.params import load_params
    from propulsor.parts.noncircular_pair import NoncircularPairParams, pair_design

    kw = dict(law="fourier", driver_turns=2, fourier_cos=[0.0], fourier_sin=[0.0], module_mm=2.5, driven_teeth=40,
              driver_shift=0.5, face_width_mm=20.0, compare_methods=False, load_driver_torque_Nm=50.0,
              gear_material="steel_case_MQ", load_K_A=1.25, load_K_v=1.1, load_K_beta=1.2)
    kw.update(load)
    p = load_params(NoncircularPairParams, kw)
    return p, pair_design(p)


def _circular_drive_contact(pitches: float):
    """``_circular_pair`` and its drive direction's as-built contact over ``pitches`` driven pitches from 0, sampled
    every 0.5 deg of driver: (p, dd, pitch, contact law)."""
    from propulsor.checks.motion.contact_events import DRIVE, resolve_contact
    from propulsor.parts.noncircular_pair.as_built import pair_outlines

    p, dd = _circular_pair()
    pitch = 2 * math.pi / 40
    cl = resolve_contact(pair_outlines(dd.d, dd.mount), dd.d.run_law.theta, 0.0, pitches * pitch, DRIVE,
                         step_driver_rad=math.radians(0.5))
    return p, dd, pitch, cl


def test_load_per_tooth_of_a_circular_pair_by_hand():
    """The circular pair over 0.2 .. 1.0 of a driven pitch (driver 3.6 .. 18 deg) every 1 deg of driver (16 phases,
    0.96 deg apart) and the change from two pairs to one bisected 7 times: T1 = 50, T2 = T1 U eta = 97 N·m; the
    pairs' forces balance T1 on the driver's base radius 23.49 mm; sigma_H = Z_E sqrt(F K_H / (b rho_red)) with
    K_H = 1.25 x 1.1 x 1.2 and the columns' radii; sigma_F = F cos(alpha) / (b m) Y_F Y_S K_F; the involute's radius
    of curvature sqrt(r^2 - r_b^2); c' of ISO 6336-1 at z_n = 20 / 40, x = +-0.5, C_B = 0.975: 0.78 / 0.06113075;
    the gap window 4 deflections 50e3 / (25 cos 20 deg) / (c' b 1e3) over r_H = 50 mm; the peaks of each tooth
    (numbered mod 20: a period is half a turn) the largest of the table's rows."""
    from propulsor.checks.motion.contact_events import DRIVE, resolve_contact
    from propulsor.gears.gear_materials import material
    from propulsor.gears.tooth_load import DenseOutline, root_section
    from propulsor.parts.noncircular_pair.as_built import pair_outlines
    from propulsor.parts.noncircular_pair.tooth_load_outputs import PHASE_COLUMNS, analyse

    p, dd = _circular_pair()
    d = dd.d
    pitch = 2 * math.pi / 40
    cl = resolve_contact(pair_outlines(d, dd.mount), d.run_law.theta, 0.0, 2 * pitch, DRIVE,
                         step_driver_rad=math.radians(0.5))
    ticks = []
    tl = analyse(d, dd.mount, p, cl.phi, cl.te, 0.2 * pitch, 0.8 * pitch, step_deg=1.0,
                 tick=lambda done, total: ticks.append((done, total)))
    assert ticks == [(k, 16) for k in range(1, 17)]
    alpha = math.radians(20.0)
    rb1, rb2 = 25.0 * math.cos(alpha), 50.0 * math.cos(alpha)
    Z_E = math.sqrt(206000.0 / (2 * math.pi * (1 - 0.3 ** 2)))
    K = 1.25 * 1.1 * 1.2
    cp = 0.8 * 0.975 / 0.06113075
    assert tl.material == material("steel_case_MQ") and tl.Z_E == pytest.approx(Z_E, rel=1e-12)
    assert tl.K_H == pytest.approx(K, rel=1e-14) and tl.K_F == tl.K_H
    assert tl.c_prime == (pytest.approx(cp, rel=1e-6), pytest.approx(cp, rel=1e-6))
    assert tl.window_rad == pytest.approx(4 * 50e3 / rb1 / (cp * 20 * 1e3) / 50.0, rel=1e-6)
    assert tl.load_case == "driver torque T1 = 50 N·m, T2 = T1·U·eta (eta = 0.97)"
    assert (tl.teeth, tl.repeat, tl.cycles) == ({"driver": 20, "driven": 40}, {"driver": 20, "driven": 20},
                                                {"driver": 2.0, "driven": 1.0})
    assert tl.lost == 0 and tl.imbalance < 1e-12
    # the phases: the 16 of the grid and the 7 of the bisection
    deg = np.degrees(tl.theta)
    grid = np.linspace(3.6, 18.0, 16)
    assert len(deg) == 23 == tl.evaluations and np.all(np.diff(deg) > 0)
    assert np.all(np.min(np.abs(deg[:, None] - grid[None, :]), axis=0) < 1e-9)
    np.testing.assert_allclose(tl.phi, tl.theta / 2, rtol=0, atol=1e-12)
    assert tl.T1 == pytest.approx(np.full(23, 50.0)) and tl.T2 == pytest.approx(np.full(23, 97.0))
    assert tl.T1.shape == tl.T2.shape == tl.loaded.shape == (23,)
    count = dict(zip(np.round(deg, 9), tl.loaded))
    lo, hi = 15.12, 16.08
    assert count[round(lo, 9)] == 2 and count[round(hi, 9)] == 1
    extra = sorted(set(np.round(deg, 9)) - set(np.round(grid, 9)))
    seen = []
    for _ in range(7):
        mid = 0.5 * (lo + hi)
        seen.append(round(mid, 9))
        lo, hi = (mid, hi) if count[round(mid, 9)] == 2 else (lo, mid)
    assert sorted(seen) == extra
    # every row by hand from its own columns
    assert all(len(r) == len(PHASE_COLUMNS) for r in tl.rows)
    by_phase = {}
    for r in tl.rows:
        by_phase.setdefault(round(r[0], 9), []).append(r)
    assert len(by_phase) == 23 and [len(v) for v in by_phase.values()] == tl.loaded.tolist()
    for rows in by_phase.values():
        F = np.array([r[9] for r in rows])
        assert sum(r[8] for r in rows) == pytest.approx(1.0, rel=1e-12)
        assert sum(r[9] * r[10] for r in rows) == pytest.approx(50e3, rel=1e-9)
        assert min(r[7] for r in rows) == 0.0 and all(r[7] >= 0 for r in rows)
        # F_j = k l2_j (Delta - delta_j), k = c' b: the gap of a pair, delta_j l2_j in um, from the forces
        first = next(r for r in rows if r[7] == 0.0)
        k = tl.c_prime[0] * 20.0 * 1e3
        for r in rows:
            assert r[7] == pytest.approx(1e3 * r[11] * (first[9] / first[11] - r[9] / r[11]) / k, rel=1e-6, abs=1e-9)
        for r in rows:
            assert r[0] == pytest.approx(2 * r[1], abs=1e-9)
            assert (r[2], r[3], r[4]) == (pytest.approx(50.0), pytest.approx(97.0), len(rows))
            assert r[8] == pytest.approx(r[9] / F.sum(), rel=1e-12)
            assert r[14] == pytest.approx(Z_E * math.sqrt(r[9] * K * (1 / r[12] + 1 / r[13]) / 20.0), rel=1e-12)
            for col, yf, ys in ((15, 19, 20), (16, 21, 22)):
                assert r[col] == pytest.approx(r[9] * math.cos(alpha) / (20.0 * 2.5) * r[yf] * r[ys] * K, rel=1e-9)
            assert 0 < r[17] < 2.25 * 2.5 and 0 < r[18] < 2.25 * 2.5
            if r[23] == "":
                assert r[10] == pytest.approx(rb1, abs=0.05) and r[11] == pytest.approx(rb2, abs=0.1)
                if r[24] > 24.05:          # just above the involute's start (r = 24.00 mm) on
                    assert r[12] == pytest.approx(math.sqrt(r[24] ** 2 - rb1 ** 2), rel=0.03)
                assert r[13] == pytest.approx(math.sqrt(r[25] ** 2 - rb2 ** 2), rel=0.03)
            else:  # a tip corner: r_a = m (z/2 + 1 + x): 28.75 and 51.25 mm
                assert r[23] in ("driver", "driven")
                assert r[24 if r[23] == "driver" else 25] == pytest.approx(28.75 if r[23] == "driver" else 51.25,
                                                                          abs=2e-3)
    assert {r[23] for r in tl.rows} == {"", "driver", "driven"}
    # the peaks: the largest of each tooth's rows (tooth numbers mod 20), where first reached
    for g, col, sf in (("driver", 5, 15), ("driven", 6, 16)):
        want = {}
        for r in tl.rows:
            j = r[col] % 20
            w = want.setdefault(j, [0.0, 0.0, math.nan, 0.0, math.nan])
            w[0] = max(w[0], r[9])
            if r[14] > w[1]:
                w[1], w[2] = r[14], r[0]
            if r[sf] > w[3]:
                w[3], w[4] = r[sf], r[0]
        assert set(tl.peaks[g]) == set(want)
        for j, w in want.items():
            pk = tl.peaks[g][j]
            assert (pk.F, pk.sH, pk.sH_at, pk.sF, pk.sF_at) == tuple(pytest.approx(v, rel=1e-12) for v in w)
    assert set(tl.peaks["driven"]) == {0, 19}
    # each loaded tooth's 30 deg section, its axis the radial line through its centre (a circular pitch curve)
    for g, gear in (("driver", d.driver), ("driven", d.driven)):
        dense = DenseOutline(gear.profile.outer.polyline(1e-5))
        centres = np.array([t.phi_centre for t in gear.teeth])
        if g == "driver":
            centres = math.pi - 2 * centres
        assert set(tl.sections[g]) == ({0, 1} if g == "driver" else {0, 39})
        for j, sec in tl.sections[g].items():
            c = centres[j]
            want = root_section(dense, j, centres, np.array([math.cos(c), math.sin(c)]), 2.5)
            assert sec.ok and sec.s_Fn == pytest.approx(want.s_Fn, abs=1e-6)
            assert (sec.rho_lo, sec.rho_hi) == (pytest.approx(want.rho_lo, abs=1e-6), pytest.approx(want.rho_hi,
                                                                                                     abs=1e-6))


def test_load_case_of_a_torque_a_power_and_a_vehicle_over_the_law():
    """T1 given: T2 = T1 U eta; a power P at n rpm: T1 = P / (2 pi n / 60); a vehicle on a walking law: F_R = f M g /
    N_p per propulsor, T2 = F_R dX01/dphi (mm -> m), T1 = T2 / (U eta); on the law the teeth realise for U and the
    mechanism's for dX01/dphi."""
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams
    from propulsor.parts.noncircular_pair.tooth_load_outputs import _loads

    phi = np.array([0.0, 0.3, 0.7])
    law, run = EllipticalLaw(0.3, 1), EllipticalLaw(0.2, 1)
    U = np.asarray(run.U(phi), float)
    d = SimpleNamespace(law=law, run_law=run)
    T1, T2, text = _loads(_load_params(load_efficiency=0.9), d, phi)
    assert T1.tolist() == [20.0] * 3 and T2 == pytest.approx(20.0 * U * 0.9, rel=1e-14)
    assert text == "driver torque T1 = 20 N·m, T2 = T1·U·eta (eta = 0.9)"
    T1, T2, text = _loads(_load_params(load_driver_torque_Nm=0.0, load_power_W=300.0, load_driver_speed_rpm=60.0), d,
                          phi)
    assert T1 == pytest.approx(np.full(3, 300.0 / (2 * math.pi)), rel=1e-14)
    assert text.startswith("power 300 W at 60 rpm of the driver: T1 = P/omega1 = 47.7465 N·m")
    _, mapping = read_part_file(PARTS / "ncg_seed000.toml")
    mapping.update(load_vehicle_mass_kg=1200.0, load_rolling_resistance=0.1, load_propulsors=3, load_efficiency=0.95)
    pw = load_params(NoncircularPairParams, mapping)
    wl, wr = WalkingLaw(60.0, 100.0, 360.0, 2), WalkingLaw(60.0, 90.0, 360.0, 2)
    T1, T2, text = _loads(pw, SimpleNamespace(law=wl, run_law=wr), phi)
    F_R = 0.1 * 1200.0 * 9.80665 / 3
    w = phi - math.pi / 2 * np.floor((phi + math.pi / 4) / (math.pi / 2))
    dX = np.asarray(wl.dX01_dphi(phi), float)
    assert dX == pytest.approx(wl.A + 3 * 100.0 * np.cos(2 * w), rel=1e-14)
    assert T2 == pytest.approx(F_R * dX * 1e-3, rel=1e-14)
    assert T1 == pytest.approx(F_R * dX * 1e-3 / (np.asarray(wr.U(phi), float) * 0.95), rel=1e-14)
    assert text.startswith("vehicle 1200 kg, rolling resistance f = 0.1, 3 driven propulsor(s): F_R = f·M·g/N_p = "
                           "392.27 N per propulsor")
    # a vehicle of half a kilogram (a model) is a vehicle load like any other
    mapping.update(load_vehicle_mass_kg=0.5)
    T1, T2, _ = _loads(load_params(NoncircularPairParams, mapping), SimpleNamespace(law=wl, run_law=wr), phi)
    assert T2 == pytest.approx(0.1 * 0.5 * 9.80665 / 3 * dX * 1e-3, rel=1e-14)
    # a walking law under a torque: no vehicle, no hub speed needed
    mapping.update(load_vehicle_mass_kg=0.0, load_driver_torque_Nm=12.0)
    T1, T2, _ = _loads(load_params(NoncircularPairParams, mapping), SimpleNamespace(law=wl, run_law=wr), phi)
    assert T1.tolist() == [12.0] * 3 and T2 == pytest.approx(12.0 * np.asarray(wr.U(phi), float) * 0.95)


def test_tooth_load_values_write_the_tables_plot_checks_values_and_note_of_the_drive_contact(tmp_path):
    """The circular pair's drive contact over 0.1 .. 0.5 of a driven pitch (an AsBuilt of that span: driver 1.8 .. 9
    deg, 16 phases at the build's 0.5 deg and the bisections): the derived values of that analysis (T1 = 50, T2 = 97
    N·m, c' of ISO 6336-1), the three tables with their columns and rows, the plot, the two safety checks with the
    part file's requirements and the equilibrium, the note's numbers, the progress through a reporter."""
    import csv

    from propulsor.checks.motion.contact_events import DRIVE, REVERSE, resolve_contact
    from propulsor.parts.noncircular_pair.as_built import AsBuilt, pair_outlines
    from propulsor.parts.noncircular_pair.tooth_load_outputs import PEAK_COLUMNS, PHASE_COLUMNS, tooth_load_values
    from propulsor.parts.writer import OutputWriter
    from propulsor.progress import Reporter

    p, dd = _circular_pair(load_S_Fmin=2.5, load_life_hours=100.0, load_driver_speed_rpm=30.0)
    d = dd.d
    pitch = 2 * math.pi / 40
    po = pair_outlines(d, dd.mount)
    dr = resolve_contact(po, d.run_law.theta, 0.1 * pitch, 0.6 * pitch, DRIVE, step_driver_rad=math.radians(0.5))
    rv = resolve_contact(po, d.run_law.theta, 0.1 * pitch, 0.6 * pitch, REVERSE, step_driver_rad=math.radians(2.0))
    ab = AsBuilt(dr, rv, 0.4 * pitch, (), 0.1, 0.2, 0.0)
    said, counts = [], []

    class Progress(Reporter):
        def __init__(self):  # a reporter that keeps what it is told
            pass

        def __call__(self, msg):
            said.append(msg)

        def count(self, phase, done, total, unit=""):
            counts.append((phase, done, total, unit))

    w = OutputWriter(tmp_path, "noncircular_pair", p, progress=Progress())
    tooth_load_values(w, SimpleNamespace(p=p, d=d, mount=dd.mount), {}, ab)
    vals = w.derived
    assert said == ["load per tooth: sharing, contact and root stress of every tooth over the period"]
    assert counts[-1] == ("load per tooth: sampled positions", 16, 16, "position")
    assert [c[1] for c in counts] == list(range(1, 17))
    assert (vals["tooth_load_T1_max_Nm"], vals["tooth_load_T2_min_Nm"]) == (pytest.approx(50.0), pytest.approx(97.0))
    assert vals["tooth_load_c_prime_min"] == pytest.approx(0.8 * 0.975 / 0.06113075, rel=1e-6)
    assert w.tables == ["tables/tooth_load.csv", "tables/tooth_peaks.csv", "tables/tooth_load_factors.csv"]
    assert w.plots == ["plots/tooth_load.png"] and (tmp_path / "plots" / "tooth_load.png").stat().st_size > 0

    def read(name):
        with open(tmp_path / "tables" / f"{name}.csv", newline="", encoding="utf-8") as f:
            return list(csv.reader(f))

    rows = read("tooth_load")
    assert rows[0] == PHASE_COLUMNS
    deg = sorted({float(r[0]) for r in rows[1:]})
    assert len(deg) == vals["tooth_load_phases"] > 16
    assert deg[0] == pytest.approx(1.8, abs=1e-6) and deg[-1] == pytest.approx(9.0, abs=1e-6)
    assert all(float(r[2]) == pytest.approx(50.0) for r in rows[1:])
    peaks = read("tooth_peaks")
    assert peaks[0] == PEAK_COLUMNS and len(peaks) == 61 and [r[0] for r in peaks[1:]] == ["driver"] * 20 + [
        "driven"] * 40
    assert read("tooth_load_factors")[0] == ["factor", "value", "source"] and len(read("tooth_load_factors")) == 26
    assert [c.name for c in w.checks] == ["tooth_load.S_H", "tooth_load.S_F", "tooth_load.equilibrium"]
    sH, sF, eq = w.checks
    assert sH.value == pytest.approx(vals["tooth_load_S_H_min"]) and sH.limit == 1.0 and sH.passed
    assert sF.limit == 2.5 and sF.passed is (vals["tooth_load_S_F_min"] >= 2.5) and eq.passed
    (note,) = w.notes
    assert note.startswith("Load per tooth (gears/tooth_load.py; seed 002: \"the uneven distribution of the load "
                           "between different teeth\"): driver torque T1 = 50 N·m, T2 = T1·U·eta (eta = 0.97); T1 "
                           "50.000 .. 50.000 N·m, T2 97.000 .. 97.000 N·m over one period (")
    assert (f"({len(deg)} phases, every 0.5 deg of driver and every change of the loaded pairs bisected 7 times; "
            f"the drive direction's as-built contact)") in note
    assert "rad of the first contact is a spring of ISO 6336-1's single stiffness c' = 12.760 .. 12.760 N/(mm um) " \
           "(local equivalent gears, E/E_steel = 1.0000) closed after its gap; " in note
    assert (f"{vals['tooth_load_pairs_min']} .. {vals['tooth_load_pairs_max']} pairs loaded (mean "
            f"{vals['tooth_load_pairs_mean']:.3f}); limits:") in note
    assert "(K_A 1.25, K_v 1.1, K_beta 1.2 as given)" in note
    assert (f"Worst teeth: driver {vals['tooth_load_driver_sigma_F_worst_tooth']} (sigma_F "
            f"{vals['tooth_load_driver_sigma_F_max_MPa']:.1f} MPa at driver "
            f"{vals['tooth_load_driver_sigma_F_worst_driver_deg']:.2f} deg), driven "
            f"{vals['tooth_load_driven_sigma_F_worst_tooth']} (sigma_F {vals['tooth_load_driven_sigma_F_max_MPa']:.1f} "
            f"MPa at driver {vals['tooth_load_driven_sigma_F_worst_driver_deg']:.2f} deg)") in note
    assert (f"root stress {vals['tooth_load_driver_uneven_sigma_F']:.3f} (driver), "
            f"{vals['tooth_load_driven_uneven_sigma_F']:.3f} (driven), normal force "
            f"{vals['tooth_load_driver_uneven_F']:.3f} / {vals['tooth_load_driven_uneven_F']:.3f}.") in note
    assert ("Material steel_case_MQ: case-hardened wrought steel (18CrNiMo7-6 / 18Kh2N4MA), 58-62 HRC, ISO 6336-5 "
            "quality MQ; sigma_Hlim 1500 MPa, sigma_FE 850 MPa (endurance limits (5e7 contact, 3e6 root cycles), 1 % "
            "failure probability; ISO 6336-5:2003, Fig. 9 / 10") in note
    assert "uncertainty ISO 6336-5 quality class MQ; ML gives 1300 / 312, ME 1650 / 525 MPa).  Safeties" in note
    assert (f"Safeties: S_H {vals['tooth_load_S_H_min']:.3f} (required 1), S_F {vals['tooth_load_S_F_min']:.3f} "
            f"(required 2.5); each driver tooth is loaded 2 times per driven turn, each driven tooth once.") in note
    assert note.endswith("tables/tooth_load.csv (every loaded pair at every phase), tables/tooth_peaks.csv (every "
                         "tooth), tables/tooth_load_factors.csv (every factor and its source), plots/tooth_load.png.")


# =========================================================================== smooth_law.py
def _part(name, **kw):
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.noncircular_pair import NoncircularPairParams

    _, mapping = read_part_file(PARTS / f"{name}.toml")
    mapping.update(kw)
    return load_params(NoncircularPairParams, mapping)


def test_screen_of_a_convex_law_closes_on_the_module_with_the_part_files_own_cutter():
    """Elliptical e = 0.3, 1:1, z 30, m = 2.5: the driver's pitch ellipse has semi-axis L/2 and its perimeter
    4 (L/2) E(e^2) holds 30 pitches of pi m; every curve convex: only the part file's own cutter (rack, its shaper's
    z0, no catalogue entry), generable."""
    from scipy.special import ellipe

    from propulsor.gears.generability import CutterSpec
    from propulsor.parts.noncircular_pair.smooth_law import screen_smooth

    p = _part("ncg_elliptical")
    law = EllipticalLaw(0.3, 1)
    scr = screen_smooth(p, law)
    L = 2 * 30 * math.pi * 2.5 / (4 * ellipe(0.09))
    assert scr.law is law and scr.m == 2.5 and scr.L == pytest.approx(L, rel=1e-9)
    assert scr.pc.L == scr.L and scr.pc.law is law
    ((entry, sh, cutter, g, why),) = scr.candidates
    assert (entry, sh, why) == (None, None, "") and g.ok
    assert cutter == CutterSpec(m=2.5, alpha=math.radians(20.0), x=0.0, x_H=-0.0, z0=p.shaper_teeth, shaper_x0=None)
    assert scr.generable == scr.candidates
    # the centre distance given instead: the module that closes it (linear in L)
    p2 = _part("ncg_elliptical", module_mm=0.0, center_distance_mm=80.0)
    scr2 = screen_smooth(p2, law)
    assert scr2.L == 80.0 and scr2.m == pytest.approx(2.5 * 80.0 / L, rel=1e-9)


def test_screen_of_a_law_no_cutter_generates_names_the_limit_and_the_remedies():
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.smooth_law import screen_smooth

    p = _part("ncg_elliptical", driven_teeth=16, eccentricity=0.1)
    with pytest.raises(InputError) as e:
        screen_smooth(p, EllipticalLaw(0.1, 1))
    assert str(e.value) == (
        "driver_shift = 0.0: the elliptical law's pitch curves are not generable at m = 2.5, z 16/16, L = 40.100 mm "
        "with the catalogue cutters (driver: convex rho_min 19.850 mm < undercut limit 21.372 mm; works with "
        "driver_shift >= 0.071, or driven_teeth >= 18 at module_mm = 2.5, or module_mm <= 2.322 mm at L = 40.100 mm; "
        "driven: convex rho_min 19.850 mm < undercut limit 21.372 mm; works with driver_shift <= -0.071, or "
        "driven_teeth >= 18 at module_mm = 2.5, or module_mm <= 2.322 mm at L = 40.100 mm)")


def test_a_concave_pitch_curve_with_law_search_tries_the_catalogue_shapers_largest_first():
    from propulsor.gears.catalogue import shaper_entry
    from propulsor.parts.noncircular_pair.smooth_law import screen_smooth

    p = _part("ncg_fourier_seed002")
    from propulsor.parts.noncircular_pair.feasibility import law_of

    law = law_of(p)
    scr = screen_smooth(p, law)
    assert [c[0].d0_mm for c in scr.candidates] == [100.0, 75.0, 50.0, 38.0, 25.0]
    assert [(c[1].z0, c[1].x0) for c in scr.candidates] == [(40, 0.0), (30, 0.0), (20, 0.0), (15, 0.0), (10, 0.0)]
    assert all(c[0] == shaper_entry(c[0].d0_mm, 2.5) and c[2].z0 == c[1].z0 and c[2].shaper_x0 == c[1].x0
               for c in scr.candidates)
    assert scr.pc.curvature("driver").concave or scr.pc.curvature("driven").concave
    # without the search: the part file's own shaper only
    own = screen_smooth(_part("ncg_fourier_seed002", law_search=False), law)
    assert len(own.candidates) == 1 and own.candidates[0][0] is None and own.candidates[0][1] is None
    assert own.candidates[0][2].z0 == p.shaper_teeth and own.candidates[0][2].shaper_x0 is None


def test_generability_limits_are_the_part_files_field_limits():
    from propulsor.parts.noncircular_pair.smooth_law import generability_limits

    assert generability_limits(_part("ncg_elliptical")) == {"x": (-1.0, 1.5), "x_H": (-1.5, 1.0), "z_H": (4, 480),
                                                            "m": (0.0, 50.0), "z0": (6, 200)}


def test_tooth_settings_of_a_cutter():
    """j_n split between the wheels: j_n / (2 cos alpha) of arc thickness each; tip land and height in modules."""
    from propulsor.parts.noncircular_pair.cutting import rack_of
    from propulsor.parts.noncircular_pair.smooth_law import _tooth_common

    p = _part("ncg_elliptical", tip_land_min_module=0.3, tip_height_max_module=1.1)
    cutter = SimpleNamespace(z0=17)
    sh = object()
    got = _tooth_common(p, 2.0, cutter, sh)
    assert got == dict(m=2.0, thinning_mm=pytest.approx(0.16 / (2 * math.cos(math.radians(20.0)))), rack=rack_of(p),
                       z0=17, tip_min_mm=pytest.approx(0.6), shaper=sh, tip_max_mm=pytest.approx(2.2))


def test_design_of_the_screened_law_generates_both_wheels_and_says_so():
    from propulsor.parts.noncircular_pair.smooth_law import design_smooth, screen_smooth

    p = _part("ncg_elliptical")
    law = EllipticalLaw(0.3, 1)
    scr = screen_smooth(p, law)
    said = []
    d = design_smooth(p, scr, said.append)
    assert said[:2] == ["generated: generability of the elliptical law at m = 2.5, z 30/30",
                        "generated: the teeth of both wheels (30 and 30), rack/shaper envelopes"]
    assert (d.method, d.law, d.run_law, d.L, d.m, d.z_H, d.z, d.pc) == ("generated", law, law, scr.L, 2.5, 30, 30,
                                                                       scr.pc)
    assert d.shaper is None and len(d.driver.teeth) == len(d.driven.teeth) == 30
    sm = d.smoothing
    assert (sm.law, sm.delta, sm.L, sm.z_H, sm.z, sm.ripple) == (law, 0.0, scr.L, 30, 30, None)
    assert sm.cutter is scr.candidates[0][2] and sm.generability is scr.candidates[0][3]
    assert d.closure_error == sm.closure_error


def test_the_refusal_names_the_shift_for_a_convex_limit_else_the_shaper_once_per_distinct_limit():
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.smooth_law import SmoothScreen, _not_generable, design_smooth

    p = _part("ncg_elliptical", shaper_teeth=23)
    law = EllipticalLaw(0.3, 1)
    scr = SmoothScreen(law, 2.5, 76.7573, None, ())
    e = _not_generable(p, scr, ["driver: convex rho_min 1 mm < undercut limit 2 mm", "shaper d0 50: too big"])
    assert isinstance(e, InputError) and (e.parameter, e.value) == ("driver_shift", 0.0)
    assert str(e) == ("driver_shift = 0.0: the elliptical law's pitch curves are not generable at m = 2.5, z 30/30, "
                      "L = 76.757 mm with the catalogue cutters (driver: convex rho_min 1 mm < undercut limit 2 mm | "
                      "shaper d0 50: too big)")
    e = _not_generable(p, scr, ["shaper d0 100: a", "shaper d0 100: a", "shaper d0 75: b"])
    assert (e.parameter, e.value) == ("shaper_teeth", 23)
    assert str(e).endswith("with the catalogue cutters (shaper d0 100: a | shaper d0 75: b)")
    assert _not_generable(p, scr, []).parameter == "driver_shift"
    # a design whose every screened cutter was refused: the refusal of their limits, after saying what it tries
    said = []
    refused = SmoothScreen(law, 2.5, 76.7573, None, ((None, None, None, None, "shaper d0 38: no"),
                                                      (None, None, None, None, "shaper d0 25: no")))
    with pytest.raises(InputError) as err:
        design_smooth(p, refused, said.append)
    assert err.value.parameter == "shaper_teeth" and str(err.value).endswith("(shaper d0 38: no | shaper d0 25: no)")
    assert said == ["generated: generability of the elliptical law at m = 2.5, z 30/30"]


def test_iso1328_source_rounds_each_number_from_its_own_micrometres():
    """Numbers a hair below a rounding step: m = 2, driver z 19 (d 38): F_r 0.8 (0.6 + 1.25 sqrt 38 + 7) = 12.2444 um
    at grade 5 ("12.2"); L = 265.34068 mm: f_a = 7 i / 2 = 11.0495 um ("11.0"); alpha with 16.08 tan(alpha) =
    15.0495 um ("15.0"): a factor 1.001 anywhere would round them up."""
    from propulsor.parts.noncircular_pair.tolerance import iso1328

    t = iso1328(SimpleNamespace(m=2.0, z=19, z_H=50), 265.3406785437347, 5, 0.7523066000146901)
    assert t.source == ("ISO 1328 grade 5: F_r 12.2 / 16.1 um (driver / driven), f_a = IT5/2 = 11.0 um, flanks "
                        "thinner by 0 .. 15.0 um")


def test_load_per_tooth_of_the_elliptical_pair_takes_the_least_radii_and_stiffness_and_either_direction():
    """The elliptical pair (r1 = L q / (1 + e cos theta) varies) under 20 N·m over 0.3 rad of driven angle at 3 deg
    of driver: c' the least and largest of ISO 6336-1's at z_n = 2 rho / m over 2049 points of the span; the window
    4 deflections T1 / (r1,min cos alpha) / (c'_min b) over r_H,min; the reverse direction (the other flanks, placed
    by the reverse contact) balances too.  A light load (0.02 N·m): the window's floor 2e-5 rad."""
    from propulsor.checks.motion.contact_events import DRIVE, REVERSE, resolve_contact
    from propulsor.gears.tooth_load import c_prime
    from propulsor.parts.noncircular_pair.as_built import pair_outlines
    from propulsor.parts.noncircular_pair.tooth_load_outputs import analyse

    p = _load_params(load_K_A=1.0, load_K_v=1.0, load_K_beta=1.0)
    _, d = _elliptical_design()
    po = pair_outlines(d, d.L)
    phi0, span = 0.4, 0.3
    tab = np.linspace(phi0, phi0 + span, 2049)
    zn1, zn2 = 2 * np.asarray(d.pc.rho(tab), float) / 2.5, 2 * np.asarray(d.pc.rho_H(tab), float) / 2.5
    cp = c_prime(zn1, zn2, 0.0, 0.0, math.radians(20.0), 1.25, 1.0)
    r1, rH = float(np.min(d.pc.r(tab))), float(np.min(d.pc.r_H(tab)))
    assert float(np.max(d.pc.r(tab))) > r1 * 1.05 and float(np.max(cp)) > float(np.min(cp)) * 1.001
    for direction in (DRIVE, REVERSE):
        c = resolve_contact(po, d.law.theta, phi0 - 0.05, phi0 + span + 0.05, direction,
                            step_driver_rad=math.radians(3.0))
        tl = analyse(d, d.L, p, c.phi, c.te, phi0, span, step_deg=3.0, direction=direction)
        assert tl.c_prime == (pytest.approx(float(np.min(cp)), rel=1e-12), pytest.approx(float(np.max(cp)),
                                                                                         rel=1e-12))
        defl = 20e3 / (r1 * math.cos(math.radians(20.0))) / (float(np.min(cp)) * 15.0 * 1e3)
        assert tl.window_rad == pytest.approx(4 * defl / rH, rel=1e-12)
        assert tl.lost == 0 and tl.imbalance < 1e-9 and len(tl.rows) >= len(tl.theta)
        # interpolated on the 2049-point table of the span: 2e-9 relative
        assert tl.T2 == pytest.approx(20.0 * 0.97 * np.asarray(d.law.U(tl.phi), float), rel=1e-7)
        if direction == DRIVE:
            drive_rows = [r[:7] for r in tl.rows]
        else:
            assert [r[:7] for r in tl.rows] != drive_rows
    light = analyse(d, d.L, _load_params(load_driver_torque_Nm=0.02), c.phi, c.te, phi0, 0.05, step_deg=3.0,
                    direction=REVERSE)
    assert light.window_rad == 2e-5
    # the pair mounted 8 mm apart: no pair within reach at any phase, the load still tabled
    off = analyse(d, d.L + 8.0, p, c.phi, c.te, phi0, 0.05, step_deg=3.0, direction=REVERSE)
    assert off.lost == len(off.theta) > 0 and off.rows == [] and off.loaded.tolist() == [0] * len(off.theta)
    assert off.T1 == pytest.approx(np.full(len(off.theta), 20.0))


def test_a_lightly_loaded_tooth_counts_below_one_newton_and_one_megapascal():
    """Peaks of 0.5 N and 0.5 MPa (a light load or a soft material): measured like any other (only 0 is unloaded)."""
    from propulsor.parts.noncircular_pair.tooth_load_outputs import _Peak, peak_rows, summary

    tl = _tooth_load(peaks={"driver": {0: _Peak(0.5, 0.5, 1.0, 0.5, 2.0), 1: _Peak(0.25, 0.4, 3.0, 0.2, 4.0)},
                            "driven": {0: _Peak(0.5, 0.6, 1.5, 0.8, 2.5)}})
    p = _load_params()
    rows = peak_rows(tl, p)
    assert rows[0][11:] == [pytest.approx(1500 / 0.5), pytest.approx(850 / 0.5)]
    v = summary(tl, p)
    assert v["tooth_load_driver_F_n_max_N"] == 0.5 and v["tooth_load_driver_uneven_F"] == 2.0
    assert v["tooth_load_driver_uneven_sigma_F"] == pytest.approx(2.5)
    assert v["tooth_load_driver_sigma_F_worst_tooth"] == 0 and v["tooth_load_driver_sigma_H_worst_tooth"] == 0
    assert v["tooth_load_driver_sigma_H_max_MPa"] == 0.5 and v["tooth_load_S_H_min"] == pytest.approx(1500 / 0.6)


def test_half_an_hour_of_life_and_a_section_measured_under_two_numbers_and_a_light_plot():
    """0.5 h at 100 rpm of the driver: 1500 driven turns, 3000 cycles of a driver tooth (Z_NT 1.6 below 1e5 cycles,
    Y_NT 2.5 below 1e3 ... (3e6/N)^0.115 above); a tooth's section found under its own number before another of its
    class; a plot of peaks below 1 MPa."""
    from propulsor.parts.noncircular_pair.tooth_load_outputs import _Peak, _life, _plot

    tl = _tooth_load()
    N, Z, Y = _life(tl, _load_params(load_driver_speed_rpm=100.0, load_life_hours=0.5), "driver")
    assert N == pytest.approx(3000.0) and Z == 1.6 and Y == pytest.approx((3e6 / 3000.0) ** 0.115, rel=1e-12)
    a, b = _section(6, 4.5, 0.7, 0.9), _section(2, 4.2, 0.7, 0.9)
    tl2 = _tooth_load(sections={"driver": {6: a, 2: b}, "driven": {}})
    assert tl2.section_of("driver", 2) is b and tl2.section_of("driver", 6) is b
    w = _Plots()
    _plot(w, _tooth_load(peaks={"driver": {0: _Peak(0.5, 0.5, 1.0, 0.5, 2.0), 1: _Peak(0.25, 0.4, 3.0, 0.2, 4.0)},
                                "driven": {0: _Peak(0.5, 0.6, 1.5, 0.8, 2.5)}}), _load_params())
    fig = w.figs["tooth_load"]
    assert fig.axes[0].get_title().endswith("(most / least loaded root 2.500)")
    import matplotlib.pyplot as plt

    plt.close(fig)


def _record_generate_pair(monkeypatch, outcomes):
    """cutting.generate_pair replaced (stand_ins.record_generate_pair)."""
    from propulsor.parts.noncircular_pair import cutting

    return record_generate_pair(monkeypatch, cutting, outcomes)


def test_design_with_law_search_cuts_with_the_next_catalogue_shaper_where_the_generator_refuses(monkeypatch):
    """Seed 002's Fourier law (driven wheel concave, driver convex, x = 0.5): the five catalogue shapers in turn, the
    driver cut at +x and the driven wheel at -x with the shaper's own settings on one arc-length frame; a refusal
    (InputError, RuntimeError, ValueError) moves on to the next shaper, the first pair cut is the design."""
    from propulsor.errors import InputError
    from propulsor.gears.noncircular_teeth import ArcFrame
    from propulsor.parts.noncircular_pair.cutting import rack_of
    from propulsor.parts.noncircular_pair.feasibility import law_of
    from propulsor.parts.noncircular_pair.smooth_law import design_smooth, screen_smooth

    p = _part("ncg_fourier_seed002")
    law = law_of(p)
    scr = screen_smooth(p, law)
    assert [c[4] for c in scr.candidates] == [""] * 5
    assert not scr.pc.curvature("driver").concave and scr.pc.curvature("driven").concave
    calls = _record_generate_pair(monkeypatch, [InputError("z0", 40, "cannot cut: the tip", "a hint"),
                                                RuntimeError("lost: the envelope"), ValueError("x: y: z"),
                                                ("DRV", "DVN")])
    said = []
    d = design_smooth(p, scr, said.append)
    assert len(calls) == 4
    assert said == ["generated: generability of the fourier law at m = 2.5, z 20/80"] + [
        "generated: the teeth of both wheels (20 and 80), rack/shaper envelopes"] * 4
    th = 0.16 / (2 * math.cos(math.radians(20.0)))
    for call, (entry, sh, cutter, g, why) in zip(calls, scr.candidates):
        assert call.pc is scr.pc and call.frame is calls[0].frame and call.progress == said.append
        for spec, x in ((call.drv, 0.5), (call.dvn, -0.5)):
            assert (spec.m, spec.x, spec.z0, spec.shaper) == (2.5, x, sh.z0, sh)
            assert spec.thinning_mm == pytest.approx(th) and spec.rack == rack_of(p)
    assert isinstance(calls[0].frame, ArcFrame) and calls[0].frame.pc is scr.pc
    entry, sh, cutter, g, _ = scr.candidates[3]
    assert (d.method, d.law, d.run_law, d.L, d.m, d.z_H, d.z, d.pc) == ("generated", law, law, scr.L, 2.5, 80, 20,
                                                                       scr.pc)
    assert (d.driver, d.driven, d.shaper) == ("DRV", "DVN", entry) and entry.d0_mm == 38.0
    assert d.smoothing.cutter is cutter and d.smoothing.generability is g and d.smoothing.delta == 0.0
    assert d.closure_error == d.smoothing.closure_error
    assert type(d.z) is int and type(d.smoothing.z) is int and d.smoothing.z == 20  # whole teeth, not 20.0


def test_design_with_law_search_refused_by_every_shaper_lists_each_refusal_once(monkeypatch):
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.feasibility import law_of
    from propulsor.parts.noncircular_pair.smooth_law import design_smooth, screen_smooth

    p = _part("ncg_fourier_seed002")
    scr = screen_smooth(p, law_of(p))
    _record_generate_pair(monkeypatch, [InputError("z0", 40, "cannot cut: the tip", "a hint"),
                                        RuntimeError("lost: the envelope"), ValueError("x: y: z"),
                                        RuntimeError("lost"), InputError("m", 2.5, "too small")])
    with pytest.raises(InputError) as e:
        design_smooth(p, scr, lambda s: None)
    assert str(e.value) == (
        "shaper_teeth = 20: the fourier law's pitch curves are not generable at m = 2.5, z 20/80, "
        f"L = {scr.L:.3f} mm with the catalogue cutters (shaper d0 100: cannot cut: the tip (a hint) | "
        "shaper d0 75: the envelope | shaper d0 50: y: z | shaper d0 38: lost | shaper d0 25: too small)")


def test_design_without_the_search_or_of_convex_curves_passes_the_generators_refusal_on_by_its_key(monkeypatch):
    """The generator's z0 is the part file's shaper_teeth (the own shaper) or shaper_d0_mm (a catalogue shaper);
    law_search retries only where a pitch curve is concave."""
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.feasibility import law_of
    from propulsor.parts.noncircular_pair.smooth_law import design_smooth, screen_smooth

    for name, kw, key in (("ncg_fourier_seed002", dict(law_search=False), "shaper_teeth"),
                          ("ncg_fourier_seed002", dict(law_search=False, shaper_d0_mm=50.0), "shaper_d0_mm"),
                          ("ncg_elliptical", dict(law_search=True), "shaper_teeth"),
                          ("ncg_elliptical", dict(law_search=True, shaper_d0_mm=50.0), "shaper_d0_mm")):
        p = _part(name, **kw)
        scr = screen_smooth(p, law_of(p))
        assert len(scr.candidates) == 1
        calls = _record_generate_pair(monkeypatch, [InputError("z0", 7, "cannot cut", "a hint")])
        with pytest.raises(InputError) as e:
            design_smooth(p, scr, lambda s: None)
        assert str(e.value) == f"{key} = 7: cannot cut (a hint)" and len(calls) == 1
        _record_generate_pair(monkeypatch, [InputError("m", 2.5, "too small")])
        with pytest.raises(InputError) as e:
            design_smooth(p, scr, lambda s: None)
        assert str(e.value) == "module_mm = 2.5: too small"
        for exc in (RuntimeError("lost"), ValueError("bad")):
            _record_generate_pair(monkeypatch, [exc])
            with pytest.raises(type(exc)) as e:
                design_smooth(p, scr, lambda s: None)
            assert e.value is exc


def test_screen_with_a_catalogue_shaper_a_shifted_driver_and_a_one_millimetre_module():
    """shaper_d0_mm = 50 at m = 2.5: the catalogue's z0 = 20 and x0 = 0 (not the file's shaper_teeth = 23); the
    driven wheel cut at -x; module 1 mm: L of 30 pitches of pi on 4 (L/2) E(e^2)."""
    from scipy.special import ellipe

    from propulsor.gears.catalogue import catalogue_shaper, shaper_entry
    from propulsor.gears.generability import CutterSpec
    from propulsor.parts.noncircular_pair.smooth_law import screen_smooth

    law = EllipticalLaw(0.3, 1)
    p = _part("ncg_elliptical", shaper_d0_mm=50.0, shaper_teeth=23, driver_shift=0.3)
    ((entry, sh, cutter, g, why),) = screen_smooth(p, law).candidates
    assert entry == shaper_entry(50.0, 2.5) and sh == catalogue_shaper(50.0, 2.5) and (sh.z0, sh.x0) == (20, 0.0)
    assert cutter == CutterSpec(m=2.5, alpha=math.radians(20.0), x=0.3, x_H=-0.3, z0=20, shaper_x0=0.0)
    assert why == "" and g.ok
    steep = screen_smooth(_part("ncg_elliptical", pressure_angle_deg=21.0), law)
    assert steep.candidates[0][2].alpha == math.radians(21.0)
    one = screen_smooth(_part("ncg_elliptical", module_mm=1.0), law)
    assert one.m == 1.0 and one.L == pytest.approx(2 * 30 * math.pi / (4 * ellipe(0.09)), rel=1e-9)


def test_screen_refusals_name_the_part_files_keys():
    """The law's refusals in the part file's keys (z_H, L named driven_teeth, center_distance_mm; values the file's
    own validation would refuse first, set past it); the installed centre distance on both sides of L - 1e-9."""
    import dataclasses

    from scipy.special import ellipe

    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.feasibility import law_of
    from propulsor.parts.noncircular_pair.smooth_law import screen_smooth

    def refusal(p, **kw):
        q = dataclasses.replace(p, **kw)
        with pytest.raises(InputError) as e:
            screen_smooth(q, law_of(q))
        return str(e.value)

    seed = _part("ncg_fourier_seed002")
    multiple = "must be a multiple of n = 4 so the driver has z_H/n whole teeth (nearest valid: 80, 84)"
    assert refusal(seed, driven_teeth=81) == f"driven_teeth = 81: {multiple}"
    assert refusal(seed, module_mm=0.0, center_distance_mm=124.0, driven_teeth=82) == f"driven_teeth = 82: {multiple}"
    assert refusal(seed, module_mm=0.0, center_distance_mm=0.0) == "center_distance_mm = 0.0: must be > 0 mm"
    # z 1/4: the remedies within the part file's limits: the concave |rho| 6.219 mm would take a shaper of
    # z0 <= ceil(2 x 6.219 / 2.5) - 1 = 4 teeth, below shaper_teeth's least 6: none is offered
    assert refusal(_part("ncg_fourier_seed002", driven_teeth=4, law_search=False, shaper_teeth=6)) == (
        "driver_shift = 0.5: the fourier law's pitch curves are not generable at m = 2.5, z 1/4, L = 6.221 mm with "
        "the catalogue cutters (driver: convex rho_min 0.962 mm < undercut limit 10.686 mm; works with driver_shift "
        ">= 0.955, or driven_teeth >= 48 at module_mm = 2.5, or module_mm <= 0.225 mm at L = 6.221 mm; driven: "
        "convex rho_min 2.290 mm < undercut limit 32.057 mm; works with driver_shift <= -0.893, or driven_teeth >= "
        "56 at module_mm = 2.5, or module_mm <= 0.1786 mm at L = 6.221 mm; driven: concave |rho|_min 6.219 mm: no "
        "shaper within the limits fits inside it (r0 < |rho|; a smoother law))")
    # the installed centre distance: at least L (e = 0.3, z 30, m = 2.5), to 1e-9 mm
    L = float(2 * 30 * math.pi * 2.5 / (4 * ellipe(0.09)))
    ell = _part("ncg_elliptical")
    assert refusal(ell, mounting_distance_mm=L - 2e-9) == (
        f"mounting_distance_mm = {L - 2e-9!r}: must be >= the design centre distance L = {L:.6f} mm (or 0)")
    for ok in (L - 0.5e-9, L):
        assert screen_smooth(dataclasses.replace(ell, mounting_distance_mm=ok), EllipticalLaw(0.3, 1)).L == pytest.approx(L)


def test_screen_of_a_concave_curve_needs_a_shaper_that_can_be_made():
    """Seed 002's driven wheel is concave: its shaper z0 = 6 with x0 = +0.5 (-x of the driven wheel, x = -0.5) has
    overlapping tip rounds.  Without the search that is the refusal; with it at m = 7 (no catalogue shaper: the part
    file's own is tried) it is the one limit listed."""
    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.feasibility import law_of
    from propulsor.parts.noncircular_pair.smooth_law import screen_smooth

    made = ("the shaper z0 = 6 with x0 = +0.5 (-x of the gear it cuts) cannot be made: rho_a0_star = 0.1: tip rounds "
            "of the shaper tooth overlap (use a smaller profile shift (driver_shift) or another shaper)")
    p = _part("ncg_fourier_seed002", shaper_teeth=6, law_search=False)
    with pytest.raises(InputError) as e:
        screen_smooth(p, law_of(p))
    assert str(e.value) == f"shaper_teeth = 6: {made}"
    p = _part("ncg_fourier_seed002", shaper_teeth=6, module_mm=7.0)
    with pytest.raises(InputError) as e:
        screen_smooth(p, law_of(p))
    assert str(e.value) == ("shaper_teeth = 6: the fourier law's pitch curves are not generable at m = 7, z 20/80, "
                            f"L = 348.350 mm with the catalogue cutters (shaper_teeth = 6: {made})")
    # at m = 7 the part file's own shaper (z0 = 20) is the one tried; at m = 5 the catalogue's d100 only
    ok = screen_smooth(_part("ncg_fourier_seed002", module_mm=7.0), law_of(p))
    assert [(c[0], c[1], c[2].z0, c[4]) for c in ok.candidates] == [(None, None, 20, "")]
    five = screen_smooth(_part("ncg_fourier_seed002", module_mm=5.0), law_of(p))
    assert [(c[0].d0_mm, c[1].z0, c[4]) for c in five.candidates] == [(100.0, 20, "")]


def test_screen_with_law_search_lists_each_catalogue_shaper_that_cannot_cut_the_concave_wheel(monkeypatch):
    """The shaper tools are asked for the concave driven wheel only (x = -0.5), under the catalogue's key; a shaper
    that cannot be made is listed by its d0 with the limit, the others stay."""
    from propulsor.errors import InputError
    from propulsor.gears.noncircular_teeth import ToothSpec
    from propulsor.parts.noncircular_pair.feasibility import law_of
    from propulsor.parts.noncircular_pair.smooth_law import screen_smooth

    asked = []

    def tools(self):
        asked.append((self.x, self.z0, self.shaper.z0))
        if self.z0 in (40, 20):
            raise InputError("z0", self.z0, f"no z0 {self.z0}: really", "a hint")
        return ()

    monkeypatch.setattr(ToothSpec, "shaper_tools", tools)
    p = _part("ncg_fourier_seed002")
    scr = screen_smooth(p, law_of(p))
    assert asked == [(-0.5, z, z) for z in (40, 30, 20, 15, 10)]
    assert [c[4] for c in scr.candidates] == ["shaper d0 100: no z0 40: really (a hint)", "",
                                              "shaper d0 50: no z0 20: really (a hint)", "", ""]
    assert [c[0].d0_mm for c in scr.generable] == [75.0, 38.0, 25.0]
    # without the search, the part file's catalogue shaper that cannot be made is the refusal, under its own key
    asked.clear()
    p = _part("ncg_fourier_seed002", law_search=False, shaper_d0_mm=50.0)
    with pytest.raises(InputError) as e:
        screen_smooth(p, law_of(p))
    assert str(e.value) == "shaper_d0_mm = 20: no z0 20: really (a hint)" and asked == [(-0.5, 20, 20)]


# =========================================================================== design.py
def test_mounting_is_the_design_centre_distance_unless_a_distance_at_least_as_large_is_given():
    import dataclasses

    from propulsor.errors import InputError
    from propulsor.parts.noncircular_pair.design import mounting

    p = _part("ncg_elliptical")
    d = SimpleNamespace(L=76.5)
    at = lambda v: mounting(dataclasses.replace(p, mounting_distance_mm=v), d)  # noqa: E731
    assert at(0.0) == 76.5 and at(80.0) == 80.0 and at(76.5) == 76.5 and at(76.5 - 0.5e-9) == 76.5 - 0.5e-9
    assert at(76.5 - 1e-9) == 76.5 - 1e-9  # the limit itself is taken
    for v in (76.5 - 2e-9, 1.0, 0.5):
        with pytest.raises(InputError) as e:
            at(v)
        assert str(e.value) == (f"mounting_distance_mm = {v!r}: must be >= the design centre distance "
                                "L = 76.500000 mm (or 0)")


def _keyed_bore_area(d, b, t2):
    """A bore of diameter d with a hub keyway b wide, t2 deep above the bore's top: the circle less the cap above the
    chord y_s = sqrt(R^2 - b^2/4), plus the keyway's rectangle from y_s to R + t2."""
    R = d / 2
    ys = math.sqrt(R * R - b * b / 4)
    cap = R * R * math.acos(ys / R) - ys * b / 2
    return math.pi * R * R - cap + b * (R + t2 - ys)


def test_a_bore_is_cut_into_the_profile_with_its_keyway_and_none_of_zero_diameter():
    """Bores of 16 mm (DIN 6885-1 keyway b = 5, t2 = 2.3 mm) with and without the keyway and of 1 mm, in a 60 mm
    disc; a bore of 0 leaves the profile as it is."""
    from propulsor.geometry.profile import Profile, circle_loop
    from propulsor.parts.noncircular_pair.bores import Bore
    from propulsor.parts.noncircular_pair.design import _with_bore

    disc = Profile(circle_loop(30.0), [], "wheel")
    full = math.pi * 900
    assert _with_bore(disc, Bore(0.0, True, False)) is disc
    keyed = _with_bore(disc, Bore(16.0, True, True, "why"))
    assert keyed.name == "wheel" and keyed.outer is disc.outer and len(keyed.holes) == 1
    assert keyed.area(1e-6) == pytest.approx(full - _keyed_bore_area(16.0, 5.0, 2.3), rel=1e-6)
    plain = _with_bore(disc, Bore(16.0, False, False))
    assert plain.area(1e-6) == pytest.approx(full - math.pi * 64, rel=1e-6)
    small = _with_bore(disc, Bore(1.0, False, False))
    assert len(small.holes) == 1 and small.area(1e-7) == pytest.approx(full - math.pi * 0.25, rel=1e-8)


def test_gear_profiles_cut_the_chosen_bores_into_each_wheel():
    from propulsor.geometry.profile import Profile, circle_loop
    from propulsor.parts.noncircular_pair.bores import Bore
    from propulsor.parts.noncircular_pair.design import gear_profiles

    d = SimpleNamespace(driver=SimpleNamespace(profile=Profile(circle_loop(20.0), [], "driver")),
                        driven=SimpleNamespace(profile=Profile(circle_loop(40.0), [], "driven")))
    drv, dvn = gear_profiles(_part("ncg_elliptical"), d, (Bore(0.0, True, False), Bore(30.0, True, True)))
    assert drv is d.driver.profile and dvn.name == "driven"
    assert dvn.area(1e-6) == pytest.approx(math.pi * 1600 - _keyed_bore_area(30.0, 8.0, 3.3), rel=1e-6)


def test_pair_design_of_the_elliptical_file_with_its_bores_profiles_and_mounting():
    """The part file's 16 mm bores with DIN 6885-1 keyways (b = 5, t2 = 2.3 mm) cut into both wheels, the design's own
    centre distance as the mounting, the design's steps told."""
    from propulsor.parts.noncircular_pair.bores import bores
    from propulsor.parts.noncircular_pair.design import design, pair_design

    p = _part("ncg_elliptical")
    said = []
    dd = pair_design(p, progress=said.append)
    d = dd.d
    assert said == ["generated: generability of the elliptical law at m = 2.5, z 30/30",
                    "generated: the teeth of both wheels (30 and 30), rack/shaper envelopes"]
    assert d.method == "generated" and (d.z, d.z_H, d.m) == (30, 30, 2.5) and dd.mount == d.L
    assert dd.bores == bores(p, d) and [b.d_mm for b in dd.bores] == [16.0, 16.0]
    assert (dd.p.driver_bore_mm, dd.p.driven_bore_mm) == (16.0, 16.0)
    hole = _keyed_bore_area(16.0, 5.0, 2.3)
    for prof, gear in zip(dd.profiles, (d.driver, d.driven)):
        assert prof.outer is gear.profile.outer and len(prof.holes) == 1
        assert prof.area(1e-4) == pytest.approx(gear.profile.area(1e-4) - hole, rel=1e-5)
    assert design(p).L == d.L
    # without chosen bores: the part file's, sized or given (bores.bores), the same cut
    from propulsor.parts.noncircular_pair.design import gear_profiles

    assert [q.area(1e-4) for q in gear_profiles(p, d)] == [q.area(1e-4) for q in dd.profiles]


def test_load_per_tooth_of_a_printed_pair_takes_the_plastics_own_elasticity():
    """PLA (E = 3000 MPa, nu = 0.36) on both wheels: Z_E = sqrt(E / (2 pi (1 - nu^2))) of ISO 6336-2 eq. 18 with both
    materials PLA, not steel's 189.8 for one of them; the circular pair placed at its constant transmission error
    -j_t / (2 r_H) over a third of a pitch."""
    from propulsor.gears.gear_materials import material
    from propulsor.parts.noncircular_pair.tooth_load_outputs import analyse

    p, dd = _circular_pair(gear_material="PLA")
    d = dd.d
    c_phi = np.linspace(0.0, 2 * math.pi, 401)
    c_te = np.full(401, -0.16 / math.cos(math.radians(20.0)) / 100.0)
    pitch = 2 * math.pi / 40
    tl = analyse(d, dd.mount, p, c_phi, c_te, 0.2 * pitch, 0.3 * pitch, step_deg=1.0)
    assert tl.material == material("PLA")
    assert tl.Z_E == pytest.approx(math.sqrt(3000.0 / (2 * math.pi * (1 - 0.36 ** 2))), rel=1e-12)
    # c' of ISO 6336-1 at z_n = 20 / 40, x = +-0.5, C_B = 0.975, scaled by E / E_steel = 3000 / 206000
    cp = 0.8 * 0.975 / 0.06113075 * 3000.0 / 206000.0
    assert tl.c_prime == (pytest.approx(cp, rel=1e-6), pytest.approx(cp, rel=1e-6))
    # a span under one step of the driver (0.4 deg of 1 deg): its two ends only (theta = 2 phi)
    short = analyse(d, dd.mount, p, c_phi, c_te, 0.5 * pitch, math.radians(0.2), step_deg=1.0)
    assert np.degrees(short.theta) == pytest.approx([9.0, 9.4], abs=1e-9)


def test_load_per_tooth_puts_each_wheels_force_on_its_line_of_action_against_its_turn():
    """The circular pair of ``_circular_pair`` (driver r_b = 25 cos 20 deg, driven 50 cos 20 deg): the force that
    ``analyse`` hands to the root-stress step of each loaded contact, in that wheel's body frame at the contact point
    P.  The two are one force, opposite (the driver's turned into the world by theta, the driven wheel's by its
    actual angle phi + te, sum to zero): the angle that makes them cancel also takes both contact points to one world
    point (driven: R(-phi_c) P; driver: (L, 0) + R(theta) P) to 0.02 mm, and lies within 0.01 rad of the law's phi
    (te = -1.7e-3 rad: the driven wheel behind the law by half the backlash).
    Each resists the driver's turn and drives the driven wheel: its moment is -F r_b on both wheels (counter-clockwise
    positive in both body frames), to 1e-3 of it on the flanks (the polylines' facets)."""
    from propulsor.gears import tooth_load as tlm
    from propulsor.parts.noncircular_pair.tooth_load_outputs import analyse

    p, dd, pitch, cl = _circular_drive_contact(2)
    d = dd.d
    seen = []
    real = tlm.root_stress

    def recorder(sec, P, Fv, *a, **k):
        seen.append((np.asarray(P, float), np.asarray(Fv, float)))
        return real(sec, P, Fv, *a, **k)

    tlm.root_stress = recorder
    try:
        tl = analyse(d, dd.mount, p, cl.phi, cl.te, 0.2 * pitch, 0.8 * pitch, step_deg=1.0)
    finally:
        tlm.root_stress = real
    alpha = math.radians(20.0)
    rb = (25.0 * math.cos(alpha), 50.0 * math.cos(alpha))
    rot = lambda a, v: np.array([math.cos(a) * v[0] - math.sin(a) * v[1], math.sin(a) * v[0] + math.cos(a) * v[1]])
    # the driver's and the driven wheel's call of each loaded contact, in the order of the table's rows
    assert len(seen) == 2 * len(tl.rows) > 0
    flanks, gaps, tes = 0, [], []
    for row, (Pd, Fd), (Pn, Fn) in zip(tl.rows, seen[0::2], seen[1::2]):
        F, theta, phi = row[9], math.radians(row[0]), math.radians(row[1])
        assert np.linalg.norm(Fd) == pytest.approx(F, rel=1e-12) and np.linalg.norm(Fn) == pytest.approx(F, rel=1e-12)
        assert float(np.hypot(*Pd)) == pytest.approx(row[24], rel=1e-12)
        assert float(np.hypot(*Pn)) == pytest.approx(row[25], rel=1e-12)
        phi_c = math.atan2(Fn[1], Fn[0]) - math.atan2(Fd[1], Fd[0]) - theta - math.pi
        phi_c = phi + (phi_c - phi + math.pi) % (2 * math.pi) - math.pi
        assert abs(phi_c - phi) < 0.01
        assert np.linalg.norm(rot(theta, Fd) + rot(-phi_c, Fn)) < 1e-9 * F
        gaps.append(float(np.linalg.norm(rot(-phi_c, Pn) - (np.array([dd.mount, 0.0]) + rot(theta, Pd)))))
        tes.append(phi_c - phi)
        md = Pd[0] * Fd[1] - Pd[1] * Fd[0]
        mn = Pn[0] * Fn[1] - Pn[1] * Fn[0]
        assert md < 0 and mn < 0
        if row[23] == "":
            flanks += 1
            assert md == pytest.approx(-F * rb[0], rel=5e-3) and mn == pytest.approx(-F * rb[1], rel=5e-3)
    assert flanks > 0
    # the two outlines' own contact points: 8.5 um apart at most here (the dense outlines against the pair's and the
    # gap each contact is found at); the driven wheel turned by -te instead (te = -1.7e-3 rad) puts them 0.17 mm apart
    assert max(gaps) < 0.02 and all(-2e-3 < t < -1.5e-3 for t in tes)


def test_load_per_tooth_reports_the_forces_own_imbalance_against_the_driver_torque():
    """The equilibrium the load per tooth reports is |sum F l1 - T1| / T1 over the phases: with the load sharing
    made 1 % strong (every pair's force x 1.01), it is 0.01 to rounding at T1 = 50 N·m (not 0.01 T1^2)."""
    from propulsor.gears import tooth_load as tlm
    from propulsor.parts.noncircular_pair.tooth_load_outputs import analyse

    p, dd, pitch, cl = _circular_drive_contact(1)
    d = dd.d
    real = tlm.share_load

    def strong(*a, **k):
        F, rest = real(*a, **k)
        return np.asarray(F) * 1.01, rest

    tlm.share_load = strong
    try:
        tl = analyse(d, dd.mount, p, cl.phi, cl.te, 0.2 * pitch, 0.3 * pitch, step_deg=1.0)
    finally:
        tlm.share_load = real
    assert tl.lost == 0 and tl.imbalance == pytest.approx(0.01, rel=1e-9)
