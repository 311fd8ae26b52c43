"""Time the whole fixed-cam part (seed 001; parts/cam_mover.toml): design search, law, outlines,
solids with every shared check, STEP/STL/3MF/DXF/CSV/plots, assembly and the proofs on the
geometry (roller sweep, hub height on the exported shoe, collisions, 3D spot checks).

Run: .venv/bin/python bench/bench_cam_part.py [part file]
Budget (issue 4): the whole part with all files and proofs in <= 30 s.

2026-12-02 (2 cores; issue 40): the cam plate fused with its core and ring, and the leg with its pin, by OCCT's glue
option (``kernel.cq_fuse(touching=True)``: they only touch).  The two fuses of each cam part file, plain and glued in
turn in one process, three rounds (CPU s): cam_linear 1.25 / 0.91 / 0.96 -> 0.42 / 0.45 / 0.43, cam_mover 1.02 /
0.97 / 0.91 -> 0.42 / 0.35 / 0.40, cam_exponential 0.89 / 0.84 / 0.88 -> 0.40 / 0.33 / 0.32, cam_quadratic 0.88 /
0.89 / 0.88 -> 0.32 / 0.40 / 0.37: about 0.55 CPU s a cam part, 2.2 of make's; the solids' BREP text identical, and
make's STEP, STL, 3MF and GLB files.  Where the rest of a cam part goes (py-spy of make, the four cam parts 39.9 CPU s
sampled): the 2D motion sweeps 14.8 (their compiled nearest-edge search 1.0-1.3 s a part; the far bodies' KD-tree
path, 1 320 calls a part at 0.35 ms, and the poses' numpy around them the rest), the files of the solids 7.7, the
design 3.8, the plots 3.5.

2026-12-02 (2 cores; old and new code in one process, in turn): the far bodies' KD-tree path was the grid levels'
gap: bodies 16 mm apart (the shoe and the carrier; 5.1 mm cells) ask for level 0, whose 3 cells (15.4 mm) fall short,
so every step went to the tree.  ``nearest._level_for`` now takes one level coarser where its 3 cells fall short of
1.25 times the last distance: a cam build's tree searches 1 320 -> 1, cam_linear's whole build 6.06 / 6.16 -> 5.53 /
5.75 CPU s (one process, PROPULSOR_JOBS=1), its files identical.  Then the sweep's steps apart in one compiled loop
(``checks/motion/sweep_steps.py``, see bench_final_drive.py).

2026-12-02 (2 cores; parts/cam_mover.toml's sweeps in one process, their 4 313 apart steps replayed, both nearest-edge
searches a step timed alone, in turn, three rounds): the body of more vertices searched only for an answer within the
other way's (``nearest.nearest_edge``'s cap) 0.74 / 0.74 / 0.72 -> 0.54 / 0.56 / 0.53 s; the same answers.

2026-12-05 (2 cores; the session's start 1a90ed6 in a worktree against 284ac06, in turn, three runs each): the nearest
searches skip the grid cells wholly beyond what they look for (``nearest._cell_beyond``) and take cells of a quarter of
the distance (FAR_CELLS 6): cam_mover's motion proofs 0.96 -> 0.57 -> 0.54 CPU s, cam_linear's 0.97 -> 0.58 (their
results identical, sha256); the final drive's pin sweep (bore 110, pin 55: every vertex 27.5 mm from the other body)
1.33 -> 0.98 -> 0.89; the carrier sweep 2.53 -> 2.52 (near mesh: level 0); the seed-002 contact given the same cut:
0.63-0.68 both ways, no gain, not kept.  make from clean: 62.3 s (115.7 + 4.5 CPU s, gauge 1.70) against 64.6 s (117.8
+ 5.9) at the session's start (gauge 1.68); its 636 files identical to bench/hashes/all_19_make_at_9ac9bbf.sha256.
"""

from __future__ import annotations

import json
import sys
import tempfile
import time
from pathlib import Path

from propulsor.cli import main as cli_main

ROOT = Path(__file__).resolve().parents[1]


def main(part: str = str(ROOT / "parts" / "cam_mover.toml")) -> int:
    from propulsor.laws.cam_design import SearchGrid, search_design
    from propulsor.params import load_params, read_part_file
    from propulsor.parts.cam_mover import CamMoverParams

    _, mapping = read_part_file(part)
    p = load_params(CamMoverParams, mapping)
    t0 = time.perf_counter()
    sr = search_design(p.mechanism(), p.limits(), SearchGrid(symmetric=p.symmetric_law), p.return_phase())
    t_search = time.perf_counter() - t0
    print(f"design search alone: {sr.n_evaluated} candidates ({sr.n_feasible} feasible) in {t_search:.2f} s "
          f"-> {sr.law.label() if sr.law else None}  (budget >= 200 in <= 10 s: "
          f"{'OK' if sr.n_evaluated >= 200 and t_search <= 10 else 'EXCEEDED'})")
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "cam_mover"
        t0 = time.perf_counter()
        rc = cli_main(["build", part, "--out", str(out), "-q"])
        wall = time.perf_counter() - t0
        if rc != 0:
            print(f"build failed with exit {rc}")
            return rc
        man = json.loads((out / "manifest.json").read_text())
        d = man["derived"]
        n_files = len(man["files"])
        n_checks = len(man["checks"])
    print(f"whole part {Path(part).name}: {wall:.2f} s wall (search included), {n_files} files, "
          f"{n_checks} checks all passed; law {d['law']}")
    print(f"  ODE error of H {d['H_error_mm']:.2e} mm; FD: profile points {d['fd_profile_points_max_mm']:.2e} mm, "
          f"R (eq. 16) relative {d['fd_profile_R_rel_max']:.2e}")
    print(f"  hub height variation (exported DXF) {d['hub_height_variation_dxf_mm'] * 1e3:.3f} um, "
          f"exact curve {d['hub_height_variation_exact_mm'] * 1e3:.4f} um")
    print(f"  roller: gap to working wall {d['roller_gap_working_mm'][0]:.2e} .. {d['roller_gap_working_mm'][1]:.2e} mm, "
          f"outer wall {d['roller_clearance_outer_mm'][0]:.5f} .. {d['roller_clearance_outer_mm'][1]:.5f} mm, "
          f"overlap {d['roller_overlap_max_mm2']:g} mm^2 over {d['sweep_steps']} steps")
    print(f"  pressure angle {d['gamma_max_deg']:.2f} deg, convex R min {d['R_convex_min_mm']:.2f} mm, "
          f"Hertz {d['sigma_max_support_MPa']:.1f} / {d['sigma_max_return_MPa']:.1f} MPa (support / return)")
    ok = wall <= 30.0
    print("budget (whole part <= 30 s):", "OK" if ok else "EXCEEDED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
