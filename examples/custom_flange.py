"""A propulsor gear in your own CadQuery geometry: the seed-002 driver with a hub flange of yours, exported
to STEP and proved by `propulsor check` (B-rep validity, volume cross-check, the STEP's own mesh).

    python examples/custom_flange.py [OUT_DIR]      (default: ./flange_out)
"""

from __future__ import annotations

import sys
from pathlib import Path

import cadquery as cq

import propulsor
from propulsor.checks.files import check_path


def main(out: Path) -> int:
    gear = propulsor.part(Path(__file__).resolve().parents[1] / "parts" / "ncg_seed002.toml")
    p = gear.params
    driver = gear.solids["driver"]  # a cadquery Shape, mm, axis along z, face 0 … face_width_mm
    flange = (cq.Workplane().workplane(offset=p.face_width_mm)
              .circle(20.0).circle(p.driver_bore_mm / 2 + 2.0).extrude(6.0)
              .faces(">Z").edges("not %LINE").fillet(1.0))
    flanged = cq.Workplane().add(driver).union(flange)
    out.mkdir(parents=True, exist_ok=True)
    step = out / "driver_with_flange.step"
    cq.exporters.export(flanged, str(step))
    solid = flanged.val()
    assert isinstance(solid, cq.Shape)
    print(f"driver {driver.Volume():.1f} mm³ + flange = {solid.Volume():.1f} mm³ -> {step}")
    results = check_path(step)
    bad = [c for checks in results.values() for c in checks if not c.passed]
    for c in bad:
        print(f"FAIL {c.name}: {c.message}")
    print(f"propulsor check: {len(results)} file(s), {'all valid' if not bad else f'{len(bad)} failed check(s)'}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("flange_out")))
