"""Fits measured on the printed pieces (printing/fits.py): each pin against the very hole it goes into.
Each test makes the mutation the check exists for and sees it fail."""

from __future__ import annotations

import dataclasses

import pytest
import trimesh

from propulsor.printing.fits import Fit, Rim, hole_radius, measure, pin_radius
from propulsor.printing.printers import load_printer

P = load_printer("generic")  # clearance 0.25, press 0.05, undersize 0.15


def _plate_with_holes(holes):
    """A 100 × 40 × 6 mm plate with round holes [(x, y, drawn diameter)] (manifold3d's difference)."""
    from propulsor.solids.kernel import manifold

    plate = manifold(trimesh.creation.box(extents=(100.0, 40.0, 6.0)), "plate")
    for x, y, d in holes:
        c = trimesh.creation.cylinder(radius=d / 2, height=10.0, sections=96)
        c.apply_translation((x, y, 0.0))
        plate = plate - manifold(c, "hole")
    m = plate.to_mesh()
    return trimesh.Trimesh(m.vert_properties[:, :3], m.tri_verts)


def _pin(d, sections=96):
    return trimesh.creation.cylinder(radius=d / 2, height=20.0, sections=sections)


def test_radii_are_read_off_the_vertices():
    plate = _plate_with_holes([(-20.0, 0.0, 12.05), (20.0, 0.0, 5.05)])
    assert hole_radius(plate, (-20.0, 0.0)) == pytest.approx(12.05 / 2, abs=1e-5)
    assert hole_radius(plate, (20.0, 0.0)) == pytest.approx(5.05 / 2, abs=1e-5)
    assert pin_radius(_pin(12.0)) == pytest.approx(6.0, abs=1e-5)


def test_unequal_pins_each_press_into_their_own_hole():
    # a 12 mm and a 5 mm pin, each hole drawn pin − 2 × press + undersize: both fits pass
    plate = _plate_with_holes([(-20.0, 0.0, 12.0 - 0.1 + 0.15), (20.0, 0.0, 5.0 - 0.1 + 0.15)])
    meshes = {"base": plate, "pin_a": _pin(12.0), "pin_b": _pin(5.0)}
    a = measure(Fit("a_in_base", "pin_a", "base", (-20.0, 0.0), "press"), meshes, P)
    b = measure(Fit("b_in_base", "pin_b", "base", (20.0, 0.0), "press"), meshes, P)
    assert a.passed and b.passed, (a.message, b.message)
    # mutation: the pins swapped (the smallest pin in the largest hole) fails both ways
    swapped = measure(Fit("a_in_base", "pin_b", "base", (-20.0, 0.0), "press"), meshes, P)
    assert not swapped.passed and "interference -3.4500" in swapped.message
    too_tight = measure(Fit("b_in_base", "pin_a", "base", (20.0, 0.0), "press"), meshes, P)
    assert not too_tight.passed


def test_a_running_fit_fails_when_the_pin_grows_or_the_hole_shrinks():
    plate = _plate_with_holes([(0.0, 0.0, 8.0 + 0.5 + 0.15)])
    fit = Fit("wheel_on_pin", "pin", "wheel", (0.0, 0.0), "running")
    ok = measure(fit, {"wheel": plate, "pin": _pin(8.0)}, P)
    assert ok.passed and ok.value == pytest.approx(0.25, abs=1e-5)
    # mutation: a pin 0.1 mm larger than the hole was drawn for
    assert not measure(fit, {"wheel": plate, "pin": _pin(8.1)}, P).passed
    # mutation: the hole drawn without the undersize allowance
    tight = _plate_with_holes([(0.0, 0.0, 8.0 + 0.5)])
    assert not measure(fit, {"wheel": tight, "pin": _pin(8.0)}, P).passed


def test_a_fit_measured_at_the_wrong_place_fails():
    plate = _plate_with_holes([(20.0, 0.0, 8.65)])
    # the kit's hole position off by 3 mm: the nearest vertices are no longer the hole's circle
    fit = Fit("wheel_on_pin", "pin", "wheel", (23.0, 0.0), "running")
    assert not measure(fit, {"wheel": plate, "pin": _pin(8.0)}, P).passed


def test_a_pin_standing_on_a_larger_piece_is_measured_on_its_own():
    from propulsor.solids.kernel import manifold

    disc = trimesh.creation.cylinder(radius=30.0, height=5.0, sections=96)
    disc.apply_translation((0.0, 0.0, 2.5))
    pin = _pin(6.0)
    pin.apply_translation((15.0, 0.0, 14.9))
    carrier = (manifold(disc, "disc") + manifold(pin, "pin")).to_mesh()
    carrier = trimesh.Trimesh(carrier.vert_properties[:, :3], carrier.tri_verts)
    assert pin_radius(carrier, (15.0, 0.0), (5.0, 24.9), reach=4.0) == pytest.approx(3.0, abs=1e-5)


def _plate_with_slot(x, y0, y1, w):
    """The 100 × 40 × 6 mm plate with a slot of width w along x = const from y0 to y1 (centres)."""
    from propulsor.solids.kernel import manifold

    plate = manifold(trimesh.creation.box(extents=(100.0, 40.0, 6.0)), "plate")
    for y in (y0, y1):
        c = trimesh.creation.cylinder(radius=w / 2, height=10.0, sections=96)
        c.apply_translation((x, y, 0.0))
        plate = plate - manifold(c, "end")
    side = trimesh.creation.box(extents=(w, y1 - y0, 10.0))
    side.apply_translation((x, 0.5 * (y0 + y1), 0.0))
    plate = plate - manifold(side, "slot")
    m = plate.to_mesh()
    return trimesh.Trimesh(m.vert_properties[:, :3], m.tri_verts)


def test_a_pin_in_a_slot_is_measured_off_the_slot_sides():
    # a 5.5 mm slot 10 mm long; the pin presses into its width mid-way (a hole drawn 5.5 prints 5.35)
    plate = _plate_with_slot(0.0, -5.0, 5.0, 5.5)
    meshes = {"sector": plate, "pin": _pin(5.45)}
    fit = Fit("clamp_in_slot", "pin", "sector", (0.0, 1.0), "press", slot=True)
    ok = measure(fit, meshes, P)
    assert ok.passed and "⌀5.350 mm hole" in ok.message, ok.message
    # at the slot's end the round end holds it as well
    assert measure(dataclasses.replace(fit, hole_at=(0.0, 5.0)), meshes, P).passed
    # mutation: read off the vertices, the slot's straight sides are not seen (their vertices are at the
    # ends): mid-way the slot measures wider than it prints and the pin falls loose
    blind = measure(dataclasses.replace(fit, slot=False), meshes, P)
    assert not blind.passed and "interference -" in blind.message, blind.message
    # mutation: the slot drawn 0.2 mm wider (no interference left)
    wide = _plate_with_slot(0.0, -5.0, 5.0, 5.7)
    assert not measure(fit, {"sector": wide, "pin": _pin(5.45)}, P).passed


def _carrier(pins, R=30.0, pin_d=6.0):
    """A disc ⌀2R × 5 mm with round pins [(x, y)] ⌀pin_d standing 10 mm on it, one body."""
    from propulsor.solids.kernel import manifold

    disc = trimesh.creation.cylinder(radius=R, height=5.0, sections=128)
    disc.apply_translation((0.0, 0.0, 2.5))
    body = manifold(disc, "disc")
    for x, y in pins:
        pin = trimesh.creation.cylinder(radius=pin_d / 2, height=10.01, sections=64)
        pin.apply_translation((x, y, 9.995))
        body = body + manifold(pin, "pin")
    m = body.to_mesh()
    return trimesh.Trimesh(m.vert_properties[:, :3], m.tri_verts)


def test_the_wall_between_a_carrier_pins_and_its_rim_is_measured():
    at = [(20.0, 0.0), (-10.0, 17.320508), (-10.0, -17.320508)]
    rim = Rim("pins_on_carrier", "carrier", tuple(at), disc_z=(0.0, 5.0), pin_z=(5.0, 15.0))
    ok = measure(rim, {"carrier": _carrier(at)}, P)
    # 30 − 20 − 3 = 7 mm, less the 128-gon's sagitta (30 (1 − cos(π/128)) = 0.009 mm)
    assert ok.passed and ok.value == pytest.approx(7.0, abs=0.01), ok.message
    # mutation: one pin drawn 6.5 mm farther out (a wrong centre distance): 0.5 mm wall < 0.8 mm
    out = [(26.5, 0.0)] + at[1:]
    moved = measure(rim, {"carrier": _carrier(out)}, P)
    assert not moved.passed and moved.value == pytest.approx(0.5, abs=0.01) and "least at pin 1" in moved.message
    # mutation: the pins grown to ⌀18.8 (the wall 0.6 mm)
    assert not measure(rim, {"carrier": _carrier(at, pin_d=18.8)}, P).passed
    # mutation: the disc drawn ⌀46.6 (the wall 0.3 mm)
    assert not measure(rim, {"carrier": _carrier(at, R=23.3)}, P).passed
    # a pin beyond the rim (its axis outside the disc) fails too
    assert not measure(rim, {"carrier": _carrier([(29.0, 0.0)] + at[1:])}, P).passed
