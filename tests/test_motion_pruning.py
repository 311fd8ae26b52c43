"""The compiled least distance of the 2D sweeps (checks/motion/nearest.py: a vertex grid, runs of source
points pruned by their discs) gives the very numbers of the KD-tree search (distance.min_dist_points_to,
with and without its own pruning): the same distance, point and foot bit for bit, in single calls (near,
touching, far beyond the grid where the tree takes over, through holes) and over a whole sweep; and the
exact least distance where an edge is long."""

from __future__ import annotations

import math

import numpy as np
import pytest

from propulsor.checks.motion import Outline, Pose, rotation_matrices, sweep_pair
from propulsor.checks.motion import distance, sweep2d
from propulsor.checks.motion.nearest import grid_of, nearest_edge
from propulsor.checks.motion.poses import apply_pose

from propulsor.checks.motion import nearest


def _star(n_teeth: int, r_root: float, r_tip: float, n: int = 1200) -> np.ndarray:
    """A wavy closed loop (a gear-like body with many vertices)."""
    a = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    r = r_root + (r_tip - r_root) * 0.5 * (1.0 + np.cos(n_teeth * a))
    return np.column_stack([r * np.cos(a), r * np.sin(a)])


def _rect(x0, y0, x1, y1) -> np.ndarray:
    return np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], float)


def _same(a, b) -> bool:
    return a[0] == b[0] and a[1] == b[1] and np.asarray(a[2]).tobytes() == np.asarray(b[2]).tobytes()


@pytest.mark.parametrize("holes", [False, True])
def test_compiled_nearest_equals_the_reference_bit_for_bit(holes):
    loops = [_star(12, 20.0, 23.0)] + ([_star(5, 6.0, 7.0, 500)[::-1]] if holes else [])
    tgt = Outline(loops, 0.1)
    src = Outline([_star(9, 14.0, 17.0, 900)], 0.1)
    assert len(src.points) > 8 * distance._CHUNK  # many discs, most of them far
    g = grid_of(tgt)
    rng = np.random.default_rng(7)
    gaps = np.concatenate([rng.uniform(0.05, 6.0, 30), [1e-9, 0.0, 80.0, 400.0]])  # touching; far off the grid
    for gap in gaps:
        ang = float(rng.uniform(0, 2 * math.pi))
        M = Pose(ang, (0.0, 0.0), (23.0 + 17.0 + float(gap), float(rng.uniform(-3, 3)))).matrix()
        P = apply_pose(M, src.points)
        full = distance.min_dist_points_to(P, tgt)
        pruned = distance.min_dist_points_to(P, tgt, src)
        got = nearest_edge(P, tgt, src)
        assert _same(full, pruned) and _same(full, got), (gap, full, got)
    # a body inside the hole (holes: a point set within the target's annulus, near the inner loop)
    if holes:
        small = Outline([_star(4, 2.0, 3.0, 300)], 0.1)
        P = apply_pose(Pose(0.3, (0.0, 0.0), (0.5, 0.0)).matrix(), small.points)
        assert _same(distance.min_dist_points_to(P, tgt), nearest_edge(P, tgt, small))
    assert g.nx > 10 and g.ny > 10  # a real grid, not one cell


def test_a_compiled_sweep_equals_the_reference_sweep(monkeypatch):
    """A toothed wheel turning beside another at a varying gap (far, near and overlapping steps)."""
    A, B = [_star(12, 20.0, 23.0)], [_star(9, 14.0, 17.0, 900)]
    phi = np.linspace(0.0, 2.0 * math.pi, 24, endpoint=False)
    Mb = rotation_matrices(phi, np.column_stack([39.0 + 2.5 * np.cos(phi), np.zeros_like(phi)]))
    fast = sweep_pair(A, Pose(), B, Mb, max_segment=0.2)
    assert (fast.overlap_area > 0).any() and (fast.clearance > 1.0).any()
    monkeypatch.setattr(sweep2d, "nearest_edge", lambda P, tgt, src, cap=math.inf: distance.min_dist_points_to(P, tgt))
    slow = sweep_pair(A, Pose(), B, Mb, max_segment=0.2)
    for f in ("overlap_area", "clearance", "point_a", "point_b"):
        assert getattr(fast, f).tobytes() == getattr(slow, f).tobytes(), f


def _brute(P, tgt):
    """Least point-to-edge distance over every pair (the reference's arithmetic)."""
    pi = np.repeat(np.arange(len(P)), len(tgt.points))
    si = np.tile(np.arange(len(tgt.points)), len(P))
    d, _ = distance._point_seg(P[pi], tgt.seg_a[si], tgt.seg_b[si])
    return float(d.min())


def test_long_edges_foot_mid_edge_and_far_points():
    """Edges longer than the grid's cells (a plate 200 × 10 mm, edges not split): the nearest point is the middle
    of an edge whose ends are 100 mm away; a body far outside the grid.  The tree's search kept only points whose
    lower bound (from the vertices' annulus) was within the first vertex distance, and missed a point nearer to
    an edge (here 0.5 mm against its 0.8 mm): both now keep every point within the least vertex distance +
    half the longest edge of a vertex, and find the exact least distance."""
    tgt = Outline([np.array([[0.0, 0.0], [200.0, 0.0], [200.0, 10.0], [0.0, 10.0]])], 1000.0)
    src = Outline([np.array([[99.0, 10.3], [101.0, 10.6], [100.0, 12.0]])], 1000.0)
    for dx, dy in ((0.0, 0.0), (37.0, 0.2), (0.0, 300.0), (-400.0, -50.0)):
        P = src.points + np.array([dx, dy])
        got = nearest_edge(P, tgt, src)
        assert got[0] == _brute(P, tgt), (dx, dy, got)
        assert distance.min_dist_points_to(P, tgt, src)[0] == got[0]
    assert nearest_edge(src.points, tgt, src)[0] == pytest.approx(0.3)


def test_every_grid_level_gives_the_same_answer(monkeypatch):
    """The coarser grids (for bodies far apart, chosen from the last answer) change the work, never the
    answer: the same distance, point and foot at every level, near, through the hole and far."""
    tgt = Outline([_star(12, 20.0, 23.0), _star(5, 6.0, 7.0, 500)[::-1]], 0.1)
    src = Outline([_star(9, 14.0, 17.0, 900)], 0.1)
    small = Outline([_star(4, 2.0, 3.0, 300)], 0.1)
    cases = [(src, Pose(0.4, (0.0, 0.0), (40.0 + gap, 1.0)).matrix()) for gap in (0.0, 0.3, 4.0, 25.0, 90.0)]
    cases.append((small, Pose(0.3, (0.0, 0.0), (0.5, 0.0)).matrix()))
    for body, M in cases:
        P = apply_pose(M, body.points)
        want = distance.min_dist_points_to(P, tgt)
        for level in range(nearest.MAX_LEVEL + 1):
            monkeypatch.setattr(nearest, "_level_for", lambda o, d, level=level: level)
            assert _same(nearest_edge(P, tgt, body), want), (level, want)
    monkeypatch.undo()
    assert nearest._level_for(tgt, 0.0) == 0 and nearest._level_for(tgt, 1e6) == nearest.MAX_LEVEL
    assert grid_of(tgt, 2).h == pytest.approx(9.0 * grid_of(tgt).h)


def _turning(steps: int, step_deg: float):
    """A toothed wheel turning beside another by small steps, the gap closing and opening (0.05 .. 1.5 mm)."""
    tgt = Outline([_star(12, 20.0, 23.0)], 0.1)
    src = Outline([_star(9, 14.0, 17.0, 900)], 0.1)
    ang = np.radians(step_deg) * np.arange(steps)
    gap = 0.05 + 1.45 * 0.5 * (1.0 + np.cos(np.linspace(0.0, 3.0 * math.pi, steps)))
    return tgt, src, [Pose(a, (0.0, 0.0), (40.0 + g, 0.3)).matrix() for a, g in zip(ang, gap)]


def test_a_remembering_search_answers_as_a_fresh_one_with_fewer_searches():
    """Step after step of a turning wheel, the search that remembers (the last answer's point, each point's and
    run's nearest vertex found farther than the bound) gives the answer of a search with no memory, bit for bit,
    and searches under 65 % as many points (59 % here)."""
    tgt, src, poses = _turning(120, 0.25)
    fresh_tgt = Outline([_star(12, 20.0, 23.0)], 0.1)
    fresh_searches = 0
    for M in poses:
        P = apply_pose(M, src.points)
        got = nearest_edge(P, tgt, src)
        fresh_tgt.__dict__.pop("_nearest_memory", None)
        want = nearest_edge(P, fresh_tgt, src)
        fresh_searches += int(fresh_tgt._nearest_memory[id(src)].searches[0])
        assert _same(got, want), (M, got, want)
        assert _same(got, distance.min_dist_points_to(P, tgt)), M
    searches = int(tgt._nearest_memory[id(src)].searches[0])
    assert 0 < searches < 0.65 * fresh_searches, (searches, fresh_searches)


def test_a_remembered_point_that_moved_is_searched_again():
    """A point found more than 3.25 mm from the target (the first search's bound; it is 4 mm off), then moved
    3.9 mm towards it: its memory less its move no longer shows it farther than the bound (3 mm, the point of
    the last answer), so it is searched again and found the nearest."""
    tgt = Outline([_rect(0.0, 0.0, 10.0, 10.0)], 0.5)
    src = Outline([np.array([[13.0, 5.0], [13.5, 5.2], [13.2, 5.6]]), np.array([[5.0, 14.0], [5.5, 14.2], [5.2, 14.6]])],
                  0.5)
    P = src.points.copy()
    d0, i0, _ = nearest_edge(P, tgt, src)
    assert d0 == pytest.approx(3.0, abs=1e-12) and P[i0].tolist() == [13.0, 5.0]
    P[src.loop_id == 1] -= (0.0, 3.9)  # the second triangle 0.1 mm from the top
    d1, i1, q1 = nearest_edge(P, tgt, src)
    assert d1 == pytest.approx(0.1, abs=1e-12) and src.loop_id[i1] == 1
    assert _same((d1, i1, q1), distance.min_dist_points_to(P, tgt))


def test_a_new_source_at_a_freed_ones_address_gets_a_new_memory():
    """The memory is kept per source object: one left under the address a new source now has (a freed outline's)
    is not used, and the memories of freed sources are dropped."""
    tgt = Outline([_star(12, 20.0, 23.0)], 0.1)
    a = Outline([_star(9, 14.0, 17.0, 900)], 0.1)
    b = Outline([_star(9, 14.0, 17.0, 900)], 0.1)
    M = Pose(0.2, (0.0, 0.0), (40.2, 0.0)).matrix()
    nearest_edge(apply_pose(M, a.points), tgt, a)
    stale = tgt._nearest_memory[id(a)]
    stale.low_pt[:] = 1e9  # a memory that would skip every point
    tgt._nearest_memory[id(b)] = stale  # as if b were at a's address
    P = apply_pose(M, b.points)
    assert _same(nearest_edge(P, tgt, b), distance.min_dist_points_to(P, tgt))
    assert tgt._nearest_memory[id(b)] is not stale and tgt._nearest_memory[id(b)].src() is b
    key = id(a)
    del a, stale
    import gc
    gc.collect()
    c = Outline([_rect(-1.0, -1.0, 1.0, 1.0)], 0.1)
    nearest_edge(c.points + (30.0, 0.0), tgt, c)
    assert key not in tgt._nearest_memory or tgt._nearest_memory[key].src() is not None


def test_a_search_that_found_nothing_remembers_only_the_rings_it_searched():
    """A frame (80 x 40 mm, hole 6..74 x 6..34; grid cells of 4 mm) and two small triangles in the hole: one 0.1 mm
    below the hole's top, one 6.1 mm left of its right side, near the right edge of its cell.  Searched within
    0.1 mm (0.35 mm), the second finds no vertex in the two rings of cells about it and remembers its nearest
    vertex at least 4 mm off (the next ring's distance: one cell), not 8.  Moved 6.05 mm right (0.05 mm from the
    side) it is searched again and is the nearest."""
    frame = [_rect(0.0, 0.0, 80.0, 40.0), _rect(6.0, 6.0, 74.0, 34.0)[::-1]]
    tgt = Outline(frame, 0.5)
    assert grid_of(tgt).h == 4.0
    t1 = np.array([[40.0, 33.9], [39.7, 33.6], [40.3, 33.6]])
    t2 = np.array([[67.9, 20.0], [67.6, 19.7], [67.6, 20.3]])
    src = Outline([t1, t2], 0.5)
    d0, i0, _ = nearest_edge(src.points, tgt, src)
    assert d0 == pytest.approx(0.1, abs=1e-9) and src.loop_id[i0] == 0
    mem = tgt._nearest_memory[id(src)]
    k = int(np.nonzero(np.all(src.points == (67.9, 20.0), axis=1))[0][0])
    assert mem.low_pt[k] == 4.0 and not mem.exact[k]
    P = src.points + np.where(src.loop_id[:, None] == 1, (6.05, 0.0), (0.0, 0.0))
    d1, i1, q1 = nearest_edge(P, tgt, src)
    assert d1 == pytest.approx(0.05, abs=1e-9) and i1 == k
    assert _same((d1, i1, q1), distance.min_dist_points_to(P, tgt))


def test_a_capped_search_finds_the_answer_within_the_cap_and_nothing_beyond():
    """``nearest_edge(..., cap)`` (the sweeps search the body of more vertices only for an answer within the other
    way's, its first pass left out): the uncapped answer bit for bit where it is within the cap (the cap equal to
    it, a little above, far above; wavy outlines, so no two point-edge pairs tie at the least distance, where the
    pair taken can differ: nearest._nearest_edge), none (inf, -1) where the cap is below it, near and touching,
    whatever the grid level the last answer chose; bodies more than FAR_CELLS grid cells apart get the KD-tree's
    whole answer, cap or not."""
    tgt = Outline([_star(12, 20.0, 23.0), _star(5, 6.0, 7.0, 500)[::-1]], 0.1)
    rng = np.random.default_rng(11)
    seen = {"within": 0, "none": 0}
    for gap in np.concatenate([rng.uniform(0.02, 1.0, 24), [0.0, 60.0]]):
        src = Outline([_star(9, 14.0, 17.0, 900)], 0.1)  # a new source each time: no memory between the gaps
        M = Pose(float(rng.uniform(0, 2 * math.pi)), (0.0, 0.0),
                 (40.0 + float(gap), float(rng.uniform(-3, 3)))).matrix()
        P = apply_pose(M, src.points)
        want = distance.min_dist_points_to(P, tgt)
        d = want[0]
        # the grid's search (at every level) where the least lower bound of the vertices' annulus is within
        # FAR_CELLS of its finest cells; the tree's beyond that (at the finest level)
        lb_min = float(np.min(np.hypot(P[:, 0] - tgt.center[0], P[:, 1] - tgt.center[1]))) - tgt.radius
        grid = lb_min < nearest.FAR_CELLS * grid_of(tgt).h
        for cap in (d, d * (1.0 + 1e-9) + 1e-12, d + 2.0, 10.0 * d + 1.0):
            got = nearest_edge(P, tgt, src, cap)
            assert _same(want, got), (gap, cap, want, got)
            seen["within"] += 1
        if d > 1e-9:
            for cap in (d * (1.0 - 1e-9), 0.5 * d, 0.0):
                got = nearest_edge(P, tgt, src, cap)
                if grid:
                    assert got[0] == math.inf and got[1] == -1 and np.isnan(got[2]).all(), (gap, cap, got)
                    seen["none"] += 1
                else:
                    assert _same(want, got) or got[1] == -1, (gap, cap, got)
    assert seen["within"] == 104 and seen["none"] >= 30


def test_a_sweep_with_one_way_capped_equals_both_ways_searched_whole(monkeypatch):
    """The sweep's least distance with the second search capped at the first's answer (sweep2d._boundary_distance
    and the compiled steps) gives every clearance and closest point of the sweep whose searches are both whole: a
    wheel of fewer vertices and one of more, each as the first body."""
    small, big = _star(12, 20.0, 23.0, 700), _star(9, 14.0, 17.0, 2600)
    phi = np.linspace(0.0, 2.0 * math.pi, 40, endpoint=False)
    Mb = rotation_matrices(phi, np.column_stack([40.8 + 0.6 * np.cos(phi), 0.3 * np.sin(phi)]))
    whole = nearest.nearest_edge
    for A, B in ((small, big), (big, small)):
        capped = sweep_pair([A], Pose(), [B], Mb, max_segment=0.2)  # the compiled steps
        monkeypatch.setattr(sweep2d, "apart_steps", lambda A, B, rba, rab, Ma, Mb, k0, *rest: k0)
        stepwise = sweep_pair([A], Pose(), [B], Mb, max_segment=0.2)  # _boundary_distance at each step
        monkeypatch.setattr(sweep2d, "nearest_edge", lambda P, tgt, src, cap=math.inf: whole(P, tgt, src))
        ref = sweep_pair([A], Pose(), [B], Mb, max_segment=0.2)
        monkeypatch.undo()
        assert (ref.clearance > 0).all() and ref.clearance.min() < 0.5
        for f in ("overlap_area", "clearance", "point_a", "point_b"):
            assert getattr(capped, f).tobytes() == getattr(ref, f).tobytes(), f
            assert getattr(stepwise, f).tobytes() == getattr(ref, f).tobytes(), f


def test_the_nearest_vertex_within_a_bound_is_the_least_distance_of_all_vertices():
    """nearest._nearest_vertex (the contact search's sorting of candidates, the sweeps' first bound) against the least
    distance over every vertex (the same arithmetic, sqrt(dx² + dy²)): equal bit for bit where it is within the bound,
    inf where it is not; at points on the outline, near it, inside, beyond the grid, on cell borders, with bounds from 0
    to inf."""
    o = Outline([_star(12, 20.0, 23.0), _star(5, 6.0, 7.0, 500)[::-1]], 0.1)
    g = grid_of(o)
    V = o.points
    rng = np.random.default_rng(7)
    border = np.column_stack([g.origin[0] + g.h * rng.integers(0, g.nx, 200), rng.uniform(-25, 25, 200)])
    P = np.vstack([V[rng.integers(0, len(V), 300)] + rng.normal(0.0, 0.05, (300, 2)), V[:50],
                   rng.uniform(-30.0, 30.0, (400, 2)), rng.uniform(-90.0, 90.0, (100, 2)), border])
    n_inf = n_found = 0
    for px, py in P:
        exact = float(np.min(np.sqrt((px - V[:, 0]) ** 2 + (py - V[:, 1]) ** 2)))
        for bound in (0.0, 0.01, 0.2, 0.5 * g.h, 2.5 * g.h, exact, np.nextafter(exact, 0.0), 40.0, np.inf):
            got = nearest._nearest_vertex(px, py, V, g.origin[0], g.origin[1], g.h, g.nx, g.ny, g.start, g.items,
                                          bound)
            want = exact if exact <= bound else np.inf
            assert got == want, (px, py, bound)
            n_inf += got == np.inf
            n_found += got < np.inf
    assert n_inf > 100 and n_found > 100


def test_each_points_distance_is_the_least_over_every_edge_bit_for_bit():
    """``nearest.dist_each`` (one compiled loop on the vertex grid) gives each point the least of the reference's
    point-to-edge distances over every edge, the same float: points on, near and far from a wavy loop with a hole
    (short edges), and near a plate whose nearest points lie mid-edge, 100 mm from the edge's ends (long edges: an
    edge counts where either end lies within the nearest vertex's distance plus half the longest edge)."""
    rng = np.random.default_rng(7)
    star = Outline([_star(12, 20.0, 23.0, 900), _star(5, 6.0, 7.0, 300)[::-1]], 0.2)
    plate = Outline([_rect(0.0, 0.0, 200.0, 10.0)], 1000.0)
    mids = np.array([[100.0, -0.5], [100.0, 10.3], [-0.4, 5.0], [200.2, 5.0], [150.0, 5.0], [100.0, 3.0]])
    cases = [(star, star.points[rng.integers(0, len(star.points), 150)] + rng.normal(0.0, s, (150, 2)))
             for s in (0.0, 0.01, 1.0, 30.0)]
    cases.append((plate, np.vstack([mids, rng.uniform(-50.0, 250.0, (200, 2))])))
    # a long edge under a wavy top of 0.1 mm edges (cells of about 1.6 mm): below it the nearest vertex is one of the
    # top's, 4 mm off, the nearest edge the long one, 1 mm off, whose ends are 10 and 90 mm away (found from its end
    # within reach, the edge ending there at one side, starting there at the other), in either direction of the loop
    x = np.linspace(100.0, 0.0, 1001)
    top = np.column_stack([x, 3.0 + 0.2 * np.sin(x)])
    for loop in (np.vstack([[[0.0, 0.0], [100.0, 0.0]], top]), np.vstack([[[0.0, 0.0], [100.0, 0.0]], top])[::-1]):
        under = Outline([loop], 1000.0)
        P = np.array([[50.0, -1.0], [10.0, -1.0], [90.0, -1.0], [50.0, 1.2], [-2.0, 1.0], [50.0, 30.0]])
        cases.append((under, P))
        assert nearest.dist_each(P[:3], under).tolist() == [1.0, 1.0, 1.0]
    for tgt, P in cases:
        m = len(tgt.points)
        d, _ = distance._point_seg(np.repeat(P, m, axis=0), np.tile(tgt.seg_a, (len(P), 1)),
                                   np.tile(tgt.seg_b, (len(P), 1)))
        got = nearest.dist_each(P, tgt)
        assert got.tobytes() == d.reshape(len(P), m).min(axis=1).tobytes()
        assert got.tobytes() == distance.dist_each_point(P, tgt).tobytes()  # the reference's own search too
    assert nearest.dist_each(mids[:1], plate).tolist() == [0.5] and nearest.dist_each(np.empty((0, 2)), plate).size == 0


def _circle(r: float, n: int, centre=(0.0, 0.0), phase: float = 0.0) -> np.ndarray:
    a = phase + np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    return np.column_stack([centre[0] + r * np.cos(a), centre[1] + r * np.sin(a)])


def test_a_pin_turning_in_a_bore_gives_the_reference_at_every_level(monkeypatch):
    """A pin (Ø 55, 370 vertices) turning in a gear's bore (Ø 110, 520 vertices; a final drive's planet on its pin):
    every vertex of either body is about equally near the other (27.5 mm), so the searches' rings and discs reach far
    and the cells they skip (those wholly beyond the best distance found, or the reach of the second pass) decide
    nearly every answer.  Both ways, at every grid level: the reference's distance, point and foot, bit for bit."""
    planet = Outline([_star(30, 72.0, 78.0, 3000), _circle(55.0, 520)[::-1]], 0.1)
    pin = Outline([_circle(27.5, 370, (0.013, -0.021), 0.1)], 0.1)
    n = 0
    for ang in np.radians([0.0, 0.37, 11.0, 97.3]):
        M = Pose(float(ang), (0.013, -0.021), (0.0, 0.0)).matrix()
        M_back = Pose(-float(ang), (0.013, -0.021), (0.0, 0.0)).matrix()
        P_pin, P_planet = apply_pose(M, pin.points), apply_pose(M_back, planet.points)
        for tgt, src, P in ((planet, pin, P_pin), (pin, planet, P_planet)):
            want = distance.min_dist_points_to(P, tgt)
            assert 27.4 < want[0] < 27.6
            for level in range(nearest.MAX_LEVEL + 1):
                monkeypatch.setattr(nearest, "_level_for", lambda o, d, level=level: level)
                got = nearest_edge(P, tgt, src)
                assert _same(got, want), (math.degrees(ang), level, got, want)
                n += 1
            monkeypatch.undo()
    assert n == 4 * 2 * (nearest.MAX_LEVEL + 1)


def test_an_edge_far_longer_than_the_cells_found_from_an_end_beyond_the_nearest_vertex(monkeypatch):
    """A long edge (100 mm) under a wavy top of 0.1 mm edges (cells of about 1.6 mm): below its middle the nearest
    vertex is one of the top's, 4 mm off, the nearest edge the long one, 1 mm off, whose ends are 10 and 90 mm away:
    the second pass reaches them (the cells within the nearest vertex's distance plus half the longest edge), at every
    grid level, in either direction of the loop: the reference's answer, bit for bit."""
    x = np.linspace(100.0, 0.0, 1001)
    top = np.column_stack([x, 3.0 + 0.2 * np.sin(x)])
    base = np.vstack([[[0.0, 0.0], [100.0, 0.0]], top])
    for loop in (base, base[::-1]):
        tgt = Outline([loop], 1000.0)
        for pt in ((50.0, -1.0), (10.0, -1.0), (90.0, -1.0)):
            src = Outline([np.array(pt) + np.array([[0.0, 0.0], [0.3, -0.2], [-0.3, -0.2]])], 1000.0)
            want = distance.min_dist_points_to(src.points, tgt)
            assert want[0] == pytest.approx(1.0)
            for level in range(nearest.MAX_LEVEL + 1):
                monkeypatch.setattr(nearest, "_level_for", lambda o, d, level=level: level)
                assert _same(nearest_edge(src.points, tgt, src), want), (pt, level)
            monkeypatch.undo()
    assert grid_of(Outline([base], 1000.0)).h < 2.0


def test_the_nearest_vertex_searchs_lower_bound_never_exceeds_the_distance():
    """``nearest._nearest_vertex_low``'s second value (what a search remembers of a point: no vertex nearer) is at most
    the least distance over every vertex, and that distance itself where it lies within the bound: on a grid of a few
    cells (whose rings a search exhausts before any is farther than the bound) and on a fine one, at bounds from 0 to
    inf, for points inside, near and far."""
    rng = np.random.default_rng(5)
    for o in (Outline([_rect(0.0, 0.0, 8.0, 5.0)], 1000.0), Outline([_star(12, 20.0, 23.0), _circle(6.0, 200)[::-1]],
                                                                      0.1)):
        g = grid_of(o)
        V = o.points
        P = np.vstack([rng.uniform(-30.0, 30.0, (300, 2)), V[rng.integers(0, len(V), 50)] + rng.normal(0, 0.1, (50, 2)),
                       rng.uniform(-300.0, 300.0, (50, 2))])
        for px, py in P:
            exact = float(np.min(np.sqrt((px - V[:, 0]) ** 2 + (py - V[:, 1]) ** 2)))
            for bound in (0.0, 0.3, 2.0, 0.5 * exact, exact, 2.0 * exact, np.inf):
                d, low = nearest._nearest_vertex_low(px, py, V, g.origin[0], g.origin[1], g.h, g.nx, g.ny, g.start,
                                                     g.items, bound)
                assert low <= exact, (px, py, bound, low, exact)
                assert d == (exact if exact <= bound else np.inf)


@pytest.mark.parametrize("nearer_by", [5e-4, 5e-10])
def test_a_vertex_on_its_cells_border_just_nearer_than_the_best_found_so_far(nearer_by):
    """Cells of 4 mm: the point (7.7, 4) finds a vertex of its own cell 0.3 mm + `nearer_by` off first, then the ring
    about it holds the cell whose corner is a vertex 0.3 mm off, the cell's box as near as the vertex: the search skips
    a cell only where its box (widened by the rounding's margin) lies beyond the best found, so it takes that vertex."""
    from propulsor.checks.motion.nearest import VertexGrid

    px, py = 7.7, 4.0
    V = np.array([[0.0, 0.0], [8.0, 4.0], [px - 0.3 - nearer_by, 4.0], [20.0, 20.0]])
    g = VertexGrid(V, np.roll(V, -1, axis=0), np.full(len(V), 0.5))
    assert g.h == 4.0 and tuple(g.origin) == (0.0, 0.0)
    exact = float(np.min(np.sqrt((px - V[:, 0]) ** 2 + (py - V[:, 1]) ** 2)))
    assert exact == 8.0 - px
    d, low = nearest._nearest_vertex_low(px, py, V, g.origin[0], g.origin[1], g.h, g.nx, g.ny, g.start, g.items,
                                         np.inf)
    assert d == exact and low == exact
