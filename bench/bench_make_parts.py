"""The 12 part builds of `make`, old against new, side by side in one run (issue 13).

    python bench/bench_make_parts.py [OLD_REV] [NEW_REV]     # defaults: 6b72d13 (issue 13's baseline:
                                                             # main when it was written) and the working tree

Each revision's source tree is exported (`git archive`) to a temporary folder; every part file of the
new tree is built with each tree's `propulsor build` (the installed venv's interpreter, the tree's
`src/` first on PYTHONPATH), old and new alternating part by part so that both see the same machine.
Then the new tree builds the same part files as its `make` does from clean: one `propulsor build` of all
of them (the builds side by side on the machine's cores), timed whole; the old `make` ran one process per
part file in sequence, so its time is the old column's total.
Prints, and writes to bench/results/make_parts.md, the wall time of every build, the totals and the
old/new ratio.  Targets: new `make` <= 100 s, every part <= 20 s, old/new >= 2.

2026-12-02 (2 cores; every part file in one ``propulsor build``, the session's start 74af1b0 in a worktree against
d946e29): make-like runs, in turn, 142.8 / 163.4 s wall (268 / 306 user s) old, 171.3 / 143.0 (316 / 268) new; the two
trees side by side, one core each (PROPULSOR_JOBS=1, the same minutes for both), 273.3 and 274.8 user s.  The
machine's swings (one part alone, the two trees side by side: 21.7 / 26.5 / 22.7 against 25.9 / 24.2 / 22.7 CPU s)
are larger than the session's changes, whose parts were measured in one process, old and new in turn (the plots'
single draw 173 -> 139 ms a line plot, the cams' grid level -0.5 CPU s a cam part, the final drive's carrier sweep
-25 %: bench_cam_part.py, bench_final_drive.py).

2026-12-04 (2 cores, nearly idle; each part file built alone by the program, ``propulsor build <file>``, timed by GNU
time, user + sys CPU s / wall s, at ee2628f): balancer 12.35 / 9.08, cam_exponential 5.91 / 4.54, cam_linear 6.10 /
4.69, cam_mover 7.65 / 6.30, cam_quadratic 6.00 / 4.63, final_drive 12.47 / 7.26, final_drive_thesis 15.93 / 9.66,
ncg_elliptical 8.77 / 5.31, ncg_elliptical_2lobe 8.99 / 5.36, ncg_fourier_3lobe 7.82 / 4.90, ncg_fourier_seed002 10.56
/ 6.07, ncg_pitch_curve 7.78 / 4.68, ncg_seed000 13.94 / 8.28, ncg_seed000_table 19.79 / 11.63, ncg_seed002 11.47 /
7.02, ncg_seed002_table 17.62 / 10.09, ncg_table 9.18 / 5.46, polysector 12.03 / 7.50, road_wheel 4.25 / 3.27. The two
sector tables' pairs stood out: their papers' teeth jam (seed 000's table at phase 36 of 384, seed 002's at 0 of 320),
so they have no transmission as built, yet the contact started in two workers ahead of the whole-cycle proof ran to its
end (9 CPU s each) and was dropped after it. Now the proof stops it at its first jammed phase and the other tooth
method's comparison takes the freed worker beside the rest of the proof (5934d5b, 93a0ccf). Alone (``python -m
propulsor.cli build``), ee2628f and 742d749 (the contact stopped at the jam: 5934d5b) in turn, two rounds:
ncg_seed000_table 11.65 / 11.59 -> 10.06 / 9.95 s wall (18.65 / 18.61 -> 12.71 / 12.60 user s), ncg_seed002_table 10.53
/ 10.89 -> 8.45 / 8.00 (17.37 / 17.90 -> 10.18 / 9.51); then 93a0ccf (the comparison beside the proof), one run each:
8.80 s wall (12.40 user s) and 7.81 (9.90). Their 56 files identical to bench/hashes at each step. ``make`` is not
changed by it: its builds run side by side with no worker free, so the contact was never started ahead there and a
jammed pair computes none.

2026-12-05 (2 cores; from 3a2ad4d, the machine's gauge, bench_variant.py's least, 1.64-1.83 over the session): make from
clean 67.1 s (121.8 + 5.8 CPU s) at 1.68, 61.5 s a few minutes later (idle 4.0 core-s: 2.7 in the first 4 s, the
batch's imports, 0.6 at the end), 66.9 at 1.83.  perf over a whole make, all processes, by library: Python 19 %, numba's
kernels 15, manifold3d 10 (Clipper2's BuildIntersectList and DoTopOfScanbeam 5.4: the least-overlap searches and the
crops), numpy 9, libc 8 (malloc and free 4), the kernel 7, PIL 3.6, OCCT's STEP libraries 5.5.  py-spy (100 Hz, 13 253
samples), by part type: the noncircular pairs 56 CPU s (their solids' files and checks 21.5, about 1.1 s a wheel; the
proofs 16.4; the other tooth method 6.1), the final drives 17.4, the cams 12.0, the polysector 8.9, the balancer 8.6.
By function of ours (with what it calls): save_plot 7.4, read_step 7.3 (the round trip: parse and transfer about
half each), the apart sweep steps 7.1 (cam_mover's 2.9, the final drives' carrier and pin sweeps 4.0), the
least-overlap's Clipper overlaps 5.9, the contact 5.4, write_assembly_step 4.9, write_step 3.8, GIF encoding 3.5.
Looked at and left: the 52 least-overlap overlaps sampled from ncg_seed000_table, turned 90 deg first (Clipper's
scan line across the teeth): 0.96 -> 0.73 ms each, the areas 2e-13 relative apart, so the Brent searches' paths and
every jammed phase's reported offset would move (not bit for bit); the imports before the first fork 2.0 s (OCP 0.58,
numpy.f2py 0.056 and numpy.ma 0.016 through scipy's array API, networkx 0.07 through trimesh, casadi 0.015 through
cadquery.assembly): libraries' own; the pins' sweeps (bench_final_drive.py) and the round trip's healing
(bench_step_read.py).  The mesh self-intersection check (4.3 CPU s of make: 57 meshes, 18.5 million pairs of
overlapping boxes, the caps' long coplanar triangles 45 % of them): the box tree's last level and the narrow phase
fused, each leaf pair decided as found instead of all written out first (the same count and first pairs, on every
mesh of make merged and as written, 171 cases): 2.96 -> 3.95 CPU s with the narrow phase called per pair (numba's
reference counts on its array arguments), 2.86 / 2.86 -> 2.86 / 2.87 batched 4 096 at a time: the pairs' arrays
were not the cost (the pairs' decisions, about 150 ns each, are); reverted.

2026-12-05, a new session (2 cores; from 0404b16).  The least-overlap searches of jammed phases (the sector tables'
pairs and the other tooth method's sector teeth): their crops were cut to discs about the axes (``_LensCrops``: 4 862
driver and 4 245 driven vertices an overlap in ncg_seed000_table), now to the sectors about each axis that hold where
the two bodies' polar envelopes meet over the offsets searched (``pair_proof._MeetCrops``,
``checks.motion.outlines.PolarEnvelope``: 3 271 / 2 531), the warm Brent search taking the cuts of its quarter span (3
111 / 2 223 on average over both spans).  In one process, CPU s, the PairProof arrays identical (sha256): the proof of
ncg_seed000_table 4.17 -> 3.05 -> 2.58-2.83, ncg_seed002_table 3.16 -> 2.57 -> 2.39-2.43, the comparisons of seed 000
and seed 002 1.64 -> 1.24 -> 1.18-1.20 and 1.13 -> 0.97 (a CI run on both cores during the last numbers).  Tried and
not kept: the driver cut by the meeting region itself (offset 0.05 mm): its overlaps 1.40 -> 0.77 s, but the areas not
bit for bit (the Brent searches took other paths: 3 750 evaluations against 3 748); spares of 0 / 0.2 / 1 mm and 0 /
0.005 / 0.03 rad, and 360 / 720 / 2 048 envelope bins: within the spread.  Also the batch draws one figure before it
forks (``plots.warm``): a forked build's first figure 108-117 -> 90-109 ms, the same pixels. make from clean, its 636
files identical to bench/hashes/all_19_make_at_9ac9bbf.sha256 after each step: before, 66.3 s (120.0 + 5.4 CPU s) at
gauge 1.66-1.73 and 68.5 s (125.8 + 4.8) at 1.74-1.76; after, 63.1 s (115.8 + 4.5) at 1.67-1.68, 64.6 s (118.1 + 5.0)
at 1.68-1.76 and 63.3 s (116.7 + 4.6) at 1.67-1.68 (the gauge: bench_variant.py's least, 1.46-1.60 on quiet minutes).
py-spy over a whole make: ``_overlap_at``'s own share 4.0 -> 2.8 %.  Looked at and left: the polysector's start tests
and the proofs' overlapping sweep steps take one boolean a pose (no cut reused over evaluations: a cut would cost what
it saves); glibc's malloc thresholds (mmap 32 MiB, trim 256 MiB, top pad 64 MiB) for one pair's build: faults 320 000
-> 284 000, CPU within the spread.

2026-12-05, a third session (2 cores; from 59c33e7; gauge, bench_variant.py's least, 1.65-1.71).  make from clean at
the start: 63.7 s wall (115.8 + 6.2 CPU s).  The four cam part files share their carrier, leg and roller and the two
final drives their carrier and sun, byte for byte (sha256 of their STEP): eleven solids whose files and checks each
build made again (in a build's forked worker, the batch's modules loaded: the final drive's carrier 0.57 CPU s, its
sun 0.43, the cam's carrier 0.20, leg 0.08, roller 0.09 a build; 2.1 s in all.  A first measurement in a fresh
process had put the cam's carrier at 1.13 s: its first mesh check loaded the compiled kernels).  Now the batch
keeps each solid's two halves (its STEP and checks; its STL, 3MF, picture, mesh checks and arrays) under a digest
of its binary B-rep, name, genus and volume, and a later build's job takes them
(``parts/solid_cache.py``): 20 halves taken in make (every shared one but the final drives' carrier mesh, made by both
at once).  make from clean: 60.6 / 60.8 / 61.6 / 59.9 s wall (110.1-113.1 user + 4.7-5.6 sys) at gauge 1.66-1.71;
with the halves kept by hard links instead of copies, 59.5 / 59.5 s (109.3 / 109.2 user + 4.4 / 4.7 sys) at 1.66-1.69;
the 636 files identical to bench/hashes/all_19_make_at_9ac9bbf.sha256 after each.  What is left idle (/proc/stat,
0.1 s samples): 2.4 core-s in the first 2.3 s (the batch's imports: OCP's 0.54 s and the others hold the interpreter's
lock, so a thread importing beside them gains nothing, 1.62-1.74 s either way) and 1.4 in the last 1.5 s (the road
wheel alone, then the gallery).  Also the animations' repeated text lines from one mask each (bench_animation.py).
Later, the machine slower (gauge 1.74-1.80), with and without the shared solids in turn (a local switch, not kept):
61.66 / 61.55 s wall (112.45 / 112.54 user + 4.7 sys) against 63.36 / 62.82 (116.23 / 114.86 + 4.7-5.0): 1.5 s of
wall and 2.3-3.8 user s.  So make's 59.5 s above was the shared solids and a quiet minute together.
2026-12-05, later (2 cores, idle): the generated pairs' wheels of equal lobes cut as one lobe and patterned (cf02913;
bench_variant.py).  make from clean, the old tree (PYTHONPATH to a worktree of 7124cb8) and the new in turn, two
rounds: 60.42 / 59.51 s wall (110.87 / 108.89 user + 4.8 / 4.7 sys) against 57.55 / 57.45 (104.90 / 104.97 user +
4.8 / 4.6 sys): -2.5 s wall, -5 user s.  The seven pairs of laws with lobes changed in their last digits (see
bench_variant.py); the new list bench/hashes/all_19_make_at_cf02913.sha256, every other file as at 9ac9bbf; two makes
of the new tree gave the same 636 files.
2026-12-05, a new session (2 cores, idle): the whole-cycle proof of a pair that repeats measured over its law's first
period (943c444; bench_variant.py).  make from clean, the old tree (PYTHONPATH to a worktree of d990ae3) and the new in
turn, two rounds: 59.96 / 58.18 s wall (111.01 / 106.74 user + 4.5 / 4.3 sys) against 57.71 / 57.51 (105.70 / 105.18
user + 4.4 / 4.6 sys): -1.5 s wall, -3 user s.  What changed: the seven pairs of more than one period's
transmission.csv and anim_pair.csv in their last digits, seed 002's animation (its caption's place of least backlash:
135 -> 315 deg, a tie one period apart), the 3-lobe Fourier pair's transmission-error plot (35 pixels), every pair's
report (the proof's note says how its phases were measured) and manifest; the new list
bench/hashes/all_19_make_at_cf1e11f.sha256, every other file as at cf02913; two makes of the new tree gave the same
636 files.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "bench" / "results" / "make_parts.md"
OLD_DEFAULT = "6b72d13"
TOTAL_TARGET_S, PART_TARGET_S, RATIO_TARGET = 100.0, 20.0, 2.0


def export(rev: str | None, dest: Path) -> Path:
    """The tree of `rev` (None: the working tree's src/ and parts/ as they are) in dest."""
    if rev is None:
        return ROOT
    dest.mkdir(parents=True)
    data = subprocess.run(["git", "archive", rev], cwd=ROOT, capture_output=True, check=True).stdout
    tar = dest / "src.tar"
    tar.write_bytes(data)
    with tarfile.open(tar) as t:
        t.extractall(dest, filter="data")
    tar.unlink()
    return dest


def build(tree: Path, part: Path, out: Path) -> tuple[float, int]:
    env = dict(os.environ, PYTHONPATH=str(tree / "src"))
    env.pop("MAKEFLAGS", None)
    t0 = time.perf_counter()
    r = subprocess.run([sys.executable, "-m", "propulsor.cli", "build", str(tree / "parts" / part.name), "--out",
                        str(out)], cwd=tree, env=env, capture_output=True, text=True)
    return time.perf_counter() - t0, r.returncode


def build_all(tree: Path, parts: list[Path], folder: Path) -> tuple[float, int]:
    """`make`'s build of the part files from clean in the new tree: one command, into folder/output."""
    import shutil

    (folder / "parts").mkdir(parents=True)
    for part in (tree / "parts").glob("*.toml"):
        shutil.copy2(part, folder / "parts" / part.name)
    env = dict(os.environ, PYTHONPATH=str(tree / "src"))
    env.pop("MAKEFLAGS", None)
    t0 = time.perf_counter()
    r = subprocess.run([sys.executable, "-m", "propulsor.cli", "build", *(f"parts/{p.name}" for p in parts),
                        "--depfile-dir", "output/.deps", "-q"], cwd=folder, env=env, capture_output=True, text=True)
    return time.perf_counter() - t0, r.returncode


def main(argv: list[str]) -> int:
    old_rev = argv[1] if len(argv) > 1 else OLD_DEFAULT
    new_rev = argv[2] if len(argv) > 2 else None
    parts = sorted((ROOT / "parts").glob("*.toml"))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        old, new = export(old_rev, tmp / "old"), export(new_rev, tmp / "new")
        for part in parts:
            if not (old / "parts" / part.name).is_file():
                continue
            t_old, rc_old = build(old, part, tmp / "out_old" / part.stem)
            t_new, rc_new = build(new, part, tmp / "out_new" / part.stem)
            rows.append((part.stem, t_old, rc_old, t_new, rc_new))
            print(f"{part.stem:22s} old {t_old:6.1f} s (exit {rc_old})   new {t_new:6.1f} s (exit {rc_new})", flush=True)
        t_make, rc_make = build_all(new, [ROOT / "parts" / f"{r[0]}.toml" for r in rows], tmp / "make_new")
        print(f"new make (one command, {len(rows)} part files): {t_make:.1f} s (exit {rc_make})", flush=True)
    tot_old, tot_new = sum(r[1] for r in rows), sum(r[3] for r in rows)
    worst = max(rows, key=lambda r: r[3])
    ok = t_make <= TOTAL_TARGET_S and worst[3] <= PART_TARGET_S and tot_old / t_make >= RATIO_TARGET
    load = os.getloadavg()[0]
    lines = ["# The part builds of `make`, old against new", "",
             f"Measured {time.strftime('%Y-%m-%d %H:%M')} (`python bench/bench_make_parts.py {old_rev} "
             f"{new_rev or 'working tree'}`), load average at the end {load:.2f}; targets: total <= "
             f"{TOTAL_TARGET_S:g} s, every part <= {PART_TARGET_S:g} s, old/new >= {RATIO_TARGET:g}.", "",
             "| part | old s | new s | old/new |", "|---|---:|---:|---:|"]
    lines += [f"| {n} | {a:.1f}{'' if ra == 0 else f' (exit {ra})'} | {b:.1f}{'' if rb == 0 else f' (exit {rb})'} | "
              f"{a / b:.2f} |" for n, a, ra, b, rb in rows]
    lines += [f"| **total** | **{tot_old:.1f}** | **{tot_new:.1f}** | **{tot_old / tot_new:.2f}** |", "",
              f"`make` from clean: old (one process per part file, in sequence) {tot_old:.1f} s; new (one "
              f"`propulsor build` of the {len(rows)} part files, side by side) {t_make:.1f} s"
              f"{'' if rc_make == 0 else f' (exit {rc_make})'}; old/new **{tot_old / t_make:.2f}**.", ""]
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text("\n".join(lines) + "\n")
    print(f"total old {tot_old:.1f} s, new {tot_new:.1f} s, old/new {tot_old / tot_new:.2f}; new make {t_make:.1f} s, "
          f"old/new make {tot_old / t_make:.2f}; slowest new "
          f"{worst[0]} {worst[3]:.1f} s; {'targets met' if ok else 'targets missed'}; table in "
          f"{OUT.relative_to(ROOT)}")
    return 0 if all(r[2] == 0 and r[4] == 0 for r in rows) and rc_make == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
