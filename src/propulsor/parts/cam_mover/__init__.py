"""Driven wheel-walking propulsor with a fixed cam (seed 001): cam, carrier, legs, rollers, shoes.

Mechanism (seed 001, fig. 3): a cam fixed on the axle O2; a carrier turning around
it with ``n_legs`` radial slides; in each slide a leg with a roller that rides the cam in a
guide channel (a closed-track cam); a support shoe on every leg.

Pipeline:

1. Law of motion — the roller-centre path H(φ) over the support phase from a curvature law
   K(φ) by integrating seed 001 eq. 20 (laws.cam_motion, error measured), closed C2 over the
   return phase; the law is either searched against the limits (laws.cam_design: pressure
   angle eq. 17, cam radius of curvature eq. 16, Hertz stress eq. 14–15, shoe without loops,
   footprint ratio, cam core) or given (family + coefficients).
2. Per φ: pressure angle, radius of curvature of both channel walls (eq. 16), Hertz stress
   (eq. 14), hub speed analogue (eq. 8); the shoe (eq. 1, 7, 11–13) — tables as CSV.
3. Outlines (geometry.cam_outlines): channel walls (eq. 9–10 at r and at r + clearance),
   carrier with radial slides, leg, roller, shoe — exact B-splines / arcs / lines.
4. Solids (STEP/STL/3MF each, all shared checks), an assembly STEP at a chosen carrier
   angle, DXF of the cam channel, of the shoe and of the carrier.
5. Proofs on the geometry, not on the formulas:
   * the roller outline swept through a full carrier turn (``sweep_steps`` ≥ 720 positions
     H(φ)) against the cam channel bodies with manifold3d booleans: overlap with the working
     wall and with the outer wall, gap to each (min/max); plus 3D spot checks of the roller
     and cam meshes read back from the exported STL files;
   * the shoe outline read back from the exported DXF, placed for every leg at every step
     by the computed leg position, lowest point → hub height over flat ground; its variation
     over each support phase;
   * neighbouring legs + shoes against each other, legs and shoes against the carrier over
     a turn (all of them share one axial layer, so plan-view overlap is 3D overlap; the cam
     and the rollers sit in the layer below, separated by ``carrier_axial_gap_mm``).

Axial stack (z along the axle, cam back face at z = 0): cam plate [0, tp]; channel
[tp, tp + dg] with dg = roller width + 2·groove_axial_gap; roller [tp + gap, tp + gap + b];
carrier, legs [zc, zc + carrier_thickness] with zc = tp + dg + carrier_axial_gap; shoes
[zc, zc + shoe_width]; the roller pin from the leg down through the roller.

Defaults are ours (R0 + r + C = 320 mm like the driving propulsor, R0 = 90, r = 20,
C = 210 mm, four legs); every other dimension is ours too and is a parameter.
"""

from __future__ import annotations

from .. import PartType
from .design import Plan, plan
from .outputs import build, build_solids, expected_genus
from .params import LAWS, MIN_WEB_MM, CamMoverParams
from .proofs import hub_height_from_outline, motion_proofs, profile_fd_check, spot_checks_3d

__all__ = ["CamMoverParams", "LAWS", "MIN_WEB_MM", "Plan", "plan", "PART_TYPE", "build", "build_solids",
           "expected_genus", "hub_height_from_outline", "motion_proofs", "profile_fd_check", "spot_checks_3d"]

PART_TYPE = PartType(
    name="cam_mover",
    summary="fixed cam (closed track), carrier, legs, rollers and shoes of the driven wheel-walking propulsor (seed 001)",
    params_cls=CamMoverParams,
    build=build,
    design=plan,
)
