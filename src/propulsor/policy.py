"""Numeric tolerances and sampling densities: the one place they live.

All lengths in millimetres, angles in radians.
"""

# --- geometry / fitting -------------------------------------------------------
#: maximum deviation of a fitted B-spline from the exact (analytic / envelope) curve
SPLINE_FIT_TOL_MM = 1e-5
#: chord tolerance of polylines written to DXF and of mesh tessellation (STL/3MF)
CHORD_TOL_MM = 0.005
#: angular tolerance of mesh tessellation
ANGULAR_TOL_RAD = 0.1
#: two points closer than this are the same point
POINT_TOL_MM = 1e-7

# --- solids / checks ----------------------------------------------------------
#: re-imported STEP volume vs built solid, relative
STEP_VOLUME_REL_TOL = 1e-6
#: mesh volume vs B-rep volume, relative
MESH_VOLUME_REL_TOL = 1e-3
#: overlap area below this (mm^2) counts as no overlap in 2D motion sweeps
OVERLAP_AREA_TOL_MM2 = 1e-6
#: overlap volume below this (mm^3) counts as no overlap in 3D motion sweeps
OVERLAP_VOLUME_TOL_MM3 = 1e-3

# --- root finding / ODE -------------------------------------------------------
ROOT_XTOL = 1e-12
ODE_RTOL = 1e-11
ODE_ATOL = 1e-11

# --- sampling -----------------------------------------------------------------
#: points per flank used to build an envelope before spline fitting
ENVELOPE_SAMPLES_PER_FLANK = 200
#: planetary interference sweep: steps per degree of carrier turn
PLANETARY_SWEEP_STEPS_PER_DEG = 2
