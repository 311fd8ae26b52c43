"""`make` behaves like make: a part is rebuilt only when its part file, a file it names, the source or
the installed versions are newer than its manifest; the depfile a build writes; the worker budget
under `make -jN`.  The Makefile is run with `make -n` in a copy of the project whose outputs are
faked by their manifests' time stamps (nothing is built)."""

from __future__ import annotations

import os
import shutil
import subprocess
import time
from pathlib import Path

import pytest

from propulsor import parallel
from propulsor.cli import main

ROOT = Path(__file__).resolve().parents[1]
needs_make = pytest.mark.skipif(shutil.which("make") is None, reason="make is not installed")


def _touch(path: Path, t: float) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.exists():
        path.write_text("{}\n")
    os.utime(path, (t, t))


@pytest.fixture
def project(tmp_path):
    """A copy of the Makefile, part files and source; the venv stamp and every manifest up to date."""
    for name in ("Makefile", "pyproject.toml", "constraints.txt"):
        shutil.copy2(ROOT / name, tmp_path / name)
    shutil.copytree(ROOT / "parts", tmp_path / "parts")
    shutil.copytree(ROOT / "src", tmp_path / "src", ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    now = time.time()
    for f in list((tmp_path / "src").rglob("*")) + list((tmp_path / "parts").glob("*")) + \
            [tmp_path / n for n in ("Makefile", "pyproject.toml", "constraints.txt")]:
        os.utime(f, (now - 100, now - 100))
    _touch(tmp_path / ".venv" / ".installed", now - 50)
    names = sorted(p.stem for p in (tmp_path / "parts").glob("*.toml"))
    for n in names:
        _touch(tmp_path / "output" / n / "manifest.json", now - 10)
    (tmp_path / "output" / ".deps").mkdir()
    (tmp_path / "output" / ".deps" / "balancer.mk").write_text(
        "output/balancer/manifest.json: parts/balancer.toml parts/road_wheel.toml\n")
    return tmp_path, names, now


def _builds(folder: Path, *targets: str) -> list[str]:
    """The part files `make` would build: queued for the one build process (`echo parts/x.toml >>
    output/.build-queue`), or kits built one by one."""
    r = subprocess.run(["make", "-n", *targets], cwd=folder, capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    queued = [line.split("echo ", 1)[1].split()[0] for line in r.stdout.splitlines()
              if "echo " in line and ".build-queue" in line]
    return sorted(queued + [line.split()[2] for line in r.stdout.splitlines() if " print " in line])


@needs_make
def test_nothing_changed_nothing_built(project):
    folder, names, _ = project
    assert len(names) >= 12
    (folder / "output" / ".built").touch()  # a complete earlier run: every part, then the gallery
    (folder / "output" / "index.html").touch()
    assert _builds(folder) == []
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}  # as a user runs it
    r = subprocess.run(["make", "-n"], cwd=folder, capture_output=True, text=True, timeout=60, env=dict(env, LC_ALL="C"))
    assert r.stdout.strip() == "make: Nothing to be done for 'all'.", r.stdout  # no recipe, not even the queue's
    t0 = time.perf_counter()
    subprocess.run(["make", "-q"], cwd=folder, capture_output=True, timeout=60)
    assert time.perf_counter() - t0 < 5.0  # evaluating the Makefile itself is quick (bench: 0.03 s)


@needs_make
def test_one_part_file_touched_rebuilds_that_part_and_what_reads_it(project):
    folder, names, now = project
    os.utime(folder / "parts" / "ncg_seed002.toml", (now, now))
    assert _builds(folder) == ["parts/ncg_seed002.toml"]
    os.utime(folder / "parts" / "road_wheel.toml", (now, now))  # the balancer names it (its depfile)
    assert _builds(folder) == ["parts/balancer.toml", "parts/ncg_seed002.toml", "parts/road_wheel.toml"]
    assert _builds(folder, "ncg_seed002") == ["parts/ncg_seed002.toml"]


@needs_make
def test_source_or_versions_changed_rebuild_all(project):
    folder, names, now = project
    os.utime(folder / "src" / "propulsor" / "policy.py", (now, now))
    assert _builds(folder) == sorted(f"parts/{n}.toml" for n in names)
    os.utime(folder / "src" / "propulsor" / "policy.py", (now - 100, now - 100))
    os.utime(folder / ".venv" / ".installed", (now, now))
    assert len(_builds(folder)) == len(names)


def test_depfile_names_the_files_a_build_read(tmp_path, monkeypatch):
    parts = tmp_path / "parts"
    shutil.copytree(ROOT / "parts", parts)
    monkeypatch.chdir(tmp_path)
    # a dry run builds nothing and writes no depfile
    assert main(["build", "parts/balancer.toml", "--out", "output/b", "--dry-run", "-q",
                 "--depfile", "output/.deps/b.mk"]) == 0
    assert not (tmp_path / "output" / ".deps" / "b.mk").exists()
    from propulsor.building import write_depfile

    write_depfile(Path("output/.deps/b.mk"), Path("output/b/manifest.json"),
                   (Path("parts/balancer.toml"), tmp_path / "parts" / "road_wheel.toml"))
    assert (tmp_path / "output/.deps/b.mk").read_text() == \
        "output/b/manifest.json: parts/balancer.toml parts/road_wheel.toml\n"


@pytest.mark.parametrize("flags, jobs", [("", None), (" -j2 --jobserver-auth=3,4", 2), ("k -j", 0),
                                         ("--jobs=3", 3), ("-j1", 1), ("n", None)])
def test_make_jobs_read_from_makeflags(flags, jobs):
    assert parallel.make_jobs(flags) == jobs


def test_worker_budget_under_make_j(monkeypatch):
    monkeypatch.delenv("PROPULSOR_JOBS", raising=False)
    monkeypatch.setattr(os, "cpu_count", lambda: 2)
    monkeypatch.setenv("MAKEFLAGS", " -j2 --jobserver-auth=3,4")
    assert parallel.jobs_budget() == 1 and parallel.worker_cap(2) == 0
    assert parallel.fork_pool(2) is None  # two builds on two cores: each runs inline
    monkeypatch.setenv("MAKEFLAGS", "")
    assert parallel.jobs_budget() == 2 and parallel.worker_cap(2) == 2
    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    assert parallel.worker_cap(2) == 0
    done = parallel.start(sum, [1, 2, 3])
    assert isinstance(done, parallel.Done) and done.result() == 6


_STATE: list = []


def _grow_state() -> int:
    _STATE.append(1)
    return len(_STATE)


def test_several_part_files_each_build_from_the_same_process_state():
    """`propulsor build a.toml b.toml`: each build runs in a child forked from the same state, so that it
    writes what a build on its own writes (OCCT numbers STEP assembly occurrences with a process-wide
    counter: in one process the second part's assembly STEP wrapped its lines differently)."""
    from propulsor.batch import in_child

    assert [in_child(_grow_state) for _ in range(3)] == [1, 1, 1] and _STATE == []


def test_several_part_files_exit_with_the_worst_code(tmp_path, capfd):
    bad = tmp_path / "bad.toml"
    bad.write_text('type = "road_wheel"\nrows = 0\n')
    good = ROOT / "parts" / "road_wheel.toml"
    assert main(["build", str(good), str(bad), "--dry-run"]) == 2
    out, err = capfd.readouterr()  # the builds' children write to the file descriptors
    assert "road_wheel.toml is valid" in out and "rows" in err
    assert main(["build", str(good), str(good), "--out", str(tmp_path / "o")]) == 2  # --out names one folder


def _fake_build(args, part_file, depfile) -> int:
    """Stands in for a build: notes when it ran and prints two lines with a pause between them."""
    import sys as _sys

    log = Path(os.environ["FAKE_BUILD_LOG"])
    t0 = time.time()
    print(f"{part_file.stem}: first line", file=_sys.stderr, flush=True)
    time.sleep(0.3)
    pool = parallel.fork_pool(2)  # halfway: the build beside it holds the other slot
    got = pool is not None and pool._max_workers
    if pool is not None:
        pool.shutdown(wait=True)
    time.sleep(0.3)
    print(f"{part_file.stem}: second line", file=_sys.stderr, flush=True)
    with open(log, "a") as f:
        f.write(f"{part_file.stem} {t0} {time.time()} {got}\n")
    return 1 if part_file.stem == "cam_linear" else 0


def test_several_part_files_build_side_by_side_within_the_budget(tmp_path, monkeypatch, capfd):
    """`propulsor build a b c d` on a budget of 2 processes: two builds at a time, the longest (by its size
    estimate) first; a build's own workers only take a slot that is free (none while another build holds
    it, none while builds wait for one); each build's lines come out together; the exit code is the
    worst."""
    import propulsor.cli as cli

    log = tmp_path / "log"
    monkeypatch.setenv("FAKE_BUILD_LOG", str(log))
    monkeypatch.setenv("PROPULSOR_JOBS", "2")
    monkeypatch.delenv("MAKEFLAGS", raising=False)
    monkeypatch.setattr(cli, "build_one", _fake_build)
    names = ["road_wheel", "cam_linear", "balancer", "polysector"]
    assert main(["build", *(str(ROOT / "parts" / f"{n}.toml") for n in names)]) == 1
    rows = [line.split() for line in log.read_text().splitlines()]
    assert sorted(r[0] for r in rows) == sorted(names)
    spans = {r[0]: (float(r[1]), float(r[2])) for r in rows}
    # never more than two at once; the first two started are the two with the largest estimates
    for t in [s for s, _ in spans.values()]:
        assert sum(1 for s, e in spans.values() if s <= t + 1e-3 < e) <= 2
    started = sorted(spans, key=lambda n: spans[n][0])
    assert set(started[:2]) == {"balancer", "polysector"} and started[-1] == "road_wheel"
    # a build that ran beside another got no worker (its slot was taken)...
    assert all(r[3] == "False" for r in rows)
    _, err = capfd.readouterr()
    lines = [ln for ln in err.splitlines() if ": first line" in ln or ": second line" in ln]
    for k in range(0, len(lines), 2):  # ...and the lines of each build come out together
        assert lines[k].split(":")[0] == lines[k + 1].split(":")[0]
    assert parallel.slots_shared() is False


def test_slots_shared_cap_the_workers(monkeypatch):
    monkeypatch.setenv("PROPULSOR_JOBS", "3")
    sem = parallel.share_slots(3)
    try:
        assert sem.acquire(block=False)  # this build's own slot
        assert parallel.fork_pool(4) is None  # builds are still waiting for slots: no worker takes one
        parallel.open_slots_to_workers()
        pool = parallel.fork_pool(4)  # up to the budget, but only two slots are free
        assert pool is not None and pool._max_workers == 2
        assert not sem.acquire(block=False)
        assert parallel.start(sum, [1, 2]).result() == 3  # no slot free: runs inline
        pool.shutdown(wait=True)  # the pool's two slots come back
        assert sem.acquire(block=False) and sem.acquire(block=False)
        assert not parallel.threads_ok()
    finally:
        parallel.share_slots(None)
