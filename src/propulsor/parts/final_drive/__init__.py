"""Planetary final drive of the 50 t tracked carrier (seed 004, ch. 4).

Wires the parameters to the library: the ISO 21771 / GOST 16532 / GOST 19274 sheet of both meshes
(:mod:`propulsor.gears.involute`), the four conditions of the set (eq. 30–35,
:mod:`propulsor.gears.planetary`), generated outlines (rack for sun and planets, shaper for the
ring, :mod:`propulsor.geometry.gear_outline`), prismatic solids, the assembly at the mesh positions,
and an interference sweep over one full carrier turn on the finished outlines
(:func:`propulsor.checks.motion.sweep_pair`, manifold3d booleans).
"""

from __future__ import annotations

from .. import PartType, summary
from .design import FinalDriveDesign, design, feasible, gear_outlines, planetary_set, ring_outer_d
from .outputs import build
from .params import FinalDriveParams
from .proofs import MeshSweep, carrier_sweep

__all__ = ["FinalDriveParams", "FinalDriveDesign", "design", "PART_TYPE", "build", "planetary_set", "gear_outlines",
           "ring_outer_d", "carrier_sweep", "MeshSweep"]

PART_TYPE = PartType(
    name="planetary_final_drive",
    summary=summary("planetary_final_drive"),
    params_cls=FinalDriveParams,
    build=build,
    design=design,
    feasible=feasible,
)
