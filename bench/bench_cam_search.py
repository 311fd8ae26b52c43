"""Time the design search of the fixed cam (seed 001; propulsor.laws.cam_design).

Run: .venv/bin/python bench/bench_cam_search.py [repeats]
Budget (issue 4): >= 200 candidates in <= 10 s.

2026-12-01 (issue 40; 2 cores, one busy at times; the old tree (546969d) in a worktree and the new one in turn, wall
s of the search, best of 3): the support phase's dense output, the return quintics and the shoe's self-crossing test
compiled, the return's KKT matrix held (laws/cam_kernels.py, every value bit for bit): 5.92 / 5.68 s (22.50 / 21.61
ms a candidate) -> 2.45 / 2.09 s (9.32 / 7.93 ms); one cam_motion 7.7 -> 5.1 ms (the kernels now loaded before it is
timed).  The same search in CPU s a process, paired twice:
5.42 / 5.11 -> 1.97 / 2.02.  What is left: the least-pressure-angle search's 8-norm (numpy's arctan2 and power, kept
for their bits), the support phase's integration (scipy's DOP853 steps) and the shoe tables.
"""

from __future__ import annotations

import sys
import time

from propulsor.laws.cam_design import search_design
from propulsor.laws.cam_motion import CamMechanism, CurvatureLaw, cam_motion


def main(repeats: int = 2) -> int:
    cam_motion(CamMechanism(), CurvatureLaw("quadratic", 0.017), estimate_error=False)  # the kernels loaded
    t0 = time.perf_counter()
    for _ in range(20):
        cam_motion(CamMechanism(), CurvatureLaw("quadratic", 0.017), estimate_error=False)
    t_one = (time.perf_counter() - t0) / 20
    times = []
    res = None
    for _ in range(repeats):
        t0 = time.perf_counter()
        res = search_design()
        times.append(time.perf_counter() - t0)
    best = min(times)
    print(f"cam_motion (support ODE + return closure): {1e3 * t_one:.2f} ms")
    print(f"search_design: {res.n_evaluated} candidates, {res.n_feasible} feasible, "
          f"best of {repeats}: {best:.3f} s ({1e3 * best / res.n_evaluated:.2f} ms/candidate), "
          f"all: {', '.join(f'{t:.3f}' for t in times)} s")
    print(f"chosen: {res.reason}")
    ok = res.n_evaluated >= 200 and best <= 10.0
    print("budget (>= 200 candidates in <= 10 s):", "OK" if ok else "EXCEEDED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else 2))
