"""The compiled rotation hits of the backlash search (checks/motion/backlash.py, numba) against the numpy
formulation they replaced (tests/rot_hits_reference.py): the same first-hit angle for every point, and
the same edge and edge parameter for every point that hits, bit for bit, on two toothed bodies close to mesh,
in both senses, narrow and wide windows; and the free rotation built on them."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.checks.motion import Outline
from propulsor.checks.motion import backlash
from propulsor.checks.motion.poses import Pose, apply_pose

import rot_hits_reference as ref


def _gear(n_teeth: int, r_root: float, r_tip: float, n: int) -> np.ndarray:
    a = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    r = r_root + (r_tip - r_root) * np.clip(1.5 * np.cos(n_teeth * a), -1.0, 1.0) * 0.5 + 0.5 * (r_tip - r_root)
    return np.column_stack([r * np.cos(a), r * np.sin(a)])


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("w", [0.004, 0.05, 0.6, 4.0])
def test_compiled_rotation_hits_equal_the_reference_bit_for_bit(sign, w):
    drv = Outline([_gear(12, 20.0, 23.0, 1500), _gear(4, 5.0, 6.0, 200)[::-1]], 0.1)
    dvn = Outline([_gear(9, 14.0, 17.0, 1100)], 0.1)
    rng = np.random.default_rng(11)
    hits = 0
    for _ in range(6):
        C = np.array([38.2 + float(rng.uniform(0.0, 1.5)), float(rng.uniform(-0.5, 0.5))])  # driven centre
        M = Pose(float(rng.uniform(0, 2 * math.pi)), (0.0, 0.0), tuple(C)).matrix()
        P = apply_pose(M, dvn.points)  # driven vertices in the driver frame
        rho = np.linalg.norm(P - C, axis=1)
        lb = drv.boundary_lower_bound(P)
        got = backlash._rot_hits(P, C, drv, sign, w, rho, lb)
        want = ref.rot_hits(P, C, drv, sign, w, rho, lb)
        assert got[0].tobytes() == np.asarray(want[0], float).tobytes()  # every point's first hit (or inf)
        hit = np.isfinite(got[0])
        for g, r in zip(got[1:], want[1:]):  # the edge and its parameter of every hit
            assert g[hit].tobytes() == np.asarray(r, dtype=g.dtype)[hit].tobytes()
        assert np.all(got[1][~hit] == -1) and np.all(got[2][~hit] == 0.0)  # none: -1 and 0
        hits += int(np.isfinite(got[0]).sum())
    assert hits > 0 or w < 0.01  # the windows meet teeth


def test_rot_bounds_are_the_norms_and_the_annulus_bound_bit_for_bit():
    """``backlash.rot_bounds`` (one compiled pass) gives the floats of ``norms(P - C)`` and
    ``Outline.boundary_lower_bound(P)`` it replaced in the proofs: points placed about a toothed body, inside its
    annulus, outside it and on its centre, about centres near and far (a mutant taking the bound's lesser gap, or the
    distance from the outline's centre for rho, fails here)."""
    from propulsor.planar import norms

    drv = Outline([_gear(12, 20.0, 23.0, 1500), _gear(4, 5.0, 6.0, 200)[::-1]], 0.1)
    dvn = Outline([_gear(9, 14.0, 17.0, 1100)], 0.1)
    rng = np.random.default_rng(5)
    for k in range(8):
        C = np.array([38.2 + float(rng.uniform(-30.0, 1.5)), float(rng.uniform(-3.0, 3.0))])
        M = Pose(float(rng.uniform(0, 2 * math.pi)), (0.0, 0.0), tuple(C)).matrix()
        P = apply_pose(M, dvn.points)
        P = np.vstack([P, drv.center[None, :], rng.normal(0.0, 25.0, (200, 2))])
        rho, lb = backlash.rot_bounds(P, C, drv)
        assert np.array_equal(rho, norms(P - C)) and np.array_equal(lb, drv.boundary_lower_bound(P))
        assert (lb < 0).any() and (lb > 0).any()  # points within the annulus and beyond it
        rho0, lb0 = backlash.rot_bounds(P, (0.0, 0.0), dvn)
        assert np.array_equal(rho0, norms(P)) and np.array_equal(lb0, dvn.boundary_lower_bound(P))


def _zones_numpy(d1, rho1, d2, rho2, e2, t2, dmin, tol, dvn, merge) -> int:
    """free_rotation's contact zones as numpy counted them before ``backlash._zones_nb``."""
    f1, f2 = np.isfinite(d1), np.isfinite(d2)
    c1 = np.nonzero(f1)[0][(d1[f1] - dmin) * rho1[f1] <= tol]
    c2 = np.nonzero(f2)[0][(d2[f2] - dmin) * rho2[f2] <= tol]
    pos = np.concatenate([dvn.arclen[c1], dvn.arclen[e2[c2]] + t2[c2] * dvn.seg_len[e2[c2]]])
    loop = np.concatenate([dvn.loop_id[c1], dvn.loop_id[e2[c2]]])
    n = 0
    for lid in np.unique(loop):
        s = np.sort(pos[loop == lid])
        n += max(int(np.count_nonzero(np.diff(np.concatenate([s, [s[0] + dvn.perimeter[lid]]])) > merge)), 1)
    return n


def test_contact_zones_are_numpy_s_count():
    """The compiled count of contact zones equals the numpy formulation it replaced, on hits of a two-loop outline with
    gaps either side of the merge distance and hits across a loop's start (killed by a mutant leaving out the
    wrap-around gap, or one counting each loop's groups without the one a loop has at least)."""
    dvn = Outline([_gear(9, 14.0, 17.0, 1100), _gear(4, 5.0, 6.0, 200)[::-1]], 0.1)
    rng = np.random.default_rng(3)
    counts = set()
    for k in range(300):
        n1, n2 = int(rng.integers(1, 40)), int(rng.integers(0, 40))
        d1 = np.full(len(dvn.points), np.inf)
        i1 = rng.choice(len(dvn.points), n1, replace=False)
        d1[i1] = rng.uniform(0.0, 2e-3, n1)
        d2 = np.where(rng.uniform(size=n2) < 0.7, rng.uniform(0.0, 2e-3, n2), np.inf)
        e2 = rng.integers(0, len(dvn.points), n2).astype(np.int64)
        t2 = rng.uniform(0.0, 1.0, n2)
        rho1, rho2 = rng.uniform(5.0, 20.0, len(d1)), rng.uniform(5.0, 20.0, n2)
        dmin = float(min(d1.min(), d2.min(initial=np.inf)))
        tol, merge = float(rng.uniform(0.001, 0.02)), float(rng.uniform(0.05, 30.0))
        want = _zones_numpy(d1, rho1, d2, rho2, e2, t2, dmin, tol, dvn, merge)
        got = backlash._zones_nb(d1, rho1, d2, rho2, e2, t2, dmin, tol, dvn.arclen, dvn.seg_len, dvn.loop_id,
                                 dvn.perimeter, merge)
        assert got == want, (k, got, want)
        counts.add(want)
    assert len(counts) >= 5  # few zones and many


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("w, w_other", [(0.004, 0.05), (0.05, 0.004), (0.02, 0.02), (0.6, 0.001), (1e-5, 4.0)])
def test_both_senses_from_one_search_are_each_sense_s_own(sign, w, w_other):
    """``_rot_hits_both`` (the pairs of the wider window sought once) gives each sense the hits ``_rot_hits`` finds in
    that sense's own window, bit for bit: first hit, edge and parameter of every point, on two toothed bodies close
    to mesh, the windows narrower and wider either way (a mutant reducing the other sense with this sense's window,
    or with this sense's entering roots, fails here)."""
    drv = Outline([_gear(12, 20.0, 23.0, 1500), _gear(4, 5.0, 6.0, 200)[::-1]], 0.1)
    dvn = Outline([_gear(9, 14.0, 17.0, 1100)], 0.1)
    rng = np.random.default_rng(17)
    hits = 0
    for _ in range(5):
        C = np.array([38.2 + float(rng.uniform(0.0, 1.5)), float(rng.uniform(-0.5, 0.5))])
        M = Pose(float(rng.uniform(0, 2 * math.pi)), (0.0, 0.0), tuple(C)).matrix()
        P = apply_pose(M, dvn.points)
        rho, lb = backlash.rot_bounds(P, C, drv)
        one, other = backlash._rot_hits_both(P, C, drv, sign, w, w_other, rho, lb)
        for got, want in ((one, backlash._rot_hits(P, C, drv, sign, w, rho, lb)),
                          (other, backlash._rot_hits(P, C, drv, -sign, w_other, rho, lb))):
            for g, r in zip(got, want):
                assert g.tobytes() == r.tobytes()
            hits += int(np.isfinite(got[0]).sum())
    assert hits > 0


def test_free_rotations_are_two_free_rotations():
    """Both senses at once (``free_rotations``) against ``free_rotation`` twice, with first windows too narrow (they
    grow), near and wide: the same free rotation, contact zones and point."""
    drv = Outline([_gear(12, 20.0, 23.0, 1500)], 0.1)
    dvn = Outline([_gear(9, 14.0, 17.0, 1100)], 0.1)
    for th in (0.1, 0.13, 0.17):
        C1 = np.array([39.0, 0.0])
        M2 = np.array(Pose(th, (0.0, 0.0), tuple(C1)).matrix())
        P1 = apply_pose(M2, dvn.points)
        P2 = apply_pose(np.array(Pose(-th, (0.0, 0.0), (0.0, 0.0)).matrix()), drv.points - C1)
        args = (drv, dvn, P1, C1, P2, *backlash.rot_bounds(P1, C1, drv), *backlash.rot_bounds(P2, (0.0, 0.0), dvn), M2)
        for s, wa, wb in ((1.0, 1e-4, 0.05), (-1.0, 0.2, 1e-6), (1.0, 0.01, 0.01)):
            both = backlash.free_rotations(*args, s, wa, wb, 1.0, 1e-3, 0.5)
            each = (backlash.free_rotation(*args, s, wa, 1.0, 1e-3, 0.5),
                    backlash.free_rotation(*args, -s, wb, 1.0, 1e-3, 0.5))
            for f, g in zip(both, each):
                assert f.delta == g.delta and f.n_pairs == g.n_pairs and f.point.tobytes() == g.point.tobytes()
                assert math.isfinite(f.delta)
