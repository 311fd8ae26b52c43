"""Closed outlines of the generated non-circular gears: the teeth of ``gears.noncircular_teeth``
fitted piece by piece and chained into one loop.

Every piece (fillet, flank, tip equidistant, flank, fillet, root equidistant) is fitted by a
clamped cubic B-spline within ``policy.SPLINE_FIT_TOL_MM``; consecutive pieces share their end
points exactly.  Body frames: see ``gears.noncircular_teeth``.  The papers' sector teeth are in
``geometry.sector_outline``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..gears.noncircular import PitchCurves
from ..gears.noncircular_teeth import ArcFrame, ToothSpec, generate_teeth
from ..policy import OUTLINE_JOINT_TOL_MM, OUTLINE_JOINT_TOL_REPHASED_MM, SPLINE_FIT_TOL_MM
from ..gears.curve_batch import evaluate_curves
from .bspline import fit_curve, fit_curves
from .profile import Loop, Profile, Spline

__all__ = ["GeneratedGear", "generate_gear", "fit_piece", "FIT_N0"]

#: initial interpolation points of every spline fit (refined adaptively to the tolerance):
#: few knots keep the tessellation of the solids (OCCT meshes every knot span) and the DXF light
FIT_N0 = 8


def fit_piece(func, u0, u1, tol):
    """B-spline of one outline piece ``func`` on [u0, u1] within ``tol`` (``FIT_N0`` initial points)."""
    return fit_curve(func, u0, u1, tol, n0=FIT_N0)


@dataclass
class GeneratedGear:
    """A generated non-circular gear: its profile and the per-tooth record."""

    role: str
    profile: Profile
    teeth: list
    root_min_radius: float
    pitch_points: np.ndarray  # (n, 2) pitch curve in the body frame (reference)
    root_gaps: tuple = ()     # straight root bridges (mm) of a re-phased shaper's sides (ToothSide.root_gap_mm)

    @property
    def undercut_teeth(self) -> int:
        return sum(t.undercut for t in self.teeth)

    @property
    def shortened_teeth(self) -> int:
        return sum(t.shortened for t in self.teeth)

    @property
    def shaper_teeth(self) -> int:
        return sum(t.right == "shaper" or t.left == "shaper" for t in self.teeth)

    @property
    def tip_thickness_min(self) -> float:
        return min(t.tip_thickness_mm for t in self.teeth)


def _turned(seg, c: float, s: float):
    """A spline piece turned about the body axis by the angle of cosine c and sine s (each pole by its own products,
    element by element: the same floats on every machine, whatever its BLAS)."""
    x, y = seg.poles[:, 0], seg.poles[:, 1]
    return Spline(seg.knots.copy(), np.column_stack([c * x - s * y, s * x + c * y]), seg.degree)


def _turn(segs: list, angle: float) -> list:
    """The pieces turned about the body axis by ``angle`` (rad)."""
    c, s = math.cos(angle), math.sin(angle)
    return [_turned(seg, c, s) for seg in segs]


def generate_gear(pc: PitchCurves, role: str, spec: ToothSpec, frame: ArcFrame | None = None,
                  tol: float = SPLINE_FIT_TOL_MM, start=None, tick=None, lobe: bool = True) -> GeneratedGear:
    """Closed outline of the generated teeth of one gear of the pair (``generate_teeth``), fitted
    and chained counter-clockwise on the body (increasing polar angle).  `start(fn, *args)`, when given,
    runs ``fn(*args)`` beside this process and returns an object whose ``result()`` gives its value (the
    caller's process pool: this layer forks nothing itself): half the teeth of a large gear are fitted
    that way.  ``tick(done, total)``, when given, is told the teeth generated, then those fitted here (total: twice
    the teeth cut; progress only).

    A wheel of equal lobes is cut as one lobe and patterned (``generate_teeth(..., lobe=True)``): the first z / lobes
    teeth and the roots after them are generated and fitted, the lobe's last root ending at the next lobe's first
    tooth (the first tooth turned by a lobe), and the lobe's pieces are turned by j lobes, j = 1 .. lobes - 1, as a
    CAD circular pattern does: the outline repeats exactly.  ``lobe=False``: every tooth cut on its own (the lobes
    then repeat to within the fits' tolerance ``tol``)."""
    g = generate_teeth(pc, role, spec, frame, None if tick is None else (lambda k, z: tick(k, 2 * z)), lobe=lobe)
    curve, n, m = g.curve, g.n, spec.m
    z = len(g.sides)  # the teeth cut: all, or one lobe's
    # tooth k + z turned by ``turn`` about the body axis: the driven wheel on by a lobe, the driver back (its teeth
    # run clockwise on its body); ``dphi``: the driven angle of a lobe
    turn = (1.0 if role == "driven" else -1.0) * 2 * math.pi / g.lobes
    dphi = 2 * math.pi / (g.lobes * (1 if role == "driven" else n))
    teeth_sides, tips, teeth = g.sides, g.tips, g.teeth
    # fit and chain (counter-clockwise on the body: increasing polar angle)
    order = list(range(z)) if role == "driven" else list(range(z - 1, -1, -1))
    units = _fit_units(curve, teeth_sides, tips, order, tol, start,
                       None if tick is None else (lambda k: tick(min(2 * z, z + k), 2 * z)))
    # the tooth the last space ends at, counter-clockwise: the first (a whole wheel's), or the first's in the next
    # lobe that way (the driven wheel's next, tooth z; the driver's last, tooth z lobes - 1: ``lap`` lobes on)
    lap = 1 if role == "driven" else g.lobes - 1
    if g.lobes > 1:
        first = units[0]
        after = (_turn(first[0], lap * turn), first[1] + lap * dphi, first[2] + lap * dphi, first[3], first[4])
    else:
        after = units[0]
    nexts = units[1:] + [after]
    segs = []
    root_r = []
    hf = -spec.h_root
    spaces = []  # per space: (phi of its left root point, of the next tooth's right one), unwrapped
    for i, (_unit, _phr, phl, _gr, _gl) in enumerate(units):
        ph_a, ph_b = phl, nexts[i][1]
        # unwrap: the next tooth's right root point follows counter-clockwise
        if role == "driven":
            while ph_b < ph_a:
                ph_b += 2 * math.pi
        else:  # driver: counter-clockwise = decreasing phi; one driver turn = 2 pi / n of phi
            while ph_b > ph_a:
                ph_b -= 2 * math.pi / n
        spaces.append((ph_a, ph_b))
    crossed = [abs(ph_b - ph_a) > math.pi / (1 if role == "driven" else n) for ph_a, ph_b in spaces]
    lifted = [units[i][4] > 0.0 or nexts[i][3] > 0.0 for i in range(len(units))]
    # the roots of the spaces whose feet did not cross and whose fillets reach the root equidistant, fitted in lock
    # step (a lifted root, below, on its own)
    plain = [i for i in range(len(units)) if not crossed[i] and not lifted[i]]
    roots = dict(zip(plain, fit_curves([(curve.equidistant(hf),) + spaces[i] for i in plain], evaluate_curves, tol,
                                       n0=FIT_N0)))
    for i, (unit, _phr, phl, _gr, gl) in enumerate(units):
        segs.extend(unit)
        nxt = nexts[i]
        ph_a, ph_b = spaces[i]
        if crossed[i]:
            # the feet crossed (a re-phased shaper's space whose root land vanished): the two fillets
            # cross above the root equidistant, both are trimmed at the crossing and meet there
            j = (i + 1) % len(units)
            nb = len(units[0][0])
            # the first tooth's head as it stands (trimmed by nothing yet), in this space: the next lobe's
            head = (segs[:nb] if g.lobes == 1 else _turn(segs[:nb], lap * turn)) if j == 0 else nxt[0]
            ka, kb, a_new, b_new, X = _trim_pairs(segs[-3:], head[:3], tol)
            del segs[len(segs) - 3 + ka:]
            segs.append(a_new)
            head[kb] = b_new
            del head[:kb]
            if j == 0:
                segs[:nb] = head if g.lobes == 1 else _turn(head, -lap * turn)
            root_r.append(float(np.hypot(*X)))
            continue
        g_a, g_b = gl, nxt[3]
        if lifted[i]:
            # a re-phased shaper's fillet may stop short of the root equidistant (ToothSide.root_gap_mm,
            # its foot at phi_root): the root rises linearly in phi from one fillet start to the other
            lift = lambda ph: g_a + (g_b - g_a) * (np.asarray(ph, float) - ph_a) / (ph_b - ph_a)
            root = fit_piece(lambda ph: curve.offset(ph, hf + lift(ph)[:, None]), ph_a, ph_b, tol)
        else:
            root = roots[i]
        root_r.append(float(np.min(np.linalg.norm(root.poles, axis=1))))
        segs.append(root)
    if g.lobes > 1:  # the pattern, counter-clockwise from the first tooth: each lobe the cut one turned j lobes
        laps = range(1, g.lobes) if role == "driven" else range(g.lobes - 1, 0, -1)
        pattern = [seg for j in laps for seg in _turn(segs, j * turn)]
        segs = segs + pattern if role == "driven" else pattern + segs
    rephased = any(sd.root_gap_mm > 0.0 or type(sd.fillet).__name__ == "RoundEnvelope"
                   for pair in teeth_sides for sd in pair)
    segs = _snap(segs, OUTLINE_JOINT_TOL_REPHASED_MM if rephased else OUTLINE_JOINT_TOL_MM)
    prof = Profile(Loop(segs), name=f"{role} generated z={g.z} m={m:g}")
    ph = np.linspace(0.0, 2 * math.pi / (1 if role == "driven" else n), 1441)
    gaps = tuple(float(sd.root_gap_mm) for pair in teeth_sides for sd in pair if sd.root_gap_mm > OUTLINE_JOINT_TOL_MM)
    return GeneratedGear(role, prof, teeth, min(root_r), curve.point(ph), gaps * g.lobes)



#: teeth from which a gear's pieces are fitted in two processes (this one and a forked one), half each
SPLIT_FIT_TEETH = 40
#: (curve, teeth sides, tips, tol) of the fits a forked process makes (read there: the fork copies it)
_FITS = None


def _fit_units(curve, teeth_sides, tips, order, tol, start=None, tick=None) -> list:
    """The fitted pieces of the teeth in ``order`` (one unit per tooth: pieces, root angles, root gaps).
    From SPLIT_FIT_TEETH teeth on, with a `start`, the first half is fitted by ``start`` (a forked process)
    while this one fits the second (the same pieces: every tooth is fitted on its own); an error is the
    first tooth's, as in one process.  ``tick(done)``: told the teeth fitted (those of the first half when it is
    done)."""
    global _FITS

    if start is None or len(order) < SPLIT_FIT_TEETH:
        return _fit_teeth(curve, teeth_sides, tips, order, tol, tick)
    half = len(order) // 2
    _FITS = (curve, teeth_sides, tips, tol)
    try:
        job = start(_fit_forked, order[:half])  # the fork (or the inline fits) happens here
    finally:
        _FITS = None
    try:
        second, error = _fit_teeth(curve, teeth_sides, tips, order[half:], tol, tick), None
    except Exception as exc:  # noqa: BLE001 - raised below, after the first half's own error if any
        second, error = None, exc
    first = job.result()
    if tick is not None:
        tick(len(order))
    if error is not None:
        raise error
    return first + second


def _fit_forked(order) -> list:
    curve, teeth_sides, tips, tol = _FITS
    return _fit_teeth(curve, teeth_sides, tips, order, tol)


def _fit_teeth(curve, teeth_sides, tips, order, tol, tick=None) -> list:
    """The pieces of the teeth in ``order``, fitted in lock step (:func:`.bspline.fit_curves`: each round's new
    points of a kind of piece computed for all the teeth at once, :func:`..gears.curve_batch.evaluate_curves`)."""
    curves, spans = [], []
    for k in order:
        R, Lf = teeth_sides[k]
        h, hr, hl = tips[k]
        fits = []
        # a side whose flank reaches the root itself (ToothSide.fillet_is_flank) is one piece
        if R.fillet_is_flank:
            fits.append((R.flank, R.fillet.u0, hr[0]))
        else:
            fits += [(R.fillet, R.fillet.u0, R.fillet.u1), (R.flank, R.flank.u0, hr[0])]
        fits.append((curve.equidistant(h), hr[1], hl[1]))
        if Lf.fillet_is_flank:
            fits.append((Lf.flank, hl[0], Lf.fillet.u0))
        else:
            fits += [(Lf.flank, hl[0], Lf.flank.u0), (Lf.fillet, Lf.fillet.u1, Lf.fillet.u0)]
        spans.append((len(curves), len(fits)))
        curves += fits
    splines = fit_curves(curves, evaluate_curves, tol, n0=FIT_N0)
    units = []
    for k, (at, n) in zip(order, spans):
        R, Lf = teeth_sides[k]
        # a shaper with its own x0 may stop short of the root equidistant (ToothSide.root_gap_mm): the root
        # below is lifted to meet it (above)
        units.append((splines[at:at + n], R.phi_root, Lf.phi_root, R.root_gap_mm, Lf.root_gap_mm))
        if tick is not None:
            tick(len(units))
    return units


def _trim_pairs(tail: list, head: list, tol: float):
    """The crossing of the last pieces ``tail`` of one tooth with the first pieces ``head`` of the next
    nearest to their joint: (index in tail, index in head, trimmed tail piece, trimmed head piece, point)."""
    for ka in range(len(tail) - 1, -1, -1):
        for kb in range(len(head)):
            try:
                a_new, b_new, X = _trim_pair(tail[ka], head[kb], tol)
            except RuntimeError:
                continue
            return ka, kb, a_new, b_new, X
    raise RuntimeError("the fillets of a space whose root land vanished do not cross")


def _trim_pair(a: Spline, b: Spline, tol: float):
    """a ends past the start of b (their curves cross): both trimmed at the crossing, refitted.
    RuntimeError when they do not cross."""
    ta = np.linspace(a.knots[0], a.knots[-1], 801)
    tb = np.linspace(b.knots[0], b.knots[-1], 801)
    A, B = a._bs(ta), b._bs(tb)
    best = None
    for k in range(len(A) - 1):
        p, r = A[k], A[k + 1] - A[k]
        q, sv = B[:-1], B[1:] - B[:-1]
        den = r[0] * sv[:, 1] - r[1] * sv[:, 0]
        with np.errstate(divide="ignore", invalid="ignore"):
            t = ((q[:, 0] - p[0]) * sv[:, 1] - (q[:, 1] - p[1]) * sv[:, 0]) / den
            u = ((q[:, 0] - p[0]) * r[1] - (q[:, 1] - p[1]) * r[0]) / den
        hit = np.nonzero((np.abs(den) > 0) & (t >= 0) & (t <= 1) & (u >= 0) & (u <= 1))[0]
        if len(hit):
            m = int(hit[0])
            best = (ta[k] + t[m] * (ta[k + 1] - ta[k]), tb[m] + u[m] * (tb[m + 1] - tb[m]))
            break
    if best is None:
        raise RuntimeError("the fillets of a space whose root land vanished do not cross")
    from scipy.optimize import fsolve

    sol = fsolve(lambda y: a._bs(y[0]) - b._bs(y[1]), np.array(best), xtol=1e-13)
    X = a._bs(sol[0])
    a_new = fit_piece(lambda t: a._bs(np.atleast_1d(t)), a.knots[0], float(sol[0]), tol)
    b_new = fit_piece(lambda t: b._bs(np.atleast_1d(t)), float(sol[1]), b.knots[-1], tol)
    b_new = Spline(b_new.knots, np.vstack([a_new.end, b_new.poles[1:]]), b_new.degree)
    return a_new, b_new, X


def _snap(segs: list, tol: float = OUTLINE_JOINT_TOL_MM) -> list:
    """Make consecutive splines share their end points exactly (they agree to ~1e-9 mm)."""
    out = []
    for i, s in enumerate(segs):
        prev = segs[i - 1]
        gap = float(np.linalg.norm(prev.end - s.start))
        if gap > tol:
            raise RuntimeError(f"outline pieces {i - 1} and {i} do not meet: gap {gap:.3g} mm")
        P = s.poles.copy()
        P[0] = prev.end
        out.append(Spline(s.knots, P, s.degree))
    return out

