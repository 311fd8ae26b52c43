"""The tip searches of one tooth keep what does not depend on the height (gears/noncircular_teeth.py, ``_tip_hit``'s
``memo``: the flank's samples, the pitch curve's points and normals at the sampled angles): every search of the
seed-002 pair's tip shortening gives, to the last bit, what the search without them gives."""

from __future__ import annotations

from pathlib import Path

import propulsor.gears.noncircular_teeth as nt
from propulsor import api

ROOT = Path(__file__).resolve().parents[1]


def test_a_tooth_s_tip_searches_with_the_memo_are_those_without(monkeypatch):
    real = nt._tip_hit
    searched = {"memo": 0, "reused": 0}

    def both(side, curve, h, phi_guess, span, memo=None):
        kept = None if memo is None else memo.get(id(side.flank))
        got = real(side, curve, h, phi_guess, span, memo)
        assert got == real(side, curve, h, phi_guess, span)  # (u, phi) or None, bit for bit
        if memo is not None:
            searched["memo"] += 1
            searched["reused"] += kept is not None and kept[0] is side.flank
        return got

    monkeypatch.setattr(nt, "_tip_hit", both)
    design = api.part(str(ROOT / "parts" / "ncg_seed002.toml")).design
    shortened = sum(t.shortened for gear in (design.d.driver, design.d.driven) for t in gear.teeth)
    assert shortened > 0
    # the shortened teeth's searches went through the memo, and most found their samples there
    assert searched["memo"] > 10 * shortened and searched["reused"] > 0.8 * searched["memo"]
