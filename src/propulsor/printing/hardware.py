"""Pins, axles and handles of a kit: diameters a maker can buy, and the hardware that may replace them.

A printed pin's diameter is a standard dowel diameter (ISO 2338 / ISO 8734: 2, 2.5, 3, 4, 5, 6, 8, 10,
12 mm), so that a steel dowel pin or a silver-steel rod of the same size fits the same holes (the
holes are drawn for the pin's diameter with the printer's allowances, whatever it is made of).  A
pin whose room is below the least printable diameter may still be a steel pin: :func:`pin_diameter`
says which.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: dowel pin diameters (mm) sold everywhere
STANDARD_PIN_D = (2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 16.0)
#: dowel pin lengths (mm)
STANDARD_PIN_L = (4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0, 20.0, 22.0, 24.0, 26.0, 28.0, 30.0, 32.0,
                  35.0, 40.0, 45.0, 50.0, 55.0, 60.0, 70.0, 80.0, 90.0, 100.0)
#: least printed pin that does not snap off in use (mm); below it only steel
PRINTED_PIN_MIN_MM = 4.0


def standard_at_most(d: float) -> float | None:
    """The largest standard pin diameter ≤ d (None below 2 mm)."""
    fit = [s for s in STANDARD_PIN_D if s <= d + 1e-9]
    return fit[-1] if fit else None


def pin_diameter(wanted: float, room: float, least: float = PRINTED_PIN_MIN_MM) -> float | None:
    """A pin's diameter: the largest standard diameter ≤ min(wanted, room), at least `least`; raised to
    `least` when `wanted` is smaller and room allows; None when the room holds no pin of `least`."""
    d = standard_at_most(min(max(wanted, least), room))
    return d if d is not None and d >= least - 1e-9 else None


def mm(x: float) -> str:
    """A length as a maker reads it: 0.1 mm (0.01 mm below 1 mm), no trailing zeros."""
    return f"{x:.2f}".rstrip("0").rstrip(".") if abs(x) < 1.0 else f"{x:.1f}".rstrip("0").rstrip(".")


@dataclass(frozen=True)
class Hardware:
    """A bought part that may replace a printed piece (or that the kit needs): what, how many, instead of."""

    what: str
    count: int
    instead_of: str = ""


def dowel(d: float, length: float, count: int, piece: str, use: str) -> Hardware:
    """A steel dowel or rod of diameter d for a printed pin of `length`: the standard length at most that
    long (or the rod cut to length)."""
    fit = [s for s in STANDARD_PIN_L if s <= length + 1e-9]
    ln = f"{fit[-1]:g} mm long (or ⌀{d:g} mm silver-steel rod cut to {mm(length)} mm)" if fit else \
        f"⌀{d:g} mm silver-steel rod cut to {mm(length)} mm"
    what = f"⌀{d:g} mm steel dowel pin, {ln}" if fit else ln
    return Hardware(f"{what} — {use}", count, piece)


def least_scale_for(room_full: float, need: float) -> float:
    """The largest reduction S with room_full / S ≥ need (room in full-size mm)."""
    return room_full / need if need > 0 else math.inf


#: depth of the flat along a printed pin, × its diameter: the pin prints lying on it
PIN_FLAT = 0.1


def side_pin(d: float, length: float):
    """A printed pin of diameter d (axis z, 0 … length) with a flat along its side PIN_FLAT × d deep: it is
    laid on that flat (its largest face once it is longer than 1.25 d), so its layers run along it — a pin
    printed standing breaks between two layers.  Its round part keeps the diameter d for the holes."""
    from ..solids.kernel import box, cut, cylinder

    r = d / 2
    x0 = r - PIN_FLAT * d
    return cut(cylinder(r, 0.0, length), box(r + 1.0 - x0, d + 2.0, length + 2.0, corner=(x0, -r - 1.0, -1.0)),
               name="pin")
