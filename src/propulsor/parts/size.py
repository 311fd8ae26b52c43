"""Size estimates of the builds: what a part file will cost, from its parameters, before any work.

Each model counts what drives the build's time — teeth (outline samples, tessellation), motion-proof
steps times the outline size each step handles, tessellated length for a fixed chord — and weighs
them with coefficients measured on this machine (2 cores) by building the part files of parts/ and
variants with the counts doubled or quadrupled (CPU seconds of the build and its workers; a build
keeps both cores busy, so its wall time is CPU / `_CORES_USED`).  They are meant to refuse builds
that cannot finish in minutes (policy.BUILD_SECONDS_MAX), not to predict a build to the second.

Calibration (CPU s; default part file → variant):
final drive 28.1 → 39.2 with the sweep density doubled, → 43.8 with every tooth count doubled (before the
carrier; the carrier solid, its pin sweep and the strength step add 11.5 CPU s: 24.9 → 36.4 user s);
non-circular pair (seed 002) 25.2 → 26.5 with the proof phases doubled, → 42.6 with the teeth doubled (2026-11-28:
its as-built contact recalibrated after the compiled search, 1.2 → 0.3 ms a position, over one period of the pair:
`bench/bench_size_estimates.py` gives estimate / measured CPU 0.73 .. 1.18 on the ten ncg part files);
cam mover (exponential law) 18.7 → 32.7 with 4 × the sweep steps; balancer 17.1 → 29.6 with 4 × the
travel steps (2026-11-25: damper heat exact, the drill point's mesh measured, not halved three times; before:
92.7 → 161.3, and → 143.5 with the sweep chord a quarter, whose exponent is kept); road wheel 17.8.
The other models were calibrated before the later build speed-ups and now overestimate by a fifth to a third;
the builds of several part files start the longest first by these estimates.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class SizeEstimate:
    """What a build will cost, estimated from the parameters before any work.

    `seconds`: the build's time on the reference machine (2 cores), from a cost model calibrated on
    the part files in parts/; `detail`: what the model counts (teeth, samples, sweep steps)."""

    seconds: float
    detail: str

    @property
    def cpu_seconds(self) -> float:
        """The build's CPU seconds (its process and its workers): what a busy machine stretches over more time."""
        return self.seconds * _CORES_USED

    def text(self) -> str:
        return (f"≈ {self.seconds:.2g} s on two idle cores ({self.cpu_seconds:.2g} CPU s: longer on a busy machine; "
                f"{self.detail})" if self.seconds > 0 else self.detail)


#: a build keeps about this many cores busy (main process and its forked workers)
_CORES_USED = 1.8


def wall(cpu_seconds: float, detail: str) -> SizeEstimate:
    return SizeEstimate(cpu_seconds / _CORES_USED, detail)


def final_drive(p, part_file: Path | None = None) -> SizeEstimate:
    """Solids ∝ teeth of sun + planet + ring; sweep ∝ steps × meshes × √(teeth / 92); carrier and strength
    a fixed 11.5 CPU s; the rest fixed 12 CPU s (45-59 measured on the two part files, 2026-11-28, against 39.6
    estimated with 6)."""
    teeth = p.z_sun + p.z_planet + p.z_ring
    steps = round(360.0 * p.sweep_steps_per_deg)
    meshes = 2 * p.n_planets
    cpu = 12.0 + 11.5 + 0.12 * teeth + 0.00257 * steps * meshes * math.sqrt(teeth / 92.0)
    return wall(cpu, f"{teeth} teeth, sweep {steps} steps × {meshes} meshes")


def cam_mover(p, part_file: Path | None = None) -> SizeEstimate:
    """Fixed 14 CPU s (law, outlines, six solids) scaled with the tessellated length for the fixed
    chord (∝ √ size), 6.5 ms per sweep step, 3 s more for the law search."""
    size = max(1.0, (p.R0_mm + p.roller_radius_mm + p.stand_C_mm) / 320.0)
    cpu = 14.0 * math.sqrt(size) + 0.0065 * p.sweep_steps * math.sqrt(size) + (3.2 if p.law == "searched" else 0.0)
    return wall(cpu, f"{p.sweep_steps} sweep steps, hub height {p.R0_mm + p.roller_radius_mm + p.stand_C_mm:g} mm")


def road_wheel(p, part_file: Path | None = None) -> SizeEstimate:
    """Revolved solids: tessellated length ∝ √ radius for the fixed chord, times the web holes."""
    size = max(1.0, p.tyre_radius_mm / 315.0)
    holes = p.rows * p.lightening_holes
    cpu = (4.0 + 1.0 * p.rows + 0.4 * holes) * math.sqrt(size) * 1.4
    return wall(cpu, f"{p.rows} row(s), {holes} lightening holes, R = {p.tyre_radius_mm:g} mm")


def polysector_gear(p, part_file: Path | None = None) -> SizeEstimate:
    """Design, three solids and their checks ∝ teeth of the gear and a sector; one assembly and one DXF per
    flow per position; the proof ∝ its steps (steps per pitch × pitches per sector period), 0.022 CPU s a
    step with the outlines within 1e-4 mm, 0.041 s at the blank's own circle (e = 0, outlines within 3e-5 mm
    to resolve Δi below 1e-6); the tracked contact law ≈ 3.7 CPU s a position (refined at every hand-over).
    Calibrated on parts/polysector.toml: 29 CPU s with three positions and the contact law (2026-11-25;
    20.5 with four positions before it); 51.7 CPU s measured on 2026-11-28 (a loaded machine), the fixed part raised
    from 6.2 to 20 CPU s."""
    per = p.flows * p.sectors_per_flow
    zc = [z for z in p.conditional_teeth if isinstance(z, int) and not isinstance(z, bool)]
    steps = [p.proof_steps_per_pitch * max(1, z // per) for z in zc]
    proof = sum(n * (0.041 if z == p.blank_teeth else 0.022) for n, z in zip(steps, zc))
    cpu = 20.0 + 0.093 * (p.gear_teeth + p.sector_teeth) + 0.62 * len(zc) * p.flows + proof + 3.7 * len(zc)
    return wall(cpu, f"{len(zc)} positions, proof {sum(steps)} steps, {p.gear_teeth + p.sector_teeth} teeth")


ESTIMATES = {
    "polysector_gear": polysector_gear,
    "planetary_final_drive": final_drive,
    "cam_mover": cam_mover,
    "road_wheel": road_wheel,
}
