"""Whether two planar bodies are certainly apart, without a boolean: their boundaries cross nowhere and
neither holds a loop of the other (compiled with numba; the 2D sweeps skip the manifold3d intersection
at the steps where this holds, its area being 0 there).

Two polylines whose least vertex-to-edge distance d exceeds half the longest edge of either cannot
cross (at a crossing, the nearer end of each edge lies within half its length of the other edge);
below that the edges near each other are tested pairwise (orientation signs; any zero counts as a
crossing, so that a doubtful step goes to the boolean).  With the boundaries apart, the bodies' common
area is a union of whole loops of one inside the other, so one vertex of each loop decides
(winding number about it, manifold3d's fill rule Positive: inside where it is above 0).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .nearest import disc_cells, grid_of
from ...nbcache import bind

__all__ = ["certainly_apart", "common_area"]

#: least vertex-to-edge distance (mm) below which the boolean always decides
APART_MIN_MM = 1e-6


@njit(cache=True)
def _orient(ax, ay, bx, by, cx, cy):
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


@njit(cache=True)
def _segments_meet(ax, ay, bx, by, cx, cy, dx, dy) -> bool:
    """Whether segments ab and cd cross or touch (a zero orientation counts as touching)."""
    o1 = _orient(ax, ay, bx, by, cx, cy)
    o2 = _orient(ax, ay, bx, by, dx, dy)
    if (o1 > 0 and o2 > 0) or (o1 < 0 and o2 < 0):
        return False
    o3 = _orient(cx, cy, dx, dy, ax, ay)
    o4 = _orient(cx, cy, dx, dy, bx, by)
    return not ((o3 > 0 and o4 > 0) or (o3 < 0 and o4 < 0))


@njit(cache=True)
def _any_crossing(P, nxt_p, prev_p, V, seg_b, prev_v, ox, oy, h, nx, ny, start, items, r):
    """Whether an edge of P (P[i] -> P[nxt_p[i]]) meets an edge of the outline V (V[v] -> seg_b[v]): the pairs of
    edges with ends within r of each other (r: the sum of half the longest edge of each)."""
    for i in range(len(P)):
        px, py = P[i, 0], P[i, 1]
        ix0, ix1, iy0, iy1 = disc_cells(px, py, r, ox, oy, h, nx, ny)
        for ix in range(ix0, ix1 + 1):
            for iy in range(iy0, iy1 + 1):
                c = ix * ny + iy
                for k in range(start[c], start[c + 1]):
                    v = items[k]
                    dx, dy = px - V[v, 0], py - V[v, 1]
                    if dx * dx + dy * dy > r * r:
                        continue
                    for a in (i, prev_p[i]):
                        b = nxt_p[a]
                        for e in (v, prev_v[v]):
                            if _segments_meet(P[a, 0], P[a, 1], P[b, 0], P[b, 1], V[e, 0], V[e, 1],
                                              seg_b[e, 0], seg_b[e, 1]):
                                return True
    return False


@njit(cache=True)
def _winding(px, py, V, seg_b) -> int:
    """Winding number of the closed edges V[k] -> seg_b[k] about (px, py)."""
    w = 0
    for k in range(len(V)):
        ax, ay, bx, by = V[k, 0], V[k, 1], seg_b[k, 0], seg_b[k, 1]
        if ay <= py:
            if by > py and _orient(ax, ay, bx, by, px, py) > 0:
                w += 1
        elif by <= py and _orient(ax, ay, bx, by, px, py) < 0:
            w -= 1
    return w


@njit(cache=True)
def _holds_a_loop(P, firsts, V, seg_b) -> bool:
    for j in range(len(firsts)):
        i = firsts[j]
        if _winding(P[i, 0], P[i, 1], V, seg_b) > 0:
            return True
    return False


def _loop_firsts(o) -> np.ndarray:
    f = getattr(o, "_loop_firsts", None)
    if f is None:
        f = o._loop_firsts = np.flatnonzero(np.r_[True, o.loop_id[1:] != o.loop_id[:-1]]).astype(np.int64)
    return f


@njit(cache=True)
def _apart(d, PB, PA, nxt_b, prev_b, Va, seg_b0, prev_a, ox, oy, h, nx, ny, start, items, r_cross, half_max, firsts_b,
           firsts_a, seg_b_a, Vb, seg_b_b) -> bool:
    """:func:`certainly_apart`'s tests (d < 0: the least distance not known), on the arguments of
    :func:`apart_args` after PB and PA."""
    if not (d < 0.0 or d > APART_MIN_MM):
        return False
    if (d < 0.0 or not d > half_max) and _any_crossing(PB, nxt_b, prev_b, Va, seg_b0, prev_a, ox, oy, h, nx, ny, start,
                                                       items, r_cross):
        return False
    return not (_holds_a_loop(PB, firsts_b, Va, seg_b_a) or _holds_a_loop(PA, firsts_a, Vb, seg_b_b))


def apart_args(A, B) -> tuple:
    """What :func:`_apart` takes after d, PB and PA for outlines A and B (A's grid of level 0; r_cross: the sum of
    half the longest edge of each, the reach of a crossing)."""
    g = grid_of(A)
    r_cross = (A.half_len + B.half_len) * (1.0 + 1e-9) + 1e-12
    return (B.nxt, B.prev, A.points, g.seg_b, A.prev, g.origin[0], g.origin[1], g.h, g.nx, g.ny, g.start, g.items,
            r_cross, max(A.half_len, B.half_len), _loop_firsts(B), _loop_firsts(A), A.seg_b, B.points, B.seg_b)


def certainly_apart(A, B, PB: np.ndarray, PA: np.ndarray, d: float | None) -> bool:
    """Whether outlines A and B (PB: B's vertices in A's frame, PA: A's in B's; d: the least vertex-to-edge
    distance between them, both ways, or None when not known) have no area in common: the boundaries cross
    nowhere and no loop of one lies inside the other.  False when in doubt (d below APART_MIN_MM, or edges that
    meet or touch)."""
    return bool(_apart(-1.0 if d is None else float(d), np.ascontiguousarray(PB, np.float64),
                       np.ascontiguousarray(PA, np.float64), *apart_args(A, B)))


def common_area(A, B, rel_ba: np.ndarray, PB: np.ndarray, PA: np.ndarray) -> float:
    """The area (mm^2) outlines A and B have in common with B placed in A's frame by ``rel_ba`` (PB: B's vertices in
    A's frame, PA: A's in B's): 0.0 without the boolean where they are :func:`certainly_apart`, else manifold3d's
    intersection.  Where they touch, the boolean may leave a sliver of about 1e-14 mm^2 that this gives as 0.0: for a
    comparison with a tolerance (a start free or not), not for an area reported as the boolean's."""
    if certainly_apart(A, B, PB, PA, None):
        return 0.0
    return float((A.section ^ B.section.transform(rel_ba)).area())


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
