"""Layer contracts of ``src/propulsor`` (docs/architecture.md, "layers"), read from the source.

Every ``import`` and ``from ... import`` of every module counts, at module level or inside a
function (the part modules import lazily).  A module's layer is its first package below
``propulsor`` (``gears/involute.py`` -> ``gears``); top-level modules are layers of their own.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
PACKAGE = "propulsor"

#: the CAD kernel (cadquery wraps OCP, i.e. OCCT) and the boolean kernel
KERNEL = {"cadquery", "OCP", "manifold3d"}
#: everything that is not math: kernels, meshes, DXF, plots and pictures (PIL: animation frames)
CAD_MESH_DXF_PLOT = KERNEL | {"trimesh", "ezdxf", "matplotlib", "PIL"}

#: layers from the bottom up; a module may import its own layer and the layers of lower rank only
#: (so the layers cannot form a cycle).  errors / policy / check (the one check result type) / the package root are the ground floor.
RANK = {
    "errors": 0, "policy": 0, "check": 0, "write_root": 0, "regular_file": 0, "atomic_file": 0, "make_names": 0.5, PACKAGE: 0,
    "numbers": 0.5,
    "laws": 1,
    "gears": 2,
    "geometry": 3,
    "solids": 4,
    "export": 5,
    "checks": 6,
    "params": 7, "progress": 7, "parallel": 7, "output_folder": 7, "signals": 7,
    "printing": 7.5,
    "parts": 8,
    "building": 8.5,
    "api": 8.6,
    "batch": 8.7,
    "api": 8.6,
    "study": 8.8,
    "cli": 9,
}
MATH = ("laws", "gears")
#: the layers whose public names the package root re-exports lazily (``propulsor.part``, ``propulsor.explore``)
FACADE_OF = {"api", "study", "errors"}


@dataclass(frozen=True)
class Import:
    module: str  # importing module, dotted
    line: int
    target: str  # imported module, dotted (a propulsor module or a third-party top-level package)

    @property
    def layer(self) -> str:
        return layer_of(self.module)

    @property
    def internal(self) -> bool:
        return self.target == PACKAGE or self.target.startswith(PACKAGE + ".")

    @property
    def target_layer(self) -> str:
        return layer_of(self.target) if self.internal else self.target.split(".")[0]

    def __str__(self) -> str:
        path = self.module.replace(".", "/") + ".py"
        return f"src/{path}:{self.line} imports {self.target}"


def layer_of(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else PACKAGE


def _is_module(dotted: str) -> bool:
    p = SRC.joinpath(*dotted.split("."))
    return p.with_suffix(".py").is_file() or (p / "__init__.py").is_file()


def imports_of(path: Path) -> list[Import]:
    rel = path.relative_to(SRC).with_suffix("")
    parts = list(rel.parts)
    is_pkg = parts[-1] == "__init__"
    if is_pkg:
        parts = parts[:-1]
    module = ".".join(parts)
    package = parts if is_pkg else parts[:-1]
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
        if isinstance(node, ast.Import):
            out += [Import(module, node.lineno, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - (node.level - 1)]
                stem = ".".join(base + ([node.module] if node.module else []))
            else:
                stem = node.module
            for a in node.names:  # `from propulsor import policy` imports the module propulsor.policy
                sub = f"{stem}.{a.name}"
                out.append(Import(module, node.lineno, sub if _is_module(sub) else stem))
    return out


def all_imports() -> list[Import]:
    return [imp for p in sorted((SRC / PACKAGE).rglob("*.py")) for imp in imports_of(p)]


IMPORTS = all_imports()


def _violations(layers, forbidden_layers=(), forbidden_libraries=()) -> list[str]:
    bad = []
    for imp in IMPORTS:
        if imp.layer not in layers:
            continue
        if imp.internal and imp.target_layer in forbidden_layers:
            bad.append(str(imp))
        if not imp.internal and imp.target_layer in forbidden_libraries:
            bad.append(str(imp))
    return bad


def test_every_layer_is_known():
    """A new top-level module or package must be given its place in RANK (and in the docs)."""
    layers = {imp.layer for imp in IMPORTS} | {imp.target_layer for imp in IMPORTS if imp.internal}
    assert layers <= set(RANK), sorted(layers - set(RANK))


def test_math_layers_import_no_cad_mesh_dxf_or_plot_library():
    assert _violations(MATH, forbidden_libraries=CAD_MESH_DXF_PLOT) == []


def test_math_layers_import_nothing_above_them():
    upper = {"geometry", "solids", "checks", "export", "parts", "params", "cli", "progress", "parallel"}
    assert _violations(MATH, forbidden_layers=upper) == []
    assert _violations(("laws",), forbidden_layers={"gears"}) == []


def test_geometry_imports_no_solids_checks_export_parts_nor_any_kernel():
    upper = {"solids", "checks", "export", "parts", "params", "cli", "progress", "parallel"}
    assert _violations(("geometry",), forbidden_layers=upper, forbidden_libraries=CAD_MESH_DXF_PLOT) == []


def test_checks_and_exports_never_import_parts():
    assert _violations(("checks", "export", "solids"), forbidden_layers={"parts", "cli", "params"}) == []


def test_parts_import_no_kernel():
    assert _violations(("parts",), forbidden_libraries=KERNEL) == []


def test_layers_import_only_downwards_so_they_form_no_cycle():
    # the package root's public names are loaded on first use from the layers that make them (api,
    # study): a facade above everything, imported by no layer for anything but plain values
    bad = [f"{imp} ({imp.layer} may not import {imp.target_layer})" for imp in IMPORTS
           if imp.internal and imp.target_layer != imp.layer and RANK[imp.target_layer] >= RANK[imp.layer]
           and not (imp.module == PACKAGE and imp.target_layer in FACADE_OF)]
    assert bad == []


def test_nothing_imports_the_api_but_the_root_and_the_command_line():
    users = {imp.module for imp in IMPORTS if imp.internal and imp.target_layer == "api"}
    assert users <= {PACKAGE, "propulsor.cli", "propulsor.study"} | {m for m in users if m.startswith("propulsor.study.")}


def test_the_contracts_see_imports_inside_functions():
    """The parser itself: lazy imports count, relative imports resolve to the module."""
    found = {(imp.module, imp.target) for imp in IMPORTS}
    assert ("propulsor.parts.noncircular_pair.design", "propulsor.geometry.noncircular_outline") in found
    assert ("propulsor.gears.noncircular_teeth", "propulsor.gears.envelope") in found
    assert ("propulsor.laws.shoe", "propulsor.policy") in found
