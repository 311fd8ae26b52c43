"""The depfile's file names against GNU make itself: every name the escaper writes comes back from make
exactly (a prerequisite newer than its target makes it out of date, an older one does not, a deleted one
rebuilds instead of stopping make), nothing runs from a name, and the names make cannot express are
refused with one line naming the key and the value."""

from __future__ import annotations

import os
import shutil
import subprocess
import time
from pathlib import Path

import pytest

from propulsor.errors import InputError
from propulsor.make_names import READ_VARIABLE, depfile_text, escape, refusal, vet

needs_make = pytest.mark.skipif(shutil.which("make") is None, reason="make is not installed")

#: names make can be given (each as a prerequisite and, with ".out" added, as a target)
NAMEABLE = [
    "plain.toml", "a b.toml", "rw$(shell touch PWNED).toml", "x$(y.toml", "$$.toml", "wheels/rw#1.toml",
    "a:b.toml", "a%b.toml", "a]b.toml", "a|b.toml", "a\\b.toml", "a\\ b.toml", "a\\#b.toml", "a\\%b.toml",
    "a\\|b.toml", "a\\\\:b.toml", "räder.toml", "a'b\"c.toml", "a(b),c.toml", "-x.toml", "a~b.toml",
    "a&b!c.toml", "a`b`@^{}.toml", "sub dir#2/a:b c.toml", "../up.toml", "a\\\\b\\c.toml",
]
#: files a name would also match were make to read it as a pattern (newer than every target)
DECOYS = ["aXb.toml", "ab.toml", "a"]

REFUSED = {
    "rw$(shell\ttouch\tPWNED).toml": "a tab", "a\nb.toml": "a newline", "a\rb.toml": "a carriage return",
    "a;touch PWNED.toml": "a ';'", "SHELL=x.toml": "an '='", "a\\": "a backslash at its end",
    "~root": "a '~' at its start", ".SILENT": "a '.' at its start", ".SECONDEXPANSION": "a '.' at its start",
    "a\x1bb.toml": "a control character", "a\x0bb.toml": "a control character",
    "a\x01b.toml": "a control character", "a*b.toml": "a '*'", "a?b.toml": "a '?'", "a[b].toml": "a '['",
    "a\\*b.toml": "a '*'",
}


def _make(folder: Path, *args: str) -> subprocess.CompletedProcess:
    """`make -q` without the built-in rules: exit 0 up to date, 1 out of date, 2 an error."""
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    return subprocess.run(["make", "-r", "-q", *args], cwd=folder, capture_output=True, timeout=60,
                          env=dict(env, LC_ALL="C"))


def _project(tmp_path: Path, target: str, prereqs: list[str]) -> Path:
    """In tmp_path/run: the prerequisites (old), the target and `check` (newer), decoys (newest), the
    depfile, a Makefile that reads it (a recipe for the target: *.out) and one (check.mk) whose goal
    depends on the read variable."""
    run = tmp_path / "run"
    run.mkdir()
    now = time.time()
    for name, t in [(p, now - 100) for p in prereqs] + [(target, now - 50), ("check", now - 50)] + \
            [(d, now) for d in DECOYS]:
        f = run / name
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text("x")
        os.utime(f, (t, t))
    (run / "dep.mk").write_text(depfile_text(target, prereqs), encoding="utf-8")
    (run / "Makefile").write_text("-include dep.mk\n%.out:\n\t@:\n")
    (run / "check.mk").write_text(f"{READ_VARIABLE} :=\n-include dep.mk\n.DEFAULT_GOAL := check\n"
                                  f"check: $({READ_VARIABLE})\n\ttouch check\n")
    return run


def _files(folder: Path) -> set[str]:
    return {str(p.relative_to(folder.parent)) for p in folder.parent.rglob("*")}


def _read_back(run: Path, target: str, prereqs: list[str]) -> None:
    """make reads back exactly these names: up to date as they are; out of date when any one of them is
    newer than the target or deleted; and no file appears."""
    before = _files(run)
    goals = (("--", target), ("-f", "check.mk"))
    for goal in goals:
        r = _make(run, *goal)
        assert r.returncode == 0, (goal, r.stderr)  # every name found, none newer (the decoys are)
    db = _make(run, "-p").stdout.decode("utf-8", "surrogateescape").splitlines()
    for name in prereqs:
        assert f"{name}:" in db  # its empty rule, named as the file is
    assert any(line.startswith(f"{target}: ") for line in db)
    now = time.time()
    for name in prereqs:
        os.utime(run / name, (now, now))
        for goal in goals:
            assert _make(run, *goal).returncode == 1, (name, goal)
        os.utime(run / name, (now - 100, now - 100))
    assert _files(run) == before  # nothing ran from a name
    for name in prereqs:
        (run / name).rename(run / "gone")
        for goal in goals:
            r = _make(run, *goal)
            assert r.returncode == 1, (name, goal, r.stderr)  # rebuilt, not "No rule to make target"
        (run / "gone").rename(run / name)


@needs_make
@pytest.mark.parametrize("name", NAMEABLE)
def test_make_reads_each_escaped_name_back(tmp_path, name):
    target = (name + ".out" if not name.startswith("..") else "out/" + name[3:] + ".out")
    _read_back(_project(tmp_path, target, [name]), target, [name])


@needs_make
def test_make_reads_many_names_in_one_rule(tmp_path):
    names = [n for n in NAMEABLE if not n.startswith("..")]
    target = "out put#%$|:/manifest.out"
    _read_back(_project(tmp_path, target, names), target, names)


@pytest.mark.parametrize("name, why", sorted(REFUSED.items()))
def test_names_make_cannot_express_are_refused(name, why):
    assert why in (refusal(name) or "")
    with pytest.raises(ValueError):
        escape(name)
    with pytest.raises(InputError) as exc:
        depfile_text("out/manifest.json", ["parts/a.toml", name])
    assert exc.value.value == name
    with pytest.raises(InputError) as exc:
        vet([("part file", "parts/a.toml", "parts/a.toml"), ("road_wheel_file", name + "!", name)])
    msg = str(exc.value)
    assert msg.startswith(f"road_wheel_file = {name + '!'!r}: make cannot name a file with {why}")
    assert msg.endswith("; rename it") and "\n" not in msg and "\t" not in msg


def test_escapes_written():
    """What the depfile holds (make's reading of it is tested above)."""
    assert escape("rw$(shell touch PWNED).toml") == "rw$$(shell\\ touch\\ PWNED).toml"
    assert escape("a#b%c|d") == "a\\#b%c\\|d" and escape("a#b%c|d", target=True) == "a\\#b\\%c|d"
    assert escape("a\\ b\\c") == "a\\\\\\ b\\c"
    assert depfile_text("output/b/manifest.json", ["parts/b.toml", "parts/my wheel.toml"]) == (
        "output/b/manifest.json: parts/b.toml parts/my\\ wheel.toml\n"
        "parts/b.toml:\nparts/my\\ wheel.toml:\n"
        f"{READ_VARIABLE} += parts/b.toml parts/my\\ wheel.toml\n")
