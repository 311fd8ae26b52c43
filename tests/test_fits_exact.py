"""Fits (printing/fits.py) on hand-made vertex sets whose answers are exact: every field of each check (name,
verdict, value, limit, unit, the whole message), the limits at float equality, pins off the origin, a pin missing
from a carrier, the least wall at another pin than the first.  These are the cases `make mutation MODULE=printing`
found no test for (mutation/README.md); they run in well under a second, without a kernel."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from propulsor.check import Check
from propulsor.printing.fits import (PRESS_MAX_MM, TOL_MM, Fit, Rim, circle_fit, hole_radius, measure, pin_radius,
                                     rim_outline, rim_pins, rim_walls, slot_radius)


def _ring(r, z, at=(0.0, 0.0), n=64, phase=0.0):
    a = phase + 2 * np.pi * np.arange(n) / n
    return np.column_stack([at[0] + r * np.cos(a), at[1] + r * np.sin(a), np.full(n, float(z))])


def _mesh(*parts, edges=None):
    v = np.vstack(parts)
    return SimpleNamespace(vertices=v, edges_unique=np.zeros((0, 2), int) if edges is None else edges)


def _same(c: Check, name, passed, value, limit, unit, message):
    """Every field of the check; value and limit to 1e-9 when they are numbers."""
    assert (c.name, c.passed, c.unit, c.message) == (name, passed, unit, message), c
    for got, want in ((c.value, value), (c.limit, limit)):
        assert got == (pytest.approx(want, abs=1e-9) if isinstance(want, float) else want), c


def _printer(undersize=0.0, clearance=0.25, press=0.05, feature=0.8):
    return SimpleNamespace(hole_undersize_mm=undersize, running_clearance_mm=clearance, press_fit_mm=press,
                           min_feature_mm=feature)


# --- the running and press fits: every field -----------------------------------------------------------------

def test_running_fit_check_in_full():
    hole = _mesh(_ring(4.5, 0.0, at=(20.0, 10.0)), _ring(4.5, 6.0, at=(20.0, 10.0)), _ring(30.0, 0.0))
    pin = _mesh(_ring(4.0, -10.0), _ring(4.0, 10.0))
    fit = Fit("wheel_on_pin", "pin", "wheel", (20.0, 10.0), "running", what="the wheel turns on it")
    c = measure(fit, {"wheel": hole, "pin": pin}, _printer(undersize=0.2))
    _same(c,
        "fit.wheel_on_pin", True, 0.4, 0.25 - TOL_MM, "mm",
        "radial running clearance, measured: ⌀8.000 mm pin in the ⌀8.800 mm hole of wheel as printed (drawn "
        "9.000 mm, 0.2 mm undersize); the wheel turns on it")
    # no `what`: the message ends at the measurement
    bare = measure(Fit("wheel_on_pin", "pin", "wheel", (20.0, 10.0), "running"), {"wheel": hole, "pin": pin},
                   _printer(undersize=0.2))
    assert bare.message.endswith("0.2 mm undersize)")


def test_press_fit_check_in_full():
    hole = _mesh(_ring(3.9, 0.0, at=(-5.0, 7.0)), _ring(3.9, 6.0, at=(-5.0, 7.0)))
    pin = _mesh(_ring(4.0, 0.0), _ring(4.0, 12.0))
    fit = Fit("pin_in_plate", "pin", "plate", (-5.0, 7.0), "press", what="pressed from below")
    c = measure(fit, {"plate": hole, "pin": pin}, _printer())
    _same(c, "fit.pin_in_plate", True, True, True, "",
                      "radial press interference 0.1000 mm (at least 0.05, at most 0.3), measured: ⌀8.000 mm pin in "
                      "the ⌀7.800 mm hole of plate as printed (drawn 7.800 mm, 0 mm undersize); pressed from below")
    bare = measure(Fit("pin_in_plate", "pin", "plate", (-5.0, 7.0), "press"), {"plate": hole, "pin": pin},
                   _printer(press=0.2))
    assert not bare.passed and bare.message.endswith("0 mm undersize)"), bare.message


def test_a_pin_beside_another_pin_on_its_piece_is_measured_on_its_own():
    # two ⌀4 pins 6 mm apart on a disc; the hole's radius 2.25: the neighbour's nearest vertices are 4 mm from the
    # axis, beyond the reach of the hole (radius + 1 mm) and so not this pin's
    disc = [_ring(20.0, 0.0), _ring(20.0, 5.0)]
    pins = [_ring(2.0, z, at=(x, 0.0), n=32) for x in (3.0, -3.0) for z in (5.0, 15.0)]
    carrier = _mesh(*disc, *pins)
    hole = _mesh(_ring(2.25, 0.0, at=(3.0, 0.0)), _ring(2.25, 8.0, at=(3.0, 0.0)))
    fit = Fit("wheel_on_pin", "carrier", "wheel", (3.0, 0.0), "running", pin_at=(3.0, 0.0), pin_z=(5.0, 15.0))
    c = measure(fit, {"carrier": carrier, "wheel": hole}, _printer())
    assert c.passed and c.value == pytest.approx(0.25, abs=1e-9), c.message


@pytest.mark.parametrize("h, p, printer, passed", [
    (0.25, 0.5, _printer(press=0.25 + TOL_MM), True),   # interference exactly the least allowed
    (0.3, 0.6, _printer(press=0.05), True),              # interference exactly PRESS_MAX_MM
])
def test_press_fit_limits_hold_at_equality(h, p, printer, passed):
    assert (p - h) in (printer.press_fit_mm - TOL_MM, PRESS_MAX_MM)  # the float equality the test is about
    c = measure(Fit("f", "pin", "hole", (0.0, 0.0), "press"),
                {"hole": _mesh(_ring(h, 0.0, n=4)), "pin": _mesh(_ring(p, 0.0, n=4))}, printer)
    assert c.passed is passed, c.message


# --- the radii -------------------------------------------------------------------------------------------------

def test_hole_and_pin_radii_off_the_origin():
    plate = _mesh(_ring(2.5, 0.0, at=(3.0, 4.0)), _ring(2.5, 6.0, at=(3.0, 4.0)), _ring(2.5, 0.0, at=(3.0, -4.0)))
    # the hole at (3, 4), not its mirror image
    assert hole_radius(plate, (3.0, 4.0)) == pytest.approx(2.5, abs=1e-12)
    pin = _mesh(_ring(1.5, 0.0, at=(3.0, 4.0)), _ring(1.5, 6.0, at=(3.0, 4.0)))
    assert pin_radius(pin, (3.0, 4.0)) == pytest.approx(1.5, abs=1e-12)


def test_pin_radius_reads_only_its_height_range_and_reach():
    # a ⌀8 pin from z = 5 to 15 standing on a ⌀40 disc, a ⌀10 head from 15.5 to 16 (on a neck the vertex set does
    # not need); a 0.8 mm stub at z 5 .. 5.8
    disc = [_ring(20.0, 0.0), _ring(20.0, 5.0)]
    pin = [_ring(4.0, 5.0), _ring(4.0, 15.0)]
    head = [_ring(5.0, 15.5), _ring(5.0, 16.0)]
    m = _mesh(*disc, *pin, *head)
    assert pin_radius(m, (0.0, 0.0), (5.0, 15.0), reach=6.0) == pytest.approx(4.0, abs=1e-12)
    assert pin_radius(m, (0.0, 0.0), (5.0, 16.0), reach=6.0) == pytest.approx(5.0, abs=1e-12)
    stub = _mesh(*disc, _ring(3.0, 5.0), _ring(3.0, 5.8))
    assert pin_radius(stub, (0.0, 0.0), (5.0, 15.0), reach=5.0) == pytest.approx(3.0, abs=1e-12)
    # the reach is inclusive: a vertex exactly at it belongs to the pin
    assert pin_radius(_mesh(_ring(4.0, 6.0, n=4)), (0.0, 0.0), (5.0, 15.0), reach=4.0) == 4.0


def test_slot_radius_on_short_edges_and_off_the_origin():
    # a round hole of radius 2.75 drawn as a 96-gon (edges 0.18 mm): the least distance to its edges is the
    # apothem r cos(pi/96), not a vertex's r
    n = 96
    ring = _ring(2.75, 0.0, at=(1.0, -2.0), n=n)
    edges = np.column_stack([np.arange(n), (np.arange(n) + 1) % n])
    m = _mesh(ring, edges=edges)
    assert slot_radius(m, (1.0, -2.0)) == pytest.approx(2.75 * math.cos(math.pi / n), abs=1e-12)


def test_circle_fit_is_exact_off_the_origin():
    xy = _ring(3.0, 0.0, at=(12.0, -7.0), n=9, phase=0.3)[:, :2]
    c, r = circle_fit(xy)
    assert c == pytest.approx([12.0, -7.0], abs=1e-12) and r == pytest.approx(3.0, abs=1e-12)
    # a few points on an arc only (a pin's vertices seen from one side)
    c, r = circle_fit(xy[:4])
    assert c == pytest.approx([12.0, -7.0], abs=1e-9) and r == pytest.approx(3.0, abs=1e-9)


# --- a carrier: pins on a disc -----------------------------------------------------------------------------------

AT = (2.0, 3.0)
PINS = ((AT[0] + 20.0, AT[1]), (AT[0] - 10.0, AT[1] + 17.0), (AT[0] - 10.0, AT[1] - 17.0))


def _carrier(pins=PINS, R_bottom=30.0, R_top=30.0, pin_r=3.0, skip=()):
    parts = [_ring(R_bottom, 0.0, at=AT, n=128), _ring(R_top, 5.0, at=AT, n=128)]
    for k, p in enumerate(pins):
        if k in skip:
            continue
        parts += [_ring(pin_r, 5.0, at=p, n=16), _ring(pin_r, 15.0, at=p, n=16)]
    return _mesh(*parts)


def _rim(pins=PINS, what=""):
    return Rim("pins_on_carrier", "carrier", pins, disc_z=(0.0, 5.0), pin_z=(5.0, 15.0), at=AT, what=what)


def test_rim_check_in_full():
    c = measure(_rim(what="the carrier's pins"), {"carrier": _carrier()}, _printer())
    inside = 30.0 * math.cos(math.pi / 128) - 20.0  # pin 1's axis inside the 128-gon (a vertex direction)
    walls = [w for w, *_ in rim_walls(_carrier(), _rim())]
    assert min(walls) == pytest.approx(walls[0]) and walls[0] < min(walls[1:])
    _same(c,
        "fit.pins_on_carrier", True, walls[0], 0.8 - TOL_MM, "mm",
        f"printed wall between each pin and the rim of carrier, least at pin 1: measured ⌀6.000 mm, its axis "
        f"20.000 mm from the disc's axis and {c.value + 3.0:.3f} mm inside the rim (at least 0.8 mm, two line "
        f"widths); the carrier's pins")
    assert c.value + 3.0 == pytest.approx(inside, abs=0.01)
    assert measure(_rim(), {"carrier": _carrier()}, _printer()).message.endswith("two line widths)")


def test_rim_least_wall_at_a_later_pin():
    pins = (PINS[0], (AT[0] - 12.0, AT[1] + 22.0), PINS[2])  # pin 2 at 25.06 mm from the axis
    c = measure(_rim(pins), {"carrier": _carrier(pins)}, _printer())
    assert "least at pin 2" in c.message and "its axis 25.060 mm from the disc's axis" in c.message, c.message
    assert c.value == pytest.approx(min(w for w, *_ in rim_walls(_carrier(pins), _rim(pins))))


def test_a_pin_missing_from_the_carrier_is_named():
    c = measure(_rim(), {"carrier": _carrier(skip=(1,))}, _printer())
    _same(c, "fit.pins_on_carrier", False, False, True, "", "pin(s) [2] of carrier not found above its disc")
    walls = rim_walls(_carrier(skip=(1,)), _rim())
    assert walls[1] is None and walls[0] is not None and walls[2] is not None
    # a pin of three vertices is still a pin; of two it is not
    three = _mesh(*_carrier(skip=(1,)).vertices[None], _ring(3.0, 15.0, at=PINS[1], n=3))
    assert rim_pins(three, _rim())[1] is not None
    two = _mesh(*_carrier(skip=(1,)).vertices[None], _ring(3.0, 15.0, at=PINS[1], n=2))
    assert rim_pins(two, _rim())[1] is None


def test_rim_pins_are_told_apart_by_their_drawn_axes():
    pins = rim_pins(_carrier(), _rim())
    for (c, r), drawn in zip(pins, PINS):
        assert c == pytest.approx(drawn, abs=1e-9) and r == pytest.approx(3.0, abs=1e-9)


@pytest.mark.parametrize("R_bottom, R_top", [(30.0, 29.0), (29.0, 30.0)])
def test_rim_outline_takes_both_faces_of_the_disc(R_bottom, R_top):
    # a chamfered disc: the outline is the larger face's, whichever it is
    hull = rim_outline(_carrier(R_bottom=R_bottom, R_top=R_top), _rim())
    pts = hull.points[hull.vertices]
    assert np.max(np.hypot(pts[:, 0] - AT[0], pts[:, 1] - AT[1])) == pytest.approx(30.0, abs=1e-9)
    # the pins' vertices above the disc are not its outline (their feet, on its face, are)
    assert hull.points.shape[0] == 2 * 128 + 3 * 16
