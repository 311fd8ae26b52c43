"""The tip searches of the seed-002 pair's shortened teeth (gears/tip_search.py), each against the search
without its shortcut, on one design of the pair:

* one tooth's searches keep what does not depend on the height (``tip_hit``'s ``memo``: the flank's samples, the
  pitch curve's points and normals at the sampled angles): every search gives, to the last bit, what the search
  without them gives;
* the tallest tip's search first evaluates the heights either side of where a flank's end meets the tip equidistant
  (``tallest_tip``'s ``reach``, ``flank_reach``): the same height and tip, to the last bit, as the search without
  it, in a third of the evaluations or fewer."""

from __future__ import annotations

from pathlib import Path

import pytest

import propulsor.gears.tip_search as ts
from propulsor import api
from propulsor.policy import TIP_HEIGHT_TOL_MM

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def searched():
    """The seed-002 pair designed once with both shortcuts checked at every call (their records)."""
    real_hit, real_tallest = ts.tip_hit, ts.tallest_tip
    rec = {"memo": 0, "reused": 0, "tallest": []}

    def both(side, curve, h, phi_guess, span, memo=None):
        kept = None if memo is None else memo.get(id(side.flank))
        got = real_hit(side, curve, h, phi_guess, span, memo)
        assert got == real_hit(side, curve, h, phi_guess, span)  # (u, phi) or None, bit for bit
        if memo is not None:
            rec["memo"] += 1
            rec["reused"] += kept is not None and kept[0] is side.flank
        return got

    def tallest(thickness, h_lo, at_lo, h_hi, at_hi, t_min, reach=None):
        calls = {"with": 0, "without": 0}

        def counted(key):
            def f(h):
                calls[key] += 1
                return thickness(h)
            return f

        guess = []
        got = real_tallest(counted("with"), h_lo, at_lo, h_hi, at_hi, t_min,
                           None if reach is None else (lambda: guess.append(reach()) or guess[-1]))
        ref = real_tallest(counted("without"), h_lo, at_lo, h_hi, at_hi, t_min)
        rec["tallest"].append((got, ref, calls, guess, at_hi[1] is None or at_hi[2] is None, t_min))
        return got

    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("PROPULSOR_JOBS", "1")  # both wheels cut in this process, where the searches are watched
        mp.setattr(ts, "tip_hit", both)
        mp.setattr(ts, "tallest_tip", tallest)
        design = api.part(str(ROOT / "parts" / "ncg_seed002.toml")).design
    # the teeth searched: the driver's and the driven wheel's first lobe (the other lobes are its pattern)
    dvn = design.d.driven.teeth
    rec["shortened"] = (sum(t.shortened for t in design.d.driver.teeth)
                        + sum(t.shortened for t in dvn[:len(dvn) // design.d.law.n]))
    return rec


def test_a_tooth_s_tip_searches_with_the_memo_are_those_without(searched):
    shortened = searched["shortened"]
    assert shortened > 0
    # the shortened teeth's searches went through the memo, and most found their samples there
    assert searched["memo"] > 10 * shortened and searched["reused"] > 0.8 * searched["memo"]


def test_thetallest_tip_from_the_flanks_reach_is_the_one_without_it_in_a_third_of_the_evaluations(searched):
    rows = searched["tallest"]
    assert len(rows) == searched["shortened"]
    for got, ref, _, _, _, _ in rows:
        assert got[0] == ref[0] and got[1] == ref[1]  # the height, its land and both hits, bit for bit
    cut_short = [r for r in rows if r[4]]  # the nominal height has no tip: the flanks' reach was guessed
    assert len(cut_short) >= 4 and all(len(r[3]) == 1 for r in cut_short)  # 4: the driven wheel cut as one lobe
    assert not any(r[3] for r in rows if not r[4])  # a tooth with a tip at the nominal height guesses nothing
    for got, _, _, guess, _, t_min in cut_short:
        if got[1][0] > t_min + 0.1:  # the land to spare: the flank's end decided the height, where it was guessed
            assert abs(guess[0] - got[0]) <= TIP_HEIGHT_TOL_MM
    with_, without = (sum(r[2][k] for r in rows) for k in ("with", "without"))
    assert with_ <= without / 3  # 24 against 91 (84 against 343 before the driven wheel was cut as one lobe)
