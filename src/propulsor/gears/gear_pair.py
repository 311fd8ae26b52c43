"""A zero-backlash involute spur pair: ISO 21771 / DIN 3960 ≡ GOST 16532-70 (external pairs) and
GOST 19274-73 (internal pairs, ring cut by a shaper cutter).

Pure math (numpy/scipy).  Millimetres and radians.  The single gear, the basic rack and the
formulas [S-1] ... [S-8] are in ``gears.involute``; this module pairs two gears: operating
pressure angle and centre distance [S-2, S-3], tip shortening [S-4, S-5], contact ratio [S-8],
interference and tip/root clearances.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..errors import InputError, require
from ..policy import ANGLE_EQUAL_TOL_RAD, MINIMIZE_XATOL
from .involute import BasicRack, SpurGear, inv, inv_inverse, x_sum_for_centre_distance

__all__ = ["GearPair"]


@dataclass(frozen=True)
class GearPair:
    """A zero-backlash pair: external pinion ``gear1`` with an external or internal ``gear2``.

    a_w follows from the shifts [S-2, S-3].  Tip diameters: external pair with shortening [S-4];
    internal pair: pinion unshortened (the pinion-tip/ring-root clearance is (c* + Δy)m ≥ c*m),
    ring tip by GOST 19274 [S-5], which leaves a ring-tip/pinion-root clearance (c* + k2)m.
    """

    gear1: SpurGear
    gear2: SpurGear

    def __post_init__(self):
        g1, g2 = self.gear1, self.gear2
        require(isinstance(g1, SpurGear) and isinstance(g2, SpurGear), "gear", (g1, g2), "must be SpurGear")
        require(not g1.internal, "gear1.internal", True, "the first gear of a pair must be external")
        require(g1.m == g2.m, "gear2.m", g2.m, f"must equal gear1.m = {g1.m}")
        require(g1.rack == g2.rack, "gear2.rack", g2.rack, "both gears must use the same basic rack")
        if g2.internal:
            require(g2.z > g1.z, "gear2.z", g2.z, f"must exceed the pinion's z = {g1.z}")
        # a_w must exist
        self.alpha_w  # noqa: B018  (raises for an impossible shift)

    # ---- pair kinematics
    @property
    def internal(self) -> bool:
        return self.gear2.internal

    @property
    def _sgn(self) -> int:
        return -1 if self.internal else 1

    @property
    def m(self) -> float:
        return self.gear1.m

    @property
    def alpha(self) -> float:
        return self.gear1.alpha

    @property
    def u(self) -> float:
        """Gear ratio u = z2/z1."""
        return self.gear2.z / self.gear1.z

    @property
    def z_sum(self) -> int:
        """z2 + z1 (internal: z2 − z1)."""
        return self.gear2.z + self._sgn * self.gear1.z

    @property
    def x_sum(self) -> float:
        """x2 + x1 (internal: x2 − x1)."""
        return self.gear2.x + self._sgn * self.gear1.x

    @property
    def a(self) -> float:
        """Reference centre distance m(z2 ± z1)/2."""
        return self.m * self.z_sum / 2.0

    @cached_property
    def alpha_w(self) -> float:
        """Operating pressure angle from inv α_w = inv α + 2 tan α (x2 ± x1)/(z2 ± z1) [S-2]."""
        v = float(inv(self.alpha)) + 2.0 * math.tan(self.alpha) * self.x_sum / self.z_sum
        require(v > 0.0, "x", self.x_sum, "shift sum too negative: inv α_w <= 0")
        return inv_inverse(v)

    @property
    def a_w(self) -> float:
        """Operating centre distance a cos α / cos α_w [S-3]."""
        return self.a * math.cos(self.alpha) / math.cos(self.alpha_w)

    @property
    def y(self) -> float:
        """Centre-distance modification coefficient (a_w − a)/m."""
        return (self.a_w - self.a) / self.m

    @property
    def delta_y(self) -> float:
        """Δy = (x2 ± x1) − y (GOST 16532 'коэффициент уравнительного смещения')."""
        return self.x_sum - self.y

    @property
    def d_w1(self) -> float:
        """Operating pitch diameter of the pinion 2 a_w z1/(z2 ± z1)."""
        return 2.0 * self.a_w * self.gear1.z / self.z_sum

    @property
    def d_w2(self) -> float:
        return 2.0 * self.a_w * self.gear2.z / self.z_sum

    # ---- tips with shortening
    @property
    def k2(self) -> float:
        """GOST 19274 ring-tip coefficient: 0.25 − 0.125 x2 for x2 < 2, else 0 (h_a* = 1, α = 20°);
        0 for other racks and for external pairs."""
        r = self.gear1.rack
        if not self.internal or not (abs(r.alpha - math.radians(20.0)) < ANGLE_EQUAL_TOL_RAD and r.h_a_star == 1.0):
            return 0.0
        x2 = self.gear2.x
        return 0.25 - 0.125 * x2 if x2 < 2.0 else 0.0

    @property
    def d_a1(self) -> float:
        """Pinion tip diameter: external pair d1 + 2(h_a* + x1 − Δy)m [S-4]; internal pair unshortened."""
        g = self.gear1
        if self.internal:
            return g.d_a
        return g.d + 2.0 * (g.rack.h_a_star + g.x - self.delta_y) * g.m

    @property
    def d_a2(self) -> float:
        """Wheel tip diameter: external d2 + 2(h_a* + x2 − Δy)m [S-4]; ring
        d2 − 2(h_a* − x2 + Δy − k2)m [S-5]."""
        g = self.gear2
        ha = g.rack.h_a_star
        if self.internal:
            return g.d - 2.0 * (ha - g.x + self.delta_y - self.k2) * g.m
        return g.d + 2.0 * (ha + g.x - self.delta_y) * g.m

    def _tips(self, d_a1, d_a2):
        return (self.d_a1 if d_a1 is None else float(d_a1)), (self.d_a2 if d_a2 is None else float(d_a2))

    @property
    def c_root1(self) -> float:
        """Radial clearance at the pinion root (mate's tip to pinion root)."""
        if self.internal:
            return 0.5 * self.d_a2 - self.a_w - 0.5 * self.gear1.d_f
        return self.a_w - 0.5 * self.d_a2 - 0.5 * self.gear1.d_f

    @property
    def c_root2(self) -> float:
        """Radial clearance at the wheel/ring root (pinion tip to wheel/ring root)."""
        if self.internal:
            return 0.5 * self.gear2.d_f - self.a_w - 0.5 * self.d_a1
        return self.a_w - 0.5 * self.d_a1 - 0.5 * self.gear2.d_f

    # ---- contact
    @property
    def g_w(self) -> float:
        """Length N1N2 of the line of action between the base-circle tangency points, a_w sin α_w."""
        return self.a_w * math.sin(self.alpha_w)

    def rho_a1(self, d_a1: float | None = None) -> float:
        return self.gear1.rho_at(self._tips(d_a1, None)[0])

    def rho_a2(self, d_a2: float | None = None) -> float:
        return self.gear2.rho_at(self._tips(None, d_a2)[1])

    def rho_p1(self, d_a2: float | None = None) -> float:
        """Radius of curvature of the pinion at its lowest active point (mate's tip contact):
        external a_w sin α_w − ρ_a2; internal ρ_a2 − a_w sin α_w."""
        r2 = self.rho_a2(d_a2)
        return r2 - self.g_w if self.internal else self.g_w - r2

    def rho_p2(self, d_a1: float | None = None) -> float:
        """Wheel/ring radius of curvature at its lowest (ring: deepest) active point:
        external a_w sin α_w − ρ_a1; internal a_w sin α_w + ρ_a1."""
        r1 = self.rho_a1(d_a1)
        return self.g_w + r1 if self.internal else self.g_w - r1

    def epsilon_alpha(self, d_a1: float | None = None, d_a2: float | None = None) -> float:
        """Transverse contact ratio [S-8]: external (ρ_a1 + ρ_a2 − a_w sin α_w)/p_b,
        internal (ρ_a1 − ρ_a2 + a_w sin α_w)/p_b."""
        r1, r2 = self.rho_a1(d_a1), self.rho_a2(d_a2)
        g = r1 - r2 + self.g_w if self.internal else r1 + r2 - self.g_w
        return g / self.gear1.p_b

    def specific_sliding(self, d_a1: float | None = None, d_a2: float | None = None) -> tuple[float, float]:
        """Specific sliding at the lowest active points: ϑ_p1 = 1 − (ρ_a2/ρ_p1)(z1/z2),
        ϑ_p2 = 1 − (ρ_a1/ρ_p2)(z2/z1) (thesis Table 6: −0.73659, −0.81711)."""
        r1, r2 = self.rho_a1(d_a1), self.rho_a2(d_a2)
        p1, p2 = self.rho_p1(d_a2), self.rho_p2(d_a1)
        z1, z2 = self.gear1.z, self.gear2.z
        return 1.0 - r2 / p1 * z1 / z2, 1.0 - r1 / p2 * z2 / z1

    # ---- interference
    def involute_interference_margins(self, d_a1: float | None = None,
                                      d_a2: float | None = None) -> tuple[float, float]:
        """(pinion, wheel) margins, mm of radius of curvature, ≥ 0 when the mate's tip meets the
        flank on its involute above the boundary point (GOST 16532/19274: ρ_l ≤ ρ_p; ring:
        ρ_p2 ≤ ρ_l2).  For a ring the first margin ≥ 0 is also KHK's involute-interference
        condition z1/z2 ≥ 1 − tan α_a2 / tan α_w (when ρ_l1 ≤ 0)."""
        da2 = self._tips(None, d_a2)[1]
        if self.internal and da2 < self.gear2.d_b:
            # ring tip inside its base circle: the involute ends before the tip; the mesh
            # interferes by at least the radial shortfall (reported negative, not raised)
            m1 = -0.5 * (self.gear2.d_b - da2) - max(self.gear1.rho_l, 0.0)
        else:
            m1 = self.rho_p1(d_a2) - max(self.gear1.rho_l, 0.0)
        if self.internal:
            m2 = self.gear2.rho_l - self.rho_p2(d_a1)
        else:
            m2 = self.rho_p2(d_a1) - max(self.gear2.rho_l, 0.0)
        return m1, m2

    def tip_interference_depth(self, d_a1: float | None = None, d_a2: float | None = None,
                               samples: int = 6001) -> float:
        """Internal pair: the larger of :meth:`tip_interference_depths` (mm, > 0 = interference)."""
        return max(self.tip_interference_depths(d_a1, d_a2, samples))

    def tip_interference_depths(self, d_a1: float | None = None, d_a2: float | None = None,
                                samples: int = 6001) -> tuple[float, float]:
        """Internal pair: (pinion tips, ring tips) - the largest depth (mm, > 0 = interference) by which a
        tip corner of either gear enters a tooth of the other over the whole relative motion (trochoidal/tip
        interference, KHK 'trochoid interference'; GOST 19274 'интерференция вершин').

        Direct kinematic check: the pinion turns φ1, the ring φ1 z1/z2 in the same sense; the
        tip corners (half tooth angle at the tip) are mapped into the mate's frame and compared
        with the mate's involute tooth (half angle ψ(r), valid above its base circle); a corner past
        the ring's root circle, or inside the pinion's, is in the mate's body, as deep as it is past
        that circle (a tip striking the root: no tip clearance).  Conjugate contact gives depth 0 (to
        rounding), so a positive result above ~1e-6 mm is real.  The first value is the deepest a pinion tip corner
        goes into the ring (its teeth or its rim), the second the deepest a ring tip corner goes into the pinion; -inf
        where a gear's corners never reach the mate.
        """
        require(self.internal, "gear2.internal", False, "tip interference sweep is for internal pairs")
        from scipy.optimize import minimize_scalar

        g1, g2 = self.gear1, self.gear2
        da1, da2 = self._tips(d_a1, d_a2)
        ra1, ra2 = 0.5 * da1, 0.5 * da2
        rf2 = 0.5 * g2.d_f
        rf1 = 0.5 * g1.d_f
        aw = self.a_w
        z1, z2 = g1.z, g2.z
        psi_a1 = float(g1.psi_at(da1))
        psi_a2 = float(g2.psi_at(max(da2, g2.d_b)))
        r_in2 = max(ra2, 0.5 * g2.d_b)
        # ring centre at the origin, pinion centre O1 = (0, a_w), pitch point on +y;
        # at φ1 = 0 a pinion tooth and a ring space are centred on the +y axis.

        def pinion_corner(phi, sgn):  # depth of a pinion tip corner inside the ring teeth
            phi = np.atleast_1d(np.asarray(phi, dtype=float))
            ang = math.pi / 2 + phi + sgn * psi_a1
            px, py = ra1 * np.cos(ang), aw + ra1 * np.sin(ang)
            phi2 = phi * z1 / z2
            c, s = np.cos(phi2), np.sin(phi2)
            qx, qy = c * px + s * py, -s * px + c * py
            r = np.hypot(qx, qy)
            inside = (r > r_in2) & (r < rf2)
            pitch = 2 * math.pi / z2
            rel = (np.arctan2(qy, qx) - (math.pi / 2 + math.pi / z2)) / pitch
            dth = (rel - np.round(rel)) * pitch
            psi = g2.psi_at(np.where(inside, 2.0 * r, g2.d))
            # past the ring's root circle the corner is in the rim itself: as deep as it is past it
            return np.where(inside, (psi - np.abs(dth)) * r, np.where(r >= rf2, r - rf2, -np.inf))

        def ring_corner(phi, sgn):  # depth of a ring tip corner inside the pinion teeth
            phi = np.atleast_1d(np.asarray(phi, dtype=float))
            ang = math.pi / 2 + math.pi / z2 + phi * z1 / z2 + sgn * psi_a2
            dx, dy = ra2 * np.cos(ang), ra2 * np.sin(ang) - aw
            c, s = np.cos(phi), np.sin(phi)
            qx, qy = c * dx + s * dy, -s * dx + c * dy
            r = np.hypot(qx, qy)
            inside = (r > max(0.5 * g1.d_b, rf1)) & (r < ra1)
            pitch = 2 * math.pi / z1
            rel = (np.arctan2(qy, qx) - math.pi / 2) / pitch
            dth = (rel - np.round(rel)) * pitch
            psi = g1.psi_at(np.where(inside, 2.0 * r, g1.d))
            # inside the pinion's root circle the corner is in its body: as deep as it is inside it
            return np.where(inside, (psi - np.abs(dth)) * r, np.where(r <= rf1, rf1 - r, -np.inf))

        phi = np.linspace(-math.pi, math.pi, samples)
        step = phi[1] - phi[0]
        depths = []
        for fn in (pinion_corner, ring_corner):
            worst = -math.inf
            for sgn in (-1.0, 1.0):
                dep = fn(phi, sgn)
                i = int(np.argmax(dep))
                if not np.isfinite(dep[i]):
                    continue
                best = float(dep[i])
                res = minimize_scalar(lambda f: -float(fn(f, sgn)[0]) if np.isfinite(fn(f, sgn)[0]) else 1e9,
                                      bounds=(phi[i] - step, phi[i] + step), method="bounded",
                                      options={"xatol": MINIMIZE_XATOL})
                if res.success and -res.fun > best:
                    best = float(-res.fun)
                worst = max(worst, best)
            depths.append(worst)
        return depths[0], depths[1]

    @property
    def s_na1(self) -> float:
        """Pinion tooth thickness on its tip as made in this pair (shortened for external pairs)."""
        return self.gear1.tip_thickness(self.d_a1)

    @property
    def s_na2(self) -> float:
        """Wheel/ring tooth thickness on its tip as made in this pair (ring tip must be ≥ d_b2)."""
        return self.gear2.tip_thickness(self.d_a2)

    def sheet(self, D: float | None = None, d_a1: float | None = None,
              d_a2: float | None = None) -> list[tuple[str, str, str, float | None, float | None]]:
        """The calculation sheet as rows (quantity, symbol, unit, gear 1, gear 2); pair quantities in
        the gear-1 column.  Tips: ``d_a1``, ``d_a2`` as the gears are made (a planet serves two meshes and
        has one tip); by default the ones made for this pair.  Every tip-dependent row (d_a, h_c, s_na,
        ρ_p, ε_α) is taken on these tips.  ``D``: measuring roller diameter (default: each gear's
        :attr:`SpurGear.D_recommended`)."""
        g1, g2 = self.gear1, self.gear2
        da1, da2 = self._tips(d_a1, d_a2)
        deg = math.degrees
        rows: list[tuple[str, str, str, float | None, float | None]] = [
            ("number of teeth", "z", "-", g1.z, g2.z),
            ("module", "m", "mm", g1.m, None),
            ("pressure angle", "alpha", "deg", deg(g1.alpha), None),
            ("profile shift coefficient", "x", "-", g1.x, g2.x),
            ("gear ratio", "u", "-", self.u, None),
            ("operating pressure angle", "alpha_w", "deg", deg(self.alpha_w), None),
            ("operating centre distance", "a_w", "mm", self.a_w, None),
            ("centre distance modification coefficient", "y", "-", self.y, None),
            ("tip shortening coefficient", "delta_y", "-", self.delta_y, None),
            ("reference diameter", "d", "mm", g1.d, g2.d),
            ("tip diameter", "d_a", "mm", da1, da2),
            ("root diameter", "d_f", "mm", g1.d_f, g2.d_f),
            ("operating pitch diameter", "d_w", "mm", self.d_w1, self.d_w2),
            ("base diameter", "d_b", "mm", g1.d_b, g2.d_b),
            ("reference tooth thickness", "s_n", "mm", g1.s_n, g2.s_n),
            ("constant chord", "s_c", "mm", g1.s_c, g2.s_c),
            ("height to constant chord", "h_c", "mm", g1.h_c(da1), g2.h_c(da2)),
            ("teeth (ring: spaces) spanned", "k", "-", g1.k_W, g2.k_W),
            ("base tangent length", "W_k", "mm", g1.W_k, g2.W_k),
        ]
        D1 = g1.D_recommended if D is None else D
        D2 = g2.D_recommended if D is None else D
        rows += [
            ("measuring roller diameter", "D", "mm", D1, D2),
            ("pressure angle at roller centre", "alpha_D", "deg", deg(g1.alpha_D(D1)), deg(g2.alpha_D(D2))),
            ("roller centre circle diameter", "d_D", "mm", g1.d_D(D1), g2.d_D(D2)),
            ("dimension over (ring: between) rollers", "M", "mm", g1.M(D1), g2.M(D2)),
            ("least profile shift (no undercut)", "x_min", "-", g1.x_min, None if g2.internal else g2.x_min),
            ("radius of curvature at boundary point", "rho_l", "mm", g1.rho_l, g2.rho_l),
        ]
        try:
            rows += [
                ("tooth thickness on tip circle", "s_na", "mm", g1.tip_thickness(da1), g2.tip_thickness(da2)),
                ("radius of curvature at lowest active point", "rho_p", "mm", self.rho_p1(da2), self.rho_p2(da1)),
                ("transverse contact ratio", "epsilon_alpha", "-", self.epsilon_alpha(da1, da2), None),
            ]
        except InputError:  # a ring tip inside its base circle: these are undefined
            pass
        return rows

    # ---- the inverse problem
    @staticmethod
    def x_sum_for(z1: int, z2: int, m: float, a_w: float, rack: BasicRack = BasicRack(),
                  internal: bool = False) -> float:
        """See :func:`x_sum_for_centre_distance`."""
        return x_sum_for_centre_distance(z1, z2, m, a_w, rack, internal)
