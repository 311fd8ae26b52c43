"""Contact events of a gear pair on its finished outlines (checks/motion/contact_events.py): a conjugate spur pair
runs at the law's speed with no step, and a tooth with a bump at its tip corner - a defect of 0.05 mm a user's CAD
fillet or a printer's blob makes - is found, located in driver angle, named by tooth and kind, and its impact
measured, though it lasts less than one sampling step."""

from __future__ import annotations

import math

import manifold3d as m3d
import numpy as np
import pytest

from propulsor.checks.motion import outline
from propulsor.checks.motion.contact_events import DRIVE, KINDS, REVERSE, PairOutlines, resolve_contact
from propulsor.geometry.gear_outline import external_gear_profile
from propulsor.gears.gear_pair import GearPair
from propulsor.gears.involute import SpurGear

from contact_reference import contact

Z1, Z2, M = 20, 40, 2.0


def _rotated(profile, angle):
    c, s = math.cos(angle), math.sin(angle)
    R = np.array([[c, -s], [s, c]])
    return [q @ R.T for q in profile.polylines(1e-4)][:1]


@pytest.fixture(scope="module")
def spur():
    """Driven z2 at the origin (a tooth on +x), driver z1 at (a_w, 0) (a space on -x): meshed at phi = theta = 0."""
    pair = GearPair(SpurGear(Z1, M, 0.0), SpurGear(Z2, M, 0.0))
    g1 = external_gear_profile(Z1, M, 0.0, d_a=pair.d_a1, thinning_n_mm=0.08)
    g2 = external_gear_profile(Z2, M, 0.0, d_a=pair.d_a2, thinning_n_mm=0.08)
    driven = _rotated(g2.profile, -math.pi / 2)
    driver = _rotated(g1.profile, math.pi / 2 + math.pi / Z1)
    teeth2 = 2 * math.pi * np.arange(Z2) / Z2
    teeth1 = math.pi + math.pi / Z1 + 2 * math.pi * np.arange(Z1) / Z1
    return pair, driver, driven, teeth1, teeth2


def _law(phi):
    return np.asarray(phi, float) * Z2 / Z1


def test_a_conjugate_spur_pair_runs_at_the_law_speed_in_both_directions(spur):
    pair, driver, driven, t1, t2 = spur
    po = PairOutlines(outline(driver), outline(driven), pair.a_w, t1, t2)
    span = 2 * math.pi / Z2 * 2  # two driven teeth
    for direction in (DRIVE, REVERSE):
        c = resolve_contact(po, _law, 0.0, span, direction)
        assert np.all(np.isfinite(c.te))
        # involutes: constant transmission, the backlash on the pitch circle of the driven wheel split between them
        assert c.te_pp < 2e-5
        assert 0.997 < c.speed_min <= c.speed_max < 1.003
        assert c.step_max < 0.003
        assert (c.te < 0).all() if direction == DRIVE else (c.te > 0).all()
        # the hand-over: two tooth pairs (the contact moves from one pair to the next once a tooth)
        pairs = {(a, b) for a, b in zip(c.driver_tooth, c.driven_tooth)}
        assert len(pairs) >= 3


def _bumped(loop, near_angle, r_bump=0.05):
    """The loop with a disc of radius r_bump united at its tip corner nearest the polar angle ``near_angle`` (the
    corner vertex on the loaded side)."""
    o = outline([loop])
    a = o.seg_b - o.seg_a
    ang = np.arctan2(a[:, 1], a[:, 0])
    turn = (ang - ang[o.prev] + math.pi) % (2 * math.pi) - math.pi
    corners = np.nonzero(turn > math.radians(20))[0]
    pa = np.arctan2(o.points[corners, 1], o.points[corners, 0])
    k = corners[int(np.argmin(np.abs((pa - near_angle + math.pi) % (2 * math.pi) - math.pi)))]
    c = o.points[k]
    t = np.linspace(0, 2 * math.pi, 64, endpoint=False)
    disc = np.column_stack([c[0] + r_bump * np.cos(t), c[1] + r_bump * np.sin(t)])
    cs = m3d.CrossSection([np.ascontiguousarray(loop)], m3d.FillRule.Positive) + m3d.CrossSection([disc])
    polys = sorted(cs.to_polygons(), key=len)
    return [np.asarray(polys[-1], float)], c


def test_a_bump_on_one_tooth_is_found_named_and_measured(spur):
    """Mutation: a blob of 5 micrometres on one tip corner of driven tooth 2.  It takes the load from the conjugate
    flanks for 0.6 deg of driver twice (the driven wheel 1.2-4 % fast, then 1.5-2.7 % slow); the change of state
    is bisected: a stretch on driven tooth 2 and a step in driven speed of 4 %, none in the clean pair."""
    pair, driver, driven, t1, t2 = spur
    bumped, corner = _bumped(driven[0], t2[2] + 0.02, 0.005)
    po = PairOutlines(outline(driver), outline(bumped), pair.a_w, t1, t2)
    span = 2 * math.pi / Z2 * 4
    clean = resolve_contact(PairOutlines(outline(driver), outline(driven), pair.a_w, t1, t2), _law, 0.0, span, DRIVE)
    hit = [resolve_contact(po, _law, 0.0, span, d) for d in (DRIVE, REVERSE)]
    assert clean.step_max < 0.003
    steps = [c.step_max for c in hit]
    assert max(steps) > 0.02
    worst = hit[int(np.argmax(steps))]
    odd = [s for s in worst.stretches() if 2 in s.driven_teeth and abs(s.speed_min - 1) + abs(s.speed_max - 1) > 0.02]
    assert odd, worst.stretches()
    assert not [s for s in clean.stretches() if abs(s.speed_min - 1) + abs(s.speed_max - 1) > 0.02]
    # the step sits at an end of the bump's stretches, located by bisection far below the sampling step
    _, theta = worst.step_at()
    assert any(s.theta_from_deg - 0.06 <= math.degrees(theta) <= s.theta_to_deg + 0.06 for s in odd)
    assert min(np.diff(worst.phi)) < 2e-5 < 0.05 * math.pi / 180 * Z1 / Z2


def test_contact_kinds_are_the_documented_ones():
    assert KINDS[0] == "flank" and set(KINDS[1:]) == {"driver tip corner", "driven tip corner", "driver root corner",
                                                      "driven root corner"}


def test_a_pair_set_apart_loses_contact_and_the_check_says_so(spur):
    """Mutation: the spur pair mounted 5 mm apart: no tooth reaches the mate within the largest free rotation; every
    sample is without contact and the as-built contact check fails naming the count."""
    from types import SimpleNamespace

    from propulsor.parts.noncircular_pair.as_built import AsBuilt
    from propulsor.parts.noncircular_pair.as_built_outputs import as_built_checks

    pair, driver, driven, t1, t2 = spur
    po = PairOutlines(outline(driver), outline(driven), pair.a_w + 5.0, t1, t2)
    span = 2 * math.pi / Z2
    dr, rv = (resolve_contact(po, _law, 0.0, span, d, step_driver_rad=math.radians(0.5)) for d in (DRIVE, REVERSE))
    assert not np.isfinite(dr.te).any() and not np.isfinite(rv.te).any()
    ab = AsBuilt(dr, rv, span, (), math.nan, math.nan, math.nan)
    p = SimpleNamespace(speed_step_max=0.02, corner_run_max_deg=0.5, as_built_ripple_margin=0.005)
    (chk,) = [c for c in as_built_checks(ab, p, None) if c.name == "as_built.contact"]
    assert not chk.passed and chk.value == len(dr.te) + len(rv.te)


def test_the_compiled_runs_name_each_contact_as_the_reference_search_does(spur):
    """contact_track.track, each position searched from the law's (no seed), against the reference search one at a
    time, over the bumped pair's resolved positions in both directions: the same te to the last bit, the same contact
    kind (flank and the corners the bump and the tips make) and the same teeth."""
    from propulsor.checks.motion.contact_track import track

    pair, driver, driven, t1, t2 = spur
    bumped, _ = _bumped(driven[0], t2[2] + 0.02, 0.005)
    po = PairOutlines(outline(driver), outline(bumped), pair.a_w, t1, t2)
    span = 2 * math.pi / Z2 * 4
    kinds = set()
    for d in (DRIVE, REVERSE):
        c = resolve_contact(po, _law, 0.0, span, d)
        nan = np.full(len(c.phi), np.nan)
        te, kind, a, b = track(po, c.phi, c.theta, d, nan, nan, False)
        ref = [contact(po, float(p), float(t), d) for p, t in zip(c.phi, c.theta)]
        assert np.array_equal(te, np.array([r[0] for r in ref]), equal_nan=True)
        assert list(zip(kind.tolist(), a.tolist(), b.tolist())) == [tuple(r[1:4]) for r in ref]
        kinds |= set(kind.tolist())
    assert kinds > {0}, kinds  # corners too


class _ElementwiseLaw:
    """A law's theta (``_law``) from an object that says it is elementwise (laws/law.py), counting the angles of
    each call."""

    elementwise = True

    def __init__(self):
        self.sizes = []

    def theta(self, phi):
        self.sizes.append(np.size(phi))
        return _law(phi)


def test_an_elementwise_law_s_bisection_midpoints_are_asked_together_with_the_same_result(spur):
    """The midpoints of one bisection round go to an elementwise law's theta in one call (a thousand calls of one
    angle a cycle before); every row of the resolved contact is the one of a theta asked one angle at a time."""
    pair, driver, driven, t1, t2 = spur
    bumped, _ = _bumped(driven[0], t2[2] + 0.02, 0.005)
    po = PairOutlines(outline(driver), outline(bumped), pair.a_w, t1, t2)
    span = 2 * math.pi / Z2 * 4
    for d in (DRIVE, REVERSE):
        law, plain = _ElementwiseLaw(), []
        together = resolve_contact(po, law.theta, 0.0, span, d)
        alone = resolve_contact(po, lambda phi: plain.append(np.size(phi)) or _law(phi), 0.0, span, d)
        for f in ("phi", "theta", "te", "kind", "driver_tooth", "driven_tooth"):
            assert np.asarray(getattr(together, f)).tobytes() == np.asarray(getattr(alone, f)).tobytes(), f
        assert together.evaluations == alone.evaluations
        # a plain function is asked one midpoint at a time, the law once a round with all of them
        midpoints = plain.count(1) - law.sizes.count(1)
        assert midpoints > 20 and sum(law.sizes) == sum(plain) and len(law.sizes) < len(plain) - midpoints + 20
