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

from .spec import load_study


def explore(study: str | Path, out: str | Path | None = None, *, scheduler: str | None = None,
            workers: int | None = None, resume: bool = False, build_best: int = 0, progress=None,
            wait: bool = True):
    """Run the study file `study` into folder `out` (default output/<study file name>); returns the
    :class:`~propulsor.study.engine.Outcome` (rows, ranked rows, folder).  InputError for a bad study
    file, folder or an unreachable scheduler, before anything is written.  The folder is locked for the
    whole study (as a build's output is): `wait` False refuses a folder in use instead of waiting."""
    from .engine import run

    from ..api import as_path

    study = as_path(study, "study")
    spec = load_study(study)
    folder = as_path(out, "out") if out is not None else Path("output") / study.stem
    return run(spec, folder, scheduler=scheduler, workers=workers, resume=resume,
               progress=progress or (lambda msg: None), build_best=build_best, wait=wait)


def build_best_variants(spec, outcome, k: int, progress=None) -> list[Path]:
    """Build the `k` best variants fully (``propulsor build``'s files) into <folder>/best/<rank>/, with the
    study's folder locked; a folder there that is not empty nor a propulsor build is left alone (its rank
    not built, said by `progress`)."""
    from .engine import holding

    with holding(outcome.folder):
        return _build_best(spec, outcome, k, progress)


def _build_best(spec, outcome, k: int, progress=None) -> list[Path]:
    from ..api import Part
    from ..errors import CheckFailed, EnvironmentFailure, InputError
    from ..params import load_params
    from ..parts import get_part_type

    pt = get_part_type(spec.part_type)
    made = []
    say = progress or (lambda msg: None)
    for rank, (_, row) in enumerate(outcome.ranked[:k], 1):
        values = {n: row[n] for n in spec.varied}
        say(f"best {rank}: variant {row['variant']} ({', '.join(f'{n} = {v}' for n, v in values.items())})")
        part = Part(spec.part_type, load_params(pt.params_cls, {**spec.base, **values}), spec.part_file)
        target = outcome.folder / "best" / str(rank)
        try:
            part.write(target, keep_failed=True)  # never with force: nothing there is deleted that a build did not write
        except CheckFailed:
            pass
        except (InputError, EnvironmentFailure) as exc:
            import sys

            print(f"propulsor: best {rank} not built: {exc}", file=sys.stderr)
            continue
        made.append(target)
    from .page import write_page
    from .results import plot_front

    points = plot_front(outcome.folder, spec, outcome.rows, outcome.ranked)
    write_page(outcome.folder, spec, outcome.rows, outcome.ranked, built_best=len(made), points=points)
    return made
