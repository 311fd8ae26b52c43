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

__all__ = ["Bore", "bore_limit", "size_bore", "bores", "with_bores", "check_given", "sized_derived", "sized_note",
           "root_bound", "check_given_on_pitch_curves"]

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


def largest_bore(lim: float, keyway: bool) -> float | None:
    """The largest standard bore (``policy.BORE_STANDARD_D_MM``, keyed within DIN 6885-1's range when `keyway`) whose
    radius with its keyway's depth t2 stays under `lim` (mm); None when none does."""
    fits = [d for d in policy.BORE_STANDARD_D_MM
            if (not keyway or _KEYED[0] < d <= _KEYED[1]) and d / 2 + _t2(d, keyway) < lim]
    return fits[-1] if fits else None


def _remedy(name: str, lim: float, keyway: bool, bound: bool = False) -> str:
    """The refusal's remedy: the largest standard bore under `lim` (`bound`: a limit from the pitch curves, which the
    cut root may lower)."""
    d = largest_bore(lim, keyway)
    best = ((f"the largest standard bore that may fit is {d:g} mm (the cut root decides)" if bound else
             f"the largest standard bore that fits is {d:g} mm") if d is not None else
            f"no standard{' keyed' if keyway else ''} bore fits" + ("; keyway = false allows a plain one" if keyway
                                                                      else ""))
    return f"{best}; leave {name} out to size it from the gear"


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
                         f"bore/2 + t2 = {d / 2 + t2:.3f} mm >= {lim:.3f} mm", _remedy(name, lim, keyway))


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


def root_bound(pc, which: str, m: float, samples: int = 4096) -> float:
    """An upper bound (mm) of the least root radius of the ``which`` gear ("driver" / "driven") from the pitch curves
    ``pc`` alone (``gears.noncircular.PitchCurves``), before any tooth is cut: the largest pitch radius within one
    pitch (pi m of arc) either way of the least.  A tooth space lies within half a pitch of any point of the pitch
    curve, and its root lies inside the curve (every cutter reaches below its centrode), so the least root radius is
    at most the pitch radius somewhere in that window.  Sampled: the window widened by the largest arc between two
    samples and the bound raised by the largest change of radius between two samples."""
    import numpy as np

    phi = np.linspace(0.0, 2.0 * np.pi, samples + 1)
    r = np.asarray(pc.r(phi) if which == "driver" else pc.r_H(phi), float)
    ds = np.asarray(pc.ds_dphi(phi), float)
    s = np.concatenate([[0.0], np.cumsum(0.5 * (ds[1:] + ds[:-1]) * np.diff(phi))])  # contact arc: both curves'
    per = float(s[-1])
    k = int(np.argmin(r))
    reach = np.pi * m + float(np.max(np.diff(s)))
    gap = np.abs(s - s[k])
    near = np.minimum(gap, per - gap) <= reach
    return float(np.max(r[near])) + float(np.max(np.abs(np.diff(r))))


def check_given_on_pitch_curves(p, pc, m: float) -> None:
    """A bore the part file gives, refused before any tooth is cut when it reaches the rim below the root for certain
    (:func:`root_bound`): the dry run refuses it as the build does (the build's own check, on the cut root, then
    refuses the bores between the two).  `pc`: the pitch curves, or a list of the pitch curves the design may build
    (the law search's candidates): a bore is refused when it reaches the root on every one of them."""
    rim = policy.BORE_RIM_MIN_MODULES
    pcs = pc if isinstance(pc, (list, tuple)) else [pc]
    for which in ("driver", "driven"):
        name = f"{which}_bore_mm"
        d = getattr(p, name)
        if d is None or d <= 0 or not pcs:
            continue
        bound = max(root_bound(c, which, m) for c in pcs)
        t2 = _t2(d, p.keyway)
        lim = bound - rim * m
        if not d / 2 + t2 < lim:
            raise InputError(name, d, f"bore{' + keyway' if p.keyway else ''} must stay "
                             f"{'one module' if rim == 1 else f'{rim:g} modules'} inside the root, which lies inside "
                             f"the pitch curve: bore/2 + t2 = {d / 2 + t2:.3f} mm >= {lim:.3f} mm (the {which}'s "
                             f"largest pitch radius within a pitch of its least, {bound:.3f} mm, less "
                             f"{rim * m:.3f} mm)",
                             _remedy(name, lim, p.keyway, bound=True))


def check_given_on_design(p, d) -> None:
    """The bores the part file gives, checked on the design's cut roots as the build checks them (:func:`bores`)."""
    for which, gear in (("driver", d.driver), ("driven", d.driven)):
        name = f"{which}_bore_mm"
        given = getattr(p, name)
        if given is not None:
            check_given(name, given, p.keyway, gear.root_min_radius, d.m)
