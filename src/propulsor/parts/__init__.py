"""Part types: parameters -> design -> proofs -> outputs.  The only layer that knows all the others.

Each part type is a package (``params``, ``design``, ``proofs``, ``outputs``) exposing `PART_TYPE`
(a `PartType`); every build runs the one pipeline of :mod:`.pipeline` into the
:class:`~.writer.OutputWriter` (docs/architecture.md, "The data flow of one build").  Packages are
imported on demand so that `propulsor list` / `params` stay quick; a part that needs another
part type's parameters or design looks it up here, it never imports the other part.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from .. import policy
from ..errors import InputError

#: part type name -> module (relative to this package)
_MODULES = {
    "planetary_final_drive": "final_drive",
    "noncircular_pair": "noncircular_pair",
    "balancer": "balancer",
    "road_wheel": "road_wheel",
    "cam_mover": "cam_mover",
    "polysector_gear": "polysector",
}


@dataclass(frozen=True)
class SizeEstimate:
    """What a build will cost, estimated from the parameters before any work.

    `seconds`: the build's time on the reference machine (2 cores), from a cost model calibrated on
    the part files in parts/; `detail`: what the model counts (teeth, samples, sweep steps)."""

    seconds: float
    detail: str

    def text(self) -> str:
        return f"≈ {self.seconds:.3g} s ({self.detail})"


@dataclass(frozen=True)
class PartType:
    name: str
    summary: str
    params_cls: type
    build: Callable  # build(params, writer) -> None; writer is an OutputWriter
    design: Callable | None = None  # design(params, ...) -> the part's frozen design
    #: estimate(params, part_file) -> SizeEstimate; may read the files the part file names (InputError)
    estimate: Callable | None = None


def _estimate_of(part_type: PartType):
    """The part type's size estimate function (its own, or the one in :mod:`.size`), or None."""
    from .size import ESTIMATES

    return part_type.estimate or ESTIMATES.get(part_type.name)


def size_needs_design(part_type: PartType) -> bool:
    """True when the part type's size estimate needs the validated design (it runs after validation)."""
    return bool(getattr(_estimate_of(part_type), "needs_design", False))


def check_size(part_type: PartType, params, part_file: Path | None = None) -> SizeEstimate:
    """The build's size estimate; InputError when it cannot finish within policy.BUILD_SECONDS_MAX."""
    estimate = _estimate_of(part_type)
    if estimate is None:
        return SizeEstimate(0.0, "no estimate for this part type")
    est = estimate(params, part_file)
    if not est.seconds <= policy.BUILD_SECONDS_MAX:
        raise InputError("size estimate", f"{est.seconds:.3g} s", f"must be <= {policy.BUILD_SECONDS_MAX:g} s on "
                         f"this machine ({est.detail}); reduce the counts named")
    return est


#: part type name -> module of its print kit (relative to this package),
#: ``kit(params, printer, S, source=part_file)`` (the part file: files it names are read relative to it)
_KITS = {
    "noncircular_pair": "noncircular_pair.kit",
    "planetary_final_drive": "final_drive.kit",
    "cam_mover": "cam_mover.kit",
    "road_wheel": "road_wheel.kit",
    "balancer": "balancer.kit",
    "polysector_gear": "polysector.kit",
}


def kit_type_names() -> list[str]:
    """The part types that have a print kit."""
    return sorted(_KITS)


def get_kit(name: str):
    """The print-kit function of a part type; InputError when it has none yet."""
    if name not in _KITS:
        raise InputError("type", name, f"has no print kit yet (kits: {', '.join(sorted(_KITS)) or 'none'})")
    return importlib.import_module(f".{_KITS[name]}", __name__).kit


def part_type_names() -> list[str]:
    return sorted(_MODULES)


def _glossary_module(name: str):
    if name not in _MODULES:
        return None
    try:
        return importlib.import_module(f".{_MODULES[name]}.glossary", __name__)
    except ModuleNotFoundError:
        return None


def glossary_of(name: str) -> dict:
    """The part type's glossary of derived values ({name: (unit, meaning)}, see export.glossary); {} if none."""
    mod = _glossary_module(name)
    return dict(getattr(mod, "GLOSSARY", {})) if mod else {}


def key_values_of(name: str) -> list[str]:
    """The derived values a report's summary shows for the part type."""
    mod = _glossary_module(name)
    return list(getattr(mod, "KEY_VALUES", ())) if mod else []


def get_part_type(name: str) -> PartType:
    if name not in _MODULES:
        raise InputError("type", name, f"unknown part type (known: {', '.join(part_type_names())})")
    mod = importlib.import_module(f".{_MODULES[name]}", __name__)
    return mod.PART_TYPE
