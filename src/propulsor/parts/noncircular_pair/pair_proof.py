"""Full-cycle proof of a non-circular pair on its finished outlines (seed 000 eq. 9/11; docs/architecture.md, "The data flow of one build").

The driven wheel (axis at the origin) turns by -phi, the driver (axis at (L, 0)) by
+theta_law(phi) (seed 000 eq. 9/11 with the periodic wrap; the smoothed law for generated
teeth).  At every sampled phase ``checks.motion.transmission_sweep`` measures on the
outlines: overlap area at the law's position (manifold3d boolean), the free rotation of the
driven wheel both ways until contact (backlash), the driven angle at which the loaded flanks
touch (transmission error against the law) and the tooth pairs in contact (contact ratio).

Speed: the driven outline is cropped, per window of consecutive phases, to the annular
sector that the driver can reach (its largest radius plus the largest free-rotation search
angle and 1 mm); the rest of the driven wheel is farther from the driver than its tip
radius at every phase of the window, so it can neither overlap nor touch.  The crop's
artificial edges lie outside that reach, so the values do not depend on the windows (16 a turn:
``policy.PAIR_PROOF_WINDOW_RAD``).

A pair that repeats every period of its law (a wheel cut as one lobe and patterned) is measured over its first
period, each later phase taken as its like there turned, once both outlines are found to repeat under a period's
turns to ``policy.CYCLIC_TOL_MM`` at every vertex (:func:`cyclic_mismatch`; ``prove_pair``'s ``periods``).

Teeth that are not conjugate (the papers' sector method) may overlap at the law's position.
There the running position is searched: the driven offset of least overlap area within half
a pitch of the previous phase's offset (13-point scan refined by a bounded Brent search);
if that area is 0 the free rotations are measured from there, otherwise the phase is a
jam (no position of the driven wheel frees it) and its least overlap is reported.  The search's
booleans take the two crops cut to the sectors where the bodies can meet at any offset searched
(``_MeetCrops``, from the bodies' polar envelopes; ``_LensCrops``, discs about the axes, where those do not
apply): the same overlap, to the last bit, among a fraction of the vertices.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...checks.motion import PolarEnvelope, crop_to_sector, cut_to_disc, outline, transmission_sweep
from ...checks.motion.outlines import HeldSectorCut, polar_extent
from ... import policy
from ...planar import norms


@dataclass
class PairProof:
    """Per-phase results (arrays over the sampled driven angles phi)."""

    phi: np.ndarray
    theta_law: np.ndarray
    overlap_law: np.ndarray      #: overlap area at the law's position (mm^2)
    offset: np.ndarray           #: driven offset from the law used as the start of the free rotations (rad)
    least_overlap: np.ndarray    #: least overlap area over the offsets searched (mm^2); > 0: jammed
    phi_drive: np.ndarray        #: driven angle with the loaded (drive) flanks touching (rad)
    phi_coast: np.ndarray        #: driven angle with the other flanks touching (rad)
    pairs_drive: np.ndarray
    pairs_coast: np.ndarray
    r_ref: np.ndarray            #: driven pitch radius at phi (mm), for backlash in mm
    name: str
    #: the phases measured: all, or the first period's where the pair repeats (cyclic symmetry: each later phase its
    #: like there, turned; ``prove_pair``'s ``periods``)
    measured: int = -1
    #: the greatest distance of an outline vertex turned by a period from the vertex it lands on (mm; inf: not used)
    cyclic_mm: float = math.inf

    def __post_init__(self):
        if self.measured < 0:
            self.measured = len(self.phi)

    @property
    def te_drive(self) -> np.ndarray:
        """Transmission error of the loaded flank: actual driven angle minus the law (rad)."""
        return self.phi_drive - self.phi

    @property
    def backlash_angle(self) -> np.ndarray:
        return self.phi_coast - self.phi_drive

    @property
    def backlash_mm(self) -> np.ndarray:
        return self.backlash_angle * self.r_ref

    @property
    def jams(self) -> int:
        return int(np.count_nonzero(~np.isfinite(self.phi_drive)))

    @property
    def phi_run(self) -> np.ndarray:
        """Driven angle of the running position: loaded flanks touching; at a jammed phase the
        position of least overlap (the best the outlines allow)."""
        return np.where(np.isfinite(self.phi_drive), self.phi_drive, self.phi + self.offset)

    def theta_actual(self) -> np.ndarray:
        """Driver angle at which the teeth put the driven wheel at phi (interpolated on the
        measured pairs (phi_run, theta_law), periodic over the turn: theta(phi + 2 pi) =
        theta(phi) + 2 pi n)."""
        x, y = self.phi_run, self.theta_law
        n = round((self.theta_law[-1] - self.theta_law[0]) / (self.phi[-1] - self.phi[0]))
        per = 2 * math.pi
        xx = np.concatenate([x - per, x, x + per])
        yy = np.concatenate([y - per * n, y, y + per * n])
        order = np.argsort(xx)
        return np.interp(self.phi, xx[order], yy[order])

    def ratio_actual(self) -> tuple[np.ndarray, np.ndarray]:
        """(phi, d theta / d phi) delivered by the teeth: differences of the measured pairs
        (phi_run, theta_law) between consecutive phases (seed 000 Figure 2 from geometry); none where the running
        position stands or goes back (no division by a step of 0 there, nor its warning)."""
        x, y = self.phi_run, self.theta_law
        dx, dy = np.diff(x), np.diff(y)
        good = dx > 0
        return (0.5 * (x[1:] + x[:-1]))[good], dy[good] / dx[good]

    def measured_text(self) -> str:
        """How the phases were measured, for a report: every one, or the first period's with the repeat found."""
        if self.measured >= len(self.phi):
            return "each measured"
        return (f"the first period's {self.measured} measured, each later one its like there turned: both outlines "
                f"repeat under a period's turns to {self.cyclic_mm:.1e} mm")

    def summary(self) -> dict:
        te = self.te_drive[np.isfinite(self.te_drive)]
        bl = self.backlash_mm[np.isfinite(self.backlash_mm)]
        pd = self.pairs_drive[np.isfinite(self.phi_drive)]
        nan = math.nan
        return {
            "steps": int(len(self.phi)),
            "overlap_law_max_mm2": float(self.overlap_law.max()),
            "overlap_law_steps": int(np.count_nonzero(self.overlap_law > policy.OVERLAP_AREA_TOL_MM2)),
            "te_min_rad": float(te.min()) if len(te) else nan,
            "te_max_rad": float(te.max()) if len(te) else nan,
            "te_pp_rad": float(np.ptp(te)) if len(te) else nan,
            "backlash_min_mm": float(bl.min()) if len(bl) else nan,
            "backlash_max_mm": float(bl.max()) if len(bl) else nan,
            "contact_pairs_min": int(pd.min()) if len(pd) else 0,
            "contact_pairs_mean": float(pd.mean()) if len(pd) else nan,
            "jams": self.jams,
        }


def _turned_onto(P: np.ndarray, angle: float) -> float:
    """The greatest distance (mm) of a vertex of the closed polyline ``P`` turned by ``angle`` about the origin from the
    vertex it lands on: the one the first lands nearest to, and each next in the polyline's order (inf where the
    turned polyline is not the polyline renumbered)."""
    if len(P) == 0:
        return math.inf
    c, s = math.cos(angle), math.sin(angle)
    Q = np.column_stack([c * P[:, 0] - s * P[:, 1], s * P[:, 0] + c * P[:, 1]])
    k = int(np.argmin((P[:, 0] - Q[0, 0]) ** 2 + (P[:, 1] - Q[0, 1]) ** 2))
    return float(np.max(norms(Q - np.roll(P, -k, axis=0))))


def cyclic_mismatch(drv, dvn, phis: np.ndarray, theta: np.ndarray, M: int) -> float:
    """How far the pair is from repeating every ``M`` phases (mm): the greatest vertex distance of
    :func:`_turned_onto` for the driven outline turned by the driven angle of M phases and the driver's by its law
    angle over them, each a single loop; inf where the phases are not even over the turn or the law does not repeat
    (theta over each later period the first's plus the driver's turn, to 1e-9 rad).  The proof of the first M phases
    is then the proof of every period to within it (a wheel cut as one lobe and patterned: rounding, ~1e-13 mm)."""
    N = len(phis)
    if M <= 0 or N % M or len(drv.loops) != 1 or len(dvn.loops) != 1:
        return math.inf
    reps = N // M
    dphi, dth = float(phis[M] - phis[0]), float(theta[M] - theta[0])
    if abs(reps * dphi - 2 * math.pi) > 1e-9:
        return math.inf
    j = np.repeat(np.arange(reps), M)
    k = np.tile(np.arange(M), reps)
    if np.max(np.abs(phis - phis[k] - j * dphi)) > 1e-9 or np.max(np.abs(theta - theta[k] - j * dth)) > 1e-9:
        return math.inf
    # the driven wheel turns by -phi, the driver by +theta: each must map onto itself under its turn of a period
    return max(_turned_onto(dvn.points, -dphi), _turned_onto(drv.points, dth))


def _axis_annulus(o) -> None:
    """Tighten an Outline's far-point filter: the annulus about the gear axis (the origin of its
    body frame) that holds every boundary point (a valid bound, much tighter than the one about
    the bounding-box centre for a ring of teeth)."""
    d = norms(o.points)
    o.center = np.zeros(2)
    o.r_min = float(d.min())
    o.radius = float(d.max())


def _outer_only(profile):
    """The outer loop of a profile as a closed polyline list (bores cannot touch the mate)."""
    from ...geometry.profile import Profile

    if isinstance(profile, Profile):
        return [profile.outer.polyline(policy.MOTION_CHORD_TOL_MM)]
    return profile


def prove_pair(driver_profile, driven_profile, L: float, theta_of_phi, phis, r_ref, *, name: str = "mesh",
               windows: int | None = None, pitch_mm: float | None = None, tick=None, on_jam=None,
               periods: int = 1) -> PairProof:
    """Full-cycle proof of the pair (see the module docstring).  ``theta_of_phi``: vectorised law
    theta(phi) (rad); ``r_ref``: vectorised driven pitch radius r_H(phi) (mm); ``pitch_mm``:
    tooth pitch on the pitch curve (sets the search span of non-conjugate teeth); ``tick(done)``: told the
    phases done after each window (progress only); ``on_jam()``: called once, as soon as a phase is found jammed
    (no free position: the pair has no running position there, whatever the other phases give), so that work that
    needs a running pair stops then, not after the whole proof.

    ``periods``: the law's periods over ``phis`` (a whole turn sampled evenly).  Where both outlines repeat under the
    turns of one period (the driven wheel's 2 pi / periods, the driver's theta over it) to ``policy.CYCLIC_TOL_MM`` at
    every vertex (:func:`cyclic_mismatch`; a wheel cut as one lobe and patterned does, to rounding) and the law does
    too, the phases of the first period are measured and each later phase is its like there, turned (cyclic symmetry:
    the same positions of the same edges); unless a phase of that period needed the search for a running position
    (teeth not conjugate), whose start carries over from phase to phase: then every phase is measured."""
    jammed = False

    def jam():
        nonlocal jammed
        if not jammed:
            jammed = True
            if on_jam is not None:
                on_jam()

    drv = outline(_outer_only(driver_profile))
    dvn = outline(_outer_only(driven_profile))
    _axis_annulus(drv)
    phis = np.asarray(phis, float)
    N = len(phis)
    theta = np.asarray(theta_of_phi(phis), float)
    rr = np.asarray(r_ref(phis), float)
    reach = drv.radius
    d_dvn = norms(dvn.points)
    r_dvn, r_root = float(d_dvn.max()), float(d_dvn.min())
    max_angle = policy.MOTION_MAX_FREE_ANGLE_RAD
    search = 0.5 * (pitch_mm if pitch_mm else 8.0) / float(np.min(rr))
    margin_a = math.asin(min(1.0, (reach + 1.0) / L)) + max_angle + 2 * search
    r_in = max(0.0, min(L - reach, r_root) - 1.0)
    # the driver's likewise: the driven tips reach to L - r_dvn from its axis (deeper than its root on a jammed mount)
    r_in_drv = max(0.0, min(L - r_dvn, drv.r_min) - 1.0)
    # half-width (about the line of centres) of the driver's body angles whose points can come
    # within r_dvn + 1 of the driven axis: cos(beta + theta) <= (R^2 - L^2 - rho^2) / (2 L rho)
    rho = np.linspace(max(drv.r_min, 1e-3), reach, 64)
    c = np.clip(((r_dvn + 1.0) ** 2 - L * L - rho * rho) / (2 * L * rho), -1.0, 1.0)
    hw_drv = float(np.max(math.pi - np.arccos(c))) + 0.05
    lens = _MeetCrops(drv, dvn, L, reach + 1.0, r_dvn + 1.0)

    def run(phis, theta, rr, windows, tick):
        """The phases ``phis`` measured: (overlap, offset, least, pdrv, pcst, nd, nc, whether a phase needed the
        search for a running position)."""
        N = len(phis)
        edges = np.linspace(phis.min(), phis.max() + 1e-12, windows + 1)
        overlap = np.zeros(N)
        offset = np.zeros(N)
        least = np.zeros(N)
        pdrv = np.full(N, np.nan)
        pcst = np.full(N, np.nan)
        nd = np.zeros(N, int)
        nc = np.zeros(N, int)
        prev, warm, searched = 0.0, False, False
        for w in range(windows):
            idx = np.nonzero((phis >= edges[w]) & (phis < edges[w + 1]))[0]
            if len(idx) == 0:
                continue
            loops = crop_to_sector(dvn.section, phis[idx].min() - margin_a, phis[idx].max() + margin_a, r_in,
                                   r_dvn + 1.0)
            crop = outline(loops)
            _axis_annulus(crop)
            # the driver part that can come within the driven wheel's outer radius during the window
            tha, thb = float(theta[idx].min()), float(theta[idx].max())
            dcrop = outline(crop_to_sector(drv.section, math.pi - thb - hw_drv, math.pi - tha + hw_drv,
                                          r_in_drv, reach + 1.0))
            _axis_annulus(dcrop)
            tmap = {float(p): float(t) for p, t in zip(phis[idx], theta[idx])}
            tr = transmission_sweep(dcrop, (L, 0.0), crop, (0.0, 0.0), lambda p: tmap[float(p)], phis[idx],
                                    r_ref=rr[idx], name=name)
            overlap[idx] = tr.overlap_area
            for j, k in enumerate(idx):
                if tr.overlap_area[j] <= policy.OVERLAP_AREA_TOL_MM2:
                    pdrv[k] = phis[k] - tr.free_back[j]
                    pcst[k] = phis[k] + tr.free_fwd[j]
                    nd[k], nc[k] = tr.pairs_drive[j], tr.pairs_coast[j]
                    prev, warm = 0.0, False
                    continue
                # not conjugate: the running position nearest the previous offset
                searched = True
                crops = lambda h, p_mid=float(phis[k]) + prev, th=float(theta[k]): lens.at(dcrop, crop, p_mid, th,
                                                                                           h)
                off, area = _least_overlap(dcrop, crop, L, float(phis[k]), float(theta[k]), prev, search, warm,
                                           crops)
                offset[k], least[k] = off, area
                prev, warm = off, True
                if area > policy.OVERLAP_AREA_TOL_MM2:
                    jam()
                    continue  # jammed: no free position near the law's
                p = np.array([phis[k] + off])
                t1 = transmission_sweep(dcrop, (L, 0.0), crop, (0.0, 0.0), lambda _p, t=float(theta[k]): t, p,
                                        r_ref=rr[k], name=name)
                if t1.overlap_area[0] > policy.OVERLAP_AREA_TOL_MM2:
                    least[k] = t1.overlap_area[0]
                    jam()
                    continue
                pdrv[k] = phis[k] + off - t1.free_back[0]
                pcst[k] = phis[k] + off + t1.free_fwd[0]
                nd[k], nc[k] = t1.pairs_drive[0], t1.pairs_coast[0]
            if tick is not None:
                tick(int(idx.max()) + 1)
        return overlap, offset, least, pdrv, pcst, nd, nc, searched

    if windows is None:  # 16 a turn: each crop's cost grows with its span far less than in proportion (the reach
        # on either side is the most of it); 0.1 rad windows (63) gave the same values, to the bit, at 1.25 times the
        # time over the proofs of make's ten pairs
        windows = max(1, int(round(2 * math.pi / policy.PAIR_PROOF_WINDOW_RAD)))
    M = N // periods if periods > 1 and N % periods == 0 else N
    if tick is not None and M < N:  # the first period's windows, then maybe the whole turn's: told only what is new
        told, outer = [0], tick

        def tick(done):
            if done > told[0]:
                told[0] = done
                outer(done)
    mismatch = cyclic_mismatch(drv, dvn, phis, theta, M) if M < N else math.inf
    if mismatch <= policy.CYCLIC_TOL_MM:
        part = run(phis[:M], theta[:M], rr[:M], max(1, int(round(windows / periods))), tick)
        if not part[-1]:
            reps = N // M
            overlap, offset, least, _, _, nd, nc = (np.tile(a, reps) for a in part[:7])
            # each later phase the first period's turned: its driven angles moved by the phases' own difference
            back, fwd = part[3] - phis[:M], part[4] - phis[:M]
            pdrv = np.concatenate([part[3]] + [phis[j * M:(j + 1) * M] + back for j in range(1, reps)])
            pcst = np.concatenate([part[4]] + [phis[j * M:(j + 1) * M] + fwd for j in range(1, reps)])
            if tick is not None:
                tick(N)
            return PairProof(phis, theta, overlap, offset, least, pdrv, pcst, nd, nc, rr, name, M, mismatch)
    overlap, offset, least, pdrv, pcst, nd, nc, _ = run(phis, theta, rr, windows, tick)
    return PairProof(phis, theta, overlap, offset, least, pdrv, pcst, nd, nc, rr, name)


class _LensCrops:
    """The two crops a least-overlap search (:func:`_least_overlap`) intersects, cut down to where the bodies can meet.

    The driver (at theta about (L, 0)) reaches ``reach`` from its axis and the driven wheel (about the origin)
    ``r_dvn`` from its own: every point of an overlap lies within ``r_dvn`` of the driven axis and within ``reach``
    of the driver's.  So the driver's crop is cut to the disc of radius ``r_dvn`` about the driven axis (in the
    driver's frame: fixed while the driven offset is searched), the driven crop to the disc about the driver axis's
    mid position that holds its discs of radius ``reach`` over the offsets searched (the axis moves on the circle of
    radius L, by at most L times the angle).  The overlap is the same region of the same edges, found among
    fewer vertices (the seed-000 and seed-002 table pairs: 2 300-3 000 instead of 5 000-7 700 a body, each overlap
    equal to the last bit).  A cut is kept for the next phases while their discs lie inside it (cut ``spare`` mm
    wider than needed); the area's boolean is the only cost it saves.  :class:`_MeetCrops` cuts tighter and hands
    over to these discs where its envelopes do not apply."""

    def __init__(self, L: float, reach: float, r_dvn: float, spare: float = 1.0):
        self.L, self.reach, self.r_dvn, self.spare = L, reach, r_dvn, spare
        self.drv = self.dvn = None  # (source crop, centre x, y, radius, the cut)

    def _cut(self, held, src, cx: float, cy: float, R: float):
        if held is not None and held[0] is src and math.hypot(cx - held[1], cy - held[2]) + R <= held[3]:
            return held
        R1 = R + self.spare
        return (src, cx, cy, R1, _Cut(cut_to_disc(src.section, cx, cy, R1)))

    def at(self, dcrop, crop, p_mid: float, theta: float, half: float):
        """(driver cut, driven cut) for the driver at ``theta`` and the driven wheel within ``p_mid`` +- ``half``."""
        L = self.L
        self.drv = self._cut(self.drv, dcrop, -L * math.cos(theta), L * math.sin(theta), self.r_dvn)
        self.dvn = self._cut(self.dvn, crop, L * math.cos(p_mid), L * math.sin(p_mid), self.reach + L * (half + 1e-3))
        return self.drv[4], self.dvn[4]


class _MeetCrops:
    """The two crops a least-overlap search (:func:`_least_overlap`) intersects, cut down to where the bodies can meet
    at any driven offset of the span asked (the warm search's quarter span, or the whole).

    Each body lies within its polar envelope (:class:`~propulsor.checks.motion.outlines.PolarEnvelope`); the driven
    one's widened by the half span asked, so that it holds the driven wheel at every offset of the span.  At a phase
    both envelopes are placed in the driver's frame (the driven one at the middle offset) and intersected: every
    overlap point of every offset of the span lies in that region Z (an overlap point is in both bodies).  The
    driver's crop is cut to the sector about its axis that holds Z (1 mm more), the driven crop to the sector about
    its own that holds Z at every offset (Z placed in the driven frame at the middle offset, its angles widened by
    the half span: the offsets turn it about the driven axis).  A cut's edges inside one body then lie outside the
    other, so the overlap is the same region of the same edges (each overlap equal to the last bit), found among
    fewer vertices than the discs' cuts (:class:`_LensCrops`, which takes over where Z is empty or an axis lies near
    it).  A cut is kept for the next phases while their sectors lie inside it (cut ``spare`` mm and ``spare_rad``
    wider than needed)."""

    def __init__(self, drv, dvn, L: float, reach: float, r_dvn: float, spare: float = 1.0,
                 spare_rad: float = 0.03):
        self.L, self.spare = L, spare
        self.env_drv = PolarEnvelope(drv)
        self.dvn_body = dvn
        #: the driven wheel's envelopes by the half span they are widened for (+ 1e-3 rad), made when first asked
        self.envelopes: dict[float, PolarEnvelope] = {}
        self.lens = _LensCrops(L, reach, r_dvn, spare)
        self.drv, self.dvn = (HeldSectorCut(spare_rad, spare, _Cut) for _ in range(2))

    def at(self, dcrop, crop, p_mid: float, theta: float, half: float):
        """(driver cut, driven cut) for the driver at ``theta`` and the driven wheel within ``p_mid`` +- ``half``."""
        L = self.L
        c, s = math.cos(-theta - p_mid), math.sin(-theta - p_mid)
        ct, st = math.cos(-theta), math.sin(-theta)
        M = np.array([[c, -s, -ct * L], [s, c, -st * L]])  # driven body -> driver body (_overlap_at's)
        env_dvn = self.envelopes.get(half)
        if env_dvn is None:
            env_dvn = self.envelopes[half] = PolarEnvelope(self.dvn_body, half + 1e-3)
        near = max(self.env_drv.r_max, env_dvn.r_max) + 2.0 * self.spare >= L
        Z = [] if near else (self.env_drv.section ^ env_dvn.section.transform(M)).to_polygons()
        if not len(Z):
            return self.lens.at(dcrop, crop, p_mid, theta, half)
        V = np.vstack([np.asarray(z, float) for z in Z])
        b0, b1, rd = polar_extent(V, math.pi - theta)
        # Z in the driven frame at the middle offset: x_dvn = R^T (x_drv - t)
        W = (V - M[:, 2]) @ M[:, :2]
        g0, g1, rv = polar_extent(W, p_mid)
        if b1 - b0 > 0.5 * math.pi or g1 - g0 > 0.5 * math.pi:
            return self.lens.at(dcrop, crop, p_mid, theta, half)
        w = half + 1e-3
        return (self.drv.cut(dcrop.section, math.pi - theta, b0 - 1e-3, b1 + 1e-3, rd + 1.0),
                self.dvn.cut(crop.section, p_mid, g0 - w, g1 + w, rv + 1.0))


class _Cut:
    __slots__ = ("section",)

    def __init__(self, section):
        self.section = section


def _overlap_at(drv, dvn, L, theta, p) -> float:
    """Overlap area (mm^2) with the driven wheel at -p and the driver at +theta about (L, 0)."""
    c, s = math.cos(-theta - p), math.sin(-theta - p)
    ct, st = math.cos(-theta), math.sin(-theta)
    M = np.array([[c, -s, -ct * L], [s, c, -st * L]])  # driven body -> driver body
    return float((drv.section ^ dvn.section.transform(M)).area())


def _least_overlap(drv, dvn, L, phi, theta, start, half, warm: bool, crops=None):
    """Driven offset (rad) within start +- half of least overlap with the driver (0 inside the free
    interval): a 13-point scan refined by a bounded Brent search; ``warm`` (the previous phase
    was searched too): first a Brent search within start +- half/4, kept unless it ends on its
    bracket.  ``crops(h)``: the (driver, driven) sections whose overlap is that of ``drv`` and ``dvn`` at every
    offset within start +- h (:class:`_MeetCrops`: the narrower span's are smaller)."""
    from scipy.optimize import minimize_scalar

    tol = policy.OVERLAP_AREA_TOL_MM2

    def area_of(h):
        d, v = (drv, dvn) if crops is None else crops(h)
        return lambda o: _overlap_at(d, v, L, theta, phi + o)

    if warm:
        q = 0.25 * half
        res = minimize_scalar(area_of(q), bounds=(start - q, start + q), method="bounded", options={"xatol": 1e-6})
        if res.fun <= tol or abs(res.x - start) < 0.9 * q:
            return float(res.x), float(res.fun)
    f = area_of(half)
    grid = start + np.linspace(-half, half, 13)
    vals = np.array([f(o) for o in grid])
    i = int(np.argmin(vals))
    if vals[i] <= tol:
        return float(grid[i]), float(vals[i])
    lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
    res = minimize_scalar(f, bounds=(lo, hi), method="bounded", options={"xatol": 1e-6})
    if res.fun < vals[i]:
        return float(res.x), float(res.fun)
    return float(grid[i]), float(vals[i])
