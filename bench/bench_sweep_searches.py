"""Benchmark (issue 40): the 2D sweeps' nearest-edge searches at the steps where the bodies are apart, both ways
searched whole against the body of more vertices searched only for an answer within the other way's
(``nearest.nearest_edge``'s cap, as ``sweep2d._boundary_distance`` and the compiled steps search).

    .venv/bin/python bench/bench_sweep_searches.py [carrier | part file] [--rounds N]

Default ``carrier``: the final drive's carrier sweep (parts/final_drive.toml, 720 steps x 6 meshes, windowed); a part
file: every sweep its proof runs in this process (``PROPULSOR_JOBS=1``).  The sweeps run once as a build runs them,
their apart steps are recorded (the outlines and the relative poses of each call of ``sweep_steps.apart_steps``), then
replayed: at each step both bodies' vertices moved, the search of fewer source vertices whole, then the other whole or
capped at its answer, the memories fresh for each call as in a sweep.  Only the searches are timed (the process's
clock around the two kernel calls), the two ways in turn, ``--rounds`` times; the reported answer of each step
(distance, point, foot: the nearer way's, the first way's on a tie) must be the same both ways.

Measured: see bench_final_drive.py and bench_cam_part.py (2026-12-02).
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import numpy as np


def record(source: str) -> list:
    """The apart steps' calls of the sweeps of `source`: (A, B, rel_ba, rel_ab, first step, first step not taken)."""
    import propulsor.api as api
    from propulsor.checks.motion import sweep2d, sweep_steps

    calls = []
    run = sweep_steps.apart_steps

    def recording(A, B, rel_ba, rel_ab, Ma, Mb, k0, clear, pa, pb):
        k = run(A, B, rel_ba, rel_ab, Ma, Mb, k0, clear, pa, pb)
        calls.append((A, B, rel_ba, rel_ab, k0, k))
        return k

    sweep2d.apart_steps = recording
    try:
        if source == "carrier":
            from propulsor.parts.final_drive.proofs import carrier_sweep

            d = api.part("parts/final_drive.toml").design
            carrier_sweep(d.p, d.ps, d.outlines)
        else:
            api.part(source).prove()
    finally:
        sweep2d.apart_steps = run
    return calls


def replay(calls: list, capped: bool) -> tuple[float, list]:
    """CPU s of the searches and each step's answer (d, point index, foot x, y; the nearer way's)."""
    from propulsor.checks.motion import nearest as nn
    from propulsor.checks.motion.sweep_steps import _move

    cpu, out = 0.0, []
    for A, B, rel_ba, rel_ab, k0, k1 in calls:
        for o in (A, B):
            for key in ("_nearest_memory", "_nearest_hints"):
                o.__dict__.pop(key, None)
        mem_ba, args_ba = nn.search_args(A, B, nn._level_for(A, 0.0))
        mem_ab, args_ab = nn.search_args(B, A, nn._level_for(B, 0.0))
        PB, PA = np.empty((len(B.points), 2)), np.empty((len(A.points), 2))
        b_first = len(B.points) <= len(A.points)
        for j in range(k0, k1):
            _move(rel_ba[j], B.points, PB)
            _move(rel_ab[j], A.points, PA)
            t = time.process_time()
            if b_first:
                r1 = nn._nearest_edge(PB, mem_ba.seed, np.inf, *args_ba)
                r2 = nn._nearest_edge(PA, mem_ab.seed, r1[0] if capped else np.inf, *args_ab)
            else:
                r2 = nn._nearest_edge(PA, mem_ab.seed, np.inf, *args_ab)
                r1 = nn._nearest_edge(PB, mem_ba.seed, r2[0] if capped else np.inf, *args_ba)
            cpu += time.process_time() - t
            if r1[1] >= 0:
                mem_ba.seed = r1[1]
            if r2[1] >= 0:
                mem_ab.seed = r2[1]
            out.append(r1 if r1[0] <= r2[0] else r2)
    return cpu, out


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("source", nargs="?", default="carrier")
    ap.add_argument("--rounds", type=int, default=3)
    a = ap.parse_args(argv)
    os.environ["PROPULSOR_JOBS"] = "1"
    calls = record(a.source)
    print(f"{a.source}: {len(calls)} calls, {sum(k1 - k0 for *_, k0, k1 in calls)} apart steps")
    replay(calls, True)  # warm
    times = {False: [], True: []}
    answers = {}
    for _ in range(a.rounds):
        for capped in (False, True):
            t, answers[capped] = replay(calls, capped)
            times[capped].append(t)
    same = np.array(answers[False]).tobytes() == np.array(answers[True]).tobytes()
    print("both ways whole: " + " / ".join(f"{t:.2f}" for t in times[False]) + " CPU s")
    print("one way capped:  " + " / ".join(f"{t:.2f}" for t in times[True]) + f" CPU s; the same answers: {same}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
