"""The composite gear's contact law at one position, tracked on the finished outlines with adaptive steps.

θ(φ): the gear's angle (its own turning sense) when the wheel, turning in its working sense, drives it
against a resisting load: from the pose at the previous step the gear is pushed forward to its first
free pose, then turned back until it touches the wheel's outline (exact rotational contact on the
polylines, :func:`propulsor.checks.motion.backlash.free_rotation`).  No estimate of the ratio enters.

Every step is halved (down to ``policy.POLYSECTOR_LAW_STEP_MIN_RAD`` of wheel turn) while across it the
driving sector changes, the contact type changes, the gear moves by more than the snap tolerance beyond
its nominal advance, or the ratio of the step differs from the ratios at its ends: every hand-over is
resolved finely enough to see tip-on-tip contact and snaps.

Contact type of a pose, from the load-carrying contacts (those within the contact tolerance of the
pose): a contact point is on a body's *tip* when it lies within two chord tolerances of that body's tip
circle (the tip land or its corners); ``flank`` (neither tip), ``sector_tip`` (a sector's tip corner on
the gear's flank: the seed's edge contact), ``gear_tip`` (the gear's tip corner on a sector's flank),
``tip_tip`` (both tips).  The pose is ``flank`` if any contact is, ``tip_tip`` if all are.

Ratio i_t = dφ/dθ from the geometry, not from a fit: the pole P where the contact normal cuts the line
of centres, i_t = O2P/O1P (Kennedy; eq. 7 measured).  An involute's normal touches its base circle: for
a tip corner on a flank the normal is the tangent from the corner to the flank's base circle, for flank
on flank the internal common tangent of the two base circles at the measured pose (in each case of the
two lines the one nearer the outline's own normal at the contact); for tip-on-tip contact, which has no
normal, the step's own Δφ/Δθ.  Δi = (i_n − i_t)/i_n (eq. 8).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ... import policy

__all__ = ["TYPES", "Bodies", "position_bodies", "ContactLaw", "track", "pole_ratio", "flank_ratio", "LawResult"]

#: contact types, in the order of the shares reported
TYPES = ("flank", "sector_tip", "gear_tip", "tip_tip")


def _wrap(a):
    return (np.asarray(a) + math.pi) % (2 * math.pi) - math.pi


@dataclass
class Bodies:
    """The outlines of one position over one sector period: the gear (cropped to the teeth that mesh),
    every sector that can be engaged (wheel frame at φ = 0), their centres and the radii."""

    gear: object
    sectors: dict  # sector index -> Outline (wheel frame, φ = 0)
    angles: list  # (mid-line angle, flow) of every sector
    a: float
    offset: float
    i_n: float
    period: float
    r_a: float
    r_b: float
    r_a2: float
    r_b2: float
    w_max: float  # a gear pitch (rad)
    chord_tol: float


def position_bodies(dd, pos, chord_tol: float, margin: float = 0.05) -> Bodies:
    """Outlines of one position (see :class:`Bodies`); sectors whose mid-line passes within u_exit + margin
    of the line of centres during the period."""
    from ...checks.motion import crop_to_sector, outline
    from ...geometry.polysector_outline import place

    p, geo = dd.p, dd.geo
    period = 2 * math.pi / (p.flows * p.sectors_per_flow)
    seg = policy.MOTION_MAX_SEGMENT_MM
    full = outline(dd.gear_profile, chord_tol, seg)
    Z = 2.0 * math.asin(min(1.0, (geo.r_a + pos.offset) / pos.a)) + 0.2
    t_hi = period / pos.ratio_nominal + 4 * math.pi / p.gear_teeth
    gear = outline(crop_to_sector(full.section, math.pi - Z - 0.1, math.pi + Z + t_hi,
                                  geo.r2 - 1.5 * p.module_mm, geo.r_a2 + p.module_mm), chord_tol, seg)
    angles = [(ang, f) for f in range(1, p.flows + 1) for ang in dd.sector_angles(f)]
    sectors = {}
    for j, (ang, _f) in enumerate(angles):
        u0 = float(_wrap(ang))
        if u0 + period > -pos.u_exit - margin and u0 < pos.u_exit + margin:
            sectors[j] = outline(place(dd.sector, ang, pos.offset), chord_tol, seg)
    return Bodies(gear, sectors, angles, pos.a, pos.offset, pos.ratio_nominal, period, geo.r_a, geo.r_b, geo.r_a2,
                  geo.r_b2, 2 * math.pi / p.gear_teeth, chord_tol)


def _pole(lines, normal, a: float) -> float:
    """i_t = O2P/O1P for the candidate line (point, unit direction) most parallel to ``normal``; P where it
    cuts the x axis (O1 at the origin, O2 at (a, 0))."""
    T, dv = max(lines, key=lambda ln: abs(ln[1][0] * normal[0] + ln[1][1] * normal[1]))
    if abs(dv[1]) < 1e-12:
        return math.nan
    px = T[0] - T[1] * dv[0] / dv[1]
    return (a - px) / px


def pole_ratio(C, centre, r_b, normal, a: float) -> float:
    """i_t of a tip corner at C on an involute of the base circle (centre, r_b): the normal is the tangent
    from C to that circle (of the two, the one nearer the direction ``normal``)."""
    C, centre = np.asarray(C, float), np.asarray(centre, float)
    v = C - centre
    d = math.hypot(v[0], v[1])
    if d <= r_b:
        return math.nan
    beta, gam = math.atan2(v[1], v[0]), math.acos(r_b / d)
    lines = []
    for sgn in (1.0, -1.0):
        T = centre + r_b * np.array([math.cos(beta + sgn * gam), math.sin(beta + sgn * gam)])
        dv = (C - T) / math.hypot(*(C - T))
        lines.append((T, dv))
    return _pole(lines, normal, a)


def flank_ratio(Os, r_b, O2, r_b2, normal, a: float) -> float:
    """i_t of a flank-on-flank contact: the normal of two involutes in contact is an internal common tangent
    of their base circles (of the two, the one nearer the direction ``normal``): eq. 7 at the measured pose."""
    Os, O2 = np.asarray(Os, float), np.asarray(O2, float)
    v = O2 - Os
    d = math.hypot(v[0], v[1])
    if d <= r_b + r_b2:
        return math.nan
    n, ap = v / d, math.acos((r_b + r_b2) / d)
    lines = []
    for sgn in (1.0, -1.0):
        c, s = math.cos(sgn * ap), math.sin(sgn * ap)
        u = np.array([c * n[0] - s * n[1], s * n[0] + c * n[1]])  # towards the tangent point
        lines.append((Os + r_b * u, np.array([-u[1], u[0]])))
    return _pole(lines, normal, a)


@dataclass
class _Sample:
    phi: float
    theta: float
    driver: int
    kind: int  # index into TYPES
    i_t: float  # from the pole (NaN for tip-on-tip)
    sectors: tuple  # load-carrying sectors


class ContactLaw:
    """Poses of the gear against the wheel's outline (see the module docstring)."""

    def __init__(self, bodies: Bodies):
        self.b = bodies
        self.O2 = np.array([bodies.a, 0.0])
        self.band = 2.0 * bodies.chord_tol + 1e-9
        self.evaluations = 0

    # --- frames ------------------------------------------------------------------------------
    def _rel21(self, phi: float, th: float):
        from ...checks.motion.poses import Pose, compose_poses, inverse_pose

        M1 = Pose(phi, (0.0, 0.0), (0.0, 0.0)).matrix()
        M2 = Pose(-th, (0.0, 0.0), (self.b.a, 0.0)).matrix()
        return compose_poses(inverse_pose(M1), M2), M2

    def engaged(self, j: int, phi: float) -> bool:
        """Sector j's outline reaches into the gear's tip circle."""
        from ...planar import norms

        c, s = math.cos(phi), math.sin(phi)
        P = self.b.sectors[j].points @ np.array([[c, s], [-s, c]])
        return bool(np.min(norms(P - self.O2)) < self.b.r_a2)

    def overlaps(self, j: int, phi: float, th: float) -> bool:
        """Whether sector j and the gear have area in common (above 1e-12 mm^2: a free start is what the rotational
        contact needs): the manifold3d intersection, unless the outlines are certainly apart (no edges that meet, no
        loop inside the other: :func:`~propulsor.checks.motion.crossing.certainly_apart`), where its area is 0."""
        from ...checks.motion.crossing import common_area
        from ...checks.motion.poses import apply_pose, inverse_pose

        rel21, _ = self._rel21(phi, th)
        sec, gear = self.b.sectors[j], self.b.gear
        return common_area(sec, gear, rel21, apply_pose(rel21, gear.points),
                           apply_pose(inverse_pose(rel21), sec.points)) > 1e-12

    def back_room(self, j: int, phi: float, th: float, w0: float):
        """Free rotation of the gear backwards from th against sector j: (room, world contact point)."""
        from ...checks.motion.backlash import free_rotation, rot_bounds
        from ...checks.motion.poses import apply_pose, inverse_pose

        drv, gear = self.b.sectors[j], self.b.gear
        rel21, M2 = self._rel21(phi, th)
        rel12 = inverse_pose(rel21)
        P1, C1 = apply_pose(rel21, gear.points), rel21[:, 2]
        P2 = apply_pose(rel12, drv.points)
        r = free_rotation(drv, gear, P1, C1, P2, *rot_bounds(P1, C1, drv), *rot_bounds(P2, (0.0, 0.0), gear), M2, 1.0,
                          w0, self.b.w_max, policy.MOTION_CONTACT_TOL_MM, policy.MOTION_CONTACT_MERGE_MM)
        return r.delta, r.point

    # --- one pose ----------------------------------------------------------------------------
    def pose(self, phi: float, th_prev: float, h: float) -> _Sample:
        """The gear's pose at wheel angle phi, the previous pose th_prev a step h before."""
        b = self.b
        self.evaluations += 1
        js = [j for j in b.sectors if self.engaged(j, phi)]
        step = 1.5 * h / b.i_n + 2e-5
        while True:
            ths = th_prev + step
            if not any(self.overlaps(j, phi, ths) for j in js):
                break
            step *= 2.0
            if step > 2 * b.w_max:
                return _Sample(phi, math.nan, -1, len(TYPES) - 1, math.nan, ())
        rooms = {j: self.back_room(j, phi, ths, step + 1e-4) for j in js}
        finite = {j: r for j, r in rooms.items() if math.isfinite(r[0])}
        if not finite:
            return _Sample(phi, math.nan, -1, len(TYPES) - 1, math.nan, ())
        jd = min(finite, key=lambda j: finite[j][0])
        th = ths - finite[jd][0]
        tol_ang = policy.MOTION_CONTACT_TOL_MM / b.r_b2
        load = [j for j, r in finite.items() if r[0] - finite[jd][0] <= tol_ang]
        kinds, its = [], []
        for j in load:
            C = finite[j][1]
            ang = b.angles[j][0] + phi
            Os = b.offset * np.array([math.cos(ang), math.sin(ang)])
            s_tip = math.hypot(*(C - Os)) >= b.r_a - self.band
            g_tip = math.hypot(*(C - self.O2)) >= b.r_a2 - self.band
            kind = 3 if (s_tip and g_tip) else 1 if s_tip else 2 if g_tip else 0
            kinds.append(kind)
            if kind == 3:
                its.append(math.nan)
            elif kind == 1:  # the sector's corner on the gear's involute
                its.append(pole_ratio(C, self.O2, b.r_b2, self._normal_gear(C, th), b.a))
            elif kind == 2:  # the gear's corner on the sector's involute
                its.append(pole_ratio(C, Os, b.r_b, self._normal_sector(j, C, phi), b.a))
            else:  # flank on flank
                its.append(flank_ratio(Os, b.r_b, self.O2, b.r_b2, self._normal_sector(j, C, phi), b.a))
        kind = 0 if 0 in kinds else 3 if all(k == 3 for k in kinds) else 1 if 1 in kinds else 2
        it = its[load.index(jd)]
        if not math.isfinite(it):  # the driving contact has no normal: the ratio of a load-carrying one that has
            it = next((x for x, kk in sorted(zip(its, kinds), key=lambda t: t[1]) if math.isfinite(x)), math.nan)
        return _Sample(phi, th, jd, kind, it, tuple(sorted(load)))

    def _normal_of(self, o, p):
        i = int(o.tree.query(p)[1])
        t = o.points[o.nxt[i]] - o.points[o.prev[i]]
        return np.array([-t[1], t[0]]) / max(math.hypot(t[0], t[1]), 1e-300)

    def _normal_gear(self, C, th):
        c, s = math.cos(th), math.sin(th)  # body frame: R(+th)(C − O2)
        v = C - self.O2
        n = self._normal_of(self.b.gear, np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]]))
        return np.array([c * n[0] + s * n[1], -s * n[0] + c * n[1]])

    def _normal_sector(self, j, C, phi):
        c, s = math.cos(phi), math.sin(phi)
        n = self._normal_of(self.b.sectors[j], np.array([c * C[0] + s * C[1], -s * C[0] + c * C[1]]))
        return np.array([c * n[0] - s * n[1], s * n[0] + c * n[1]])


@dataclass
class LawResult:
    """The tracked contact law over one sector period (adaptive samples) and what it shows."""

    phi: np.ndarray
    theta: np.ndarray
    driver: np.ndarray
    kind: np.ndarray
    i_t: np.ndarray
    delta_i: np.ndarray
    ratio_nominal: float
    step_min: float
    snap_tol: float
    evaluations: int

    @property
    def te(self) -> np.ndarray:
        return self.theta - self.phi / self.ratio_nominal

    def weights(self) -> np.ndarray:
        """Wheel angle each sample stands for (half of each neighbouring step)."""
        d = np.diff(self.phi)
        w = np.zeros(len(self.phi))
        w[:-1] += d / 2
        w[1:] += d / 2
        return w

    def shares(self) -> dict:
        """Share of the period's wheel angle per contact type."""
        w = self.weights()
        tot = float(w.sum())
        return {t: float(w[self.kind == i].sum() / tot) for i, t in enumerate(TYPES)}

    def tip_tip_angle(self) -> float:
        """Wheel angle (rad) per period over which the gear rests on tips only."""
        return float(self.weights()[self.kind == TYPES.index("tip_tip")].sum())

    def jumps(self) -> np.ndarray:
        """|Δθ − Δφ/i_n| of every step (rad of gear turn)."""
        return np.abs(np.diff(self.theta) - np.diff(self.phi) / self.ratio_nominal)

    def snap_max(self) -> float:
        """Largest gear jump beyond the nominal advance within one finest step (rad); NaN if contact was lost."""
        if not np.all(np.isfinite(self.theta)):
            return math.nan
        fine = np.diff(self.phi) <= self.step_min * (1 + 1e-9)
        j = self.jumps()[fine]
        return float(j.max()) if len(j) else 0.0

    def ratio_error_max(self) -> float:
        return float(np.nanmax(np.abs(self.delta_i)))

    def at(self, phi_grid: np.ndarray) -> np.ndarray:
        """Indices of the samples at the given wheel angles (the proof's steps)."""
        return np.array([int(np.argmin(np.abs(self.phi - x))) for x in phi_grid])


def _refine(a: _Sample, b: _Sample, i_n: float, snap_tol: float) -> bool:
    if not (math.isfinite(a.theta) and math.isfinite(b.theta)):
        return True
    if (a.driver not in b.sectors and b.driver not in a.sectors) or a.kind != b.kind or b.kind == 3:
        return True  # a hand-over (not two sectors sharing the load), a change of contact type, tips
    dphi, dth = b.phi - a.phi, b.theta - a.theta
    if abs(dth - dphi / i_n) > snap_tol:
        return True
    if dth <= 0 or not (math.isfinite(a.i_t) and math.isfinite(b.i_t)):
        return True
    sec = dphi / dth
    return abs(sec - 0.5 * (a.i_t + b.i_t)) > policy.POLYSECTOR_LAW_RATIO_SPLIT * i_n


def track(bodies: Bodies, grid: np.ndarray, theta0: float, step_min: float = policy.POLYSECTOR_LAW_STEP_MIN_RAD,
          snap_tol: float = math.radians(policy.POLYSECTOR_SNAP_TOL_DEG)) -> LawResult:
    """The contact law over grid[0] … grid[-1] (every grid angle is a sample), from the pose theta0 at grid[0]
    (a contact pose, e.g. the proof's): adaptive steps, see the module docstring."""
    law = ContactLaw(bodies)
    i_n = bodies.i_n
    cur = law.pose(float(grid[0]), theta0 - 1e-5, 0.0)
    out = [cur]
    h_max = float(np.max(np.diff(grid))) if len(grid) > 1 else 0.0
    h = h_max
    last = theta0  # the last pose found (a lost contact, NaN, is reported and the tracking goes on from it)
    for target in grid[1:]:
        while cur.phi < target - 1e-15:
            h = min(h, target - cur.phi)
            last = cur.theta if math.isfinite(cur.theta) else last
            nxt = law.pose(cur.phi + h, last, h)
            if h > step_min * (1 + 1e-9) and _refine(cur, nxt, i_n, snap_tol):
                h = max(h / 2.0, step_min)
                continue
            if nxt.kind == 3 and out and math.isfinite(nxt.theta) and nxt.theta > cur.theta:
                nxt.i_t = h / (nxt.theta - cur.theta)  # no normal: the step's own ratio
            out.append(nxt)
            cur = nxt
            h = min(2.0 * h, h_max)
    phi = np.array([s.phi for s in out])
    theta = np.array([s.theta for s in out])
    it = np.array([s.i_t for s in out])
    return LawResult(phi, theta, np.array([s.driver for s in out]), np.array([s.kind for s in out]), it,
                     (i_n - it) / i_n, i_n, step_min, snap_tol, law.evaluations)
