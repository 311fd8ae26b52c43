"""Road wheel with solid rubber tyres of the 50 t tracked carrier (seed 004, ch. 5 and 7).

Seed 004 gives the wheel diameter D_k = 630 mm and the double row (ch. 5), the static wheel load
P_st = 31 490 N (ch. 2, eq. 3), Kozlov's tyre heat estimate (ch. 7, eq. 76-80) and the track
frequency ω = 2πV/t (§7.2) with the parametric-resonance speeds 7.3, 10.8 and 21.7 m/s (fig. 35).
Tyre width, rubber thickness, rim, disc and bearings are ours.  Geometry and solids:
:mod:`propulsor.solids.road_wheel`.

Kozlov's temperature uses the kinematic wheel speed n = V/(2πR) (``laws.tyre_heat``; the seed's
printed n = 60V/(3.6πR) is twice that, read with R a diameter); the printed reading is plotted
beside it.  The track pitch for ω is ch. 7's Table 12 value L = 0.15 m.
"""

from __future__ import annotations

from .. import PartType, summary
from ...solids.road_wheel import WheelModel, mass_properties, wheel_model, wheel_solids
from .design import RoadWheelDesign, design, feasible
from .outputs import build
from .params import RoadWheelParams
from .proofs import kozlov_table

__all__ = ["RoadWheelParams", "RoadWheelDesign", "design", "WheelModel", "wheel_model", "wheel_solids",
           "mass_properties", "kozlov_table", "PART_TYPE", "build"]

PART_TYPE = PartType(
    name="road_wheel",
    summary=summary("road_wheel"),
    params_cls=RoadWheelParams,
    build=build,
    design=design,
    feasible=feasible,
)
