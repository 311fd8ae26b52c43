"""The best variants of a study built fully (``propulsor build``'s files) into <folder>/best/<rank>/."""

from __future__ import annotations

from pathlib import Path

__all__ = ["build_best_variants", "build_best"]


def build_best_variants(spec, outcome, k: int, progress=None) -> list[Path]:
    """Build the `k` best variants fully (``propulsor build``'s files) into <folder>/best/<rank>/, with the
    study's folder locked; a folder there that is not empty nor a propulsor build is left alone (its rank
    not built, said by `progress`)."""
    from .folder import holding

    with holding(outcome.folder, progress=progress):
        return build_best(spec, outcome, k, progress)


def build_best(spec, outcome, k: int, progress=None) -> list[Path]:
    """The `k` best variants built by the build service (``building.build``) into <folder>/best/<rank>/, a failed
    check kept; a rank whose folder may not be used is a notice to `progress`, not the study's end.  Then the
    front's picture and the study page again (they link the built ranks)."""
    from ..building import Loaded, build
    from ..errors import CheckFailed, EnvironmentFailure, InputError
    from ..params import load_params
    from ..parts import get_part_type
    from ..progress import Reporter

    pt = get_part_type(spec.part_type)
    made = []
    say = Reporter.of(progress)
    for rank, (_, row) in enumerate(outcome.ranked[:k], 1):
        values = {n: row[n] for n in spec.varied}
        say(f"best {rank}: variant {row['variant']} ({', '.join(f'{n} = {v}' for n, v in values.items())})")
        part = Loaded(pt, load_params(pt.params_cls, {**spec.base, **values}), spec.part_file)
        target = outcome.folder / "best" / str(rank)
        try:
            build(part, target, keep_failed=True)  # never with force: nothing there is deleted that a build did not write
        except CheckFailed:
            pass
        except (InputError, EnvironmentFailure) as exc:
            say.notice(f"best {rank} not built: {exc}")
            continue
        made.append(target)
    from .page import write_page
    from .results import plot_front

    points = plot_front(outcome.folder, spec, outcome.rows, outcome.ranked)
    write_page(outcome.folder, spec, outcome.rows, outcome.ranked, built_best=len(made), points=points)
    return made
