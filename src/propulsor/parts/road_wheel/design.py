"""The road wheel's design: its geometry (:mod:`propulsor.solids.road_wheel`) and tyre, computed once."""

from __future__ import annotations

from dataclasses import dataclass

from ...solids.road_wheel import WheelModel, wheel_model
from .params import RoadWheelParams

__all__ = ["RoadWheelDesign", "design"]


@dataclass(frozen=True)
class RoadWheelDesign:
    p: RoadWheelParams
    model: WheelModel
    tyre: object  # laws.tyre_heat.SolidTyre
    P_row: float  # load per row, N


def design(p: RoadWheelParams) -> RoadWheelDesign:
    """Derived geometry and the tyre model; InputError naming the parameter for geometry that cannot be made."""
    return RoadWheelDesign(p, wheel_model(p), p.tyre(), p.load_N / p.rows)
