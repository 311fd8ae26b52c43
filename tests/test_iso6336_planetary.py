"""The final drive's meshes by the letter of ISO 6336-1/-2/-3 (2019): the factors a planetary set needs beyond a
plain pair, each checked against hand arithmetic from the standard's formula with the numbers written out here
(the corrected set: z = 16/20/56, m = 10 mm, α = 20°, x = 0.5/0.5/1.5, a_w = 188.643 mm, three planets)."""

import math

import pytest

from propulsor.gears.iso6336 import MeshLoad, mesh_stress
from propulsor.gears.planetary import PlanetarySet

ALPHA = math.radians(20.0)
T_MESH = 90687.503 * 1.09 / 4.413 / 3      # N·m on the sun per mesh (seed 004 eq. 42, three planets)
V_REL = 2.0465125761411485                 # m/s, the sun's pitch-line speed relative to the carrier at 7.852 km/h


def _set():
    return PlanetarySet(n_planets=3).with_coaxial_ring()


def test_z_b_of_the_planet_in_the_ring_mesh_is_m1_with_the_rings_internal_geometry():
    """ISO 6336-2:2019, 6.2: Z_B = max(1, M_1) for the pinion also when its mate is internal; only Z_D of the
    internal wheel is 1.  With the internal wheel's z2, d_a2, d_b2 negative (the standard's sign convention):

        M_1 = tan α_w / √((√(d_a1²/d_b1² − 1) − 2π/z1)·(√(d_a2²/d_b2² − 1) + (ε_α − 1)·2π/|z2|))

    planet: d_b1 = 200·cos 20° = 187.939 mm, d_a1 = 227.286 mm (its tip as made: shortened in the sun mesh),
    ring: d_b2 = 560·cos 20° = 526.228 mm, d_a2 = 568.536 mm; cos α_w = 180·cos 20°/188.643 → α_w = 26.281°;
    ε_α = (ρ_a1 − ρ_a2 + a_w·sin α_w)/p_b = (63.948 − 108.239 + 83.530)/29.521 = 1.3291 ... (computed below)
    → M_1 = 1.2194 (the thesis prints 1.205); σ_H of the planet's flank = Z_B·σ_H0·√(K_A·K_v·K_Hβ·K_Hα)
    rises by that factor over the ring's (Z_D = 1): 793 → 967 MPa."""
    ps = _set()
    d_b1, d_b2 = 200.0 * math.cos(ALPHA), 560.0 * math.cos(ALPHA)
    d_a1, d_a2 = 227.28587198194845, 568.5358719819485
    a_w = 188.64293599097422
    alpha_w = math.acos(180.0 * math.cos(ALPHA) / a_w)
    rho_a1 = 0.5 * math.sqrt(d_a1 ** 2 - d_b1 ** 2)
    rho_a2 = 0.5 * math.sqrt(d_a2 ** 2 - d_b2 ** 2)
    p_b = math.pi * 10.0 * math.cos(ALPHA)
    eps = (rho_a1 - rho_a2 + a_w * math.sin(alpha_w)) / p_b
    f1 = math.sqrt((d_a1 / d_b1) ** 2 - 1.0) - 2.0 * math.pi / 20
    f2 = math.sqrt((d_a2 / d_b2) ** 2 - 1.0) + (eps - 1.0) * 2.0 * math.pi / 56
    M1 = math.tan(alpha_w) / math.sqrt(f1 * f2)
    assert round(M1, 3) == 1.219
    # the same ratio from the radii of curvature: √(ρ_red at the pitch point C / ρ_red at B), ρ_2 concave
    rC1, rC2 = 0.5 * d_b1 * math.tan(alpha_w), 0.5 * d_b2 * math.tan(alpha_w)
    rB1 = rho_a1 - p_b
    rB2 = rB1 + a_w * math.sin(alpha_w)
    assert M1 == pytest.approx(math.sqrt((rC1 * rC2 / (rC2 - rC1)) / (rB1 * rB2 / (rB2 - rB1))), rel=1e-12)
    s = mesh_stress(ps.mesh_planet_ring, ps.d_a_planet, ps.d_a_ring, 75.0, MeshLoad(T_MESH * 20 / 16, V_REL))
    assert s.eps_alpha == pytest.approx(eps, rel=1e-12)
    assert s.Z_B == pytest.approx(M1, rel=1e-12) and s.Z_D == 1.0
    assert s.sigma_H == pytest.approx(M1 * s.sigma_H_wheel, rel=1e-12)
