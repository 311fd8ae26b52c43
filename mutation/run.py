"""Mutation testing of the modules whose numbers a user trusts: ``make mutation [MODULE=...]``.

Each target of ``mutation/targets.toml`` names the modules to mutate and the test files that reach them.  For a
target this script copies the project into ``.mutation/<target>/`` (a scratch copy: mutmut rewrites the sources it
mutates), writes mutmut's settings there and runs mutmut (https://github.com/boxed/mutmut), which makes one-line
mutants of every function, finds the tests that call each function, and runs those tests against each mutant.

A mutant the tests notice is *killed*; one they do not is a *survivor*; one in a function no selected test calls has
*no tests* and counts as a survivor.  A mutant that cannot change what the code computes is *equivalent*: it is
recorded once in ``mutation/equivalent.toml`` with the reason and left out of the score, so that the score reads the
same each time.  The score of a module is killed / (killed + survived + no tests), equivalents excluded; a timeout or
a crash of the tests under a mutant is a kill.

The survivors, each with its diff, are written to ``.mutation/<target>/survivors.txt``; the per-module table is printed
and written to ``.mutation/<target>/scores.tsv``.  The exit status is 1 when a module scores below ``--min`` (90 %).

mutmut keeps its results in the scratch copy: a second run re-tests only what changed (new tests, changed functions);
``--fresh`` starts over.  mutmut does not mutate decorated functions (``@property``, ``@njit``, ``@lru_cache``):
their bodies are outside the score.
"""
from __future__ import annotations

import argparse
import fnmatch
import json
import os
import shutil
import subprocess
import sys
import time
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TARGETS = ROOT / "mutation" / "targets.toml"
EQUIVALENT = ROOT / "mutation" / "equivalent.toml"
SCRATCH = ROOT / ".mutation"
MIN_SCORE = 90.0
# copied beside src/ and tests/ into the scratch copy: files the tests read
ALSO_COPY = ["parts/", "studies/", "examples/", "docs/", "README.md", "Makefile", "bench/", "web/src/",
             "constraints.txt"]


@dataclass
class Target:
    name: str
    mutate: list[str]
    tests: list[str]
    deselect: list[str] = field(default_factory=list)
    exclude: list[str] = field(default_factory=list)   # module files (globs) `mutate` matches that another target has

    def modules(self) -> list[str]:
        """The module files (relative to the project) this target mutates."""
        found: list[str] = []
        for pattern in self.mutate:
            for p in sorted(ROOT.glob(pattern)):
                rel = p.relative_to(ROOT).as_posix()
                if any(fnmatch.fnmatch(rel, x) for x in self.exclude):
                    continue
                if p.suffix == ".py" and p.name != "__init__.py" and rel not in found:
                    found.append(rel)
        return found


@dataclass(frozen=True)
class Equivalent:
    module: str
    function: str
    before: str
    after: str
    why: str


def load_targets() -> list[Target]:
    data = tomllib.loads(TARGETS.read_text("utf-8"))
    return [Target(t["name"], list(t["mutate"]), list(t["tests"]), list(t.get("deselect", [])),
                   list(t.get("exclude", []))) for t in data["target"]]


def load_equivalents() -> list[Equivalent]:
    if not EQUIVALENT.exists():
        return []
    data = tomllib.loads(EQUIVALENT.read_text("utf-8"))
    out = []
    for e in data.get("equivalent", []):
        if not str(e.get("why", "")).strip():
            raise SystemExit(f"mutation/equivalent.toml: an equivalent mutant of {e.get('module')} "
                             f"{e.get('function')} has no reason ('why')")
        out.append(Equivalent(e["module"], e["function"], _norm(e["before"]), _norm(e["after"]), e["why"]))
    return out


def _norm(text: str) -> str:
    return "\n".join(" ".join(line.split()) for line in text.strip().splitlines())


def select(targets: list[Target], module: str | None) -> list[tuple[Target, list[str]]]:
    """The targets to run and, for each, its modules (all, or those ``module`` names: a target's name, a file, or a
    glob)."""
    if not module:
        return [(t, t.modules()) for t in targets]
    chosen = []
    for t in targets:
        if module == t.name:
            chosen.append((t, t.modules()))
            continue
        hit = [m for m in t.modules() if m == module or fnmatch.fnmatch(m, module) or m.endswith("/" + module)
               or m.removeprefix("src/").removesuffix(".py").replace("/", ".") == module]
        if hit:
            chosen.append((t, hit))
    if not chosen:
        names = ", ".join(t.name for t in targets)
        raise SystemExit(f"MODULE = {module!r}: no target names it; targets are {names}, or give a module file "
                         f"(src/propulsor/...py) one of them mutates")
    return chosen


def _tracked_files() -> list[str]:
    out = subprocess.run(["git", "ls-files", "-z", "-co", "--exclude-standard"], cwd=ROOT, check=True,
                         capture_output=True).stdout.decode()
    return [f for f in out.split("\0") if f]


def scratch_of(target: Target, modules: list[str]) -> Path:
    """The scratch folder of a target, or of one module of it (mutmut keeps the results of one set of modules)."""
    if sorted(modules) == sorted(target.modules()):
        return SCRATCH / target.name
    return SCRATCH / (target.name + "-" + "-".join(Path(m).stem for m in modules))


def sync_scratch(target: Target, modules: list[str], fresh: bool) -> Path:
    """Copy the project's files into the target's scratch folder (only what changed) and write mutmut's settings."""
    scratch = scratch_of(target, modules)
    if fresh and scratch.exists():
        shutil.rmtree(scratch)
    scratch.mkdir(parents=True, exist_ok=True)
    for rel in _tracked_files():
        if rel.startswith((".mutation/", "output/")):
            continue
        src, dst = ROOT / rel, scratch / rel
        if not src.is_file():
            continue
        if dst.exists() and dst.stat().st_size == src.stat().st_size and dst.read_bytes() == src.read_bytes():
            continue
        dst.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(src, dst)
        # mutmut copies the tests once, when it makes the mutants: a changed test must reach its copy too
        mirror = scratch / "mutants" / rel
        if rel.startswith("tests/") and mirror.parent.exists():
            shutil.copy2(src, mirror)
    pyproject = (ROOT / "pyproject.toml").read_text("utf-8")
    args = ["-q", "-p", "no:cacheprovider", "-m", "not sweep"] + [f"--deselect={d}" for d in target.deselect]
    settings = (
        "\n[tool.mutmut]\n"
        f"only_mutate = {json.dumps(modules)}\n"
        f"also_copy = {json.dumps(ALSO_COPY)}\n"
        f"pytest_add_cli_args_test_selection = {json.dumps(target.tests)}\n"
        f"pytest_add_cli_args = {json.dumps(args)}\n"
        "timeout_multiplier = 10.0\n"
        "timeout_constant = 5.0\n"
    )
    text = pyproject + settings
    path = scratch / "pyproject.toml"
    if not path.exists() or path.read_text("utf-8") != text:
        path.write_text(text, "utf-8")
    return scratch


#: the address space of mutmut and the tests it forks: a mutant that allocates without end (an index array of every
#: pair of boxes squared) fails with MemoryError, a kill, instead of taking the machine's memory from other work
ADDRESS_SPACE_CAP = 8 << 30


def _address_space_cap() -> None:
    import resource

    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    if hard == resource.RLIM_INFINITY or hard > ADDRESS_SPACE_CAP:
        resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE_CAP, hard))


def run_mutmut(scratch: Path, jobs: int, names: list[str]) -> float:
    mutmut = Path(sys.executable).with_name("mutmut")
    env = dict(os.environ)
    env.pop("PYTEST_XDIST_WORKER", None)
    env["PROPULSOR_OCCT_SERIAL"] = "1"  # tests/conftest.py: OCCT on the calling thread (mutmut forks its workers)
    t0 = time.monotonic()
    with open(scratch / "mutmut.log", "w", encoding="utf-8") as log:
        proc = subprocess.run([str(mutmut), "run", "--max-children", str(jobs), *names], cwd=scratch, env=env,
                              stdout=log, stderr=subprocess.STDOUT, preexec_fn=_address_space_cap)
    elapsed = time.monotonic() - t0
    if proc.returncode != 0:
        tail = (scratch / "mutmut.log").read_text("utf-8", "replace").splitlines()[-25:]
        raise SystemExit("mutmut failed (the tests must pass unmutated); the end of "
                         f"{scratch / 'mutmut.log'}:\n" + "\n".join(line[-300:] for line in tail))
    return elapsed


def _tests_hash(scratch: Path, target: Target) -> str:
    """sha256 over the target's test files (and the shared conftest) as the scratch copy has them."""
    import hashlib

    h = hashlib.sha256()
    files = sorted({t.split("::")[0] for t in target.tests} | {"tests/conftest.py"})
    for rel in files:
        p = scratch / rel
        h.update(rel.encode() + b"\0" + (p.read_bytes() if p.exists() else b"") + b"\0")
    return h.hexdigest()


@dataclass
class Score:
    module: str
    killed: int = 0
    survived: int = 0
    no_tests: int = 0
    equivalent: int = 0
    other: int = 0

    @property
    def counted(self) -> int:
        return self.killed + self.survived + self.no_tests

    @property
    def percent(self) -> float:
        return 100.0 * self.killed / self.counted if self.counted else 100.0


KILLED = {"killed", "timeout", "segfault", "suspicious", "caught by type check"}


def read_results(scratch: Path, modules: list[str], equivalents: list[Equivalent]):
    """Scores per module and the survivors (name, module, function, diff) from mutmut's result files."""
    here = os.getcwd()
    os.chdir(scratch)  # mutmut reads its settings from the working folder
    try:
        from mutmut.mutation.diff_apply import get_diff_for_mutant
        from mutmut.stats import status_by_exit_code
        from mutmut.configuration import reset_config
        reset_config()
        scores, survivors, used = [], [], set()
        for module in modules:
            score = Score(module)
            meta = scratch / "mutants" / (module + ".meta")
            if not meta.exists():
                scores.append(score)
                continue
            codes = json.loads(meta.read_text("utf-8"))["exit_code_by_key"]
            for name, code in sorted(codes.items(), key=lambda kv: _natural(kv[0])):
                status = status_by_exit_code[code]
                if status in KILLED:
                    score.killed += 1
                    continue
                if status not in ("survived", "no tests"):
                    score.other += 1
                    continue
                diff = get_diff_for_mutant(name, path=module)
                function = _function_of(name)
                before = _norm("\n".join(l[1:] for l in diff.splitlines() if l.startswith("-")
                                         and not l.startswith("---")))
                after = _norm("\n".join(l[1:] for l in diff.splitlines() if l.startswith("+")
                                        and not l.startswith("+++")))
                eq = next((e for e in equivalents if e.module == module and e.function == function
                           and e.before == before and e.after == after), None)
                if eq is not None:
                    score.equivalent += 1
                    used.add(eq)
                    continue
                if status == "survived":
                    score.survived += 1
                else:
                    score.no_tests += 1
                survivors.append((name, module, function, status, diff))
            scores.append(score)
        return scores, survivors, used
    finally:
        os.chdir(here)


def _natural(name: str):
    head, _, n = name.rpartition("__mutmut_")
    return (head, int(n) if n.isdigit() else 0)


def _function_of(name: str) -> str:
    """``propulsor.laws.ratio_laws.xǁFourierLawǁtheta1__mutmut_91`` -> ``FourierLaw.theta1``."""
    last = name.rsplit(".", 1)[-1].rsplit("__mutmut_", 1)[0]
    if last.startswith("xǁ"):
        return ".".join(last[2:].split("ǁ"))
    return last[2:] if last.startswith("x_") else last


def report(target: Target, scratch: Path, scores: list[Score], survivors, elapsed: float) -> None:
    lines = [f"{'module':<58} {'mutants':>7} {'equiv':>5} {'killed':>6} {'surv':>5} {'no test':>7} {'score':>7}"]
    tsv = ["module\tmutants\tequivalent\tkilled\tsurvived\tno_tests\tscore_percent"]
    for s in scores:
        total = s.counted + s.equivalent + s.other
        lines.append(f"{s.module:<58} {total:>7} {s.equivalent:>5} {s.killed:>6} {s.survived:>5} {s.no_tests:>7} "
                     f"{s.percent:>6.1f}%")
        tsv.append(f"{s.module}\t{total}\t{s.equivalent}\t{s.killed}\t{s.survived}\t{s.no_tests}\t{s.percent:.1f}")
    print(f"\ntarget {target.name}: {elapsed:.0f} s wall (tests: {', '.join(target.tests)})")
    print("\n".join(lines))
    (scratch / "scores.tsv").write_text("\n".join(tsv) + "\n", "utf-8")
    with open(scratch / "survivors.txt", "w", encoding="utf-8") as f:
        for name, module, function, status, diff in survivors:
            f.write(f"# {name} ({status}) {module} {function}\n{diff}\n\n")
    if survivors:
        print(f"survivors and their diffs: {scratch / 'survivors.txt'}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="make mutation", description=__doc__.split("\n\n")[0])
    ap.add_argument("--module", default=os.environ.get("MODULE") or None,
                    help="a target of mutation/targets.toml, a module file or a glob (default: all targets)")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("MUTATION_JOBS", "2")),
                    help="mutants tested side by side (default 2)")
    ap.add_argument("--min", type=float, default=MIN_SCORE, help="the least score of a module, %% (default 90)")
    ap.add_argument("--fresh", action="store_true", help="forget mutmut's earlier results for these targets")
    ap.add_argument("--report-only", action="store_true", help="read the last results, run nothing")
    ap.add_argument("--list", action="store_true", help="list the targets and their modules")
    args = ap.parse_args(argv)
    targets = load_targets()
    if args.list:
        for t in targets:
            print(f"{t.name}: {len(t.modules())} modules; tests {' '.join(t.tests)}")
            for m in t.modules():
                print(f"  {m}")
        return 0
    equivalents = load_equivalents()
    low = []
    all_used = set()
    for target, modules in select(targets, args.module):
        scratch = scratch_of(target, modules)
        elapsed = 0.0
        if args.report_only and not scratch.is_dir():
            print(f"mutation: --report-only: no results of target {target.name} to read ({scratch} does not exist: "
                  "run it first)", file=sys.stderr)
            return 2
        if not args.report_only:
            scratch = sync_scratch(target, modules, args.fresh)
            # results of an earlier run whose tests are unknown (it was stopped before it wrote its stamp)
            unstamped = (not (scratch / "tests.sha256").exists()
                         and any((scratch / "mutants" / (m + ".meta")).exists() for m in modules))
            print(f"target {target.name}: mutating {len(modules)} module(s); mutmut's log: {scratch / 'mutmut.log'}",
                  flush=True)
            elapsed = run_mutmut(scratch, args.jobs, [])
            # mutmut re-tests a mutant when its function changes, not when a test is added: after a change of the
            # tests, the survivors of the last run are tested again, by name
            stamp, now = scratch / "tests.sha256", _tests_hash(scratch, target)
            if unstamped or (stamp.exists() and stamp.read_text() != now):
                _, again, _ = read_results(scratch, modules, equivalents)
                if again:
                    print(f"target {target.name}: the tests changed; {len(again)} survivor(s) tested again", flush=True)
                    elapsed += run_mutmut(scratch, args.jobs, [name for name, *_ in again])
            stamp.write_text(now)
        scores, survivors, used = read_results(scratch, modules, equivalents)
        all_used |= used
        report(target, scratch, scores, survivors, elapsed)
        stale = [e for e in equivalents if e.module in modules and e not in used]
        for e in stale:
            print(f"stale entry in mutation/equivalent.toml (no such surviving mutant): {e.module} {e.function}: "
                  f"{e.before!r} -> {e.after!r}")
        low += [s for s in scores if s.percent < args.min]
    if low:
        print(f"\n{len(low)} module(s) below {args.min:.0f} %: " + ", ".join(f"{s.module} {s.percent:.1f} %"
                                                                          for s in low))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
