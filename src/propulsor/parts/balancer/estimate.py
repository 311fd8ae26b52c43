"""The balancer's size estimate (parts/size.py: the models and their calibration)."""

from __future__ import annotations

import math
from pathlib import Path

from ..pipeline import design_of
from ..size import SizeEstimate, wall
from .design import suspension_design


def estimate(p, part_file: Path | None = None) -> SizeEstimate:
    """On validated parameters (``needs_validated``): the suspension design's travel (InputError as the build's
    design raises it; the arm's outline, the long part of the design, is not needed), then: solids, arm stations,
    damper heat and the kit-free outputs fixed (22 CPU s: 31.8 measured on parts/balancer.toml, 2026-11-28), travel
    sweep ∝ steps × (0.1 mm / chord)^0.84 (the sweep meshes' size for the chord, measured)."""
    tor = design_of(p, suspension_design).torsion  # the build's design holds this same one (design.resolve)
    steps = int(math.ceil(math.degrees(tor.beta_m - tor.beta0) * p.sweep_steps_per_deg)) + 1
    cpu = 22.0 + 0.01 * p.n_stations + 0.0425 * steps * (0.1 / p.sweep_chord_mm) ** 0.84
    return wall(cpu, f"travel sweep {steps} steps, sweep chord {p.sweep_chord_mm:g} mm")


estimate.needs_validated = True  # the travel's angles come from the suspension design (validated parameters)
