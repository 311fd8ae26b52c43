"""propulsor: CAD and manufacturing-export pipeline for wheel-walking propulsors and tracked running gear.

From Python (:mod:`propulsor.api`)::

    import propulsor
    gear = propulsor.part("parts/ncg_seed002.toml", module_mm=2.5)  # or propulsor.part("noncircular_pair", ...)
    gear.design, gear.solids, gear.assembly(), gear.profiles, gear.prove(), gear.write("out"), gear.kit()

Layers (each importable alone):
    laws/, gears/   pure math (numpy/scipy only)
    geometry/       2D closed profiles (numpy/scipy only)
    solids/         cadquery / OCCT solids from profiles
    checks/         B-rep, mesh and motion checks (OCP, trimesh, manifold3d)
    export/         STEP, STL/3MF, DXF, CSV, plots, report, manifest
    parts/          part types: parameters -> library -> outputs
    api.py          the Python interface above
    study/          design studies: many variants on a Dask cluster, one table, the Pareto front
"""

from typing import TYPE_CHECKING

from .version import __version__

__all__ = ["Part", "Build", "Proof", "part", "part_types", "parameters", "explore", "InputError", "CheckFailed",
           "EnvironmentFailure", "__version__"]

if TYPE_CHECKING:  # pragma: no cover - for type checkers; at run time the names load on first use
    from .api import Build, Part, Proof, parameters, part, part_types
    from .errors import CheckFailed, EnvironmentFailure, InputError
    from .study import explore


def __getattr__(name: str):
    """The public names, imported on first use (``import propulsor`` stays fast: no CAD kernel)."""
    if name in ("Part", "Build", "Proof", "part", "part_types", "parameters"):
        from . import api

        return getattr(api, name)
    if name == "explore":
        from .study import explore

        return explore
    if name in ("InputError", "CheckFailed", "EnvironmentFailure"):
        from . import errors

        return getattr(errors, name)
    raise AttributeError(f"module 'propulsor' has no attribute {name!r}")


def __dir__():
    return sorted(list(globals()) + __all__)
