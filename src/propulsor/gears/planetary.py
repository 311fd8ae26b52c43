"""Simple planetary set (sun 1, planets 2, ring 3, carrier H; ring fixed) and its conditions.

Seed 004 ch. 4, eq. 30–35: Willis ratio i_1H = 1 + z3/z1 (eq. 32), coaxiality r_H = r_w1 + r_w2 =
r_w3 − r_w2 (with profile shifts: the operating centre distances of the sun–planet and the
planet–ring meshes are equal), neighbour condition 2 r_H sin(π/k) > d_a,planet (eq. 30), assembly
condition z1 i_1H (1 + kp)/k whole (eq. 31) ⇔ (z1 + z3)/k whole.  Gear geometry from
:mod:`propulsor.gears.involute` (GOST 16532 / GOST 19274).

The thesis set (z = 16/20/56, m = 10, x = 0.5/0.5/1.417, shaper z0 = 14, x0 = 0.04) is not
coaxial: sun–planet a_w = 188.643 mm, planet–ring a_w = 187.997 mm (the thesis prints 188), a
0.646 mm mismatch.  :meth:`PlanetarySet.ring_shift_for_coaxiality` gives x3 = 1.5 (exactly
x1 + 2 x2 here, because z3 − z2 = z1 + z2).

Pure math: numpy/scipy only.  Millimetres, radians.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property
from typing import NamedTuple

from ..errors import InputError, require, require_finite, require_positive
from ..policy import (
    GEAR_CONTACT_RATIO_MIN,
    GEAR_INTERFERENCE_TOL_MM,
    GEAR_TIP_THICKNESS_MIN_MODULE,
    PLANET_TIP_CLEARANCE_MIN_MODULE,
    PLANETARY_COAXIALITY_TOL_MM,
)
from .gear_pair import GearPair
from .involute import BasicRack, SpurGear, x_sum_for_centre_distance

__all__ = ["Condition", "PlanetarySet"]


class Condition(NamedTuple):
    """One checked condition, as it goes into the manifest."""

    name: str
    passed: bool
    value: float
    limit: float
    unit: str
    message: str


@dataclass(frozen=True)
class PlanetarySet:
    """Sun / planets / fixed ring with profile shifts, the ring cut by a shaper (z0, x0).

    Defaults are the thesis's final drive (seed 004 ch. 4) with its printed ring shift
    1.417 — which fails coaxiality; pass ``x_ring=PlanetarySet().ring_shift_for_coaxiality()``
    (= 1.5) for the corrected set.
    """

    z_sun: int = 16
    z_planet: int = 20
    z_ring: int = 56
    m: float = 10.0
    x_sun: float = 0.5
    x_planet: float = 0.5
    x_ring: float = 1.417
    n_planets: int = 4
    rack: BasicRack = field(default_factory=BasicRack)
    z0: int | None = 14
    x0: float = 0.04
    b_sun: float = 80.0
    b_planet: float = 75.0
    b_ring: float = 80.0
    ratio_target: float | None = None
    ratio_tol: float = 0.0

    def __post_init__(self):
        require_positive("m", self.m, "mm")
        k = require_finite("n_planets", self.n_planets)
        require(float(k).is_integer() and k >= 1, "n_planets", self.n_planets, "must be a whole number >= 1")
        object.__setattr__(self, "n_planets", int(k))
        for name in ("b_sun", "b_planet", "b_ring"):
            require_positive(name, getattr(self, name), "mm")
        if self.ratio_target is not None:
            require_positive("ratio_target", self.ratio_target)
            t = require_finite("ratio_tol", self.ratio_tol)
            require(t >= 0.0, "ratio_tol", self.ratio_tol, "must be >= 0")
        require(self.z_ring > self.z_sun and self.z_ring > self.z_planet, "z_ring", self.z_ring,
                f"must exceed z_sun = {self.z_sun} and z_planet = {self.z_planet}")
        # building the gears and meshes validates teeth, shifts and the operating angles
        self.mesh_sun_planet  # noqa: B018
        self.mesh_planet_ring  # noqa: B018

    # ---- members
    @cached_property
    def sun(self) -> SpurGear:
        return SpurGear(self.z_sun, self.m, self.x_sun, self.rack)

    @cached_property
    def planet(self) -> SpurGear:
        return SpurGear(self.z_planet, self.m, self.x_planet, self.rack)

    @cached_property
    def ring(self) -> SpurGear:
        return SpurGear(self.z_ring, self.m, self.x_ring, self.rack, internal=True, z0=self.z0, x0=self.x0)

    @cached_property
    def mesh_sun_planet(self) -> GearPair:
        return GearPair(self.sun, self.planet)

    @cached_property
    def mesh_planet_ring(self) -> GearPair:
        return GearPair(self.planet, self.ring)

    # ---- kinematics
    @property
    def ratio(self) -> float:
        """Willis ratio sun → carrier with the ring fixed, i_1H = 1 + z3/z1 (seed 004 eq. 32)."""
        return 1.0 + self.z_ring / self.z_sun

    # ---- centre distances
    @property
    def a_w(self) -> float:
        """Carrier radius r_H = sun–planet operating centre distance."""
        return self.mesh_sun_planet.a_w

    @property
    def coaxiality_mismatch(self) -> float:
        """a_w(planet–ring) − a_w(sun–planet), mm (0 for a coaxial set)."""
        return self.mesh_planet_ring.a_w - self.mesh_sun_planet.a_w

    def ring_shift_for_coaxiality(self) -> float:
        """x_ring that makes the planet–ring a_w equal the sun–planet a_w (inverse of GOST 19274
        inv α_w relation): x3 = x2 + (z3 − z2)(inv α_w − inv α)/(2 tan α), cos α_w = a cos α / a_w."""
        return self.x_planet + x_sum_for_centre_distance(
            self.z_planet, self.z_ring, self.m, self.a_w, self.rack, internal=True)

    def with_coaxial_ring(self) -> "PlanetarySet":
        """The same set with the ring shift corrected for coaxiality."""
        return replace(self, x_ring=self.ring_shift_for_coaxiality())

    # ---- tips as made (one planet serves both meshes)
    @property
    def d_a_sun(self) -> float:
        return self.mesh_sun_planet.d_a1

    @property
    def d_a_planet(self) -> float:
        """Planet tip: the smaller of its tip in the external mesh (shortened, GOST 16532) and in
        the internal mesh (GOST 19274, unshortened)."""
        return min(self.mesh_sun_planet.d_a2, self.mesh_planet_ring.d_a1)

    @property
    def d_a_ring(self) -> float:
        return self.mesh_planet_ring.d_a2

    # ---- the four conditions of the seed
    @property
    def neighbour_gap(self) -> float:
        """Gap between the tip circles of adjacent planets, 2 a_w sin(π/k) − d_a,planet (eq. 30)."""
        if self.n_planets == 1:
            return math.inf
        return 2.0 * self.a_w * math.sin(math.pi / self.n_planets) - self.d_a_planet

    @property
    def assembly_quotient(self) -> float:
        """(z1 + z3)/k — whole for equally spaced planets (eq. 31 with i_1H = 1 + z3/z1; p drops out)."""
        return (self.z_sun + self.z_ring) / self.n_planets

    @property
    def assembly_ok(self) -> bool:
        return (self.z_sun + self.z_ring) % self.n_planets == 0

    @property
    def epsilon_alpha_sun_planet(self) -> float:
        return self.mesh_sun_planet.epsilon_alpha(self.d_a_sun, self.d_a_planet)

    @property
    def epsilon_alpha_planet_ring(self) -> float:
        return self.mesh_planet_ring.epsilon_alpha(self.d_a_planet, self.d_a_ring)

    # ---- all conditions
    def conditions(self) -> list[Condition]:
        """Every condition of the set, passed or not, as manifest records."""
        out: list[Condition] = []
        m = self.m
        sp, pr = self.mesh_sun_planet, self.mesh_planet_ring

        def add(name, passed, value, limit, unit, message):
            out.append(Condition(name, bool(passed), float(value), float(limit), unit, message))

        # Willis ratio (eq. 32)
        if self.ratio_target is None:
            add("willis_ratio", True, self.ratio, self.ratio, "-", f"i_1H = 1 + z3/z1 = {self.ratio:.6g}")
        else:
            dev = abs(self.ratio - self.ratio_target)
            add("willis_ratio", dev <= self.ratio_tol, dev, self.ratio_tol, "-",
                f"|i_1H − i_target| = |{self.ratio:.6g} − {self.ratio_target:.6g}| must be <= {self.ratio_tol:g}")
        # coaxiality
        mis = self.coaxiality_mismatch
        add("coaxiality", abs(mis) <= PLANETARY_COAXIALITY_TOL_MM, abs(mis), PLANETARY_COAXIALITY_TOL_MM, "mm",
            f"a_w sun–planet {sp.a_w:.4f} mm vs planet–ring {pr.a_w:.4f} mm; "
            f"x_ring for coaxiality = {self.ring_shift_for_coaxiality():.5f}")
        # neighbours (eq. 30)
        gap_min = PLANET_TIP_CLEARANCE_MIN_MODULE * m
        gap = self.neighbour_gap
        add("neighbour", gap >= gap_min, gap if math.isfinite(gap) else 1e300, gap_min, "mm",
            f"2·a_w·sin(π/{self.n_planets}) − d_a,planet = {gap:.4f} mm must be >= {gap_min:.4f} mm")
        # assembly (eq. 31)
        q = self.assembly_quotient
        add("assembly", self.assembly_ok, q, round(q), "-",
            f"(z1 + z3)/k = {self.z_sun + self.z_ring}/{self.n_planets} = {q:.6g} must be whole")
        # contact ratios
        for name, getter in (("contact_ratio_sun_planet", lambda: self.epsilon_alpha_sun_planet),
                             ("contact_ratio_planet_ring", lambda: self.epsilon_alpha_planet_ring)):
            try:
                eps = getter()
            except InputError as exc:  # a tip inside its base circle: no involute contact to measure
                add(name, False, 0.0, GEAR_CONTACT_RATIO_MIN, "-", f"ε_α undefined: {exc}")
                continue
            add(name, eps >= GEAR_CONTACT_RATIO_MIN, eps, GEAR_CONTACT_RATIO_MIN, "-",
                f"ε_α = {eps:.4f} must be >= {GEAR_CONTACT_RATIO_MIN}")
        # undercut (rack-generated external gears)
        for name, g in (("undercut_sun", self.sun), ("undercut_planet", self.planet)):
            add(name, g.x >= g.x_min, g.x, g.x_min, "-", f"x = {g.x:.4f} must be >= x_min = {g.x_min:.4f}")
        # pointed tips (on the tips as made)
        s_min = GEAR_TIP_THICKNESS_MIN_MODULE * m
        for name, g, da in (("tip_thickness_sun", self.sun, self.d_a_sun),
                            ("tip_thickness_planet", self.planet, self.d_a_planet),
                            ("tip_thickness_ring", self.ring, self.d_a_ring)):
            if da < g.d_b:
                add(name, False, -1.0, s_min, "mm", f"tip d_a = {da:.4f} mm inside the base circle")
                continue
            s_a = g.tip_thickness(da)
            add(name, s_a >= s_min, s_a, s_min, "mm", f"s_na = {s_a:.4f} mm must be >= {s_min:.4f} mm")
        # interference
        for mesh, tag, tips in ((sp, "sun_planet", (self.d_a_sun, self.d_a_planet)),
                                (pr, "planet_ring", (self.d_a_planet, self.d_a_ring))):
            m1, m2 = mesh.involute_interference_margins(*tips)
            for who, mar in (("pinion" if tag == "sun_planet" else "planet", m1),
                             ("wheel" if tag == "sun_planet" else "ring", m2)):
                add(f"involute_interference_{tag}_{who}", mar >= 0.0, mar, 0.0, "mm",
                    f"active profile margin (ρ_p − ρ_l) = {mar:.4f} mm must be >= 0")
        depth = pr.tip_interference_depth(self.d_a_planet, self.d_a_ring)
        add("tip_interference_planet_ring", depth <= GEAR_INTERFERENCE_TOL_MM, depth, GEAR_INTERFERENCE_TOL_MM, "mm",
            f"deepest tip-corner entry {depth:.3e} mm must be <= {GEAR_INTERFERENCE_TOL_MM:g} mm")
        # radial clearances
        for mesh, tag in ((sp, "sun_planet"), (pr, "planet_ring")):
            c = min(self._root_clearances(mesh))
            add(f"root_clearance_{tag}", c > 0.0, c, 0.0, "mm", f"least tip-to-root clearance {c:.4f} mm must be > 0")
        # ring generation by the shaper
        if self.z0 is not None and self.d_a_ring >= self.ring.d_b:
            r = self.ring
            marg = (r.rho_at(self.d_a_ring) - r.a_w0 * math.sin(r.alpha_w0))
            add("ring_tip_cut_by_shaper", marg >= 0.0, marg, 0.0, "mm",
                f"ring tip meets the shaper on its involute: margin {marg:.4f} mm must be >= 0")
        return out

    def _root_clearances(self, mesh: GearPair) -> tuple[float, float]:
        d1 = self.d_a_sun if mesh is self.mesh_sun_planet else self.d_a_planet
        d2 = self.d_a_planet if mesh is self.mesh_sun_planet else self.d_a_ring
        g1, g2 = mesh.gear1, mesh.gear2
        if mesh.internal:
            return 0.5 * d2 - mesh.a_w - 0.5 * g1.d_f, 0.5 * g2.d_f - mesh.a_w - 0.5 * d1
        return mesh.a_w - 0.5 * d2 - 0.5 * g1.d_f, mesh.a_w - 0.5 * d1 - 0.5 * g2.d_f

    def failures(self) -> list[Condition]:
        """The conditions that do not hold."""
        return [c for c in self.conditions() if not c.passed]

    @property
    def valid(self) -> bool:
        return not self.failures()
