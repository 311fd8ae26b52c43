"""Hand-made mutants (issue 36): ``make mutation-handmade``.

``mutation/handmade.toml`` lists one-line mutants of the modules whose numbers a user trusts, written from the
source alone (without reading the tests).  For each mutant this script

* checks that the original text is still on its line (else the mutant is reported *stale* and skipped);
* applies it to a scratch copy of ``src/`` (a temporary folder put first on PYTHONPATH of the pytest subprocess;
  the project tree is never changed; no bytecode written, numba's cache in the scratch folder);
* runs the tests that reach it, chosen automatically from ``tests/``: first the test files whose name carries the
  module's name and that mention the module, then -- only if those all pass -- the other test files that import
  the module by its dotted name or name the function the mutated line lives in (the package named too);
  each tier with ``-x``, tests marked sweep / slicer / browser left out, and a timeout (a timeout is a kill);
* records killed (a failure, an error or a timeout) or survived (every selected test passed).

A mutant with ``equivalent = "reason"`` is left out of the score.  Each mutant belongs to a round (``round = N``;
none given: round 1): ``--round N`` runs, lists and reports the mutants of that round only (each round written
blind, from the sources, after the previous one's gaps were closed).  The table per module group (mutants,
equivalent, killed, survived, score = killed / (killed + survived)) is printed and written, with the survivors and
their diffs, to ``.mutation/handmade/``.  Exit status 1 when the total score is below ``--min`` (90 %).

    python mutation/handmade.py                 # every mutant
    python mutation/handmade.py --only ID ...   # some mutants
    python mutation/handmade.py --survivors     # re-run the survivors of the last run (after new tests)
    python mutation/handmade.py --report-only   # print the last results again
    python mutation/handmade.py --list          # the mutants and the tests each would run
    python mutation/handmade.py --round 2 ...   # any of the above for the mutants of one round
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SPEC = ROOT / "mutation" / "handmade.toml"
OUT = ROOT / ".mutation" / "handmade"
RESULTS = OUT / "results.json"
TESTS = ROOT / "tests"
MARKERS = "not sweep and not slicer and not browser"
MIN_SCORE = 90.0


def load() -> list[dict]:
    """The mutants, each at the line that holds its original text now: its own line, else the one line of the file
    that holds that text exactly (an edit above it moved it; ``moved_from`` keeps the written line); a text found on
    no line or on several stays at its line and is reported stale."""
    mutants = tomllib.loads(SPEC.read_text())["mutant"]
    for m in mutants:
        lines = (ROOT / m["file"]).read_text().split("\n")
        if len(lines) >= m["line"] and lines[m["line"] - 1] == m["original"]:
            continue
        hits = [i + 1 for i, line in enumerate(lines) if line == m["original"]]
        if len(hits) == 1:
            m["moved_from"], m["line"] = m["line"], hits[0]
    return mutants


def round_of(m: dict) -> int:
    """The round a mutant was written in (round-1 entries carry no field)."""
    return int(m.get("round", 1))


def module_of(file: str) -> str:
    """src/propulsor/laws/walking.py -> propulsor.laws.walking"""
    return file.removeprefix("src/").removesuffix(".py").replace("/", ".")


def enclosing_function(lines: list[str], i: int) -> str | None:
    """Name of the def the 0-based line i lives in (None at module level)."""
    ind = len(lines[i]) - len(lines[i].lstrip())
    for k in range(i - 1, -1, -1):
        s = lines[k]
        if not s.strip():
            continue
        k_ind = len(s) - len(s.lstrip())
        m = re.match(r"\s*(?:async\s+)?def\s+(\w+)", s)
        if m and k_ind < ind:
            return m.group(1)
        if k_ind == 0 and not s.startswith(("@", "#")) and not m:
            return None
    return None


_texts: dict[Path, str] = {}


def _text(p: Path) -> str:
    if p not in _texts:
        _texts[p] = p.read_text(errors="replace")
    return _texts[p]


def select_tests(m: dict, depth: int = 0) -> tuple[list[str], list[str]]:
    """(tier 1, tier 2) test files (relative to the project) for a mutant (see the module docstring)."""
    file = m["file"]
    dotted = module_of(file)
    pkg, stem = dotted.rsplit(".", 1)
    lines = (ROOT / file).read_text().splitlines()
    func = enclosing_function(lines, m["line"] - 1) if depth == 0 else None
    mentions = re.compile(rf"{re.escape(dotted)}\b|from\s+{re.escape(pkg)}\s+import\s[^\n]*\b{stem}\b"
                          rf"|from\s+{re.escape(pkg)}\s+import\s*\([^)]*\b{stem}\b")
    by_func = re.compile(rf"\b{re.escape(func)}\b") if func and len(func) >= 4 and not func.startswith("__") else None
    # the words of the module's name that say what it is about (final_drive/strength: final_drive, strength)
    words = [w for w in dotted.split(".")[1:] if w not in ("parts", "laws", "gears", "checks", "motion", "study",
                                                          "printing", "design")]
    tier1, tier2 = [], []
    for p in sorted(TESTS.glob("test_*.py")):
        t = _text(p)
        hit = bool(mentions.search(t)) or (by_func is not None and pkg in t and bool(by_func.search(t)))
        if not hit:
            continue
        named = any(w in p.stem for w in words) or stem in p.stem
        (tier1 if named else tier2).append(p.relative_to(ROOT).as_posix())
    if not tier1:
        tier1, tier2 = tier2, []
    if not tier1 and depth < 2:
        # no test names the module: the tests of the modules that import it (one level up, then two)
        for imp in importers(file):
            a, b = select_tests({"file": imp, "line": 1}, depth + 1)
            tier1 += [t for t in a + b if t not in tier1]
    return sorted(tier1, key=_cost), sorted(tier2, key=_cost)


#: test files that build whole parts or kits (minutes each) run after the unit tests of a tier
_SLOW = ("part_", "gallery", "animation", "glb", "build", "kit", "user_solids", "viewer", "polysector_part")


def _cost(f: str) -> tuple:
    return (any(w in f for w in _SLOW), f)


def importers(file: str) -> list[str]:
    """Source files (relative to the project) that import the module ``file``."""
    dotted = module_of(file)
    stem = dotted.rsplit(".", 1)[1]
    pat = re.compile(rf"^\s*(from\s+[\w.]*\b{stem}\b\s+import|from\s+[\w.]+\s+import\s[^\n]*\b{stem}\b"
                     rf"|import\s+{re.escape(dotted)}\b)", re.M)
    out = []
    for p in sorted((ROOT / "src").rglob("*.py")):
        rel = p.relative_to(ROOT).as_posix()
        if rel != file and pat.search(_text(p)):
            out.append(rel)
    return out


def apply(scratch: Path, m: dict, mutated: bool) -> None:
    src = (ROOT / m["file"]).read_text()
    if mutated:
        lines = src.split("\n")
        lines[m["line"] - 1] = m["mutated"]
        src = "\n".join(lines)
    (scratch / m["file"]).write_text(src)


def run_tests(scratch: Path, files: list[str], timeout: float) -> tuple[str, float, str]:
    """('killed' | 'passed' | 'none', seconds, last lines of the output)."""
    env = dict(os.environ, PYTHONPATH=str(scratch / "src"), PYTHONDONTWRITEBYTECODE="1",
               NUMBA_CACHE_DIR=str(scratch / "numba_cache"), MPLBACKEND="Agg")
    cmd = [sys.executable, "-m", "pytest", "-q", "-x", "-p", "no:cacheprovider", "-m", MARKERS, *files]
    t0 = time.perf_counter()
    try:
        r = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=timeout,
                           start_new_session=True)
    except subprocess.TimeoutExpired as e:
        tail = (e.stdout or b"")[-400:] if isinstance(e.stdout, bytes) else (e.stdout or "")[-400:]
        return "killed", time.perf_counter() - t0, f"timeout after {timeout:g} s {tail!s}"
    dt = time.perf_counter() - t0
    tail = "\n".join(r.stdout.strip().splitlines()[-6:])
    if r.returncode == 0:
        return "passed", dt, tail
    if r.returncode == 5:
        return "none", dt, tail
    if r.returncode == 4:
        raise RuntimeError(f"pytest usage error: {' '.join(cmd)}\n{r.stdout}\n{r.stderr}")
    return "killed", dt, tail


def table(mutants: list[dict], res: dict) -> tuple[str, float]:
    groups: dict[tuple[int, str], list[int]] = {}
    for m in mutants:
        # mutants, equivalent, killed, survived, stale
        g = groups.setdefault((round_of(m), m["group"]), [0, 0, 0, 0, 0])
        g[0] += 1
        st = res.get(m["id"], {}).get("status")
        if "equivalent" in m:
            g[1] += 1
        elif st == "killed":
            g[2] += 1
        elif st == "survived":
            g[3] += 1
        elif st == "stale":
            g[4] += 1
    rows = ["| round | group | mutants | equivalent | killed | survived | stale | score |",
            "|---|---|---|---|---|---|---|---|"]
    tot = [0, 0, 0, 0, 0]
    for (rnd, name), g in groups.items():
        tot = [a + b for a, b in zip(tot, g)]
        sc = 100.0 * g[2] / (g[2] + g[3]) if g[2] + g[3] else float("nan")
        rows.append(f"| {rnd} | {name} | {g[0]} | {g[1]} | {g[2]} | {g[3]} | {g[4]} | {sc:.1f} % |")
    score = 100.0 * tot[2] / (tot[2] + tot[3]) if tot[2] + tot[3] else float("nan")
    rounds = "+".join(str(r) for r in sorted({r for r, _ in groups}))
    rows.append(f"| {rounds} | **total** | {tot[0]} | {tot[1]} | {tot[2]} | {tot[3]} | {tot[4]} | **{score:.1f} %** |")
    return "\n".join(rows), score


def report(mutants: list[dict], res: dict) -> float:
    text, score = table(mutants, res)
    print(text)
    surv = []
    for m in mutants:
        r = res.get(m["id"], {})
        if "equivalent" not in m and r.get("status") == "survived":
            surv.append(f"{m['id']}  (round {round_of(m)})  {m['file']}:{m['line']}  ({m['why']})\n"
                        f"- {m['original'].strip()}\n"
                        f"+ {m['mutated'].strip()}\n  tests run: {' '.join(r.get('tests', []))}\n")
        if r.get("status") == "stale":
            print(f"STALE {m['id']}: the original text is no longer on {m['file']}:{m['line']}")
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "survivors.txt").write_text("\n".join(surv) or "no survivors\n")
    (OUT / "scores.md").write_text(text + "\n")
    if surv:
        print(f"\n{len(surv)} survivor(s), with their diffs, in {(OUT / 'survivors.txt').relative_to(ROOT)}")
    return score


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--only", nargs="*", default=None, help="mutant ids")
    ap.add_argument("--survivors", action="store_true", help="re-run the survivors of the last run")
    ap.add_argument("--report-only", action="store_true")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--round", type=int, default=None, help="only the mutants of this round (no field: round 1)")
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds per test tier (a timeout is a kill)")
    ap.add_argument("--min", type=float, default=MIN_SCORE)
    a = ap.parse_args(argv)

    mutants = load()
    ids = [m["id"] for m in mutants]
    if len(set(ids)) != len(ids):
        raise SystemExit("duplicate mutant ids in handmade.toml")
    if a.round is not None:
        mutants = [m for m in mutants if round_of(m) == a.round]
        if not mutants:
            raise SystemExit(f"no mutant of round {a.round} in handmade.toml")
    res = json.loads(RESULTS.read_text()) if RESULTS.exists() else {}
    if a.list:
        for m in mutants:
            lines = (ROOT / m["file"]).read_text().split("\n")
            stale = len(lines) < m["line"] or lines[m["line"] - 1] != m["original"]
            t1, t2 = select_tests(m)
            print(f"r{round_of(m)}", m["id"], "STALE |" if stale else "|", " ".join(Path(t).stem for t in t1), "||",
                  " ".join(Path(t).stem for t in t2))
        return 0
    if a.report_only:
        return 0 if report(mutants, res) >= a.min else 1

    todo = [m for m in mutants if "equivalent" not in m]
    if a.only is not None:
        todo = [m for m in todo if m["id"] in set(a.only)]
    elif a.survivors:
        todo = [m for m in todo if res.get(m["id"], {}).get("status") != "killed"]
    t_all = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="handmade-") as tmp:
        scratch = Path(tmp)
        shutil.copytree(ROOT / "src", scratch / "src", ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        for n, m in enumerate(todo, 1):
            lines = (ROOT / m["file"]).read_text().split("\n")
            if len(lines) < m["line"] or lines[m["line"] - 1] != m["original"]:
                res[m["id"]] = {"status": "stale"}
                print(f"[{n}/{len(todo)}] {m['id']}: STALE")
                continue
            t1, t2 = select_tests(m)
            apply(scratch, m, True)
            try:
                ran, status, secs, tail = [], "survived", 0.0, ""
                for tier in (t1, t2):
                    if not tier:
                        continue
                    ran += tier
                    out, dt, tail = run_tests(scratch, tier, a.timeout)
                    secs += dt
                    if out == "killed":
                        status = "killed"
                        break
            finally:
                apply(scratch, m, False)
            if not ran:
                status = "survived"
                tail = "no test file reaches this module"
            res[m["id"]] = {"status": status, "seconds": round(secs, 1), "tests": ran, "tail": tail}
            print(f"[{n}/{len(todo)}] {m['id']}: {status} ({secs:.0f} s, {len(ran)} test files)", flush=True)
            OUT.mkdir(parents=True, exist_ok=True)
            RESULTS.write_text(json.dumps(res, indent=1))
    print(f"\nwall time {time.perf_counter() - t_all:.0f} s\n")
    return 0 if report(mutants, res) >= a.min else 1


if __name__ == "__main__":
    sys.exit(main())
