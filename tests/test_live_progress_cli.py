"""Live progress of the command line, run as the user runs it (issue 39, «long silences»): the first line of
`propulsor build`, `print` and `explore` within a second of the start, a long phase's counts while it runs, and
`-q` silent on success.  The commands run in a subprocess whose stderr is a pipe (not a terminal: plain lines)
and the time each line arrives is read here."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: the first line's bound: the acceptance's «within a second» (measured 0.15-0.2 s on a loaded 2-core machine:
#: the interpreter's start and the command line's imports; the part type's imports and the design come after)
FIRST_LINE_S = 1.0


def _started(*argv: str, cwd: Path = ROOT) -> tuple[subprocess.Popen, float]:
    t0 = time.perf_counter()
    p = subprocess.Popen([sys.executable, "-m", "propulsor.cli", *argv], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, cwd=cwd)
    return p, t0


def _first_line(*argv: str, cwd: Path = ROOT) -> tuple[str, float]:
    """The first stderr line of the command and the seconds from its start to its arrival; the command is
    then stopped (SIGTERM: it leaves nothing behind)."""
    p, t0 = _started(*argv, cwd=cwd)
    try:
        line = p.stderr.readline().decode()
        arrived = time.perf_counter() - t0
    finally:
        p.send_signal(signal.SIGTERM)
        p.communicate(timeout=120)
    return line, arrived


def _lines(*argv: str, cwd: Path = ROOT, timeout: float = 600) -> tuple[int, list[tuple[float, str]], str]:
    """Run the command to its end: (exit code, [(arrival s, stderr line)], stdout)."""
    p, t0 = _started(*argv, cwd=cwd)
    got = []
    for raw in p.stderr:
        got.append((time.perf_counter() - t0, raw.decode().rstrip("\n")))
    out = p.stdout.read().decode()
    return p.wait(timeout=timeout), got, out


def test_build_first_line_within_a_second(tmp_path):
    line, arrived = _first_line("build", str(ROOT / "parts" / "road_wheel.toml"), "--out", str(tmp_path / "out"))
    assert arrived < FIRST_LINE_S, (arrived, line)
    assert re.fullmatch(r"\[ +0\.\d s\] .*parts/road_wheel\.toml: reading the part file\n", line), line


def test_print_first_line_within_a_second(tmp_path):
    line, arrived = _first_line("print", str(ROOT / "parts" / "road_wheel.toml"), "--out", str(tmp_path / "kit"),
                                "--slice", "no")
    assert arrived < FIRST_LINE_S, (arrived, line)
    assert "road_wheel.toml: reading the part file" in line, line


def test_explore_first_line_within_a_second(tmp_path):
    study = sorted((ROOT / "studies").glob("*.toml"))[0]
    line, arrived = _first_line("explore", str(study), "--out", str(tmp_path / "study"), "--workers", "1")
    assert arrived < FIRST_LINE_S, (arrived, line)
    assert "reading the study file" in line, line


def test_several_part_files_first_line_within_a_second(tmp_path):
    parts = [str(ROOT / "parts" / f"{n}.toml") for n in ("road_wheel", "cam_linear")]
    line, arrived = _first_line("build", *parts, cwd=tmp_path)
    assert arrived < FIRST_LINE_S, (arrived, line)
    assert "2 part files" in line, line


def test_a_long_phase_counts_while_it_runs(tmp_path):
    """cam_mover's motion proofs (its longest phase in this process): the sweeps counted as they end, each line
    stamped; the build's files are those of a build without progress (nothing else changes)."""
    code, got, _ = _lines("build", str(ROOT / "parts" / "cam_linear.toml"), "--out", str(tmp_path / "out"))
    assert code == 0, got
    assert got[0][0] < FIRST_LINE_S, got[:2]
    counts = [(t, line) for t, line in got if re.search(r"motion proofs: sweep \d+/8", line)]
    assert counts and counts[0][1].endswith("sweep 0/8") and counts[-1][1].endswith("sweep 8/8"), got
    phase = next(t for t, line in got if "motion proofs (720 steps per turn)" in line)
    assert counts[0][0] - phase < 1.0  # the count shows at once, not when the phase ends
    assert all(re.match(r"\[ *\d+\.\d s\] ", line) for _, line in got), got


def test_quiet_build_prints_nothing_on_success(tmp_path):
    code, got, out = _lines("build", str(ROOT / "parts" / "road_wheel.toml"), "--out", str(tmp_path / "out"), "-q")
    assert (code, got, out) == (0, [], "")
    assert (tmp_path / "out" / "manifest.json").is_file()


def test_dry_run_quiet_prints_the_answer_only(tmp_path):
    code, got, out = _lines("build", str(ROOT / "parts" / "road_wheel.toml"), "--dry-run", "-q")
    assert code == 0 and got == [] and "is valid" in out


def test_on_a_terminal_a_live_line_that_goes_when_the_command_ends(tmp_path):
    """stderr a terminal (a pty): the steps as lines and a live line drawn for a terminal under them, the cursor
    shown again at the end, stdout's answer intact; nothing of the live line left in a file written."""
    import pty

    master, slave = pty.openpty()
    p = subprocess.Popen([sys.executable, "-m", "propulsor.cli", "build", str(ROOT / "parts" / "road_wheel.toml"),
                          "--dry-run"], stdin=subprocess.DEVNULL, stdout=slave, stderr=slave, cwd=tmp_path)
    os.close(slave)
    data = b""
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # EIO: the terminal's last writer has gone
            break
        if not chunk:
            break
        data += chunk
    os.close(master)
    assert p.wait(timeout=120) == 0
    text = data.decode("utf-8", "replace")
    assert "road_wheel.toml: reading the part file" in text and "is valid" in text
    assert "\x1b[?25l" in text and "\x1b[?25h" in text  # the live line hid the cursor and gave it back
    assert text.index("\x1b[?25h") < text.index("is valid")  # closed before the answer is printed
    assert list(tmp_path.iterdir()) == []


def test_the_program_leaves_without_the_teardown_having_done_what_the_teardown_would(tmp_path):
    """``propulsor`` ends through cli.leave: a file written through but left open has its buffer on disk, the exit
    functions ran (a temporary folder removed), the exit code is the command's, stdout and stderr complete; with a
    thread still running the normal exit waits for it; a build run as the user runs it ends with its report line and
    code 0 (its time saved is measured in bench/bench_vs_ncgears.py, not here)."""
    script = tmp_path / "leave.py"
    script.write_text(
        "import atexit, sys, tempfile, threading, time\n"
        "from pathlib import Path\n"
        "from propulsor.cli import leave\n"
        "keep = open(sys.argv[1], 'w')\n"
        "keep.write('x' * 100)\n"  # buffered: on disk only once flushed
        "d = tempfile.TemporaryDirectory(dir=sys.argv[2])\n"  # removed by its exit function
        "Path(d.name, 'f').write_text('y')\n"
        "atexit.register(lambda: print('bye'))\n"
        "if sys.argv[3] == 'thread':\n"
        "    threading.Thread(target=lambda: (time.sleep(0.5), open(sys.argv[1] + '.t', 'w').write('t'))).start()\n"
        "print('out', end='')\n"
        "sys.stderr.write('err')\n"
        "leave(7)\n")
    for mode in ("plain", "thread"):
        kept = tmp_path / f"kept_{mode}.txt"
        (tmp_path / mode).mkdir()
        r = subprocess.run([sys.executable, str(script), str(kept), str(tmp_path / mode), mode], capture_output=True,
                           text=True, cwd=ROOT, timeout=120)
        assert (r.returncode, r.stdout, r.stderr) == (7, "outbye\n", "err"), r
        assert kept.read_text() == "x" * 100
        assert list((tmp_path / mode).iterdir()) == []  # the temporary folder removed
        assert (Path(str(kept) + ".t").exists()) == (mode == "thread")
    code, got, _ = _lines("build", str(ROOT / "parts" / "road_wheel.toml"), "--out", str(tmp_path / "out"))
    assert code == 0 and "built into" in got[-1][1] and "all checks passed" in got[-1][1], got[-3:]


@pytest.mark.parametrize("entry", ["run", "module"])
def test_the_program_tunes_its_garbage_collector_before_it_runs_a_command(entry):
    """``propulsor`` (cli.run) and ``python -m propulsor`` set the collector's thresholds to policy.GC_THRESHOLDS
    before the command runs (its builds and their forked workers inherit them: bench notes in policy.py); the
    Python API leaves a user's process as it is (importing propulsor and cli changes nothing)."""
    from propulsor import policy

    call = ("import propulsor.cli as c\n" if entry == "run" else "import propulsor.cli as c, runpy\n")
    script = (
        "import gc, sys\n"
        "import propulsor, propulsor.api\n"
        + call +
        "untouched = gc.get_threshold()\n"
        "def main(argv=None):\n"
        "    print(untouched, gc.get_threshold())\n"
        "    return 0\n"
        "c.main = main\n"
        + ("c.run()\n" if entry == "run" else "runpy.run_module('propulsor', run_name='__main__')\n"))
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == f"{(700, 10, 10)} {policy.GC_THRESHOLDS}"
    assert policy.GC_THRESHOLDS != (700, 10, 10)


def test_a_study_runs_with_pythons_own_garbage_collector():
    """``propulsor explore`` runs as long as its study: the program's tuned collector (set before the command is known)
    is put back to Python's thresholds before the study starts (its cyclic garbage would pile up over the variants);
    a build keeps the tuned one (the test above)."""
    script = (
        "import gc, sys\n"
        "import propulsor.cli as c\n"
        "def explore(args, progress):\n"
        "    print(gc.get_threshold())\n"
        "    return 0\n"
        "c._explore = explore\n"
        "sys.argv = ['propulsor', 'explore', 'any.toml']\n"
        "c.run()\n")
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == f"{(700, 10, 10)}"
    # put back to what the process had before it was first tuned, however often it was tuned; nothing without a tune
    script = ("import gc\nfrom propulsor.collector import tune, untune\n"
              "untune(); a = gc.get_threshold(); gc.set_threshold(800, 11, 12); tune(); tune(); b = gc.get_threshold()\n"
              "untune(); print(a, b, gc.get_threshold())\n")
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr
    from propulsor import policy

    assert r.stdout.strip() == f"{(700, 10, 10)} {policy.GC_THRESHOLDS} {(800, 11, 12)}"
