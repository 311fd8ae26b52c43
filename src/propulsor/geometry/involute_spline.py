"""Involute splines with 30° pressure angle, flat root, side fit: GOST 6033-80 / ISO 4156-1.

numpy/scipy only.  Millimetres and radians.

The two standards share the 30° basic rack.  GOST 6033-80 names a joint by its nominal
diameter D, module m and tooth count z (designation "Эв. D × m"); the profile shift of the
basic rack follows from them:

    x m = (D − m z − 1.1 m) / 2                                   GOST 6033-80
    d = m z,   d_b = m z cos 30°                                  pitch, base diameter
    e = π m / 2 + 2 x m tan 30°     (basic space width of the hub, = tooth thickness of the shaft)
    external (shaft) major  d_a = D − 0.2 m = m (z + 1 + 2x)      (ISO 4156: D_ee = m(z + 1) at x = 0)
    internal (hub) minor    D_a = D − 2 m   = m (z − 0.9 + 2x)    (ISO 4156: D_ii ≈ m(z − 1))
    internal (hub) major    D_f = m (z + 1.5 + 2x)                (ISO 4156 flat root: D_ei = m(z + 1.5))

The hub space at radius r has the shape of the shaft tooth: its half angle is
ψ(r) = e / (2 r_p) + inv 30° − inv α_r with cos α_r = r_b / r (r_p = d/2, r_b = d_b/2).

Load capacity (crushing of the working flanks), GOST 21425-75, as seed 004 §4.3 uses it:

    h = 0.8 m,  d_m = D − 1.1 m,  S_F = 0.5 d_m h z  (mm³/mm),  σ_cr = T / (S_F l)
    [σ]_cr = σ_T / (n K_Σ)   (seed 004 §4.3: n = 1.4, K_Σ = K_z K_pr K_p = 1 × 2.65 × 1.4 = 3.71)

(seed 004 prints the crushing formula with a stray factor 2π; its own numbers, 117.164 MPa from
T = 90 687.5 N m, S_F = 5528.74 mm³/mm, l = 140 mm, follow σ = T / (S_F l) without it.)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, require_finite, require_positive
from ..policy import SPLINE_FIT_TOL_MM
from .bspline import fit_curve
from .profile import Arc, Loop, Spline

__all__ = ["InvoluteSpline", "ALPHA_SPLINE"]

#: pressure angle of the GOST 6033 / ISO 4156 basic rack
ALPHA_SPLINE = math.radians(30.0)


def _inv(a):
    return np.tan(a) - a


@dataclass(frozen=True)
class InvoluteSpline:
    """A GOST 6033-80 joint "Эв. D × m", z teeth (see module docstring for every formula)."""

    D: float
    m: float
    z: int

    def __post_init__(self):
        object.__setattr__(self, "D", require_positive("spline_D", self.D, "mm"))
        object.__setattr__(self, "m", require_positive("spline_m", self.m, "mm"))
        z = require_finite("spline_z", self.z)
        if z != int(z) or z < 6:
            raise InputError("spline_z", self.z, "must be a whole number >= 6")
        object.__setattr__(self, "z", int(z))
        if not -0.5 <= self.x <= 1.0:
            raise InputError("spline_D", self.D, f"profile shift x = (D − m z − 1.1 m)/(2m) = {self.x:.4f} "
                             f"outside −0.5 ... 1 (GOST 6033-80 tooth counts: z ≈ (D − 1.1 m)/m = "
                             f"{(self.D - 1.1 * self.m) / self.m:.2f})")
        if not self.D_a_hub / 2 > self.r_b:
            raise InputError("spline_z", self.z, f"hub minor radius {self.D_a_hub / 2:.4f} mm below the base "
                             f"radius {self.r_b:.4f} mm: the flank would not be an involute")
        if not self.psi(self.D_f_hub / 2) > 0:
            raise InputError("spline_z", self.z, "the hub spaces close before the major diameter")
        if not self.hub_tooth_angle(self.D_a_hub / 2) > 0:
            raise InputError("spline_z", self.z, "the hub teeth vanish at the minor diameter")

    # -- geometry -------------------------------------------------------------------
    @property
    def x(self) -> float:
        """Profile shift coefficient (GOST 6033-80)."""
        return (self.D - self.m * self.z - 1.1 * self.m) / (2.0 * self.m)

    @property
    def d(self) -> float:
        """Pitch diameter m z, mm."""
        return self.m * self.z

    @property
    def r_b(self) -> float:
        """Base radius, mm."""
        return 0.5 * self.d * math.cos(ALPHA_SPLINE)

    @property
    def e(self) -> float:
        """Basic space width of the hub on the pitch circle, mm."""
        return math.pi * self.m / 2.0 + 2.0 * self.x * self.m * math.tan(ALPHA_SPLINE)

    @property
    def d_a_shaft(self) -> float:
        """Major diameter of the external spline (torsion-bar head), mm."""
        return self.D - 0.2 * self.m

    @property
    def D_a_hub(self) -> float:
        """Minor diameter of the internal spline (tips of the hub teeth), mm."""
        return self.D - 2.0 * self.m

    @property
    def D_f_hub(self) -> float:
        """Major diameter of the internal spline (flat root of the hub spaces), mm."""
        return self.m * (self.z + 1.5 + 2.0 * self.x)

    def psi(self, r):
        """Half angle of a hub space at radius r (rad)."""
        r = np.asarray(r, float)
        a_r = np.arccos(np.clip(self.r_b / r, -1.0, 1.0))
        return self.e / self.d + _inv(ALPHA_SPLINE) - _inv(a_r)

    def hub_tooth_angle(self, r) -> float:
        """Angular width of a hub tooth at radius r (rad)."""
        return 2.0 * math.pi / self.z - 2.0 * float(self.psi(r))

    # -- strength (GOST 21425-75, seed 004 §4.3) -----------------------------------------
    @property
    def h_work(self) -> float:
        return 0.8 * self.m

    @property
    def d_mean(self) -> float:
        return self.D - 1.1 * self.m

    @property
    def S_F(self) -> float:
        """Specific static moment of the working flank areas, mm³/mm."""
        return 0.5 * self.d_mean * self.h_work * self.z

    def crushing_stress(self, T_Nmm: float, length_mm: float) -> float:
        """Mean flank pressure σ_cr = T / (S_F l), MPa."""
        return float(T_Nmm) / (self.S_F * require_positive("spline_length", length_mm, "mm"))

    # -- the hole of the hub ----------------------------------------------------------------
    def hub_hole_loop(self, tol: float = SPLINE_FIT_TOL_MM) -> Loop:
        """Closed outline of the internal spline (the hole), centred on the origin, one space on +x.

        Per space: involute flank (B-spline within tol of the exact involute), flat-root arc on
        D_f_hub, mirrored flank; hub-tooth tip arcs on D_a_hub between the spaces.
        """
        return self._flank_loop(0.5 * self.D_a_hub, 0.5 * self.D_f_hub, tol)

    def _flank_loop(self, r0: float, r1: float, tol: float) -> Loop:
        """z gaps of half angle ψ(r) between r0 and r1, centred on k·2π/z: flank r0 → r1 (B-spline within
        tol of the involute), arc on r1, mirrored flank back to r0, arc on r0 to the next gap.  The hub's
        hole (spaces, r0 = minor, r1 = major) and the shaft (teeth, r0 = root, r1 = tip) are both this."""

        def flank(u):  # u = r, lower flank (angle −ψ), from r0 outwards
            u = np.asarray(u, float)
            ps = self.psi(u)
            return np.column_stack([u * np.cos(-ps), u * np.sin(-ps)])

        lower = fit_curve(flank, r0, r1, tol=tol)
        upper = Spline(lower.knots[0] + lower.knots[-1] - lower.knots[::-1],
                       (lower.poles * np.array([1.0, -1.0]))[::-1].copy(), lower.degree)  # mirrored, r1 -> r0
        p0, p1 = float(self.psi(r0)), float(self.psi(r1))
        step = 2.0 * math.pi / self.z
        segs = []
        for k in range(self.z):
            a = k * step
            segs.append(lower.transformed(a))
            segs.append(Arc((0.0, 0.0), r1, a - p1, a + p1))
            segs.append(upper.transformed(a))
            segs.append(Arc((0.0, 0.0), r0, a + p0, a + step - p0))
        return Loop(segs)

    @property
    def d_f_shaft(self) -> float:
        """External (shaft) flat-root diameter m (z − 1.5 + 2x) (ISO 4156 flat root: D_ie = m(z − 1.5))."""
        return self.m * (self.z - 1.5 + 2.0 * self.x)

    def shaft_loop(self, tol: float = SPLINE_FIT_TOL_MM) -> Loop:
        """Closed outline of the external spline (the carrier's shaft), centred on the origin, one tooth
        on +x.  The shaft tooth fills the hub space (side fit, no flank clearance): half angle ψ(r)
        from the flat root d_f_shaft to the major diameter d_a_shaft = D − 0.2 m."""
        r0, r1 = 0.5 * self.d_f_shaft, 0.5 * self.d_a_shaft
        if not r0 > self.r_b:
            raise InputError("spline_z", self.z, f"shaft root radius {r0:.4f} mm below the base radius "
                             f"{self.r_b:.4f} mm: the flank would not be an involute")
        p0, p1 = float(self.psi(r0)), float(self.psi(r1))
        if not (p1 > 0 and 2.0 * p0 < 2.0 * math.pi / self.z):
            raise InputError("spline_z", self.z, "the shaft teeth close at the root or vanish at the tip")
        return self._flank_loop(r0, r1, tol)

    def designation(self) -> str:
        return f"Эв. {self.D:g} x {self.m:g} GOST 6033-80 (z = {self.z}, x = {self.x:+.3f})"
