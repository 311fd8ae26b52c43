"""The two as-built directions of a pair run one after the other in one process (no worker free) each on its own
copy of the design; the second takes the outlines, grids and distance fields the first prepared
(parts/noncircular_pair/as_built.py, ``pair_outlines``: the last pair, by the values it is made of).  The contact it
resolves is the one resolved on a pair prepared anew, bit for bit; other values (the mount, the outline) prepare
another pair."""

from __future__ import annotations

import math
import pickle
from pathlib import Path

import numpy as np

from propulsor import api
from propulsor.checks.motion.contact_events import DRIVE, REVERSE, resolve_contact
from propulsor.parts.noncircular_pair import as_built

ROOT = Path(__file__).resolve().parents[1]


def _law(c):
    return (c.phi.tobytes(), c.te.tobytes(), c.kind.tobytes(), c.driver_tooth.tobytes(), c.driven_tooth.tobytes())


def test_the_second_direction_takes_the_first_s_pair_and_resolves_the_same_contact(monkeypatch):
    dd = api.part(str(ROOT / "parts" / "ncg_elliptical.toml")).design
    d, mount = dd.d, dd.mount
    span = 2.0 * math.pi * d.m / d.L  # a few teeth
    monkeypatch.setattr(as_built, "_LAST", [None, None])
    first = as_built.pair_outlines(pickle.loads(pickle.dumps(d)), mount)
    drive = resolve_contact(first, d.run_law.theta, 0.0, span, DRIVE)
    second = as_built.pair_outlines(pickle.loads(pickle.dumps(d)), mount)  # another copy, equal values
    assert second is first
    reverse = resolve_contact(second, d.run_law.theta, 0.0, span, REVERSE)
    # against pairs prepared anew for each direction
    monkeypatch.setattr(as_built, "_LAST", [None, None])
    fresh_r = as_built.pair_outlines(d, mount)
    assert fresh_r is not first
    assert _law(resolve_contact(fresh_r, d.run_law.theta, 0.0, span, REVERSE)) == _law(reverse)
    monkeypatch.setattr(as_built, "_LAST", [None, None])
    assert _law(resolve_contact(as_built.pair_outlines(d, mount), d.run_law.theta, 0.0, span, DRIVE)) == _law(drive)
    # other values: another pair
    other = as_built.pair_outlines(d, mount + 0.05)
    assert other.L == mount + 0.05 and as_built.pair_outlines(d, mount) is not other
    moved = pickle.loads(pickle.dumps(d))
    seg = moved.driven.profile.outer.segments[3]
    object.__setattr__(seg, "poles", seg.poles + np.array([1e-9, 0.0]))
    seg.__dict__.pop("_samples", None)
    base = as_built.pair_outlines(d, mount)
    assert as_built.pair_outlines(moved, mount) is not base
