"""Benchmark (issue 40): the CPU seconds of one design-study variant at proof depth, and where they go.

    .venv/bin/python bench/bench_variant.py [part file ...] [--repeat N] [--profile]

Default: the seed-002 pair (parts/ncg_seed002.toml, walking law, generated teeth) and its Fourier form
(parts/ncg_fourier_seed002.toml).  A variant is what a study's worker computes for one row at ``depth = "proof"``
(:func:`propulsor.study.evaluate.evaluate`): the design (law search, teeth), the whole-cycle proof, the as-built
contact in both directions, the per-tooth load and every derived value and check of the report, no solid and no
file, on one core (``PROPULSOR_JOBS=1``, as the study's workers run).  The study reads ``speed_as_built_min`` and
``center_distance_mm`` (so the other tooth method's comparison is skipped: ``evaluate.ONLY_WHEN_READ``).

BLAS and OpenMP at one thread, as the study's workers run (before 2026-11-30's last entry the benchmark left
OpenBLAS its own threads, whose spinning between calls perf put at 7 % of a variant's CPU).  Each part: one warm-up
variant (imports, numba's compiled kernels loaded from their cache), then ``--repeat``
variants with the face width changed (a new design each: nothing is reused between them), each timed by the
process's CPU clock (``time.process_time``).  The target: <= 1.0 CPU s a variant.  ``--profile``: cProfile of the
last variant, the 25 functions of most own time.

Measured (2 cores, the other one running a mutation test; CPU s a variant, three each, old and new one after the
other): before (86d800c) the seed-002 pair 27.14 / 27.23 / 34.75 (the comparison with the sector method included),
its Fourier form 27.79 / 25.06 / 26.73; after the compiled contact search, the states computed once and the
comparison only when read (a5eae93) 13.58 / 13.00 / 13.18 and 18.31 / 18.25 / 18.97.  Of what remains (the Fourier
form, cProfile): the design 8 s (the teeth's envelope points through scalar law calls and bounded minimisations 4 s,
B-spline fitting of 600 pieces 4 s), the as-built contact 2 x 10 935 measurements at 0.18-0.23 ms, the per-tooth
load 3 s, the whole-cycle proof 2 s.

2026-11-29 (2 cores, both busy with mutation runs; two variants each, old and new in turn): at 118e7c2 the seed-002
pair 7.19 / 7.31 / 7.02 / 7.23 CPU s, its Fourier form 6.98 / 7.11 / 7.09 / 7.21; after the root-equidistant heights
found together and the tip searches that cannot leave a land skipped (d875009), 6.89 / 6.86 / 7.15 / 6.97 and
6.82 / 7.18 / 7.14 / 6.89.  The teeth alone (``generate_teeth``, both wheels): seed 002 1.79 -> 1.31 s (752 -> 568
tip searches), its Fourier form 0.93 -> 0.67 s; tips and outlines of seven pairs identical.  Where the rest goes
(the seed-002 pair, one variant, timed per step): the as-built contact 2.5 s (2 x 9 803 measurements at about 100 us
in the compiled search and 25 us around it; 632 of its 651 changes of state are the loaded tooth pair swapping
within a double contact, each bisected), the whole-cycle proof 1.1 s, the teeth 1.3 s, the B-spline fits 0.8 s.

2026-11-29, later (both cores busy with mutation runs; the design alone, ``Variant(...).design``, old and new in
turn): the arc-length frame's phi of one float (28 892 calls a seed-002 design, three scipy spline calls each) in
plain Python, the same operations as scipy's compiled evaluation (bit for bit): seed 000's design 4.66 -> 4.11 CPU s,
seed 002's 2.79 -> 2.57, its Fourier form 1.86 -> 1.87 (it takes the other path); tips and outlines of ten pairs
identical.

2026-11-29, a new session (one core free, the other running a mutation test; two variants each, old and new in
turn, two rounds): the as-built contact's measurements in one compiled loop (``checks/motion/contact_track.py``; a
cache of the pair's outlines measured with it never hit, each direction getting its own copy of the design, and was
reverted): at 9c07cd9 the seed-002 pair 5.88 /
5.81 / 6.04 / 5.89 CPU s, its Fourier form 6.03 / 6.17 / 6.23 / 6.08; at c7497ae 5.87 / 5.87 / 5.93 / 5.93 and 6.05
/ 6.04 / 6.30 / 6.30: no difference above the spread.  One direction's contact alone (``resolve_contact``, CPU s, old -> new):
seed 002 reverse 1.18 -> 1.00, seed 000 drive 0.99 -> 0.93 and reverse 0.80 -> 0.74, the elliptical pair 1.44 ->
1.35 and 1.35 -> 1.19; the te, states, evaluations and progress ticks identical bit for bit.  What is left of the
contact: the compiled search itself (2 x 9 803 positions at about 94 us: of the ~650 vertices it tests a position,
~130 have an edge within reach; a distance field 4 times finer cuts that to 69 us at 1 s of set-up) and the law's
theta of each bisection midpoint one at a time (batched, the Fourier law's theta differs in the last bit).

2026-11-30 (2 cores idle, 7015ca8, two variants each): the seed-002 pair 5.51 / 5.50 CPU s, its Fourier form 5.89 /
5.86 (the same code as 30ceab7's, measured on a machine at rest for once).

2026-11-30, a new session (2 cores, nothing else running; 1fe4bb3 in a worktree against the working tree, two rounds
of two variants each, in turn): the contact search reusing each pose's candidate vertices over the poses after it
(``checks/motion/contact_reuse.py``) and a loaded vertex's curvature fitted once: the seed-002 pair 5.95 / 6.02 /
6.11 / 6.14 -> 5.31 / 5.33 / 5.24 / 5.25 CPU s, its Fourier form 6.45 / 6.64 / 6.67 / 6.68 -> 5.70 / 5.58 / 5.68 /
5.69 (-13 %).  The compiled search of the Fourier form's as-built contact 2.00 -> 1.22 CPU s (21 870 positions: the
14 402 sampled 92 -> 53 us each, the 7 468 of the bisections 88 -> 61 us); the contact laws of seven pairs, their
ticks and the 636 files of ``make`` identical bit for bit.  What a position costs now: about 28 us in the hits of the
~45 vertices a side that do come within reach of the mate (~43 of them hit it), ~13 us in sorting the candidates
again every ~6 positions.  Sorting one run of vertices at a time instead, each at its own pose, was slower (0.77 ->
0.84 s the sampled positions, 0.47 -> 0.62 s the bisections) and was not kept.

2026-11-30 (one core free, the other idle; paired, the old tree (4022d76) and the new one in turn, two rounds of two):
the spline fit's foot-point distances compiled (geometry/spline_foot.py): seed 002 5.14 / 4.98 / 5.28 / 5.19 ->
4.72 / 4.72 / 4.98 / 4.94 CPU s (-6 %), its Fourier form 5.39 / 5.37 / 5.49 / 5.49 -> 5.27 / 5.35 / 5.27 / 5.35
(-2.5 %).  The fits alone, their exact points known (bench/bench_spline_fit.py): 0.40 -> 0.21 CPU s a design,
every spline identical.  What is left (the seed-002 pair, cProfile): the compiled as-built contact search 1.2 s
(23 %), the rest spread over the laws' and the pitch curves' small-array and one-float calls of the design
(0.1-0.2 s each), the whole-cycle proof's crops and booleans (0.15 s each), the per-tooth load's fits (0.3 s).
At eb11034 (the same pairing, two rounds of two; also the tip searches' samples kept per tooth, the Fourier law's
one-point inversion compiled, the smoothed walking law's few-angle calls on its one-point path, and no figure drawn
at proof depth): seed 002 5.07 / 5.00 / 5.21 / 4.99 -> 4.36 / 4.34 / 4.44 / 4.52 CPU s (-13 %), its Fourier form
5.28 / 5.41 / 5.38 / 5.37 -> 4.67 / 4.80 / 4.75 / 4.75 (-12 %); the 636 files of make identical after each step.

2026-11-30, a new session on a slower, noisier machine (2 cores; paired, 8e99e60 in a worktree and the new tree in
turn, three rounds of two; the least of each pair): the seed-002 pair 7.00 / 7.42 / 7.21 -> 6.49 / 6.63 / 6.55 CPU s
(-9 %).  perf showed 18 % of a contact search's samples in numba's reference counting (NRT_incref / NRT_decref,
called at every vertex a point's cells hold: an array variable reassigned inside the scan, and the distance field
handed to an inlined function at every vertex); without them one direction's contact 1.21-1.25 -> 1.00 CPU s, the
te identical bit for bit.  The free rotations' rotation hits (the whole-cycle proof, the polysector) now seek a
point's hits only near its circle about the turning axis: the polysector's 1 500 searches 4.40 -> 1.19 s, the
whole-cycle proof unchanged (1.55 vs 1.60 s: its windows are narrow).

2026-11-30, the next session (2 cores, idle; 57047af in a worktree and 9fdd08d in turn, four rounds of two): the
seed-002 pair 5.59 / 5.71 / 5.74 / 5.69 -> 5.68 / 6.07 / 5.68 / 5.64 CPU s: unchanged (that session's work, the
least-overlap lens cuts, the compiled pictures and the faster vertex merge, is outside a conjugate pair's proof-depth
variant; the two rotation-hit kernels made one source cost nothing).

2026-11-30, a third session (2 cores; 68c8983 in a worktree and the new tree in turn, two rounds of two, least of
each; at the end, with the machine quiet): the seed-002 pair 5.55 / 5.62 -> 3.85 / 3.73 CPU s (-32 %), its Fourier
form 6.39 / 6.22 -> 5.65 / 5.54 (-11 %).  What changed, each with every output identical
bit for bit: the shortened tips' search starts from where the tip leaves a flank (seed 002: 343 -> 84 evaluations);
a wheel's spline fits in lock step, each round's points of a kind of piece for every tooth in one array (not for
the Fourier law, which is not elementwise: hence its smaller gain); the law search kept by its inputs (the variant
changes the face width: the seed-002 pair's 0.45 s search made once); a spline's samples kept; the two as-built
directions share the pair prepared first; the whole-cycle proof's common area 0 without the boolean where the bodies
are certainly apart.  The design alone (``Variant(...).design``, least of three): seed 002 2.13 -> 1.27 CPU s; the
whole-cycle proof alone 1.32 -> 0.96 CPU s.  What is left (seed 002, py-spy): the as-built contact's compiled
search 36 %, the design 31 % (the tip searches' fsolve, the fits' B-spline interpolation), the whole-cycle proof
27 % (the crops' booleans, the free rotations).

2026-11-30, a fourth session (2 cores; 23513cd in a worktree and the new tree in turn, least of two variants each):
numpy's reductions along the short axis of (n, 2) arrays (``np.linalg.norm(V, axis=1)``, ``V.min(axis=0)``: 5 and 10
times the cost of the same arithmetic column by column) replaced where the outlines, the vertex grids and the foot and
tip searches prepare thousands of vertices (``propulsor.planar``: the same floats), and the vertex grid's buckets built
by one compiled counting pass (the same arrays).  Quiet, two rounds: the seed-002 pair 3.84 / 3.81 -> 3.66 / 3.58 CPU s
(-5 %), its Fourier form 5.67 / 5.62 -> 5.59 / 5.58; later, the machine ~10 % slower: 4.08 / 4.43 -> 4.03 / 3.72 and
6.42 / 6.41 -> 6.11 / 6.19.  Every output identical bit for bit.  Where the 1.0 CPU s target stands: the as-built
contact's compiled search alone is 1.34 CPU s a seed-002 variant (2 x ~10 800 positions at ~62 us: the 0.05 deg
sampling and the 1e-5 rad location of each change of state that policy asks for), so the target needs that search
three times faster or fewer positions, which would change the measured transmission.

2026-12-01, a fifth session (2 cores; f219260 in a worktree and the new tree in turn, two rounds of two variants):
the tracked contact search turns through the nearer 1.05 of its window's two margins first and through the whole
only where that part holds no contact (``policy.CONTACT_TRACK_FIRST_WINDOW``; a hit within the part is the first
within the whole, so the contact is the same, bit for bit).  Where the contact lies in the window (d / margin at
consecutive samples, seed 002, seed 000 and the elliptical pair, both directions): 0.990 to 1.011, so the part holds
it at every sample of these pairs.  The six contacts of seed 002, its Fourier form and seed 000, in one process, the
whole window and the part in turn (least of four): 4.33 -> 3.41 CPU s (-21 %).  Variants: the seed-002 pair 3.82 /
3.81 -> 3.45 / 3.45 CPU s (-10 %), its Fourier form 6.00 / 5.93 -> 5.30 / 5.88 (noisy).  perf (with a map of numba's
symbols written by hand: address and size of each compiled function) of the contacts after it: the per-vertex root
search 23 %, the candidates' new sorting 20 %, numba's reference counts 19 % (the ~30 arrays each call of the
per-position search hands on), the candidates' filter 5 %.  The Fourier form's variant also measures the load per
tooth (1.24 CPU s, of which the curvature fits 0.43), which the seed-002 pair's part file does not ask for.

2026-12-01, a sixth session (2 cores, the machine drifting 10-20 % within minutes): each change of state's bisection
starts from the candidate caches the sampled run held at the change's first end (``contact_reuse.seed_slots``: before,
each bisection slot started empty, and its first search sorted the window's ~740 vertices again; now 199 of 240
midpoints of the test pair are served from the kept cache).  The six contacts of seed 002, its Fourier form and seed
000 in one process, the kernels of 4cf9bba (compiled in the same process) and the new ones in turn, least of three:
3.756 -> 3.369 CPU s (-10.3 %), the contact laws identical bit for bit.  Variants, 4cf9bba in a worktree and the new
tree in turn, two rounds of two: the seed-002 pair 3.42 / 3.50 -> 3.64 / 3.63 CPU s, its Fourier form 5.19 / 5.66 ->
5.28 / 5.62: the machine's drift (the unchanged design and proof were 7-20 % slower in the new tree's runs under
cProfile too) is larger than the contact's 0.1 s a variant.

2026-12-01, a ninth session (2 cores; a loop of 20 M additions 2.2-3.0 s, the machine slow throughout): the
whole-cycle proof crops both outlines once per 0.4 rad window instead of 0.1 (``policy.PAIR_PROOF_WINDOW_RAD``): a
crop's boolean costs about the same whatever its span (the reach on either side of the window is most of it), and
every value of the proof is the same to the bit in 16, 63 or one window (the ten pairs of ``make`` compared; a test
holds it).  The proofs of make's ten pairs in one process, 63 and 16 windows in turn, three rounds: 20.83 / 20.26 /
20.67 -> 16.47 / 16.81 / 16.21 CPU s (seed 002's 1.03-1.19 -> 0.74-0.76, seed 000's 1.43-1.52 -> 0.93-1.06; the
sector tables' proofs, whose time is the least-overlap booleans, 5-7 % less).  Variants, 7dc0106 in a worktree and
the new tree in turn, two rounds of two: the seed-002 pair 4.80 / 4.40 / 4.40 / 4.83 -> 3.79 / 3.83 / 3.66 / 3.97
CPU s, its Fourier form 7.11 / 8.04 / 6.48 / 6.29 -> 7.97 / 6.12 / 6.58 / 7.03; the same pairing later (also the
silent progress counter, 6683191): 3.45 / 3.32 / 3.88 / 4.77 -> 3.57 / 3.20 / 4.52 / 5.18 and 7.31 / 8.09 / 9.48 /
9.74 -> 6.08 / 5.05 / 7.80 / 8.28.  The machine's swings are larger than the change; the proof's own time inside
a variant, 63 and 16 windows in turn in one process, four rounds: seed 002 1.09-1.15 -> 0.83-0.97 CPU s, its
Fourier form 1.06-1.35 -> 0.74-0.77.  A coarse crop held for the next windows
(each window's crop cut from it) gave the same loops vertex for vertex and 28-45 % less crop time at 63 windows,
nothing at 16: reverted.

2026-12-01, a tenth session (2 cores, the machine's speed swinging by up to 70 % between minutes): a variant's steps
timed in one process (``generate_pair``, ``prove_pair``, ``resolve_contact`` both ways, the per-tooth load's
``analyse``; least of two, the machine quiet): the seed-002 pair 3.17 CPU s (the design 1.33, of it the teeth 0.82 and
the fits 0.45; the whole-cycle proof 0.64; the as-built contact 1.05-1.10; no load case in its part file), its Fourier
form 5.54 (the design 1.99, the proof 0.66, the contact 1.20, the per-tooth load 1.54, of it 2 507 flank curvatures
fitted 7 481 + 2 547 times by least squares).  Those curvatures are now fitted together (``tooth_load.curvatures_at``:
the problems solved in stacks of one shape by numpy's own LAPACK driver, each the one-at-a-time value to the last
bit): 2 500 vertices of a toothed outline 0.66 -> 0.53 CPU s, three rounds; numpy's ``lstsq`` on one cubic 25 us, in a
stack 5.4 us; the rest is the windows' and the problems' setting up.  The contact search's reuse and pruning
parameters swept (slack 0.05-0.2 mm, widening 0.01-0.04 rad, turn factor 1.25-2, first window 0.8-1.5 margins, runs
of 16-64 vertices; each the same contact law to the bit): none faster beyond the machine's swings, the first window
of 0.8 margins twice as slow.  ``bench_variant.py`` at the end: the seed-002 pair 3.95 / 3.92, its Fourier form
7.90 / 7.51 CPU s (the machine slow: ncgears' generation 65.5 s against 59.8 s last session).

2026-12-01, an eleventh session (2 cores; afd7c03 in a worktree and the new tree in turn, a variant's steps timed in
one process, three rounds of two).  The Fourier law's array functions are its compiled one-point path at each angle
(``laws/fourier_kernels.py``: ``theta_many``, ``derivs_many``, ``phi_many``; before, numpy's Newton over the whole
array and a matrix product, whose row sums depend on the array's length), so the law is ``elementwise`` and its
teeth's curves are fitted in lock step; the last array's theta and U's derivatives are kept (a pitch curve asks for
U, U' and U'' of one array in turn: 7 045 -> 1 621 inversions a design).  The two Fourier part files' outlines move
by at most 2.0e-10 mm (the driven tip lands, found to the tip search's tolerance; the flanks by 6e-14 mm), every
check passing.  For every law, each identical to the last bit: a re-phased shaper's tip round evaluated at s and a
step either side in one array (1 618 -> 619 evaluations a seed-002 design), the spline fit's interpolation by
scipy's own steps without ``make_interp_spline``'s checks (100 -> 27 us a call, 1 400 calls a design), the
arc-length frame's phi of up to 8 arc lengths by ``phi1`` (7 126 -> 4 150 scipy spline calls a design).  The Fourier
form: the design 1.81 / 2.03 / 1.92 / 2.21 / 2.29 -> 0.93 / 0.98 / 1.01 / 1.05 / 1.13 CPU s (the fits 0.90-1.17 ->
0.34-0.47, the teeth 0.84-1.05 -> 0.53-0.75), the variant (least of each pair) 5.27 / 4.72 / 6.40 -> 3.74 / 4.51 /
4.11 CPU s.  The seed-002 pair: the design 1.26 / 1.31 / 1.36 -> 1.04 / 1.07 / 1.19 (the fits 0.43-0.54 ->
0.32-0.38), the variant 3.18 / 3.36 / 2.99 -> 2.88 / 3.04 / 2.76.  ``bench_variant.py`` at the end, both trees in
turn, two rounds: the seed-002 pair 2.87 / 3.08 -> 2.85 / 3.24 CPU s, its Fourier form 4.47 / 4.82 -> 4.57 / 3.91
(the machine's swings as large as the change there; the steps above are the measure).  Later (53c0746): a bisection
round's midpoints go to an elementwise law's theta in one call; 7 500 midpoints' theta one at a time 0.07-0.11 CPU s
(the seed-002 pair's blended law) and 0.08-0.18 (the Fourier law), in calls of 600 0.001-0.005: about 0.1 CPU s a
variant, below the six contacts' swings (3.1-5.3 CPU s either way, the contact laws identical array by array).

2026-12-01, a twelfth session (2 cores; no change kept).  The seed-002 variant 2.96 / 4.07 CPU s (cProfile: the
as-built contact's compiled loop ``_track_nb`` 0.95 s in 38 calls, the rest spread over ~2.4 M Python calls).  Where
the contact's compiled time goes, by ``perf record --call-graph dwarf`` with the JIT addresses mapped through the
kernels' cached object code (``nm`` of the ELF in the ``.nbc``, placed at the entry numba gives): the rotation pairs
(``backlash._rot_pairs``) 28-36 %, the cache refresh's nearest-vertex searches (``nearest._nearest_vertex``) 12 %,
``_reused`` 7 %, ``_refresh`` 6 %, ``_side_hits`` 5 %, ``_rot_reduce`` 4 %, and numba's reference counts (the atomic
add of ``NRT_incref`` / ``NRT_decref``) 18-24 % of it: an array handed to a compiled function is counted up on entry
and down on exit (the nearest-vertex search: 6 atomic operations a call, one call a vertex of a refreshed window),
and an array variable assigned inside a loop at every turn.  Tried, each the same contact law to the bit and none
faster (in one process, the old tree imported beside the new as ``propulsor_old`` and the two run in turn ten times:
identical code measures 0.98-1.02): the per-position helpers inlined (``inline="always"``: numba's inliner binds the
arrays to new variables, counted the same), the rotation pairs' scratch arrays sized by a first pass over the points
instead of grown in the loop (the atomics go, the extra pass costs as much), the nearest-edge search's per-point
helpers inlined (the cams' motion proofs: 2.03 -> 2.05 CPU s least of eight).  The same mapping on the cams' motion
proofs: ``_nearest_edge`` with its helpers 30 % of the samples, their reference counts a further 11 %.
2026-12-02, a fifteenth session (2 cores, idle; 965c6b0, no change to a variant's work): the seed-002 pair 3.38 / 2.96 /
2.74 CPU s.  py-spy of five variants (21.7 s sampled): the as-built contact's compiled loop 26 % (1.15 s a variant),
then nothing above 4 %: the free rotations' hits 0.16 s a variant, the spline fits' foot distances 0.10, the walking
law's ``wrap_leg`` on small arrays 0.09, the proof's crops 0.09, the pickle round trip of the design handed to each
contact direction run inline (``parallel.as_if_sent``) 0.06.
2026-12-02, a sixteenth session (2 cores; the machine's swings 2.4-4.7 CPU s for one variant within the hour, so each
change measured on its own step, in one process, old and new in turn).  The load per tooth (the Fourier form's part
file asks for it): each phase's window of hits now leaves out the vertices that cannot reach the mate
(``PairOutlines.hits``, the finite hits of ``_all_hits`` in order) and names the teeth by a compiled nearest centre;
the 1 001 ``phase_contacts`` of one variant replayed, four rounds in turn: 0.444 / 0.335 / 0.395 / 0.313 -> 0.262 /
0.257 / 0.302 / 0.278 CPU s, every contact identical (te, teeth, gap, lever arms, vertex, point, normal).  Tried and
not kept, each the same contact law to the bit and no faster: the nearest-vertex search leaving out the cells of a
ring farther than its bound (200 000 searches at 0.7 cells' bound: 0.026-0.033 s either way: a search is 0.15 us,
the refresh's cost is their number, ~360 a refresh), and the rotation pairs listing each edge once (the edge ending
at a near vertex is the edge starting at the one before it: in the contact search a point has a few near vertices,
the six contacts 2.369 / 2.347 least of twelve, the whole-cycle proofs 0.518 / 0.500).  Then the walking laws' ``U``
and ``dU_dphi`` of an array (7 122 and 2 270 calls a seed-002 variant, tens to hundreds of angles each) in one compiled
loop (``laws/walking_kernels.py``, numpy's values bit for bit): those calls 0.149 + 0.042 -> 0.052 + 0.013 CPU s a
variant (each call timed by the process clock, three variants); the six contact laws and make's 636 files identical.
The variants at the end: the seed-002 pair 2.49 / 2.66 / 2.85 CPU s, its Fourier form 3.82 / 3.82 / 3.60 (2.37 and
3.41 at the session's start: the swing is larger than the change).

2026-12-03, a new machine (2 cores, idle; 9f05cec's product code; four variants after the warm-up): the seed-002 pair
3.14 / 3.19 / 3.04 / 3.09 CPU s (this machine is slower than the last).  py-spy of the five variants: the proof 45 %
(the as-built contact both ways 26 %, the whole-cycle proof 17.5 %: its transmission sweep 12 %, free rotations 7 %),
the design 42 % (the teeth 24 %: the flank sides 9 %, the tip searches 8 %, of which scipy's fsolve 6 %; the spline
fits 12 %).
2026-12-03, a second session (2 cores; each step in one process, old and new in turn).  The tip hits by Newton's method
from the nearest sample, fsolve only where an iterate leaves the flank or does not converge (8953b00; 132 of the
seed-002 design's 152 found hits served, the same points to 1e-11 mm): ``tip_hit``'s time a design, three rounds,
seed 002 0.279 / 0.397 / 0.402 -> 0.235 / 0.336 / 0.342 CPU s, seed 000 0.478 / 0.562 / 0.493 -> 0.419 / 0.507 /
0.437.  What is left there is fsolve failing (a height above the flank's end: 128 of the 148 calls that reach it,
5 172 of its 5 841 evaluations in seed 002), which no exact shortcut was found to skip.  The as-built contact's
rotation hits one point at a time (9ac9bbf: ``contact_kernels._side_hits``, no arrays of every pair through three
passes) and an edge ending at a vertex within reach that also starts at one searched once (b368de5): the contact
laws of five pairs identical array by array; one direction pair 6-14 % less CPU, then a further 4-7 % (median of ten
paired runs 0.963 seed 002, 0.933 its Fourier form; the twelfth session's "each edge once" gained nothing in the old
multi-pass kernel).  perf with the kernels' symbols mapped, one direction pair: before, ``_rot_pairs`` 38 %,
``_nearest_vertex`` 19 %, ``_refresh`` 10 %, ``_reused`` 8 %, numba's reference counts 7.5 %; after, ``_side_hits``
43 %, ``_nearest_vertex`` 21 %, reference counts 7.7 %.  Calling ``_nearest_vertex``'s inner search from
``_refresh`` directly: no difference (reverted).  Python's collector: 1.5 CPU s of make's 208, ~2 % of a variant:
not pursued.
2026-12-04, a new session (2 cores; the machine's speed swinging 25-40 % within minutes).  The spline fit's foot
distances (``spline_foot._foot``) without the five scratch arrays its basis-function step allocated at each of its
~340 000 evaluations a seed-002 variant (4ae55ab): the 1 404 and 1 452 calls of the seed-002 and Fourier variants
replayed, old and new in turn, eight rounds: every distance identical; medians 0.0574 -> 0.0529, 0.0568 -> 0.0539
CPU s on a quiet minute, 0.0988 -> 0.0757, 0.0978 -> 0.0800 on a slow one (about 0.01-0.02 CPU s a variant).
py-spy of five variants at the session's start (seed 002): the as-built contact's compiled loop 23 % (self), the
whole-cycle proof's transmission sweep 13 % (its free rotations 8 %), the teeth 22 % (the tip searches 7.6 %, the
flank sides 8 %), the fits 14 % (foot distances 2.8 %, interpolation 2.5 %, the refinement's bookkeeping ~2 %).
Variants after that change: the seed-002 pair 2.61 / 2.87 / 2.69 / 2.89 CPU s, its Fourier form 4.22 / 4.40 / 4.42 /
4.60 (2.47 / 2.64 / 2.72 / 2.53 for seed 002 at the session's start, before any change: the machine's swing).
Then the whole-cycle proof's transmission sweep (16 windows, 320 positions, both ways at each): each position's radii
and boundary bounds in one compiled pass (``backlash.rot_bounds``, 9a1deee), its contact zones counted in one
(``_zones_nb``, 16423de), and the two senses' first windows from one search of each side's pairs
(``free_rotations``, 76a5459: the pairs of the wider window, each sense reducing its own entering roots within its
own window, bit for bit the hits of its own search).  b368de5 in a worktree and the new tree in turn, three rounds of
three variants (the sweep's own time, process clock): 0.481 / 0.474 / 0.415, 0.377 / 0.323 / 0.345, 0.387 / 0.351 /
0.342 -> 0.241 / 0.283 / 0.234, 0.198 / 0.196 / 0.211, 0.217 / 0.297 / 0.268 CPU s (-40 %, about 0.14 s a variant);
the variants themselves 2.16-2.66 -> 1.95-2.81 (medians 2.40 -> 2.27: the machine's swing again as large as the
change).  py-spy of six variants after: 4 295 samples against 5 089 at the session's start; the contact's compiled
loop 25 %, the rotation hits' wrapper 2.6 % (4.6 %), nothing else above 2.2 %.  make's 636 files identical after each
step.  Last, the contact events' side speeds walk a run id per sample instead of comparing state rows with numpy at
every step (f83ef2e): the two contact laws of a seed-002 variant (9 803 samples each), old and new methods in one
process, five rounds: 0.059-0.063 -> 0.017-0.020 CPU s, the events equal.

2026-12-04 (from 0774daa).  py-spy of six seed-002 variants (200 Hz): the contact's compiled loop 25.5 % (its sampled
run 80 %, the bisections 20 %), the teeth 24 %, the whole-cycle proof 15.6 % (its transmission sweep 8.5 %, the
crops' booleans 3.1 %, their outlines 2 %), the fits 12.6 %, nothing else above 3 %.  In the contact loop (perf on a
fresh compile): the rotation hits 43 %, the candidates' sorting 35 % (a sorting every 12 positions a side, each ~76
runs, ~184 candidates), their reuse test 10 %.  Tried and not kept: sorting again only the runs whose bound fails
(each run with its own pose): full sortings 8 % -> 1.9 % of a side's calls, but partial ones at 42 % of them and
the candidates a call 60 -> 84 (their bounds older), the two contact laws 0.69-0.93 -> 0.85-0.92 CPU s with the same
hashes: no gain.  The slack and widening at 0.05-0.2 mm and 0.02-0.05 rad: no gain either (0.1 mm, 0.02 rad stay).
Kept: a profile's loops oriented by their exact signed area (Green's theorem, each segment's ``sweep``: a B-spline's
by Gauss-Legendre on each knot span, compiled), not by the area of their polylines sampled at 0.005 mm only for it:
the two generated wheels of a variant (120 + 472 segments) 6.6 + 21.8 -> 1.2 + 7.0 ms, the same senses, make's 636
files identical.  The variants, old and new trees in turn, three rounds of four: 2.13-2.89 / 1.77-2.14 / 2.00-2.43
against 1.85-2.03 / 2.20-2.54 / 1.87-2.11 CPU s (the machine's swing larger than the change, ~0.02 s).  make from
clean, old and new in turn: 88.3 / 73.3 s wall (151.7 / 133.7 user s) against 77.6 / 74.6 / 83.2 s (139.5 / 135.6 /
152.8): the same within the swing.

2026-12-04, a later session (2 cores; from 6fe32a6; the machine fast at first: the seed-002 pair 1.72 / 1.75 / 1.72 /
1.72 CPU s, its Fourier form 2.51-2.65).  py-spy of six seed-002 variants: the contact's compiled loop 34 % of the
samples (0.6 s a variant), the design 29 % (the teeth 15 %, the fits 9 %), the whole-cycle proof 16 %; the Fourier
form adds the load per tooth, 0.66 CPU s of its 2.5 (the phases' contacts 0.27, the flank curvatures 0.24 of which
their windows' set-up 0.16, the root sections and stresses 0.12).  Kept (70bf949): the curvatures' windows and frame
coordinates of every vertex in one compiled pass (``gears/tooth_load_kernels.py``; numpy's ``q @ t`` for two columns
is OpenBLAS's gemv, ``fma(q0, t0, q1 t1) + 0.0``: the fused product, then added to the zeroed y, so a -0.0 comes
out +0.0; 200 000 random rows and every window of three outlines at three half lengths to the bit), and each phase's
hits gathered, their points and each tooth pair's first hit compiled (``mesh_load._phase_hits``, ``_firsts_nb``):
``analyse`` 0.66 -> 0.47 CPU s, its rows identical (repr); the Fourier variant, 6fe32a6 in a worktree and the new
tree in turn, two rounds of three: 2.58 / 2.48 / 2.65, 2.43 / 2.54 / 2.54 -> 2.36 / 2.39 / 2.34, 2.26 / 2.24 / 2.26
CPU s (-0.2 s, -8 %).  Tried and not kept: the contact's margin (``CONTACT_TRACK_MARGIN_RAD``) 3e-4 -> 1e-4 / 3e-5 /
1e-5 / 3e-6 rad: both directions 0.70 -> 0.58-0.60 / 0.58 / 0.58 / 0.54 CPU s (the window's reach shrinks, the
sorting's cost stays), the same states at the same phases, te moved by up to 7e-16 rad (a rounding of prev + sign
(m - d)): files would change in their last digits for 17 % of the contact; with the reuse's slack 0.03 / 0.01 mm
and widening 0.005 / 0.002 rad beside it, slower (0.79 / 1.41 s: more sortings).  The first window's share
(``CONTACT_TRACK_FIRST_WINDOW``) 1.02 / 1.15 / 1.5: 0.62-0.69 / 0.67-0.72 / 0.74-0.77 against 0.65-0.69 at 1.05
(kept).  A nearest tooth by bisection of the sorted centres: 0.54 us a measurement of its ~30 (80 teeth), not done.

2026-12-04, a new session (2 cores; from fc540ec).  The contact's margin measured again, three positions each, two
rounds, 3e-4 / 1e-4 / 3e-5 rad: 0.72-0.77 / 0.58-0.75 / 0.57-0.66 CPU s for both directions: 10-15 % of the contact
(about 0.08 s a variant) against every contact file changed in its last digits: still not done.  The garbage
collector tuned (49ffcaa, ``policy.GC_THRESHOLDS``, tried in a study's workers and this benchmark too): a variant's
collections 0.06-0.09 CPU s -> 0.01-0.02; the variants, fc540ec in a worktree and the new tree in turn, two rounds of
three: 1.69-1.73 / 2.31-2.43 -> 1.71-1.77 / 2.23-2.38 CPU s (the seed-002 pair / its Fourier form): no difference
above the spread (the collector's cost is in the builds, whose processes fork: bench_vs_ncgears.py); and a process
evaluating 30 variants grew 258 -> 316 MiB (garbage left to pile up) against 257 -> 276 at the defaults: a study's
workers, and this benchmark, keep Python's own thresholds.  Where the design's
time still goes (one design each, ``tip_search.tip_hit`` timed): seed 002, 213 tip searches of which 61 find no tip
(the flank stops short of the height asked: Newton leaves the flank, then fsolve fails, once or twice) 0.101 of the
design's 0.74 CPU s; seed 000, 277 of which 103 none, 0.184 of 1.16 s; the Fourier form takes no tip search.  A proof
that no flank point lies within the solver's tolerance of the equidistant (the flank's greatest height below h by more
than it) would return the same None without the solver; it needs a bound on the flank's height between its 41 samples
that holds on an undercut flank too (its cusp), which was not found this session.  For compiling the one-point
envelope chain (the other way to make those searches cheap): on this machine numpy's ``arctan2`` (array or scalar:
the same loop) differs from libm's ``atan2`` in 2.5 % of 200 000 random pairs and numpy's ``arctan`` from libm's in
0.13 %, while numpy's ``cos`` equals libm's everywhere and numba's ``math.atan2`` is libm's: a compiled chain must
take its arc tangents from numpy's loop (or a copy of its algorithm), not from numba's.

2026-12-04, a later session (2 cores; from 82d843d).  numpy's loop is callable from a kernel: numpy exports SVML's
``__svml_atan28_ha`` from its core module (the ``_ha`` one: the plain ``__svml_atan28`` differs from numpy's results
on 26 % of pairs, ``_ha`` on none of 2 million), so ``propulsor/npmath.py`` registers it with LLVM and calls it on
one lane of eight (a numba intrinsic): ``np.arctan2``'s float bit for bit, or the C library's where numpy takes that
(``NPY_DISABLE_CPU_FEATURES=X86_V4``: checked, both ways).  First use (db01302): the whole-cycle proof's steps in one
compiled loop (``checks/motion/transmission_kernel.py``): the proof of the seed-002 pair, 82d843d in a worktree and
the new tree in turn, two rounds of four in one process each (the least): 0.278 / 0.269 -> 0.234 / 0.231 CPU s, its
Fourier form 0.265 / 0.265 -> 0.223 / 0.221, seed 000 0.378 / 0.374 -> 0.324 / 0.342, the elliptical pair 0.151 /
0.145 -> 0.132 / 0.129 (-12 to -17 %), every result identical; the variants themselves, three rounds of three in
turn, 1.72-1.86 / 1.77-2.01 / 1.74-1.83 -> 1.73-1.75 / 1.76-2.02 / 1.83-1.93 CPU s: the 0.04 s is below this
machine's spread today.  What is left of the proof (0.23 s): its steps 0.13-0.15 (the certainly-apart test about
10 % of the proof: tried without it, 0.216-0.233 against 0.244), the 32 crops by Clipper 0.05 and their outlines 0.04
(1.2 ms each, 4 200-6 000 vertices).  The contact's margin once more, decided: not made smaller.  A position is
searched from a start a margin m = 3e-4 + 0.25 |d phi| rad on the free side of the last contact, which holds while
the contact moves less than that between two positions; at a driven speed 44 % off the law's (seed 000 as cut) and
the sampled spacing (about 9e-4 rad) it moves 4e-4 rad: 1e-4 would leave the start inside the mate there, and a
start inside finds a later contact, not the first.  The first window's share 0.8 / 1.3 against 1.05: 1.11-1.16 /
0.69-0.70 against 0.68-0.84 s both directions (kept).  The reuse's slack 0.05 / 0.2 mm, widening 0.01 / 0.04 rad,
prune runs of 16 and a field of 1 000 cells: within the spread (0.69-0.91 s against 0.71-0.81).  Not worth the change
(measured): the pickle round trip of a job run in place (``parallel.as_if_sent``, the design of 0.88 MB) 0.016 s a
direction, 1.2 % of a variant.

2026-12-04, a third session (2 cores; 08f6215, every output identical to bench/hashes/all_19_make_at_9ac9bbf.sha256).
Where a variant's time goes, sampled (py-spy at 200 Hz, eight seed-002 variants, no tracing: cProfile had put the
Python-bound parts at two to three times their share): the contact's compiled search 30 % (0.48 s), the design 40 %
spread over ten parts of 0.05-0.15 s each (the B-spline fits 0.15, the sides' generation 0.13, the nominal tips 0.10,
the tip shortening 0.08), the proof 0.15 s.  The one-point envelope chain is smaller than the last notes thought:
``envelope_point1`` timed per call in a seed-002 design, 7 976 calls, 0.077 s in all (about 10 us each; seed 000
13 894 calls, 0.14 s): compiling it is worth at most that, not the lever it was taken for.  perf (Debian's
linux-perf; numba's code shows as [JIT]) puts 7.3 % of a variant and about a fifth of the contact search's own time
in numba's reference counts (``NRT_incref`` / ``NRT_decref``: an atomic add each, on every array variable a kernel
takes or copies that LLVM's reference-count pruning does not pair off).  Their sites, from the return addresses of
400 000 increfs in a direction's steady state (gdb, a breakpoint enabled mid-run, on kernels compiled in a fresh
cache so that their symbols are known): 44 % the three array arguments of ``nearest._nearest_vertex`` (called once a
candidate by the reuse's refresh), 18 % one site in ``_side_hits``'s vertex loop, 13 % ``_track_nb``, 8 %
``first_hit_reusing``, 6 % ``_side``.  numba's IR inlining does not remove them: with ``_nearest_vertex_low``
(inline="always") called in the refresh instead, the same share moved into ``_refresh`` (48 %); only code written out
in the loop takes no reference.  Together they are about 0.1 s a variant (in the contact's bench, both directions:
0.14 s of 0.75, a fifth of its compiled time).  The changes tried (that one, the candidate scan's helpers written out
in ``_side_hits``, ``first_hit_reusing`` written out in ``_track_nb``) left the contact's time within the spread (old
and new tree alternating, three rounds: 0.70-0.83 s a round either way) and none removed the largest site: the next
step, tried at the session's end in a worktree, is ``_nearest_vertex``'s ring search written out in ``_refresh``: its
44 % gone (``_refresh`` then holds 8 % of the increfs), the contact bit for bit the same, both directions 0.715 /
0.716 / 0.737 -> 0.695 / 0.692 / 0.690 CPU s a round (about 0.02 s a variant); not kept, as it is a second copy of
``_nearest_vertex_low``'s search.  Not one kept.  A limit met on the way: numba cannot IR-inline a call with more
than 30 arguments (CPython 3.11 compiles it to CALL_FUNCTION_EX, which numba reads as ``*args``: "Calling a closure
with *args is unsupported").
``make`` from clean at 08f6215: 65.5 s wall, 118.5 user + 5.8 sys s; ``propulsor build`` of the 19 part files alone
60.7 s wall on a quiet minute: its imports 2.4 s and the part files' estimates 0.7 s before the first build (0.5 s of
it the balancer's, whose estimate needs its suspension design), the road wheel alone for its last 1.2 s.  The table
pairs' proofs (``pair_proof._least_overlap``): 2 554 and 3 748 Clipper overlaps of 0.9 and 0.5 ms
(12-14 a non-conjugate phase, Brent to 1e-6 rad), 4.4 s of make's CPU; their lens cuts are made afresh at each such
phase (the driver's centre moves about 1.5 mm a phase, the cut keeps 1 mm spare: 640 cuts, 0.5 s).

2026-12-05 (2 cores; 0404b16; the gauge 1.66-1.81 over the session).  numba's ``error_model="numpy"`` on the
contact's kernels (contact_kernels, contact_reuse, contact_track, nearest, backlash; no division-by-zero checks):
both directions of seed 002's contact 0.63-0.68 -> 0.63-0.68 CPU s, the same values: reverted.  py-spy (200 Hz, ten
variants): the contact's compiled loop 32 % (about 0.55 s), the design 43 % (generate_gear 24 + 5 % for the two
wheels, the B-spline fits 10 %, the tip searches 8 %), the whole-cycle proof's compiled steps 7 %.

2026-12-05, a later session (2 cores, idle; from 7124cb8).  A wheel of equal lobes cut as one lobe and patterned
(132a569, cf02913: ``generate_teeth(..., lobe=True)``, ``noncircular_outline.generate_gear``): the driven wheel has the
law's ``periods`` lobes, the driver periods / n; the teeth of one lobe and the roots after it are generated and
fitted, the rest are its B-spline pieces turned (each pole by its own products).  seed 002's driven wheel (80 teeth,
4 lobes) 0.65 -> 0.18 CPU s; the variants, old tree (PYTHONPATH to a worktree of 7124cb8) and new in turn, three
each: the seed-002 pair 1.70 / 1.73 / 1.75 -> 1.22 / 1.23 / 1.21 CPU s, its Fourier form 2.70 / 2.57 / 2.39 -> 1.87 /
1.82 / 1.83.  Not bit for bit: the lobes cut tooth by tooth differed by the fits' own choices, so the patterned wheels
moved by at most 3.8e-6 mm at a pole (the fits' tolerance 1e-5 mm; seed 000's driven wheel, 4.05e-6 mm between the
outlines sampled at 1e-4), the first lobe the same floats; every derived value of the seven pairs concerned moved by
at most 3.2e-10 relative (speed_step_max of the 2-lobe elliptical pair); make's other 12 part files identical.  Where
a seed-002 variant's 1.20 CPU s go now (process clock around each step, four variants): the as-built contact 0.63 (its
compiled track 0.58), the design 0.26 (the driven wheel's lobe 0.17, the driver 0.09), the whole-cycle proof 0.23.

2026-12-05, a new session (2 cores, idle; from d990ae3).  The whole-cycle proof by cyclic symmetry (943c444): over
the whole turn, generated teeth whose outlines repeat under a period's turns to 1e-9 mm at every vertex (the make's
seven pairs of more than one period: 2.6e-14 to 5.7e-14 mm; ``pair_proof.cyclic_mismatch``) have the phases of the
law's first period measured and each later one taken as its like turned; measured whole where a phase needs the
running-position search.  The proof alone, measured whole and so in turn in one process: seed 002 0.226 -> 0.129
CPU s, seed 000 0.320 -> 0.129; what is left of it, cProfile: the outlines' polylines sampled from the B-splines
0.05 s (592 pieces, paid once a variant: the samples go to the contact with the design), the measured period's
sweep 0.03, its crops and outlines 0.02.  Against measuring every phase: te within 3e-15 rad and backlash 1e-13 mm,
but the 3-lobe Fourier pair's 1.5e-10 rad and 1e-8 mm, which the old whole-turn proof showed between its own
periods: its crops are manifold3d booleans, which round each vertex on a fixed grid (a few 1e-9 mm, a vertex's
rounding depending on where it lies).  The variants (least of four, two parts): the seed-002 pair 1.22 -> 1.08 CPU
s, its Fourier form 1.82 -> 1.68.  Where the seed-002 variant's 1.08 s go now (py-spy, ten variants): the contact's
compiled search 47 % (0.50 s), the design 26 % (0.28), the proof 5.5 % (0.06), the contact's Python around the
search 5 %, the pickle round trip of the design to each direction 1.6 %.  Not done: the patterned pieces' samples
taken as the cut lobe's turned (about 0.035 s a variant; the polylines, and so every contact value, would change in
their last digits).  Then, each the same floats (make's 636 files identical to all_19_make_at_cf1e11f.sha256): a
B-spline piece sampled by scipy's evaluation routine itself rather than through a BSpline built each piece
(``Spline._sample``: seed 002's 592 pieces at three tolerances 0.094 -> 0.056 CPU s), and the contact's positions
counted only where a counter listens (``parallel.listening``; both directions 0.654-0.664 -> 0.640-0.645 in one
process).  The variants then: the seed-002 pair 1.03 / 1.02 / 1.03 / 1.03 and 1.02 / 1.04 / 1.03 / 1.02 CPU s, its
Fourier form 1.64 / 1.60 / 1.58 / 1.64.  Where the seed-002 variant's ~1.02 s go (process clock per step): the
contact's compiled search 0.59, the Python around it 0.05, the design 0.27, the proof 0.07, the pickle round trips of
the jobs run in place 0.02, checks and values 0.02.

2026-12-05, a third session (2 cores, idle; b47635b in a worktree against the tree, paired, least of three each).
The as-built contact's refresh bounds each vertex the vertex bound leaves within the slack by its exact distance to
the mate's edges (``contact_reuse._boundary_distance``), and the slack 0.10 -> 0.15 mm: the candidates a pose of the
seed-002 contact 1 142 700 -> 570 034 over 19 604 side searches, the same 186 440 hits; both directions 0.650 ->
0.582 CPU s.  Variants, old -> new over five rounds: the seed-002 pair 1.05 / 1.03 / 1.04 / 1.03 / 1.02 -> 1.00 / 0.98
/ 0.99 / 0.98 / 0.99 CPU s, its Fourier form 1.57 / 1.54 -> 1.48 / 1.51.  The same process gives the same least
within 0.01 s, separate processes within 0.05 (a process's memory layout; the machine itself drifts more).  Tried and
not kept: each run of vertices sorted again on its own as its bound fails (the others kept: 0.634 CPU s against
0.582, the kept runs' candidates aging, twice as many a pose); finer runs (16, 8 vertices: slower); numba's numpy
error model (no change); a finer distance field (960 cells: the variant 0.96-0.99, but make 58.7 -> 59.5 s: each
contact job computes its own).  Inside one direction (captured calls, timed alone): the compiled side searches 37 %,
the refreshes 32 % (76 us each: of ~2 400 window vertices, 77 runs, 15 left to test vertex by vertex, 422 nearest-
vertex searches 23 us, 219 exact distances 10 us), the reuse's tests 31 %.  Then the cache's test holding the runs
far from the contact by a bound of the motion (8adffca; the same answers): both directions -1 %, and the variants,
b47635b -> 8adffca over three rounds: 1.03 / 1.05 / 1.04 -> 0.97 / 1.00 / 0.98 CPU s.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
import tomllib
from pathlib import Path

os.environ["PROPULSOR_JOBS"] = "1"  # one core, as a study's worker runs a variant
for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # one BLAS thread, as the study's workers have it (study/engine.py)

ROOT = Path(__file__).resolve().parents[1]
TARGET_CPU_S = 1.0
WANTED = ("speed_as_built_min", "center_distance_mm")


def variants(part: Path, repeat: int, profile: bool) -> list[float]:
    from propulsor.study.evaluate import evaluate

    base = tomllib.loads(part.read_text(encoding="utf-8"))
    ptype = base.pop("type")
    base.pop("meta", None)
    width = float(base.get("face_width_mm", 20.0))
    row = evaluate(ptype, base, str(part), {"face_width_mm": width}, "proof", WANTED)  # warm-up
    if row["status"] != "ok":
        raise SystemExit(f"{part}: {row['status']}: {row['reason']}")
    times = []
    for k in range(repeat):
        prof = None
        if profile and k == repeat - 1:
            import cProfile

            prof = cProfile.Profile()
            prof.enable()
        t0 = time.process_time()
        row = evaluate(ptype, base, str(part), {"face_width_mm": width + 1.0 + k}, "proof", WANTED)
        times.append(time.process_time() - t0)
        if prof is not None:
            import pstats

            prof.disable()
            pstats.Stats(prof).sort_stats("tottime").print_stats(25)
        if row["status"] != "ok":
            raise SystemExit(f"{part}: {row['status']}: {row['reason']}")
    return times


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("parts", nargs="*", default=["parts/ncg_seed002.toml", "parts/ncg_fourier_seed002.toml"])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--profile", action="store_true")
    a = ap.parse_args(argv)
    for p in a.parts:
        t = variants(ROOT / p, a.repeat, a.profile)
        best = min(t)
        print(f"{p}: CPU s a variant {' / '.join(f'{x:.2f}' for x in t)} (least {best:.2f}; target "
              f"{TARGET_CPU_S:.1f}: {'met' if best <= TARGET_CPU_S else 'not met'})", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
