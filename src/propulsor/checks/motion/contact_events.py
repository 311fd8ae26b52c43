"""The loaded contact of a gear pair on its finished outlines, resolved by contact events.

The driver is placed at the law's angle theta(phi); the driven wheel is turned from the law's position until its
outline first touches the driver's (drive: turned back, the driver's loaded flanks pushing; reverse: turned on,
the other flanks, as when the driver turns the other way).  Each contact is a vertex of one polyline meeting an
edge of the other (:func:`.backlash._rot_hits`, exact for the polylines); its *state* is

* the contact kind: ``flank`` (neither outline at a corner there), ``driver tip corner`` / ``driven tip corner``
  (the contact at a convex corner of that outline: the tip land meets the flank), ``driver root corner`` /
  ``driven root corner`` (a concave corner);
* the tooth of each wheel it lies on (nearest tooth centre by polar angle in the wheel's body frame).

The transmission is sampled every ``step`` of driver angle (``policy.CONTACT_STEP_DRIVER_DEG``), and every interval
whose ends are in different states is bisected down to ``h_min`` of driven angle
(``policy.CONTACT_EVENT_STEP_RAD``), so that each change of the tooth pair or the contact kind is located to
``h_min`` and a stretch in another state that starts or ends between two samples is found when at least 2 ``h_min``
wide.  A sample is found from the previous one's contact: the driven wheel is placed a little on the free side of it
and turned through a small window (a full search from the law's position when that finds nothing), which keeps one
measurement under a millisecond; the nearer part of that window (``policy.CONTACT_TRACK_FIRST_WINDOW`` margins of
its two) is searched first, the whole only where the part holds no contact (a hit within the part is the first
within the whole: the same contact, fewer vertices tested).  Before any per-vertex work the search leaves out the
window's vertices that cannot reach the mate within the window: runs of ``policy.CONTACT_PRUNE_CHUNK`` vertices by
their bounding circle, then the rest one by one, against a lower bound of the distance to the mate's outline read
from a grid (:func:`distance_field`); the first hit is the same, bit for bit.  The sampled run, and the bisection of
each change of state, reuse the vertices that can reach the mate at one pose over the poses after it while that
provably holds (:mod:`.contact_reuse`): the same hits again, about half the search's time.

Driven speed over the law's at the same driver angle: (d phi_actual / d theta) / (d phi / d theta) =
1 + d te / d phi, te = phi_actual - phi (the chord slopes of the resolved samples: piecewise constant).
A *step* is the change of that speed across a change of state (the last interval of the one state against the
first of the next, each at least ``step_window`` wide): what the mate feels as an impact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ... import policy
from .contact_kernels import (DRIVE, REVERSE, _first_hit_pruned, _least, _nearest_tooth_nb, _pair_hits,  # noqa: F401
                              _pair_hits_pruned, _pruned_window, _side_hits, _window_bounds, _window_nb)
from .backlash import _target
from .contact_reuse import add_slots, new_caches, seed_slots
from .contact_track import track
from ...planar import box, norms
from .outlines import Outline

__all__ = ["KINDS", "PairOutlines", "ContactLaw", "Stretch", "resolve_contact", "contact_law", "runs"]

#: contact kinds, by code
KINDS = ("flank", "driver tip corner", "driven tip corner", "driver root corner", "driven root corner")
#: positions measured in one compiled run between two progress reports (about 50 ms)
_TRACK_RUN = 512


def _turning(o: Outline) -> np.ndarray:
    """Turning angle (rad, + convex for material on the left) of the outline at each vertex."""
    a = o.seg_b - o.seg_a
    ang = np.arctan2(a[:, 1], a[:, 0])
    return (ang - ang[o.prev] + math.pi) % (2 * math.pi) - math.pi


def _sorted_by_angle(o: Outline, r_min: float):
    """Indices of the vertices farther than r_min from the body axis, sorted by polar angle, and the angles."""
    r = norms(o.points)
    keep = np.nonzero(r > r_min)[0]
    a = np.arctan2(o.points[keep, 1], o.points[keep, 0])
    order = np.argsort(a, kind="stable")
    return keep[order], a[order]


def distance_field(o: Outline, cells: int = policy.CONTACT_FIELD_CELLS) -> tuple:
    """A lower bound of the distance from a point to the outline's boundary, on a grid over its body frame:
    ``(x0, y0, h, nx, ny, values)``, ``values[ix * ny + iy]`` bounding every point of cell (ix, iy) from below.
    The Euclidean distance transform of the cells that hold a vertex (scipy.ndimage) gives the distance between
    cell centres; less a cell's diagonal (the point and the vertex each lie within half of it of their cells'
    centres) and half the longest edge (a boundary point lies within that of a vertex), at least 0.  About
    ``cells`` cells along the longer side of the bounding box, two more on each side.  Cached on the outline."""
    f = getattr(o, "_distance_field", None)
    if f is None:
        from scipy.ndimage import distance_transform_edt

        lo, hi = box(o.points)
        h = float(np.max(hi - lo)) / cells
        lo = lo - 2.0 * h
        nx, ny = (int(math.ceil(float(hi[k] + 2.0 * h - lo[k]) / h)) for k in (0, 1))
        free = np.ones((nx, ny), bool)
        ix = np.clip(np.floor((o.points[:, 0] - lo[0]) / h).astype(np.int64), 0, nx - 1)
        iy = np.clip(np.floor((o.points[:, 1] - lo[1]) / h).astype(np.int64), 0, ny - 1)
        free[ix, iy] = False
        d = distance_transform_edt(free) * h
        values = np.maximum(d - h * math.sqrt(2.0) - o.half_len - 1e-9, 0.0).ravel()
        f = o._distance_field = (float(lo[0]), float(lo[1]), h, nx, ny, np.ascontiguousarray(values, np.float64))
    return f


def _chunks(points: np.ndarray, order: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Bounding circles (centres, radii) of the runs of ``size`` vertices in ``order`` (the last run shorter)."""
    P = points[order]
    m = -(-len(P) // size)
    if m == 0:
        return np.zeros((0, 2)), np.zeros(0)
    Q = np.concatenate([P, np.repeat(P[-1:], m * size - len(P), axis=0)]).reshape(m, size, 2)
    cc = 0.5 * (Q.min(axis=1) + Q.max(axis=1))
    cr = np.sqrt(np.max(np.sum((Q - cc[:, None, :]) ** 2, axis=2), axis=1)) + 1e-9
    return cc, cr


def _rot(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s], [s, c]])


class PairOutlines:
    """A pair's outer outlines prepared for contact events.

    ``driver``, ``driven``: :class:`.outlines.Outline` in their body frames (axis at the origin); the driven
    wheel's axis is the assembly origin, the driver's at (L, 0); at phase phi the driven wheel is turned by
    -phi and the driver by +theta (an external pair).  ``driver_teeth``, ``driven_teeth``: body polar angles
    of the tooth centres (rad), to name the teeth in contact.  ``corner_deg``: a vertex whose outline turns by
    more than this is a corner."""

    def __init__(self, driver: Outline, driven: Outline, L: float, driver_teeth, driven_teeth,
                 corner_deg: float = policy.CONTACT_CORNER_TURN_DEG):
        self.drv, self.dvn, self.L = driver, driven, float(L)
        self.driver_teeth = np.asarray(driver_teeth, float)
        self.driven_teeth = np.asarray(driven_teeth, float)
        lim = math.radians(corner_deg)
        self.turn_drv, self.turn_dvn = _turning(driver), _turning(driven)
        self.corner_drv = np.abs(self.turn_drv) > lim
        self.corner_dvn = np.abs(self.turn_dvn) > lim
        r_drv, r_dvn = norms(driver.points), norms(driven.points)
        R1, R2 = float(r_drv.max()), float(r_dvn.max())
        self.o1, self.a1 = _sorted_by_angle(driven, self.L - R1 - 1.0)
        self.o2, self.a2 = _sorted_by_angle(driver, self.L - R2 - 1.0)
        # half-widths (about the line of centres) of the body angles that can come within reach of the mate,
        # widened by the largest free rotation searched
        self.R1, self.R2 = R1, R2
        self.hw_dvn = self._half_width(r_dvn, R1)
        self.hw_drv = self._half_width(r_drv, R2)

    def _half_width(self, r: np.ndarray, R_mate: float) -> float:
        """Largest angle from the line of centres of a point at radius r (of these) within R_mate + 1 of
        the mate's axis at distance L."""
        L = self.L
        rr = np.linspace(max(float(r.min()), 1e-3), float(r.max()), 64)
        c = np.clip((L * L + rr * rr - (R_mate + 1.0) ** 2) / (2 * L * rr), -1.0, 1.0)
        return float(np.max(np.arccos(c))) + 0.02

    def _target(self, o: Outline) -> tuple:
        """What the compiled hit search needs of a target outline: the rotation hits' (:func:`.backlash._target`: its
        vertices, edges and vertex grid) and its annulus."""
        return _target(o) + (float(o.center[0]), float(o.center[1]), float(o.radius), float(o.r_min))

    @property
    def _kernel_args(self) -> tuple:
        k = self.__dict__.get("_kargs")
        if k is None:
            k = self.__dict__["_kargs"] = (
                self.L, np.ascontiguousarray(self.dvn.points, np.float64), self.o1, self.a1, float(self.hw_dvn),
                np.ascontiguousarray(self.drv.points, np.float64), self.o2, self.a2, float(self.hw_drv),
                float(self.R1), float(self.R2)) + self._target(self.drv) + self._target(self.dvn)
        return k

    @property
    def _prune_args(self) -> tuple:
        """What the pruned hit search adds: the runs' bounding circles of both windows and both distance fields."""
        k = self.__dict__.get("_pargs")
        if k is None:
            size = policy.CONTACT_PRUNE_CHUNK
            cc1, cr1 = _chunks(self.dvn.points, self.o1, size)
            cc2, cr2 = _chunks(self.drv.points, self.o2, size)
            k = self.__dict__["_pargs"] = ((size, cc1, cr1, cc2, cr2) + distance_field(self.drv)
                                           + distance_field(self.dvn))
        return k

    def _all_hits(self, phi_a: float, theta: float, sign: float, w: float):
        """Every hit within w when the driven wheel, at actual angle phi_a, turns by sign (+1: back, the drive
        flanks): (i1, d1, e1, t1) of the driven vertices on driver edges and (i2, d2, e2, t2) of the driver
        vertices on driven edges (vertex, turn to the hit, edge, place on the edge; inf where none).  Compiled:
        :func:`_pair_hits`."""
        i1, d1, e1, t1, i2, d2, e2, t2 = _pair_hits(float(phi_a), float(theta), float(sign), float(w),
                                                    *self._kernel_args)
        return (i1, d1, e1, t1), (i2, d2, e2, t2)

    def hits(self, phi_a: float, theta: float, sign: float, w: float):
        """:meth:`_all_hits` less the vertices that cannot reach the mate within w (compiled:
        :func:`.contact_kernels._pair_hits_pruned`): the same finite hits in the same order, fewer of the others."""
        ka = self._kernel_args
        i1, d1, e1, t1, i2, d2, e2, t2 = _pair_hits_pruned(float(phi_a), float(theta), float(sign), float(w),
                                                           *ka[:11], *self._prune_args, *ka[11:])
        return (i1, d1, e1, t1), (i2, d2, e2, t2)


@dataclass(frozen=True)
class Stretch:
    """A stretch of the cycle whose driven speed departs from the law's or whose contact is on a corner."""

    theta_from_deg: float
    theta_to_deg: float
    phi_from_rad: float
    phi_to_rad: float
    kinds: tuple
    driver_teeth: tuple
    driven_teeth: tuple
    speed_min: float   #: least driven speed over the law's in the stretch
    speed_max: float


@dataclass
class ContactLaw:
    """The resolved loaded contact of one direction over a span of the law (arrays over the samples, sorted)."""

    direction: int
    phi: np.ndarray
    theta: np.ndarray
    te: np.ndarray
    kind: np.ndarray
    driver_tooth: np.ndarray
    driven_tooth: np.ndarray
    evaluations: int
    step_window: float = field(default=policy.CONTACT_STEP_WINDOW_RAD)

    @property
    def name(self) -> str:
        return "drive" if self.direction == DRIVE else "reverse"

    @property
    def span(self) -> float:
        """The law's angle resolved, first sample to last (rad)."""
        return float(self.phi[-1] - self.phi[0])

    @property
    def ok(self) -> np.ndarray:
        return np.isfinite(self.te)

    def _state(self) -> np.ndarray:
        """(kind, driver tooth, driven tooth) of every sample (computed once: the samples never change)."""
        st = self.__dict__.get("_state_rows")
        if st is None:
            st = self.__dict__["_state_rows"] = np.stack([self.kind, self.driver_tooth, self.driven_tooth], axis=1)
        return st

    @property
    def slope(self) -> np.ndarray:
        """Chord slope d te / d phi of every interval between neighbouring samples."""
        return np.diff(self.te) / np.diff(self.phi)

    @property
    def speed(self) -> np.ndarray:
        """Driven speed over the law's at the same driver angle on every interval: 1 + d te / d phi."""
        return 1.0 + self.slope

    @property
    def speed_min(self) -> float:
        return float(np.nanmin(self.speed))

    @property
    def speed_max(self) -> float:
        return float(np.nanmax(self.speed))

    @property
    def te_pp(self) -> float:
        te = self.te[self.ok]
        return float(np.ptp(te)) if len(te) else math.nan

    @property
    def edge_share(self) -> float:
        """Share of the driver's turning over the span with the contact on a corner (intervals whose ends are
        both on a corner; a change interval counts half to each side)."""
        dth = np.diff(self.theta)
        k0, k1 = self.kind[:-1] != 0, self.kind[1:] != 0
        w = 0.5 * (k0.astype(float) + k1.astype(float))
        return float(np.sum(w * dth) / np.sum(dth))

    def events(self) -> list[tuple[float, float, float, tuple, tuple]]:
        """Every change of state: (phi, speed before, speed after, state before, state after); the speeds are
        the chord slopes over at least ``step_window`` of driven angle on each side within one state (computed
        once)."""
        ev = self.__dict__.get("_events")
        if ev is None:
            ev = self.__dict__["_events"] = self._find_events()
        return list(ev)

    def _find_events(self) -> list[tuple[float, float, float, tuple, tuple]]:
        st = self._state()
        out = []
        change = np.nonzero(np.any(st[1:] != st[:-1], axis=1))[0]
        # the run of equal states each sample lies in (a new run at every change): a walk from a sample stays in its
        # state exactly as long as it stays in its run
        run = np.zeros(len(st), np.int64)
        run[change + 1] = 1
        run = np.cumsum(run).tolist()
        for i in change.tolist():
            before = self._side_speed(i, -1, run)
            after = self._side_speed(i + 1, 1, run)
            if before is None or after is None:
                continue
            out.append((float(0.5 * (self.phi[i] + self.phi[i + 1])), before, after,
                        tuple(int(x) for x in st[i]), tuple(int(x) for x in st[i + 1])))
        return out

    def _side_speed(self, j: int, way: int, run: list) -> float | None:
        """Chord speed from sample j over at least step_window within its state (way -1: backwards); ``run``: the run
        of equal states of every sample (:meth:`_find_events`)."""
        k = j
        n = len(self.phi)
        r = run[j]
        while 0 <= k + way < n and run[k + way] == r and abs(self.phi[k + way] - self.phi[j]) < self.step_window:
            k += way
        if 0 <= k + way < n and run[k + way] == r:
            k += way
        if k == j:
            return None
        a, b = (k, j) if way < 0 else (j, k)
        if not (math.isfinite(self.te[a]) and math.isfinite(self.te[b])):
            return None
        return 1.0 + (self.te[b] - self.te[a]) / (self.phi[b] - self.phi[a])

    @property
    def step_max(self) -> float:
        """Largest change of the driven speed (over the law's) across a change of contact state."""
        ev = self.events()
        return max((abs(b - a) for _, a, b, _, _ in ev), default=0.0)

    def step_at(self) -> tuple[float, float] | None:
        """(phi, driver angle) of the largest step."""
        ev = self.events()
        if not ev:
            return None
        k = int(np.argmax([abs(b - a) for _, a, b, _, _ in ev]))
        phi = ev[k][0]
        return phi, float(np.interp(phi, self.phi, self.theta))

    def stretches(self, speed_tol: float = policy.CONTACT_STRETCH_SPEED_TOL) -> list[Stretch]:
        """The runs of intervals whose speed departs from the law's by more than ``speed_tol`` or whose contact
        is on a corner, merged when they touch."""
        sp = self.speed
        bad = (np.abs(sp - 1.0) > speed_tol) | (self.kind[:-1] != 0) | (self.kind[1:] != 0)
        bad &= np.isfinite(sp)
        out = []
        for i, j in runs(bad):
            sl = slice(i, j + 2)
            kinds = tuple(sorted({KINDS[k] for k in self.kind[sl] if k >= 0}))
            out.append(Stretch(math.degrees(self.theta[i]), math.degrees(self.theta[j + 1]), float(self.phi[i]),
                               float(self.phi[j + 1]), kinds, tuple(sorted({int(t) for t in self.driver_tooth[sl]})),
                               tuple(sorted({int(t) for t in self.driven_tooth[sl]})), float(np.min(sp[i:j + 1])),
                               float(np.max(sp[i:j + 1]))))
        return out

    def corner_run_max(self) -> tuple[float, float]:
        """(deg of driver, its start in deg) of the longest run of consecutive samples with the load on a corner;
        a run reaches half-way to the neighbouring samples on either side."""
        best, at = 0.0, math.nan
        n = len(self.kind)
        for i, j in runs((self.kind > 0) & np.isfinite(self.te)):
            lo = self.theta[i - 1] if i > 0 else self.theta[i]
            hi = self.theta[j + 1] if j + 1 < n else self.theta[j]
            run = math.degrees(0.5 * ((self.theta[i] - lo) + (hi - self.theta[j])) + (self.theta[j] - self.theta[i]))
            if run > best:
                best, at = run, math.degrees(self.theta[i])
        return best, at


def runs(mask) -> list[tuple[int, int]]:
    """(first, last) index of every run of True in ``mask``."""
    m = np.asarray(mask, bool).astype(np.int8)
    d = np.diff(np.concatenate([[0], m, [0]]))
    return list(zip(np.nonzero(d == 1)[0].tolist(), (np.nonzero(d == -1)[0] - 1).tolist()))


def resolve_contact(pair: PairOutlines, theta_of_phi, phi0: float, phi1: float, direction: int, *,
                    step_driver_rad: float | None = None, h_min: float = policy.CONTACT_EVENT_STEP_RAD,
                    max_evals: int = policy.CONTACT_EVALUATIONS_MAX, tick=None) -> ContactLaw:
    """The loaded contact of ``direction`` over phi0..phi1 (driven law angles): sampled every
    ``step_driver_rad`` of driver angle (default ``policy.CONTACT_STEP_DRIVER_DEG``) and every change of state
    bisected down to ``h_min`` (see the module docstring); at most ``max_evals`` measurements.  ``tick(done,
    total)``: told the positions measured, sampled then bisected (the total of the bisections estimated, exact at the
    end; progress only)."""
    step = step_driver_rad if step_driver_rad is not None else math.radians(policy.CONTACT_STEP_DRIVER_DEG)
    th0, th1 = float(theta_of_phi(np.array([phi0]))[0]), float(theta_of_phi(np.array([phi1]))[0])
    n = max(2, int(math.ceil(abs(th1 - th0) / step)) + 1)
    # uniform in driver angle: phi of each theta by interpolation on a fine table, then refined by Newton
    grid = _phi_of_theta(theta_of_phi, phi0, phi1, np.linspace(th0, th1, n))
    grid[0], grid[-1] = phi0, phi1
    samples: dict[float, tuple] = {}
    evals = 0
    # the progress's total while sampling: the samples, and the bisections of the changes of state seen so far
    # projected over the rest (each change bisected about log2(spacing / 2 h_min) times)
    rounds = max(0, math.ceil(math.log2(max(abs(phi1 - phi0) / max(n - 1, 1), 2.0 * h_min) / (2.0 * h_min))))

    def measure(phis, tick=None):
        """The grid's rows (theta, te, kind, driver tooth, driven tooth), each position searched from the one before
        (compiled: :func:`.contact_track.track`, in runs of ``_TRACK_RUN``); ``tick`` told each position."""
        nonlocal evals
        phis = np.asarray(phis, float)
        th = np.asarray(theta_of_phi(phis), float)
        out = []
        changes = 0
        seed, seed_phi = math.nan, math.nan
        for j in range(0, len(phis), _TRACK_RUN):
            P, T = phis[j:j + _TRACK_RUN], th[j:j + _TRACK_RUN]
            te, kind, t_drv, t_dvn = track(pair, P, T, direction, [seed], [seed_phi], True,
                                           np.zeros(len(P), np.int64), caches, kept)
            evals += len(P)
            seed, seed_phi = float(te[-1]), float(P[-1])  # a nan te: the next run starts with the full search
            for t, r in zip(T.tolist(), zip(te.tolist(), kind.tolist(), t_drv.tolist(), t_dvn.tolist())):
                out.append((t,) + r)
                if tick is not None:
                    if len(out) > 1 and out[-1][2:5] != out[-2][2:5]:
                        changes += 1
                    k = len(out)
                    tick(k, len(phis) + round(changes * (len(phis) - 1) / max(k - 1, 1) * rounds))
        return out

    def measure_each(mids):
        """The rows at the midpoints ``(a, b, m, slot)``, each searched from the contact at its own a, reusing the
        candidates its slot kept from the bisection of the same change before it (at the first, those the sampled run
        held at the change's first end)."""
        if not mids:
            return []
        ms = [m for _, _, m, _ in mids]
        if together:  # a law's theta that gives each angle the value it gets alone: all midpoints in one call
            th = np.asarray(theta_of_phi(np.asarray(ms, float)), float).reshape(len(ms)).tolist()
        else:
            th = [float(np.asarray(theta_of_phi(np.asarray([m], float)), float)[0]) for m in ms]  # one by one
        te, kind, t_drv, t_dvn = track(pair, ms, th, direction, [samples[a][1] for a, _, _, _ in mids],
                                       [a for a, _, _, _ in mids], False, np.array([k for *_, k in mids], np.int64),
                                       caches)
        return [(t,) + r for t, r in zip(th, zip(te.tolist(), kind.tolist(), t_drv.tolist(), t_dvn.tolist()))]

    # the midpoints' driver angles asked together where theta is an elementwise law's (laws/law.py): the same floats
    together = getattr(getattr(theta_of_phi, "__self__", None), "elementwise", False) is True
    # slot 0: the sampled run; then one slot for the bisection of each change of state
    caches = new_caches(1)
    kept = new_caches(0)  # the sampled run's caches after each position
    for p, r in zip(grid, measure(grid, tick=tick)):
        samples[float(p)] = r
    # bisect every interval whose ends differ in state
    def state(r):
        return (r[2], r[3], r[4])

    xs = sorted(samples)
    todo = [(a, b) for a, b in zip(xs[:-1], xs[1:]) if state(samples[a]) != state(samples[b])]
    first = add_slots(caches, len(todo))
    # each change's bisection starts with the candidates the sampled run held after the change's first end (its
    # midpoints lie within one sample of there): sorted again only where they no longer hold
    at = {float(p): i for i, p in enumerate(grid)}
    seed_slots(caches, first, kept, np.array([at[a] for a, _ in todo], np.int64))
    todo = [(a, b, first + k) for k, (a, b) in enumerate(todo)]
    # the progress's total from here: each change bisected about `rounds` times (one half holds it)
    est = n + len(todo) * rounds
    while todo and evals < max_evals:
        mids = []
        for a, b, k in todo:
            if b - a > 2.0 * h_min:
                mids.append((a, b, 0.5 * (a + b), k))
        if not mids:
            break
        nxt = []
        mids = mids[:max(0, max_evals - evals)]
        for (a, b, m, k), r in zip(mids, measure_each(mids)):
            evals += 1
            samples[m] = r
            if tick is not None:
                tick(evals, max(est, evals + 1))
            if state(r) != state(samples[a]):
                nxt.append((a, m, k))
            if state(r) != state(samples[b]):
                nxt.append((m, b, k))
        todo = nxt
    if tick is not None:
        tick(evals, evals)
    xs = np.array(sorted(samples))
    rows = [samples[x] for x in xs]
    return ContactLaw(direction, xs, np.array([r[0] for r in rows]), np.array([r[1] for r in rows]),
                      np.array([r[2] for r in rows], int), np.array([r[3] for r in rows], int),
                      np.array([r[4] for r in rows], int), evals)


def _phi_of_theta(theta_of_phi, phi0: float, phi1: float, thetas: np.ndarray) -> np.ndarray:
    """Driven law angles of the driver angles ``thetas`` (theta increasing with phi): a table of 4097 points,
    then two Newton steps with a centred difference."""
    tab = np.linspace(phi0, phi1, 4097)
    tt = np.asarray(theta_of_phi(tab), float)
    phi = np.interp(thetas, tt, tab)
    for _ in range(3):
        h = 1e-7
        f = np.asarray(theta_of_phi(phi), float) - thetas
        df = (np.asarray(theta_of_phi(phi + h), float) - np.asarray(theta_of_phi(phi - h), float)) / (2 * h)
        phi = phi - f / df
    return phi


def contact_law(pair: PairOutlines, theta_of_phi, phi0: float, phi1: float, **kw) -> tuple[ContactLaw, ContactLaw]:
    """Both directions: (drive, reverse)."""
    return (resolve_contact(pair, theta_of_phi, phi0, phi1, DRIVE, **kw),
            resolve_contact(pair, theta_of_phi, phi0, phi1, REVERSE, **kw))
