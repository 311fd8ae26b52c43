"""Composite (polysector) gear with stepwise adjustable ratio (seed 003).

Wires the parameters to the library: the synthesis of eq. 1–4 (:mod:`propulsor.gears.polysector`),
the sectors cut from a rack-generated blank, the hub's flow discs and the solid gear
(:mod:`propulsor.geometry.polysector_outline`), the proof of every position over a full turn on the
finished outlines (:mod:`.mesh_proof`: overlap, contact, the gear's angle from contact, ε_s measured;
:mod:`.contact_law`: the contact law through every hand-over, contact types, tip on tip, snaps, Δi),
the tooth position error (eq. 15–22), the friction loss (eq. 12–14) and the torsional dynamics
(eq. 9–11, :mod:`propulsor.gears.polysector_dynamics`).
"""

from __future__ import annotations

from .. import PartType, summary
from .design import PolysectorDesign, design, feasible
from .outputs import build
from .params import PolysectorParams

__all__ = ["PolysectorParams", "PolysectorDesign", "design", "build", "PART_TYPE"]

PART_TYPE = PartType(
    name="polysector_gear",
    summary=summary("polysector_gear"),
    params_cls=PolysectorParams,
    build=build,
    design=design,
    feasible=feasible,
)
