"""What import-linter cannot say about the layers of ``src/propulsor`` (docs/architecture.md, «Layers»).

The contracts themselves — the layers, the independence of the part packages, no CAD kernel in the math
layers, no kernel in the part types — are import-linter's (``[tool.importlinter]`` in pyproject.toml,
``lint-imports`` in ``make test``).  Here: every top-level module has its layer in that contract (a new one must
be placed), no import cycle anywhere (grimp, which import-linter uses, finds them), grimp sees the imports inside
functions, and the contracts do fail on the two mutations the issue names.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src"
PACKAGE = "propulsor"
CONFIG = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["importlinter"]
LINT = Path(sys.executable).parent / "lint-imports"

grimp = pytest.importorskip("grimp", reason="import-linter (and its grimp) are in the test extra: make install")


def _graph():
    return grimp.build_graph(PACKAGE, include_external_packages=False, cache_dir=None)


GRAPH = _graph()


def _contract(contract_id: str) -> dict:
    return next(c for c in CONFIG["contracts"] if c.get("id") == contract_id)


def _layer_modules() -> set[str]:
    names = set()
    for layer in _contract("layers")["layers"]:
        for part in layer.replace("|", ":").split(":"):
            names.add(part.strip())
    return names


def test_every_top_level_module_has_its_layer():
    """A new top-level module or package must be placed in the layers contract (and in the docs)."""
    top = {m for m in GRAPH.modules if m.count(".") == 1}
    assert top - _layer_modules() == set(), "not in [tool.importlinter] layers: " + ", ".join(sorted(top - _layer_modules()))
    assert _layer_modules() - top == set(), "in the layers contract but no module: " + ", ".join(sorted(_layer_modules() - top))


def _cycles(graph) -> list[list[str]]:
    """The strongly connected groups of more than one module (Tarjan, iterative), each sorted."""
    index, low, on, stack, out = {}, {}, set(), [], []
    counter = 0
    for root in sorted(graph.modules):
        if root in index:
            continue
        work = [(root, iter(sorted(graph.find_modules_directly_imported_by(root))))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on.add(root)
        while work:
            v, it = work[-1]
            w = next(it, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = counter
                    counter += 1
                    stack.append(w)
                    on.add(w)
                    work.append((w, iter(sorted(graph.find_modules_directly_imported_by(w)))))
                elif w in on:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                group = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    group.append(w)
                    if w == v:
                        break
                if len(group) > 1:
                    out.append(sorted(group))
    return out


def test_no_import_cycle_in_the_package():
    """No module reaches itself through its imports (those inside functions count): the groups grimp's graph
    holds, each with one of its arrows back."""
    found = _cycles(GRAPH)
    shown = []
    for group in found:
        members = set(group)
        arrows = [f"{a} -> {b}" for a in group for b in sorted(GRAPH.find_modules_directly_imported_by(a)) if b in members]
        shown.append(f"{len(group)} modules: " + "; ".join(arrows[:6]))
    assert found == [], "\n".join(shown)


def test_the_cycle_finder_finds_a_cycle():
    g = grimp.ImportGraph()
    for m in ("p", "p.a", "p.b", "p.c"):
        g.add_module(m)
    g.add_import(importer="p.a", imported="p.b")
    g.add_import(importer="p.b", imported="p.a")
    g.add_import(importer="p.c", imported="p.a")
    assert _cycles(g) == [["p.a", "p.b"]]


def test_grimp_sees_imports_inside_functions():
    """The graph holds the lazy imports the part modules use (and relative imports resolved to the module)."""
    assert GRAPH.direct_import_exists(importer="propulsor.parts.noncircular_pair.design",
                                      imported="propulsor.geometry.noncircular_outline")
    assert GRAPH.direct_import_exists(importer="propulsor.gears.noncircular_teeth", imported="propulsor.gears.envelope")
    assert GRAPH.direct_import_exists(importer="propulsor.laws.shoe", imported="propulsor.policy")


def _lint(src: Path) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(src)}
    return subprocess.run([str(LINT), "--config", str(ROOT / "pyproject.toml"), "--no-cache"], capture_output=True,
                          text=True, cwd=ROOT, env=env, timeout=300)


@pytest.mark.skipif(not LINT.exists(), reason="lint-imports not installed (make install)")
@pytest.mark.parametrize("module, line, contract", [
    ("gears/involute.py", "import cadquery  # mutation\n", "The math and 2D layers import no CAD kernel"),
    ("parts/balancer/design.py", "from ..cam_mover import params as _mutation  # mutation\n",
     "Part packages are independent"),
], ids=["cadquery_in_gears", "cam_mover_in_balancer"])
def test_the_contracts_break_under_a_mutation(tmp_path, module, line, contract):
    """The source as it is keeps every contract; with the one line added, the contract named breaks."""
    src = tmp_path / "src"
    shutil.copytree(SRC / PACKAGE, src / PACKAGE, ignore=shutil.ignore_patterns("__pycache__", "web"))
    target = src / PACKAGE / module
    text = target.read_text(encoding="utf-8")
    cut = text.index("\n\n", text.index("from __future__ import annotations")) + 1
    target.write_text(text[:cut] + line + text[cut:], encoding="utf-8")
    r = _lint(src)
    assert r.returncode != 0, r.stdout
    broken = [ln for ln in r.stdout.splitlines() if ln.endswith("BROKEN")]
    assert any(contract in ln for ln in broken) or contract in r.stdout.split("Broken contracts")[-1], r.stdout


@pytest.mark.skipif(not LINT.exists(), reason="lint-imports not installed (make install)")
def test_the_source_keeps_every_contract():
    r = _lint(SRC)
    assert r.returncode == 0, r.stdout[-3000:]


def test_below_the_command_line_nothing_prints():
    """The build service and everything below it report through values, exceptions and progress events: no
    ``print`` and no ``sys.stdout`` / ``sys.stderr`` outside the command-line face (cli.py, batch.py, render.py, and
    program_end.py: how the program ends, its streams flushed)."""
    import ast

    face = {SRC / PACKAGE / "cli.py", SRC / PACKAGE / "batch.py", SRC / PACKAGE / "render.py",
            SRC / PACKAGE / "__main__.py", SRC / PACKAGE / "program_end.py"}
    bad = []
    for path in sorted((SRC / PACKAGE).rglob("*.py")):
        if path in face:
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "print":
                bad.append(f"{path.relative_to(SRC)}:{node.lineno} print()")
            if (isinstance(node, ast.Attribute) and node.attr in ("stdout", "stderr")
                    and isinstance(node.value, ast.Name) and node.value.id == "sys"):
                bad.append(f"{path.relative_to(SRC)}:{node.lineno} sys.{node.attr}")
    assert bad == [], "\n".join(bad)
