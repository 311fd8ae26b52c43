"""A kit's words agree with its contents: the coupon's piece and the guide say the same holes and slots; the
assembly names a push-on washer only where the hardware lists one."""

from __future__ import annotations

import re

import pytest

from propulsor.printing import coupon
from propulsor.printing.printers import load_printer


@pytest.mark.parametrize("name", ["generic", "prusa_mini"])
def test_the_coupon_piece_and_the_guide_give_the_same_holes_and_slots(name):
    pr = load_printer(name, {"backlash_mm": 0.2})
    what = next(pc.what for pc in coupon.coupon_pieces(pr) if pc.name == "coupon")
    guide = coupon.advice(pr)[0]
    holes = ", ".join(f"{s:+.1f}" if s else "0" for s in coupon.STEPS)
    gaps = "0.1, 0.2, 0.3, 0.4, 0.5"  # the slots: the key's 3 mm plus the backlash 0.2 and the steps −0.1 … +0.3
    for text in (what, guide):
        assert f"{holes} mm radial clearance" in text
        assert re.search(rf"3 mm (key )?plus {re.escape(gaps)} mm", text), text


@pytest.mark.parametrize("capped", [(True, True), (True, False), (False, True), (False, False)])
def test_the_assembly_names_a_push_on_washer_only_where_no_cap_fits(capped):
    from propulsor.parts.noncircular_pair.kit import _keep_on_step

    step = _keep_on_step(capped)
    for role, c in zip(("driver", "driven wheel"), capped):
        said_washer = re.search(rf"retaining washer \(starlock, in the hardware\) onto the {role}'s pin", step)
        said_cap = re.search(rf"cap onto (the {role}'s|each) pin", step)
        assert bool(said_washer) == (not c) and bool(said_cap) == c, step
    assert ("starlock" in step) == (not all(capped))
