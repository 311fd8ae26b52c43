"""Driven wheel-walking propulsor with a fixed cam (seed 001): cam, carrier, legs, rollers, shoes.

Mechanism (seed 001, fig. 3): a cam fixed on the axle O2; a carrier turning around it with
``n_legs`` radial slides; in each slide a leg with a roller that rides the cam in a guide channel
(a closed-track cam); a support shoe on every leg.

Parameters (:mod:`.params`) → design (:mod:`.design`: the law of motion, searched or given,
seed 001 eq. 14-20; the outlines) → outputs (:mod:`.outputs`: tables per φ of pressure angle,
radius of curvature, Hertz stress, hub speed (eq. 8, 14, 16, 17), shoe (eq. 1, 7, 11-13); solids,
assembly, DXF) → proofs on the exported geometry (:mod:`.proofs`).  Defaults are ours
(R0 + r + C = 320 mm like the driving propulsor, R0 = 90, r = 20, C = 210 mm, four legs).
"""

from __future__ import annotations

from .. import PartType, summary
from .design import Plan, feasible, plan
from .outputs import build, build_solids, expected_genus
from .params import LAWS, MIN_WEB_MM, CamMoverParams
from .proofs import hub_height_from_outline, motion_proofs, profile_fd_check, spot_checks_3d

__all__ = ["CamMoverParams", "LAWS", "MIN_WEB_MM", "Plan", "plan", "PART_TYPE", "build", "build_solids",
           "expected_genus", "hub_height_from_outline", "motion_proofs", "profile_fd_check", "spot_checks_3d"]

PART_TYPE = PartType(
    name="cam_mover",
    summary=summary("cam_mover"),
    params_cls=CamMoverParams,
    build=build,
    design=plan,
    feasible=feasible,
)
