"""`make` behaves like make: a part is rebuilt only when its part file, a file it names, the source or
the installed versions are newer than its manifest; the depfile a build writes; the worker budget
under `make -jN`.  The Makefile is run with `make -n` in a copy of the project whose outputs are
faked by their manifests' time stamps (nothing is built)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
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
    _depfile(tmp_path, "balancer", "parts/balancer.toml", "parts/road_wheel.toml")
    return tmp_path, names, now


def _depfile(folder: Path, name: str, *files: str) -> None:
    """output/.deps/<name>.mk as a build of parts/<name>.toml that read `files` writes it."""
    from propulsor.building import write_depfile

    here = os.getcwd()
    os.chdir(folder)
    try:
        write_depfile(Path("output/.deps") / f"{name}.mk", Path("output") / name / "manifest.json",
                      [Path(f) for f in files])
    finally:
        os.chdir(here)


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
        "output/b/manifest.json: parts/balancer.toml parts/road_wheel.toml\n" \
        "parts/balancer.toml:\nparts/road_wheel.toml:\n" \
        "PROPULSOR_READ += parts/balancer.toml parts/road_wheel.toml\n"


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


def _fake_build(args, part_file, depfile, gallery=True) -> int:
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
    monkeypatch.chdir(tmp_path)  # nothing written, so no gallery: not the checkout's output/ either
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
    slots = parallel.share_slots(3)
    try:
        own = slots.take(timeout=0)  # this build's own slot
        assert own is not None
        assert parallel.fork_pool(4) is None  # builds are still waiting for slots: no worker takes one
        parallel.open_slots_to_workers()
        pool = parallel.fork_pool(4)  # up to the budget, but only two slots are free
        assert pool is not None and pool._max_workers == 2
        assert slots.take(timeout=0) is None
        assert parallel.start(sum, [1, 2]).result() == 3  # no slot free: runs inline
        pool.shutdown(wait=True)  # the pool's two slots come back
        assert slots.take(timeout=0) is not None and slots.take(timeout=0) is not None
        assert not parallel.threads_ok()
    finally:
        parallel.share_slots(None)


@pytest.fixture
def jobserver_pipe(monkeypatch):
    """make's jobserver as make 4.3 hands it to a `+` recipe: a pipe holding the free tokens, named in
    MAKEFLAGS.  Yields a function that puts k tokens in and gives the number of tokens in the pipe."""
    r, w = os.pipe()
    monkeypatch.setenv("MAKEFLAGS", f" -j3 --jobserver-auth={r},{w}")
    monkeypatch.delenv("PROPULSOR_JOBS", raising=False)

    def tokens(put: int = 0) -> int:
        os.write(w, b"+" * put)
        os.set_blocking(r, False)
        try:
            got = os.read(r, 64)
        except BlockingIOError:
            got = b""
        os.set_blocking(r, True)
        os.write(w, got)
        return len(got)

    yield tokens
    os.close(r)
    os.close(w)


def test_jobserver_tokens_taken_without_waiting_and_given_back(jobserver_pipe):
    assert jobserver_pipe(2) == 2
    js = parallel.Jobserver.from_makeflags()
    assert js is not None
    got = [js.take(), js.take()]
    assert got == [b"+", b"+"] and js.take() is None  # make has no third token: no wait
    assert jobserver_pipe() == 0
    for tok in got:
        js.give(tok)
    assert jobserver_pipe() == 2
    # a recipe not marked `+` (the descriptors closed, or other files now), -j1, no -j: no jobserver
    assert parallel.Jobserver.from_makeflags(" -j2 --jobserver-auth=97,98") is None
    with open(__file__) as f:
        assert parallel.Jobserver.from_makeflags(f" -j2 --jobserver-auth={f.fileno()},{f.fileno()}") is None
    assert parallel.Jobserver.from_makeflags(" -j1") is None and parallel.Jobserver.from_makeflags("") is None


def test_slots_under_the_jobserver_take_make_s_tokens(jobserver_pipe):
    """A budget of 4 processes but one token free: the command's own slot and one more; a worker pool gets
    a slot only while a token is free, and each goes back to make."""
    jobserver_pipe(1)
    slots = parallel.share_slots(4, parallel.Jobserver.from_makeflags())
    try:
        own = slots.take(timeout=0)
        assert own == b"" and parallel.jobs_budget() == 4
        parallel.open_slots_to_workers()
        pool = parallel.fork_pool(3)
        assert pool is not None and pool._max_workers == 1 and jobserver_pipe() == 0
        assert parallel.fork_pool(1) is None  # no token: inline
        pool.shutdown(wait=True)
        assert jobserver_pipe() == 1
        slots.give(own)
    finally:
        parallel.share_slots(None)


@pytest.mark.parametrize("tokens", [0, 1])
def test_several_part_files_under_make_s_jobserver(tmp_path, monkeypatch, capfd, jobserver_pipe, tokens):
    """`make -jN` hands the build command its jobserver: builds run side by side only on make's tokens
    (cores permitting), and every token goes back to make."""
    import propulsor.cli as cli

    log = tmp_path / "log"
    monkeypatch.setenv("FAKE_BUILD_LOG", str(log))
    monkeypatch.setattr(os, "cpu_count", lambda: 4)
    monkeypatch.setattr(cli, "build_one", _fake_build)
    monkeypatch.chdir(tmp_path)
    jobserver_pipe(tokens)
    names = ["road_wheel", "cam_linear", "balancer"]
    assert main(["build", "-q", *(str(ROOT / "parts" / f"{n}.toml") for n in names)]) == 1
    rows = [line.split() for line in log.read_text().splitlines()]
    spans = [(float(r[1]), float(r[2])) for r in rows]
    at_once = max(sum(1 for s, e in spans if s <= t + 1e-3 < e) for t, _ in spans)
    assert at_once == 1 + tokens
    assert jobserver_pipe() == tokens
    capfd.readouterr()


@needs_make
def test_make_hands_its_jobserver_to_the_build_and_runs_no_recipe_under_n(project):
    """The build recipe is marked `+`: under `make -j3` the build command finds make's jobserver (2 free
    tokens); `make -n` with a queue left by an interrupted run names it and builds nothing."""
    folder, _, now = project
    fake = folder / ".venv" / "bin" / "propulsor"
    fake.parent.mkdir(parents=True, exist_ok=True)
    fake.write_text(f"#!{sys.executable}\nimport sys\nfrom propulsor.parallel import Jobserver\n"
                    "js = Jobserver.from_makeflags()\ntoks = [t for t in iter(js.take, None)] if js else []\n"
                    "[js.give(t) for t in toks]\n"
                    "open('built.txt', 'a').write(f'{len(toks)} {sys.argv[2:-4]} {sys.argv[-4:-2]}\\n')\n")
    fake.chmod(0o755)
    os.utime(folder / "parts" / "cam_linear.toml", (now, now))
    os.utime(folder / "parts" / "road_wheel.toml", (now, now))
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    env["PYTHONPATH"] = str(ROOT / "src")
    (folder / "output" / ".build-queue").write_text("parts/road_wheel.toml\n")
    r = subprocess.run(["make", "-n", "parts"], cwd=folder, capture_output=True, text=True, timeout=60, env=env)
    assert r.returncode == 0 and "would build: parts/road_wheel.toml" in r.stdout, r.stdout + r.stderr
    assert not (folder / "built.txt").exists()
    r = subprocess.run(["make", "-j3", "parts"], cwd=folder, capture_output=True, text=True, timeout=60, env=env)
    assert r.returncode == 0, r.stdout + r.stderr
    assert (folder / "built.txt").read_text().split("\n")[0] == \
        "2 ['parts/balancer.toml', 'parts/cam_linear.toml', 'parts/road_wheel.toml'] ['--out-dir', 'output']"


def _fake_propulsor(folder: Path) -> Path:
    """.venv/bin/propulsor that notes the part files it was asked to build and writes their manifests."""
    fake = folder / ".venv" / "bin" / "propulsor"
    fake.parent.mkdir(parents=True, exist_ok=True)
    fake.write_text(f"#!{sys.executable}\nimport sys, pathlib\n"
                    "files = [a for a in sys.argv[2:] if a.endswith('.toml')]\n"
                    "open('built.txt', 'a').write(' '.join(files) + '\\n')\n"
                    "for f in files:\n"
                    "    m = pathlib.Path('output') / pathlib.Path(f).stem / 'manifest.json'\n"
                    "    m.parent.mkdir(parents=True, exist_ok=True); m.write_text('{}')\n")
    fake.chmod(0o755)
    return fake


@needs_make
def test_make_builds_an_edited_part_file_for_real_and_then_nothing(project):
    """Not `make -n` but make itself: the queue of out-of-date parts is built (a manifest whose recipe only
    queued its part keeps its time stamp, and make would not remake .built for it), once."""
    folder, names, now = project
    _fake_propulsor(folder)
    _touch(folder / "output" / ".built", now - 5)
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}

    def make_parts() -> list[str]:
        before = (folder / "built.txt").read_text().splitlines() if (folder / "built.txt").exists() else []
        r = subprocess.run(["make", "parts"], cwd=folder, capture_output=True, text=True, timeout=60, env=env)
        assert r.returncode == 0, r.stdout + r.stderr
        after = (folder / "built.txt").read_text().splitlines() if (folder / "built.txt").exists() else []
        return after[len(before):]

    assert make_parts() == []
    os.utime(folder / "parts" / "ncg_seed002.toml", (now, now))
    assert make_parts() == ["parts/ncg_seed002.toml"]
    assert make_parts() == []
    t = time.time()  # after the last run's stamp, not in the future
    os.utime(folder / "parts" / "road_wheel.toml", (t, t))  # the balancer read it (its depfile)
    assert make_parts() == ["parts/balancer.toml parts/road_wheel.toml"]
    assert make_parts() == [] and not (folder / "output" / ".build-queue").exists()
    shutil.rmtree(folder / "output" / "cam_linear")  # an output folder deleted: built again
    assert make_parts() == ["parts/cam_linear.toml"]
    assert make_parts() == []


def _clean_env() -> dict:
    return {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}


def _make_parts(folder: Path, *goals: str) -> list[str]:
    """The part files `make` (with a stand-in propulsor) built in one run; asserts that make succeeded."""
    log = folder / "built.txt"
    before = log.read_text().splitlines() if log.exists() else []
    r = subprocess.run(["make", *(goals or ("parts",))], cwd=folder, capture_output=True, text=True, timeout=60,
                       env=_clean_env())
    assert r.returncode == 0, r.stdout + r.stderr
    after = log.read_text().splitlines() if log.exists() else []
    return after[len(before):]


def _name_road_wheel(folder: Path, name: str) -> Path:
    """parts/balancer.toml names parts/<name> (a copy of the road wheel) as its road_wheel_file."""
    part = folder / "parts" / "balancer.toml"
    part.write_text(part.read_text().replace('road_wheel_file = "road_wheel.toml"',
                                             f'road_wheel_file = "{name}"'))
    wheel = folder / "parts" / name
    wheel.parent.mkdir(parents=True, exist_ok=True)
    shutil.copy2(folder / "parts" / "road_wheel.toml", wheel)
    return wheel


@needs_make
def test_a_file_name_that_would_run_code_is_refused_and_make_runs_nothing(project, monkeypatch, capfd):
    """A road-wheel file named `rw$(shell<TAB>touch<TAB>PWNED).toml`: make cannot name it (a tab), so the
    build refuses it before building (exit 2, one line with the key and the value, nothing written), and
    no `make` creates PWNED."""
    folder, _, now = project
    _fake_propulsor(folder)
    _touch(folder / "output" / ".built", now - 5)
    _name_road_wheel(folder, "wheels/rw$(shell\ttouch\tPWNED).toml")
    monkeypatch.chdir(folder)
    capfd.readouterr()
    assert main(["build", "parts/balancer.toml", "-q", "--out", "output/b", "--depfile", "output/.deps/b.mk"]) == 2
    err = capfd.readouterr().err
    assert err == "propulsor: error: road_wheel_file = 'wheels/rw$(shell\\ttouch\\tPWNED).toml': make cannot name a " \
                  "file with a tab; rename it\n"
    assert not (folder / "output" / "b").exists() and not (folder / "output" / ".deps" / "b.mk").exists()
    r = subprocess.run(["make", "-n", "list"], cwd=folder, capture_output=True, text=True, timeout=60,
                       env=_clean_env())
    assert r.returncode == 0, r.stderr
    assert _make_parts(folder) == ["parts/balancer.toml"]  # the stand-in builds what the real one refuses
    assert not list(folder.rglob("PWNED"))


@needs_make
def test_make_with_a_named_file_whose_name_holds_make_s_characters(project):
    """A named file `wheels/rw#1 $(shell touch PWNED).toml`: its depfile makes make neither stop ("No rule
    to make target 'wheels/rw'") nor run anything; touching the file rebuilds the part that reads it."""
    folder, _, now = project
    _fake_propulsor(folder)
    _touch(folder / "output" / ".built", now - 5)
    wheel = _name_road_wheel(folder, "wheels/rw#1 $(shell touch PWNED).toml")
    os.utime(wheel, (now - 100, now - 100))
    os.utime(folder / "parts" / "balancer.toml", (now - 100, now - 100))
    _depfile(folder, "balancer", "parts/balancer.toml", str(wheel.relative_to(folder)))
    r = subprocess.run(["make", "-n", "list"], cwd=folder, capture_output=True, text=True, timeout=60,
                       env=_clean_env())
    assert r.returncode == 0, r.stderr
    assert _make_parts(folder) == []
    t = time.time()
    os.utime(wheel, (t, t))
    assert _make_parts(folder) == ["parts/balancer.toml"]
    assert _make_parts(folder) == []
    assert not list(folder.rglob("PWNED"))


@needs_make
def test_make_after_a_built_part_file_is_deleted_or_renamed(project):
    """Depfiles of part files deleted or renamed are not read; a deleted file that a build read makes that
    part out of date (make runs its build, which says what is missing) instead of stopping make."""
    folder, names, now = project
    _fake_propulsor(folder)
    _touch(folder / "output" / ".built", now - 5)
    for n in names:
        _depfile(folder, n, f"parts/{n}.toml", *(["parts/road_wheel.toml"] if n == "balancer" else []))
    assert _make_parts(folder) == []
    (folder / "parts" / "cam_quadratic.toml").unlink()
    assert _make_parts(folder) == []
    (folder / "parts" / "cam_linear.toml").rename(folder / "parts" / "cam_linear2.toml")
    assert _make_parts(folder) == ["parts/cam_linear2.toml"]
    assert _make_parts(folder) == []
    (folder / "parts" / "road_wheel.toml").unlink()  # the balancer read it
    assert _make_parts(folder) == ["parts/balancer.toml"]


@needs_make
@pytest.mark.parametrize("name", ["my part.toml", "a$(touch PWNED).toml", "a;touch PWNED;.toml", "a#b.toml",
                                  "a:b.toml", "a%b.toml", "a=b.toml", "a*.toml", "a\\b.toml", "a'b.toml"])
def test_make_refuses_a_part_file_name_it_cannot_handle(project, name):
    """make says which part file it cannot name, in one line, and stops before it reads one (nothing
    built, nothing run from the name); `propulsor build` still takes the file."""
    folder, _, _ = project
    _fake_propulsor(folder)
    shutil.copy2(folder / "parts" / "road_wheel.toml", folder / "parts" / name)
    for goals in (["-n", "list"], ["parts"]):
        r = subprocess.run(["make", *goals], cwd=folder, capture_output=True, text=True, timeout=60,
                           env=dict(_clean_env(), LC_ALL="C"))
        assert r.returncode == 2 and r.stdout == ""
        assert len(r.stderr.splitlines()) == 1 and f"'parts/{name}': make cannot name a part file" in r.stderr
    assert not list(folder.rglob("PWNED")) and not (folder / "built.txt").exists()


def test_propulsor_build_takes_a_part_file_make_cannot_name(tmp_path, monkeypatch, capfd):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "parts").mkdir()
    shutil.copy2(ROOT / "parts" / "road_wheel.toml", tmp_path / "parts" / "my wheel;1.toml")
    assert main(["build", "parts/my wheel;1.toml", "--dry-run"]) == 0
    assert "is valid" in capfd.readouterr().out
    # a depfile is for make: the file is refused before anything is built
    assert main(["build", "parts/my wheel;1.toml", "--depfile", "x.mk", "--dry-run"]) == 2
    assert "part file = 'parts/my wheel;1.toml': make cannot name a file with a ';'" in capfd.readouterr().err


@needs_make
def test_make_builds_a_part_file_named_in_another_alphabet(project):
    folder, _, now = project
    _fake_propulsor(folder)
    _touch(folder / "output" / ".built", now - 5)
    shutil.copy2(folder / "parts" / "road_wheel.toml", folder / "parts" / "räder-2.toml")
    assert _make_parts(folder) == ["parts/räder-2.toml"]
    assert _make_parts(folder) == []


@needs_make
def test_make_builds_into_the_out_folder_it_is_given(project):
    """`make OUT=alt`: the build command is told --out-dir alt, so the manifests make waits for (alt/<name>/) are
    the ones written, and a second run builds nothing (the builds went to output/ before: make rebuilt every time)."""
    folder, names, now = project
    fake = folder / ".venv" / "bin" / "propulsor"
    fake.parent.mkdir(parents=True, exist_ok=True)
    fake.write_text(f"#!{sys.executable}\nimport sys, pathlib\n"
                    "a = sys.argv[1:]\n"
                    "if a[0] == 'build':\n"
                    "    files = [x for x in a if x.endswith('.toml')]\n"
                    "    out = pathlib.Path(a[a.index('--out-dir') + 1])\n"
                    "    open('built.txt', 'a').write(str(out) + ' ' + ' '.join(files) + '\\n')\n"
                    "    for f in files:\n"
                    "        m = out / pathlib.Path(f).stem / 'manifest.json'\n"
                    "        m.parent.mkdir(parents=True, exist_ok=True); m.write_text('{}')\n")
    fake.chmod(0o755)
    built = _make_parts(folder, "parts", "OUT=alt")
    assert built == ["alt " + " ".join(f"parts/{n}.toml" for n in names)]
    assert all((folder / "alt" / n / "manifest.json").is_file() for n in names)
    assert _make_parts(folder, "parts", "OUT=alt") == []


def test_build_out_dir_names_the_parent_of_each_parts_folder(tmp_path, capfd):
    from propulsor.cli import main

    assert main(["build", str(ROOT / "parts" / "road_wheel.toml"), "--out-dir", str(tmp_path / "alt"),
                 "--dry-run"]) == 0
    assert f"would build into {tmp_path / 'alt' / 'road_wheel'};" in capfd.readouterr().out
    assert main(["build", str(ROOT / "parts" / "road_wheel.toml"), "--out", str(tmp_path / "x"), "--out-dir",
                 str(tmp_path / "alt")]) == 2
    assert capfd.readouterr().err.strip().endswith(
        f"--out-dir = {str(tmp_path / 'alt')!r}: not with --out: give --out (the part's own folder) or --out-dir "
        "(<dir>/<file name>)")


@needs_make
def test_make_writes_the_gallery_only_where_the_builds_did_not(project):
    """The builds rewrite a gallery propulsor wrote (`propulsor build` of several part files once, after the last):
    when the builds' run (.built) is all that is newer than such a page, `make` renews its time stamp and does not
    write it again (some 40 MB: half a second).  A page propulsor did not write, no page, or a viewer file newer
    than the page: `propulsor gallery`, as before."""
    folder, names, now = project
    fake = folder / ".venv" / "bin" / "propulsor"
    fake.parent.mkdir(parents=True, exist_ok=True)
    fake.write_text(f"#!{sys.executable}\nimport sys\nopen('calls.txt', 'a').write(' '.join(sys.argv[1:]) + '\\n')\n")
    fake.chmod(0o755)
    page, built = folder / "output" / "index.html", folder / "output" / ".built"
    from propulsor.export.gallery import GENERATOR

    # the Makefile's mark is the one the gallery writes and reads (gallery.is_ours): one string, not two drifting
    assert f"GALLERY_MARK := {GENERATOR}\n" in (ROOT / "Makefile").read_text()
    ours = f'<!DOCTYPE html>\n<html><head><meta charset="utf-8">\n{GENERATOR}\n'

    def make(text: str | None, newer: Path | None = None) -> list[str]:
        _touch(built, now - 5)  # the builds' run, after every manifest
        page.unlink(missing_ok=True)
        if text is not None:
            page.write_text(text)
            os.utime(page, (now - 20, now - 20))
        if newer is not None:
            os.utime(newer, (now - 1, now - 1))
        calls = folder / "calls.txt"
        calls.unlink(missing_ok=True)
        r = subprocess.run(["make"], cwd=folder, capture_output=True, text=True, timeout=60, env=_clean_env())
        assert r.returncode == 0, r.stdout + r.stderr
        if newer is not None:
            os.utime(newer, (now - 100, now - 100))
        return calls.read_text().splitlines() if calls.exists() else []

    assert make(ours) == []  # current: only .built is newer
    assert page.stat().st_mtime > built.stat().st_mtime and page.read_text() == ours
    q = subprocess.run(["make", "-q"], cwd=folder, capture_output=True, timeout=60, env=_clean_env())
    assert q.returncode == 0  # and the next make has nothing to do
    assert make("<html><head><title>mine</title></head></html>\n") == ["gallery output -q"]  # not ours
    assert make(None) == ["gallery output -q"]  # no page
    assert make(ours, newer=folder / "src" / "propulsor" / "export" / "web" / "viewer.js") == ["gallery output -q"]


def test_several_part_files_write_the_gallery_once_after_the_last(tmp_path, monkeypatch):
    """`propulsor build a b c`: no build rewrites the gallery (each is told so), the command writes it once after
    the last has ended, when the folder is a gallery of its own; a single part file's build writes it itself."""
    import propulsor.building as building
    import propulsor.cli as cli

    log, pages = tmp_path / "log", []

    def build(args, part_file, depfile, gallery=True):  # in a forked child: what it was told, in a file
        (Path(args.out_dir) / part_file.stem).mkdir(parents=True, exist_ok=True)
        with open(log, "a") as f:
            f.write(f"{gallery} {time.time()}\n")
        return 0

    def told() -> list[str]:
        rows = [line.split() for line in log.read_text().splitlines()]
        log.unlink()
        return rows

    monkeypatch.setenv("PROPULSOR_JOBS", "1")
    monkeypatch.setattr(cli, "build_one", build)
    monkeypatch.setattr(building, "regenerate_gallery", lambda folder, progress=None: pages.append((folder, time.time())))
    out = tmp_path / "out"
    out.mkdir()
    (out / "index.html").write_text('<meta name="generator" content="propulsor">\n')
    files = [str(ROOT / "parts" / f"{n}.toml") for n in ("road_wheel", "cam_linear", "balancer")]
    assert main(["build", "-q", "--out-dir", str(out), *files]) == 0
    rows = told()
    assert [r[0] for r in rows] == ["False"] * 3
    assert [f for f, _ in pages] == [out] and pages[0][1] >= max(float(r[1]) for r in rows)
    (out / "index.html").write_text("<html>a page of the user's</html>\n")  # not a gallery: none written
    pages.clear()
    assert main(["build", "-q", "--out-dir", str(out), *files]) == 0
    assert [r[0] for r in told()] == ["False"] * 3 and pages == []
    assert main(["build", "-q", "--out-dir", str(out), files[0]]) == 0
    assert [r[0] for r in told()] == ["True"] and pages == []


_INTERRUPTED_BATCH = r'''
import os, signal, sys, time
from pathlib import Path
import propulsor.building as building
import propulsor.cli as cli

def fake(args, part_file, depfile, gallery=True):
    assert gallery is False  # a batch writes its gallery once, not each build
    if part_file.stem == "first":  # a build that ends: its folder in place (not where its checks failed)
        code = int(os.environ["FIRST_CODE"])
        if code == 0:
            (Path("output") / "first").mkdir(parents=True)
            (Path("output") / "first" / "manifest.json").write_text("{}")
        Path("first.pid").write_text(str(os.getpid()))
        return code
    while True:  # side by side: until the first build has ended and the batch has seen it (reaped: no such pid)
        try:
            os.kill(int(Path("first.pid").read_text()), 0)
        except (FileNotFoundError, ValueError, PermissionError):
            pass
        except ProcessLookupError:
            break
        time.sleep(0.02)
    if os.environ.get("AT") == "gallery":  # the second ends too: Ctrl-C as the batch writes the gallery
        (Path("output") / "second").mkdir(parents=True)
        (Path("output") / "second" / "manifest.json").write_text("{}")
        return 0
    if os.environ.get("AT") == "placed":  # its output put in place and told, as publish does; then Ctrl-C before
        (Path("output") / "second").mkdir(parents=True)  # the batch has seen it end (the signal stops it: 130)
        (Path("output") / "second" / "manifest.json").write_text("{}")
        building.tell_placed()
    os.kill(os.getppid(), signal.SIGINT)  # Ctrl-C during the second build
    time.sleep(60)
    return 0

def gallery_interrupted(folder, *a, _calls=[]):
    _calls.append(1)
    if len(_calls) == 1:
        os.kill(os.getpid(), signal.SIGINT)
    return regenerate(folder, *a)

cli.build_one = fake
regenerate, building.regenerate_gallery = building.regenerate_gallery, gallery_interrupted
# the batch lingers in the fork's callbacks (logging's lock let go, …): a signal there is raised inside a callback,
# whose exception Python does not propagate (the race CI met: a second build that signals at once)
os.register_at_fork(after_in_parent=lambda: time.sleep(0.5))
sys.exit(cli.main(["build", *sys.argv[1:], "-q"]))
'''


@pytest.mark.parametrize("jobs, first_code, at", [("1", 0, "build"), ("2", 0, "build"), ("1", 1, "build"),
                                                  ("2", 0, "gallery"), ("1", 0, "placed"), ("2", 0, "placed")])
def test_an_interrupted_batch_shows_the_builds_that_ended_in_the_gallery(tmp_path, jobs, first_code, at):
    """Ctrl-C during the second of `propulsor build first.toml second.toml`: the first build's folder is in place,
    so the gallery (written once at a batch's end, not by each build) is written for it before the exit, and the
    one line says what was kept (130, as any interrupted build); one build at a time and side by side, the signal
    also where it lands in the fork's own callbacks in the batch (held there half a second).  A first build
    whose checks failed (exit 1, its output not kept without --keep-failed): nothing written, no gallery.  Ctrl-C as
    the batch writes its gallery after both builds: the page written all the same, the line counting both.  Ctrl-C
    once the second build has put its output in place but before the batch has seen it end (the signal then stops
    it, exit 130): counted by its word through its own pipe (building.tell_placed), in the line and the page."""
    for name in ("first", "second"):
        shutil.copy(ROOT / "parts" / "road_wheel.toml", tmp_path / f"{name}.toml")
    (tmp_path / "slow.py").write_text(_INTERRUPTED_BATCH)
    env = {**os.environ, "PROPULSOR_JOBS": jobs, "FIRST_CODE": str(first_code), "AT": at}
    env.pop("MAKEFLAGS", None)
    p = subprocess.run([sys.executable, "slow.py", "first.toml", "second.toml"], cwd=tmp_path, env=env,
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 130, p.stderr
    last = [ln for ln in p.stderr.splitlines() if ln.startswith("propulsor: interrupted")][-1]
    page = tmp_path / "output" / "index.html"
    if first_code:
        assert last == "propulsor: interrupted by SIGINT; nothing written" and not page.exists(), p.stderr
        return
    if jobs == "1":  # the build the signal stopped says so first, naming its part file
        assert "propulsor: second.toml: interrupted by SIGINT; nothing written" in p.stderr.splitlines(), p.stderr
    finished = 2 if at in ("gallery", "placed") else 1
    assert page.is_file() and "first" in page.read_text() and ("second" in page.read_text()) == (finished == 2)
    assert last == f"propulsor: interrupted by SIGINT; {finished} of 2 builds finished, their output in output/ (the " \
                   "gallery shows them); nothing else written", p.stderr
