"""Benchmark: z = 50, m = 2 spur gear solid (generated outline + OCCT prism), warm process.

Target (brief §3.2 / solids task): median ≤ 0.3 s for outline + solid.  Prints the median over
RUNS warm runs and the split (outline: envelope + B-spline fit + pattern; solid: edges, wire,
face, prism).  The BRep check is run once, outside the timing.
"""

from __future__ import annotations

import statistics
import sys
import time

from OCP.BRepCheck import BRepCheck_Analyzer

from propulsor.geometry.gear_outline import external_gear_profile
from propulsor.solids.build import extrude_profile

RUNS = 10
TARGET_S = 0.3


def build_once(z=50, m=2.0, x=0.0, width=20.0):
    t0 = time.perf_counter()
    g = external_gear_profile(z, m, x)
    t1 = time.perf_counter()
    solid = extrude_profile(g.profile, width)
    t2 = time.perf_counter()
    return solid, t1 - t0, t2 - t1


def main() -> int:
    build_once()  # warm-up: imports, caches
    outline, solid_t, total = [], [], []
    for _ in range(RUNS):
        solid, a, b = build_once()
        outline.append(a)
        solid_t.append(b)
        total.append(a + b)
    valid = BRepCheck_Analyzer(solid.wrapped).IsValid()
    med = statistics.median(total)
    print(f"z=50 m=2 spur gear solid: median {med * 1e3:.1f} ms over {RUNS} warm runs "
          f"(outline {statistics.median(outline) * 1e3:.1f} ms, solid {statistics.median(solid_t) * 1e3:.1f} ms); "
          f"faces {len(solid.Faces())}, BRep valid {valid}; target <= {TARGET_S * 1e3:.0f} ms")
    return 0 if (valid and med <= TARGET_S) else 1


if __name__ == "__main__":
    sys.exit(main())
