"""A loop over modules reading design values: the planetary final drive of the 50 t carrier (seed 004
ch. 4) at modules 8, 9 and 10 mm — operating centre distance, working pressure angle and contact ratios.
Only the design is computed (no solids, no files): a fraction of a second per variant.

    python examples/sweep_module.py
"""

from __future__ import annotations

import math

import propulsor


def main() -> list[dict[str, float]]:
    rows = []
    print(f"{'m mm':>6} {'a_w mm':>9} {'alpha_w deg':>12} {'eps_a sun-planet':>17} {'eps_a planet-ring':>18}")
    for m in (8.0, 9.0, 10.0):
        part = propulsor.part("planetary_final_drive", module_mm=m)
        ps = part.design.ps  # gears.planetary.PlanetarySet: the ISO 21771 sheet of both meshes
        row = {"module_mm": m, "a_w_mm": ps.a_w, "alpha_w_deg": math.degrees(ps.mesh_sun_planet.alpha_w),
               "epsilon_alpha_sun_planet": ps.epsilon_alpha_sun_planet,
               "epsilon_alpha_planet_ring": ps.epsilon_alpha_planet_ring}
        rows.append(row)
        print(f"{m:6.1f} {row['a_w_mm']:9.3f} {row['alpha_w_deg']:12.4f} {row['epsilon_alpha_sun_planet']:17.4f} "
              f"{row['epsilon_alpha_planet_ring']:18.4f}")
    return rows


if __name__ == "__main__":
    main()
