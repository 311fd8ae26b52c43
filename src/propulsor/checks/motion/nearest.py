"""Least distance from a set of points to an outline's edges, compiled with numba (the hot loop of the 2D
motion sweeps: both directions at every step).

The outline's vertices are bucketed in a uniform grid (built once per outline, body frame).  A point's
nearest vertex is searched ring by ring of cells around it until the ring's distance exceeds the bound,
and the source points come in runs of consecutive vertices (distance._CHUNK) each held in a disc about its first
(radius fixed in the source body): a run whose first point is farther than bound + radius from every
vertex is skipped whole.

Searches remember what they found (per source outline, on the target): the point of the last answer gives the
first bound, and a point or a run whose nearest vertex was found farther than the bound by more than it has
moved since is skipped (the final drive's windowed sweeps -32 %, the cams' -49 %: a sweep's steps are close).

The answer is that of the KD-tree search (:func:`propulsor.checks.motion.distance.min_dist_points_to`,
which takes over when the bodies are far apart): ub = least nearest-vertex distance; candidates: points
within ub + half the longest edge of a vertex; their pairs (point, edge starting at each vertex within
that radius), then (point, edge ending there); the first pair at the least point-to-edge distance.
"""

from __future__ import annotations

import math
import weakref

import numpy as np
from numba import njit
from ...nbcache import bind
from ...planar import box

__all__ = ["VertexGrid", "grid_of", "disc_cells", "nearest_edge"]


class VertexGrid:
    """Uniform grid of an outline's vertices (body frame): cell (ix, iy) of side h from `origin`; the
    vertices of cell c are ``items[start[c]:start[c + 1]]`` in ascending order."""

    def __init__(self, points: np.ndarray, seg_b: np.ndarray, seg_len: np.ndarray, scale: float = 1.0):
        lo, hi = box(points)
        span = np.maximum(hi - lo, 1e-9)
        # about 8 mean edges a cell side (times `scale`), at most 2^21 cells
        h = scale * max(8.0 * float(np.mean(seg_len)), math.sqrt(float(span[0] * span[1]) / float(1 << 21)), 1e-6)
        nx, ny = int(span[0] // h) + 1, int(span[1] // h) + 1
        ix = np.minimum(((points[:, 0] - lo[0]) / h).astype(np.int64), nx - 1)
        iy = np.minimum(((points[:, 1] - lo[1]) / h).astype(np.int64), ny - 1)
        # the vertices of each cell in ascending order (a stable sort by cell), the cells' starts, and near[c]: a
        # vertex lies in cell c or one of its 8 neighbours (a disc of radius <= h about a point of cell c, or of the
        # edge cell a point outside the grid is clamped to, overlaps those cells only): compiled, one counting pass
        self.items, self.start, self.near = _bucket_nb(ix, iy, nx, ny)
        self.origin = lo.astype(np.float64)
        self.seg_b = np.ascontiguousarray(seg_b, np.float64)
        self.h, self.nx, self.ny = float(h), nx, ny


@njit(cache=True)
def _bucket_nb(ix, iy, nx, ny):
    """(items, start, near) of :class:`VertexGrid` from each vertex's cell column and row: the vertex indices by
    cell c = ix * ny + iy, ascending within a cell (a counting sort: ``np.argsort(cell, kind="stable")``), the
    start of each cell's run (``np.searchsorted`` of the sorted cells, nx ny + 1 of them), and whether a vertex lies
    in the cell or one of its 8 neighbours."""
    n = len(ix)
    cells = nx * ny
    count = np.zeros(cells + 1, np.int64)
    for k in range(n):
        count[ix[k] * ny + iy[k] + 1] += 1
    start = np.cumsum(count)
    fill = start[:-1].copy()
    items = np.empty(n, np.int64)
    for k in range(n):
        c = ix[k] * ny + iy[k]
        items[fill[c]] = k
        fill[c] += 1
    near = np.zeros(cells, np.bool_)
    for gx in range(nx):
        for gy in range(ny):
            if start[gx * ny + gy + 1] > start[gx * ny + gy]:
                for qx in range(max(gx - 1, 0), min(gx + 2, nx)):
                    for qy in range(max(gy - 1, 0), min(gy + 2, ny)):
                        near[qx * ny + qy] = True
    return items, start, near


#: the grids of an outline: cells of 1, 3, 9, … times the finest side (a search costs about (distance /
#: cell side)² cells, so bodies far apart are searched in the coarser grids)
LEVEL_FACTOR = 3.0
MAX_LEVEL = 4
#: bodies farther apart than this many grid cells are left to the KD-tree search (distance.min_dist_points_to)
FAR_CELLS = 6.0


def grid_of(outline, level: int = 0) -> VertexGrid:
    """The vertex grid of an Outline at `level` (cell side LEVEL_FACTOR ** level times the finest; cached on it)."""
    grids = getattr(outline, "_vertex_grids", None)
    if grids is None:
        grids = outline._vertex_grids = {}
    g = grids.get(level)
    if g is None:
        g = grids[level] = VertexGrid(outline.points, outline.seg_b, outline.seg_len, LEVEL_FACTOR ** level)
    return g


def _level_for(outline, distance: float) -> int:
    """The grid level of an Outline for a search at `distance` (:func:`level_of` of its finest cell side)."""
    return int(level_of(grid_of(outline).h, float(distance)))


@njit(cache=True)
def level_of(h0, distance):
    """The coarsest grid whose cell side (h0 the finest's) is at most a quarter of `distance`, the finest for a
    distance below four of its cells; one level coarser where that one's FAR_CELLS cells fall short of 1.25 times the
    distance (bodies that far apart would be left to the KD-tree at every step: the cams' shoe and carrier 16 mm
    apart).  The searches skip the cells wholly beyond what they look for (:func:`_cell_beyond`), so the rings of
    finer cells cost little, and cells of a quarter of the distance rather than a half hold fewer vertices beyond it (a
    pin in a bore, every vertex 27.5 mm from the other body: the final drive's pin sweep 0.98 -> 0.89 CPU s, the cams'
    motion proofs 0.57 -> 0.54).  It decides the searches' speed, never their answer."""
    if not distance > 4.0 * h0:
        return 0
    level = int(min(MAX_LEVEL, math.floor(math.log(distance / (4.0 * h0)) / math.log(LEVEL_FACTOR))))
    if level < MAX_LEVEL and FAR_CELLS * h0 * LEVEL_FACTOR ** level < 1.25 * distance:
        level += 1
    return level


@njit(cache=True)
def disc_cells(px, py, r, ox, oy, h, nx, ny):
    """The grid cells (ix0, ix1, iy0, iy1, inclusive, cut to the grid) that the disc of radius r about (px, py)
    overlaps: an empty range (ix1 < ix0 or iy1 < iy0) where the disc misses the grid (before, it was clamped to the
    grid's edge cells, whose vertices, all farther than r, were tested: the final drive's crossing tests 0.93 -> 0.38
    CPU s)."""
    return (max(int(math.floor((px - r - ox) / h)), 0), min(int(math.floor((px + r - ox) / h)), nx - 1),
            max(int(math.floor((py - r - oy) / h)), 0), min(int(math.floor((py + r - oy) / h)), ny - 1))


@njit(cache=True, inline="always")
def _cell_beyond(px, py, ix, iy, ox, oy, h, r):
    """Whether every point of grid cell (ix, iy)'s box is farther than r from (px, py), by more than a margin for the
    rounding of the box's sides against the cells the vertices were filed in: a search skips such a cell, whose
    vertices it would test and reject one by one (the same answer).  Where the vertices lie in a band about the point
    (a pin in a bore: every vertex about equally near) the square of cells about the point's disc holds most of the
    band beyond the disc: skipping them, the final drive's pin sweep 1.33 -> 0.98 CPU s, the cams' motion proofs 0.96
    -> 0.57."""
    x0 = ox + ix * h
    y0 = oy + iy * h
    dx = max(x0 - px, px - (x0 + h), 0.0)
    dy = max(y0 - py, py - (y0 + h), 0.0)
    m = 1e-9 * (1.0 + abs(px) + abs(py) + abs(ox) + abs(oy) + h)
    rr = r + m
    return dx * dx + dy * dy > rr * rr


@njit(cache=True, inline="always")
def _nearest_vertex_low(px, py, V, ox, oy, h, nx, ny, start, items, bound):
    """(distance from (px, py) to the nearest vertex if it is <= bound, else inf; a lower bound of that distance):
    cKDTree's arithmetic, the square root of dx² + dy².  The rings of cells are searched until the next is farther
    than the bound; the lower bound is the least of the nearest vertex found and that ring's distance (a point off
    the grid is no nearer to a cell than its projection on the grid's box, which lies in the cell searched first).
    A cell wholly beyond the nearest vertex found so far is skipped (:func:`_cell_beyond`: none of its vertices is
    nearer); not one beyond the bound only, whose vertices still lower the best, which the lower bound takes."""
    cx = min(max(int(math.floor((px - ox) / h)), 0), nx - 1)
    cy = min(max(int(math.floor((py - oy) / h)), 0), ny - 1)
    best = np.inf
    r = 0
    rmax = max(nx, ny)
    low = -1.0
    while r <= rmax:
        if (r - 1) * h > min(best, bound):  # every cell of this ring and beyond is farther
            low = min(best, (r - 1) * h)
            break
        for ix in range(cx - r, cx + r + 1):
            if ix < 0 or ix >= nx:
                continue
            step = 1 if (ix == cx - r or ix == cx + r) else 2 * r
            iy = cy - r
            while iy <= cy + r:
                if 0 <= iy < ny and not _cell_beyond(px, py, ix, iy, ox, oy, h, best):
                    c = ix * ny + iy
                    for k in range(start[c], start[c + 1]):
                        v = items[k]
                        dx = px - V[v, 0]
                        dy = py - V[v, 1]
                        d = math.sqrt(dx * dx + dy * dy)
                        if d < best:
                            best = d
                iy += step
        r += 1
    if low < 0.0:  # every cell searched
        low = best
    return (best if best <= bound else np.inf), low


@njit(cache=True)
def _nearest_vertex(px, py, V, ox, oy, h, nx, ny, start, items, bound):
    """Distance from (px, py) to the nearest vertex if it is <= bound, else inf (``_nearest_vertex_low``)."""
    return _nearest_vertex_low(px, py, V, ox, oy, h, nx, ny, start, items, bound)[0]


@njit(cache=True, inline="always")
def _still_farther(low, ax, ay, px, py, bound):
    """Whether a point whose nearest vertex was at least `low` away when it stood at (ax, ay) is still farther than
    `bound` from every vertex, standing at (px, py): at least `low` less its move (1e-9: the rounding)."""
    hx, hy = px - ax, py - ay
    return low - math.sqrt(hx * hx + hy * hy) > bound + 1e-9 * (1.0 + abs(low))


@njit(cache=True)
def _run_within(P, r0, lb_r0, rho_c, bound, margin, V, ox, oy, h, nx, ny, start, items, heads, lows, c):
    """Whether a point of the run c starting at r0 (all within rho_c of P[r0]) may lie within `bound` of a vertex:
    first by the annulus bound of P[r0], then by what an earlier search of the run showed (its head's nearest
    vertex was at least lows[c] away with the head at heads[c]: now at least lows[c] less the head's move), then
    by its nearest vertex (margin: the rounding of the moved points against their body-frame discs).  A search
    leaves its head and its lower bound in heads / lows.  The answer is that of the search alone: the memory only
    skips searches that would say no."""
    if lb_r0 - rho_c > bound + margin:
        return False
    if _still_farther(lows[c], heads[c, 0], heads[c, 1], P[r0, 0], P[r0, 1], bound + margin + rho_c):
        return False
    dr, low = _nearest_vertex_low(P[r0, 0], P[r0, 1], V, ox, oy, h, nx, ny, start, items,
                                  bound + rho_c + 2.0 * margin)
    heads[c, 0], heads[c, 1] = P[r0, 0], P[r0, 1]
    lows[c] = low
    return not dr - rho_c > bound + margin


@njit(cache=True)
def _known_farther(P, i, at, low_pt, bound):
    """Whether an earlier search shows point i's nearest vertex farther than `bound` (``_still_farther``)."""
    return _still_farther(low_pt[i], at[i, 0], at[i, 1], P[i, 0], P[i, 1], bound)


@njit(cache=True)
def _search(P, i, V, ox, oy, h, nx, ny, start, items, bound, at, low_pt, exact, tally):
    """Point i's nearest vertex if it is within `bound` (else inf), remembered with a lower bound of its distance
    (exact when found; tally[0] counts the searches)."""
    d, low = _nearest_vertex_low(P[i, 0], P[i, 1], V, ox, oy, h, nx, ny, start, items, bound)
    tally[0] += 1
    at[i, 0], at[i, 1] = P[i, 0], P[i, 1]
    exact[i] = d < np.inf
    low_pt[i] = low
    return d


@njit(cache=True, inline="always")
def _point_seg(px, py, ax, ay, bx, by):
    """(distance, foot x, foot y) of (px, py) on the segment a-b: the operations of ``distance._point_seg`` on one
    row, in its order (the dot products as numpy's einsum of two terms sums them, the norm as numpy's: the square root
    of the sum of squares), so the same floats; inlined into the searches that call it."""
    sx, sy = bx - ax, by - ay
    dd = sx * sx + sy * sy
    t = ((px - ax) * sx + (py - ay) * sy) / (dd if dd > 0 else 1.0)
    t = min(max(t, 0.0), 1.0)
    qx, qy = ax + t * sx, ay + t * sy
    ex, ey = px - qx, py - qy
    return math.sqrt(ex * ex + ey * ey), qx, qy


@njit(cache=True)
def _nearest_edge(P, seed, cap, rho, V, B, prev, half_len, ox, oy, h, nx, ny, start, items, chunk, margin, ccx, ccy,
                  r_min, r_max, far, heads, lows, at, low_pt, exact, tally):
    """(d, index in P, foot x, y) of :func:`nearest_edge`; (-1, -1, nan, nan): far apart, the KD-tree's turn.  With a
    finite ``cap`` only an answer d <= cap is sought, (inf, -1, nan, nan) where there is none: every point whose edge
    lies within cap has a vertex of that edge within cap + half_len, so the first pass (the least nearest-vertex
    distance, ub) is left out and cap takes its place (a smaller bound where cap <= ub: the other direction's answer
    is at most the least vertex-to-vertex distance, which ub is).  The distance is the whole search's; where several
    point-edge pairs tie at it, the first in the order (the edge's side of the vertex it was found from, the point,
    the vertex) is taken among those found from vertices within the bound + half_len, so a pair found from its
    farther end by the whole search (its reach the larger) can lose the tie to another (make's 19 parts: no
    reported point moved; a bound from the last answer's point alone, cap or not, moved 13 of a cam slide's 720,
    each to another point at the same least distance, and was left out)."""
    n = len(P)
    nch = (n + chunk - 1) // chunk
    # a lower bound of each point's distance from the outline's vertices: the annulus r_min .. r_max about
    # (ccx, ccy) holds them
    lb = np.empty(n)
    lb_min = np.inf
    for i in range(n):
        dx, dy = P[i, 0] - ccx, P[i, 1] - ccy
        dc = math.sqrt(dx * dx + dy * dy)
        lb[i] = max(dc - r_max, r_min - dc)
        lb_min = min(lb_min, lb[i])
    if lb_min > far:  # far apart: the rings of cells to search grow as (distance / cell)²; the tree's turn
        return -1.0, -1, np.nan, np.nan
    if cap < np.inf:
        ub = cap
    else:
        # a first bound: the nearest vertex of the point with the least lower bound
        i0 = 0
        for i in range(n):
            if lb[i] < lb[i0]:
                i0 = i
        ub = _nearest_vertex(P[i0, 0], P[i0, 1], V, ox, oy, h, nx, ny, start, items, np.inf)
        if 0 <= seed < n and seed != i0:  # the point of the last answer (a sweep's steps are close): a tighter bound
            ub = min(ub, _nearest_vertex(P[seed, 0], P[seed, 1], V, ox, oy, h, nx, ny, start, items, ub))
        # ub: the least nearest-vertex distance over every point (runs pruned by their discs)
        # (margin: the rounding of the moved points against their body-frame discs; 1e-9: that of the bounds)
        for c in range(nch):
            r0 = c * chunk
            if not _run_within(P, r0, lb[r0], rho[c], ub, margin, V, ox, oy, h, nx, ny, start, items, heads, lows, c):
                continue
            for i in range(r0, min(r0 + chunk, n)):
                if lb[i] > ub + 1e-9 * (1.0 + ub):
                    continue
                if _known_farther(P, i, at, low_pt, ub):
                    continue
                d = _search(P, i, V, ox, oy, h, nx, ny, start, items, ub, at, low_pt, exact, tally)
                if d < ub:
                    ub = d
    R = ub + half_len
    rb = R + 1e-12
    best_d = np.inf
    best_key0 = 2
    best_key1 = 0
    best_key2 = 0
    best_i = -1
    qx_best = np.nan
    qy_best = np.nan
    k = -1  # candidate counter (ascending point index)
    for c in range(nch):
        r0 = c * chunk
        if not _run_within(P, r0, lb[r0], rho[c], R, margin, V, ox, oy, h, nx, ny, start, items, heads, lows, c):
            continue
        for i in range(r0, min(r0 + chunk, n)):
            if lb[i] > R + 1e-9 * (1.0 + R):
                continue
            px, py = P[i, 0], P[i, 1]
            if _known_farther(P, i, at, low_pt, R):
                continue
            if exact[i] and at[i, 0] == px and at[i, 1] == py:
                dv = low_pt[i]  # this very point's nearest vertex, found in the first pass
            else:
                dv = _search(P, i, V, ox, oy, h, nx, ny, start, items, R, at, low_pt, exact, tally)
            if dv > R:
                continue
            k += 1
            # the vertices within rb: cells overlapping the disc (those of its square wholly beyond it skipped)
            ix0, ix1, iy0, iy1 = disc_cells(px, py, rb, ox, oy, h, nx, ny)
            for ix in range(ix0, ix1 + 1):
                for iy in range(iy0, iy1 + 1):
                    if _cell_beyond(px, py, ix, iy, ox, oy, h, rb):
                        continue
                    cc = ix * ny + iy
                    for kk in range(start[cc], start[cc + 1]):
                        v = items[kk]
                        dx = px - V[v, 0]
                        dy = py - V[v, 1]
                        if not (math.sqrt(dx * dx + dy * dy) <= rb):
                            continue
                        for blk in range(2):
                            e = v if blk == 0 else prev[v]
                            d, qx, qy = _point_seg(px, py, V[e, 0], V[e, 1], B[e, 0], B[e, 1])
                            if d < best_d or (d == best_d and (blk, k, v) < (best_key0, best_key1, best_key2)):
                                best_d, best_key0, best_key1, best_key2 = d, blk, k, v
                                best_i, qx_best, qy_best = i, qx, qy
    if best_d > cap:  # the least within cap + half_len of a vertex, not the least of all: none within cap
        return np.inf, -1, np.nan, np.nan
    return best_d, best_i, qx_best, qy_best



class _Memory:
    """What the searches of one source outline against one target have shown (:func:`nearest_edge`): the point of
    the last answer (``seed``); per run of source points its head and a lower bound of the head's distance from
    the target's vertices (``heads``, ``lows``; -inf: never searched); per point the same (``at``, ``low_pt``),
    ``exact`` where the bound is the distance itself.  Target frame."""

    __slots__ = ("src", "seed", "heads", "lows", "at", "low_pt", "exact", "searches")

    def __init__(self, src, n_runs: int, n_points: int):
        self.src = weakref.ref(src)
        self.seed = -1
        self.heads = np.zeros((n_runs, 2))
        self.lows = np.full(n_runs, -np.inf)
        self.at = np.zeros((n_points, 2))
        self.low_pt = np.full(n_points, -np.inf)
        self.exact = np.zeros(n_points, np.bool_)
        self.searches = np.zeros(1, np.int64)  # points' nearest-vertex searches made


def _memory(tgt, src, n_runs: int, n_points: int) -> _Memory:
    """The memory of src's searches against tgt (kept on tgt, per source; a new one for a new source object, even
    one at the address of a freed one)."""
    mems = getattr(tgt, "_nearest_memory", None)
    if mems is None:
        mems = tgt._nearest_memory = {}
    mem = mems.get(id(src))
    if mem is None or mem.src() is not src or len(mem.lows) != n_runs or len(mem.low_pt) != n_points:
        for key in [key for key, m in mems.items() if m.src() is None]:  # of sources since freed
            del mems[key]
        mem = mems[id(src)] = _Memory(src, n_runs, n_points)
    return mem


def hints_of(tgt) -> dict:
    """The last least distance of each source outline's searches against tgt (by id; the grid level follows it)."""
    hints = getattr(tgt, "_nearest_hints", None)
    if hints is None:
        hints = tgt._nearest_hints = {}
    return hints


def search_args(tgt, src, level: int) -> tuple[_Memory, tuple]:
    """The memory of src's searches against tgt, and what the compiled search takes after the points, the seed and
    the cap for src's vertices (moved into tgt's frame) against tgt's edges on grid
    `level` (``_nearest_edge(P, seed, cap, *args)``): :func:`nearest_edge` and the sweep's compiled steps
    (sweep_steps.py) both call it so."""
    from ... import policy
    from .distance import _CHUNK, _chunk_discs

    g = grid_of(tgt, level)
    _, rho, _ = _chunk_discs(src)
    mem = _memory(tgt, src, len(rho), len(src.points))
    return mem, (rho, tgt.points, g.seg_b, tgt.prev, tgt.half_len, g.origin[0], g.origin[1], g.h, g.nx, g.ny, g.start,
                 g.items, _CHUNK, policy.MOTION_PRUNE_MARGIN_MM, float(tgt.center[0]), float(tgt.center[1]),
                 tgt.r_min - 1e-9 * (1.0 + tgt.radius), tgt.radius + 1e-9 * (1.0 + tgt.radius), FAR_CELLS * g.h,
                 mem.heads, mem.lows, mem.at, mem.low_pt, mem.exact, mem.searches)


def nearest_edge(P: np.ndarray, tgt, src, cap: float = math.inf) -> tuple[float, int, np.ndarray]:
    """Least distance from points P (tgt body frame; the vertices of outline `src`, rigidly moved, same order)
    to tgt's edges: (d, index in P, foot point) — from the grid, or from distance.min_dist_points_to (the same
    answer) when every point is more than FAR_CELLS cells from tgt's vertices.  The grid's level follows the
    last answer for the same two outlines (a sweep's steps are close), the first bound starts from the point of
    that answer, and a point (a run) whose nearest vertex an earlier search put farther than the bound by more
    than it has moved since is not searched again (``_Memory``): the answer depends on none of them.  With a finite
    ``cap`` (the least distance the other way, :func:`.sweep2d._boundary_distance`), only an answer d <= cap is
    sought: (inf, -1, [nan, nan]) where there is none (``_nearest_edge``); bodies far apart get the KD-tree's whole
    answer, cap or not."""
    from .distance import min_dist_points_to

    hints = hints_of(tgt)
    mem, args = search_args(tgt, src, _level_for(tgt, hints.get(id(src), 0.0)))
    d, i, qx, qy = _nearest_edge(np.ascontiguousarray(P, np.float64), mem.seed, float(cap), *args)
    if i < 0 and d < 0.0:
        d, i, q = min_dist_points_to(P, tgt, src)
        hints[id(src)] = d
        return d, i, q
    if i < 0:  # none within cap: the distance is more (the grid's level follows cap)
        hints[id(src)] = float(cap)
        return math.inf, -1, np.array([np.nan, np.nan])
    hints[id(src)] = float(d)
    mem.seed = int(i)
    return float(d), int(i), np.array([qx, qy])


@njit(cache=True, inline="always")
def _edge_distance(px, py, V, seg_b, prev, reach, ox, oy, h, nx, ny, start, items):
    """The least distance from (px, py) to the edges with an end within ``reach`` (each vertex starts one edge and
    ends another, prev[v]: both taken), by :func:`_point_seg`; inf where no vertex lies that near.  A caller that
    makes ``reach`` its nearest vertex's distance plus half the longest edge gets the distance to the whole outline
    (every nearest edge has an end within it)."""
    best = np.inf
    r2 = reach * reach
    ix0, ix1, iy0, iy1 = disc_cells(px, py, reach, ox, oy, h, nx, ny)
    for ix in range(ix0, ix1 + 1):
        for iy in range(iy0, iy1 + 1):
            c = ix * ny + iy
            for k in range(start[c], start[c + 1]):
                v = items[k]
                fx, fy = px - V[v, 0], py - V[v, 1]
                if fx * fx + fy * fy > r2:
                    continue
                for e in (v, prev[v]):  # the edges starting and ending at v, as _nearest_edge takes them
                    d = _point_seg(px, py, V[e, 0], V[e, 1], seg_b[e, 0], seg_b[e, 1])[0]
                    if d < best:
                        best = d
    return best


@njit(cache=True)
def _dist_each_nb(P, half_len, V, seg_b, prev, ox, oy, h, nx, ny, start, items):
    """Each point's least distance to the outline's edges (``distance.dist_each_point``): among the edges with an end
    within its nearest vertex's distance plus half the longest edge (:func:`_edge_distance`: every nearest edge has an
    end within that disc; 1e-12 mm to spare for the rounding)."""
    out = np.full(len(P), np.inf)
    for i in range(len(P)):
        px, py = P[i, 0], P[i, 1]
        reach = _nearest_vertex(px, py, V, ox, oy, h, nx, ny, start, items, np.inf) + half_len + 1e-12
        out[i] = _edge_distance(px, py, V, seg_b, prev, reach, ox, oy, h, nx, ny, start, items)
    return out


def dist_each(P: np.ndarray, tgt) -> np.ndarray:
    """Distance from every point of P (tgt body frame) to tgt's boundary: :func:`.distance.dist_each_point`'s floats
    (for each point the least of ``distance._point_seg``'s distances to the edges with an end within its nearest
    vertex's distance plus half the longest edge) in one compiled loop on tgt's finest grid (:func:`_dist_each_nb`),
    without the KD-tree's ball query and numpy's rows: 0.36 -> 0.05 ms a call of an overlapping sweep step's
    penetration depth (177 points each on the thesis final drive)."""
    if len(P) == 0:
        return np.empty(0)
    g = grid_of(tgt)
    return _dist_each_nb(np.ascontiguousarray(P, np.float64), float(tgt.half_len), tgt.points, g.seg_b,
                         np.ascontiguousarray(tgt.prev, np.int64), g.origin[0], g.origin[1], g.h, g.nx, g.ny, g.start,
                         g.items)


# the disk cache of these kernels keyed on every kernel source (one may be compiled into another's code)
bind(globals())
