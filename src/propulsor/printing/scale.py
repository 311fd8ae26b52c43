"""The scale of a print kit: the largest standard scale at which every piece fits the bed.

Scales are reductions 1:S with S from the model-making series below.  A piece fits when its
laid-flat extents (x, y, z), divided by S, fit the bed less its edge margins in x and y (either way
round: the margins are those the plates are laid out with) and the printable height in z.  The kit then refuses scales that make teeth or walls unprintable
(:func:`check_printable`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

from ..errors import InputError

#: reductions 1:S of model making (1:1, 1:1.5, 1:2, 1:2.5, 1:3, 1:4, 1:5 ...)
STANDARD_SCALES = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0)


@dataclass(frozen=True)
class ScaleChoice:
    """The reduction S (print = real / S) and why it was chosen.  An automatic choice also carries the bed it was made
    for and ``bed_at(T)``: the least bed (x, y, z, mm; square) that holds every piece at 1:T with the plates' margins,
    so that a refusal of the scale can say which bed prints the kit (:func:`check_printable`)."""

    S: float
    reason: str
    bed: tuple = field(default=(), compare=False)
    bed_at: Callable | None = field(default=None, compare=False)

    @property
    def label(self) -> str:
        return f"1:{self.S:g}"


def fits(extents, bed) -> bool:
    """Laid-flat extents (x, y, z) fit the bed (x, y, z), turned by 90° about z if needed."""
    x, y, z = extents
    bx, by, bz = bed
    return z <= bz and ((x <= bx and y <= by) or (y <= bx and x <= by))


def _bed_text(bed, margin: float) -> str:
    text = f"{bed[0]:g} × {bed[1]:g} × {bed[2]:g} mm bed"
    return text + (f" with {margin:g} mm margins" if margin else "")


def smallest_fitting(extents, bed, margin: float = 0.0) -> float | None:
    """The smallest standard reduction S at which one piece's extents fit (None: none does)."""
    usable = (bed[0] - 2 * margin, bed[1] - 2 * margin, bed[2])
    return next((S for S in STANDARD_SCALES if fits([v / S for v in extents], usable)), None)


def least_bed(pieces: dict[str, tuple[float, float, float]], T: float, margin: float = 0.0) -> tuple:
    """The least square bed (side, side, height; mm) on which every piece fits at 1:T with `margin` along each edge,
    and the clearance coupon (printed at full size whatever the scale: :mod:`.coupon`)."""
    from .coupon import bar_length

    side = max(max(max(e[0], e[1]) for e in pieces.values()) / T, bar_length()) + 2 * margin
    return (side, side, max(e[2] for e in pieces.values()) / T)


def choose_scale(pieces: dict[str, tuple[float, float, float]], bed: tuple[float, float, float],
                 requested: float | None = None, margin: float = 0.0) -> ScaleChoice:
    """The scale for `pieces` {name: laid-flat extents in mm at full size} on `bed` (mm) less `margin`
    along each edge (the plates' edge margin).

    `requested`: a reduction S given by the user (checked to fit); None: the largest standard
    scale (smallest S) at which every piece fits, with the piece that decided it named."""
    usable = (bed[0] - 2 * margin, bed[1] - 2 * margin, bed[2])
    where = _bed_text(bed, margin)

    def too_big(S):
        return [n for n, e in pieces.items() if not fits([v / S for v in e], usable)]

    if requested is not None:
        bad = too_big(requested)
        if bad:
            e = pieces[bad[0]]
            works = max(smallest_fitting(e, bed, margin) or STANDARD_SCALES[-1] for e in pieces.values())
            raise InputError("--scale", f"1:{requested:g}", f"{bad[0]} ({e[0] / requested:.1f} × "
                             f"{e[1] / requested:.1f} × {e[2] / requested:.1f} mm) does not fit the {where}; "
                             f"every piece fits at 1:{works:g}")
        return ScaleChoice(requested, "as requested")
    auto = dict(bed=tuple(bed), bed_at=lambda T: least_bed(pieces, T, margin))
    for S in STANDARD_SCALES:
        if not too_big(S):
            if S == 1.0:
                return ScaleChoice(S, "every piece fits the bed at full size", **auto)
            # the piece that needed the reduction: the one that does not fit at the next larger scale
            prev = STANDARD_SCALES[STANDARD_SCALES.index(S) - 1]
            name = too_big(prev)[0]
            e = pieces[name]
            return ScaleChoice(S, f"{name} is {e[0]:.1f} × {e[1]:.1f} × {e[2]:.1f} mm; at 1:{prev:g} it does "
                                  f"not fit the {where}, at 1:{S:g} it does", **auto)
    name = too_big(STANDARD_SCALES[-1])[0]
    raise InputError("--scale", "auto", f"{name} does not fit the bed even at 1:{STANDARD_SCALES[-1]:g}; "
                     "choose a larger printer")


def larger(S: float) -> str:
    """What works when a piece is too small at 1:S: the next larger standard scale, on a larger bed."""
    bigger = [T for T in STANDARD_SCALES if T < S]
    return f"print at 1:{bigger[-1]:g} (a larger bed)" if bigger else "it is too small even at full size"


def check_printable(S: float, module_mm: float | None, min_module_mm: float,
                    thinnest: dict[str, float] | None = None, min_feature_mm: float = 0.8,
                    choice: ScaleChoice | None = None) -> None:
    """InputError when the scaled module or a scaled feature falls below what the printer holds.

    `thinnest`: {feature name: its full-size thickness in mm} (tip lands, webs, walls); `choice`:
    the automatic choice of S, named in the message (the bed is then what is too small)."""
    def works(limit: float) -> str:
        """The smallest standard reduction at most `limit` (the scale that prints it)."""
        ok = [T for T in STANDARD_SCALES if T <= limit + 1e-9]
        return f"1:{ok[-1]:g}" if ok else "full size"

    if module_mm is not None and module_mm / S < min_module_mm:
        largest = module_mm / min_module_mm
        auto = choice is not None and choice.reason != "as requested"
        if auto and choice.bed_at is not None and choice.bed:
            # the scale was the bed's choice: the bed is what is refused, with the least bed that prints the kit
            T = max(T for T in STANDARD_SCALES if T <= largest + 1e-9) if largest >= 1.0 - 1e-9 else 1.0
            x, y, z = (math.ceil(v - 1e-9) for v in choice.bed_at(T))  # whole mm, up
            b = choice.bed
            raise InputError("--bed", f"{b[0]:g}x{b[1]:g}x{b[2]:g}",
                             f"too small for this kit: {choice.reason}; at {choice.label} the module would be "
                             f"{module_mm / S:.3g} mm, below the printable {min_module_mm:g} mm",
                             f"a bed of at least {x} x {y} x {z} mm prints it at 1:{T:g} (module "
                             f"{module_mm / T:.3g} mm): --bed {x}x{y}x{max(z, math.ceil(b[2])):g}, or a larger printer")
        why = f" — the bed is too small: {choice.reason}" if auto else ""
        raise InputError("--scale", f"1:{S:g}", f"the scaled module {module_mm / S:.3g} mm is below the printable "
                         f"{min_module_mm:g} mm; print at {works(largest)} or larger (a larger printer){why}")
    for name, t in (thinnest or {}).items():
        if t / S < min_feature_mm:
            raise InputError("--scale", f"1:{S:g}", f"{name} is {t / S:.3g} mm at this scale, below two line "
                             f"widths ({min_feature_mm:g} mm); it prints at {works(t / min_feature_mm)} or larger (a "
                             f"larger printer), or thicken it")
