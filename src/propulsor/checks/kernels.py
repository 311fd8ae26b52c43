"""The checks' compiled kernels (numba, ``cache=True``: compiled once per machine and source, kept beside the
modules): whether they still need compiling (:func:`cold`), and their compilation on small inputs (:func:`warm`).

A build on a fresh install compiled them where they were first called — in the proof, in the workers of the
as-built contact (each worker its own copy), in the mesh checks — as 12-19 s silences between its progress lines,
about 34 CPU s in all on the seed-002 Fourier pair (71 s wall against 38 s warm).  The build now compiles them first
when :func:`cold`, saying so, before it forks any worker; ``make install`` compiles them ahead (:func:`warm`).
Their disk cache is keyed on every kernel source (:mod:`propulsor.nbcache`): a kernel compiled into another's code is
never loaded stale after its own file changed.
"""

from __future__ import annotations

import importlib
import math

import numpy as np

#: the modules whose kernels are cached on disk
MODULES = ("propulsor.checks.tri_tri", "propulsor.checks.motion.nearest", "propulsor.checks.motion.crossing",
           "propulsor.checks.motion.backlash", "propulsor.checks.motion.transmission_kernel",
           "propulsor.checks.motion.contact_kernels",
           "propulsor.checks.motion.contact_reuse", "propulsor.checks.motion.contact_track",
           "propulsor.checks.box_pairs", "propulsor.export.normals", "propulsor.export.render",
           "propulsor.geometry.spline_foot", "propulsor.laws.fourier_kernels",
           "propulsor.laws.cam_kernels", "propulsor.checks.motion.poses",
           "propulsor.checks.motion.sweep_steps", "propulsor.laws.walking_kernels",
           "propulsor.checks.motion.mesh_load", "propulsor.gears.tooth_load_kernels")

__all__ = ["MODULES", "cold", "warm", "warm_if_cold"]


def _dispatchers() -> list:
    from numba.core.registry import CPUDispatcher

    found = []
    for name in MODULES:
        for value in vars(importlib.import_module(name)).values():
            # a kernel inlined into its callers (inline="always") is compiled within them, never cached on its own
            if (isinstance(value, CPUDispatcher) and value not in found
                    and getattr(value, "targetoptions", {}).get("inline") != "always"):
                found.append(value)
    return found


def cold() -> bool:
    """Whether a kernel has no compiled code on disk for its current source (a fresh install, an edited module):
    numba's own cache index, read without compiling.  False where the cache cannot be read (numba's layout
    changed, caching off): then nothing is said and the kernels compile where they are called, as before."""
    try:
        for d in _dispatchers():
            if not d.signatures and not d._cache._cache_file._load_index():
                return True
    except (AttributeError, OSError, TypeError, ValueError):
        return False
    return False


def _toothed(z: int, r: float, h: float, n: int = 24) -> np.ndarray:
    """A closed outline of `z` round-topped teeth about radius `r` (height `h`), `n` points a tooth."""
    t = np.linspace(0.0, 2.0 * math.pi, z * n, endpoint=False)
    rr = r + 0.5 * h * np.cos(z * t)
    return np.column_stack([rr * np.cos(t), rr * np.sin(t)])


def warm() -> None:
    """Call every cached kernel once on small inputs, so that each is compiled (or loaded) now, in this process:
    the mesh checks' triangle tests, the motion proof's distance, crossing and rotation searches and its steps, and the as-built
    contact search (its first hit and all of a window's, the per-tooth load's hits) on a pair of toothed rings, the
    flank curvatures' windows; the GLB's shading normals; the
    spline fit's foot-point distances and a spline's exact sweep; the poses' point product and the sweeps' steps
    apart; the Fourier law's one-point inversion; the cam's dense output, return quintics and shoe self-crossing test;
    the pictures' rasteriser."""
    from scipy.integrate import solve_ivp

    from ..export.normals import smooth_normals
    from ..export.render import _paint
    from ..geometry.spline_foot import foot_distances, sweep_area
    from ..laws.cam_kernels import DenseSolution, polyline_crosses_itself, quintic_derivs
    from ..gears.smoothed_law import SmoothedWalkingLaw
    from ..laws.ratio_laws import FourierLaw
    from ..laws.walking import WalkingLaw
    from .mesh import self_intersections
    from .motion import Outline, transmission_sweep
    from .motion.backlash import _rot_hits, _zones_nb, rot_bounds
    from .motion.contact_events import DRIVE, PairOutlines, resolve_contact
    from .motion.contact_kernels import _nearest_teeth_nb
    from .motion.crossing import certainly_apart
    from ..gears.tooth_load_kernels import fit_windows, frame_coordinates
    from .motion.mesh_load import _firsts_nb, phase_contacts
    from .motion.nearest import dist_each, nearest_edge
    from .motion.poses import Pose, apply_pose, rotation_matrices
    from .motion.sweep2d import sweep_pair
    from .motion.sweep_steps import move_each

    self_intersections(np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]),
                       np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]))
    square = Outline([np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])], 0.5)
    apply_pose(np.array([[0.0, -1.0, 0.5], [1.0, 0.0, 0.25]]), square.points)  # the poses' compiled product
    # the sweep's compiled steps where the bodies are apart (motion/sweep_steps.py), and its points' poses
    sweep_pair(square, Pose(), square, rotation_matrices(np.zeros(2), np.array([[3.0, 0.0], [3.5, 0.0]])))
    move_each(np.zeros((1, 2, 3)), np.zeros((1, 2)))
    nearest_edge(square.points + 1.5, square, square)
    dist_each(square.points + 0.25, square)  # each point's distance (an overlapping step's penetration depth)
    certainly_apart(square, square, square.points + 1.2, square.points - 1.2, 0.2)
    P = square.points + 1.2
    _rot_hits(P, np.zeros(2), square, 1.0, 0.5, np.linalg.norm(P, axis=1), square.boundary_lower_bound(P))
    rot_bounds(P, (0.0, 0.0), square)  # the free rotations' radii and bounds in one pass
    _zones_nb(np.zeros(4), np.ones(4), np.zeros(1), np.ones(1), np.zeros(1, np.int64), np.zeros(1), 0.0, 1e-3,
              square.arclen, square.seg_len, square.loop_id, square.perimeter, 0.1)  # a free rotation's contact zones
    # two rings of 12 and 18 teeth (module 1) at their centre distance, a few positions of the driven one
    z1, z2, m = 12, 18, 1.0
    drv, dvn = Outline([_toothed(z1, 0.5 * m * z1, 1.6 * m)]), Outline([_toothed(z2, 0.5 * m * z2, 1.6 * m)])
    pair = PairOutlines(drv, dvn, 0.5 * m * (z1 + z2), 2 * math.pi * np.arange(z1) / z1,
                        2 * math.pi * np.arange(z2) / z2)
    step = 2 * math.pi / z2 / 4
    resolve_contact(pair, lambda phi: np.asarray(phi, float) * z2 / z1, 0.0, 4 * step, DRIVE,
                    step_driver_rad=step * z2 / z1, max_evals=40)
    # the whole-cycle proof's compiled steps (motion/transmission_kernel.py) and their free rotations
    transmission_sweep(drv, (0.5 * m * (z1 + z2), 0.0), dvn, (0.0, 0.0), lambda phi: phi * z2 / z1,
                       np.array([0.0, step]))
    pair._all_hits(0.0, 0.0, 1.0, step)  # every hit of a window (the reference of the per-tooth load's search)
    pair.hits(0.0, 0.0, 1.0, step)  # the per-tooth load's search
    _nearest_teeth_nb(pair.driver_teeth, np.array([0.1, 2.0]))
    phase_contacts(pair, 0.0, 0.0, 0.0, step)  # the per-tooth load's hits and pairs (motion/mesh_load.py) ...
    _firsts_nb(np.array([0.2, 0.1]), np.array([0, 1]), np.array([1, 0]))  # ... each pair's first (none above: no hit)
    # the flank curvatures' fit windows and frame coordinates (gears/tooth_load_kernels.py): a toothed ring's
    ring = _toothed(12, 6.0, 1.6)
    seg_len = np.linalg.norm(np.roll(ring, -1, axis=0) - ring, axis=1)
    todo = np.array([3, 7], np.int64)
    is_corner, Ks, first, last = fit_windows(seg_len, np.zeros(len(ring), np.bool_), todo, 0.5)
    frame_coordinates(ring, todo, Ks, first, last, np.array([[1.0, 0.0], [0.0, 1.0]]),
                      np.array([[0, 0], [1, 1]], np.int64))
    # the shading normals of the assemblies' GLB (export/normals.py's crease sums)
    smooth_normals(np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]),
                   np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]))
    # the spline fit's foot-point distances (geometry/spline_foot.py): a cubic through four points
    foot_distances(np.array([0.0, 0, 0, 0, 1, 1, 1, 1]), np.array([[0.0, 0], [1, 1], [2, 1], [3, 0]]), 3,
                   np.array([[1.5, 1.0]]), np.array([0.5]), 0.0, 1.0)
    # and a spline's exact sweep (the loops' orientation, geometry/profile.py)
    sweep_area(np.array([0.0, 0, 0, 0, 1, 1, 1, 1]), np.array([[0.0, 0], [1, 1], [2, 1], [3, 0]]), 3)
    # the Fourier law's one-point inversion and slopes, and its array functions (laws/fourier_kernels.py)
    law = FourierLaw(1, (), (0.05,))
    law.U_derivs1(0.3)
    law.U(np.linspace(0.0, 1.0, 9))
    law.phi_of_theta(np.linspace(0.0, 1.0, 9))
    # the walking law's array functions, exact and blended (laws/walking_kernels.py)
    walking = WalkingLaw(60.0, 100.0, 360.0, 2)  # seed 000
    for w in (walking, SmoothedWalkingLaw(walking, 0.05)):
        w.U(np.linspace(0.0, 1.0, 9))
        w.dU_dphi(np.linspace(0.0, 1.0, 9))
    # the cam's dense output, return quintics and shoe test (laws/cam_kernels.py): a short DOP853 integration, two
    # quintics, a polyline folded back over itself
    sol = solve_ivp(lambda t, y: [y[1], -y[0]], (0.0, 1.0), [1.0, 0.0], method="DOP853", dense_output=True).sol
    DenseSolution(sol)(np.array([0.25, 0.5]))
    quintic_derivs(np.ones((2, 6)), np.array([0, 1]), np.ones((6, 2)), np.ones((2, 6)), np.ones(2))
    polyline_crosses_itself(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, -1.0]]))
    # the pictures' rasteriser (export/render.py): one triangle into a 4 x 4 picture
    _paint(np.array([[0.5, 3.5, 0.5]]), np.array([[0.5, 0.5, 3.5]]), np.zeros((1, 3)), np.zeros((1, 3), np.uint8),
           4, 4, np.full(16, -np.inf, np.float32), np.empty((16, 3), np.uint8))


def warm_if_cold(progress=None) -> bool:
    """:func:`warm` when :func:`cold`, said to `progress` first; whether it compiled."""
    if not cold():
        return False
    if progress is not None:
        progress("compiling the numeric kernels for this machine (once after an install or an update: about 30 s)")
    warm()
    return True
