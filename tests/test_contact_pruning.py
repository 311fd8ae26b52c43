"""The contact search's pruning (checks/motion/contact_events.py: :func:`distance_field`, :func:`_pruned_window`,
:func:`_first_hit_pruned`): the same first contact as the search over every vertex of the window, bit for bit, found
after leaving out, in runs and then one by one, the vertices that cannot reach the mate within the window."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor import policy
from propulsor.checks.motion import outline
from propulsor.checks.motion import contact_events as ce
from propulsor.checks.motion.contact_events import DRIVE, REVERSE, PairOutlines, distance_field, resolve_contact

from contact_hit_reference import first_hit
from contact_reference import contact
from test_contact_events import Z1, Z2, _law, _bumped, spur  # noqa: F401  (the fixture)


def _segment_distance(p, a, b):
    d = b - a
    t = np.clip(np.sum((p - a) * d, axis=1) / np.maximum(np.sum(d * d, axis=1), 1e-300), 0.0, 1.0)
    q = a + t[:, None] * d
    return float(np.min(np.linalg.norm(q - p, axis=1)))


def test_the_distance_field_is_a_lower_bound_and_not_a_loose_one(spur):
    _, driver, driven, _, _ = spur
    o = outline(driven)
    x0, y0, h, nx, ny, values = distance_field(o)
    rng = np.random.default_rng(7)
    lo, hi = o.points.min(axis=0), o.points.max(axis=0)
    # points near the boundary (where the bound matters) and anywhere in the box
    near = o.points[rng.integers(0, len(o.points), 1500)] + rng.normal(0.0, 0.6, (1500, 2))
    anywhere = rng.uniform(lo, hi, (1500, 2))
    gaps = []
    for p in np.vstack([near, anywhere]):
        ix, iy = int(math.floor((p[0] - x0) / h)), int(math.floor((p[1] - y0) / h))
        if not (0 <= ix < nx and 0 <= iy < ny):
            continue  # outside the grid the search takes the annulus bound alone
        true = _segment_distance(p, o.seg_a, o.seg_b)
        bound = values[ix * ny + iy]
        assert bound <= true, (p, bound, true)
        gaps.append(true - bound)
    # the bound is off by at most two cells' diagonals (the point's and its nearest vertex's offsets from their
    # cells' centres, counted once in the bound and once in the distance between the centres) and half an edge
    assert max(gaps) <= 2.0 * h * math.sqrt(2.0) + o.half_len + 1e-9
    assert max(gaps) > h  # and the test does reach where the bound is loose
    assert np.count_nonzero(values > 0.0) > 0.5 * nx * ny  # most cells hold a positive bound


def _queries(po, rng, n):
    """(phi_a, theta, sign, w): tracked windows about the contact of both directions, and wider ones anywhere."""
    out = []
    for _ in range(n):
        phi = rng.uniform(0.0, 2 * math.pi / Z2 * 2)
        theta = float(_law(phi))
        sign = float(rng.choice([1.0, -1.0]))
        te = contact(po, phi, theta, DRIVE if sign > 0 else REVERSE)[0]
        te = te if math.isfinite(te) else 0.0
        m = float(rng.uniform(1e-4, 1e-3))
        out.append((phi + te + sign * m, theta, sign, 2.0 * m))
        out.append((phi, theta, sign, float(rng.choice([3e-3, 1.2e-2]))))
        # from 0.4-0.8 mm of clearance (driven tip radius about 42 mm): the hitting vertex lies where the distance
        # field's bound is above 0 (more than two cells' diagonals from the mate), so only a sound bound keeps it
        back = float(rng.uniform(0.01, 0.02))
        out.append((phi + te + sign * back, theta, sign, 2.0 * back))
    return out


@pytest.mark.parametrize("bump", [False, True])
def test_the_pruned_search_finds_the_same_first_hit_bit_for_bit(spur, bump):
    pair, driver, driven, t1, t2 = spur
    if bump:
        driven, _ = _bumped(driven[0], 0.0)
    po = PairOutlines(outline(driver), outline(driven), pair.a_w, t1, t2)
    rng = np.random.default_rng(11 + bump)
    found = 0
    for q in _queries(po, rng, 150):
        a = first_hit(*q, *po._kernel_args)
        b = ce._first_hit_pruned(*q, *po._kernel_args[:11], *po._prune_args, *po._kernel_args[11:])
        assert tuple(a) == tuple(b), (q, a, b)
        found += math.isfinite(a[0])
    assert found > 200  # most queries touch: the comparison is not of empty searches


def _kept(po, q):
    phi_a, theta, sign, w = q
    ka, pa = po._kernel_args, po._prune_args
    size, cc1, cr1 = pa[:3]
    L = ka[0]
    chord = 2.0 * math.sin(0.5 * w)
    cp, sp = math.cos(-phi_a), math.sin(-phi_a)
    ct, st = math.cos(-theta), math.sin(-theta)
    window = ce._window_nb(po.o1, po.a1, phi_a, po.hw_dvn + w)
    kept = ce._pruned_window(po.o1, po.a1, phi_a, po.hw_dvn + w, size, cc1, cr1, po.dvn.points, cp, sp, -L, ct, st,
                             po.R1 + w * po.R2 + 1e-6, -L * ct, -L * st, chord, *ka[11 + 12:11 + 16], *pa[5:11])
    return window, kept


def test_the_pruned_window_keeps_the_window_order_and_leaves_out_most_of_it(spur):
    pair, driver, driven, t1, t2 = spur
    po = PairOutlines(outline(driver), outline(driven), pair.a_w, t1, t2)
    rng = np.random.default_rng(5)
    shares = []
    for q in _queries(po, rng, 40)[::3]:  # the tracked windows: what a resolved contact asks
        window, kept = _kept(po, q)
        pos = {int(v): i for i, v in enumerate(window)}
        idx = [pos[int(v)] for v in kept]
        assert idx == sorted(idx) and len(set(idx)) == len(idx)  # a subsequence of the window, in its order
        shares.append(len(kept) / len(window))
    assert max(shares) < 0.5, shares  # the pruning does leave vertices out (at least half of each window)


def test_a_resolved_contact_is_the_same_with_and_without_the_pruning(spur):
    """Over the resolved positions of both directions (the grid and its bisections, in order), the compiled search
    chained from one position to the next (``contact_track.track``, its windows pruned) gives, bit for bit, the te,
    contact kind and teeth of the reference search chained the same way with the first hit taken from every vertex of
    each window (``contact_hit_reference.first_hit``: no vertex left out)."""
    from propulsor.checks.motion.contact_track import track

    def unpruned(po, phi_a, theta, sign, w):
        return first_hit(float(phi_a), float(theta), float(sign), float(w), *po._kernel_args)

    pair, driver, driven, t1, t2 = spur
    bumped, _ = _bumped(driven[0], 0.0)
    span = 2 * math.pi / Z2 * 2
    po = PairOutlines(outline(driver), outline(bumped), pair.a_w, t1, t2)
    for d in (DRIVE, REVERSE):
        c = resolve_contact(po, _law, 0.0, span, d)
        assert len(c.phi) > 100
        te, kind, a, b = track(po, c.phi, c.theta, d, [math.nan], [math.nan], True)
        ref, prev, prev_phi = [], None, 0.0
        for p, t in zip(c.phi.tolist(), c.theta.tolist()):
            r = contact(po, p, t, d, prev, p - prev_phi, hit=unpruned)
            ref.append(r[:4])
            prev, prev_phi = r[0], p
        assert np.array_equal(te, np.array([r[0] for r in ref]), equal_nan=True)
        assert list(zip(kind.tolist(), a.tolist(), b.tolist())) == [tuple(r[1:4]) for r in ref]
        assert np.all(np.isfinite(te))


def test_the_prune_settings_are_sane():
    assert policy.CONTACT_PRUNE_CHUNK >= 1 and policy.CONTACT_FIELD_CELLS >= 16
