"""The road wheel's design: its geometry (:mod:`propulsor.solids.road_wheel`) and tyre, computed once."""

from __future__ import annotations

from dataclasses import dataclass

from ...solids.road_wheel import WheelModel, wheel_model
from .params import RoadWheelParams

__all__ = ["feasible", "RoadWheelDesign", "design"]


@dataclass(frozen=True)
class RoadWheelDesign:
    p: RoadWheelParams
    model: WheelModel
    tyre: object  # laws.tyre_heat.SolidTyre
    P_row: float  # load per row, N


def design(p: RoadWheelParams) -> RoadWheelDesign:
    """Derived geometry and the tyre model; InputError naming the parameter for geometry that cannot be made."""
    return RoadWheelDesign(p, wheel_model(p), p.tyre(), p.load_N / p.rows)


def feasible(p, source=None) -> None:
    """InputError (parameter, value, limit) when the geometry cannot be made: the design computed once (the
    build reuses it, :func:`~propulsor.parts.pipeline.design_of`).  What the parameters cannot tell from their
    fields; run by the dry run and the Python API after ``validate()`` (``parts.vet``)."""
    from ..pipeline import design_of

    design_of(p, design)
