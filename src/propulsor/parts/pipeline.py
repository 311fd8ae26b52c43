"""The one build pipeline every part type uses: parameters → design (once) → output steps → writer.

A part type is its parameter dataclass, a ``design(params) -> Design`` function (frozen result;
raises InputError for parameters that cannot be made) and an ordered list of output steps
``step(design, writer, built)``: each step adds derived values, checks, solids, tables, plots, DXF
and notes to the :class:`~propulsor.parts.writer.OutputWriter`, which writes every solid's files
and runs the shared checks on them (B-rep, STEP round trip, mesh), then the report and the
manifest (docs/architecture.md, "The data flow of one build").  ``built`` is a dict in which a step leaves
what a later step needs (the solids, a proof running in a forked worker).

A part type may declare which of its steps are its proofs (``proof_steps``): the steps that make the
full-cycle proofs, their checks and the derived values, from the design alone — no solid, no file.
:meth:`Pipeline.prove` runs the design and those steps only, in the build's order, into a writer that keeps
values and writes nothing (:class:`~propulsor.parts.proof_writer.ProofWriter`): the same code as the
build, so the same numbers (a design study's ``proof`` depth, :attr:`propulsor.Part.proof_run`).

The design is computed once per parameter values (:func:`design_of`): where validating the
parameters computes it (final drive, road wheel, the balancer's suspension, a cam with a given law)
the build gets that same object; where the design is a long generation or search (non-circular
teeth, the cam law search) ``validate()`` checks the inputs only, so that the build's size estimate
bounds the work before it starts, and the build computes the design.  The designs are kept with the
parameter object (a private attribute, :data:`STORE`, outside its fields: not compared, not printed, not pickled or
copied), so they go with it: a design holds its parameters, so a store beside them (a dict by ``id``, dropped when
they die) kept every design a long-lived process ever made — a study's worker grew by each variant's design (the
final drive's 0.36 MB, a whole pair's far more) until it was out of memory.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass
from typing import Callable, Sequence

from ..params import DESIGN_STORE, params_to_dict

__all__ = ["design_of", "Pipeline"]

#: the attribute of a parameter object that holds its designs: [(key, design)] (a cycle through the design, which
#: holds its parameters: freed with them by the garbage collector)
STORE = DESIGN_STORE
#: (design callable, parameters, writer) of the design a forked process computes (read there: the fork
#: copies it; nothing is pickled on the way in)
_APART = None


def design_of(params, design_fn: Callable, *args, progress=None):
    """``design_fn(params, *args)``, computed once per parameter values (and args) for as long as the
    parameter object lives; recomputed when a field of the parameters has changed since.  `progress`, when given,
    is passed on as ``design_fn(..., progress=progress)`` (it is not part of the key)."""
    key = (design_fn.__module__, design_fn.__qualname__, params_to_dict(params), args)
    store = _store_of(params)
    for k, d in store:
        if k == key:
            return d
    d = design_fn(params, *args) if progress is None else design_fn(params, *args, progress=progress)
    store.append((copy.deepcopy(key), d))
    return d


def _store_of(params) -> list:
    store = params.__dict__.get(STORE)
    if store is None:
        store = []
        object.__setattr__(params, STORE, store)  # frozen dataclasses too: outside the fields
    return store


def _design_in_child(fd: int | None = None):
    """In the forked process: the design, and every design computed on the way (:func:`design_of`); its progress
    (the writer's) sent to the build through `fd` (``parallel.forward_events``)."""
    design, params, w = _APART
    if fd is not None and getattr(w, "progress", None) is not None:
        from ..parallel import forward_events
        from ..progress import Reporter

        w.progress = Reporter(forward_events(fd))
    d = design(params, w)
    return d, params.__dict__.get(STORE, [])


def design_apart(design: Callable, params, w):
    """``design(params, w)`` computed in a forked process while this one calls ``w.warm_up()`` (the compiled
    kernels, the plotting library; the CAD kernel later, beside the jobs the design lets start); the designs it
    computed on the way join this process's cache (:func:`design_of`), its progress shown as it comes.  In this
    process, without warm-up, where no worker may be forked (a budget of one process, slots shared by several
    builds, no fork)."""
    global _APART
    from ..parallel import event_pipe, fork_pool, result, slots_shared
    from ..progress import Reporter

    pool = None if slots_shared() or not callable(getattr(w, "warm_up", None)) else fork_pool(1)
    if pool is None:
        return design(params, w)
    _APART = (design, params, w)
    said = getattr(w, "progress", None)
    shown = said.callback if isinstance(said, Reporter) else said
    try:
        if shown is None:
            job = pool.submit(_design_in_child)  # the fork happens here
        else:
            job = event_pipe(shown, lambda fd: pool.submit(_design_in_child, fd))
    finally:
        _APART = None
    job.add_done_callback(lambda _f: pool.give_back())
    pool.shutdown(wait=False)
    w.warm_up()
    d, computed = result(job)
    store = _store_of(params)
    known = [k for k, _ in store]
    store.extend((k, v) for k, v in computed if k not in known)
    return d


@dataclass(frozen=True)
class Pipeline:
    """``build(params, writer)`` of a part type: its design, then each output step in order.

    ``proof_steps``: the steps (each one of ``steps``) that prove the design without its solids or files,
    or None where the part type declares none (its proof is the whole build).  ``solid_steps``: the steps
    that make the solids, the assemblies and the DXF outlines from the design alone (no file, no check), or
    None (the solids come from the whole build)."""

    design: Callable  # design(params, writer) -> Design (the writer gives the part file's folder)
    steps: Sequence[Callable]  # step(design, writer, built) -> None
    proof_steps: Sequence[Callable] | None = None
    #: the build's design may run in a forked process (:func:`design_apart`): it only reads the writer
    #: and its result pickles exactly
    design_apart: bool = False
    solid_steps: Sequence[Callable] | None = None

    #: a build is a callable ``build(params, writer)``; named so that ``inspect`` and ``help`` can show it
    __name__ = "build"

    def __post_init__(self) -> None:
        for kind, declared in (("proof", self.proof_steps), ("solid", self.solid_steps)):
            stray = [s for s in declared or () if not any(s is t for t in self.steps)]
            if stray:
                raise ValueError(f"{kind} step {getattr(stray[0], '__name__', stray[0])!r} is not a step of the build")

    def __call__(self, params, w) -> None:
        self._run(params, w, self.steps, apart=self.design_apart)

    @property
    def proves_alone(self) -> bool:
        """Whether the part type declares its proof steps (else its proof is the whole build)."""
        return self.proof_steps is not None

    def prove(self, params, w) -> None:
        """The design, then only the proof steps, in the order the build runs them (the same derived
        values and checks as the build's, without its solids and files)."""
        if self.proof_steps is None:
            raise ValueError("this part type declares no proof steps: its proof is the whole build")
        self._run(params, w, [s for s in self.steps if any(s is t for t in self.proof_steps)])

    @property
    def solids_alone(self) -> bool:
        """Whether the part type declares the steps that make its solids (else they come from its build)."""
        return self.solid_steps is not None

    def solids(self, params, w) -> None:
        """The design, then only the solid steps, in the build's order (the build's solids, assemblies and
        outlines, without their files and checks: a :class:`~.proof_writer.SolidWriter`)."""
        if self.solid_steps is None:
            raise ValueError("this part type declares no solid steps: its solids come from the whole build")
        self._run(params, w, [s for s in self.steps if any(s is t for t in self.solid_steps)])

    def _run(self, params, w, steps, apart: bool = False) -> None:
        if not (apart and callable(getattr(w, "warm_up", None))):  # (else the warm-up beside the design does it)
            from ..checks.kernels import warm_if_cold

            warm_if_cold(getattr(w, "progress", None))
        d = design_apart(self.design, params, w) if apart else self.design(params, w)
        built: dict = {}
        flush = getattr(w, "flush_beside", None)  # the files a step asked to be written beside the build
        for step in steps:
            step(d, w, built)
            if flush is not None:
                flush()
