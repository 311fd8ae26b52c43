"""Our whole build of a Fourier-law pair against ncgears 0.3.1 generating the 2D pair of the same law.

    python bench/bench_vs_ncgears.py [--part parts/ncg_fourier_seed002.toml] [--no-elliptical]

ncgears (PyPI, Apache-2.0) runs in a venv of its own OUTSIDE this repository, made once and kept:
``$PROPULSOR_NCGEARS_VENV``, else ``$XDG_CACHE_HOME/propulsor/ncgears-0.3.1-venv``, else
``/tmp/propulsor-ncgears-venv`` (``pip install ncgears==0.3.1`` pulls shapely, sympy, ezdxf, numpy,
scipy); nothing is installed into the project's venv.  ncgears is given the part file's law in its own
form, the driven angle as a function of the driver angle, ``psi(phi) = phi / k + sum_j (c_j cos j phi +
s_j sin j phi)`` (our ``theta`` is its ``phi``), with the driver's teeth, the module and the pressure
angle of the part file; its pair is checked to be real (both outlines, the driven teeth, DXF and SVG
written).  Then our build of the part file runs in a fresh process (``propulsor build ... --out tmp``:
3D solids, proofs and every file).  Each is timed as a whole process: wall seconds, and CPU seconds of
the process and its children (forked workers included).  ``ncg_elliptical.toml`` is timed too (its
target: a whole build <= 10 s).

Run it on an idle machine: the numbers are wall times (issue 40's targets: wall ratio ours / ncgears <= 0.1, CPU ratio
<= 0.15, our build's largest process <= 400 MiB; issue 13's was a wall ratio <= 0.3).
Measured here (2 cores, idle; three runs): ncgears 35.04 / 35.25 / 34.36 s wall (37.60 / 37.67 / 36.27 CPU s);
ours 10.17 / 9.71 / 10.18 s wall (17.20 / 16.96 / 17.30 CPU s): ratio 0.290 / 0.275 / 0.296 (the third began at
load 2.0, just after a test run); ``ncg_elliptical.toml`` 7.61 / 7.52 / 7.50 s wall.
2026-11-30 (2 cores, idle; two runs, 7015ca8): ncgears 27.61 / 26.80 s wall (29.24 / 28.37 CPU s), peak 289 / 289 MiB;
ours 11.03 / 10.78 s wall (17.91 / 17.66 CPU s), peak 651 / 665 MiB: wall ratio 0.399 / 0.402, CPU ratio 0.613 /
0.622; ``ncg_elliptical.toml`` 8.61 s wall.  (The issue's 40 s of ncgears was measured on a busier machine.)  The
peak's floor: ``import cadquery`` alone is 456 MiB resident here (OCP 286 MiB, VTK through OCP.IVtkOCC 126 MiB), so
no process that holds the CAD kernel meets 400 MiB.
2026-11-30, later (2 cores, idle; eb11034): ncgears 25.64 s wall (26.75 CPU s), peak 288 MiB; ours 9.94 s wall
(16.16 CPU s), peak 652 MiB: wall ratio 0.388, CPU ratio 0.604; ``ncg_elliptical.toml`` 7.91 s wall.
2026-11-30, a new session on a slower machine (2 cores, idle; 9199b6c): ncgears 48.85 s wall (51.70 CPU s), peak
289 MiB; ours 16.00 s wall (25.29 CPU s), peak 750 MiB: wall ratio 0.328, CPU ratio 0.489; ``ncg_elliptical.toml``
11.75 s wall.
2026-11-30, the next session (2 cores, idle; 9fdd08d, the pictures' rasteriser compiled): ncgears 43.91 s wall (46.28
CPU s), peak 288 MiB; ours 12.13 s wall (18.84 CPU s), peak 642 MiB: wall ratio 0.276, CPU ratio 0.407;
``ncg_elliptical.toml`` 9.28 s wall.  The peak's floor, measured again: the build's process holds 464 MiB once its
modules are loaded (cadquery is imported with VTK deferred, ``solids/cq_import.py``: 345 MiB with it, OCP alone 286
MiB), before any part data; it peaks at 620-640 MiB at the end of the build.
2026-11-30, a third session (2 cores, idle, the machine ~6 % slower than the last; e9c081e..44f74b8): ncgears 46.61 s
wall (49.52 CPU s), peak 288 MiB; ours 13.84 s wall (21.84 CPU s), peak 665 MiB: wall ratio 0.297, CPU ratio 0.441;
``ncg_elliptical.toml`` 10.31 s wall.  Our Fourier build against the session's start (68c8983), paired, two rounds:
12.76 / 13.02 -> 12.92 / 12.61 s wall, 18.98 / 19.37 -> 18.83 / 18.55 CPU s: this session's gains (the lock-step fits,
the law search kept) do not reach a Fourier law, and its peak grew by 10 MB (the spline samples kept).
2026-11-30, a fourth session (2 cores, the machine ~15 % slower than the last; 8aa9e9d): ncgears 54.01 s wall (56.80
CPU s), peak 288 MiB; ours 16.49 s wall (25.47 CPU s), peak 651 MiB: wall ratio 0.305, CPU ratio 0.448 (the
session's gains, a few per cent of a variant, are within this benchmark's spread).
2026-12-01, a fifth session (2 cores, idle; 9efa157): ncgears 46.83 s wall (49.14 CPU s), peak 285 MiB; ours 14.49 s
wall (22.69 CPU s), peak 662 MiB: wall ratio 0.309, CPU ratio 0.462; ``ncg_elliptical.toml`` 10.42 s wall.  ``make``
from clean, f219260 and the new tree in turn, two rounds: 145.6 / 139.6 -> 141.3 / 126.9 s wall, 270.4 / 259.4 ->
261.3 / 235.8 CPU s (the contact search's nearer window first); the 636 files identical.
2026-12-01, a sixth session (2 cores; 4cf9bba in a worktree, then the new tree, one run each, the machine drifting):
the new tree ncgears 59.96 s wall (63.48 CPU s), ours 15.31 s wall (23.22 CPU s), peak 662 MiB: wall ratio 0.255, CPU
ratio 0.366; 4cf9bba ncgears 50.00 s wall (53.42 CPU s), ours 13.84 s (20.95 CPU s), peak 668 MiB: 0.277, 0.392.
What changed for this build: it imported cadquery with its VTK loaded (the deferral of ``solids/cq_import.py`` was
taken by make's preload and the writer only; the build's first extrusion imported cadquery plainly): 0.79 s of
imports, and user 19.0 / 19.3 -> 17.7 / 17.9 s in consecutive runs; its full garbage collections 0.70 -> 0.38-0.45 s
(``gc.freeze`` of what the build loaded before it starts); its two contacts -10 %.  ``make`` from clean, 4cf9bba and
the new tree in turn, two rounds: 136.9 / 131.6 -> 134.0 / 146.1 s wall, 256.8 / 244.5 -> 251.0 / 273.4 user s (the
changes are a few per cent of make; the drift is more); the 636 files identical.

2026-12-01, a seventh session (2 cores; the machine slow and drifting: a loop of 20 M additions 3.0 s).  Our build
alone, 1e22eb3 in a worktree and the new tree in turn, three rounds (``python -m propulsor.cli build``, wall and
CPU of the process and its children): 17.68 / 19.18 / 18.27 -> 15.06 / 14.94 / 16.42 s wall, 28.36 / 28.92 / 28.33
-> 23.88 / 23.62 / 25.99 CPU s.  What changed: the process leaves without the interpreter's teardown (its garbage
collections over every object: 1.3 s after the report, now 0.12-0.18 s; ``cli.leave``), and the STEP round trip's
read skipped eight healing fixes that change nothing on our files (bench/bench_step_read.py; seven since c086013:
the wires' orientation fix is kept, a CadQuery union's STEP needs it).  This benchmark then,
the machine slower still: ncgears 64.30 s wall (67.58 CPU s), ours 19.23 s (29.17 CPU s), peak 668 MiB: wall ratio
0.299, CPU ratio 0.432.
At the session's end, the machine quieter (e2fb499): ncgears 50.44 s wall (53.56 CPU s), peak 288 MiB; ours 12.65 s
wall (19.68 CPU s), peak 644 MiB: wall ratio 0.251, CPU ratio 0.367 (4cf9bba against an ncgears of the same 50.0 s:
13.84 s, 20.95 CPU s).  ``make`` from clean, 1e22eb3 in a worktree and e2fb499 in turn, two rounds: 151.76 / 135.44
-> 129.37 / 128.64 s wall, 284.46 / 254.25 -> 242.84 / 239.76 user s; the 636 files identical in both trees.

2026-12-01, an eighth session (2 cores; a loop of 20 M additions 1.8 s at the start, 2.8 s at the end).  Changed:
the part files ordered by their size estimates from their values alone, each build vetting its own file in its
forked child (make's head, "checking the part files 0/19 .. 19/19": 4.1 -> 1.2 s and, paired, 5.4 -> 1.4 s of
wall with one core idle); the mesh self-intersection's narrow phase inlined (make's 57 STL files 5.63 -> 3.58
CPU s).  ``python -m propulsor.cli build`` of every part file, 8a13375 in a worktree and the new tree in turn:
142.84 / 128.08 / 170.44 -> 129.72 / 126.36 / 172.77 s wall, 265.81 / 242.30 / 319.20 -> 245.57 / 240.67 / 328.60
user s (the third round on the slowed machine): a few seconds, within the drift.  This benchmark at the end, the
machine slow: ncgears 65.42 s wall (69.14 CPU s), peak 286 MiB; ours 17.74 s wall (27.18 CPU s), peak 651 MiB:
wall ratio 0.271, CPU ratio 0.393.

2026-12-01, a ninth session (2 cores, a fresh venv; a loop of 20 M additions 2.2-3.0 s).  Changed: the whole-cycle
proof's 16 windows a turn instead of 63 (the proofs of make's ten pairs 20.3-20.8 -> 16.2-16.8 CPU s, every value the
same), the STEP half of a solid's files taking the writer's B-rep volume instead of integrating it again (the
volume integration was 4.4 of the 399 s py-spy sampled over make), the animations' caption lines set from each
character's own bitmap (Pillow's pixels; 64 frames of a two-line caption 0.40 -> 0.13-0.21 CPU s).  This
benchmark: ncgears 59.79 s wall (63.08 CPU s), peak 289 MiB; ours 15.99 s wall (23.67 CPU s), peak 765 MiB: wall
ratio 0.267, CPU ratio 0.375.  The peak, measured again for 7dc0106 and the new tree in turn: 763 / 774 -> 777 /
776 MiB (651 last session for 7dc0106's build on the previous machine: the change is the machine or its fresh venv,
not the code).  ``python -m propulsor.cli build`` of every part file, 7dc0106 in a worktree and the new tree in
turn, two rounds: 153.85 / 138.11 -> 160.41 / 152.24 s wall, 290.99 / 264.15 -> 305.64 / 289.76 user s: the
machine's drift (the same code gave 264-306 s) hides the ~10 CPU s measured piece by piece; the 636 files identical.
2026-12-01, a tenth session (2 cores, the machine's speed swinging by up to 70 % between minutes): the cam's motion
read in compiled loops (the support phase's dense output, the return quintics, the shoe's self-crossing test; the cam
design search 5.1-5.4 -> 2.0 CPU s), the captions' degree sign and ellipsis set from their own bitmaps (1.0-1.2 ->
0.1 ms a caption line), the per-tooth load's curvatures fitted together: every output identical.  This benchmark at
the end: ncgears 65.51 s wall (68.88 CPU s), peak 289 MiB; ours 16.13 s wall (24.50 CPU s), peak 773 MiB: wall
ratio 0.246, CPU ratio 0.356.  ``make`` from clean: 159.5 s wall (288.9 user s) at the session's start, 139.8
(264.6) after the cam kernels, 196.1 (360.9) at the end with the machine slow; paired (546969d in a worktree and the
new tree in turn, one round) 162.27 -> 158.90 s wall, 310.30 -> 300.41 user s; the four cam part files alone, two
rounds: 57.64 / 63.31 -> 54.65 / 55.08 user s.
2026-12-01, an eleventh session (2 cores; the Fourier law's array functions compiled and elementwise, its teeth
fitted in lock step, the spline fits' interpolation without scipy's checks): our Fourier build alone, afd7c03 in a
worktree and the new tree in turn, three rounds: 12.34 / 13.10 / 12.93 -> 11.54 / 10.84 / 11.72 s wall, 18.38 /
18.77 / 19.50 -> 16.70 / 15.18 / 16.59 user s (-12 %), peak 796-799 MiB both.  This benchmark at the end, the
machine fast for once: ncgears 45.45 s wall (47.96 CPU s), peak 291 MiB; ours 9.92 s wall (14.69 CPU s), peak 768
MiB: wall ratio 0.218, CPU ratio 0.306; ``ncg_elliptical.toml`` 7.84 s wall (11.74 CPU s).  Earlier in the session,
the machine slower, at 02bfeb1: ncgears 58.92 s (62.18 CPU s), ours 15.79 s (23.26 CPU s): 0.268, 0.374.  ``python -m
propulsor.cli build`` of every part file, afd7c03 in a worktree and the new tree in turn, two rounds: 121.11 / 123.39
-> 124.48 / 106.19 s wall, 228.22 / 232.11 -> 235.74 / 200.57 user s (the drift again larger than the change, a few
CPU s); ``make`` from clean at bdccec4: 121.9 s wall, 229.2 user s; its 636 files those of 02bfeb1 (which changed
only the two Fourier part files' and the gallery's).
2026-12-01, a twelfth session (2 cores; no change kept).  Where our Fourier build's wall goes, its processes' CPU
sampled every 0.25 s (10.1 s wall that run): one core busy for the first 1.0 s (the imports), both from 1.0 to 2.0
(the design forked beside the CAD kernel's import), one from 2.1 to 3.0 (the design's result taken, the solids
started), both from 3.3 to 7.1 (the solids' files and checks in two workers, the proof, the contact in both
directions, the animation), one from 7.35 to 9.9: the main process alone (the as-built values 1.2 s, the load per
tooth about 1.5 s and its plot 0.5 s), its workers done.  About 4.4 core-seconds idle of 20: the wall's lever.  Tried:
the assemblies' STEP written in a forked worker (``parallel.start``) beside the build: no wall gain beyond the
machine's swings (old 9.74 / 9.00 / 10.66 s, new 8.57 / 10.43 / 9.95 s), and the STEP of 7 assemblies changes (a
DIRECTION written ``(1.,0.,-0.)`` is ``(1.,0.,0.)`` after the shapes' pickle round trip): not kept.  Kept (db567b9):
the drive direction's contact job goes on to the load per tooth on its contact (``tooth_load_outputs.contact_and_load``; only
this part file has a load case), so the main process no longer analyses it after the contacts (1-1.5 s of it alone):
our Fourier build, 1dcec08 in a worktree and the new tree in turn, ten pairs: 11.46 / 10.53 / 9.71 / 9.31 / 12.82 /
10.95 / 13.40 / 10.55 / 12.13 / 10.56 -> 10.12 / 11.09 / 9.28 / 9.23 / 11.29 / 10.27 / 10.79 / 10.14 / 12.06 / 9.69 s
wall (8 of 10 faster; mean -0.75 s, -7 %; the last six -1.03 s), the same CPU (the tooth load's pickle back
from the worker: 5 ms).  Its files identical, and ``make``'s 636.  The peak's floor
measured again: the build's main process holds 362 MiB of file-backed pages once OCP is loaded (``RssFile``), its
anonymous memory 202 MiB after the import and 381 MiB at the end; the largest worker 377 MiB.
``make`` from clean (the code of 1dcec08): 114.7 s wall, 215.0 user s, 19 "all checks passed", its 636 files those of
02bfeb1.
2026-12-02, a thirteenth session (2 cores; the meshing: ``bench_tessellate.py``'s note).  This benchmark at 88968cf,
ncgears on a slow minute: ncgears 56.77 s wall (60.11 CPU s), peak 289 MiB; ours 9.04 s wall (14.43 CPU s), peak 680
MiB: wall ratio 0.159, CPU ratio 0.240; ``ncg_elliptical.toml`` 7.90 s wall (11.62 CPU s).  Our Fourier build alone,
13ee34b in a worktree and the new tree in turn, four rounds: 9.21 / 9.08 / 14.36 / 12.05 -> 9.56 / 12.10 / 13.49 /
13.66 s wall (the machine swinging by 50 % within the minute; the meshing's gain here, about 0.5 CPU s of its two
wheels, is below that); ``make``'s build of all part files, paired: about 10 % less CPU (``bench_tessellate.py``).
2026-12-02, a fifteenth session (2 cores, idle; 965c6b0): ncgears 59.84 s wall (62.94 CPU s), peak 288 MiB; ours 12.13 s
wall (19.63 CPU s), peak 651 MiB: wall ratio 0.203, CPU ratio 0.312 (the same code as the last session's 0.159 /
0.240: the machine's minute).  The peak's floor once more, one process importing what a build imports, in turn
(VmRSS): numpy 25 MiB, cadquery with its VTK deferred 363, scipy 410, numba 467, matplotlib 494, trimesh, manifold3d,
ezdxf and Pillow 520, the propulsor modules 532; a build of this part file in one process reaches 560 MiB with its
compiled kernels loaded (5.7 s in) and 708 at the end.  A process that holds the CAD kernel through cadquery starts
at 363 MiB before any data, so 400 MiB needs the CAD kernel in a process of its own with no cadquery in it.
2026-12-02, a sixteenth session (2 cores, idle; 1f6bd2b, the sweeps' second search capped): ncgears 62.19 s wall
(64.70 CPU s), peak 287 MiB; ours 14.71 s wall (23.35 CPU s), peak 645 MiB: wall ratio 0.236, CPU ratio 0.361.  The
run before it gave ours 93.59 s wall, 104.81 CPU s, 889 MiB: the first build after a kernel source changed compiles
every kernel (nbcache), so a benchmark after an edit needs one build first.
2026-12-03, a new machine (2 cores, idle; 781390e: the product code of 9f05cec; ncgears' venv made afresh):
ncgears 53.36 s wall (54.97 CPU s), peak 291 MiB; ours 11.52 s wall (16.66 CPU s), peak 641 MiB: wall ratio 0.216,
CPU ratio 0.303; ``ncg_elliptical.toml`` 9.38 s wall.
2026-12-04 (2 cores, otherwise idle but slow that minute; 4ae55ab): ncgears 58.58 s wall (57.21 CPU s), peak 290 MiB;
ours 14.09 s wall (19.79 CPU s), peak 645 MiB: wall ratio 0.241, CPU ratio 0.346.  The peak's floor measured again
(VmRSS of one process, nothing else): ``import OCP`` 295 MiB (file-backed 184, anonymous 111), ``import cadquery``
467 (its VTK not deferred); the project defers VTK (363).  ``make`` from clean at b368de5, the kernels cached: 95.9 s
wall, 174.3 user + 8.1 sys s, its 636 files identical to ``all_19_make_at_9ac9bbf.sha256``; the first make on this
machine compiled every kernel for its CPU (numba keys its cache by the CPU) in its 45.7 s of loading: 126.9 s wall.
2026-12-04, later (2 cores, idle; a8d0ef8, one run): ncgears 44.60 s wall (46.85 CPU s), peak 289 MiB; ours 13.67 s
wall (14.28 CPU s), peak 654 MiB: wall ratio 0.306, CPU ratio 0.305 (ncgears 24 % faster than in the run above, ours
about as fast: the machine's minute); ``ncg_elliptical.toml`` 6.98 s wall (10.05 CPU s).
2026-12-04, a later session (2 cores, idle; f1f6769): ncgears 35.01 s wall (37.01 CPU s), peak 292 MiB; ours 7.37 s
wall (11.42 CPU s), peak 643 MiB: wall ratio 0.211, CPU ratio 0.308; ``ncg_elliptical.toml`` 6.04 s wall (8.92 CPU
s).  Where our build's wall went (its processes' CPU sampled every 30 ms, 6fe32a6): the main process 5.99 CPU s of
the 7.9 s wall, the workers 5.8 together; one core idle 0-1.1 s (the design's imports), 1.8-2.6 s (the solids made
in the main process) and from 5.8 s on (the main process alone: the as-built values after the drive direction's
contact and load job, the plots, the GLB, the report).  Kept: the assemblies' STEP and the pair's DXF written in a
worker forked as the build asks for them (``writer._beside``: the build's own objects stashed before the fork, not
pickled: the -0.0 that sank the earlier try stays), and the pair's whole-cycle proof with its contact jobs started
before its solids are made: the main process 5.99 -> 4.99 CPU s; the build, aa66e81 and the new tree in turn, six
rounds on a slow machine, 8.09-9.00 -> 7.62-8.79 s wall (medians 8.55 -> 8.27); its files identical.  Then the
step's files in one worker (beb1a4f: one fork for the assembly and both DXF): aa66e81 / the new tree with the solids
first / the new tree, five rounds in turn, mean wall 8.32 / 7.98 / 7.80 s, mean CPU (user + sys) 12.33 / 12.31 /
12.34 s: the wall 6 % less for the same CPU.  The peak's
floor is unchanged (a process holding OCP and numba starts above 460 MiB; the main process's RSS at the end: 433 MiB
file-backed, of which OCP's library 139 and llvmlite's 69, heap 172 and anonymous 137; gc and ``malloc_trim`` at
the end give back 53 MiB).
2026-12-04, a new session (2 cores, idle; 49ffcaa, one run): ncgears 37.45 s wall (39.60 CPU s), peak 288 MiB; ours
7.55 s wall (11.81 CPU s), peak 633 MiB: wall ratio 0.202, CPU ratio 0.298; ``ncg_elliptical.toml`` 6.12 s wall (9.10
CPU s).  Kept (49ffcaa): the program's garbage collector at (100 000, 50, 100) (``policy.GC_THRESHOLDS``, set by
``propulsor`` before its imports): at CPython's 700 the build's main process ran 927 young, 83 middle and 6 full
collections (0.52-0.66 CPU s), its processes 0.87-0.93 CPU s of them, and a collection in a process that has forked
writes the header of every object it scans (pages its workers share, copied); now 6 young, 0.36-0.38 CPU s over the
processes, the main process 5.9-6.1 -> 4.9-5.0 CPU s, its peak 643 -> 648 MiB; the files identical.  Tried and not
kept: glibc's malloc held (mmap threshold 32 MiB, trim 256 MiB, top pad 64 MiB through ``mallopt``): minor faults
300 000 -> 260 000 a build, the CPU within the spread (9.63 / 9.59 -> 9.91 / 9.34 user s), the peak 4 MiB more.
2026-12-04, a later session (2 cores, idle but slow that hour; db01302: the proof's steps compiled): ncgears 38.98 s
wall (40.79 CPU s), peak 287 MiB; ours 8.78 s wall (12.54 CPU s), peak 639 MiB: wall ratio 0.225, CPU ratio 0.307;
``ncg_elliptical.toml`` 6.02 s wall (9.50 CPU s).  ``make`` from clean at db01302 on the same slow hour: 87.7 s wall,
160.6 user s (a core idle only in the first 4 s and the last 3 s: vmstat), its 636 files identical.
2026-12-04, a new session (2 cores, idle; 7070d3e, ``--no-elliptical``, one run): ncgears 35.31 s wall (37.58 CPU s),
peak 290 MiB; ours 6.33 s wall (10.73 CPU s), peak 649 MiB: wall ratio 0.179, CPU ratio 0.286.  No change to this
build's work this session (its law has no sector method: nothing jams); its cores idle 1.3 core-s of the 6.2 s, 0.9
of it in the first 2 s (the part type's imports and the check of the part file, 0.67 CPU s in one process, before
the design forks beside the kernel's import).
2026-12-05, a later session (2 cores, idle; cf02913, the wheels of equal lobes cut as one and patterned): ncgears
33.60 s wall (35.43 CPU s), peak 289 MiB; ours 5.82 s wall (9.32 CPU s), peak 633 MiB: wall ratio 0.173, CPU ratio
0.263 (at 7124cb8 the same day: 0.191 / 0.297); ``ncg_elliptical.toml`` 4.84 s wall (7.76 CPU s).
2026-12-05, a new session (2 cores, idle; a59dbf9, the whole-cycle proof over one period of a pair that repeats): two
runs, ncgears 35.36 / 34.78 s wall (37.20 / 36.58 CPU s), peak 291 / 289 MiB; ours 6.94 / 6.28 s wall (10.67 / 9.86 CPU
s), peak 637 / 636 MiB: wall ratio 0.196 / 0.181, CPU ratio 0.287 / 0.269 (the machine slower than the session
before's, whose same build took 5.82 s); ``ncg_elliptical.toml`` 5.83 s wall (9.10 CPU s).  Our build alone, d990ae3
in a worktree and the new tree in turn, three rounds: 6.06 / 6.32 / 6.24 -> 5.66 / 6.11 / 6.13 s wall, 9.98 / 10.22 /
10.28 -> 9.52 / 10.14 / 10.01 CPU s (user + sys).
2026-12-05, a third session (2 cores, idle; 1dcde18, the contact's candidates bounded by their exact distance to the
mate's edges): ncgears 34.33 s wall (36.07 CPU s), peak 287 MiB; ours 5.60 s wall (9.13 CPU s), peak 648 MiB: wall
ratio 0.163, CPU ratio 0.253; ``ncg_elliptical.toml`` 4.96 s wall (7.83 CPU s).  Where the build's CPU goes (per
step of its main process, CPU / wall s: the proof 0.23 / 0.33, the solids 0.49 / 0.76, the plots 0.71 / 1.63 with
matplotlib's import 0.32 of it, the as-built and load values 0.55 / 0.69; the main process 4.45 CPU s of a 6.3 s wall,
its forked workers 5.3: each wheel's STEP, STL and 3MF with their checks 1.1-1.3, the STEP round trip's read and OCCT
volumes the most of it, each contact direction 0.5-1.1, the design 0.2): what is left is spread over work each file's
proof needs, none of it a tenth of the whole.
2026-12-05, a fourth session (2 cores, idle).  At 8d65361: ncgears 34.79 s wall (36.48 CPU s), ours 6.14 s (9.87 CPU
s), peak 632 MiB: 0.177 / 0.270.  Changed (41583b5): the CAD kernel loads after the as-built contact's jobs are
forked, not while the design is computed (its import, about a second holding the interpreter's lock, held back the
design's result and so the contact's start: 1.94 -> 1.15 s into the build, a core idle meanwhile).  Our build alone,
8d65361's tree in a worktree and the new one in turn, five rounds: 6.15 / 5.63 / 5.85 / 5.84 / 5.73 -> 5.46 / 5.30 /
5.49 / 5.57 / 5.54 s wall, 10.04 / 9.30 / 9.60 / 9.54 / 9.50 -> 9.34 / 9.04 / 9.34 / 9.45 / 9.42 CPU s (the contact's
workers forked from a process without the kernel); the files identical.  This benchmark then: ncgears 35.55 s wall
(37.47 CPU s), ours 6.06 s (9.83 CPU s), peak 646 MiB: 0.170 / 0.262; ``ncg_elliptical.toml`` 5.31 s wall.  What the
ratios cannot go below: bench/bench_kernel_floor.py (the libraries' own work in this build, 5.01 CPU s: 0.92 of the
CPU budget).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
NCGEARS = "ncgears==0.3.1"
#: issue 40's targets: the wall and CPU ratios ours / ncgears, our build's peak memory (the largest process, MiB);
#: and the elliptical build's wall target (s, issue 13)
RATIO_TARGET, CPU_RATIO_TARGET, PEAK_TARGET_MIB = 0.1, 0.15, 400.0
ELLIPTICAL_TARGET_S = 10.0

#: runs in the ncgears venv: generate the pair, write DXF and SVG, print what was made and its times
_NCGEARS_RUN = r"""
import json, sys, time
t0 = time.perf_counter()
import ncgears
t1 = time.perf_counter()
a = json.loads(sys.argv[1])
pair = ncgears.generate_from_transmission(a["expression"], name="pair", teeth=a["teeth"], module=a["module"],
                                          pressure_angle_deg=a["alpha_deg"], output_directory=a["out"])
dxf = pair.export_dxf(a["out"] + "/pair.dxf")
svg = pair.export_svg(a["out"] + "/pair.svg")
t2 = time.perf_counter()
print(json.dumps({"import_s": t1 - t0, "generate_s": t2 - t1, "drive_points": len(pair.drive_outline),
                  "driven_points": len(pair.driven_outline), "drive_teeth": pair.drive_teeth,
                  "driven_teeth": pair.driven_teeth, "center_distance": pair.center_distance,
                  "files": sorted(str(p) for p in (dxf, svg)) + sorted(str(p) for p in pair.directory.iterdir())}))
"""


def venv_dir() -> Path:
    env = os.environ.get("PROPULSOR_NCGEARS_VENV")
    if env:
        d = Path(env)
    elif os.environ.get("XDG_CACHE_HOME"):
        d = Path(os.environ["XDG_CACHE_HOME"]) / "propulsor" / "ncgears-0.3.1-venv"
    else:
        d = Path(tempfile.gettempdir()) / "propulsor-ncgears-venv"
    d = d.resolve()
    if d == ROOT or ROOT in d.parents:
        sys.exit(f"bench_vs_ncgears: the ncgears venv {d} must lie outside the repository {ROOT}")
    return d


def ncgears_python() -> Path:
    """The ncgears venv's interpreter, the venv made (once) where it is missing."""
    d = venv_dir()
    py = d / "bin" / "python"
    ok = py.exists() and subprocess.run([str(py), "-c", "import ncgears; assert ncgears.__version__ == '0.3.1'"],
                                        capture_output=True).returncode == 0
    if not ok:
        print(f"bench_vs_ncgears: making the ncgears venv {d} (once)", file=sys.stderr, flush=True)
        subprocess.run([sys.executable, "-m", "venv", str(d)], check=True)
        subprocess.run([str(py), "-m", "pip", "install", "-q", NCGEARS], check=True)
    return py


#: the peak memory of the last run timed: the largest resident set of any one of its processes (MiB), sampled
PEAK_MIB = [0.0]


def _timed(cmd: list[str], **kw) -> tuple[float, float, subprocess.CompletedProcess]:
    """(wall s, CPU s of the process and its children, the result) of one fresh process; its peak memory, the
    largest resident set any one of its processes (its forked workers included) reached, sampled every 20 ms, in
    :data:`PEAK_MIB`."""
    import threading

    import psutil

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kw)
    peak = [0]

    def sample():
        root = psutil.Process(proc.pid)
        while proc.poll() is None:
            try:
                for q in [root] + root.children(recursive=True):
                    try:
                        peak[0] = max(peak[0], q.memory_info().rss)
                    except psutil.Error:
                        pass
            except psutil.Error:
                pass
            time.sleep(0.02)

    th = threading.Thread(target=sample, daemon=True)
    th.start()
    out, err = proc.communicate()
    wall = time.perf_counter() - t0
    th.join()
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    PEAK_MIB[0] = peak[0] / 2 ** 20
    return wall, cpu, subprocess.CompletedProcess(cmd, proc.returncode, out, err)


def fourier_law(part: Path) -> dict:
    """The part file's Fourier law in ncgears' form, with the driver's teeth, the module and the pressure angle."""
    p = tomllib.loads(part.read_text(encoding="utf-8"))
    if p.get("law") != "fourier":
        sys.exit(f"bench_vs_ncgears: {part} is not a law = \"fourier\" part file")
    k = int(p.get("driver_turns", 4))
    terms = [f"phi/{k}"]
    for key, fn in (("fourier_cos", "cos"), ("fourier_sin", "sin")):
        terms += [f"({float(v)!r})*{fn}({j}*phi)" for j, v in enumerate(p.get(key, []), start=1) if float(v)]
    z_H = int(p.get("driven_teeth", 80))
    return {"expression": " + ".join(terms), "teeth": z_H // k, "driven_teeth": z_H,
            "module": float(p.get("module_mm", 2.5)), "alpha_deg": float(p.get("pressure_angle_deg", 20.0))}


def run_ncgears(py: Path, law: dict, out: Path) -> tuple[float, float, dict]:
    arg = json.dumps({**law, "out": str(out)})
    wall, cpu, r = _timed([str(py), "-c", _NCGEARS_RUN, arg], cwd=str(out))
    if r.returncode:
        sys.exit(f"bench_vs_ncgears: ncgears failed:\n{r.stderr[-2000:]}")
    info = json.loads(r.stdout.strip().splitlines()[-1])
    made = [Path(f) for f in info["files"]]
    real = (info["drive_points"] > 100 and info["driven_points"] > 100 and info["driven_teeth"] == law["driven_teeth"]
            and all(f.is_file() and f.stat().st_size > 0 for f in made)
            and any(f.suffix == ".dxf" for f in made) and any(f.name == "drive.csv" for f in made))
    if not real:
        sys.exit(f"bench_vs_ncgears: ncgears made no real pair: {info}")
    return wall, cpu, info


def run_ours(part: Path, out: Path) -> tuple[float, float]:
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    wall, cpu, r = _timed([sys.executable, "-m", "propulsor.cli", "build", str(part), "--out", str(out), "-q"],
                          env=env, cwd=str(ROOT))
    if r.returncode or not (out / "manifest.json").is_file():
        sys.exit(f"bench_vs_ncgears: our build of {part.name} failed (exit {r.returncode}):\n{r.stderr[-2000:]}")
    return wall, cpu


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--part", type=Path, default=ROOT / "parts" / "ncg_fourier_seed002.toml")
    ap.add_argument("--no-elliptical", action="store_true", help="do not time parts/ncg_elliptical.toml")
    a = ap.parse_args(argv)
    py = ncgears_python()
    law = fourier_law(a.part)
    print(f"law: psi(phi) = {law['expression']}; driver {law['teeth']} teeth, driven {law['driven_teeth']}, "
          f"m = {law['module']:g} mm, alpha = {law['alpha_deg']:g} deg")
    with tempfile.TemporaryDirectory(prefix="bench-ncgears-") as d:
        d = Path(d)
        (d / "ncgears").mkdir()
        n_wall, n_cpu, info = run_ncgears(py, law, d / "ncgears")
        n_peak = PEAK_MIB[0]
        print(f"ncgears 0.3.1 (2D pair, DXF + SVG): wall {n_wall:.2f} s, CPU {n_cpu:.2f} s, peak {n_peak:.0f} MiB "
              f"(import {info['import_s']:.2f} s, generation {info['generate_s']:.2f} s; "
              f"{info['drive_teeth']}/{info['driven_teeth']} teeth, L = {info['center_distance']:.3f} mm, "
              f"{info['drive_points']} + {info['driven_points']} outline points)")
        o_wall, o_cpu = run_ours(a.part, d / "ours")
        o_peak = PEAK_MIB[0]
        ratio = o_wall / n_wall
        print(f"propulsor build {a.part.name} (3D solids, proofs, every file): wall {o_wall:.2f} s, CPU {o_cpu:.2f} s, "
              f"peak {o_peak:.0f} MiB (the largest process; target <= {PEAK_TARGET_MIB:g})")
        print(f"wall ratio ours / ncgears: {ratio:.3f} (target <= {RATIO_TARGET}); CPU ratio {o_cpu / n_cpu:.3f} "
              f"(target <= {CPU_RATIO_TARGET})")
        if not a.no_elliptical:
            e_wall, e_cpu = run_ours(ROOT / "parts" / "ncg_elliptical.toml", d / "elliptical")
            print(f"propulsor build ncg_elliptical.toml: wall {e_wall:.2f} s, CPU {e_cpu:.2f} s "
                  f"(target <= {ELLIPTICAL_TARGET_S:g} s wall)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
