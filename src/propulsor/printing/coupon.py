"""The clearance test coupon: print it first, and read off the allowances the maker's printer holds.

A bar with five holes for its ⌀5 mm test pin, drawn with a radial clearance of −0.1, 0, +0.1, +0.2 and
+0.3 mm (plus the profile's hole undersize, as every hole of the kit), and five slots for its 3 mm
key, each wider than the key by the profile's backlash −0.1 … +0.3 mm (a tooth in its tooth space).
The holes and slots run from the notched end of the bar.  What each outcome means, and the ``--set``
that prints the next kit to fit, is :func:`advice`.
"""

from __future__ import annotations

from .hardware import side_pin

#: the five steps (mm): radial clearance of the holes; the slots' extra width over the profile's backlash
STEPS = (-0.1, 0.0, 0.1, 0.2, 0.3)
PIN_D, PIN_L, KEY_W, KEY_T, KEY_L = 5.0, 20.0, 3.0, 2.0, 24.0
#: the bar: thickness, the holes' and slots' pitch, the slots' depth, and the bar beyond the first and last hole (the
#: notch's corner clear of the first hole): 2 × 6 + 4 × 11 = 56 mm long, so that the coupon plate fits an 80 × 80 mm
#: bed inside its margins (policy.PLATE_MARGIN_MM: 64 mm left)
BAR_T, PITCH, SLOT_DEPTH, BAR_END = 4.0, 11.0, 8.0, 6.0


def bar_length() -> float:
    """The bar's length (mm): its ends and the steps' pitches."""
    return 2 * BAR_END + PITCH * (len(STEPS) - 1)


def coupon_pieces(printer):
    """[Piece] of the coupon: the bar, the test pin (on its flat) and the key."""
    from ..geometry.profile import Profile, circle_loop, polygon_loop
    from ..solids.build import extrude_profile
    from ..solids.kernel import box
    from .piece import Piece

    under = printer.hole_undersize_mm
    n = len(STEPS)
    length = bar_length()
    depth = 2 * SLOT_DEPTH + PIN_D + 8.0
    # outline with the slots open at y = 0 and a notch at the first end (x = 0, y = depth)
    pts = [(0.0, 0.0)]
    for k, step in enumerate(STEPS):
        x = BAR_END + PITCH * k
        half = 0.5 * (KEY_W + printer.backlash_mm + step)
        pts += [(x - half, 0.0), (x - half, SLOT_DEPTH), (x + half, SLOT_DEPTH), (x + half, 0.0)]
    pts += [(length, 0.0), (length, depth), (3.0, depth), (0.0, depth - 3.0)]
    holes = [circle_loop(0.5 * (PIN_D + 2 * step + under), (BAR_END + PITCH * k, depth - 4.0 - PIN_D / 2), ccw=False)
             for k, step in enumerate(STEPS)]
    bar = extrude_profile(Profile(polygon_loop(pts), holes, "coupon"), BAR_T)
    return [Piece("coupon", bar, genus=n, what=f"clearance coupon: holes {_marks()} mm radial clearance for the "
                  f"⌀{PIN_D:g} mm pin; slots the {KEY_W:g} mm key plus {_gaps(printer)} mm"),
            Piece("coupon_pin", side_pin(PIN_D, PIN_L), genus=0, what=f"coupon test pin ⌀{PIN_D:g}", chamfer_mm=0.0),
            Piece("coupon_key", box(KEY_W, KEY_L, KEY_T), genus=0, what=f"coupon key {KEY_W:g} mm (a tooth)")]


def _marks() -> str:
    """The holes' radial clearances from the notched end, as the coupon's piece and the guide both say them."""
    return ", ".join(f"{s:+.1f}" if s else "0" for s in STEPS)


def _gaps(printer) -> str:
    """The slots' gaps over the key from the notched end: the profile's backlash and the steps."""
    return ", ".join(f"{printer.backlash_mm + s:.1f}" for s in STEPS)


def advice(printer) -> list[str]:
    """What the coupon tells, as steps a maker follows (Markdown-safe text)."""
    c, j, p = printer.running_clearance_mm, printer.backlash_mm, printer.press_fit_mm
    return [
        f"Print plate 1 (the coupon) first. Its holes are, from the notched end: {_marks()} mm radial clearance "
        f"for the ⌀{PIN_D:g} mm pin; its slots, from the same end, are the key's {KEY_W:g} mm plus {_gaps(printer)} mm.",
        f"Running fit: find the tightest hole in which the pin turns freely by hand. This kit is drawn for "
        f"{c:g} mm; if that hole is +0.3 use `--set running_clearance_mm=0.35`, if it is +0.1 or 0 use "
        f"`--set running_clearance_mm=` that value (at least 0.1).",
        f"Press fit: the pin should go into the −0.1 hole only when pressed hard (this kit: {p:g} mm interference). "
        f"If it drops in, your holes print larger: `--set hole_undersize_mm="
        f"{max(0.0, printer.hole_undersize_mm - 0.1):g}`; if it will not go into the 0 hole at all, they print "
        f"smaller: `--set hole_undersize_mm={printer.hole_undersize_mm + 0.1:g}`.",
        f"Gear backlash: find the narrowest slot the key slides through without force; use `--set backlash_mm=` "
        f"its gap (this kit: {j:g} mm). Tight gears grind; loose ones knock.",
    ]
