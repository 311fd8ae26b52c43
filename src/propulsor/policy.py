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
#: nodes of different faces of a mesh closer than this are the same node (mm)
MERGE_TOL_MM = 1e-6

# --- files read back ------------------------------------------------------------
#: the largest manifest.json a build, the gallery or a check reads (bytes); a real one is below 200 kB
MANIFEST_MAX_BYTES = 16 << 20

# --- solids / checks ----------------------------------------------------------
#: re-imported STEP volume vs built solid, relative
STEP_VOLUME_REL_TOL = 1e-6
#: a union of solids that only touch (kernel.cq_fuse(touching=True)): its volume vs the sum of theirs, relative (the
#: cam plate with its core and ring: -5e-8, OCCT's integration over the unified faces); past it they are fused as
#: solids that overlap
TOUCHING_VOLUME_REL_TOL = 1e-6
#: mesh volume vs B-rep volume, relative
MESH_VOLUME_REL_TOL = 1e-3
#: overlap area below this (mm^2) counts as no overlap in 2D motion sweeps
OVERLAP_AREA_TOL_MM2 = 1e-6
#: overlap volume below this (mm^3) counts as no overlap in 3D motion sweeps
OVERLAP_VOLUME_TOL_MM3 = 1e-3
#: a 3D sweep's gap at a step is first sought within the last step's gap plus this (mm; or twice the last change,
#: whichever is more): the least distance is the same where it lies within (only the candidates differ)
SWEEP3D_GAP_GUESS_MM = 0.25

#: consecutive outline pieces meet (and a loop is closed) within this (mm)
OUTLINE_JOINT_TOL_MM = 1e-6
#: the same for outlines with teeth cut by a re-phased shaper (own x0): its tip hits meet the flank
#: to a few nm (measured 4.8e-6 mm at most on seed 002), snapped like the others
OUTLINE_JOINT_TOL_REPHASED_MM = 1e-5
#: a finished outline (arm, shoe, carrier) must close within this (mm)
OUTLINE_CLOSED_TOL_MM = 1e-7
#: two radii closer than this (mm) are the same circle (sector outlines: one root arc, radial flank)
RADIUS_EQUAL_TOL_MM = 1e-9
#: a periodic roller-centre path must close within this before its ends are joined (mm)
PATH_CLOSURE_TOL_MM = 1e-6
#: stations of a sampled requirement are uniform within this (relative and absolute, mm)
GRID_UNIFORM_TOL = 1e-9

# --- root finding / ODE -------------------------------------------------------
#: x tolerance of Brent's method (and relative tolerance of the coarser roots)
ROOT_XTOL = 1e-12
#: x (and relative) tolerance of the fine roots: angles, curve parameters, fsolve on outlines
ROOT_XTOL_FINE = 1e-14
#: solved or compared to rounding: brentq / fsolve of the tooth geometry, Newton of inv^-1 (relative
#: step), a diameter against the base diameter (relative)
ROUNDING_TOL = 1e-15
#: relative rounding margin of a comparison against a limit (phase end, torsion stress, undercut test)
REL_ROUNDING_TOL = 1e-12
#: x tolerance of the bounded 1-D minimisations (curvature, speed and clearance extremes)
MINIMIZE_XATOL = 1e-12
#: Gauss-Newton steps of the feet of many points on an equidistant at once (pitch_frame.BodyPitchCurve.heights):
#: the heights whose signs decide where a re-phased shaper's fillet crosses the root (noncircular_teeth.make_side: 4
#: steps from the nearest of 201 grid points leave about 1e-10 rad), and a flank end's height (tip_search.flank_reach)
FOOT_GAUSS_NEWTON_STEPS = 4
#: Newton inverse of theta(phi) of the walking law (rad)
PHI_OF_THETA_TOL_RAD = 1e-14
#: a Newton / fsolve solution on an outline counts when its residual is below this (mm), and its
#: parameter may leave the curve's range by as much
SOLVE_RESIDUAL_MM = 1e-9
#: the vectorised Newton of the tip hits stops when every residual is below this (mm)
NEWTON_STOP_MM = 1e-12
#: Newton iterations of one tip hit (gears.tip_search.tip_hit) before its hybrid method (fsolve) takes over
TIP_NEWTON_ITER_MAX = 6
#: forward-difference step relative to a curve's parameter range
FD_STEP_REL = 1e-7
#: forward-difference step in the driven angle phi (rad)
FD_STEP_PHI_RAD = 1e-8
#: central-difference step in phi for the arc length of an equidistant (rad)
FD_STEP_ARC_RAD = 1e-6
#: central-difference step (mm of rolling arc) of the path of a re-phased shaper's tip-round centre, whose normal
#: gives the round's contact direction (gears.envelope.RoundEnvelope)
SHAPER_MESH_FD_STEP_MM = 1e-4
#: stop of the search on a re-phased shaper's tip round (mm of rolling arc) for where its contact reaches the tip
#: land (gears.envelope.round_envelope)
SHAPER_MESH_STOP_MM = 1e-8
#: window (in shaper pitch radii) and samples of the search for the rolling arc where the tip round's contact
#: reaches the tip land (gears.envelope.round_envelope: four times the samples over twice the window)
SHAPER_MESH_WINDOW_R = 0.75
SHAPER_MESH_SAMPLES = 48
#: x tolerance of the cusp search on an envelope, relative to the parameter
CUSP_XATOL_REL = 1e-13
#: a jump of curvature without a corner inside a flank's curvature window (gears.tooth_load.curvature_at): the two
#: one-sided cubic fits' curvatures differ by more than this share of the larger and by more than the 1/mm below, or
#: one side fits its points this many times worse than the other (and worse than the mm below)
CURVATURE_JUMP_REL = 0.1
CURVATURE_JUMP_ABS_PER_MM = 1e-3
CURVATURE_JUMP_RMS_RATIO = 10.0
CURVATURE_JUMP_RMS_MM = 1e-6
#: x tolerance of the measuring-roller diameter (mm)
ROLLER_DIAMETER_XTOL_MM = 1e-13
#: sampled values within this share of the least one are the same least value, and the first in the table's order is
#: named where it lies (a symmetric law has two mirror points whose last bits differ from one CPU's maths to
#: another's: named by their bits, a report would say 75.70 deg on one machine and 284.30 deg on the next)
EXTREME_TIE_REL = 1e-9
#: two angles (rad) are equal within this (the GOST 19274 rack test alpha = 20 deg)
ANGLE_EQUAL_TOL_RAD = 1e-12
ODE_RTOL = 1e-11
ODE_ATOL = 1e-11

# --- sampling -----------------------------------------------------------------
#: points per flank when an envelope is sampled (``EnvelopeCurve.sample``, dense tooth points)
ENVELOPE_SAMPLES_PER_FLANK = 200
#: planetary interference sweep: steps per degree of carrier turn
PLANETARY_SWEEP_STEPS_PER_DEG = 2
#: chord tolerance of the gear outlines in the planetary sweep (clearances of tenths of a mm)
PLANETARY_SWEEP_CHORD_TOL_MM = 1e-3
#: final drive carrier: steps per degree of the sweep of the planet pins against the planets' bores
#: (pin and bore are concentric: the clearance is the same at every step; the sweep shows it is)
CARRIER_PIN_SWEEP_STEPS_PER_DEG = 0.5
#: damper heat of the balancer's station (seed 004 ch. 6): speeds (km/h) and the integrated time (s)
DAMPER_HEAT_SPEEDS_KMH = (5.0, 10.0, 20.0, 30.0, 40.0, 50.0)
DAMPER_HEAT_T_END_S = 30.0

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
#: rounding margin of the distance pruning of the sweeps (far runs of vertices skipped before the
#: exact search; it only decides what is searched, never a result: far above the rounding of
#: millimetre coordinates, far below any clearance of interest)
MOTION_PRUNE_MARGIN_MM = 1e-6

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
#: d/dx (sin x / x) by its Taylor series below this |x| (no cancellation)
SINC_SERIES_BELOW = 1e-2
#: the return-phase top H(pi) is searched up to the free curve's value plus this (mm), to this x tolerance
RETURN_TOP_SLACK = 1e-9
RETURN_TOP_XATOL = 1e-6
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
#: the slopes on either side of a corner of the exact law are taken this far from it (rad)
CORNER_SIDE_RAD = 1e-12
#: a computed tooth count closer than this to a whole number is whole
TOOTH_COUNT_TOL = 1e-6
#: relative precision of the automatically chosen smoothing half-width delta
SMOOTHING_DELTA_RTOL = 1e-6
#: the smoothing search starts at this half-width (rad)
SMOOTHING_DELTA_MIN_RAD = 1e-3

# --- tooth generator (gears/cutters.py, gears/envelope.py, gears/generation.py, gears/noncircular_teeth.py)
#: roll parameter where a shaper's involute ends, just above its base circle (t = 0 is the cusp)
INVOLUTE_T_MIN = 1e-9
#: the tip rounds of a rack tool may overlap its pitch by this much (mm) before it has no tip land
TOOL_TIP_LAND_TOL_MM = 1e-12
#: a shaper's module and the gear's module are equal within this (mm)
MODULE_MATCH_TOL_MM = 1e-12
#: bisection of the shortened tip height stops at this interval (mm)
TIP_HEIGHT_TOL_MM = 1e-6
#: a shortened tip's search first evaluates the heights this far either side of where it guesses the tip leaves a
#: flank (``gears.tip_search.tallest_tip``): far below TIP_HEIGHT_TOL_MM, well above the guess's error
TIP_REACH_PROBE_MM = 5e-9
#: the most secant (Illinois) steps of the tip shortening's search before it bisects (tip_search.tallest_tip)
TIP_SECANT_STEPS_MAX = 40

# --- suspension and balancer (laws/suspension.py, laws/balancer_beam.py) ---------
#: a damper sits on a wheel when their positions agree within this (m)
POSITION_EQUAL_TOL_M = 1e-9
#: equal-strength section depth by Brent's method, x tolerance (mm)
SECTION_DEPTH_XTOL_MM = 1e-9
#: statics residual and torque balance of the beam checks, relative; stress limit rounding margin
STATICS_REL_TOL = 1e-9

# --- mesh export (appended by the checks/exports layer) -------------------------
#: largest tessellation chord error of the STL / 3MF files (README, «Parts»: <= 0.01 mm); the mesher aims at
#: CHORD_TOL_MM and refines when OCCT reports a larger achieved deflection
MESH_CHORD_LIMIT_MM = 0.01

# --- build size (propulsor build --dry-run, parts.check_size) --------------------------------
#: longest build accepted (s on the reference machine, 2 cores): past it the size estimate refuses
BUILD_SECONDS_MAX = 600.0

# --- composite (polysector) gear, seed 003 -------------------------------------------------------
#: chord tolerance of the outlines in the proof of a position whose sectors are not conjugate to the
#: gear (e > 0): the measured ratio error is ≥ 1e-3 there, the polylines resolve it to ~1e-5
POLYSECTOR_PROOF_CHORD_TOL_MM = 1e-4
#: the same where eq. 7 predicts no ratio error (e = 0): fine enough to resolve Δi below 1e-6
POLYSECTOR_PROOF_CHORD_TOL_CONJUGATE_MM = 3e-5
#: eq. 7's largest |Δi| below which a position counts as conjugate (the finer chord is used)
POLYSECTOR_CONJUGATE_DI = 1e-4
#: ε_s measured on the outlines must match eq. 4 within this
POLYSECTOR_EPS_S_MATCH = 0.02
#: the contact law's finest step of wheel turn at a hand-over (rad; 0.0029°): steps are halved down to it
#: while the driving sector or the contact type changes across them, or the gear jumps
POLYSECTOR_LAW_STEP_MIN_RAD = 5e-5
#: a step is halved while its own ratio Δφ/Δθ differs from the ratios at its ends by more than this share of i_n
POLYSECTOR_LAW_RATIO_SPLIT = 0.01
#: snap: the gear's angle jumps by more than this (deg) beyond its nominal advance within one finest step
POLYSECTOR_SNAP_TOL_DEG = 0.05

# --- non-circular pair: law search ---------------------------------------------------------------
#: law search of the non-circular pair (gears.law_search): blend half-widths scanned (deg), hand-over
#: values u_h / u scanned upwards for the first generable one, bisections between it and the last
#: refused one (2^-7 of the scan step ~ 8e-5 u)
LAW_SEARCH_DELTA_DEG = (3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0, 12.0, 14.0, 17.0, 20.0, 24.0)
LAW_SEARCH_UH_SCAN = (1.0, 1.01, 1.02, 1.03, 1.04, 1.05, 1.06, 1.07, 1.08, 1.09, 1.10, 1.12, 1.14, 1.17, 1.20)
LAW_SEARCH_UH_BISECTIONS = 7
#: law search: how many of the least-ripple generable blends (distinct shaper and ripple) the design
#: tries to cut before it refuses
LAW_SEARCH_TRIES = 5
#: ... and at most this many per shaper (so that the next shaper size gets its turn)
LAW_SEARCH_TRIES_PER_SHAPER = 2
#: largest gap (in modules) between the fillet start of a re-phased shaper (own x0) and the root
#: equidistant that the outline closes by lifting the root; more is refused (InputError)
ROOT_BRIDGE_MAX_MODULE = 0.1

# --- files read by `propulsor check` (checks/safe_read.py, checks/formats.py) ---------------------
# Checked before a byte is parsed: a larger file is invalid, unread.  The largest outputs of the 13
# parts are 7.6 MB (STEP), 7.0 MB (STL), 3.3 MB (GLB), 2.0 MB (3MF, 11.5 MB unzipped), 1.3 MB (DXF)
# and 42 kB (manifest); the limits leave four to ten times that and keep the check of a valid file
# at the limit under CHECK_MEMORY_CEILING (a 32 MiB binary STL: 1.5 GB peak resident, 31 s).
MIB = 1 << 20
#: largest file read, by kind (bytes)
READ_LIMIT_BYTES = {
    "manifest": 16 * MIB,
    "step": 32 * MIB,  # OCCT: the 7.6 MB STEP peaks at 0.55 GB resident
    "stl": 32 * MIB,  # binary: 84 + 50 n bytes, n <= 671 k triangles (the largest part: 140 k)
    "stl_ascii": 16 * MIB,
    "3mf": 16 * MIB,  # the zip as stored
    "dxf": 16 * MIB,
    "glb": 32 * MIB,
    # a page: the gallery carries its parts' GLBs inline as data (at most PAGE_MODEL_BYTES_MAX, base64)
    "html": 96 * MIB,
}
#: a 3MF: its members decompressed, in total (declared sizes and what decompression yields), and
#: how many members it may hold
THREEMF_UNZIPPED_MAX_BYTES = 24 * MIB  # ~82 bytes a triangle: ~300 k triangles (22 MiB: 1.07 GB peak)
THREEMF_MEMBERS_MAX = 4096
#: a GLB's JSON chunk (the rest are binary buffers, bounded by the file)
GLB_JSON_MAX_BYTES = 16 * MIB
#: nodes, meshes, accessors (and every other list) of a GLB, each (an assembly has tens of components); the
#: primitives of all its meshes together too
GLB_ITEMS_MAX = 10_000
#: triangles a GLB makes the 3D view draw: every node's mesh counted once per node that instances it (the
#: largest output, 3.3 MB, draws about 0.1 M); the viewer (web/viewer.js) refuses more, `check` too
GLB_DRAWN_TRIANGLES_MAX = 2_000_000
#: GLB bytes one page carries inline as model data (the gallery of every part in a folder): a model past
#: it is not drawn on that page (its report's page draws it)
PAGE_MODEL_BYTES_MAX = 64 * MIB
#: a file listed in a manifest is hashed only up to this size (a larger one is a mismatch)
HASH_LIMIT_BYTES = 1024 * MIB
#: a mesh's triangle boxes may overlap in at most this many pairs before the self-intersection
#: test gives up (a real mesh has ~10 per triangle; a hostile one n^2 / 2)
MESH_BOX_PAIRS_MAX = 10_000_000
#: DXF coordinates, radii and arc radii (mm): the largest part is an assembly of ~1 m; 100 m is far
#: beyond any running gear and keeps the flattening of an arc to a few thousand points
DXF_COORD_MAX_MM = 1e5
#: points of all the flattened curves of one DXF (a 1.3 MB real drawing flattens to ~100 k)
DXF_POINTS_MAX = 4_000_000
#: peak memory of `propulsor check` (bytes of address space): the limits above keep it below; the
#: whole output/ of the 13 parts needs ~1.1 GB resident
CHECK_MEMORY_CEILING = 2048 * MIB

# --- non-circular pair: as built (parts/noncircular_pair/as_built.py) ------------------------------------------
#: default limits of the as-built checks (each a part-file parameter): the as-built hub speed ripple may exceed the
#: law's by this (a share: 0.005 = half a point) ...
AS_BUILT_RIPPLE_MARGIN = 0.005
#: ... a change of contact may change the driven speed by at most this share of the law's ...
AS_BUILT_SPEED_STEP_MAX = 0.02
#: ... the load may sit on a tooth's corner for at most this much driver angle in a row (deg) ...
AS_BUILT_CORNER_RUN_MAX_DEG = 0.5
#: ... and a tooth keeps at least this share of its addendum (a tip shortened below it is named)
TOOTH_HEIGHT_MIN_SHARE = 0.1

#: the whole-cycle proof of a non-circular pair (parts/noncircular_pair/pair_proof.py) crops both outlines once per
#: window of phases this wide (rad of the driven wheel) to what the driver can reach during it; the values do not
#: depend on it (the crops hold every vertex within reach), only the time
PAIR_PROOF_WINDOW_RAD = 0.4
#: a pair's whole-cycle proof measures one period of its law where both outlines repeat under a period's turns to this
#: (mm, at every vertex; parts/noncircular_pair/pair_proof.cyclic_mismatch): a wheel cut as one lobe and patterned
#: repeats to rounding (~1e-13 mm), one cut tooth by tooth to the B-spline fits' 1e-5 mm, and is measured whole
CYCLIC_TOL_MM = 1e-9

# --- contact events of a gear pair (checks/motion/contact_events.py) ------------------------------------------
#: the loaded contact is sampled every this many degrees of the driver (the resolution of the independent contact
#: code the as-built transmission is compared with) ...
CONTACT_STEP_DRIVER_DEG = 0.05
#: ... and every change of the contact's state (tooth pair, kind) is bisected down to this (rad of the driven
#: wheel; 1e-6 rad ~ 0.1 micrometre on a pitch curve of 100 mm)
CONTACT_EVENT_STEP_RAD = 1e-5
#: at most this many contact measurements for one direction of one span
CONTACT_EVALUATIONS_MAX = 200_000
#: a vertex where the outline turns by more than this is a corner (a tooth's tip corners turn by 40-90 deg; a
#: flank sampled at 1e-4 mm chord turns by under 2 deg from one vertex to the next)
CONTACT_CORNER_TURN_DEG = 20.0
#: a contact on an edge within this of a corner of that outline is a contact at that corner (mm)
CONTACT_CORNER_NEAR_MM = 2e-3
#: a sample is found from its neighbour's contact: the driven wheel placed this far (rad) on the free side of it
CONTACT_TRACK_MARGIN_RAD = 3e-4
#: ... at most this far (rad): less than half the backlash of any pair the proofs pass (0.1 mm on 100 mm)
CONTACT_TRACK_MARGIN_MAX_RAD = 1e-3
#: ... and turned first through this many margins (of the two its window spans), the whole window only where that
#: holds no contact: the same first contact (a hit within the part is the first within the whole), fewer vertices
#: tested (2: the whole window at once)
CONTACT_TRACK_FIRST_WINDOW = 1.05
#: the contact search skips, before any per-vertex work, each run of this many vertices (in polar-angle order) whose
#: bounding circle stays farther from the mate's outline than the run can turn (a lower bound of that distance read
#: from a grid of the mate, :func:`.contact_events.distance_field`): the same first contact, found in fewer steps
CONTACT_PRUNE_CHUNK = 32
#: ... that grid has about this many cells along the longer side of the mate's bounding box (finer: tighter bounds, a
#: longer distance transform, each contact job its own: a seed-002 variant 0.99-1.01 / 0.96-0.99 CPU s and make 58.7 /
#: 59.5 s wall at 640 / 960; the transform of seed 002's two outlines 0.03 / 0.09 / 0.19 CPU s at 640 / 960 / 1280)
CONTACT_FIELD_CELLS = 640
#: the chained search keeps as candidates the vertices within this of their reach (mm; their exact distance to the
#: mate's edges) and reuses them at the next poses while no other vertex can have come within reach
#: (:mod:`.checks.motion.contact_reuse`): larger, more candidates to sort and fewer sortings (both directions of the
#: seed-002 pair: 0.10 / 0.15 / 0.20 mm, 0.611 / 0.582 / 0.612 CPU s; any value gives the same hits)
CONTACT_REUSE_SLACK_MM = 0.15
#: ... the window of the sorting widened by this (rad) on either side, the turn it holds by this factor
CONTACT_REUSE_WIDEN_RAD = 0.02
CONTACT_REUSE_TURN_FACTOR = 1.25
#: first window of a full search from the law's position (rad; grown 4x until a contact is found)
CONTACT_SEARCH_START_RAD = 3e-3
#: the speed before / after a change of state is the chord over at least this much driven angle (rad)
CONTACT_STEP_WINDOW_RAD = 2e-5
#: a stretch departs from the law where the driven speed is off the law's by more than this share
CONTACT_STRETCH_SPEED_TOL = 0.01
#: a tolerance case (parts/noncircular_pair/tolerance.py) samples the whole driven turn every this many degrees
#: of driver (every change of contact still bisected): about 1/10 of the as-built resolution's cost
TOLERANCE_STEP_DRIVER_DEG = 0.5
#: dimensional accuracy of a desktop FDM print in xy (mm): every edge within +- this of the drawn one (0.1 ... 0.2;
#: the tolerance study of a print kit)
PRINT_XY_ACCURACY_MM = 0.15

# --- load per tooth (gears/tooth_load.py, parts/noncircular_pair/tooth_load_outputs.py) ------------------------
#: the tooth pairs that can take load are measured every this many degrees of the driver over one period ...
TOOTH_LOAD_STEP_DRIVER_DEG = 0.5
#: ... and every change of the set of loaded pairs is bisected this many times (0.5 deg / 2^7 = 0.004 deg: a
#: contact point moved by about 2 micrometres along a flank of 30 mm radius)
TOOTH_LOAD_REFINE_STEPS = 7
#: the flanks' and fillets' curvature is fitted on the outline sampled to this chord tolerance (mm; points on the
#: exact curve 0.008 mm apart at m = 2.5) ...
TOOTH_LOAD_DENSE_CHORD_MM = 1e-5
#: ... over this many modules of arc length on either side of the point (flank) and of the 30 deg point (fillet)
TOOTH_LOAD_FLANK_FIT_MODULE = 0.12
#: a pair whose gap is more than this many times the single pair's deflection under the whole load is not listed
TOOTH_LOAD_GAP_WINDOW_DEFLECTIONS = 4.0

# --- a print kit's hand on the crank (parts/noncircular_pair/kit_load.py) ----------------------------------------
#: the force a hand puts on the crank handle of a print kit (N, tangential; the kit's load case is this force at the
#: handle's radius, the driven wheel held).  A stated assumption: a firm one-hand push on a small handle held
#: between thumb and fingers, the order of the thumb-finger (tips) grip strength MIL-STD-1472D (1989) gives for
#: control forces, 48 N (momentary hold, 5th-percentile man; FAA Human Factors Design Standard HF-STD-001, 2003,
#: Exhibit 14.5.2.1).  A strong hand round the handle pushes several times more: the guide gives the force each
#: printed material takes.
KIT_HAND_FORCE_N = 50.0
#: the kit's pair is placed at each phase from its contact law resolved every this many degrees of the driver: start
#: values only, each phase's contact is measured anew (on the elliptical kit the safeties agree with those from the
#: 0.05 deg law to 4 digits, in a fifth of the time)
KIT_HAND_LOAD_CONTACT_STEP_DEG = 0.5

# --- plates as a slicer takes them (printing/layout.py, printing/printers.py) ---------------------------------------
#: the skirt a slicer draws round a plate's first layer: PrusaSlicer's defaults (skirts = 1 loop, skirt_distance = 6 mm
#: from the objects, or from their brim), carried in each plate's slicer settings (Metadata/Slic3r_PE.config)
SLICER_SKIRTS = 1
SLICER_SKIRT_DISTANCE_MM = 6.0
#: the brim the plates' settings ask for (mm; 0: none, PrusaSlicer's default; a brim pushes the skirt out by its width)
SLICER_BRIM_MM = 0.0
#: the widest first-layer line of the skirt (mm): PrusaSlicer's first_layer_extrusion_width 200 % of its default
#: first-layer height 0.35 mm
SLICER_FIRST_LAYER_LINE_MM = 0.7
#: room kept beyond the skirt's outer edge to the bed's edge (mm): the bed's clips, a slicer's rounding
SLICER_EDGE_ROOM_MM = 1.0
#: the pieces' least distance to the bed's edge (a printer profile's default margin_mm): the brim, the skirt's
#: distance and its loops, and the room beyond them (0 + 6 + 0.7 + 1 = 7.7, rounded up to whole mm)
PLATE_MARGIN_MM = 8.0

# --- bores of a non-circular pair (parts/noncircular_pair/bores.py) -------------------------------------------------
#: the least rim a bore (with its keyway) leaves below a gear's least root radius, in modules: a given bore that leaves
#: less is refused, a sized one never does
BORE_RIM_MIN_MODULES = 1.0
#: a bore the part file does not give is the largest standard shaft whose diameter d is at most the gear's least root
#: radius: the gear's body about it is at least BORE_HUB_RATIO d across (a steel hub's proportion, about 1.8 ... 2 d)
BORE_HUB_RATIO = 2.0
#: the shaft diameters a sized bore is chosen from (mm): ISO 775 / DIN 748-1 cylindrical shaft ends (6 ... 220), and
#: 3, 4, 5 (ISO 2338 dowel pins) for a plain bore below them
BORE_STANDARD_D_MM = (3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 14.0, 16.0, 18.0, 19.0, 20.0, 22.0, 24.0,
                      25.0, 28.0, 30.0, 32.0, 35.0, 38.0, 40.0, 42.0, 45.0, 48.0, 50.0, 55.0, 56.0, 60.0, 63.0, 65.0,
                      70.0, 71.0, 75.0, 80.0, 85.0, 90.0, 95.0, 100.0, 110.0, 120.0, 125.0, 130.0, 140.0, 150.0, 160.0,
                      170.0, 180.0, 190.0, 200.0, 220.0)

#: the smallest module a non-circular pair takes (mm): the smallest of ISO 54 and GOST 9563 (0.05 mm); below it the
#: solvers meet the limits of double precision at the part's other lengths (a scipy warning, then a refusal)
MODULE_MIN_MM = 0.05

# --- the process -------------------------------------------------------------------------------------------------
#: Python's cyclic garbage collector in the program's own processes (``propulsor`` and its forked builds and
#: workers): a young collection every this many net allocations of container objects, then the older
#: generations' (CPython's defaults: 700, 10, 10).  A build allocates millions of small objects, nearly all freed by
#: their reference counts: at 700 the Fourier pair's build ran 927 young, 83 middle and 6 full collections in its
#: main process (0.52-0.66 CPU s), 0.87-0.93 CPU s over its processes, and each collection in a process that has
#: forked writes the headers of the objects it scans, copying pages its workers share.  At these: 6 young, none
#: older; 0.36-0.38 CPU s over its processes, the main process's CPU 5.9-6.1 -> 4.9-5.0 s, its peak 643 -> 648 MiB
#: (cycles such as a closed figure's wait longer).  The files the same.  Only where the process ends with its command:
#: one that evaluates variant after variant (30 seed-002 proof variants in one process) grew 258 -> 316 MiB resident,
#: 70 000 objects of garbage left uncollected, against 257 -> 276 MiB at the defaults; a study and its Dask workers
#: keep Python's own (collector.untune)
GC_THRESHOLDS = (100_000, 50, 100)
