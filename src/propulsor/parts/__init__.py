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
from typing import Callable

from ..errors import InputError

#: part type name -> module (relative to this package)
_MODULES = {
    "planetary_final_drive": "final_drive",
    "noncircular_pair": "noncircular_pair",
    "balancer": "balancer",
    "road_wheel": "road_wheel",
    "cam_mover": "cam_mover",
}


@dataclass(frozen=True)
class PartType:
    name: str
    summary: str
    params_cls: type
    build: Callable  # build(params, writer) -> None; writer is an OutputWriter
    design: Callable | None = None  # design(params, ...) -> the part's frozen design


def part_type_names() -> list[str]:
    return sorted(_MODULES)


def get_part_type(name: str) -> PartType:
    if name not in _MODULES:
        raise InputError("type", name, f"unknown part type (known: {', '.join(part_type_names())})")
    mod = importlib.import_module(f".{_MODULES[name]}", __name__)
    return mod.PART_TYPE
