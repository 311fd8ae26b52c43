"""Load per tooth of a gear pair on its real tooth outlines (any pair: circular or non-circular): the load case over
the cycle, its sharing between the tooth pairs in contact, the contact stress of each pair and the root stress of
each tooth.  Pure numpy; the contacts themselves (which tooth pairs touch, where, with which gap) come from
``checks.motion.mesh_load`` on the finished outlines.  mm, N, N·mm (N·m at the edges), MPa, radians.

Load case (seed 000/002 eqs. 2-3, 15; seed 004 eq. 40 for the rolling resistance):

    driver torque given:        T1 = const,  T2 = T1·U(φ)·η
    power P and speed n1:       T1 = P / ω1, ω1 = 2π·n1/60
    vehicle (walking law):      F_R = f·M·g / N_p (rolling resistance per driven propulsor),
                                T2(φ) = F_R·dX01/dφ (power balance of the carrier: T2·ω2 = F_R·v, v = ω2·dX01/dφ),
                                T1 = T2 / (U·η)  (constant where the law keeps the hub speed constant: T1 = F_R·(A/u)/η)

Sharing between the tooth pairs in contact (a stated simpler model than ISO 6336-1's K_Hα): every pair j that can
touch is a spring along its contact normal of stiffness c′·b (ISO 6336-1:2006 9.3, the single stiffness c′ of the
local equivalent gears, :func:`c_prime`), closed once the driven wheel, turned by Δ from the first contact against
the driver held, has taken up the pair's rotational gap δ_j measured on the outlines:

    F_j = c′·b·l2_j·(Δ − δ_j)⁺,   Σ_j F_j·l1_j = T1                      (l1, l2: the normal's lever arms about the
                                                                        driver's and the driven axis)
Limits: the teeth are rigid bodies plus one constant spring per pair (no variation of the stiffness along the path,
no rim or shaft compliance, no friction in the force direction, no dynamics: K_v, K_Hβ are the user's factors);
pairs farther apart than the window searched never share.

Contact stress (Hertz, line contact; ISO 6336-2 eq. 18 for Z_E):

    σ_H = Z_E·√(F_n·K_H/(b·ρ_red)),   1/ρ_red = 1/ρ1 + 1/ρ2 (signed, convex > 0),
    Z_E = √(1/(π·((1 − ν1²)/E1 + (1 − ν2²)/E2))),   K_H = K_A·K_v·K_Hβ

with ρ1, ρ2 the radii of curvature of the two flanks at the contact point, measured on the outlines
(:func:`curvature_at`).  At the pitch point of a circular pair this is ISO 6336-2's Z_H·Z_E·√(F_t/(d1·b)·(u+1)/u)·√K_H;
at the pinion's inner point of single contact it carries ISO's Z_B.

Root stress (ISO 6336-3 cl. 6-7 on the real tooth, :func:`root_section`, :func:`root_stress`): the critical section
is the chord s_Fn between the points of the two fillets whose tangent makes 30° with the tooth's axis (the normal of
the pitch curve at the tooth's centre: the radial line of the local equivalent cylindrical gear); the load F at its
point of application P on its line of action gives the bending moment about the chord's middle C,
M = |(P − C) × F| = F·cos α_Fen·h_Fe, and

    σ_F = 6·M/(b·s_Fn²)·Y_S·K_F,   Y_S = (1.2 + 0.13·L)·q_s^(1/(1.21 + 2.3/L)),  L = s_Fn/h_Fe,  q_s = s_Fn/(2ρ_F)
    Y_F = 6·(h_Fe/m)·cos α_Fen / ((s_Fn/m)²·cos α)   (reported: σ_F = F_t/(b·m)·Y_F·Y_S·K_F with F_t = F_n·cos α)

ρ_F the fillet's radius of curvature at the 30° point on the loaded side (the tension fillet), K_F = K_A·K_v·K_Fβ.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..policy import (CURVATURE_JUMP_ABS_PER_MM, CURVATURE_JUMP_REL, CURVATURE_JUMP_RMS_MM,
                      CURVATURE_JUMP_RMS_RATIO)

__all__ = ["G", "torques", "c_prime", "share_load", "hertz", "curvature_at", "curvatures_at", "RootSection",
           "root_section", "root_stress", "y_s", "DenseOutline"]

#: standard gravity, m/s² (the vehicle load)
G = 9.80665


# ======================================================================================= the load over the cycle
def torques(U, *, T1_Nm: float = 0.0, power_W: float = 0.0, speed_rpm: float = 0.0, eta: float = 1.0,
            vehicle_mass_kg: float = 0.0, rolling_resistance: float = 0.0, propulsors: int = 1, dX01_dphi=None):
    """(T1, T2, source) in N·m over the phases where the law's ratio is ``U`` (array): the driver's torque and the
    driven (carrier) torque, and a line naming the load case (module docstring).  ``dX01_dphi``: the hub's horizontal
    speed analogue (mm/rad) at the same phases, for the vehicle load of a walking law."""
    U = np.asarray(U, float)
    if not 0.0 < eta <= 1.0:
        raise InputError("load_efficiency", eta, "must be within (0, 1]")
    if vehicle_mass_kg > 0:
        if dX01_dphi is None:
            raise InputError("load_vehicle_mass_kg", vehicle_mass_kg,
                             "a vehicle load needs the walking law (its hub speed dX01/dphi); give load_driver_torque_Nm")
        F_R = rolling_resistance * vehicle_mass_kg * G / propulsors
        T2 = F_R * np.asarray(dX01_dphi, float) * 1e-3
        T1 = T2 / (U * eta)
        return T1, T2, (f"vehicle {vehicle_mass_kg:g} kg, rolling resistance f = {rolling_resistance:g}, "
                        f"{propulsors} driven propulsor(s): F_R = f·M·g/N_p = {F_R:.2f} N per propulsor, "
                        f"T2 = F_R·dX01/dphi, T1 = T2/(U·eta)")
    if T1_Nm > 0:
        T1 = np.full_like(U, float(T1_Nm))
        what = f"driver torque T1 = {T1_Nm:g} N·m"
    elif power_W > 0:
        if not speed_rpm > 0:
            raise InputError("load_driver_speed_rpm", speed_rpm, "a power load needs the driver speed (> 0 rpm)")
        T1 = np.full_like(U, power_W / (2 * math.pi * speed_rpm / 60.0))
        what = f"power {power_W:g} W at {speed_rpm:g} rpm of the driver: T1 = P/omega1 = {T1[0]:.4f} N·m"
    else:
        raise InputError("load_driver_torque_Nm", T1_Nm, "no load given (a driver torque, a power or a vehicle)")
    return T1, T1 * U * eta, what + f", T2 = T1·U·eta (eta = {eta:g})"


# ======================================================================================= sharing
def c_prime(z_n1, z_n2, x1: float, x2: float, alpha: float, h_fP_star: float = 1.25, E_ratio: float = 1.0,
            C_M: float = 0.8, C_R: float = 1.0):
    """Single stiffness c′ of one tooth pair, N/(mm·µm) (ISO 6336-1:2006 9.3, eq. 60-63 with Table 12's C1...C9;
    spur, solid discs C_R = 1, C_M = 0.8).  z_n1, z_n2: teeth of the local equivalent cylindrical gears, 2ρ/m of the
    pitch curves at the contact (inf or a negative value for a concave pitch curve: ISO's internal wheel, 1/z_n2 = 0).
    E_ratio: E/E_steel of the pair (ISO 6336-1 9.3: c′ scales with E = 2E1E2/(E1 + E2))."""
    from .iso6336_helical import _C

    C1, C2, C3, C4, C5, C6, C7, C8, C9 = _C
    inv1 = np.where(np.asarray(z_n1, float) > 0, 1.0 / np.asarray(z_n1, float), 0.0)
    inv2 = np.where(np.asarray(z_n2, float) > 0, 1.0 / np.asarray(z_n2, float), 0.0)
    q = C1 + C2 * inv1 + C3 * inv2 + C4 * x1 + C5 * x1 * inv1 + C6 * x2 + C7 * x2 * inv2 + C8 * x1 * x1 + C9 * x2 * x2
    C_B = (1.0 + 0.5 * (1.2 - h_fP_star)) * (1.0 - 0.02 * (20.0 - math.degrees(alpha)))
    return E_ratio * C_M * C_R * C_B / q


def share_load(T1: float, l1, l2, gap, k):
    """Normal forces (N) of the tooth pairs of one phase: F_j = k_j·l2_j·(Δ − δ_j)⁺ with Σ F_j·l1_j = T1 (N·mm),
    k_j = c′·b (N/mm per mm of approach), δ_j the rotational gap (rad) of pair j; returns (F, Δ).  The pair with the
    least gap always carries load."""
    l1, l2, gap, k = (np.asarray(a, float) for a in (l1, l2, gap, k))
    if T1 <= 0 or len(gap) == 0:
        return np.zeros_like(gap), 0.0
    order = np.argsort(gap)
    g, a = gap[order], (k * l1 * l2)[order]   # torque on the driver per rad of Δ beyond each gap
    S = 0.0   # Σ a_j over the closed pairs
    P = 0.0   # Σ a_j δ_j
    D = g[0]
    for j in range(len(g)):
        S += a[j]
        P += a[j] * g[j]
        D = (T1 + P) / S
        if j + 1 == len(g) or D <= g[j + 1]:
            break
    F = k * l2 * np.maximum(D - gap, 0.0)
    return F, float(D)


# ======================================================================================= contact stress
def hertz(F, b: float, rho1, rho2, Z_E: float, K: float = 1.0):
    """σ_H (MPa) of a line contact: Z_E·√(F·K/(b·ρ_red)), 1/ρ_red = 1/ρ1 + 1/ρ2 (signed radii, convex > 0, mm);
    nan where the flanks do not curve towards each other (1/ρ_red <= 0)."""
    F, rho1, rho2 = (np.asarray(a, float) for a in (F, rho1, rho2))
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / rho1 + 1.0 / rho2
        s = Z_E * np.sqrt(np.maximum(F, 0.0) * K * inv / b)
    return np.where(inv > 0, s, np.nan)


# ======================================================================================= outlines
class DenseOutline:
    """A closed outline sampled densely with its points on the exact curve (a profile's outer loop at a fine chord
    tolerance, counter-clockwise, material on the left): its unit tangents, turning angles, a k-d tree."""

    def __init__(self, points, corner_deg: float = 10.0):
        from scipy.spatial import cKDTree

        p = np.asarray(points, float)
        if len(p) > 1 and np.allclose(p[0], p[-1]):
            p = p[:-1]
        self.points = p
        seg = np.roll(p, -1, axis=0) - p
        self.seg_len = np.linalg.norm(seg, axis=1)
        d = seg / self.seg_len[:, None]
        a = np.arctan2(d[:, 1], d[:, 0])
        # turning at vertex i between segment i-1 and segment i
        self.turn = (a - np.roll(a, 1) + math.pi) % (2 * math.pi) - math.pi
        self.corner = np.abs(self.turn) > math.radians(corner_deg)
        t = d + np.roll(d, 1, axis=0)
        self.tangent = t / np.linalg.norm(t, axis=1)[:, None]
        self.polar = np.arctan2(p[:, 1], p[:, 0])
        self.tree = cKDTree(p)

    def __len__(self) -> int:
        return len(self.points)

    def nearest(self, q) -> np.ndarray:
        return self.tree.query(np.atleast_2d(q))[1]


def _problem(o: DenseOutline, i: int, idx, t):
    """The least-squares problem (A, y) of the cubic y(x) through the vertices ``idx`` in the frame of the unit tangent
    t at vertex i; None below 5 vertices."""
    idx = np.asarray(idx)
    if len(idx) < 5:
        return None
    nrm = np.array([-t[1], t[0]])
    q = o.points[idx] - o.points[i]
    x, y = q @ t, q @ nrm
    return np.column_stack([np.ones_like(x), x, x * x, x ** 3]), y


def _fitted(problem, c) -> tuple[float, float]:
    """The cubic's curvature at the vertex (its coefficients c) and the RMS of its residuals (mm); nan, nan without a
    problem."""
    if problem is None:
        return math.nan, math.nan
    A, y = problem
    rms = float(np.sqrt(np.mean((A @ c - y) ** 2)))
    return float(2.0 * c[2] / (1.0 + c[1] ** 2) ** 1.5), rms


def _fit_rms(o: DenseOutline, i: int, idx, t) -> tuple[float, float]:
    """The cubic fit's curvature at vertex i and the RMS of its residuals (mm); nan, nan below 5 vertices."""
    pr = _problem(o, i, idx, t)
    return _fitted(pr, None if pr is None else np.linalg.lstsq(pr[0], pr[1], rcond=None)[0])


def _fit(o: DenseOutline, i: int, idx, t) -> float:
    return _fit_rms(o, i, idx, t)[0]


#: a jump inside the window (policy): the one-sided curvatures differ by more than JUMP_REL of the larger (and
#: JUMP_ABS 1/mm), or one side's cubic fits its points JUMP_RMS_RATIO times worse than the other's (and JUMP_RMS_MM)
JUMP_REL, JUMP_ABS = CURVATURE_JUMP_REL, CURVATURE_JUMP_ABS_PER_MM
JUMP_RMS_RATIO, JUMP_RMS_MM = CURVATURE_JUMP_RMS_RATIO, CURVATURE_JUMP_RMS_MM


def curvature_at(o: DenseOutline, i: int, half_len: float) -> float:
    """:func:`_curvature_at`, kept on the outline per vertex and window (a vertex loaded at several positions is
    fitted once)."""
    memo = o.__dict__.setdefault("_curvatures", {})
    key = (int(i), float(half_len))
    k = memo.get(key)
    if k is None:
        k = memo[key] = _curvature_at(o, int(i), float(half_len))
    return k


def _lstsq_failed(err, flag):
    raise np.linalg.LinAlgError("SVD did not converge in Linear Least Squares")  # as np.linalg.lstsq says it


def curvatures_at(o: DenseOutline, indices, half_len: float) -> None:
    """:func:`curvature_at` of each vertex of ``indices`` not yet kept, made together: every vertex's fit windows and
    their points in the frames of their tangents set up in one compiled pass (:mod:`.tooth_load_kernels`: the
    windows and coordinates of :func:`_problems`, the same floats), the cubic's columns by numpy, the least-squares
    problems solved in stacks of one shape (numpy's own LAPACK driver, called once per problem as for one alone: the
    same coefficients to the last bit, a fifth of the time), then each vertex's curvature from its own fits
    (:func:`_curvature_of`) as one at a time."""
    from numpy.linalg import _umath_linalg

    from .tooth_load_kernels import fit_windows, frame_coordinates

    memo = o.__dict__.setdefault("_curvatures", {})
    h = float(half_len)
    todo = sorted({int(i) for i in indices} - {k[0] for k in memo if k[1] == h})
    if not todo:
        return
    todo_a = np.array(todo, np.int64)
    is_corner, Ks, first, last = fit_windows(np.ascontiguousarray(o.seg_len, np.float64),
                                            np.ascontiguousarray(o.corner, np.bool_), todo_a, h)
    # the fits of each vertex and their frames: the tangent at the vertex (three fits); at a corner each side's edge
    # direction (two fits), numpy's norm as in _problems
    rows, frames = [], []
    n = len(o)
    for r, i in enumerate(todo):
        if is_corner[r]:
            d_ahead = o.points[(i + 1) % n] - o.points[i]
            d_back = o.points[i] - o.points[(i - 1) % n]
            rows += [(r, 0), (r, 1)]
            frames += [d_ahead / np.linalg.norm(d_ahead), d_back / np.linalg.norm(d_back)]
        else:
            t = o.tangent[i]
            rows += [(r, 0), (r, 1), (r, 2)]
            frames += [t, t, t]
    rows_a = np.array(rows, np.int64).reshape(-1, 2)
    X, Y, offsets = frame_coordinates(np.ascontiguousarray(o.points, np.float64), todo_a, Ks, first, last,
                                      np.ascontiguousarray(np.array(frames, np.float64).reshape(-1, 2)), rows_a)
    X2, X3 = X * X, X ** 3
    sizes = np.diff(offsets)
    by_size: dict = {}
    for p, m in enumerate(sizes.tolist()):
        if m >= 5:  # fewer points: no problem (_problem's None)
            by_size.setdefault(m, []).append(p)
    problems: dict = {}
    coef: dict = {}
    for m, ps in by_size.items():
        R = offsets[np.array(ps)][:, None] + np.arange(m)[None, :]
        A = np.empty((len(ps), m, 4))
        A[..., 0] = 1.0
        A[..., 1], A[..., 2], A[..., 3] = X[R], X2[R], X3[R]
        y = Y[R]
        with np.errstate(call=_lstsq_failed, invalid="call", over="ignore", divide="ignore", under="ignore"):
            x = _umath_linalg.lstsq(A, y[..., None], np.finfo(np.float64).eps * max(4, m), signature="ddd->ddid")[0]
        for k, p in enumerate(ps):
            problems[p] = (A[k].copy(), y[k].copy())
            coef[p] = x[k, :, 0].copy()
    fits: list = [[] for _ in todo]
    for p, (r, _) in enumerate(rows):
        fits[r].append(_fitted(problems.get(p), coef.get(p)))
    for r, i in enumerate(todo):
        memo[(i, h)] = _curvature_of(bool(is_corner[r]), fits[r])


def _curvature_at(o: DenseOutline, i: int, half_len: float) -> float:
    """Signed curvature (1/mm, convex > 0) of the outline at vertex i: a cubic y(x) least-squares fitted to the
    vertices within ``half_len`` of arc length on either side, in the frame of the tangent at i, stopping at a corner;
    κ = 2c2/(1 + c1²)^1.5.  At a corner vertex (a contact on a tooth's tip edge) each side is fitted alone and the
    more curved one taken: Hertz does not hold at an edge; its flank's radius is the nearest stated value.

    A jump of curvature without a corner (the involute's start meeting the fillet: tangent continuous, radius not)
    inside the centred window makes its cubic a mix of both pieces (the circular pair's first contact, 0.6 mm above
    the base circle: 411 mm where the involute gives 5.4 mm, σ_H half its value).  So at a non-corner vertex each
    one-sided window (vertex i and the vertices within ``half_len`` on one side, up to a corner) is fitted too.  A
    cubic holds a curvature varying linearly along the arc exactly, so on one smooth piece the two sides agree in
    curvature (within JUMP_REL of the larger, or JUMP_ABS) and fit their points about equally well (RMS residuals
    within JUMP_RMS_RATIO, or both under JUMP_RMS_MM): there the centred fit is kept, unchanged.  Otherwise a jump
    lies inside the window (the curvatures differ, or the side straddling it fits its points far worse than the
    other: on the circular pair the straddling side's curvature sweeps through every value and can agree with the
    other side by chance, its residual does not); the side whose cubic fits its own points best (least RMS residual)
    lies on the smooth piece vertex i belongs to, and its curvature is taken."""
    corner, probs = _problems(o, i, half_len)
    return _curvature_of(corner, [_fitted(pr, None if pr is None else np.linalg.lstsq(pr[0], pr[1], rcond=None)[0])
                                  for pr in probs])


def _problems(o: DenseOutline, i: int, half_len: float) -> tuple[bool, list]:
    """(whether vertex i is a corner, the least-squares problems of its fits, :func:`_problem`): at a corner the side
    ahead and the side behind, each in the frame of its own edge; elsewhere the centred window, then the side ahead and
    the side behind, in the frame of the tangent at i (:func:`_curvature_at`)."""
    n = len(o)
    K = int(min(n // 2 - 1, math.ceil(2.0 * half_len / max(float(o.seg_len[i]), 1e-9)) + 2))
    off = np.arange(-K, K + 1)
    idx = (i + off) % n
    c = np.concatenate([[0.0], np.cumsum(o.seg_len[idx])])
    s = c[:-1] - c[K]                     # arc length of each vertex from vertex i
    keep = np.abs(s) <= half_len
    cor = o.corner[idx]
    ahead = np.nonzero(cor[K + 1:])[0]
    back = np.nonzero(cor[:K][::-1])[0]
    hi = K + 1 + int(ahead[0]) if len(ahead) else 2 * K      # the last vertex ahead (a corner ends the piece)
    lo = K - 1 - int(back[0]) if len(back) else 0
    j = np.arange(2 * K + 1)
    if not o.corner[i]:
        sel = keep & (j >= lo) & (j <= hi)
        t = o.tangent[i]
        return False, [_problem(o, i, idx[sel], t), _problem(o, i, idx[keep & (j >= K) & (j <= hi)], t),
                       _problem(o, i, idx[keep & (j <= K) & (j >= lo)], t)]
    d_ahead = o.points[(i + 1) % n] - o.points[i]
    d_back = o.points[i] - o.points[(i - 1) % n]
    return True, [_problem(o, i, idx[keep & (j >= K) & (j <= hi)], d_ahead / np.linalg.norm(d_ahead)),
                  _problem(o, i, idx[keep & (j <= K) & (j >= lo)], d_back / np.linalg.norm(d_back))]


def _curvature_of(corner: bool, fits: list) -> float:
    """The curvature of a vertex from its fits' (curvature, RMS) in :func:`_problems`' order (:func:`_curvature_at`):
    elsewhere than a corner the centred fit's, unless the sides disagree (a jump inside the window), then the side
    that fits its points best; at a corner the more curved side's."""
    if not corner:
        (k_c, _), (k_a, r_a), (k_b, r_b) = fits
        if not (math.isfinite(k_a) and math.isfinite(k_b)):
            return k_c
        apart = abs(k_a - k_b) > max(JUMP_REL * max(abs(k_a), abs(k_b)), JUMP_ABS)
        worse = max(r_a, r_b) > max(JUMP_RMS_RATIO * min(r_a, r_b), JUMP_RMS_MM)
        if not (apart or worse):
            return k_c
        return k_a if r_a <= r_b else k_b
    ks = [k for k, _ in fits if math.isfinite(k)]
    return max(ks, key=abs) if ks else math.nan


# ======================================================================================= root
@dataclass(frozen=True)
class RootSection:
    """The critical section of one tooth (ISO 6336-3's 30° tangents on its real outline), body frame of its gear."""

    tooth: int
    A_lo: np.ndarray      #: 30° point of the fillet on the clockwise side (lower polar angle)
    A_hi: np.ndarray      #: on the counter-clockwise side
    rho_lo: float         #: fillet radius of curvature there, mm
    rho_hi: float
    axis: np.ndarray      #: the tooth's axis (outward unit normal of the pitch curve at its centre)

    @property
    def s_Fn(self) -> float:
        return float(np.linalg.norm(self.A_hi - self.A_lo))

    @property
    def C(self) -> np.ndarray:
        return 0.5 * (self.A_lo + self.A_hi)

    @property
    def ok(self) -> bool:
        return bool(np.all(np.isfinite(self.A_lo)) and np.all(np.isfinite(self.A_hi)) and self.rho_lo > 0
                    and self.rho_hi > 0)


def _crossing(o: DenseOutline, run: np.ndarray, axis: np.ndarray, angle: float):
    """Along ``run`` (vertex indices from the root towards the tooth's tip), the first point whose tangent makes at
    most ``angle`` with the axis (interpolated between the vertices on either side): (point, vertex index)."""
    gam = np.arccos(np.clip(np.abs(o.tangent[run] @ axis), 0.0, 1.0))
    below = np.nonzero(gam <= angle)[0]
    if len(below) == 0 or below[0] == 0:
        return np.full(2, np.nan), -1
    k = below[0]
    g0, g1 = gam[k - 1], gam[k]
    f = (g0 - angle) / (g0 - g1) if g0 != g1 else 1.0
    p = o.points[run[k - 1]] + f * (o.points[run[k]] - o.points[run[k - 1]])
    return p, int(run[k] if f >= 0.5 else run[k - 1])


def root_section(o: DenseOutline, tooth: int, centres: np.ndarray, axis: np.ndarray, m: float,
                 angle_deg: float = 30.0) -> RootSection:
    """The critical section of tooth ``tooth`` of a gear whose tooth centres lie at the body polar angles ``centres``
    (sorted or not): its cell runs half-way to the neighbouring teeth; on each side the fillet is walked from the
    cell's edge (the space) towards the tip and the 30° point taken where the tangent first comes within 30° of
    the tooth's ``axis``."""
    c = np.asarray(centres, float)
    ck = c[tooth]
    d = (c - ck + math.pi) % (2 * math.pi) - math.pi
    lo = np.max(d[d < 0]) / 2 if np.any(d < 0) else -math.pi
    hi = np.min(d[d > 0]) / 2 if np.any(d > 0) else math.pi
    rel = (o.polar - ck + math.pi) % (2 * math.pi) - math.pi
    idx = np.nonzero((rel > lo) & (rel < hi))[0]
    nan = np.full(2, np.nan)
    if len(idx) < 8:
        return RootSection(tooth, nan, nan, math.nan, math.nan, np.asarray(axis, float))
    # one run along the loop (the cell may straddle the loop's first vertex)
    gaps = np.diff(idx)
    if np.any(gaps > 1):
        cut = int(np.argmax(gaps)) + 1
        idx = np.concatenate([idx[cut:], idx[:cut]])
    # counter-clockwise along an outer loop: from the clockwise space (lo) over the tip to the other space (hi)
    ax = np.asarray(axis, float)
    half = math.radians(angle_deg)
    A_lo, i_lo = _crossing(o, idx, ax, half)
    A_hi, i_hi = _crossing(o, idx[::-1], ax, half)
    w = 0.05 * m
    r_lo = -1.0 / curvature_at(o, i_lo, w) if i_lo >= 0 else math.nan
    r_hi = -1.0 / curvature_at(o, i_hi, w) if i_hi >= 0 else math.nan
    return RootSection(tooth, A_lo, A_hi, r_lo, r_hi, ax)


def y_s(s_Fn, h_Fe, rho_F):
    """Stress correction factor Y_S = (1.2 + 0.13·L)·q_s^(1/(1.21 + 2.3/L)) (ISO 6336-3:2006 eq. 39)."""
    L = np.asarray(s_Fn, float) / np.asarray(h_Fe, float)
    q_s = np.asarray(s_Fn, float) / (2.0 * np.asarray(rho_F, float))
    return (1.2 + 0.13 * L) * q_s ** (1.0 / (1.21 + 2.3 / L))


def root_stress(sec: RootSection, P, F, b: float, m: float, alpha: float, K: float = 1.0) -> dict:
    """Root stress of the tooth ``sec`` under the force vector F (N, body frame of its gear) applied at P: the moment
    about the section's middle, its arm h_Fe and angle α_Fen, Y_F, Y_S, σ_F (MPa; module docstring)."""
    P, F = np.asarray(P, float), np.asarray(F, float)
    C = sec.C
    chord = sec.A_hi - sec.A_lo
    s = float(np.linalg.norm(chord))
    e = chord / s                      # along the section
    r = P - C
    M = abs(float(r[0] * F[1] - r[1] * F[0]))
    Fn = float(np.linalg.norm(F))
    F_perp = abs(float(F @ e))
    h = M / F_perp if F_perp > 0 else math.nan
    a_Fen = math.acos(min(1.0, F_perp / Fn)) if Fn > 0 else math.nan
    rho = sec.rho_hi if float(r @ e) > 0 else sec.rho_lo    # the tension fillet: on the loaded flank's side
    Y_S = float(y_s(s, h, rho))
    Y_F = 6.0 * (h / m) * math.cos(a_Fen) / ((s / m) ** 2 * math.cos(alpha))
    sigma = 6.0 * M / (b * s * s) * Y_S * K
    return {"sigma_F": sigma, "h_Fe": h, "s_Fn": s, "rho_F": rho, "alpha_Fen": a_Fen, "Y_F": Y_F, "Y_S": Y_S, "M": M}
