"""Benchmark: the road wheel and balancer part builds (seed 004 ch. 2, 7, 8), and their stages.

Each part is built once through the command line in a fresh temporary folder (wall time, the
whole pipeline: calculation, solids, every B-rep / STEP / mesh check, exports).  Then the
balancer's stages are timed on their own in this process: inputs (suspension, beam model,
equal-strength outline), the solid, the sweep meshes and the travel sweep (98 steps × hull +
2 neighbours).  The build runs the sweep in a second process beside the solid checks, so the
build's wall time is less than the sum of its stages.

2026-12-01 (2 cores; manifold3d's min_gap counted and timed in the build of parts/balancer.toml): the travel sweep's
gaps sought where they are cheap first (``checks/motion/sweep3d._Gaps``: within the last step's gap plus 0.25 mm,
and after a step with nothing within the 20 mm window the convex hulls first): 255 min_gap calls 8.07 -> 2.87 CPU s
(the 123 steps with nothing within 20 mm 3.5 -> 0.04 s: the hulls answer; the 97 steps against the hull envelope,
13 mm away, 68 -> 22 ms each: what is left is the boolean min_gap makes before it measures); every gap the same,
bit for bit (the build's 26 files identical).  A cam's 16 spot checks in 3D 0.50 -> 0.12 s.
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def timed(fn, *a, **k):
    t0 = time.perf_counter()
    r = fn(*a, **k)
    return r, time.perf_counter() - t0


def main() -> int:
    from propulsor.cli import main as cli

    rc = 0
    with tempfile.TemporaryDirectory() as tmp:
        for part in ("road_wheel", "balancer"):
            code, t = timed(cli, ["build", str(ROOT / "parts" / f"{part}.toml"), "--out", str(Path(tmp) / part), "-q"])
            print(f"build {part:10s}: {t:7.2f} s wall (exit {code})", flush=True)
            rc = rc or code

    from propulsor.params import load_params, read_part_file
    from propulsor.parts.balancer import BalancerParams, balancer_solid, sweep_mesh, resolve, travel_sweep
    from propulsor.parts.road_wheel import wheel_solids

    f = ROOT / "parts" / "balancer.toml"
    p = load_params(BalancerParams, read_part_file(f)[1])
    m, t_in = timed(resolve, p, f)
    bal, t_sol = timed(balancer_solid, m)
    ws, t_ws = timed(wheel_solids, m.wheel)
    m.extras["wheel_names"] = list(ws)
    t0 = time.perf_counter()
    bm = sweep_mesh(bal, p.sweep_chord_mm)
    wm = [sweep_mesh(s, p.sweep_chord_mm) for s in ws.values()]
    t_mesh = time.perf_counter() - t0
    res, t_sw = timed(travel_sweep, m, bm, wm)
    print(f"balancer stages: inputs + outline {t_in:.2f} s, balancer solid {t_sol:.2f} s, wheel solids {t_ws:.2f} s, "
          f"sweep meshes {t_mesh:.2f} s ({len(bm[1])} + {sum(len(x[1]) for x in wm)} triangles), "
          f"travel sweep {t_sw:.2f} s ({len(res['beta'])} steps)")
    print("travel sweep split: " + ", ".join(f"{k} {v:.2f} s" for k, v in res["timing_s"].items()))
    return rc


if __name__ == "__main__":
    sys.exit(main())
