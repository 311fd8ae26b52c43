"""The steps of a 2D sweep (:func:`.sweep2d.sweep_pair`) where the bodies are apart, in one compiled loop.

At such a step the sweep moves each body's vertices into the other's frame, measures the least distance between the
boundaries both ways (:func:`.nearest.nearest_edge`'s compiled search, its memory and grid), and shows the bodies
certainly apart (:func:`.crossing.certainly_apart`'s tests), so that the area in common is 0 without a boolean. Here
the same operations run without the Python around them (a final drive's carrier sweep 3.3-4.1 -> 2.8-3.2 CPU s,
bench/bench_final_drive.py): the same kernels on the same arrays, the points moved by the same fused multiply-adds as
:func:`.poses.apply_pose`, so every distance, point and memory entry is the one the step-by-step path gives. The loop
stops at the first step it does not finish itself — the grid level the last distance asks for differs from the one it
was given, the bodies are far enough apart for the KD-tree, or they may share area (the boolean decides) — and the
sweep takes that step as before.
"""

from __future__ import annotations


import numpy as np
from numba import njit

from ... import policy
from ...nbcache import bind
from .crossing import APART_MIN_MM, _any_crossing, _holds_a_loop, _loop_firsts
from .distance import _CHUNK, _chunk_discs
from .nearest import FAR_CELLS, _level_for, _memory, _nearest_edge, grid_of, level_of
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
def _search(P, rho, V, prev, half_len, ccx, ccy, r_min, r_max, g_o, g_h, g_n, g_start, g_items, g_segb, chunk, margin,
            seed, heads, lows, at, low_pt, exact, tally):
    return _nearest_edge(P, rho, V, g_segb, prev, half_len, g_o[0], g_o[1], g_h, g_n[0], g_n[1], g_start, g_items,
                         chunk, margin, ccx, ccy, r_min, r_max, FAR_CELLS * g_h, seed, heads, lows, at, low_pt, exact,
                         tally)


@njit(cache=True)
def _steps_nb(k0, rel_ba, rel_ab, Ma, Mb, chunk, margin,
              Va, prev_a, half_a, ca, rmin_a, rmax_a, h0a, lva, ga_o, ga_h, ga_n, ga_start, ga_items, ga_segb,
              rho_b, seed_ba, heads_ba, lows_ba, at_ba, low_ba, exact_ba, tally_ba, hint_ba,
              Vb, prev_b, half_b, cb, rmin_b, rmax_b, h0b, lvb, gb_o, gb_h, gb_n, gb_start, gb_items, gb_segb,
              rho_a, seed_ab, heads_ab, lows_ab, at_ab, low_ab, exact_ab, tally_ab, hint_ab,
              g0_o, g0_h, g0_n, g0_start, g0_items, g0_segb, nxt_b, r_cross, half_max, firsts_b, firsts_a, segb_a,
              segb_b, clear, pa, pb):
    n = len(rel_ba)
    PB = np.empty((len(Vb), 2))
    PA = np.empty((len(Va), 2))
    for k in range(k0, n):
        # B's vertices against A's edges (A's frame), then A's against B's (sweep2d._boundary_distance)
        if level_of(h0a, hint_ba) != lva or level_of(h0b, hint_ab) != lvb:
            return k, seed_ba, hint_ba, seed_ab, hint_ab
        _move(rel_ba[k], Vb, PB)
        d1, i1, q1x, q1y = _search(PB, rho_b, Va, prev_a, half_a, ca[0], ca[1], rmin_a, rmax_a, ga_o, ga_h, ga_n,
                                   ga_start, ga_items, ga_segb, chunk, margin, seed_ba, heads_ba, lows_ba, at_ba,
                                   low_ba, exact_ba, tally_ba)
        if i1 < 0:  # far apart: the KD-tree's
            return k, seed_ba, hint_ba, seed_ab, hint_ab
        hint_ba, seed_ba = d1, i1
        if level_of(h0b, hint_ab) != lvb:
            return k, seed_ba, hint_ba, seed_ab, hint_ab
        _move(rel_ab[k], Va, PA)
        d2, i2, q2x, q2y = _search(PA, rho_a, Vb, prev_b, half_b, cb[0], cb[1], rmin_b, rmax_b, gb_o, gb_h, gb_n,
                                   gb_start, gb_items, gb_segb, chunk, margin, seed_ab, heads_ab, lows_ab, at_ab,
                                   low_ab, exact_ab, tally_ab)
        if i2 < 0:
            return k, seed_ba, hint_ba, seed_ab, hint_ab
        hint_ab, seed_ab = d2, i2
        # crossing.certainly_apart
        d = d1 if d1 <= d2 else d2
        if not d > APART_MIN_MM:
            return k, seed_ba, hint_ba, seed_ab, hint_ab
        if not d > half_max and _any_crossing(PB, nxt_b, prev_b, Va, g0_segb, prev_a, g0_o[0], g0_o[1], g0_h,
                                              g0_n[0], g0_n[1], g0_start, g0_items, r_cross):
            return k, seed_ba, hint_ba, seed_ab, hint_ab
        if _holds_a_loop(PB, firsts_b, Va, segb_a) or _holds_a_loop(PA, firsts_a, Vb, segb_b):
            return k, seed_ba, hint_ba, seed_ab, hint_ab
        clear[k] = d
        if d1 <= d2:
            pa[k, 0], pa[k, 1] = _move1(Ma[k], q1x, q1y)
            pb[k, 0], pb[k, 1] = _move1(Ma[k], PB[i1, 0], PB[i1, 1])
        else:
            pa[k, 0], pa[k, 1] = _move1(Mb[k], PA[i2, 0], PA[i2, 1])
            pb[k, 0], pb[k, 1] = _move1(Mb[k], q2x, q2y)
    return n, seed_ba, hint_ba, seed_ab, hint_ab


def _grid_args(g):
    return (g.origin, g.h, np.array([g.nx, g.ny], np.int64), g.start, g.items, g.seg_b)


def _body_args(tgt, src, level: int):
    """What ``nearest_edge(P, tgt, src)`` passes its kernel, for src's points at grid `level` of tgt."""
    g = grid_of(tgt, level)
    _, rho, _ = _chunk_discs(src)
    mem = _memory(tgt, src, len(rho), len(src.points))
    return ((tgt.points, tgt.prev, tgt.half_len, np.asarray(tgt.center, np.float64),
             tgt.r_min - 1e-9 * (1.0 + tgt.radius), tgt.radius + 1e-9 * (1.0 + tgt.radius), grid_of(tgt).h, level)
            + _grid_args(g) + (rho, mem.seed, mem.heads, mem.lows, mem.at, mem.low_pt, mem.exact, mem.searches)), mem


def apart_steps(A, B, rel_ba: np.ndarray, rel_ab: np.ndarray, Ma: np.ndarray, Mb: np.ndarray, k0: int,
                clear: np.ndarray, pa: np.ndarray, pb: np.ndarray) -> int:
    """Steps k0, k0 + 1, … of a sweep of outlines A and B (rel_ba[k]: B's body to A's, rel_ab[k] its inverse; Ma, Mb
    the world poses) while the bodies are certainly apart, their clearance and closest points written into clear,
    pa, pb (the overlap area is 0 there); returns the first step not taken (len(rel_ba) when every one was), which
    the caller takes step by step.  The searches' memories, seeds and hints are left as nearest_edge leaves them."""
    hints_a = A.__dict__.setdefault("_nearest_hints", {})
    hints_b = B.__dict__.setdefault("_nearest_hints", {})
    hint_ba, hint_ab = float(hints_a.get(id(B), 0.0)), float(hints_b.get(id(A), 0.0))
    args_a, mem_ba = _body_args(A, B, _level_for(A, hint_ba))
    args_b, mem_ab = _body_args(B, A, _level_for(B, hint_ab))
    g0 = grid_of(A)
    r_cross = (A.half_len + B.half_len) * (1.0 + 1e-9) + 1e-12
    k, seed_ba, h_ba, seed_ab, h_ab = _steps_nb(
        k0, rel_ba, rel_ab, Ma, Mb, _CHUNK, policy.MOTION_PRUNE_MARGIN_MM, *args_a, hint_ba, *args_b, hint_ab,
        *_grid_args(g0), B.nxt, r_cross, max(A.half_len, B.half_len), _loop_firsts(B), _loop_firsts(A), A.seg_b,
        B.seg_b, clear, pa, pb)
    if k > k0 or seed_ba != mem_ba.seed or h_ba != hint_ba:
        mem_ba.seed, hints_a[id(B)] = int(seed_ba), float(h_ba)
    if k > k0 or seed_ab != mem_ab.seed or h_ab != hint_ab:
        mem_ab.seed, hints_b[id(A)] = int(seed_ab), float(h_ab)
    return int(k)


# the disk cache of these kernels keyed on every kernel source (nbcache)
bind(globals())
