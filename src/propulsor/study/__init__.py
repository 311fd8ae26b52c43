"""Design studies: many variants of a part evaluated on a Dask cluster, gathered in one table, ranked.

    import propulsor
    outcome = propulsor.explore("studies/final_drive_face_module.toml", out="output/fd_study")
    outcome.ranked[0]          # (Pareto layer, row) of the best variant

``propulsor explore STUDY.toml [--out DIR] [--scheduler ADDRESS] [--workers N] [--resume] [--build-best K]``
runs the same.  The study file's format: :mod:`propulsor.study.spec`; one evaluation:
:mod:`propulsor.study.evaluate`; the engine: :mod:`propulsor.study.engine`.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["explore", "build_best_variants", "load_study"]

from .best import build_best_variants
from .spec import load_study


def explore(study: str | Path, out: str | Path | None = None, *, scheduler: str | None = None,
            workers: int | None = None, resume: bool = False, build_best: int = 0, progress=None,
            wait: bool = True):
    """Run the study file `study` into folder `out` (default output/<study file name>); returns the
    :class:`~propulsor.study.engine.Outcome` (rows, ranked rows, folder).  InputError for a bad study
    file, folder or an unreachable scheduler, before anything is written.  The folder is locked for the
    whole study (as a build's output is): `wait` False refuses a folder in use instead of waiting."""
    from .engine import run

    from ..building import as_path

    study = as_path(study, "study")
    spec = load_study(study)
    folder = as_path(out, "out") if out is not None else Path("output") / study.stem
    return run(spec, folder, scheduler=scheduler, workers=workers, resume=resume,
               progress=progress or (lambda msg: None), build_best=build_best, wait=wait)
