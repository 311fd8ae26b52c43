"""Part files read: a part file's type and parameters, checked as far as anything can be before a build
(:func:`load`, a :class:`Loaded`), or only as far as its size estimate needs (:func:`early_estimate`, for
ordering several builds), and the files a part file names.  The build service (:mod:`.building`) builds
what is loaded here."""

from __future__ import annotations

import dataclasses
from pathlib import Path

from .errors import InputError
from .progress import Reporter


@dataclasses.dataclass(frozen=True)
class Loaded:
    """A part ready to build: its type (``parts.PartType``), validated parameters, the part file they came from
    (None for a type's defaults or a Python caller's values) and the size estimate (None when not made)."""

    part_type: object
    params: object
    source: Path | None = None
    estimate: object = None

    @property
    def files_read(self) -> tuple[Path, ...]:
        """The part file and every file it names (() without a part file)."""
        return files_read(self.params, self.source) if self.source is not None else ()


def named_files(params, part_file: Path) -> tuple[tuple[str, str, Path], ...]:
    """(key, value as written, path) of the part file and of every file it names (string parameters
    ending in `_file`, relative to it)."""
    files = [("part file", str(part_file), part_file)]
    for f in dataclasses.fields(params):
        v = getattr(params, f.name)
        if f.name.endswith("_file") and isinstance(v, str) and v:
            p = Path(v)
            files.append((f.name, v, p if p.is_absolute() else part_file.resolve().parent / p))
    return tuple(files)


def files_read(params, part_file: Path) -> tuple[Path, ...]:
    """The part file and every file it names (:func:`named_files`)."""
    return tuple(p for _, _, p in named_files(params, part_file))


def _values(part_file: Path, say=None):
    """What :func:`load` and :func:`early_estimate` both do first: (the part type's name as the file gives it, the
    part type, the file's mapping, its parameters unvalidated, the size estimate from the values alone or None where
    the part type's needs validated parameters).  InputError (a size estimate refused: named as :func:`default_named` does)."""
    from .params import load_params, read_part_file
    from .parts import check_size, get_part_type, size_needs_validation

    part_type_name, mapping = read_part_file(part_file)
    if say is not None:
        say(f"{part_type_name}: loading the part type (its design's modules)")
    part_type = get_part_type(part_type_name)
    params = load_params(part_type.params_cls, mapping, validate=False, type_name=part_type.name)
    try:  # the size estimate first where it needs only the values (a design can itself be the long part)
        estimate = None if size_needs_validation(part_type) else check_size(part_type, params, part_file)
    except InputError as exc:
        raise default_named(exc, mapping, part_type.params_cls) from None
    return part_type_name, part_type, mapping, params, estimate


def load(part_file: Path, progress=None) -> Loaded:
    """The part file read and its parameters checked as far as anything can be before a build: fields, the
    rules between them, the size estimate and the design's own feasibility (``parts.vet``).  InputError.
    `progress`: a callback for the steps on the way (the part type's imports, the feasibility)."""
    say = Reporter.of(progress)
    from .parts import check_size, vet

    part_type_name, part_type, mapping, params, estimate = _values(part_file, say)
    try:
        say(f"{part_type_name}: checking the parameters and the design's feasibility")
        vet(part_type, params, part_file)  # the rules between fields, then the design's own feasibility (may take s)
        estimate = estimate or check_size(part_type, params, part_file)
    except InputError as exc:
        raise default_named(exc, mapping, part_type.params_cls) from None
    return Loaded(part_type, params, part_file, estimate)


def early_estimate(part_file: Path) -> float:
    """The size estimate (s) of a part file's build before the design's feasibility is checked (:func:`load` computes
    the same value): from its values alone, or, for a part type whose estimate needs validated parameters (the
    balancer's, which computes the suspension's travel: not the arm's outline, the long part of its design), after
    the rules between its fields.  InputError (parameter, value, limit) as :func:`load` raises it.  For ordering
    several builds without computing their designs (batch.longest_first): each build's own :func:`load` checks the
    rest."""
    from .parts import early_size

    _, part_type, mapping, params, estimate = _values(part_file)
    if estimate is None:
        try:
            estimate = early_size(part_type, params, part_file)
        except InputError as exc:
            raise default_named(exc, mapping, part_type.params_cls) from None
    return estimate.seconds


def default_named(exc: InputError, mapping: dict, params_cls) -> InputError:
    """`exc` as it is, or, where it names a parameter the part file does not set, with that said: the value is the
    part type's default (a user reading "driver_shift = 0.5" looks for a line that is not there)."""
    names = {f.name for f in dataclasses.fields(params_cls)}
    if type(exc) is not InputError or exc.parameter not in names or exc.parameter in mapping:
        return exc
    said = f"{exc.parameter} is not in the part file: {exc.value!r} is its default"
    out = InputError(exc.parameter, exc.value, exc.limit, f"{exc.hint}; {said}" if exc.hint else said)
    out.__dict__.update({k: v for k, v in exc.__dict__.items() if k not in ("parameter", "value", "limit", "hint")})
    return out


def load_part(part_file: Path):
    """(part type, validated parameters, size estimate) of a part file (:func:`load`)."""
    loaded = load(part_file)
    return loaded.part_type, loaded.params, loaded.estimate
