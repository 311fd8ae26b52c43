"""The best variants of a study built fully (``propulsor build``'s files) into <folder>/best/<rank>/."""

from __future__ import annotations

from pathlib import Path

__all__ = ["build_best_variants", "build_best"]


def build_best_variants(spec, outcome, k: int, progress=None) -> list[Path]:
    """Build the `k` best variants fully (``propulsor build``'s files) into <folder>/best/<rank>/, with the
    study's folder locked; a folder there that is not empty nor a propulsor build is left alone (its rank
    not built, said by `progress`)."""
    from .folder import holding

    with holding(outcome.folder):
        return build_best(spec, outcome, k, progress)


def build_best(spec, outcome, k: int, progress=None) -> list[Path]:
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
