"""The non-circular pair's size estimate (parts/size.py: the models and their calibration)."""

from __future__ import annotations

from pathlib import Path

from ..size import SizeEstimate, wall


def _pair_periods(p, part_file: Path | None) -> int:
    """The periods the as-built contact covers one of (``as_built.period_span``): the walking law's four legs, a smooth
    law's periods (its lobes), when the driven teeth divide into them; else one (the whole turn).  The smooth law is
    the dry run's own screen (:func:`~propulsor.parts.noncircular_pair.feasibility.screened`: computed once)."""
    if p.law == "walking":
        periods = 4
    else:
        from .feasibility import screened

        smooth = screened(p, part_file).smooth
        periods = int(getattr(getattr(smooth, "law", None), "periods", 1) or 1)
    return periods if periods > 1 and p.driven_teeth % periods == 0 else 1


def estimate(p, part_file: Path | None = None) -> SizeEstimate:
    """Design, outlines and solids ∝ teeth of both gears; proof ∝ phases (the other method's proof
    when compared: one leg, a quarter of them); as built: 0.3 ms a contact position, both directions over one
    period of the pair (the driver's turns of a period every 0.05°, and about 190 positions a driven tooth at the
    changes of contact: 2 × (7 200 + 3 735) on the seed-002 Fourier pair, measured); as made: each tolerance case
    the same over the whole turn every 0.5°."""
    from ... import policy

    z_H = p.driven_teeth
    teeth = z_H + z_H // p.driver_turns
    phases = z_H * p.proof_phases_per_tooth
    cpu = 6.5 + 0.174 * teeth * (1.25 if p.compare_methods else 1.0) + 0.004 * phases * teeth / 100.0
    periods = _pair_periods(p, part_file)
    driver_deg = 360.0 * p.driver_turns
    contact = 2 * _CONTACT_S * (driver_deg / periods / policy.CONTACT_STEP_DRIVER_DEG + 190 * z_H / periods)
    cases = (4 + p.tolerance_samples) if p.tolerance_grade else 0
    made = cases * 2 * _CONTACT_S * (driver_deg / policy.TOLERANCE_STEP_DRIVER_DEG + 190 * z_H)
    cpu += contact + made
    return wall(cpu, f"{teeth} teeth, proof {phases} phases" + (f", {cases} tolerance cases" if cases else ""))


#: CPU seconds of one as-built contact position (the compiled search and its Python around it)
_CONTACT_S = 0.3e-3
