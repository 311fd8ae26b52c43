"""Record survivors of a mutation run as equivalent mutants, by rules, with their reasons.

    python mutation/add_equivalents.py LABEL .mutation/<scratch>/survivors.txt RULES.py [--dry-run]

RULES.py defines ``RULES``: a list of ``(after_regex, function_regex_or_None, why)``.  A survivor whose mutated line
(after, whitespace folded) matches ``after_regex`` (re.search) and whose function matches ``function_regex``
(re.fullmatch; None: any) is appended to ``mutation/equivalent.toml`` under a ``# --- LABEL`` heading with ``why``,
once (an entry already recorded is skipped).  The first matching rule wins.  Read every survivor before writing a
rule: a rule records a claim that no input the code gets can tell the mutant apart.
"""
from __future__ import annotations

import argparse
import re
import runpy
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from run import EQUIVALENT, _norm, load_equivalents  # noqa: E402

HEAD = re.compile(r"^# (\S+) \((survived|no tests)\) (\S+) (\S+)$")


def survivors(path: Path):
    """(name, module, function, before, after) of each survivor in a survivors.txt."""
    blocks = path.read_text("utf-8").split("\n# ")
    for i, block in enumerate(blocks):
        text = block if i == 0 else "# " + block
        lines = text.splitlines()
        m = HEAD.match(lines[0]) if lines else None
        if not m:
            continue
        diff = lines[1:]
        before = _norm("\n".join(l[1:] for l in diff if l.startswith("-") and not l.startswith("---")))
        after = _norm("\n".join(l[1:] for l in diff if l.startswith("+") and not l.startswith("+++")))
        yield m.group(1), m.group(3), m.group(4), before, after


def _toml_str(s: str) -> str:
    if "\n" in s or ("'" in s and '"' in s):
        return '"""' + s.replace("\\", "\\\\").replace('"""', '\\"\\"\\"') + '"""'
    if "'" not in s:
        return "'" + s + "'"
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("label")
    ap.add_argument("survivors", type=Path)
    ap.add_argument("rules", type=Path)
    ap.add_argument("--dry-run", action="store_true")
    a = ap.parse_args(argv)
    rules = runpy.run_path(str(a.rules))["RULES"]
    known = {(e.module, e.function, e.before, e.after) for e in load_equivalents()}
    out, unmatched = [], 0
    for name, module, function, before, after in survivors(a.survivors):
        rule = next((r for r in rules if re.search(r[0], after)
                     and (r[1] is None or re.fullmatch(r[1], function))), None)
        if rule is None:
            unmatched += 1
            continue
        key = (module, function, before, after)
        if key in known:
            continue
        known.add(key)
        out.append(f"\n[[equivalent]]\nmodule = {_toml_str(module)}\nfunction = {_toml_str(function)}\n"
                   f"before = {_toml_str(before)}\nafter = {_toml_str(after)}\nwhy = {_toml_str(rule[2])}\n")
        print(f"{name}: {after[:100]}")
    print(f"{len(out)} new equivalents, {unmatched} survivors matched no rule")
    if out and not a.dry_run:
        with open(EQUIVALENT, "a", encoding="utf-8") as f:
            f.write(f"\n# --- {a.label} " + "-" * max(3, 113 - len(a.label)) + "\n")
            f.writelines(out)
        load_equivalents()  # the file still parses
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
