"""Suspension balancer of the 50 t tracked carrier (seed 004, ch. 2 and 8).

Parameters (:mod:`.params`) → design (:mod:`.design`: the seed's suspension, the road wheel it
carries, the beam model, the arm outline) → the solid (:mod:`.solids`) → proofs (:mod:`.proofs`:
stresses on the built outline, socket / ear / pad, the travel sweep) → outputs (:mod:`.outputs`,
:mod:`.plots`).
"""

from __future__ import annotations

from .. import PartType, summary
from .design import THESIS, BalancerModel, feasible, resolve, spindle_dims, suspension_design
from .estimate import estimate
from .outputs import build
from .params import BalancerParams
from .proofs import hull_envelope, travel_sweep
from .solids import balancer_solid, spindle_section, sweep_mesh, upper_section

__all__ = ["BalancerParams", "BalancerModel", "THESIS", "resolve", "suspension_design", "spindle_dims",
           "balancer_solid", "upper_section", "spindle_section", "sweep_mesh", "hull_envelope", "travel_sweep",
           "PART_TYPE", "build"]

PART_TYPE = PartType(
    name="balancer",
    summary=summary("balancer"),
    params_cls=BalancerParams,
    build=build,
    design=resolve,
    feasible=feasible,
    estimate=estimate,
)
