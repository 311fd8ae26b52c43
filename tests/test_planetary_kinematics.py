"""Planetary kinematics: Willis ratio, pitch-line speeds, assembly phasing (seed 004 eq. 31-32)."""

import math

import numpy as np
import pytest

from propulsor.gears.planetary_kinematics import PlanetaryKinematics


def test_willis_ratio_of_the_thesis_set():
    k = PlanetaryKinematics(16, 20, 56, 3, 188.643)
    assert k.ratio == pytest.approx(4.5, abs=1e-15)


def test_pitch_line_speeds_match_in_both_meshes():
    z1, z2, z3, m = 16, 20, 56, 10.0
    k = PlanetaryKinematics(z1, z2, z3, 3, m * (z1 + z2) / 2)
    psi = np.array([0.0, 1e-3])
    # relative to the carrier
    sun_rel = np.diff(k.sun_angle(psi) - psi)[0]
    planet_rel = np.diff(k.planet_angle(psi, 0) - psi)[0]
    ring_rel = -np.diff(psi)[0]
    assert sun_rel * m * z1 / 2 == pytest.approx(-planet_rel * m * z2 / 2, rel=1e-12)  # external: opposite
    assert planet_rel * m * z2 / 2 == pytest.approx(ring_rel * m * z3 / 2, rel=1e-12)  # internal: same sense


@pytest.mark.parametrize("n, whole", [(3, True), (4, True), (5, False), (6, True), (7, False)])
def test_assembly_phase_error_is_zero_exactly_when_condition_holds(n, whole):
    k = PlanetaryKinematics(16, 20, 56, n, 188.0)
    errs = [abs(k.assembly_phase_error(j)) for j in range(n)]
    assert (max(errs) < 1e-12) == whole == ((16 + 56) % n == 0)
