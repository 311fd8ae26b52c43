"""Another user, a dying disk, a folder removed under a build, crafted input: nothing lost, nothing
published half-written, nothing hung, one line and a code that means one thing.

Exit codes: 2 bad input (before any work), 3 the environment refused (disk full, read-only, a folder
removed under the build; the path and the errno named).  The attacks of another user run as uid 65534
(``setpriv``) and need root; the disk tests mount a small tmpfs and need root too (skipped with a
message otherwise).
"""

from __future__ import annotations

import errno
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

from propulsor import output_folder as of
from propulsor import write_root
from propulsor.errors import EnvironmentFailure

ROOT = Path(__file__).resolve().parents[1]
SMALL_WHEEL = 'type = "road_wheel"\nlightening_holes = 0\n'
NOBODY = 65534

needs_root = pytest.mark.skipif(os.geteuid() != 0 or not shutil.which("setpriv"),
                                reason="needs root and setpriv (util-linux) to act as a second user / mount a tmpfs")


def _cli(*args, cwd=None, env=None, timeout=600):
    return subprocess.run([sys.executable, "-m", "propulsor.cli", *args], capture_output=True, text=True,
                          cwd=cwd or ROOT, timeout=timeout, env=env)


def _popen(*args, env=None):
    return subprocess.Popen([sys.executable, "-m", "propulsor.cli", *args], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, cwd=ROOT, env=env)


def _one_error_line(stderr: str) -> str:
    """The one line of a refusal; the progress lines before it (``[  t s] …``: the command says what it reads
    within a second, before it finds what it refuses) are not counted."""
    lines = [line for line in stderr.splitlines() if line.strip() and not re.match(r"\[ *\d+\.\d s\] ", line)]
    assert len(lines) == 1, stderr
    assert "Traceback" not in stderr
    return lines[0]


def _as_nobody(script: str, wait=True):
    cmd = ["setpriv", f"--reuid={NOBODY}", f"--regid={NOBODY}", "--clear-groups", sys.executable, "-c", script]
    if wait:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
        assert r.returncode == 0, r.stderr
        return r
    return subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


@pytest.fixture
def wheel(tmp_path):
    f = tmp_path / "wheel.toml"
    f.write_text(SMALL_WHEEL)
    return f


@pytest.fixture
def shared():
    """A world-writable sticky folder like /tmp, that a second user can reach."""
    d = Path(tempfile.mkdtemp(prefix="propulsor-shared-", dir="/tmp"))
    os.chmod(d, 0o1777)
    yield d
    shutil.rmtree(d, ignore_errors=True)


@pytest.fixture
def victim(tmp_path):
    f = tmp_path / "secret.txt"
    f.write_text("precious\n")
    os.chmod(f, 0o600)
    return f


# -- another user ----------------------------------------------------------------------------------

@needs_root
def test_another_users_lock_folder_in_tmpdir_can_neither_truncate_a_file_nor_stop_a_build(tmp_path, wheel, shared,
                                                                                          victim):
    """A second user makes ``$TMPDIR/propulsor-locks-0`` first, world-readable, with a symbolic link where
    the lock of the output would be (the lock's old place): the build runs and the file stays."""
    out = tmp_path / "out"
    name = hashlib.sha256(os.fsencode(os.path.realpath(out))).hexdigest()[:32] + ".lock"
    _as_nobody(f"import os; d = {str(shared / 'propulsor-locks-0')!r}; os.mkdir(d, 0o755); "
               f"os.symlink({str(victim)!r}, os.path.join(d, {name!r}))")
    env = dict(os.environ, TMPDIR=str(shared))
    r = _cli("build", str(wheel), "--out", str(out), "-q", env=env)
    assert r.returncode == 0, r.stderr
    assert victim.read_text() == "precious\n"


@needs_root
def test_a_symlink_planted_as_the_lock_is_refused_and_the_target_stays(shared, victim, wheel):
    out = shared / "out"
    _as_nobody(f"import os; os.symlink({str(victim)!r}, {str(shared / '.out.lock')!r})")
    r = _cli("build", str(wheel), "--out", str(out), "-q")
    assert r.returncode == 2
    line = _one_error_line(r.stderr)
    assert ".out.lock" in line and ("symbolic link" in line or "another user" in line), line
    assert victim.read_text() == "precious\n" and not out.exists()


@needs_root
def test_another_users_lock_file_with_a_fake_pid_is_refused_not_waited_for(shared, wheel):
    """The second user holds a lock file of their own with a made-up process id: the build says whose file it
    is in one line instead of repeating the fake pid or waiting for ever."""
    lock = shared / ".out.lock"
    holder = _as_nobody(f"import fcntl, os, time; fd = os.open({str(lock)!r}, os.O_RDWR | os.O_CREAT, 0o644); "
                        "os.write(fd, b'1\\n'); fcntl.flock(fd, fcntl.LOCK_EX); print('held', flush=True); "
                        "time.sleep(120)", wait=False)
    try:
        assert holder.stdout.readline().strip() == "held"
        for extra in ([], ["--no-wait"]):
            r = _cli("build", str(wheel), "--out", str(shared / "out"), "-q", *extra, timeout=60)
            assert r.returncode == 2
            line = _one_error_line(r.stderr)
            assert f"belongs to another user (uid {NOBODY})" in line and "process 1" not in line, line
    finally:
        holder.kill()
        holder.wait()


def test_builds_of_one_output_exclude_each_other_whatever_their_tmpdir(tmp_path, wheel):
    out = tmp_path / "out"
    lock = of.OutputLock(out)
    lock.acquire(wait=False)
    try:
        env = dict(os.environ, TMPDIR=str(tmp_path))
        r = _cli("build", str(wheel), "--out", str(out), "--no-wait", "-q", env=env)
        assert r.returncode == 2
        assert f"is being built by process {os.getpid()}" in _one_error_line(r.stderr)
    finally:
        lock.release()
    assert not of.lock_path(out).exists(), "the holder removes its lock file"


def test_lock_file_with_two_links_is_refused_and_left_alone(tmp_path, victim):
    out = tmp_path / "out"
    os.link(victim, of.lock_path(out))
    with pytest.raises(of.InputError, match="2 links"):
        of.OutputLock(out).acquire(wait=False)
    assert victim.read_text() == "precious\n"


def test_a_lock_removed_by_its_holder_is_not_taken_by_a_waiter(tmp_path):
    """A waiter that gets the lock of a file its holder removed tries again on the file now there, so it
    never holds a lock beside a build holding the new file's."""
    out = tmp_path / "out"
    a = of.OutputLock(out)
    a.acquire(wait=False)
    fd = a._open()  # the waiter's open file: the same inode as the holder's
    a.release()     # removed, then let go
    b = of.OutputLock(out)
    b.acquire(wait=False)  # a new file
    try:
        assert not b._still_there(fd) and b._still_there(b.fd)
    finally:
        os.close(fd)
        b.release()


# -- a folder removed under the build, nothing published -------------------------------------------

def _remove_when(p, path_glob: Path, what, timeout=300):
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout and p.poll() is None:
        hits = [q for q in path_glob.parent.glob(path_glob.name) if (q / what).exists()]
        if hits:
            shutil.rmtree(hits[0])
            return hits[0]
        time.sleep(0.01)
    return None


@pytest.mark.parametrize("remove", ["temporary folder", "output's parent"])
def test_folder_removed_mid_build_is_exit_3_and_nothing_published(tmp_path, wheel, remove):
    parent = tmp_path / "par"
    out = parent / "out"
    p = _popen("build", str(wheel), "--out", str(out), "-q")
    hit = _remove_when(p, parent / ".out.tmp-*", "tables")
    assert hit is not None, "the build ended before its temporary folder could be seen"
    if remove == "output's parent":
        shutil.rmtree(parent, ignore_errors=True)
    _, err = p.communicate(timeout=300)
    assert p.returncode == 3, err
    line = _one_error_line(err)
    assert "[ENOENT]" in line or "[ESTALE]" in line, line
    assert not out.exists()


def test_writers_never_make_a_removed_build_folder_again(tmp_path):
    tmp = tmp_path / "t"
    tmp.mkdir()
    with write_root.writing_into(tmp):
        write_root.prepare(tmp / "tables" / "a.csv").write_text("x")
        shutil.rmtree(tmp)
        for rel in ("b.step", "tables/b.csv", "anim/c.gif"):
            with pytest.raises(FileNotFoundError):
                write_root.prepare(tmp / rel).write_text("x")
        tmp.mkdir()  # another folder in its place
        with pytest.raises(OSError) as exc:
            write_root.prepare(tmp / "tables" / "d.csv")
        assert exc.value.errno == errno.ESTALE
    assert not (tmp / "tables").exists()


def _built(tmp_path, wheel) -> Path:
    out = tmp_path / "built"
    assert _cli("build", str(wheel), "--out", str(out), "-q").returncode == 0
    return out


@pytest.mark.parametrize("change", ["remove", "alter", "add"])
def test_a_folder_that_is_not_what_its_manifest_lists_is_not_published(tmp_path, wheel, change):
    out = _built(tmp_path, wheel)
    ident = write_root.identity(out)  # the folder stays: its inode is not reused
    target = out / "tables" / "tyre_temperature.csv"
    if change == "remove":
        target.unlink()
    elif change == "alter":
        target.write_text(target.read_text() + "0\n")
    else:
        (out / "tables" / "planted.csv").write_text("x\n")
    with pytest.raises(EnvironmentFailure, match="changed under the build"):
        of.verify_built(out, ident)


def test_a_folder_that_holds_what_its_manifest_lists_passes(tmp_path, wheel):
    out = _built(tmp_path, wheel)
    with write_root.writing_into(out) as ident:
        of.verify_built(out, ident)
    with pytest.raises(OSError):
        of.verify_built(out, (str(out), 0, 0))  # another folder of that name


# -- the disk refuses ------------------------------------------------------------------------------

def _tmpfs(tmp_path, options):
    if os.geteuid() != 0:
        pytest.skip("mounting a small tmpfs needs root")
    mnt = tmp_path / "outer" / "disk"
    mnt.mkdir(parents=True)
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(mnt)], capture_output=True, text=True)
    if r.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {r.stderr.strip()}")
    return mnt


@pytest.fixture
def small_disk(tmp_path):
    """A 1 MiB tmpfs (root only)."""
    mnt = _tmpfs(tmp_path, "size=1m")
    yield mnt
    subprocess.run(["umount", "-l", str(mnt)], capture_output=True)


@pytest.fixture
def few_inodes(tmp_path):
    """A roomy tmpfs with 12 inodes: out of inodes long before out of space (root only)."""
    mnt = _tmpfs(tmp_path, "size=256m,nr_inodes=12")
    yield mnt
    subprocess.run(["umount", "-l", str(mnt)], capture_output=True)


def test_disk_full_is_exit_3_naming_the_path_and_errno(small_disk, wheel):
    out = small_disk / "out"
    r = _cli("build", str(wheel), "--out", str(out), "-q")
    assert r.returncode == 3, r.stderr
    line = _one_error_line(r.stderr)
    assert "[ENOSPC]" in line and str(small_disk) in line, line
    assert not out.exists() and not [q for q in small_disk.iterdir()]


def test_out_of_inodes_is_exit_3_naming_the_path_and_errno(few_inodes, wheel):
    out = few_inodes / "out"
    r = _cli("build", str(wheel), "--out", str(out), "-q")
    assert r.returncode == 3, r.stderr
    line = _one_error_line(r.stderr)
    assert "[ENOSPC]" in line and str(few_inodes) in line, line
    assert not out.exists() and not [q for q in few_inodes.iterdir()]


def test_read_only_file_system_is_exit_3_and_the_old_output_stays(tmp_path, small_disk, wheel):
    out = small_disk / "out"
    out.mkdir()
    (out / "manifest.json").write_text(json.dumps({"part": "road_wheel", "files": [],
                                                   "versions": {"propulsor": "0"}}))
    subprocess.run(["mount", "-o", "remount,ro", str(small_disk)], check=True)
    r = _cli("build", str(wheel), "--out", str(out), "-q")
    assert r.returncode == 3, r.stderr
    assert "[EROFS]" in _one_error_line(r.stderr)
    assert json.loads((out / "manifest.json").read_text())["part"] == "road_wheel"


def test_force_never_replaces_a_folder_holding_a_mount(tmp_path, small_disk, wheel):
    """``--force`` over a folder with a file system mounted inside: refused before any work, the mounted
    file intact (it once deleted a file on the mount, then failed with EBUSY)."""
    outer = small_disk.parent
    keep = small_disk / "on_the_mount.txt"
    keep.write_text("mine")
    r = _cli("build", str(wheel), "--out", str(outer), "--force", "-q")
    assert r.returncode == 2
    assert "holds a mounted file system" in _one_error_line(r.stderr)
    assert keep.read_text() == "mine"


# -- things that are not files, and input that could blow the stack -------------------------------

def test_dry_run_into_a_folder_whose_manifest_is_a_fifo_does_not_hang(tmp_path, wheel):
    out = tmp_path / "out"
    out.mkdir()
    os.mkfifo(out / "manifest.json")
    r = _cli("build", str(wheel), "--out", str(out), "--dry-run", timeout=60)
    assert r.returncode == 2
    assert "not written by propulsor" in _one_error_line(r.stderr)


def test_a_part_file_that_is_a_fifo_is_refused(tmp_path):
    f = tmp_path / "part.toml"
    os.mkfifo(f)
    r = _cli("build", str(f), "--dry-run", timeout=60)
    assert r.returncode == 2
    assert "is a FIFO" in _one_error_line(r.stderr)


@pytest.mark.parametrize("text", [
    "type = \"road_wheel\"\nx = " + "[" * 600 + "]" * 600 + "\n",
    "type = \"road_wheel\"\n" + ".".join(f"k{i}" for i in range(10_000)) + " = 1\n",
    "type = \"road_wheel\"\n[meta]\nnotes = " + "[" * 40 + "\"x\"" + "]" * 40 + "\n",
], ids=["arrays 600 deep", "dotted key 10000 deep", "meta 40 deep"])
@pytest.mark.parametrize("command", ["build", "print", "list"])
def test_deeply_nested_part_file_is_one_line(tmp_path, text, command):
    f = tmp_path / "deep.toml"
    f.write_text(text)
    if command == "list":
        r = _cli("list", "--parts-dir", str(tmp_path))
        assert r.returncode == 0 and "Traceback" not in r.stderr + r.stdout
        assert "nests tables or arrays" in r.stdout
        return
    r = _cli(command, str(f), "--out", str(tmp_path / "out"), *(["--dry-run"] if command == "build" else []))
    assert r.returncode == 2
    assert "nests tables or arrays" in _one_error_line(r.stderr)


def test_out_longer_than_the_system_allows_is_one_line(tmp_path, wheel):
    out = tmp_path.joinpath(*["d" * 200] * 25)
    r = _cli("build", str(wheel), "--out", str(out), "-q")
    assert r.returncode == 2
    assert "bytes: the files below it would pass the system's path limit" in _one_error_line(r.stderr)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["wheel.toml"]


def test_out_that_is_not_utf8_is_refused_before_any_work(tmp_path, wheel):
    out = os.fsencode(str(tmp_path)) + b"/out\xff"
    t0 = time.monotonic()
    r = subprocess.run([sys.executable, "-m", "propulsor.cli", "build", str(wheel), "--out", out, "-q"],
                       capture_output=True, cwd=ROOT, timeout=600)
    assert r.returncode == 2
    assert "is not UTF-8" in _one_error_line(r.stderr.decode("utf-8", "replace"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["wheel.toml"]
    assert time.monotonic() - t0 < 60  # refused at once, not after a whole build (generous bound)


def test_current_folder_removed_is_one_line(tmp_path, wheel):
    gone = tmp_path / "gone"
    gone.mkdir()
    script = ("import os, sys; os.chdir(sys.argv[1]); os.rmdir(sys.argv[1]); "
              "from propulsor.cli import main; sys.exit(main(['build', sys.argv[2], '--dry-run']))")
    r = subprocess.run([sys.executable, "-c", script, str(gone), str(wheel)], capture_output=True, text=True,
                       timeout=120, env=dict(os.environ, PYTHONPATH=str(ROOT / "src")))
    assert r.returncode == 3
    assert "current folder" in _one_error_line(r.stderr)


def test_out_empty_is_refused(wheel):
    for command in (["build", str(wheel)], ["print", str(wheel)]):
        r = _cli(*command, "--out", "", "--dry-run" if command[0] == "build" else "-q")
        assert r.returncode == 2
        assert "--out = '': must name a folder" in _one_error_line(r.stderr)


def test_set_with_a_newline_is_refused_not_half_read(wheel, tmp_path):
    r = _cli("print", str(wheel), "--out", str(tmp_path / "kit"), "--set", "backlash_mm=0.3\nfoo=1")
    assert r.returncode == 2
    assert "one KEY=VALUE on one line" in _one_error_line(r.stderr)
    assert not (tmp_path / "kit").exists()


def test_gallery_with_a_fifo_for_a_manifest_or_a_page_does_not_hang(tmp_path, wheel):
    folder = tmp_path / "output"
    built = folder / "good"
    assert _cli("build", str(wheel), "--out", str(built), "-q").returncode == 0
    (folder / "bad").mkdir()
    os.mkfifo(folder / "bad" / "manifest.json")
    r = _cli("gallery", str(folder), "-q", timeout=60)
    assert r.returncode == 0, r.stderr
    page = (folder / "index.html").read_text()
    assert "output/bad" in page or "bad: manifest" in page or "is a FIFO" in page
    (folder / "index.html").unlink()
    os.mkfifo(folder / "index.html")
    r = _cli("gallery", str(folder), "-q", timeout=60)
    assert r.returncode == 2 and "not written by propulsor" in _one_error_line(r.stderr)


def test_a_build_beside_a_fifo_manifest_rewrites_the_gallery_without_hanging(tmp_path, wheel):
    """The gallery of ./output is rewritten after every build into it: a sibling whose manifest is a FIFO is
    shown as not readable, and the build ends (it once hung there, holding its output's lock)."""
    (tmp_path / "output" / "bad").mkdir(parents=True)
    os.mkfifo(tmp_path / "output" / "bad" / "manifest.json")
    r = subprocess.run([sys.executable, "-m", "propulsor.cli", "build", str(wheel), "--out", "output/good", "-q"],
                       capture_output=True, text=True, cwd=tmp_path, timeout=300,
                       env=dict(os.environ, PYTHONPATH=str(ROOT / "src")))
    assert r.returncode == 0, r.stderr
    page = (tmp_path / "output" / "index.html").read_text()
    assert "good" in page and "is a FIFO" in page


def test_a_step_writer_failure_is_the_machines_when_the_folder_takes_no_file(tmp_path):
    """OCCT's STEP writer fails without an errno; where the folder takes no new file (here /proc) the
    failure is the machine's (exit 3), elsewhere the writer's own."""
    from propulsor.errors import EnvironmentFailure
    from propulsor.export.step import _write_failed

    assert isinstance(_write_failed(Path("/proc/a.step"), "STEP write"), EnvironmentFailure)
    err = _write_failed(tmp_path / "a.step", "STEP write")
    assert type(err) is RuntimeError and "STEP write failed" in str(err)
    assert list(tmp_path.iterdir()) == []  # the probe is gone
