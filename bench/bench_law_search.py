"""Benchmark of the least-ripple law search (issue 10, acceptance 4): for seeds 000 and 002 the
search over the blend (half-width, hand-over value) and the five catalogue shapers at the part
file's module, under generability, with L within the part file's band of the exact law's.

Target: each search <= 30 s on this machine, and deterministic (run twice, identical result).
Prints the evaluations, the generable points, the least screened ripple and what binds; the
tooth generator then cuts the ranked candidates in turn (`propulsor build`, not timed here).
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TARGET_S = 30.0


def main() -> int:
    from propulsor.gears.catalogue import shaper_diameters, shaper_entry
    from propulsor.gears.law_search import search_law
    from propulsor.gears.noncircular import centre_distance
    from propulsor.laws.walking import WalkingLaw
    from propulsor.params import load_params, read_part_file
    from propulsor.parts import get_part_type

    ok = True
    for name in ("ncg_seed000", "ncg_seed002"):
        part, mapping = read_part_file(ROOT / "parts" / f"{name}.toml")
        p = load_params(get_part_type(part).params_cls, mapping)
        law = WalkingLaw(a=p.a_mm, b=p.b_mm, c=p.c_mm, n=p.driver_turns)
        m, z_H = p.module_mm, p.driven_teeth
        alpha = math.radians(p.pressure_angle_deg)
        shapers = []
        for d0 in shaper_diameters():
            try:
                shapers.append((d0, shaper_entry(d0, m).cutter(alpha)))
            except Exception:
                continue
        L_ref = centre_distance(law, m, z_H)
        t0 = time.perf_counter()
        res = search_law(law, m, z_H, p.driver_shift, shapers, L_ref, p.center_distance_band_mm, alpha)
        t = time.perf_counter() - t0
        again = search_law(law, m, z_H, p.driver_shift, shapers, L_ref, p.center_distance_band_mm, alpha)
        same = again == res
        b = res.best
        print(f"{name}: {t:5.2f} s (target <= {TARGET_S:.0f} s), deterministic {same}; {res.evaluations} laws, "
              f"{len(res.points)} generable points, {len(shapers)} shapers; least screened ripple "
              f"{100 * b.ripple:.3f} % (d0 {b.d0_mm:g} mm, z0 {b.z0}, delta {math.degrees(b.delta):.2f} deg, "
              f"u_h {b.u_h_rel:.5f} u, L {b.L:.4f} mm), binding: {b.binding}")
        ok = ok and same and t <= TARGET_S
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
