"""The steps of a 2D sweep (:func:`.sweep2d.sweep_pair`) where the bodies are apart, in one compiled loop.

At such a step the sweep moves each body's vertices into the other's frame, measures the least distance between the
boundaries both ways (:func:`.nearest.nearest_edge`'s compiled search, its memory and grid), and shows the bodies
certainly apart (:func:`.crossing.certainly_apart`'s tests), so that the area in common is 0 without a boolean. Here
the same operations run without the Python around them (a final drive's carrier sweep 3.3-4.1 -> 2.8-3.2 CPU s,
bench/bench_final_drive.py): the same kernels on the same arrays, the points moved by the same fused multiply-adds as
:func:`.poses.apply_pose`, so every distance, point and memory entry is the one the step-by-step path gives. The loop
stops at the first step it does not finish itself — the grid level the last distance asks for differs from the one it
was given, the bodies are far enough apart for the KD-tree, or they may share area (the boolean decides) — and the
sweep takes that step as before.  As there, the body of more vertices is searched only for an answer within the
other way's (:func:`.nearest.nearest_edge`'s cap).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from ...nbcache import bind
from .crossing import _apart, apart_args
from .nearest import _level_for, _nearest_edge, grid_of, hints_of, level_of, search_args
from .poses import _fma

__all__ = ["apart_steps", "move_each"]


@njit(cache=True)
def _move(M, P, out):
    """``apply_pose(M, P)`` into ``out`` (two points or more: poses._apply_pose_nb's arithmetic)."""
    a, b, c = M[0, 0], M[0, 1], M[0, 2]
    d, e, f = M[1, 0], M[1, 1], M[1, 2]
    for i in range(len(P)):
        x, y = P[i, 0], P[i, 1]
        out[i, 0] = _fma(y, b, x * a) + c
        out[i, 1] = _fma(y, e, x * d) + f


@njit(cache=True)
def _move1(M, x, y):
    """``apply_pose(M, [[x, y]])[0]`` (one point: poses._apply_pose_nb's arithmetic)."""
    return (_fma(x, M[0, 0], y * M[0, 1]) + M[0, 2], _fma(x, M[1, 0], y * M[1, 1]) + M[1, 2])


@njit(cache=True)
def move_each(M, P):
    """Point j moved by pose j: ``apply_pose(M[j], P[j:j + 1])[0]`` for each j, in one call."""
    out = np.empty((len(P), 2))
    for j in range(len(P)):
        out[j, 0], out[j, 1] = _move1(M[j], P[j, 0], P[j, 1])
    return out


@njit(cache=True)
def _first_then_capped(P1, seed1, hint1, args1, P2, seed2, hint2, args2):
    """One step's two searches (sweep2d._boundary_distance): the first way whole, the second only for an answer within
    the first's.  (go on, the first's (d, i, qx, qy), the second's, seed1, hint1, seed2, hint2: each way's seed and
    hint as nearest_edge leaves them); not go on where either way is far apart (the KD-tree's).  The grid level of
    each way follows its own hint, which the other way's search leaves as it is: both are checked before."""
    r1 = _nearest_edge(P1, seed1, np.inf, *args1)
    if r1[1] < 0:
        return False, r1, r1, seed1, hint1, seed2, hint2
    seed1, hint1 = r1[1], r1[0]
    r2 = _nearest_edge(P2, seed2, r1[0], *args2)
    if r2[0] < 0.0:
        return False, r1, r2, seed1, hint1, seed2, hint2
    if r2[1] < 0:  # none within the first's answer
        hint2 = r1[0]
    else:
        seed2, hint2 = r2[1], r2[0]
    return True, r1, r2, seed1, hint1, seed2, hint2


@njit(cache=True)
def _steps_nb(k0, rel_ba, rel_ab, Ma, Mb, Va, Vb, h0a, lva, seed_ba, hint_ba, args_ba, h0b, lvb, seed_ab, hint_ab,
              args_ab, args_apart, clear, pa, pb):
    b_first = len(Vb) <= len(Va)
    n = len(rel_ba)
    PB = np.empty((len(Vb), 2))
    PA = np.empty((len(Va), 2))
    for k in range(k0, n):
        # B's vertices against A's edges (A's frame) and A's against B's, the way of more vertices only for an answer
        # within the other's (sweep2d._boundary_distance)
        if level_of(h0a, hint_ba) != lva or level_of(h0b, hint_ab) != lvb:
            return k, seed_ba, hint_ba, seed_ab, hint_ab
        _move(rel_ba[k], Vb, PB)
        _move(rel_ab[k], Va, PA)
        if b_first:
            go, r1, r2, seed_ba, hint_ba, seed_ab, hint_ab = _first_then_capped(
                PB, seed_ba, hint_ba, args_ba, PA, seed_ab, hint_ab, args_ab)
        else:
            go, r2, r1, seed_ab, hint_ab, seed_ba, hint_ba = _first_then_capped(
                PA, seed_ab, hint_ab, args_ab, PB, seed_ba, hint_ba, args_ba)
        if not go:
            return k, seed_ba, hint_ba, seed_ab, hint_ab
        d1, i1, q1x, q1y = r1
        d2, i2, q2x, q2y = r2
        d = d1 if d1 <= d2 else d2
        if not _apart(d, PB, PA, *args_apart):
            return k, seed_ba, hint_ba, seed_ab, hint_ab
        clear[k] = d
        if d1 <= d2:
            pa[k, 0], pa[k, 1] = _move1(Ma[k], q1x, q1y)
            pb[k, 0], pb[k, 1] = _move1(Ma[k], PB[i1, 0], PB[i1, 1])
        else:
            pa[k, 0], pa[k, 1] = _move1(Mb[k], PA[i2, 0], PA[i2, 1])
            pb[k, 0], pb[k, 1] = _move1(Mb[k], q2x, q2y)
    return n, seed_ba, hint_ba, seed_ab, hint_ab


def apart_steps(A, B, rel_ba: np.ndarray, rel_ab: np.ndarray, Ma: np.ndarray, Mb: np.ndarray, k0: int,
                clear: np.ndarray, pa: np.ndarray, pb: np.ndarray) -> int:
    """Steps k0, k0 + 1, … of a sweep of outlines A and B (rel_ba[k]: B's body to A's, rel_ab[k] its inverse; Ma, Mb
    the world poses) while the bodies are certainly apart, their clearance and closest points written into clear,
    pa, pb (the overlap area is 0 there); returns the first step not taken (len(rel_ba) when every one was), which
    the caller takes step by step.  The searches' memories, seeds and hints are left as nearest_edge leaves them."""
    hints_a, hints_b = hints_of(A), hints_of(B)
    hint_ba, hint_ab = float(hints_a.get(id(B), 0.0)), float(hints_b.get(id(A), 0.0))
    lva, lvb = _level_for(A, hint_ba), _level_for(B, hint_ab)
    mem_ba, args_ba = search_args(A, B, lva)
    mem_ab, args_ab = search_args(B, A, lvb)
    k, seed_ba, hint_ba, seed_ab, hint_ab = _steps_nb(
        k0, rel_ba, rel_ab, Ma, Mb, A.points, B.points, grid_of(A).h, lva, mem_ba.seed, hint_ba, args_ba,
        grid_of(B).h, lvb, mem_ab.seed, hint_ab, args_ab, apart_args(A, B), clear, pa, pb)
    mem_ba.seed, hints_a[id(B)] = int(seed_ba), float(hint_ba)
    mem_ab.seed, hints_b[id(A)] = int(seed_ab), float(hint_ab)
    return int(k)


# the disk cache of these kernels keyed on every kernel source (nbcache)
bind(globals())
