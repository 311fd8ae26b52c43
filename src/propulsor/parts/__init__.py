"""Part types: parameters -> library -> outputs.  The only layer that knows all the others.

Each part type lives in its own module exposing `PART_TYPE` (a `PartType`).
Modules are imported on demand so that `propulsor list` / `params` stay quick.
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


def part_type_names() -> list[str]:
    return sorted(_MODULES)


def get_part_type(name: str) -> PartType:
    if name not in _MODULES:
        raise InputError("type", name, f"unknown part type (known: {', '.join(part_type_names())})")
    mod = importlib.import_module(f".{_MODULES[name]}", __name__)
    return mod.PART_TYPE
