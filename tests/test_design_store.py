"""The designs computed from a parameter object live exactly as long as it does (parts/pipeline.py, design_of).

A design holds its parameters; the designs were kept in a module-level dict by the parameters' id, dropped when
the parameters died — which they never did, being held by their own designs there.  A long-lived process (a study's
worker, the Python API in a notebook, the build service) kept every design it ever made: 0.8 MB of RSS a final-drive
variant, 240 MB per worker over a 1 000-variant study (bench/bench_study_scale.py)."""

from __future__ import annotations

import copy
import gc
import os
import pickle
import tomllib
import weakref
from dataclasses import dataclass
from pathlib import Path

from propulsor import params as params_module
from propulsor.params import load_params
from propulsor.parts import get_part_type
from propulsor.parts.pipeline import design_of

ROOT = Path(__file__).resolve().parents[1]
DESIGN_STORE = getattr(params_module, "DESIGN_STORE", "_propulsor_designs")


@dataclass(frozen=True)
class P:
    a: float = 1.0


class Design:
    def __init__(self, p):
        self.p = p  # as every part type's design does
        self.calls = 0


made: list = []


def make(p):
    d = Design(p)
    made.append(weakref.ref(d))
    return d


def test_a_design_is_made_once_per_parameter_object_and_freed_with_it():
    made.clear()
    p = P(2.0)
    d = design_of(p, make)
    assert design_of(p, make) is d and len(made) == 1  # once for the object's life
    q = P(2.0)  # equal values, another object: its own design
    assert design_of(q, make) is not d and len(made) == 2
    dref, pref = weakref.ref(d), weakref.ref(p)
    del d, p
    gc.collect()
    assert pref() is None and dref() is None  # the parameters and their design are gone together
    assert made[1]() is not None  # q's is not
    del q
    gc.collect()
    assert all(r() is None for r in made)


def _final_drive_params():
    base = tomllib.loads((ROOT / "parts" / "final_drive.toml").read_text(encoding="utf-8"))
    base.pop("type"), base.pop("meta", None)
    pt = get_part_type("planetary_final_drive")
    return pt, base, load_params(pt.params_cls, base)


def test_the_designs_stay_out_of_the_parameters_values_copies_and_pickles():
    pt, _, p = _final_drive_params()
    before = repr(p)
    from propulsor.parts.final_drive.design import design

    d = design_of(p, design)
    assert getattr(p, DESIGN_STORE)[0][1] is d
    assert repr(p) == before  # not a field: not printed
    for other in (pickle.loads(pickle.dumps(p)), copy.copy(p), copy.deepcopy(p)):
        assert other == p and hash(other) == hash(p)
        assert DESIGN_STORE not in other.__dict__  # the design is not carried along
    assert len(pickle.dumps(p)) < 2000  # the fields only (the design's outlines are megabytes)


def test_a_study_worker_keeps_no_design_of_the_variants_it_evaluated(monkeypatch):
    from propulsor.study.evaluate import evaluate

    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    pt, base, _ = _final_drive_params()
    gc.collect()
    alive0 = sum(type(o) is pt.params_cls for o in gc.get_objects())
    for k in range(4):
        row = evaluate("planetary_final_drive", base, str(ROOT / "parts" / "final_drive.toml"),
                       {"width_planet_mm": 60.0 + k}, "design", ("ring_outer_d_mm",))
        assert row["status"] == "ok", row["reason"]
    gc.collect()
    assert sum(type(o) is pt.params_cls for o in gc.get_objects()) == alive0  # 4 more before the fix
    assert os.environ["PROPULSOR_JOBS"] == "1"
