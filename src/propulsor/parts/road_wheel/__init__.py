"""Road wheel with solid rubber tyres of the 50 t tracked carrier (seed 004, ch. 5 and 7).

Seed 004 gives the wheel: diameter D_k = 630 mm, double row ("двухрядный"), on a track with a
rubber-faced running surface (ch. 5); the static wheel load P_st = 31 490 N (ch. 2, eq. 3); the
tyre heat estimate of Kozlov (ch. 7, eq. 76–80) and the "track" frequency ω = 2πV/t (§7.2) with
the parametric-resonance speeds 7.3, 10.8 and 21.7 m/s read from its Ince–Strutt diagram
(fig. 35).  It prints no tyre width, rubber thickness, rim or disc dimensions: those below are
ours (the same illustrative tyre as tests/test_tyre_heat.py: b = 90 mm, H = 40 mm, E = 6 MPa,
α = 60 W/(m² K), ψ = 0.35).

Geometry, wheel frame (mm): axis = z, origin on the axis at the hub's inboard face, +z outboard
(away from the balancer arm).  Solids, each a solid of revolution built from an exact half section
(:mod:`propulsor.solids.road_wheel`):

* ``disc``: hub tube with the two bearing seats (outer rings; the seats are counterbores from
  each end, the relief between them leaves the shoulders) and one web per row, with
  ``lightening_holes`` holes through every web — genus 1 + rows × holes;
* ``rim_<k>``: steel ring per row on the web's edge — genus 1;
* ``tyre_<k>``: solid rubber ring vulcanised on the rim — genus 1.

Kozlov's temperature uses the kinematic wheel speed n = V/(2πR) (``laws.tyre_heat``: the seed's
printed n = 60V/(3.6πR) is twice that, read with R a diameter); the printed reading is plotted
beside it.  The track pitch for ω is ch. 7's Table 12 value L = 0.15 m (ch. 4 uses t = 0.14 m,
ch. 5 t_r = 0.125 m: the seed is inconsistent; the part file may change it).
"""

from __future__ import annotations

from .. import PartType
from ...solids.road_wheel import WheelModel, mass_properties, wheel_model, wheel_solids
from .design import RoadWheelDesign, design
from .outputs import build
from .params import RoadWheelParams
from .proofs import kozlov_table

__all__ = ["RoadWheelParams", "RoadWheelDesign", "design", "WheelModel", "wheel_model", "wheel_solids",
           "mass_properties", "kozlov_table", "PART_TYPE", "build"]

PART_TYPE = PartType(
    name="road_wheel",
    summary="double road wheel with solid rubber tyres, Kozlov heat estimate (seed 004 ch. 7)",
    params_cls=RoadWheelParams,
    build=build,
    design=design,
)
