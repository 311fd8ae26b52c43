"""Motion checks: interference and clearance of mating bodies over a motion cycle.

Proofs on the finished outlines, not on the formulas (docs/architecture.md, "The data flow of one build"):
interference and clearance of mating parts over the sampled cycle with manifold booleans.
manifold3d, numpy and scipy only; no part or gear module is imported,
so any outline (generated teeth, the seeds' sector teeth, planetary gears, cams)
is checked the same way.

Three tools:

* :func:`sweep_pair` - two planar bodies, one rigid pose each per step: overlap
  area (manifold3d ``CrossSection`` intersection) and the minimum distance
  between the boundaries (exact for the sampled polylines).
* :func:`transmission_sweep` - a gear pair on its finished outlines: at each
  driven angle phi the driver is placed at the law angle theta(phi); the free
  rotation of the driven body in each direction until first contact is computed
  analytically (every boundary vertex runs on a circle about the driven centre;
  its first crossing of the other boundary is a circle-segment intersection).
  That gives backlash, transmission error against the law and the number of
  tooth pairs in contact (contact ratio along the cycle).
* :func:`sweep_solids_3d` - intersection volume (and optional gap) of two
  triangle meshes under 4x4 poses, for parts that are not prismatic.

Frames and signs: millimetres, radians, angles counter-clockwise positive.
Outlines are polylines whose material lies on the left of every edge (outer
loop CCW, holes CW, as :class:`propulsor.geometry.profile.Profile` guarantees;
raw polylines are re-oriented by nesting depth, i.e. even-odd).

Accuracy: clearance, backlash and contact are exact for the polylines; the
polylines lie within ``chord_tol`` of the true curves (on the concave side of a
convex flank), so each boundary can read up to ``chord_tol`` too thin.  The
default :data:`propulsor.policy.MOTION_CHORD_TOL_MM` (0.1 um) keeps that far below
the 1 um resolution asked of backlash.

Modules: :mod:`.outlines`, :mod:`.poses`, :mod:`.distance`, :mod:`.backlash`, :mod:`.sweep2d`,
:mod:`.transmission`, :mod:`.sweep3d`.
"""

from __future__ import annotations

from .outlines import Outline, PolarEnvelope, outline, crop_to_sector, cut_to_disc, cut_to_sector
from .poses import Pose, poses_from_angles, rotation_matrices
from .sweep2d import SweepResult, sweep_pair, sweep_pair_windowed
from .transmission import TransmissionResult, transmission_sweep
from .sweep3d import box_corners, box_of, box_gap, Sweep3DResult, sweep_solids_3d

__all__ = [
    "Outline",
    "outline",
    "crop_to_sector",
    "cut_to_disc",
    "cut_to_sector",
    "PolarEnvelope",
    "Pose",
    "poses_from_angles",
    "rotation_matrices",
    "SweepResult",
    "sweep_pair",
    "sweep_pair_windowed",
    "TransmissionResult",
    "transmission_sweep",
    "Sweep3DResult",
    "sweep_solids_3d",
    "box_corners",
    "box_of",
    "box_gap",
]
