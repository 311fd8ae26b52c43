"""The 2D sweeps' least distance with and without the searches' memory (checks/motion/nearest.py), on the sweeps
a part build makes.

    python bench/bench_sweep_memory.py [part file ...]     # default: parts/final_drive.toml parts/cam_mover.toml

Builds each part file once (into a temporary folder) with ``sweep_pair`` recorded: its two outlines' loops, the
segment length and the poses of every step.  Then replays every recorded sweep's least-distance steps
(``sweep2d._boundary_distance``, both directions of ``nearest_edge``) twice, in turn: as a build runs them (each
search remembering what the last found for the same two outlines) and with the memory cleared before every
search.  Prints the CPU time a step of each, and whether every answer (distance, both points) is the same
bit for bit.
"""

from __future__ import annotations

import hashlib
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = ["parts/final_drive.toml", "parts/cam_mover.toml"]


def record(part_file: str) -> list:
    """(loops of A, loops of B, segment length, poses of A, poses of B) of every sweep_pair of a build."""
    import propulsor.checks.motion as motion
    from propulsor import policy
    from propulsor.checks.motion import sweep2d
    from propulsor.cli import main as cli

    calls = []
    real = sweep2d.sweep_pair

    def recording(pa, poses_a, pb, poses_b, chord_tol=policy.MOTION_CHORD_TOL_MM, **kw):
        seg = kw.get("max_segment", policy.MOTION_MAX_SEGMENT_MM)
        A, B = sweep2d.outline(pa, chord_tol, seg), sweep2d.outline(pb, chord_tol, seg)
        Ma, _, Mb, _ = sweep2d._pose_pair(poses_a, poses_b)
        calls.append((A.loops, B.loops, seg, Ma, Mb))
        return real(pa, poses_a, pb, poses_b, chord_tol, **kw)

    sweep2d.sweep_pair = motion.sweep_pair = recording
    try:
        with tempfile.TemporaryDirectory() as tmp:
            rc = cli(["build", str(ROOT / part_file), "--out-dir", tmp, "-q"])
    finally:
        sweep2d.sweep_pair = motion.sweep_pair = real
    if rc != 0:
        raise SystemExit(f"{part_file}: build exit {rc}")
    return calls


def replay(calls: list, forget: bool) -> tuple[float, int, str]:
    """CPU s and steps of the recorded sweeps' least distances, and a digest of every answer."""
    from propulsor.checks.motion import sweep2d
    from propulsor.checks.motion.outlines import Outline
    from propulsor.checks.motion.poses import compose_poses, inverse_pose

    digest = hashlib.sha256()
    cpu, steps = 0.0, 0
    for loops_a, loops_b, seg, Ma, Mb in calls:
        A, B = Outline(loops_a, seg), Outline(loops_b, seg)
        t = time.process_time()
        for k in range(len(Ma)):
            if forget:
                A.__dict__.pop("_nearest_memory", None)
                B.__dict__.pop("_nearest_memory", None)
            rel_ba = compose_poses(inverse_pose(Ma[k]), Mb[k])  # as sweep_pair computes them
            d, pa, pb, _, _ = sweep2d._boundary_distance(A, B, Ma[k], Mb[k], rel_ba, inverse_pose(rel_ba))
            digest.update(np.array([d, *pa, *pb]).tobytes())
        cpu += time.process_time() - t
        steps += len(Ma)
    return cpu, steps, digest.hexdigest()


def main(files: list[str]) -> int:
    import os

    os.environ.setdefault("PROPULSOR_JOBS", "1")  # the sweeps in this process, where they are recorded
    from propulsor.checks import kernels

    kernels.warm()
    same = True
    for f in files:
        calls = record(f)
        replay(calls[:1], False)  # grids and caches of the first outlines: not timed
        (t_mem, n, h_mem), (t_none, _, h_none) = replay(calls, False), replay(calls, True)
        same &= h_mem == h_none
        print(f"{f}: {len(calls)} sweeps, {n} steps; least distance a step {1e6 * t_mem / n:.0f} us remembering, "
              f"{1e6 * t_none / n:.0f} us without ({100 * (t_mem / t_none - 1):+.0f} %); answers "
              f"{'identical' if h_mem == h_none else 'DIFFERENT'}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:] or DEFAULT))
