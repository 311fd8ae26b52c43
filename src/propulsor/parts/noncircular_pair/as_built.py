"""The pair as built: its transmission measured on the finished outlines, in both directions, by contact events.

Both directions of the loaded contact (``checks.motion.contact_events``: the driver at the law's angle, the driven
wheel turned until the outlines touch; drive: the driver's loaded flanks pushing; reverse: the other flanks, as when
the driver turns the other way) over one period of the pair (one leg of the walking law when the driven teeth
divide into the legs, else the whole turn), sampled every ``policy.CONTACT_STEP_DRIVER_DEG`` of driver and every
change of the tooth pair or the contact kind located to ``policy.CONTACT_EVENT_STEP_RAD``.

For each direction: the driven speed over the law's (1 + te'), the largest step of it across a change of contact
state, the share of the cycle on a corner, the stretches that depart from the law, the transmission error
peak-to-peak, and for the walking law the hub speed the outlines deliver (seed 000 eq. 2-3),

    v/omega = dX01/dphi (phi + te) * (1 + te'(phi)) / U(phi),

its ripple (max - min) / mean with the mean A/u of the closed law.  The least backlash is the gap between the two
directions' contacts, (te_reverse - te_drive) r_H(phi), on every sample of either.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...checks.motion.contact_events import DRIVE, REVERSE, ContactLaw, PairOutlines, resolve_contact
from ...laws.law import is_walking

__all__ = ["AsBuilt", "HubSpeed", "as_built_speed", "pair_outlines", "contact_direction", "combine", "as_built",
           "period_span"]


@dataclass(frozen=True)
class HubSpeed:
    """The hub speed v/omega the outlines deliver in one direction (walking law)."""

    ripple: float        #: (max - min) / mean
    v_min_rel: float     #: least v/omega over its mean A/u
    v_max_rel: float
    phi_min: float       #: driven angle of the least (rad)
    phi_max: float


@dataclass(frozen=True)
class AsBuilt:
    """Both directions' contact laws over ``span`` and what follows from them."""

    drive: ContactLaw
    reverse: ContactLaw
    span: float                          #: driven angle resolved (rad): one period of the pair
    hub: tuple                           #: (HubSpeed drive, HubSpeed reverse), or () for a law without a hub
    backlash_min_mm: float
    backlash_max_mm: float
    backlash_min_phi: float

    @property
    def directions(self) -> tuple[ContactLaw, ContactLaw]:
        return self.drive, self.reverse

    @property
    def ripple(self) -> float:
        """The larger as-built hub speed ripple of the two directions (walking law), nan without a hub."""
        return max(h.ripple for h in self.hub) if self.hub else math.nan

    @property
    def step_max(self) -> float:
        return max(c.step_max for c in self.directions)

    @property
    def speed_min(self) -> float:
        return min(c.speed_min for c in self.directions)

    @property
    def speed_max(self) -> float:
        return max(c.speed_max for c in self.directions)

    @property
    def edge_share(self) -> float:
        return max(c.edge_share for c in self.directions)

    def corner_run_max_deg(self) -> tuple[float, str]:
        """The longest run of driver angle with the load on a corner (deg) and where (direction, driver deg)."""
        best, where = 0.0, ""
        for c in self.directions:
            run, at = c.corner_run_max()
            if run > best:
                best, where = run, f"{c.name} at driver {at:.3f} deg"
        return best, where

    @property
    def evaluations(self) -> int:
        return self.drive.evaluations + self.reverse.evaluations


def as_built_speed(law, run_law, phi, te, samples: int = 20001):
    """(phi grid, v/omega) of the loaded outlines: te piecewise linear through the resolved samples, its
    chord slopes for te', the law ``run_law`` the teeth realise for U, the mechanism's ``law`` for dX01/dphi."""
    grid = np.union1d(np.linspace(phi[0], phi[-1], samples), 0.5 * (phi[1:] + phi[:-1]))
    k = np.clip(np.searchsorted(phi, grid, side="right") - 1, 0, len(phi) - 2)
    slope = np.diff(te) / np.diff(phi)
    t = te[k] + slope[k] * (grid - phi[k])
    return grid, law.dX01_dphi(grid + t) * (1.0 + slope[k]) / run_law.U(grid)


def period_span(d) -> float:
    """The driven angle after which the pair repeats: one period of the law when its periods hold whole driven
    teeth, else the whole turn."""
    law = d.run_law
    periods = int(getattr(law, "periods", 1) or 1)
    return 2 * math.pi / periods if periods > 1 and d.z_H % periods == 0 else 2 * math.pi


def _tooth_angles(d):
    """Body polar angles of the tooth centres: (driver, driven); None for teeth without a record (sectors)."""
    drv, dvn = d.driver, d.driven
    if not (hasattr(drv, "teeth") and drv.teeth and hasattr(drv.teeth[0], "phi_centre")):
        return None
    th = d.run_law.theta
    driven = np.array([t.phi_centre for t in dvn.teeth])
    driver = math.pi - np.asarray(th(np.array([t.phi_centre for t in drv.teeth])), float)
    return driver, driven


def _teeth_from_corners(o, turn, corner) -> np.ndarray:
    """Tooth centres of an outline without a tooth record: the mid-angles of its convex corners taken in pairs."""
    idx = np.nonzero(corner & (turn > 0))[0]
    a = np.sort(np.arctan2(o.points[idx, 1], o.points[idx, 0]))
    if len(a) < 2:
        return np.zeros(1)
    return np.array([0.5 * (a[i] + a[i + 1]) for i in range(0, len(a) - 1, 2)])


#: the last pair prepared in this process, by the values it is made of: (key, PairOutlines).  The two directions of
#: one pair run here one after the other when no worker is free, each on its own copy of the design (the pickle
#: round trip of ``parallel.start``): the second takes the first's outlines, grids and distance fields (a resolved
#: contact reads them and changes none of their values)
_LAST: list = [None, None]


def pair_outlines(d, mount: float) -> PairOutlines:
    """The pair's outer outlines at the installed centre distance, prepared for contact events (the one prepared last
    when it was made of equal values: ``_LAST``)."""
    import hashlib

    from ...checks.motion import outline
    from .pair_proof import _outer_only

    lines = (_outer_only(d.driver.profile), _outer_only(d.driven.profile))
    teeth = _tooth_angles(d)
    arrays = [np.ascontiguousarray(a, np.float64) for a in (*lines[0], *lines[1], *(teeth or ()))]
    h = hashlib.sha256(repr((float(mount), [len(x) for x in lines], teeth is None, [a.shape for a in arrays])).encode())
    for a in arrays:
        h.update(a.tobytes())
    key = h.digest()
    if _LAST[0] == key:
        return _LAST[1]
    drv, dvn = outline(lines[0]), outline(lines[1])
    pair = PairOutlines(drv, dvn, mount, *(teeth if teeth is not None else (np.zeros(1), np.zeros(1))))
    if teeth is None:
        pair.driver_teeth = _teeth_from_corners(drv, pair.turn_drv, pair.corner_drv)
        pair.driven_teeth = _teeth_from_corners(dvn, pair.turn_dvn, pair.corner_dvn)
    _LAST[:] = [key, pair]
    return pair


def contact_direction(d, mount: float, direction: int, step_driver_rad: float | None = None) -> ContactLaw:
    """One direction's resolved contact over one period of the pair (a worker job; its sampled positions
    counted to the build that started it with a counter: ``parallel.tick``; not counted where none listens, as in a
    study's variant)."""
    from ...parallel import listening, tick

    return resolve_contact(pair_outlines(d, mount), d.run_law.theta, 0.0, period_span(d), direction,
                           step_driver_rad=step_driver_rad, tick=tick if listening() else None)


def _hub(d, c: ContactLaw) -> HubSpeed:
    ok = np.isfinite(c.te)
    grid, v = as_built_speed(d.law, d.run_law, c.phi[ok], c.te[ok])
    mean = d.law.hub_speed_ratio
    i, j = int(np.argmin(v)), int(np.argmax(v))
    return HubSpeed(float((v[j] - v[i]) / mean), float(v[i] / mean), float(v[j] / mean), float(grid[i]), float(grid[j]))


def combine(d, drive: ContactLaw, reverse: ContactLaw) -> AsBuilt:
    """The as-built values of the two directions' contact laws."""
    from ...gears.noncircular import PitchCurves

    x = np.union1d(drive.phi, reverse.phi)
    okd, okr = np.isfinite(drive.te), np.isfinite(reverse.te)
    ted = np.interp(x, drive.phi[okd], drive.te[okd])
    ter = np.interp(x, reverse.phi[okr], reverse.te[okr])
    r_H = np.asarray(PitchCurves(d.run_law, d.L).r_H(x), float)
    bl = (ter - ted) * r_H
    k = int(np.argmin(bl))
    hub = (_hub(d, drive), _hub(d, reverse)) if is_walking(d.law) else ()
    return AsBuilt(drive, reverse, drive.span, hub, float(bl[k]), float(np.max(bl)),
                   float(x[k]))


def as_built(d, mount: float, pr=None, step_driver_rad: float | None = None) -> AsBuilt | None:
    """Both directions in this process; None where the proof ``pr`` found a jam (no running position)."""
    if pr is not None and (pr.jams or not np.all(np.isfinite(pr.phi_drive))):
        return None
    return combine(d, contact_direction(d, mount, DRIVE, step_driver_rad),
                   contact_direction(d, mount, REVERSE, step_driver_rad))
