"""A build never destroys, mixes or half-writes anything.

The output folder is vetted before any work (never the current folder, a parent of it, the home
folder or /; an existing folder only when empty or written by propulsor, unless --force), one build
at a time holds its lock, a killed build leaves no process behind and its debris is cleaned by the
next one, replacement is one step, and every bad input of the command line is exit 2 with one line.
Real builds use a small road wheel (no lightening holes: a few seconds).
"""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from propulsor import output_folder as of
from propulsor.cli import main

ROOT = Path(__file__).resolve().parents[1]
SMALL_WHEEL = 'type = "road_wheel"\nlightening_holes = 0\n'


def _cli(*args, cwd=None, **kw):
    return subprocess.run([sys.executable, "-m", "propulsor.cli", *args], capture_output=True, text=True,
                          cwd=cwd or ROOT, timeout=600, **kw)


def _popen(*args, cwd=None):
    return subprocess.Popen([sys.executable, "-m", "propulsor.cli", *args], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, cwd=cwd or ROOT)


def _one_error_line(stderr: str) -> str:
    """The one line of a refusal; the progress lines before it (``[  t s] …``: the command says what it reads
    within a second, before it finds what it refuses) are not counted."""
    lines = [line for line in stderr.splitlines() if line.strip() and not re.match(r"\[ *\d+\.\d s\] ", line)]
    assert len(lines) == 1, stderr
    assert "Traceback" not in stderr
    return lines[0]


def _children(pid: int) -> set[int]:
    """Process ids of the children of `pid` (Linux /proc)."""
    out = set()
    for task in Path(f"/proc/{pid}/task").glob("*"):
        try:
            out |= {int(x) for x in (task / "children").read_text().split()}
        except OSError:
            pass
    return out


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def _wait_for(cond, timeout=120.0, step=0.05):
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        if cond():
            return True
        time.sleep(step)
    return False


@pytest.fixture
def wheel(tmp_path):
    f = tmp_path / "wheel.toml"
    f.write_text(SMALL_WHEEL)
    return f


# -- the output folder is vetted before any work ---------------------------------------------------

def test_out_dot_never_replaced(tmp_path, wheel):
    (tmp_path / "notes.txt").write_text("mine")
    for extra in ([], ["--force"]):
        r = _cli("build", "wheel.toml", "--out", ".", *extra, cwd=tmp_path)
        assert r.returncode == 2
        assert "is the current folder" in _one_error_line(r.stderr)
    assert (tmp_path / "notes.txt").read_text() == "mine" and wheel.is_file()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes.txt", "wheel.toml"]


@pytest.mark.parametrize("target, why", [("..", "parent of the current folder"), ("/", "root folder"),
                                         ("~", "home folder")])
def test_protected_folders_refused_even_with_force(tmp_path, wheel, monkeypatch, capsys, target, why):
    monkeypatch.chdir(tmp_path)
    rc = main(["build", str(wheel), "--out", os.path.expanduser(target), "--force", "-q"])
    assert rc == 2 and why in _one_error_line(capsys.readouterr().err)


def test_foreign_folder_refused_without_force(tmp_path, wheel, capsys):
    out = tmp_path / "photos"
    out.mkdir()
    (out / "cat.jpg").write_bytes(b"\xff\xd8")
    assert main(["build", str(wheel), "--out", str(out), "-q"]) == 2
    assert "not written by propulsor" in _one_error_line(capsys.readouterr().err)
    # a propulsor folder with a stranger in it is refused too
    (out / "manifest.json").write_text(json.dumps({"part": "road_wheel", "files": [], "checks": [],
                                                   "versions": {"propulsor": "0.1.0"}}))
    assert main(["build", str(wheel), "--out", str(out), "-q"]) == 2
    assert "did not write (first: cat.jpg)" in _one_error_line(capsys.readouterr().err)
    # with --force it is accepted (a dry run: nothing is touched)
    assert main(["build", str(wheel), "--out", str(out), "--force", "--dry-run", "-q"]) == 0
    assert (out / "cat.jpg").read_bytes() == b"\xff\xd8"


def test_out_holding_the_part_file_refused(tmp_path, capsys):
    out = tmp_path / "o"
    out.mkdir()
    (out / "wheel.toml").write_text(SMALL_WHEEL)
    assert main(["build", str(out / "wheel.toml"), "--out", str(out), "--force", "-q"]) == 2
    assert "which this build reads" in _one_error_line(capsys.readouterr().err)


def test_out_file_below_file_symlink_and_unwritable(tmp_path, wheel, capsys):
    f = tmp_path / "a_file"
    f.write_text("x")
    link = tmp_path / "link"
    link.symlink_to(tmp_path)
    cases = [(f, "is a file, not a folder", 2), (f / "sub", "which is a file", 2), (link, "symbolic link", 2),
             (Path("/proc/1/propulsor_out"), "cannot make the lock file /proc/1/.propulsor_out.lock: [ENOENT]", 3)]
    for out, fragment, code in cases:
        assert main(["build", str(wheel), "--out", str(out), "-q"]) == code, out
        assert fragment in _one_error_line(capsys.readouterr().err), out
    assert f.read_text() == "x" and sorted(p.name for p in tmp_path.iterdir()) == ["a_file", "link", "wheel.toml"]


def test_dry_run_writes_nothing(tmp_path, wheel, capsys):
    out = tmp_path / "deep" / "out"
    assert main(["build", str(wheel), "--out", str(out), "--dry-run"]) == 0
    assert "is valid" in capsys.readouterr().out
    assert sorted(p.name for p in tmp_path.iterdir()) == ["wheel.toml"]


# -- bad input: exit 2, one line, nothing written --------------------------------------------------

@pytest.mark.parametrize("text, fragment", [
    (b"\x00\x01\x02\xff binary", "not UTF-8"),
    ("type = \"road_wheel\"\n# é\n".encode("latin-1"), "not UTF-8"),
    (b'type = "road_wheel"\nmeta = 5\n', "meta = 5: must be a table"),
    (b'type = "road_wheel"\n[meta]\ntitle = {a = 1}\n', "meta.title"),
    (b'type = "road_wheel"\n[meta]\nexpected_failures = "x"\n', "meta.expected_failures"),
    (b'type = "road_wheel"\n[meta]\ncolour = "red"\n', "unknown [meta] key"),
    (b'type = "road_wheel"\nrows = true\n', "rows = True: must be a whole number"),
    (b'type = "road_wheel"\nrows = 2.0\n', "rows = 2.0: must be a whole number"),
    (b'type = "road_wheel"\nhub_length_mm = 1e9\n', "hub_length_mm = 1000000000.0: must be <= 1000.0"),
    (b'type = "planetary_final_drive"\nwidth_ring_mm = 1e9\n', "width_ring_mm"),
    (b'type = "noncircular_pair"\ndriven_teeth = 1000000000\n', "driven_teeth"),
    (b'type = "noncircular_pair"\na_mm = 300.0\n', "a_mm = 300.0: must be < c_mm"),
    (b'type = "balancer"\nroad_wheel_file = "bin.toml"\n', "not UTF-8"),
])
def test_bad_part_files_exit_2_one_line(tmp_path, capsys, text, fragment):
    (tmp_path / "bin.toml").write_bytes(b"\xfe\xff\x00binary")
    f = tmp_path / "part.toml"
    f.write_bytes(text)
    out = tmp_path / "out"
    assert main(["build", str(f), "--out", str(out), "-q"]) == 2
    assert fragment in _one_error_line(capsys.readouterr().err)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bin.toml", "part.toml"]


def test_list_over_a_folder_with_a_binary_file(tmp_path):
    (tmp_path / "bad.toml").write_bytes(b"\xff\xfe\x00")
    r = _cli("list", "--parts-dir", str(tmp_path))
    assert r.returncode == 0 and "Traceback" not in r.stderr
    assert "bad.toml" in r.stdout and "not UTF-8" in r.stdout


def test_size_estimate_refuses_builds_that_cannot_finish(tmp_path, capsys):
    f = tmp_path / "big.toml"
    f.write_text('type = "noncircular_pair"\ndriven_teeth = 480\ndriver_turns = 1\nmodule_mm = 1.0\n'
                 'proof_phases_per_tooth = 64\n')
    assert main(["build", str(f), "--out", str(tmp_path / "o"), "--dry-run", "-q"]) == 2
    line = _one_error_line(capsys.readouterr().err)
    assert "size estimate" in line and "must be <= 600 s" in line and "teeth" in line


# -- propulsor check never raises ------------------------------------------------------------------

@pytest.mark.parametrize("manifest, fragment", [
    ({"part": "x", "files": "all", "checks": [], "versions": {}}, "'files' is missing or not a list"),
    ({"part": "x", "files": [{"bytes": 3}], "checks": [], "versions": {}}, "has no 'path'"),
    ({"part": "x", "files": [5], "checks": [], "versions": {}}, "has no 'path'"),
    ({"part": "x", "files": [{"path": "../../etc/passwd"}], "checks": [], "versions": {}}, "leaves the folder"),
    ([1, 2], "not an object"),
])
def test_check_malformed_manifest_is_invalid(tmp_path, capsys, manifest, fragment):
    (tmp_path / "manifest.json").write_text(json.dumps(manifest))
    assert main(["check", str(tmp_path)]) == 1
    assert fragment in capsys.readouterr().out


def test_check_nothing_to_check_is_exit_2(tmp_path, capsys):
    (tmp_path / "readme.txt").write_text("x")
    assert main(["check", str(tmp_path)]) == 2
    assert "holds no STEP" in _one_error_line(capsys.readouterr().err)


# -- one build per output at a time ----------------------------------------------------------------

def test_lock_file_lives_beside_the_output_folder(tmp_path, monkeypatch):
    a, b = of.lock_path(tmp_path / "out"), of.lock_path(tmp_path / "." / "out")
    monkeypatch.setenv("TMPDIR", str(tmp_path / "elsewhere"))
    assert a == b == of.lock_path(tmp_path / "out") == tmp_path.resolve() / ".out.lock"
    assert of.lock_path(tmp_path / "other") != a


def test_lock_no_wait_names_the_holder_then_waits(tmp_path, wheel):
    out = tmp_path / "out"
    lock = of.OutputLock(out)
    lock.acquire(wait=False)
    try:
        r = _cli("build", str(wheel), "--out", str(out), "--no-wait", "-q")
        assert r.returncode == 2 and f"is being built by process {os.getpid()}" in _one_error_line(r.stderr)
        p = _popen("build", str(wheel), "--out", str(out), "-q")
        lines = []
        reader = threading.Thread(target=lambda: lines.extend(p.stderr), daemon=True)
        reader.start()
        assert _wait_for(lambda: any("waiting" in line for line in lines), timeout=60)
        assert p.poll() is None and not out.exists()
    finally:
        lock.release()
    assert p.wait(timeout=600) == 0
    reader.join(timeout=5)
    assert _cli("check", str(out)).returncode == 0


def test_concurrent_builds_take_turns(tmp_path, wheel):
    out = tmp_path / "out"
    procs = [_popen("build", str(wheel), "--out", str(out), "-q") for _ in range(2)]
    assert [p.wait(timeout=600) for p in procs] == [0, 0]
    r = _cli("check", str(out))
    assert r.returncode == 0, r.stdout
    manifest = json.loads((out / "manifest.json").read_text())
    files = {p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file()}
    assert files == {e["path"] for e in manifest["files"]} | {"manifest.json"}
    # nothing beside an --out that is not in the default output folder (nor in a gallery folder)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out", "wheel.toml"]


def test_concurrent_builds_in_output_share_one_gallery(tmp_path, wheel):
    """Two builds into ./output/a and ./output/b at once: the gallery beside them (rewritten by each
    build under its own lock) shows both."""
    procs = [_popen("build", str(wheel), "--out", f"output/{n}", "-q", cwd=tmp_path) for n in "ab"]
    assert [p.wait(timeout=600) for p in procs] == [0, 0]
    page = (tmp_path / "output" / "index.html").read_text()
    assert page.count("<section class=\"part\"") == 2


# -- no orphans, no debris -------------------------------------------------------------------------

def _start_and_wait_for_workers(wheel, out):
    p = _popen("build", str(wheel), "--out", str(out), "-q")
    assert _wait_for(lambda: len(_children(p.pid)) >= 2 or p.poll() is not None, timeout=300)
    kids = _children(p.pid)
    assert p.poll() is None and len(kids) >= 2, "the build ended before its workers could be seen"
    return p, kids


def test_sigkill_leaves_no_process_and_the_next_build_cleans_up(tmp_path, wheel):
    out = tmp_path / "out"
    p, kids = _start_and_wait_for_workers(wheel, out)
    p.send_signal(signal.SIGKILL)
    p.wait(timeout=30)
    assert _wait_for(lambda: not any(_alive(k) for k in kids), timeout=5), "workers outlived their parent"
    stale = [q for q in tmp_path.iterdir() if q.name.startswith(".out.tmp-")]
    assert stale, "a killed build leaves its temporary folder"
    lock = of.OutputLock(out)
    lock.acquire(wait=False)  # the kernel dropped the dead build's lock
    try:
        assert sorted(of.clean_stale(out)) == sorted(stale)
    finally:
        lock.release()
    assert sorted(q.name for q in tmp_path.iterdir()) == ["wheel.toml"]


@pytest.mark.parametrize("sig, code", [(signal.SIGTERM, 143), (signal.SIGINT, 130)])
def test_interrupt_exits_with_one_line_and_leaves_nothing(tmp_path, wheel, sig, code):
    out = tmp_path / "out"
    p, kids = _start_and_wait_for_workers(wheel, out)
    p.send_signal(sig)
    _, err = p.communicate(timeout=60)
    assert p.returncode == code
    assert f"interrupted by {signal.Signals(sig).name}" in _one_error_line(err)
    assert not any(_alive(k) for k in kids)
    assert sorted(q.name for q in tmp_path.iterdir()) == ["wheel.toml"]


_INTERRUPTED_AFTER_PLACING = r'''
import os, signal, sys
import propulsor.building as building
from propulsor.cli import main

real = building.regenerate_gallery
calls = []

def gallery(folder, *a):  # Ctrl-C as the build, its output in place, writes the gallery beside it
    calls.append(1)
    if len(calls) == 1:
        os.kill(os.getpid(), signal.SIGINT)
    return real(folder, *a)

building.regenerate_gallery = gallery
sys.exit(main(["build", "wheel.toml", "-q"]))
'''


def test_an_interrupt_once_the_output_is_in_place_says_so_and_keeps_it(tmp_path, wheel):
    """A signal after the build's output was put in place (here: as the gallery beside it is written) does not undo
    it: the folder stays, the gallery is written for it, exit 130 and one line that says what is there, not "nothing
    written"."""
    (tmp_path / "run.py").write_text(_INTERRUPTED_AFTER_PLACING)
    p = subprocess.run([sys.executable, "run.py"], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert p.returncode == 130, p.stderr
    out = (tmp_path / "output" / "wheel").resolve()
    assert _one_error_line(p.stderr) == f"propulsor: interrupted by SIGINT; {out} is built (the gallery shows it); " \
                                        "nothing else written"
    assert (out / "manifest.json").is_file() and "wheel" in (tmp_path / "output" / "index.html").read_text()
    assert sorted(q.name for q in (tmp_path / "output").iterdir()) == ["index.html", "wheel"]  # no temporary folder


def test_interrupt_during_imports_is_one_line(tmp_path, wheel):
    p = _popen("build", str(wheel), "--out", str(tmp_path / "out"), "-q")
    time.sleep(1.0)  # inside the imports of the kernel and the part
    p.send_signal(signal.SIGINT)
    _, err = p.communicate(timeout=120)
    assert p.returncode == 130, err
    assert "interrupted by SIGINT" in _one_error_line(err)
    assert sorted(q.name for q in tmp_path.iterdir()) == ["wheel.toml"]


# -- atomic replacement ----------------------------------------------------------------------------

def _folder(path: Path, tag: str) -> Path:
    path.mkdir()
    (path / "manifest.json").write_text(tag)
    return path


def _replace_under_watch(tmp_path, exchange, rounds=200):
    out = _folder(tmp_path / "out", "0")
    seen_missing = []
    stop = threading.Event()

    def watch():
        while not stop.is_set():
            try:
                (out / "manifest.json").read_text()
            except FileNotFoundError:
                seen_missing.append(time.monotonic())

    t = threading.Thread(target=watch)
    t.start()
    try:
        for k in range(1, rounds + 1):
            of.replace(_folder(tmp_path / f".out.tmp-{k:08d}", str(k)), out, exchange=exchange)
    finally:
        stop.set()
        t.join()
    return out, seen_missing


def test_replacement_is_one_step(tmp_path):
    out, missing = _replace_under_watch(tmp_path, of.rename_exchange)
    assert (out / "manifest.json").read_text() == "200" and missing == []
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_fallback_replacement_is_recovered_after_a_crash(tmp_path):
    """Without renameat2 the old folder is renamed aside first; a crash between the two renames
    leaves no output, and the next build (holding the lock) puts the old one back."""
    out, _ = _replace_under_watch(tmp_path, lambda a, b: False, rounds=5)
    assert (out / "manifest.json").read_text() == "5"
    os.rename(out, tmp_path / ".out.old-0123abcd")  # the crash
    _folder(tmp_path / ".out.tmp-deadbeef", "new, unfinished")
    assert [p.name for p in of.clean_stale(out)] == [".out.tmp-deadbeef"]
    assert (out / "manifest.json").read_text() == "5"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_a_closed_pipe_is_no_traceback():
    """`propulsor params balancer | head -1` where the reader has gone before the first line: exit 141
    (128 + SIGPIPE), nothing on stderr."""
    r, w = os.pipe()
    os.close(r)  # the reader is gone
    try:
        p = subprocess.run([sys.executable, "-m", "propulsor.cli", "params", "balancer"], stdout=w,
                           stderr=subprocess.PIPE, cwd=ROOT, timeout=60)
    finally:
        os.close(w)
    assert p.returncode == 141 and p.stderr == b"", p.stderr.decode()
