"""The transmission sweep's compiled loop (checks/motion/transmission_kernel.py, backlash._free_rotation_nb) against
the Python loop it replaced (tests/transmission_reference.py): every step's common area, free rotations both ways,
contact pairs and contact points, bit for bit, on involute pairs in mesh, squeezed into interference (the boolean's
steps, with and without rotations after it), in either sense and with either body at the origin; and what it rests
on: numpy's arctan2 in compiled code (propulsor.npmath) and numpy's poses."""

from __future__ import annotations

import math

import numpy as np
import pytest
from numba import njit

from propulsor import policy
from propulsor.checks.motion import backlash, outline, transmission_sweep
from propulsor.checks.motion.poses import Pose, compose_poses, inverse_pose
from propulsor.checks.motion.transmission_kernel import pose_pair
from propulsor.npmath import KIND, atan2

import transmission_reference as ref
from test_motion import involute_gear

Z1, Z2, M, J_N = 20, 30, 2.0, 0.1


@njit
def _atan2_each(Y, X):
    out = np.empty(len(Y))
    for i in range(len(Y)):
        out[i] = atan2(Y[i], X[i])
    return out


def test_compiled_arctan2_is_numpy_s_bit_for_bit():
    """npmath.atan2 in a kernel gives np.arctan2's float for 400 000 random pairs over 16 decades and every pair of
    zeros, infinities, nan, subnormals and units (where numpy calls SVML it differs from the C library's atan2, which
    numba's math.atan2 calls, on about 1 % of them: the test would fail with that)."""
    rng = np.random.default_rng(7)
    n = 400_000
    Y = rng.standard_normal(n) * 10.0 ** rng.integers(-8, 8, n)
    X = rng.standard_normal(n) * 10.0 ** rng.integers(-8, 8, n)
    special = np.array([0.0, -0.0, np.inf, -np.inf, np.nan, 5e-324, -5e-324, 1.0, -1.0, 1e308, -1e308])
    YY, XX = np.meshgrid(special, special)
    Y, X = np.concatenate([Y, YY.ravel()]), np.concatenate([X, XX.ravel()])
    want, got = np.arctan2(Y, X), _atan2_each(Y, X)
    assert got.tobytes() == want.tobytes()
    libm = np.array([math.atan2(y, x) for y, x in zip(Y[:20000].tolist(), X[:20000].tolist())])
    assert KIND == ("svml" if libm.tobytes() != want[:20000].tobytes() else "libm")


def test_compiled_poses_are_numpy_s_bit_for_bit():
    """pose_pair gives Pose.matrix, compose_poses(inverse_pose(M1), M2) and its inverse as numpy computes them (their
    2x2 products by OpenBLAS with fused multiply-adds), every float and the sign of every zero, for random angles and
    centres, either body at the origin, either sense."""
    rng = np.random.default_rng(3)
    for it in range(600):
        th, ph = rng.uniform(-20.0, 20.0, 2)
        c1 = ((float(rng.uniform(-300, 300)), float(rng.uniform(-300, 300))) if it % 4
              else (float(rng.uniform(1, 300)), 0.0))
        c2 = (float(rng.uniform(-50, 50)), float(rng.uniform(-50, 50))) if it % 4 >= 2 else (0.0, 0.0)
        s1, s2 = (1.0, -1.0) if it % 3 else (1.0, 1.0)
        M1 = Pose(s1 * th, (0.0, 0.0), c1).matrix()
        M2 = Pose(s2 * ph, (0.0, 0.0), c2).matrix()
        rel21 = compose_poses(inverse_pose(M1), M2)
        for got, want in zip(pose_pair(s1, th, s2, ph, c1, c2), (M2, rel21, inverse_pose(rel21))):
            assert got.tobytes() == np.ascontiguousarray(want).tobytes()


@pytest.fixture(scope="module")
def involutes():
    return outline(involute_gear(Z1, M, J_N)[0]), outline(involute_gear(Z2, M, J_N)[0])


@pytest.mark.parametrize("case", ["mesh", "mesh, driven at the origin", "squeezed", "squeezed, rotations kept",
                                  "other sense"])
def test_compiled_steps_are_the_python_loop_s_bit_for_bit(involutes, monkeypatch, case):
    o1, o2 = involutes
    a = M * (Z1 + Z2) / 2 - (0.3 if case.startswith("squeezed") else 0.0)
    if case == "squeezed, rotations kept":  # the overlapping steps go on to the rotations (known_free in the loop)
        monkeypatch.setattr(policy, "OVERLAP_AREA_TOL_MM2", 0.5)
    phi0 = math.pi / Z2
    phis = phi0 + np.linspace(0.0, 2.0 * math.pi / Z2, 41)
    u = Z2 / Z1
    senses = (1, 1) if case == "other sense" else (1, -1)
    c1, c2 = ((a, 0.0), (0.0, 0.0)) if case == "mesh, driven at the origin" else ((0.0, 0.0), (a, 0.0))
    law = lambda p: u * (p - phi0)  # noqa: E731
    res = transmission_sweep(o1, c1, o2, c2, law, phis, senses=senses)
    theta = np.array([law(p) for p in phis])
    want = ref.steps(o1, o2, phis, theta, senses, c1, c2, policy.MOTION_MAX_FREE_ANGLE_RAD,
                     policy.MOTION_CONTACT_TOL_MM, policy.MOTION_CONTACT_MERGE_MM)
    got = (res.overlap_area, res.free_fwd, res.free_back, res.pairs_drive, res.pairs_coast, res.contact_point_drive,
           res.contact_point_coast)
    for g, w in zip(got, want):
        assert g.dtype == w.dtype and g.tobytes() == w.tobytes()
    interfering = res.overlap_area > policy.OVERLAP_AREA_TOL_MM2
    overlapping = res.overlap_area > 0.0
    if case in ("squeezed", "other sense"):  # turned the same way, the external pair jams at once
        assert interfering.any() and np.isnan(res.free_fwd[interfering]).all()
    elif case == "squeezed, rotations kept":
        assert overlapping.any() and not interfering.any() and np.isfinite(res.free_fwd).all()
    else:
        assert not overlapping.any() and np.isfinite(res.free_back).all() and (res.pairs_drive >= 1).all()


def test_free_rotation_is_the_python_one_bit_for_bit():
    """The compiled free rotation (one sense, its window grown from too narrow a start; both senses at once) against
    the Python formulation it replaced, on the numpy formulation's hits (tests/rot_hits_reference.py)."""
    import rot_hits_reference as hits_ref
    from propulsor.checks.motion.poses import apply_pose

    drv, dvn = outline(involute_gear(Z1, M, J_N)[0]), outline(involute_gear(Z2, M, J_N)[0])
    a = M * (Z1 + Z2) / 2
    for p in np.linspace(0.0, 2.0 * math.pi / Z2, 7):
        M1 = Pose(Z2 / Z1 * p, (0.0, 0.0), (a, 0.0)).matrix()
        M2 = Pose(-(p + math.pi / Z2), (0.0, 0.0), (0.0, 0.0)).matrix()
        rel21 = compose_poses(inverse_pose(M1), M2)
        P1, P2 = apply_pose(rel21, dvn.points), apply_pose(inverse_pose(rel21), drv.points)
        C1 = rel21[:, 2]
        rho1, lb1 = backlash.rot_bounds(P1, C1, drv)
        rho2, lb2 = backlash.rot_bounds(P2, (0.0, 0.0), dvn)
        geo = (drv, dvn, P1, C1, P2, rho1, lb1, rho2, lb2, M2)
        for s in (1.0, -1.0):
            got = backlash.free_rotation(*geo, s, 1e-6, 1.0, 1e-3, 0.5)
            want = ref.free_rotation(*geo, s, 1e-6, 1.0, 1e-3, 0.5, hits=hits_ref.rot_hits)
            assert (got.delta, got.n_pairs, got.point.tobytes()) == (want[0], want[1], want[2].tobytes())
            assert math.isfinite(got.delta)
        both = backlash.free_rotations(*geo, 1.0, 1e-5, 2e-3, 1.0, 1e-3, 0.5)
        for got, want in zip(both, ref.free_rotations(*geo, 1.0, 1e-5, 2e-3, 1.0, 1e-3, 0.5)):
            assert (got.delta, got.n_pairs, got.point.tobytes()) == (want[0], want[1], want[2].tobytes())
