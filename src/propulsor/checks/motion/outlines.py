"""Outlines of planar bodies: closed polylines, oriented by nesting, indexed for distance queries."""

from __future__ import annotations

import math
import weakref
from functools import cached_property
from typing import Sequence

import manifold3d as m3d
import numpy as np
from scipy.spatial import cKDTree

from ... import policy
from ...errors import InputError, require, require_positive
from ...geometry.profile import Profile
from ...planar import box, norms

__all__ = ['Outline', 'outline', 'crop_to_sector', 'cut_to_disc', 'cut_to_sector', 'FacingCut', 'HeldSectorCut',
           'PolarEnvelope', 'offset_outline', 'polar_extent']


def _signed_area(p: np.ndarray) -> float:
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def _points_in_polygon(pts: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Even-odd ray casting of many points against one closed polygon."""
    x, y = pts[:, 0][:, None], pts[:, 1][:, None]
    a, b = poly, np.roll(poly, -1, axis=0)
    ax, ay, bx, by = a[:, 0][None], a[:, 1][None], b[:, 0][None], b[:, 1][None]
    cond = (ay > y) != (by > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xi = ax + (y - ay) * (bx - ax) / (by - ay)
    return (np.count_nonzero(cond & (x < xi), axis=1) % 2) == 1


def _clean_loop(p, name: str) -> np.ndarray:
    p = np.asarray(p, float)
    require(p.ndim == 2 and p.shape[1] == 2, name, p.shape, "must be an (n, 2) array of points")
    require(bool(np.all(np.isfinite(p))), name, "non-finite", "points must be finite")
    if len(p) > 1 and np.linalg.norm(p[0] - p[-1]) <= policy.POINT_TOL_MM:
        p = p[:-1]
    step = norms(np.diff(p, axis=0, append=p[:1]))
    p = p[step > policy.POINT_TOL_MM]  # drop repeated vertices
    require(len(p) >= 3, name, len(p), "a closed loop needs at least 3 distinct points")
    return p


def _orient_by_nesting(loops: list[np.ndarray]) -> list[np.ndarray]:
    """Outer loops (even nesting depth) CCW, holes (odd depth) CW: material on the left."""
    out = []
    for i, p in enumerate(loops):
        depth = sum(bool(_points_in_polygon(p[:1], q)[0]) for j, q in enumerate(loops) if j != i)
        ccw = depth % 2 == 0
        out.append(p if (_signed_area(p) > 0) == ccw else p[::-1].copy())
    return out


def _densify(p: np.ndarray, max_seg: float) -> np.ndarray:
    """Insert points on the straight edges so that no edge exceeds max_seg (same polyline)."""
    q = np.roll(p, -1, axis=0)
    n = np.maximum(1, np.ceil(norms(q - p) / max_seg).astype(int))
    if np.all(n == 1):
        return p
    idx = np.repeat(np.arange(len(p)), n)
    k = np.arange(len(idx)) - np.repeat(np.cumsum(n) - n, n)
    t = (k / np.repeat(n, n))[:, None]
    return p[idx] + t * (q[idx] - p[idx])


class Outline:
    """A planar body prepared for motion checks (in its own body frame).

    ``loops``: closed polylines (first point not repeated), material on the left;
    ``section``: the manifold3d CrossSection of those loops (fill rule Positive; made when first asked for);
    ``points``: all vertices after subdividing long edges, with edge arrays
    ``seg_a``/``seg_b`` (edge k runs from point k to point ``nxt[k]``), ``prev``,
    ``loop_id``, ``arclen`` (arc length of each vertex along its loop) and a
    cKDTree of the points (``tree``, built when first asked for); ``center``, ``r_min``, ``radius``: an annulus holding
    every boundary point (used to discard far points before any tree query).
    """

    def __init__(self, loops: Sequence[np.ndarray], max_segment: float = policy.MOTION_MAX_SEGMENT_MM):
        require_positive("max_segment", max_segment, "mm")
        require(len(loops) >= 1, "loops", len(loops), "need at least one closed loop")
        cleaned = [_clean_loop(p, f"loops[{i}]") for i, p in enumerate(loops)]
        self.loops = _orient_by_nesting(cleaned)
        dense = [_densify(p, max_segment) for p in self.loops]
        sizes = np.array([len(d) for d in dense])
        starts = np.concatenate([[0], np.cumsum(sizes)[:-1]])
        self.points = np.vstack(dense)
        self.loop_id = np.repeat(np.arange(len(dense)), sizes)
        local = np.arange(len(self.points)) - starts[self.loop_id]
        self.nxt = starts[self.loop_id] + (local + 1) % sizes[self.loop_id]
        self.prev = starts[self.loop_id] + (local - 1) % sizes[self.loop_id]
        self.seg_a = self.points
        self.seg_b = self.points[self.nxt]
        self.seg_len = norms(self.seg_b - self.seg_a)
        self.half_len = 0.5 * float(self.seg_len.max())
        cum = np.cumsum(self.seg_len)
        loop_start_cum = (cum - self.seg_len)[starts]
        self.arclen = cum - self.seg_len - loop_start_cum[self.loop_id]
        # each loop's edges are one slice (the sum of the same elements in the same order as a mask would select)
        self.perimeter = np.array([self.seg_len[a:a + m].sum() for a, m in zip(starts.tolist(), sizes.tolist())])
        lo, hi = box(self.points)
        self.center = 0.5 * (lo + hi)
        dc = norms(self.points - self.center)
        self.radius = float(dc.max())  # an edge is farthest from center at an end
        # ... but may come nearer between its ends: r_min is the least distance of any edge from center, so that
        # the whole boundary lies in the annulus r_min .. radius about center
        e = self.seg_b - self.seg_a
        t = np.clip(np.einsum("ij,ij->i", self.center - self.seg_a, e) / (self.seg_len * self.seg_len), 0.0, 1.0)
        self.r_min = float(norms(self.seg_a + t[:, None] * e - self.center).min())

    @cached_property
    def section(self) -> m3d.CrossSection:
        """The manifold3d CrossSection of the loops (fill rule Positive), made at its first use (a sweep whose
        bodies stay apart, or a backlash search, never asks for it)."""
        return m3d.CrossSection([np.ascontiguousarray(p) for p in self.loops], m3d.FillRule.Positive)

    @cached_property
    def tree(self) -> cKDTree:
        """A cKDTree of the points, built at its first query (most outlines are searched on their vertex grid
        alone: :mod:`.nearest`)."""
        return cKDTree(self.points)

    def boundary_lower_bound(self, P: np.ndarray) -> np.ndarray:
        """A lower bound of the distance from each point (body frame) to the boundary (annulus test)."""
        d = norms(P - self.center)
        return np.maximum(d - self.radius, self.r_min - d)

    @property
    def area(self) -> float:
        return float(self.section.area())

    def __len__(self) -> int:
        return len(self.points)


_OUTLINE_CACHE: "weakref.WeakKeyDictionary[Profile, dict]" = weakref.WeakKeyDictionary()


def outline(body, chord_tol: float = policy.MOTION_CHORD_TOL_MM, max_segment: float = policy.MOTION_MAX_SEGMENT_MM) -> Outline:
    """Outline of a Profile (sampled to chord_tol, cached per profile) or of a list of closed polylines.

    An :class:`Outline` passes through unchanged.
    """
    if isinstance(body, Outline):
        return body
    if isinstance(body, Profile):
        require_positive("chord_tol", chord_tol, "mm")
        per = _OUTLINE_CACHE.setdefault(body, {})
        key = (float(chord_tol), float(max_segment))
        if key not in per:
            per[key] = Outline(body.polylines(chord_tol), max_segment)
        return per[key]
    if isinstance(body, np.ndarray) and body.ndim == 2:
        body = [body]
    try:
        loops = list(body)
    except TypeError:
        raise InputError("body", type(body).__name__, "must be a Profile, an Outline or a list of closed (n, 2) polylines") from None
    return Outline(loops, max_segment)


def crop_to_sector(section: m3d.CrossSection, a0: float, a1: float, r_in: float, r_out: float) -> list[np.ndarray]:
    """Loops of ``section`` inside the annular sector a0..a1, r_in..r_out (about the origin)."""
    n = max(8, int(math.ceil((a1 - a0) / 0.02)))
    a = np.linspace(a0, a1, n)
    outer = np.column_stack([r_out * np.cos(a), r_out * np.sin(a)])
    inner = np.column_stack([r_in * np.cos(a[::-1]), r_in * np.sin(a[::-1])]) if r_in > 0 else np.zeros((1, 2))
    wedge = m3d.CrossSection([np.ascontiguousarray(np.vstack([outer, inner]))], m3d.FillRule.Positive)
    return [np.asarray(p, float) for p in (section ^ wedge).to_polygons()]


def cut_to_disc(section: m3d.CrossSection, cx: float, cy: float, R: float, sides: int = 256) -> m3d.CrossSection:
    """``section`` inside the disc of radius ``R`` about (cx, cy): cut by a regular polygon of ``sides`` sides whose
    edges touch the circle from outside (so the whole disc is kept, and up to R / cos(pi / sides) of its
    neighbourhood)."""
    a = np.linspace(0.0, 2.0 * math.pi, sides, endpoint=False)
    Rc = R / math.cos(math.pi / sides)
    disc = m3d.CrossSection([np.column_stack([cx + Rc * np.cos(a), cy + Rc * np.sin(a)])], m3d.FillRule.Positive)
    return section ^ disc


class PolarEnvelope:
    """A star polygon about a body's axis (its body frame's origin) that holds the whole body: per bin of polar angle,
    the largest radius of its outline there (each edge counted in every bin its angle sweeps: an edge is farthest
    from the axis at an end), the bin's arc replaced by the chord that touches it from outside.  A point of the body
    at angle psi lies on the ray from the axis at psi, which leaves the body through an outline point farther out at
    the same angle: within the envelope.  ``widen`` (rad): each bin takes the largest radius of the bins within that
    angle, so that the envelope holds the body turned by up to ``widen`` either way too."""

    BINS = 720

    def __init__(self, o, widen: float = 0.0):
        n = self.BINS
        w = 2.0 * math.pi / n
        a, b = o.seg_a, o.seg_b
        a0 = np.arctan2(a[:, 1], a[:, 0])
        d = (np.arctan2(b[:, 1], b[:, 0]) - a0 + math.pi) % (2.0 * math.pi) - math.pi  # the edge's sweep
        r = np.maximum(norms(a), norms(b))
        lo = np.floor((np.minimum(a0, a0 + d) + math.pi) / w).astype(np.int64)
        span = np.floor((np.maximum(a0, a0 + d) + math.pi) / w).astype(np.int64) - lo
        rb = np.zeros(n)
        for s in range(int(span.max()) + 1):
            m = span >= s
            np.maximum.at(rb, (lo[m] + s) % n, r[m])
        k = int(math.ceil(widen / w)) + 1 if widen > 0.0 else 0
        if k:
            rb = np.max(np.stack([np.roll(rb, j) for j in range(-k, k + 1)]), axis=0)
        self.r_max = float(rb.max())
        R = rb / math.cos(0.5 * w) * (1.0 + 1e-9)
        A = -math.pi + w * np.arange(n + 1)
        pts = np.empty((2 * n, 2))
        pts[0::2, 0], pts[0::2, 1] = R * np.cos(A[:-1]), R * np.sin(A[:-1])
        pts[1::2, 0], pts[1::2, 1] = R * np.cos(A[1:]), R * np.sin(A[1:])
        self.section = m3d.CrossSection([pts], m3d.FillRule.Positive)


def cut_to_sector(section: m3d.CrossSection, a0: float, a1: float, r: float) -> m3d.CrossSection:
    """``section`` inside the sector of the disc of radius ``r`` about the origin between the polar angles a0 < a1
    (cut by a polygon whose arc's chords lie outside the circle: the whole sector is kept)."""
    n = max(2, int(math.ceil((a1 - a0) / 0.02)))
    a = np.linspace(a0, a1, n + 1)
    R = r / math.cos(0.5 * (a1 - a0) / n)
    pts = np.vstack([[0.0, 0.0], np.column_stack([R * np.cos(a), R * np.sin(a)])])
    return section ^ m3d.CrossSection([np.ascontiguousarray(pts)], m3d.FillRule.Positive)


def polar_extent(P: np.ndarray, centre: float) -> tuple[float, float, float]:
    """(least, largest polar angle of points ``P`` measured from ``centre`` (rad, within +-pi), their largest
    radius), about the frame's origin."""
    rel = (np.arctan2(P[:, 1], P[:, 0]) - centre + math.pi) % (2.0 * math.pi) - math.pi
    return float(rel.min()), float(rel.max()), float(norms(P).max())


class HeldSectorCut:
    """A section cut to a sector about its frame's origin (:func:`cut_to_sector`), the sector asked for widened by
    ``spare_rad`` either way and ``spare_mm`` outwards, and kept (``wrap`` of the cut: the same object) for later
    requests of the same section whose sectors lie inside it."""

    def __init__(self, spare_rad: float, spare_mm: float = 0.0, wrap=lambda cs: cs):
        self.spare_rad, self.spare_mm, self.wrap, self.held = spare_rad, spare_mm, wrap, None

    def cut(self, section, centre: float, a0: float, a1: float, r: float):
        """The cut holding the sector ``centre + a0`` .. ``centre + a1`` (rad) out to radius ``r``."""
        h = self.held  # (section, centre, a0, a1, r, the wrapped cut)
        if h is not None and h[0] is section and r <= h[4]:
            shift = (centre - h[1] + math.pi) % (2.0 * math.pi) - math.pi  # this centre from the held one's
            if h[2] <= a0 + shift and a1 + shift <= h[3]:
                return h[5]
        a0, a1, r = a0 - self.spare_rad, a1 + self.spare_rad, r + self.spare_mm
        self.held = (section, centre, a0, a1, r, self.wrap(cut_to_sector(section, centre + a0, centre + a1, r)))
        return self.held[5]


class FacingCut:
    """A body B's section cut to the sector about its body frame's origin (its axis) that holds a region of another
    body seen in B's frame, 1 mm and 0.01 rad more, and ``spare`` rad more again (:class:`HeldSectorCut`, kept for
    later regions while their sectors lie inside it): every point B has in common with the region lies in the
    region, so the cut's edges inside B lie outside it and each intersection with the region is the one of B's whole
    section, bit for bit (a ring's window against a planet: 2 100 of the planet's 9 000 vertices, the boolean 0.69 ->
    0.22 ms).  B's whole section where the region seen from B's origin spans more than 0.9 pi (or surrounds it)."""

    def __init__(self, B, spare: float):
        self.B, self.sector = B, HeldSectorCut(spare)

    def section(self, P: np.ndarray):
        """The section for a region whose boundary's vertices, in B's frame, are ``P`` (n, 2)."""
        centre = math.atan2(float(P[:, 1].mean()), float(P[:, 0].mean()))
        a0, a1, r = polar_extent(P, centre)
        if a1 - a0 + 0.02 > 0.9 * math.pi:
            return self.B.section
        return self.sector.cut(self.B.section, centre, a0 - 0.01, a1 + 0.01, r + 1.0)


def offset_outline(o: Outline, inward: float, shift=(0.0, 0.0)) -> Outline:
    """The outline's outer loop offset along its normals by ``inward`` (mm; material removed, < 0: added; round
    joins) and translated by ``shift``: a part made thinner or thicker, or turning off its axis."""
    loops = o.loops
    if inward != 0.0:
        cs = o.section.offset(-inward, m3d.JoinType.Round, 2.0, 64)
        loops = [np.asarray(p, float) for p in cs.to_polygons() if len(p) >= 3]
        loops = [max(loops, key=lambda p: abs(_signed_area(p)))]
    return Outline([p + np.asarray(shift, float) for p in loops])
