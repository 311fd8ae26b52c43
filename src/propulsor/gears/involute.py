"""Involute spur-gear calculation sheet: ISO 21771 / DIN 3960 ≡ GOST 16532-70 (external
pairs) and GOST 19274-73 (internal pairs, ring cut by a shaper cutter).

Pure math (numpy/scipy only).  Millimetres and radians.  Names follow the standards:
d, d_b, d_a, d_f, d_w, alpha_w, a_w, y, Δy (``delta_y``), epsilon_alpha, W_k, M, s_c, h_c, ρ (``rho``).

Seed 004 ch. 4 (Tables 6 and 7) runs a sun z1 = 16 / planet z2 = 20 / ring z3 = 56 set,
m = 10, x = +0.5 / +0.5 / +1.417, shaper z0 = 14, x0 = 0.04 through these two standards;
``tests/test_involute.py`` reproduces the entries that follow from the inputs and lists those
that do not.

Sign convention of the profile shift of an internal gear (GOST 19274, KHK, and the thesis):
a positive ``x`` moves the generating tool *away from the gear axis*, as for an external gear.
For a ring that deepens and widens the spaces: tooth thickness s = m(π/2 − 2x·tan α), tip
diameter d_a = d − 2(h_a* − x)m.  The spaces of the ring play the role of the teeth of an
external gear, so the span measurement W_k and the dimension between rollers M use the external
formulas with the ring's space width e = m(π/2 + 2x·tan α).

Formulas (referenced below as [S-n]):
  S-1  inv α = tan α − α
  S-2  inv α_w = inv α + 2 tan α (x2 ± x1)/(z2 ± z1)         (GOST 16532 tab. 1; GOST 19274 tab. 1)
  S-3  a_w = m (z2 ± z1)/2 · cos α / cos α_w,  y = (a_w − a)/m,  Δy = (x2 ± x1) − y
  S-4  external tips with shortening: d_a = d + 2(h_a* + x − Δy) m          (GOST 16532)
  S-5  ring tip: d_a2 = d2 − 2(h_a* − x2 + Δy − k2) m, k2 = 0.25 − 0.125 x2 for x2 < 2,
       k2 = 0 for x2 ≥ 2 (GOST 19274, h_a* = 1, α = 20°; k2 = 0 for any other basic rack)
  S-6  ring root cut by a shaper: d_f2 = d_a0 + 2 a_w0, d_a0 = d0 + 2(h_a* + c* + x0) m,
       inv α_w0 = inv α + 2 tan α (x2 − x0)/(z2 − z0)                       (GOST 19274)
  S-7  W = m cos α [π(k − 0.5) + z inv α + 2x tan α]  (ring: k spaces, x as above)
  S-8  ε_α = (ρ_a1 ± ρ_a2 ∓ a_w sin α_w)/p_b, ρ_a = ½√(d_a² − d_b²)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from ..errors import InputError, require, require_finite, require_positive
from ..policy import ROLLER_DIAMETER_XTOL_MM, ROUNDING_TOL

__all__ = [
    "inv",
    "inv_inverse",
    "BasicRack",
    "SpurGear",
    "x_sum_for_centre_distance",
    "z_min_feasible",
    "roller_diameter_for_contact_at",
]



# --------------------------------------------------------------------------- involute function
def inv(alpha):
    """Involute function inv α = tan α − α [S-1] (α in radians; scalars or arrays)."""
    return np.tan(alpha) - alpha


def inv_inverse(value: float) -> float:
    """α with inv α = ``value`` (0 ≤ α < π/2), Newton's method to ``policy.ROUNDING_TOL``.

    d(inv α)/dα = tan²α.  Start: Cheng's approximation α ≈ (3v)^(1/3) − 2v/5 (good to ~1e-3 for
    α < 60°), then Newton steps; the iteration converges monotonically from any start above the root.
    """
    v = require_finite("inv value", value)
    require(v >= 0.0, "inv value", value, "must be >= 0 (involute function of an angle in [0, π/2))")
    if v == 0.0:
        return 0.0
    a = (3.0 * v) ** (1.0 / 3.0) - 0.4 * v
    a = min(max(a, 1e-8), math.pi / 2 - 1e-9)
    if inv(a) < v:  # make sure we approach from above (convex function -> monotone Newton)
        a = min(a * 1.5 + 1e-3, math.pi / 2 - 1e-12)
        while inv(a) < v:
            a = 0.5 * (a + math.pi / 2)
    for _ in range(100):
        t = math.tan(a)
        step = (t - a - v) / (t * t)
        a -= step
        if abs(step) <= ROUNDING_TOL * max(a, 1e-300):
            break
    return a


# --------------------------------------------------------------------------- basic rack
@dataclass(frozen=True)
class BasicRack:
    """Basic rack profile (ISO 53 / GOST 13755-81): α, h_a*, c*, ρ_f*.

    ρ_f* is the root-fillet radius of the basic rack (= tip radius of the generating tool).
    It is limited so that the two fillets of a tool tooth fit on its tip land:
    ρ_f* ≤ (π/4 − (h_a* + c*) tan α) cos α / (1 − sin α).
    """

    alpha: float = math.radians(20.0)
    h_a_star: float = 1.0
    c_star: float = 0.25
    rho_f_star: float = 0.38

    def __post_init__(self):
        a = require_finite("alpha", self.alpha)
        require(math.radians(10.0) <= a <= math.radians(35.0), "alpha", self.alpha,
                "must be within 10°..35° (0.1745..0.6109 rad)")
        require_positive("h_a_star", self.h_a_star)
        require(self.h_a_star <= 2.0, "h_a_star", self.h_a_star, "must be <= 2")
        c = require_finite("c_star", self.c_star)
        require(0.0 <= c <= 1.0, "c_star", self.c_star, "must be within 0..1")
        r = require_finite("rho_f_star", self.rho_f_star)
        require(r >= 0.0, "rho_f_star", self.rho_f_star, "must be >= 0")
        r_max = self.rho_f_star_max
        require(r_max > 0.0, "c_star", self.c_star,
                "tool tooth has no tip land left (π/4 − (h_a*+c*)·tan α ≤ 0)")
        require(r <= r_max, "rho_f_star", self.rho_f_star, f"must be <= {r_max:.4f} (tool tip land)")

    @property
    def h_fP_star(self) -> float:
        """Dedendum of the basic rack = addendum of the tool, h_a* + c*."""
        return self.h_a_star + self.c_star

    @property
    def rho_f_star_max(self) -> float:
        """Largest fillet radius that fits on the tool tip land (see class docstring)."""
        a = self.alpha
        return (math.pi / 4 - self.h_fP_star * math.tan(a)) * math.cos(a) / (1.0 - math.sin(a))

    @property
    def h_l_star(self) -> float:
        """Height (from the datum line) where the straight flank of the tool ends and its tip fillet
        begins: h_l* = h_a* + c* − ρ_f*(1 − sin α).  0.99997 for GOST 13755 — this point
        generates the boundary point of the involute (GOST 16532 'граничная точка')."""
        return self.h_fP_star - self.rho_f_star * (1.0 - math.sin(self.alpha))


# --------------------------------------------------------------------------- helpers
def _acos_ratio(name: str, d_b: float, d_y: float) -> float:
    require(d_y >= d_b * (1.0 - ROUNDING_TOL), name, d_y, f"must be >= base diameter d_b = {d_b:.6f} mm")
    return math.acos(min(1.0, d_b / d_y))


@lru_cache(maxsize=64)
def z_min_feasible(rack: BasicRack = BasicRack()) -> int:
    """Fewest teeth of an external gear for which some profile shift gives a tooth that is neither
    undercut (x ≥ x_min) nor pointed at its nominal tip (s_a > 0): the tooth of x = x_min is the
    thinnest-tipped non-undercut one only if a larger x is worse, which holds because s_a falls
    with x for these small z.  Result 8 for the 20° / h_a* = 1 rack (GOST 13755)."""
    a = rack.alpha
    for z in range(2, 200):
        x = rack.h_l_star - z * math.sin(a) ** 2 / 2.0
        d, d_b = z, z * math.cos(a)
        d_a = d + 2.0 * (rack.h_a_star + x)
        s = math.pi / 2 + 2.0 * x * math.tan(a)
        s_a = d_a * (s / d + float(inv(a)) - float(inv(math.acos(d_b / d_a))))
        if s_a > 0.0:
            return z
    raise AssertionError("unreachable")  # pragma: no cover


def roller_diameter_for_contact_at(gear: "SpurGear", d_y: float) -> float:
    """Roller (ball) diameter D whose contact with both flanks lies on the diameter ``d_y``.

    External gear: the roller centre angle satisfies tan α_D = tan α_y + D/d_b (contact point on
    the normal tangent to the base circle) and inv α_D = inv α + D/d_b − e/d, e = space width
    (S-7 counterpart); one equation in D, solved by Brent.  For a ring the roller sits in a space
    and tan α_D = tan α_y − D/d_b, inv α_D = inv α + e/d − D/d_b.

    The thesis's D = 17.362 mm (m = 10) follows no such rule (contact at d or at d + 2xm gives
    13.2 / 20.9 mm for the sun); it is a measuring-roller size, passed as an input.
    """
    from scipy.optimize import brentq

    alpha_y = _acos_ratio("d_y", gear.d_b, d_y)

    def f(D):
        return gear.alpha_D(D) - math.atan(math.tan(alpha_y) + (-D if gear.internal else D) / gear.d_b)

    a = gear.alpha
    if gear.internal:  # inv α_D must stay > 0: D < d_b (inv α + π/2z + 2x tan α / z)
        hi = 0.999 * gear.d_b * (float(inv(a)) + math.pi / (2 * gear.z) + 2 * gear.x * math.tan(a) / gear.z)
    else:
        hi = 3.0 * gear.p
    lo = 1e-6 * gear.m
    if not gear.internal:  # inv α_D > 0 needs D > d_b (π/2z − 2x tan α / z − inv α)
        lo = max(lo, 1.001 * gear.d_b * (math.pi / (2 * gear.z) - 2 * gear.x * math.tan(a) / gear.z - float(inv(a))))
    if f(lo) * f(hi) > 0:
        raise InputError("d_y", d_y, "no roller diameter makes contact on this diameter")
    return float(brentq(f, lo, hi, xtol=ROLLER_DIAMETER_XTOL_MM))


# --------------------------------------------------------------------------- one gear
@dataclass(frozen=True)
class SpurGear:
    """One involute spur gear, external or internal, and its measuring dimensions.

    ``z``: number of teeth (whole); ``m``: module, mm; ``x``: profile shift coefficient (sign as in
    the module docstring); ``internal``: a ring; ``z0``, ``x0``: shaper cutter of a ring (GOST 9323
    tool, addendum h_a0* = h_a* + c*).  Without a shaper a ring's root is the rack-generated one
    (reference only: a ring cannot be hobbed).
    """

    z: int
    m: float
    x: float = 0.0
    rack: BasicRack = field(default_factory=BasicRack)
    internal: bool = False
    z0: int | None = None
    x0: float = 0.0

    def __post_init__(self):
        require_positive("m", self.m, "mm")
        require_finite("x", self.x)
        require(isinstance(self.rack, BasicRack), "rack", self.rack, "must be a BasicRack")
        zf = require_finite("z", self.z)
        require(float(zf).is_integer(), "z", self.z, "must be a whole number of teeth")
        object.__setattr__(self, "z", int(zf))
        zmin = z_min_feasible(self.rack)
        if self.internal:
            require(self.z >= zmin + 1, "z", self.z,
                    f"a ring needs z >= {zmin + 1} (it must exceed the smallest feasible pinion, z = {zmin})")
        else:
            require(self.z >= zmin, "z", self.z,
                    f"must be >= {zmin}: for fewer teeth no profile shift avoids both undercut and a pointed tip")
            require(self.z0 is None, "z0", self.z0, "a shaper cutter is given for internal gears only")
        require(abs(self.x) <= 3.0, "x", self.x, "must be within -3..3")
        require(self.s > 0.0, "x", self.x,
                f"gives no tooth thickness at the reference circle (s = {self.s:.4f} mm)")
        if self.z0 is not None:
            z0f = require_finite("z0", self.z0)
            require(float(z0f).is_integer() and z0f >= 6, "z0", self.z0, "must be a whole number >= 6")
            object.__setattr__(self, "z0", int(z0f))
            require(self.z0 < self.z, "z0", self.z0, f"must be < z = {self.z} (shaper inside the ring)")
            require_finite("x0", self.x0)
            require(abs(self.x0) <= 1.5, "x0", self.x0, "must be within -1.5..1.5")
        self.validate()

    # ---- validation
    def validate(self) -> None:
        """Raise InputError for a gear that cannot be made: an external tip inside its base circle or
        root, a pointed nominal tip (s_na ≤ 0), a ring root (shaper-cut) inside its tip, a pointed ring
        tooth.  A ring tip inside its base circle is allowed here (the involute then ends below the
        tip); the pair's interference margins report it."""
        require(self.d_a > self.d_b or self.internal, "x", self.x,
                f"tip diameter d_a = {self.d_a:.4f} mm is inside the base circle d_b = {self.d_b:.4f} mm")
        if self.internal:
            require(self.d_f > self.d_a, "x0", self.x0,
                    f"ring root d_f = {self.d_f:.4f} mm must lie outside its tip d_a = {self.d_a:.4f} mm")
            if self.d_a >= self.d_b:
                require(self.s_na > 0.0, "x", self.x, f"ring tooth is pointed at d_a (s_na = {self.s_na:.4f} mm)")
        else:
            require(self.d_f < self.d_a, "x", self.x, "root diameter must be smaller than the tip diameter")
            require(self.s_na > 0.0, "x", self.x,
                    f"tooth is pointed: s_na = {self.s_na:.4f} mm at d_a = {self.d_a:.4f} mm (must be > 0)")

    # ---- basic dimensions
    @property
    def alpha(self) -> float:
        return self.rack.alpha

    @property
    def d(self) -> float:
        """Reference diameter d = m z."""
        return self.m * self.z

    @property
    def d_b(self) -> float:
        """Base diameter d_b = d cos α."""
        return self.d * math.cos(self.alpha)

    @property
    def p(self) -> float:
        """Pitch p = π m."""
        return math.pi * self.m

    @property
    def p_b(self) -> float:
        """Base pitch p_b = π m cos α."""
        return self.p * math.cos(self.alpha)

    @property
    def d_a(self) -> float:
        """Nominal tip diameter before any tip shortening of a pair:
        external d + 2(h_a* + x)m, ring d − 2(h_a* − x)m."""
        ha = self.rack.h_a_star
        if self.internal:
            return self.d - 2.0 * (ha - self.x) * self.m
        return self.d + 2.0 * (ha + self.x) * self.m

    @property
    def d_f(self) -> float:
        """Root diameter.  External, rack-generated: d − 2(h_a* + c* − x)m.  Ring cut by a shaper:
        d_f = d_a0 + 2 a_w0 [S-6]; ring without a shaper: d + 2(h_a* + c* + x)m."""
        hf = self.rack.h_fP_star
        if not self.internal:
            return self.d - 2.0 * (hf - self.x) * self.m
        if self.z0 is None:
            return self.d + 2.0 * (hf + self.x) * self.m
        return self.d_a0 + 2.0 * self.a_w0

    # ---- shaper cutter of a ring (GOST 19274 / GOST 9323)
    def _need_shaper(self):
        if self.z0 is None:
            raise InputError("z0", None, "this quantity needs the shaper cutter of the ring (z0, x0)")

    @property
    def d_0(self) -> float:
        self._need_shaper()
        return self.m * self.z0

    @property
    def d_a0(self) -> float:
        """Shaper tip diameter d_a0 = d0 + 2(h_a* + c* + x0)m (tool addendum = rack dedendum)."""
        self._need_shaper()
        return self.d_0 + 2.0 * (self.rack.h_fP_star + self.x0) * self.m

    @property
    def d_b0(self) -> float:
        return self.d_0 * math.cos(self.alpha)

    @property
    def alpha_w0(self) -> float:
        """Machining pressure angle of shaper and ring: inv α_w0 = inv α + 2 tan α (x − x0)/(z − z0)."""
        self._need_shaper()
        a = self.alpha
        return inv_inverse(float(inv(a)) + 2.0 * math.tan(a) * (self.x - self.x0) / (self.z - self.z0))

    @property
    def a_w0(self) -> float:
        """Machining centre distance of shaper and ring, m(z − z0)/2 · cos α / cos α_w0."""
        return self.m * (self.z - self.z0) / 2.0 * math.cos(self.alpha) / math.cos(self.alpha_w0)

    # ---- tooth thickness
    @property
    def s(self) -> float:
        """Reference arc tooth thickness: external m(π/2 + 2x tan α); ring m(π/2 − 2x tan α)."""
        t = 2.0 * self.x * math.tan(self.alpha)
        return self.m * (math.pi / 2 + (-t if self.internal else t))

    @property
    def e(self) -> float:
        """Reference arc space width e = p − s."""
        return self.p - self.s

    @property
    def s_n(self) -> float:
        """Normal tooth thickness at the reference circle (spur gear: = s)."""
        return self.s

    def s_at(self, d_y: float) -> float:
        """Arc tooth thickness on diameter d_y ≥ d_b.
        External: d_y(s/d + inv α − inv α_y); ring (tooth widens outwards): d_y(s/d − inv α + inv α_y)."""
        a_y = _acos_ratio("d_y", self.d_b, d_y)
        sgn = -1.0 if self.internal else 1.0
        return d_y * (self.s / self.d + sgn * (float(inv(self.alpha)) - float(inv(a_y))))

    def psi_at(self, d_y):
        """Half tooth angle (rad) on diameter(s) d_y ≥ d_b: s_y/d_y (vectorised)."""
        d_y = np.asarray(d_y, dtype=float)
        a_y = np.arccos(np.clip(self.d_b / d_y, -1.0, 1.0))
        sgn = -1.0 if self.internal else 1.0
        return self.s / self.d + sgn * (float(inv(self.alpha)) - inv(a_y))

    @property
    def s_na(self) -> float:
        """Tooth thickness on the nominal tip circle (spur: normal = transverse)."""
        return self.s_at(self.d_a)

    def tip_thickness(self, d_a: float) -> float:
        """Tooth thickness on a given (e.g. shortened) tip diameter."""
        return self.s_at(d_a)

    # ---- undercut (external gears, rack generation)
    @property
    def x_min(self) -> float:
        """Least profile shift free of undercut by the rack: x_min = h_l* − z sin²α / 2
        (h_l* from the tool fillet, GOST 16532).  Thesis: 0.064 (z = 16), −0.17 (z = 20)."""
        return self.rack.h_l_star - self.z * math.sin(self.alpha) ** 2 / 2.0

    @property
    def z_min(self) -> float:
        """Least tooth count of an unshifted gear free of undercut: 2 h_l*/sin²α (17.1 → 17)."""
        return 2.0 * self.rack.h_l_star / math.sin(self.alpha) ** 2

    @property
    def rho_l(self) -> float:
        """Radius of curvature of the involute at its boundary (form) point, where the tool's
        straight flank ends.  External: ½ d sin α − (h_l* − x)m / sin α (negative = undercut).
        Ring cut by a shaper: a_w0 sin α_w0 + ρ_a0 (the shaper tip generates it); ring without
        shaper: ½ d sin α + (h_l* + x)m / sin α."""
        a = self.alpha
        if not self.internal:
            return 0.5 * self.d * math.sin(a) - (self.rack.h_l_star - self.x) * self.m / math.sin(a)
        if self.z0 is None:
            return 0.5 * self.d * math.sin(a) + (self.rack.h_l_star + self.x) * self.m / math.sin(a)
        return self.a_w0 * math.sin(self.alpha_w0) + self.rho_a0

    @property
    def rho_a0(self) -> float:
        """Radius of curvature of the shaper profile at its tip (straight-flank end ignored)."""
        return 0.5 * math.sqrt(self.d_a0 ** 2 - self.d_b0 ** 2)

    @property
    def shaper_tip_cut_margin(self) -> float:
        """Ring generated by a shaper: the ring tip must meet the shaper on the shaper's involute,
        ρ_a(ring) − a_w0 sin α_w0 ≥ 0 (else the shaper cuts the ring tips, GOST 19274 'срезание')."""
        return self.rho_a - self.a_w0 * math.sin(self.alpha_w0)

    def rho_at(self, d_y: float) -> float:
        """Radius of curvature of the involute at diameter d_y: ½√(d_y² − d_b²)."""
        _acos_ratio("d_y", self.d_b, d_y)
        return 0.5 * math.sqrt(max(0.0, d_y * d_y - self.d_b ** 2))

    @property
    def rho_a(self) -> float:
        """Radius of curvature at the nominal tip circle."""
        return self.rho_at(self.d_a)

    # ---- span measurement W_k [S-7]
    def W(self, k: int) -> float:
        """Base tangent length over k teeth (ring: k spaces): m cos α [π(k − 0.5) + z inv α + 2x tan α].
        The ring's spaces are the external 'teeth', space width m(π/2 + 2x tan α) [S-7]."""
        require(int(k) == k and k >= 1, "k", k, "must be a whole number >= 1")
        a = self.alpha
        return self.m * math.cos(a) * (math.pi * (k - 0.5) + self.z * float(inv(a)) + 2.0 * self.x * math.tan(a))

    @property
    def k_W(self) -> int:
        """Number of teeth (ring: spaces) spanned, so that the caliper touches the flanks near the
        middle of the tooth height, diameter d + 2xm (ISO 21771 / DIN 3960 rule):
        k = z/π (tan α_x − inv α − 2x tan α / z) + 0.5 rounded, cos α_x = d_b/(d + 2xm).
        (GOST 16532 uses the approximation k = z α_x/π + 0.5; both give 3, 3, 9 for the thesis.)"""
        a = self.alpha
        d_x = self.d + 2.0 * self.x * self.m
        c = max(-1.0, min(1.0, self.d_b / d_x))
        a_x = math.acos(c)
        k = self.z / math.pi * (math.tan(a_x) - float(inv(a)) - 2.0 * self.x * math.tan(a) / self.z) + 0.5
        return max(1, int(round(k)))

    @property
    def W_k(self) -> float:
        """Base tangent length over k_W teeth (ring: spaces)."""
        return self.W(self.k_W)

    @property
    def rho_W(self) -> float:
        """Radius of curvature of the flanks at the W contact points, W/2."""
        return 0.5 * self.W_k

    # ---- dimension over / between rollers
    def alpha_D(self, D: float) -> float:
        """Pressure angle at the roller centre (GOST 16532 / 19274).  External: inv α_D = inv α + D/d_b − e/d
        = inv α + D/(m z cos α) − π/(2z) + 2x tan α / z; ring (roller in a space of width
        e = m(π/2 + 2x tan α)): inv α_D = inv α + e/d − D/d_b = inv α − D/(m z cos α) + π/(2z) + 2x tan α / z."""
        require_positive("D", D, "mm")
        a = self.alpha
        base = float(inv(a)) + 2.0 * self.x * math.tan(a) / self.z
        if self.internal:
            v = base + math.pi / (2 * self.z) - D / self.d_b
        else:
            v = base - math.pi / (2 * self.z) + D / self.d_b
        require(v > 0.0, "D", D, "roller too small/large for this tooth (inv α_D <= 0)")
        return inv_inverse(v)

    @property
    def D_recommended(self) -> float:
        """Roller diameter that touches the flanks on d + 2xm, the middle of the tooth height — the same
        rule that fixes k_W.  Round it to an available roller/ball size and pass that to :meth:`M`.
        (The thesis's D = 17.362 mm is a given size: 20.94 / 19.98 / 16.26 mm by this rule.)"""
        return roller_diameter_for_contact_at(self, self.d + 2.0 * self.x * self.m)

    def d_D(self, D: float) -> float:
        """Diameter of the circle through the roller centres, d_b / cos α_D."""
        return self.d_b / math.cos(self.alpha_D(D))

    def M(self, D: float) -> float:
        """Dimension over two rollers (ring: between rollers).  Even z: d_D ± D; odd z:
        d_D cos(π/(2z)) ± D (+ external, − ring)."""
        dd = self.d_D(D)
        if self.z % 2:
            dd *= math.cos(math.pi / (2 * self.z))
        return dd - D if self.internal else dd + D

    def rho_M(self, D: float) -> float:
        """Radius of curvature of the flanks at the roller contact points: ½ d_b tan α_D ∓ D/2."""
        r = 0.5 * self.d_b * math.tan(self.alpha_D(D))
        return r + 0.5 * D if self.internal else r - 0.5 * D

    # ---- constant chord
    @property
    def s_c(self) -> float:
        """Constant chord s_c = s cos²α  (external m(π/2 cos²α + x sin 2α); ring with −x)."""
        return self.s * math.cos(self.alpha) ** 2

    def h_c(self, d_a: float | None = None) -> float:
        """Height to the constant chord from the tip circle: external ½(d_a − d − s_c tan α);
        ring ½(d − d_a − s_c tan α).  Negative = the chord lies beyond the tip: not measurable."""
        da = self.d_a if d_a is None else d_a
        t = self.s_c * math.tan(self.alpha)
        return 0.5 * (self.d - da - t) if self.internal else 0.5 * (da - self.d - t)

    @property
    def rho_c(self) -> float:
        """Radius of curvature at the constant-chord points: ½ d sin α ± ½ s cos α (+ external)."""
        r = 0.5 * self.d * math.sin(self.alpha)
        h = 0.5 * self.s * math.cos(self.alpha)
        return r - h if self.internal else r + h


# --------------------------------------------------------------------------- centre distance inverse
def x_sum_for_centre_distance(z1: int, z2: int, m: float, a_w: float, rack: BasicRack = BasicRack(),
                              internal: bool = False) -> float:
    """Inverse of [S-2, S-3]: the shift sum x1 + x2 (internal: x2 − x1) that makes the operating
    centre distance a_w without backlash.  cos α_w = a cos α / a_w, x_Σ = (z2 ± z1)(inv α_w − inv α)/(2 tan α)."""
    require_positive("m", m, "mm")
    require_positive("a_w", a_w, "mm")
    zs = (z2 - z1) if internal else (z2 + z1)
    require(zs > 0, "z2", z2, "must exceed z1 for an internal pair")
    a = m * zs / 2.0
    c = a * math.cos(rack.alpha) / a_w
    require(0.0 < c < 1.0, "a_w", a_w, f"must exceed a·cos α = {a * math.cos(rack.alpha):.4f} mm")
    alpha_w = math.acos(c)
    return zs * (float(inv(alpha_w)) - float(inv(rack.alpha))) / (2.0 * math.tan(rack.alpha))
