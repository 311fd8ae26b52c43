"""The bores of the pair: as the part file gives them (refused when they reach the root), or, where it gives none,
sized from the gear.

A sized bore is the largest standard shaft diameter d (``policy.BORE_STANDARD_D_MM``) that the gear carries with a
body at least ``policy.BORE_HUB_RATIO`` d across (d <= 2 r_f,min / ratio, r_f,min the least radius of the finished
root curve) and whose bore with its DIN 6885-1 keyway stays ``policy.BORE_RIM_MIN_MODULES`` modules inside the root
(d/2 + t2 < r_f,min - m); with ``keyway = false`` the same without the keyway.  A gear too small for the smallest
keyed bore gets none (the report says so, and that ``keyway = false`` gives it a plain one).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from ... import policy
from ...errors import InputError
from ...geometry.gear_outline import KEYWAY_TABLE, keyway_for_shaft

__all__ = ["Bore", "bore_limit", "size_bore", "bores", "with_bores", "check_given", "sized_derived", "sized_note"]

#: DIN 6885-1's shaft range (over, up to), mm
_KEYED = (KEYWAY_TABLE[0][0], KEYWAY_TABLE[-1][1])


@dataclass(frozen=True)
class Bore:
    """One gear's bore: its diameter (0: none), with a DIN 6885-1 keyway or not, sized from the gear or given, and
    why (a sized bore's rule and numbers)."""

    d_mm: float
    keyway: bool
    sized: bool
    why: str = ""


def _t2(d: float, keyway: bool) -> float:
    return keyway_for_shaft(d)[1] if keyway else 0.0


def bore_limit(root_min: float, m: float) -> float:
    """The largest radius a bore with its keyway may reach: the least root radius less the least rim."""
    return root_min - policy.BORE_RIM_MIN_MODULES * m


def check_given(name: str, d: float, keyway: bool, root_min: float, m: float) -> None:
    """A bore the part file gives: InputError (key, value, limit) when it or its keyway reaches the rim below the
    root."""
    if d <= 0:
        return
    t2 = _t2(d, keyway)
    lim = bore_limit(root_min, m)
    if not d / 2 + t2 < lim:
        rim = policy.BORE_RIM_MIN_MODULES
        raise InputError(name, d, f"bore{' + keyway' if keyway else ''} must stay "
                         f"{'one module' if rim == 1 else f'{rim:g} modules'} inside the root: "
                         f"bore/2 + t2 = {d / 2 + t2:.3f} mm >= {lim:.3f} mm",
                         f"largest bore about {2 * (lim - t2):.1f} mm; leave {name} out to size it from the gear")


def size_bore(root_min: float, m: float, keyway: bool) -> Bore:
    """The bore of a gear whose part file gives none (module docstring's rule)."""
    hub = 2.0 * root_min / policy.BORE_HUB_RATIO
    lim = bore_limit(root_min, m)
    fits = [d for d in policy.BORE_STANDARD_D_MM
            if d <= hub + 1e-9 and (not keyway or _KEYED[0] < d <= _KEYED[1]) and d / 2 + _t2(d, keyway) < lim]
    rule = (f"the least root radius r_f = {root_min:.2f} mm carries a standard shaft of d <= {hub:.2f} mm (a body "
            f"{policy.BORE_HUB_RATIO:g} d across)")
    if not fits:
        smallest = next(d for d in policy.BORE_STANDARD_D_MM if not keyway or d > _KEYED[0])
        return Bore(0.0, False, True, f"no bore: {rule}, and the smallest{' keyed' if keyway else ''} bore, "
                                      f"{smallest:g} mm, does not fit" + ("; keyway = false gives a plain bore"
                                                                           if keyway else ""))
    d = fits[-1]
    t2 = _t2(d, keyway)
    kw = (f" with its DIN 6885-1 keyway ({keyway_for_shaft(d)[0]:g} mm wide, t2 = {t2:g} mm)" if keyway else "")
    return Bore(d, keyway, True, f"{d:g} mm: {rule}; the bore{kw} leaves a rim of "
                                 f"{root_min - d / 2 - t2:.2f} mm >= {policy.BORE_RIM_MIN_MODULES:g} m = "
                                 f"{policy.BORE_RIM_MIN_MODULES * m:.2f} mm below the root")


def bores(p, d) -> tuple[Bore, Bore]:
    """(driver, driven) bores of the parameters `p` on the design `d`: each as given (checked), or sized where the
    part file gives none (``driver_bore_mm`` / ``driven_bore_mm`` left out: None)."""
    out = []
    for which, gear in (("driver", d.driver), ("driven", d.driven)):
        name = f"{which}_bore_mm"
        given = getattr(p, name)
        if given is None:
            out.append(size_bore(gear.root_min_radius, d.m, p.keyway))
        else:
            check_given(name, given, p.keyway, gear.root_min_radius, d.m)
            out.append(Bore(float(given), bool(p.keyway and given > 0), False))
    return out[0], out[1]


def with_bores(p, chosen: tuple[Bore, Bore]):
    """The parameters with the bores as built (a sized bore's diameter in place of None)."""
    if all(not b.sized for b in chosen):
        return p
    return dataclasses.replace(p, driver_bore_mm=chosen[0].d_mm, driven_bore_mm=chosen[1].d_mm)


def sized_derived(chosen) -> dict:
    """The report's derived values of the bores sized from the gear (none where the part file gives both)."""
    return {f"{which}_bore_mm": b.d_mm for which, b in zip(("driver", "driven"), chosen) if b.sized}


def sized_note(chosen) -> str:
    """The report's note on the bores sized from the gear ("" where the part file gives both)."""
    said = [f"{which} {b.why}" for which, b in zip(("driver", "driven"), chosen) if b.sized]
    if not said:
        return ""
    return ("Bores sized from the gear (the part file gives no " + " and no ".join(
        f"{which}_bore_mm" for which, b in zip(("driver", "driven"), chosen) if b.sized) + "; give one to choose it): "
        + "; ".join(said) + ".")
