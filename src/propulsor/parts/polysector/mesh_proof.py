"""The composite gear's proof at one position, on the finished outlines (seed 003 eq. 4–8 measured).

Over one sector period of the wheel (2π/(flows·i_s): the sectors are identical outlines turned
by exactly that angle, and the gear advances a whole number of its pitches per period, so the pose
of the pair repeats; the full turn is that period repeated, and the tables list the full turn):

* per sector j and wheel angle φ, with that sector alone: the gear's *drive* pose θ_j (turned back
  from a free pose until it touches the sector's driving flanks) and *coast* pose (turned forward
  until the other flanks touch) — exact rotational contact on the polylines
  (:func:`propulsor.checks.motion.backlash.free_rotation`);
* the gear's actual angle under load θ(φ) = max_j θ_j (every sector's driving flanks bound it from
  behind; the most advanced one drives), found from contact, not from the ratio;
* jam / overlap: θ(φ) must not pass any engaged sector's coast pose; the overlap area of the gear
  at θ(φ) with each flow's sectors (manifold3d booleans, through the outlines' sections) is reported;
* tooth pairs in contact at θ(φ) (all flows), continuity (never 0);
* engagement of a sector: from its leading tooth's driving corner entering the gear's tip circle to its
  trailing tooth's driving corner leaving it (both corners taken from the outline, the boundaries found
  by bisection): φ1 and ε_s = φ1 i_s/2π measured (eq. 4);
* the contact law through every hand-over with adaptive steps (:mod:`.contact_law`): contact types,
  tip-on-tip contact, snaps, i_t from the pole of the contact normal (eq. 7 measured), Δi (eq. 8).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ... import policy

__all__ = ["PositionProof", "prove_position"]


@dataclass
class PositionProof:
    """One position's proof over one sector period (see the module docstring)."""

    k: int
    phi: np.ndarray  # wheel angles of one period, rad
    period: float
    theta: np.ndarray  # actual gear angle (the gear's own turning sense), rad
    theta_nominal: np.ndarray  # φ / i_n
    driver: np.ndarray  # index of the driving sector per step
    driver_u: np.ndarray  # its mid-line angle from the line of centres
    pairs: np.ndarray  # tooth pairs in contact at the actual pose (all flows)
    sectors_engaged: np.ndarray  # sectors whose outline is inside the gear tip circle
    overlap_flow: np.ndarray  # (steps, flows) overlap area at the actual pose, mm²
    coast_room: np.ndarray  # least coast-side free rotation of the engaged sectors (rad; < 0: jam)
    phi1_measured: float
    u_enter: float
    u_exit: float
    contact_points: np.ndarray  # drive contact point per step (world, mm)
    contacts: list  # per step: (sector index, world point) of every tooth pair in contact at the actual pose
    drive_theta: dict  # sector index -> its own drive pose per step (NaN where not engaged)
    ratio_nominal: float
    chord_tol: float
    r_ref: float
    flows: int
    i_s: int
    law: object = None  # contact_law.LawResult over the period (adaptive steps; its samples include phi)

    @property
    def te(self) -> np.ndarray:
        """Transmission error θ − φ/i_n of the gear (rad)."""
        return self.theta - self.theta_nominal

    def eps_s_measured(self) -> tuple[float, float]:
        """ε_s (per flow, all flows) from the measured engagement angle φ1 (eq. 4)."""
        f = self.phi1_measured * self.i_s / (2 * math.pi)
        return f, f * self.flows

    def ratio_measured(self) -> tuple[np.ndarray, np.ndarray]:
        """(i_t, Δi) per step from the tracked contact law (the pole of the contact normal, eq. 7 measured;
        no fit): see :mod:`.contact_law`."""
        idx = self.law.at(self.phi)
        return self.law.i_t[idx], self.law.delta_i[idx]


def _wrap(a):
    return (np.asarray(a) + math.pi) % (2 * math.pi) - math.pi


def _driving_corner_span(dd, pos, chord_tol, r_a2, O2) -> tuple[float, float]:
    """(u_enter, u_exit) of flow 1's first sector from its outline's driving tip corners (see the caller)."""
    from ...checks.motion import outline
    from ...geometry.polysector_outline import place

    geo = dd.geo
    o = outline(place(dd.sector, 0.0, pos.offset), chord_tol, policy.MOTION_MAX_SEGMENT_MM)
    rel = o.points - np.array([pos.offset, 0.0])
    tip = rel[np.hypot(rel[:, 0], rel[:, 1]) >= geo.r_a - 2.0 * chord_tol - 1e-9]
    beta = np.sort(np.arctan2(tip[:, 1], tip[:, 0]))  # from the mid-line, CCW
    cuts = np.nonzero(np.diff(beta) > math.pi / dd.p.blank_teeth)[0]
    trailing_inner = beta[cuts[0]] if len(cuts) else beta[-1]  # the last tip vertex of the CW-most tooth
    leading_outer = beta[-1]

    def inside(beta0, u):
        c = np.array([pos.offset * math.cos(u) + geo.r_a * math.cos(u + beta0),
                      pos.offset * math.sin(u) + geo.r_a * math.sin(u + beta0)])
        return bool(np.hypot(*(c - O2)) < r_a2)

    def boundary(beta0, lo, hi, sgn=1.0):
        """The wheel angle sgn·u, u in lo … hi, at which the corner crosses the tip circle (bisection)."""
        e_lo = inside(beta0, sgn * lo)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if inside(beta0, sgn * mid) == e_lo:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)

    grid = np.linspace(0.0, math.pi / 2, 721)
    ins = np.array([inside(trailing_inner, g) for g in grid])
    k = int(np.argmax(ins)) + int(np.argmax(~ins[int(np.argmax(ins)):]))
    u_exit = boundary(trailing_inner, grid[k - 1], grid[k])
    ins = np.array([inside(leading_outer, -g) for g in grid])
    k = int(np.argmax(ins)) + int(np.argmax(~ins[int(np.argmax(ins)):]))
    u_enter = -boundary(leading_outer, grid[k - 1], grid[k], -1.0)
    return u_enter, u_exit


def prove_position(dd, pos, steps_per_pitch: int | None = None, chord_tol: float = policy.MOTION_CHORD_TOL_MM):
    from ...checks.motion import outline
    from ...checks.motion.backlash import free_rotations, rot_bounds
    from ...checks.motion.crossing import common_area
    from ...planar import norms
    from ...checks.motion.poses import Pose, apply_pose, compose_poses, inverse_pose

    p, geo = dd.p, dd.geo
    n_sec = p.flows * p.sectors_per_flow
    period = 2 * math.pi / n_sec
    spp = steps_per_pitch or p.proof_steps_per_pitch
    pitches = pos.z_cond // n_sec
    n = spp * pitches
    phi = np.arange(n) * (period / n)
    i_n = pos.ratio_nominal
    a = pos.a
    theta_n = phi / i_n
    seg = policy.MOTION_MAX_SEGMENT_MM
    # the gear's teeth that meet the sectors during the period: world angles π ± Z about O2 (Z: the
    # sector reach seen from O2, generous), the gear turning by up to a period/i_n (+ a pitch)
    from ...checks.motion import crop_to_sector

    full = outline(dd.gear_profile, chord_tol, seg)
    Z = 2.0 * math.asin(min(1.0, (geo.r_a + pos.offset) / a)) + 0.2
    t_hi = period / i_n + 4 * math.pi / p.gear_teeth
    gear = outline(crop_to_sector(full.section, math.pi - Z - 0.1, math.pi + Z + t_hi,
                                  geo.r2 - 1.5 * p.module_mm, geo.r_a2 + p.module_mm), chord_tol, seg)
    # sectors that can be engaged during the period: mid-line within u_exit (+ margin) of the line of centres
    margin = 0.05
    angles = []
    for f in range(1, p.flows + 1):
        for ang in dd.sector_angles(f):
            angles.append((ang, f))
    cand = []
    for j, (ang, f) in enumerate(angles):
        u0 = float(_wrap(ang))  # over the period its mid-line sweeps u0 … u0 + period
        if u0 + period > -pos.u_exit - margin and u0 < pos.u_exit + margin:
            cand.append(j)
    from ...geometry.polysector_outline import place

    sec_out = {j: outline(place(dd.sector, angles[j][0], pos.offset), chord_tol, seg) for j in cand}
    r_a2 = geo.r_a2
    O2 = np.array([a, 0.0])
    s2 = -1.0  # the gear turns clockwise (its own sense is −z)
    tol, merge = policy.MOTION_CONTACT_TOL_MM, policy.MOTION_CONTACT_MERGE_MM
    w_max = 2 * math.pi / p.gear_teeth  # a gear pitch

    def engaged(j, ph):
        """The sector's outline reaches into the gear's tip circle (measured on its vertices)."""
        o = sec_out[j]
        c, s = math.cos(ph), math.sin(ph)
        P = o.points @ np.array([[c, s], [-s, c]])
        return bool(np.min(norms(P - O2)) < r_a2)

    def u_of(j, ph):
        return float(_wrap(angles[j][0] + ph))

    def te_estimate(j, ph):
        """Gear angle of sector j's flank contact from eq. 7 (start of the search only)."""
        u = u_of(j, ph)
        uu = np.linspace(0.0, u, 65)
        it = geo.ratio_flank(pos.offset, uu)
        integ = float(np.trapezoid(1.0 / it, uu))
        return (ph - u) / i_n + integ

    def sector_free(j, ph, th, w0=2e-3):
        """(drive pose, coast pose, pairs at drive, drive contact point) of sector j alone from the free
        start pose th; None when th overlaps the sector (a free rotation from inside the gear would find a
        false first contact)."""
        drv = sec_out[j]
        M1 = Pose(ph, (0.0, 0.0), (0.0, 0.0)).matrix()
        M2 = Pose(s2 * th, (0.0, 0.0), (a, 0.0)).matrix()
        rel21 = compose_poses(inverse_pose(M1), M2)
        rel12 = inverse_pose(rel21)
        P1 = apply_pose(rel21, gear.points)
        C1 = rel21[:, 2]
        P2 = apply_pose(rel12, drv.points)
        # the common area: 0 without the boolean where the outlines are certainly apart (crossing.common_area)
        if common_area(drv, gear, rel21, P1, P2) > policy.OVERLAP_AREA_TOL_MM2:
            return None
        rho1, lb1 = rot_bounds(P1, C1, drv)
        rho2, lb2 = rot_bounds(P2, (0.0, 0.0), gear)
        b, f = free_rotations(drv, gear, P1, C1, P2, rho1, lb1, rho2, lb2, M2, -s2, w0, w0, w_max, tol, merge)
        return th - b.delta, th + f.delta, b.n_pairs, b.point

    drive = {j: np.full(n, np.nan) for j in cand}
    coast = {j: np.full(n, np.nan) for j in cand}
    npairs = {j: np.zeros(n, int) for j in cand}
    cpt = {j: np.full((n, 2), np.nan) for j in cand}
    eng = {j: np.zeros(n, bool) for j in cand}
    placed: set = set()  # the sectors placed free at the step before
    for k in range(n):
        for j in cand:
            if not engaged(j, phi[k]):
                placed.discard(j)
                continue
            eng[j][k] = True
            # starts, each tested for overlap (a free rotation from inside the gear finds a false contact): just on
            # the free side of the drive contact extrapolated from the two steps before, then of the step before's
            # turned on by the nominal ratio (a step into the free range: half of it, at most 1.5 mrad), eq. 7's
            # estimate; then a scan about the estimate.  The middle of the free range is no start: where the coast
            # side is open (a sector entering) it lies a tooth away, and an extrapolation of it landed inside the gear
            # at e = 0 (seed 003's part, 2 steps a pitch): its false contact, 0.2 mm off, lost two of four tooth pairs
            starts = []
            if j in placed:
                d1 = drive[j][k - 1]
                inset = 0.5 * min(coast[j][k - 1] - d1, 3e-3)
                if k >= 2 and np.isfinite(drive[j][k - 2]):
                    starts.append((2 * d1 - drive[j][k - 2] + inset, 2e-3))
                starts.append((d1 + (theta_n[k] - theta_n[k - 1]) + inset, 2e-3))
            else:
                starts.append((te_estimate(j, phi[k]), 2e-3))
            for start, w0 in starts:  # at least one
                res = sector_free(j, phi[k], start, w0)
                if res is not None and math.isfinite(res[0]) and math.isfinite(res[1]):
                    break
            if res is None or not (math.isfinite(res[0]) and math.isfinite(res[1])):
                base = te_estimate(j, phi[k])
                for off in np.linspace(0.0, w_max, 33)[1:]:
                    for sgn in (1.0, -1.0):
                        res = sector_free(j, phi[k], base + sgn * off / 2)
                        if res is not None and math.isfinite(res[0]) and math.isfinite(res[1]):
                            break
                    else:
                        continue
                    break
            if res is None or not (math.isfinite(res[0]) and math.isfinite(res[1])):
                placed.discard(j)
                continue
            drive[j][k], coast[j][k], npairs[j][k], cpt[j][k] = res
            placed.add(j)
    D = np.vstack([drive[j] for j in cand])
    C = np.vstack([coast[j] for j in cand])
    theta = np.nanmax(D, axis=0)
    row_drv = np.nanargmax(np.where(np.isfinite(D), D, -np.inf), axis=0)
    jdrv = np.array([cand[r] for r in row_drv])
    r_ref = geo.r_b2
    pairs = np.zeros(n, int)
    for row, j in enumerate(cand):
        inc = np.isfinite(D[row]) & ((theta - D[row]) * r_ref <= tol)
        pairs += np.where(inc, npairs[j], 0)
    # least coast-side room of the engaged sectors at the actual pose (< 0: the gear is pushed into a
    # sector's other flanks: jam)
    room = np.nanmin(np.where(np.isfinite(C), C, np.inf), axis=0) - theta
    # overlap of the gear at the actual pose with each flow's sectors (manifold3d, through the sections)
    overlap = np.zeros((n, p.flows))
    for k in range(n):
        M2 = Pose(s2 * theta[k], (0.0, 0.0), (a, 0.0)).matrix()
        for j in cand:
            if not eng[j][k]:
                continue
            M1 = Pose(phi[k], (0.0, 0.0), (0.0, 0.0)).matrix()
            rel21 = compose_poses(inverse_pose(M1), M2)
            overlap[k, angles[j][1] - 1] += (sec_out[j].section ^ gear.section.transform(rel21)).area()
    n_eng = np.sum([eng[j] for j in cand], axis=0)
    # measured engagement of one sector (flow 1's first, mid-line on +x at φ = 0): the wheel angles at which
    # the leading tooth's driving corner enters the gear's tip circle and the trailing tooth's leaves it,
    # both corners taken from the outline (its vertices on the blank's tip circle about O'), by bisection
    u_enter, u_exit = _driving_corner_span(dd, pos, chord_tol, r_a2, O2)
    # the driving sector's mid-line angle and contact points
    drv_u = np.array([u_of(j, ph) for j, ph in zip(jdrv, phi)])
    cp = np.array([cpt[j][k] for k, j in enumerate(jdrv)])
    # every tooth pair in contact at the actual pose: gear boundary points within the contact tolerance of
    # a sector in contact, grouped along the gear's boundary (groups more than `merge` apart are pairs)
    from ...checks.motion.distance import within

    contacts = []
    for k in range(n):
        here = []
        M2 = Pose(s2 * theta[k], (0.0, 0.0), (a, 0.0)).matrix()
        M1 = Pose(phi[k], (0.0, 0.0), (0.0, 0.0)).matrix()
        rel21 = compose_poses(inverse_pose(M1), M2)  # gear body -> sector body (wheel frame at φ = 0)
        for row, j in enumerate(cand):
            if not (np.isfinite(D[row][k]) and (theta[k] - D[row][k]) * r_ref <= tol):
                continue
            P = apply_pose(rel21, gear.points)
            near = np.nonzero(sec_out[j].boundary_lower_bound(P) <= tol)[0]
            if len(near) == 0:
                continue
            near = near[within(P[near], sec_out[j], tol)]
            if len(near) == 0:
                continue
            order = np.argsort(gear.arclen[near])
            idx = near[order]
            cuts = np.nonzero(np.diff(gear.arclen[idx]) > merge)[0] + 1
            for grp in np.split(idx, cuts):
                here.append((j, apply_pose(M2, gear.points[grp]).mean(axis=0)))
        contacts.append(here)
    from .contact_law import position_bodies, track

    law = track(position_bodies(dd, pos, chord_tol), np.append(phi, period), float(theta[0]))
    return PositionProof(k=pos.k, phi=phi, period=period, theta=theta, theta_nominal=theta_n, driver=jdrv,
                         driver_u=drv_u, pairs=pairs, sectors_engaged=n_eng, overlap_flow=overlap, coast_room=room,
                         phi1_measured=u_exit - u_enter, u_enter=u_enter, u_exit=u_exit, contact_points=cp, contacts=contacts,
                         drive_theta={j: drive[j] for j in cand}, ratio_nominal=i_n, chord_tol=chord_tol,
                         r_ref=r_ref, flows=p.flows, i_s=p.sectors_per_flow, law=law)
