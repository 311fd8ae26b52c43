"""Part types: parameters -> design -> proofs -> outputs.  The only layer that knows all the others.

Each part type is a package (``params``, ``design``, ``proofs``, ``outputs``) exposing `PART_TYPE`
(a `PartType`); every build runs the one pipeline of :mod:`.pipeline` into the
:class:`~.writer.OutputWriter` (docs/architecture.md, "The data flow of one build").  Packages are
imported on demand so that `propulsor list` / `params` stay quick; a part that needs another
part type's parameters or design looks it up here, it never imports the other part.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from .. import policy
from ..errors import InputError
from .size import SizeEstimate

#: part type name -> module (relative to this package)
_MODULES = {
    "planetary_final_drive": "final_drive",
    "noncircular_pair": "noncircular_pair",
    "balancer": "balancer",
    "road_wheel": "road_wheel",
    "cam_mover": "cam_mover",
    "polysector_gear": "polysector",
}


#: part type name -> (its parameter class, one line on what it is): read without importing the part's
#: package (its CAD and proof modules), so that `propulsor list` and `params` stay quick
_REGISTRY = {
    "planetary_final_drive": ("FinalDriveParams", "planetary final drive: sun, planets, fixed ring (seed 004 ch. 4, "
                              "ISO 21771)"),
    "noncircular_pair": ("NoncircularPairParams", "non-circular gear pair of any ratio law (elliptical, Fourier, "
                         "table, pitch curve; the walking drive of seeds 000, 002): generated or sector teeth"),
    "balancer": ("BalancerParams", "suspension balancer with road wheel: torsion suspension calc, equal-strength "
                 "arm, travel sweep (seed 004 ch. 2, 8)"),
    "road_wheel": ("RoadWheelParams", "double road wheel with solid rubber tyres, Kozlov heat estimate (seed 004 "
                   "ch. 7)"),
    "cam_mover": ("CamMoverParams", "fixed cam (closed track), carrier, legs, rollers and shoes of the driven "
                  "wheel-walking propulsor (seed 001)"),
    "polysector_gear": ("PolysectorParams", "composite (polysector) gear with stepwise adjustable ratio and its "
                        "solid mate (seed 003)"),
}


def summary(name: str) -> str:
    """One line on what part type `name` is."""
    _known(name)
    return _REGISTRY[name][1]


def params_class(name: str) -> type:
    """The parameter dataclass of part type `name`, loaded from its ``params`` module alone (the part's
    package, with its kernel and proof imports, is not run: the same module object it imports later)."""
    _known(name)
    mod_name = f"{__name__}.{_MODULES[name]}.params"
    mod = sys.modules.get(mod_name)
    if mod is None:
        from pathlib import Path as _Path

        spec = importlib.util.spec_from_file_location(mod_name, _Path(__file__).parent / _MODULES[name] / "params.py")
        mod = importlib.util.module_from_spec(spec)
        sys.modules[mod_name] = mod
        try:
            spec.loader.exec_module(mod)
        except BaseException:
            sys.modules.pop(mod_name, None)
            raise
    return getattr(mod, _REGISTRY[name][0])


def _known(name: str) -> None:
    if name not in _MODULES:
        raise InputError("type", name, f"unknown part type (known: {', '.join(part_type_names())})")


@dataclass(frozen=True)
class PartType:
    name: str
    summary: str
    params_cls: type
    build: Callable  # build(params, writer) -> None; writer is an OutputWriter
    design: Callable | None = None  # design(params, ...) -> the part's frozen design
    #: estimate(params, part_file) -> SizeEstimate; may read the files the part file names (InputError)
    estimate: Callable | None = None
    #: feasible(params, part_file) -> None: InputError when the design cannot be made (generability, closure, a
    #: set that does not assemble) — what the parameters cannot tell from their fields (:func:`vet`)
    feasible: Callable | None = None


def vet(part_type: PartType, params, part_file: Path | None = None) -> None:
    """Everything the parameters of a part can be refused for before any work: the rules between their fields
    (``params.validate()``), then the design's own feasibility (``part_type.feasible``: generability, closure;
    a file the part file names read relative to `part_file`).  InputError (parameter, value, limit)."""
    if callable(getattr(params, "validate", None)):
        params.validate()
    if part_type.feasible is not None:
        part_type.feasible(params, part_file)


def _estimate_of(part_type: PartType):
    """The part type's size estimate function (its own, or the one in :mod:`.size`), or None."""
    from .size import ESTIMATES

    return part_type.estimate or ESTIMATES.get(part_type.name)


def size_needs_validation(part_type: PartType) -> bool:
    """True when the part type's size estimate needs validated parameters (it runs after the rules between the
    fields, and computes the part of the design it needs: ``estimate.needs_validated``)."""
    return bool(getattr(_estimate_of(part_type), "needs_validated", False))


def early_size(part_type: PartType, params, part_file: Path | None = None) -> SizeEstimate:
    """The size estimate before the design's feasibility is checked: from the values alone, or after the rules
    between the fields where the part type's estimate needs validated parameters (:func:`size_needs_validation`).
    InputError (parameter, value, limit) as the build's checks raise it."""
    if size_needs_validation(part_type) and callable(getattr(params, "validate", None)):
        params.validate()
    return check_size(part_type, params, part_file)


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
    _known(name)
    mod = importlib.import_module(f".{_MODULES[name]}", __name__)
    return mod.PART_TYPE
