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
#: chord tolerance of the gear outlines in the planetary sweep (clearances of tenths of a mm)
PLANETARY_SWEEP_CHORD_TOL_MM = 1e-3

# --- involute gear sheet / planetary set (gears/involute.py, gears/planetary.py) ------------
#: least transverse contact ratio accepted (seed 004 Table 6, "рекомендованное торцовое перекрытие")
GEAR_CONTACT_RATIO_MIN = 1.2
#: least normal tooth thickness on the tip circle, in modules (seed 004 Table 6, surface-hardened teeth)
GEAR_TIP_THICKNESS_MIN_MODULE = 0.4
#: a tip corner entering the mate deeper than this (mm) counts as interference
GEAR_INTERFERENCE_TOL_MM = 1e-6
#: sun-planet vs planet-ring operating centre distances may differ by at most this (mm)
PLANETARY_COAXIALITY_TOL_MM = 0.01
#: least gap between the tip circles of neighbouring planets, in modules (design rule; seed eq. 30 has a bare '>')
PLANET_TIP_CLEARANCE_MIN_MODULE = 0.5

# --- motion checks (checks/motion.py) -----------------------------------------
#: chord tolerance used to sample outlines for motion checks (clearance / backlash
#: are exact for the polyline; the polyline lies within this of the true curve)
MOTION_CHORD_TOL_MM = 1e-4
#: boundary segments longer than this are subdivided (exactly) for the KD-tree search
MOTION_MAX_SEGMENT_MM = 0.1
#: a tooth pair counts as "in contact" when its remaining circumferential gap is below this
MOTION_CONTACT_TOL_MM = 1e-3
#: contact points closer than this along the driven boundary belong to one tooth pair
MOTION_CONTACT_MERGE_MM = 0.5
#: largest free rotation searched for when measuring backlash (rad)
MOTION_MAX_FREE_ANGLE_RAD = 0.2

# --- fixed cam of the driven propulsor (seed 001) ------------------------------
#: reference integration of eq. 20 used to measure the error of the working one
CAM_ODE_REF_TOL = 1e-13
#: largest admissible integration error of H (mm)
CAM_H_ERROR_MAX_MM = 1e-6
#: eq. 20 counts as blown up when cos(gamma) falls below this inside the support phase
CAM_COS_GAMMA_MIN = 1e-3
#: ... or when rho leaves [CAM_RHO_MIN_FACTOR, CAM_RHO_MAX_FACTOR] * H0
CAM_RHO_MAX_FACTOR = 100.0
CAM_RHO_MIN_FACTOR = 1e-6
#: Gauss-Legendre nodes for the shoe quotient (gamma - phi)/phi of seed 001 eq. 7
CAM_QUAD_NODES = 24
#: samples of the support phase used to evaluate a design candidate
CAM_SUPPORT_SAMPLES = 181
#: samples of the whole turn used to evaluate a design candidate
CAM_TURN_SAMPLES = 1441

# --- non-circular walking-drive pair (gears/sectors.py, gears/noncircular.py) ---
#: convergence of the papers' sector iterations (seed 000 eqs. 25-31, 48-51); the
#: papers say 1e-6 rad but print the converged, symmetric solution
SECTOR_ITER_TOL_RAD = 1e-13
#: a computed tooth count closer than this to a whole number is whole
TOOTH_COUNT_TOL = 1e-6
#: relative precision of the automatically chosen smoothing half-width delta
SMOOTHING_DELTA_RTOL = 1e-6

# --- mesh export (appended by the checks/exports layer) -------------------------
#: largest tessellation chord error SPEC §9 allows (STL / 3MF); the mesher aims at
#: CHORD_TOL_MM and refines when OCCT reports a larger achieved deflection
MESH_CHORD_LIMIT_MM = 0.01

# --- build size (propulsor build --dry-run, parts.check_size) --------------------------------
#: longest build accepted (s on the reference machine, 2 cores): past it the size estimate refuses
BUILD_SECONDS_MAX = 600.0
