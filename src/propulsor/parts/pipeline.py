"""The one build pipeline every part type uses: parameters → design (once) → output steps → writer.

A part type is its parameter dataclass, a ``design(params) -> Design`` function (frozen result;
raises InputError for parameters that cannot be made) and an ordered list of output steps
``step(design, writer, built)``: each step adds derived values, checks, solids, tables, plots, DXF
and notes to the :class:`~propulsor.parts.writer.OutputWriter`, which writes every solid's files
and runs the shared checks on them (B-rep, STEP round trip, mesh), then the report and the
manifest (docs/architecture.md, "The data flow of one build").  ``built`` is a dict in which a step leaves
what a later step needs (the solids, a proof running in a forked worker).

The design is computed once per parameter values (:func:`design_of`): where validating the
parameters computes it (final drive, road wheel, the balancer's suspension, a cam with a given law)
the build gets that same object; where the design is a long generation or search (non-circular
teeth, the cam law search) ``validate()`` checks the inputs only, so that the build's size estimate
bounds the work before it starts, and the build computes the design.  The designs are kept beside
the parameter objects, not in them: the parameters stay plain values.
"""

from __future__ import annotations

import copy
import weakref
from dataclasses import dataclass
from typing import Callable, Sequence

from ..params import params_to_dict

__all__ = ["design_of", "Pipeline"]

#: id(parameter object) -> [(key, design)], dropped with the parameter object
_DESIGNS: dict[int, list] = {}


def design_of(params, design_fn: Callable, *args):
    """``design_fn(params, *args)``, computed once per parameter values (and args) for as long as the
    parameter object lives; recomputed when a field of the parameters has changed since."""
    key = (design_fn.__module__, design_fn.__qualname__, params_to_dict(params), args)
    if id(params) not in _DESIGNS:
        _DESIGNS[id(params)] = []
        weakref.finalize(params, _DESIGNS.pop, id(params), None)
    store = _DESIGNS[id(params)]
    for k, d in store:
        if k == key:
            return d
    d = design_fn(params, *args)
    store.append((copy.deepcopy(key), d))
    return d


@dataclass(frozen=True)
class Pipeline:
    """``build(params, writer)`` of a part type: its design, then each output step in order."""

    design: Callable  # design(params, writer) -> Design (the writer gives the part file's folder)
    steps: Sequence[Callable]  # step(design, writer, built) -> None

    #: a build is a callable ``build(params, writer)``; named so that ``inspect`` and ``help`` can show it
    __name__ = "build"

    def __call__(self, params, w) -> None:
        d = self.design(params, w)
        built: dict = {}
        for step in self.steps:
            step(d, w, built)
