"""Fits at the cases the mutation run of 2026-11-28 found untested (TEST-GAPS.md X3, X7): a pin with a collar
at its foot, a press fit just beyond the most a printed hole takes."""

from __future__ import annotations

import pytest
import trimesh

from propulsor.printing.fits import Fit, measure
from propulsor.printing.printers import load_printer

P = load_printer("generic")  # clearance 0.25, press 0.05, undersize 0.15


def _plate_with_hole(d):
    """A 60 × 60 × 6 mm plate with a round hole of drawn diameter d at the origin."""
    from propulsor.solids.kernel import manifold

    plate = manifold(trimesh.creation.box(extents=(60.0, 60.0, 6.0)), "plate")
    plate = plate - manifold(trimesh.creation.cylinder(radius=d / 2, height=10.0, sections=96), "hole")
    m = plate.to_mesh()
    return trimesh.Trimesh(m.vert_properties[:, :3], m.tri_verts)


def _cyl(r, z0, z1, sections=96):
    c = trimesh.creation.cylinder(radius=r, height=z1 - z0, sections=sections)
    c.apply_translation((0.0, 0.0, (z0 + z1) / 2))
    return c


def test_a_collar_at_the_pins_foot_is_not_the_pin():  # X3
    # a ⌀8 pin standing on a 5 mm disc, with a ⌀9.6 collar whose top is the disc's face (z = 5): the collar's rim
    # lies within reach of the axis (hole radius 4.25 + 1 mm) but at the face height, not on the pin
    base = trimesh.creation.box(extents=(40.0, 40.0, 5.0))
    base.apply_translation((0.0, 0.0, 2.5))
    carrier = trimesh.util.concatenate([base, _cyl(4.8, 3.0, 5.0), _cyl(4.0, 5.0, 15.0)])
    wheel = _plate_with_hole(8.0 + 0.5 + 0.15)  # running: pin + 2 x 0.25 clearance + the undersize
    fit = Fit("wheel_on_pin", "carrier", "wheel", (0.0, 0.0), "running", pin_z=(5.0, 15.0))
    c = measure(fit, {"carrier": carrier, "wheel": wheel}, P)
    assert c.passed and c.value == pytest.approx(0.25, abs=1e-5), c.message


@pytest.mark.parametrize("interference, ok", [(0.295, True), (0.305, False)])
def test_press_fit_beyond_the_most_a_printed_hole_takes_fails(interference, ok):  # X7
    # hole drawn pin − 2 × interference + undersize: measured (as printed) radius 4 − interference; at most 0.3 mm
    # (radial) before the printed hole splits
    hole = _plate_with_hole(8.0 - 2 * interference + 0.15)
    c = measure(Fit("pin_in_plate", "pin", "plate", (0.0, 0.0), "press"),
                {"plate": hole, "pin": _cyl(4.0, -10.0, 10.0)}, P)
    assert c.passed is ok, c.message
    assert f"interference {interference:.4f} mm" in c.message
