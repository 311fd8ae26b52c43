"""Non-circular gear pair of the driving wheel-walking propulsor (seeds 000 and 002), or of any law the
part file names (``law = "elliptical" | "fourier" | "table" | "pitch_curve"``: ``laws.law``; such a law
has no corners, so no blend, and no hub: the output speed ratio is reported instead of the hub speed).

law (seed 000 eqs. 1-15, periodic per leg) -> pitch curves r_H(phi), r(theta) (seed 000 eqs. 12-13)
closed by true arc length -> teeth -> finished outlines -> full-cycle proof on the outlines
(:mod:`.pair_proof`) -> solids with face width, bore and keyway -> STEP / STL / 3MF / DXF, the
papers' tables, transmission table, plots, report (docs/architecture.md, "Non-circular pair").

Two tooth methods (:mod:`.design`): ``generated`` (default; conjugate teeth on a C2 blend of the law)
and ``sectors`` (the papers' own method, seed 000 eqs. 16-52, seed 002 Tables 2-4, on the exact
law; its teeth are not conjugate and the proof measures what that costs: interference at the law's
positions, jams, transmission error).

Frames (the contract other tools read): the driven wheel's axis at the origin, the driver's at
(L, 0); ``driven.dxf`` / ``driver.dxf`` hold each gear about its own axis in its phase at
phi = theta = 0 of the assembly (the contact of law angle 0 on the line of centres).
"""

from __future__ import annotations

from .. import PartType, summary
from .design import (
    Design, PairDesign, design, design_generated, design_sectors, feasible, gear_profiles, mounting, pair_design,
    sector_design_table,
)
from .estimate import estimate
from .outputs import build, start_solids, write_outputs
from .params import METHODS, NoncircularPairParams
from .proofs import compare, prove

__all__ = ["NoncircularPairParams", "METHODS", "Design", "PairDesign", "design", "pair_design", "design_generated",
           "design_sectors", "sector_design_table", "mounting", "gear_profiles", "prove", "compare", "build",
           "start_solids", "write_outputs", "PART_TYPE"]

PART_TYPE = PartType(
    name="noncircular_pair",
    summary=summary("noncircular_pair"),
    params_cls=NoncircularPairParams,
    build=build,
    design=pair_design,
    feasible=feasible,
    estimate=estimate,
)
