"""Angles and positions of the members of a simple planetary set (ring fixed,
sun driving, carrier driven) over a carrier turn, with the meshing phases that
let outlines be placed for an interference sweep.  Pure math.

Seed 004, ch. 4, eq. 32 (Willis): i_1H = 1 + z3/z1 with the ring held.

Outline convention (what `geometry.gear_outline` produces): an external gear has
a tooth centred on its +x axis at rotation 0; a ring (internal gear) has one of
its teeth centred on its +x axis at rotation 0.

Phasing at carrier angle psi = 0: planet 0 sits on the +x axis at the operating
centre distance a_w.  It must show a space to the sun (towards -x): its rotation
beta_0 = pi - pi/z2.  It then shows a space to the ring (towards +x) when z2 is
even; when z2 is odd it shows a tooth there and the ring is turned half a pitch.
Planet k, placed at carrier angle 2*pi*k/n, is planet 0 after the carrier has
turned by 2*pi*k/n with the sun turned by i*2*pi*k/n — a whole number of sun
pitches exactly when (z1 + z3)/n is whole (the assembly condition, eq. 31).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class PlanetaryKinematics:
    z_sun: int
    z_planet: int
    z_ring: int
    n_planets: int
    a_w: float  # operating centre distance sun-planet = planet-ring, mm

    @property
    def ratio(self) -> float:
        """Willis ratio sun -> carrier with the ring fixed (seed 004, eq. 32)."""
        return 1.0 + self.z_ring / self.z_sun

    @property
    def ring_rotation(self) -> float:
        return 0.0 if self.z_planet % 2 == 0 else math.pi / self.z_ring

    def planet_slot_angle(self, k: int) -> float:
        return 2.0 * math.pi * k / self.n_planets

    def sun_angle(self, psi):
        return self.ratio * np.asarray(psi, float)

    def planet_centre(self, psi, k: int) -> np.ndarray:
        a = np.asarray(psi, float) + self.planet_slot_angle(k)
        return np.stack([self.a_w * np.cos(a), self.a_w * np.sin(a)], axis=-1)

    def planet_angle(self, psi, k: int):
        """Absolute rotation of planet k: it turns by -z3/z2 relative to the carrier."""
        a = np.asarray(psi, float) + self.planet_slot_angle(k)
        return a * (1.0 - self.z_ring / self.z_planet) + (math.pi - math.pi / self.z_planet)

    def assembly_phase_error(self, k: int) -> float:
        """Sun rotation needed to seat planet k, in sun pitches, minus the nearest whole number."""
        pitches = self.ratio * self.planet_slot_angle(k) * self.z_sun / (2.0 * math.pi)
        return float(pitches - round(pitches))
