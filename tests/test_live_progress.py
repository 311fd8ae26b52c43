"""Live progress (issue 39, «long silences»): count events and their throttle (progress.Reporter.count), the
command line's renderer on a terminal (a rich live line) and elsewhere (plain lines, throttled, with the time
left), -q, and the board of several builds side by side."""

from __future__ import annotations

import io
import json
import pickle

import pytest

from propulsor import render
from propulsor.progress import COUNT_EVERY_S, NOTICE, PROGRESS, Event, Reporter, counter
from propulsor.render import Board, Renderer, eta_text


class Clock:
    """time.monotonic / time.perf_counter under the test's hand."""

    def __init__(self, t: float = 1000.0):
        self.t = t

    def __call__(self) -> float:
        return self.t


@pytest.fixture
def clock(monkeypatch):
    c = Clock()
    monkeypatch.setattr("propulsor.progress.time.monotonic", c)
    monkeypatch.setattr("propulsor.render.time.perf_counter", c)
    return c


def test_count_events_are_throttled_first_and_last_always(clock):
    got = []
    say = Reporter(got.append)
    for i in range(1001):  # a loop reporting every turn, all within one instant
        say.count("proof", i, 1000, "phase")
    assert [(e.done, e.total) for e in got] == [(0, 1000), (1000, 1000)]
    assert got[0] == "proof: phase 0/1000" and got[0].phase == "proof" and got[0].kind == PROGRESS
    got.clear()
    say.count("proof", 1, 10)  # at the same instant as the last: held back
    clock.t += 1.0
    say.count("proof", 1, 10)
    clock.t += COUNT_EVERY_S / 2
    say.count("proof", 2, 10)  # too soon after the last one
    clock.t += COUNT_EVERY_S
    say.count("proof", 3, 10)
    assert [e.done for e in got] == [1, 3] and got[1] == "proof: 3/10"


def test_a_new_phase_always_goes(clock):
    got = []
    say = Reporter(got.append)
    say.count("a", 1, 5)
    say.count("b", 1, 5)  # same instant, another phase
    assert [e.phase for e in got] == ["a", "b"]


def test_counter_and_plain_callbacks():
    got = []
    tick = counter(Reporter(got.append), "as made: tolerance cases", 32, "case")
    assert got[-1] == "as made: tolerance cases: case 0/32"
    tick(32)
    assert got[-1].done == 32
    texts = []
    counter(texts.append, "x", 3)(3)  # a callback that takes text only: no counts
    counter(None, "x", 3)(3)
    assert texts == []


def test_events_pickle_with_their_counts():
    e = pickle.loads(pickle.dumps(Event("p: 3/7", PROGRESS, "p", 3, 7)))
    assert (str(e), e.kind, e.phase, e.done, e.total, e.counted) == ("p: 3/7", PROGRESS, "p", 3, 7, True)
    plain = pickle.loads(pickle.dumps(Event("solids")))
    assert plain.phase == "solids" and not plain.counted


def test_plain_lines_one_per_phase_the_counts_throttled_with_time_left(clock):
    out = io.StringIO()
    r = Renderer(stream=out, live=False)
    r(Event("solids"))
    clock.t += 1.0
    for i in range(11):
        r(Event(f"proof: phase {i}/10", PROGRESS, "proof", i, 10))
        clock.t += 1.0  # one a second: a line at the first, after PLAIN_EVERY_S, and the last
    r(Event("report"))
    lines = out.getvalue().splitlines()
    assert lines[0] == "[   0.0 s] solids"
    assert lines[1] == "[   1.0 s] proof: phase 0/10"
    assert lines[2].startswith("[   6.0 s] proof: phase 5/10, about 5 s left")
    assert lines[3] == "[  11.0 s] proof: phase 10/10"
    assert lines[4] == "[  12.0 s] report" and len(lines) == 5


def test_plain_counts_that_give_their_own_time_left_get_none_added(clock):
    out = io.StringIO()
    r = Renderer(stream=out, live=False)
    r(Event("0/4 variants", PROGRESS, "variants", 0, 4))
    clock.t += 10
    r(Event("2/4 variants, 12 per min, about 10 s left; variant 2: ok", PROGRESS, "variants", 2, 4))
    assert out.getvalue().splitlines()[-1] == "[  10.0 s] 2/4 variants, 12 per min, about 10 s left; variant 2: ok"


def test_quiet_prints_the_notices_only():
    out = io.StringIO()
    r = Renderer(quiet=True, stream=out, live=None)
    r(Event("solids"))
    r(Event("proof: 1/2", PROGRESS, "proof", 1, 2))
    r(Event("output is being built by process 7; waiting", NOTICE))
    r.close()
    assert out.getvalue() == "propulsor: output is being built by process 7; waiting\n"
    assert not r.live


def test_not_a_terminal_is_plain_by_itself():
    out = io.StringIO()
    assert not Renderer(stream=out).live
    assert Renderer(stream=out, live=True).live


def test_live_line_on_a_terminal(clock):
    out = io.StringIO()
    r = Renderer(stream=out, live=True)
    r(Event("solids"))
    r(Event("proof: phase 0/40", PROGRESS, "proof", 0, 40))
    clock.t += 2.0
    r(Event("proof: phase 20/40", PROGRESS, "proof", 20, 40))
    r._progress.refresh()
    drawn = out.getvalue()
    r.close()
    assert "\x1b[" in drawn  # drawn for a terminal (cursor and colour codes)
    assert "20/40" in drawn and "about 2 s left" in drawn  # the count and the time left at its pace
    assert "[   0.0 s] solids" in drawn and "[   0.0 s] proof" in drawn  # each new step stays as a line
    assert "phase 20/40" not in drawn.split("[   0.0 s] proof")[1].split("\n")[0]  # counts only on the live line
    r(Event("after"))  # closed: plain lines
    assert out.getvalue().endswith("after\n")


def test_eta_text():
    assert eta_text(None) == "" and eta_text(0.2) == "about 1 s left"
    assert eta_text(42.4) == "about 42 s left" and eta_text(600) == "about 10 min left"


def test_board_plain_one_line_per_step_of_each_build(clock):
    out = io.StringIO()
    b = Board(stream=out, live=False)
    b.start(1, "parts/a.toml")
    b.start(2, "parts/b.toml")
    ev = [dict(kind="progress", text="solids", phase="solids", done=None, total=None),
          dict(kind="progress", text="proof: 0/4", phase="proof", done=0, total=4),
          dict(kind="progress", text="proof: 1/4", phase="proof", done=1, total=4),  # throttled
          dict(kind="notice", text="check failed: x", phase="check failed: x", done=None, total=None)]  # its stderr's
    data = "".join(json.dumps(e) + "\n" for e in ev).encode()
    b.feed(1, data[:17])  # a line in pieces
    b.feed(1, data[17:])
    b.end(1)
    b.close()
    assert out.getvalue().splitlines() == ["propulsor: building parts/a.toml", "propulsor: building parts/b.toml",
                                           "[   0.0 s] parts/a.toml: solids", "[   0.0 s] parts/a.toml: proof: 0/4"]


def test_board_live_lines(clock):
    out = io.StringIO()
    b = Board(stream=out, live=True)
    b.start(1, "parts/a.toml")
    b.start(2, "parts/b.toml")
    b.feed(2, (json.dumps(dict(kind="progress", text="proof: 3/9", phase="proof", done=3, total=9)) + "\n").encode())
    b._progress.refresh()
    b.close()
    drawn = out.getvalue()
    assert "parts/a.toml" in drawn and "parts/b.toml: proof" in drawn and "3/9" in drawn and "\x1b[" in drawn


def test_forwarded_events(tmp_path, monkeypatch):
    import os

    rfd, wfd = os.pipe()
    monkeypatch.setattr(render, "_FORWARD_FD", wfd)
    r = Renderer(quiet=True, stream=io.StringIO(), live=False)
    r(Event("proof: 2/5", PROGRESS, "proof", 2, 5))
    os.close(wfd)
    monkeypatch.setattr(render, "_FORWARD_FD", None)
    with os.fdopen(rfd, "rb") as f:
        assert json.loads(f.readline()) == dict(kind="progress", text="proof: 2/5", phase="proof", done=2, total=5)


def _fake_build(args, part_file, depfile, gallery=True):
    """A build that reports as a real one does (its own Renderer, a step, a count, a notice)."""
    import time

    with Renderer(args.quiet) as r:
        say = Reporter(r)
        say(f"{part_file.stem}: solids")
        tick = say.counter(f"{part_file.stem}: proof", 3, "phase")
        for i in range(1, 4):
            time.sleep(0.05)
            tick(i)
        say.notice(f"{part_file.stem}: a notice")
    return 0


@pytest.mark.parametrize("quiet", [False, True])
def test_builds_side_by_side_report_through_the_board(monkeypatch, capfd, quiet, tmp_path):
    """`propulsor build a b` (what make runs), stderr not a terminal: each build's steps and counts come as
    plain lines while it runs, named by its part file, and are not repeated when its own output is written
    out at its end (that keeps its notices); -q: the notices only."""
    from pathlib import Path

    import propulsor.cli as cli

    root = Path(__file__).resolve().parents[1]
    monkeypatch.setenv("PROPULSOR_JOBS", "2")
    monkeypatch.delenv("MAKEFLAGS", raising=False)
    monkeypatch.setattr(cli, "build_one", _fake_build)
    monkeypatch.chdir(tmp_path)  # no output/ here: no gallery written after the builds
    files = [str(root / "parts" / f"{n}.toml") for n in ("road_wheel", "cam_linear")]
    assert cli.main(["build", *files] + (["-q"] if quiet else [])) == 0
    err = capfd.readouterr().err.splitlines()
    notices = [ln for ln in err if ln.endswith(": a notice")]
    assert sorted(notices) == ["propulsor: cam_linear: a notice", "propulsor: road_wheel: a notice"]
    if quiet:
        assert err == notices
        return
    assert err[0] == "[   0.0 s] 2 part files: loading the CAD kernel and the checks"
    for f, stem in zip(files, ("road_wheel", "cam_linear")):
        mine = [ln for ln in err if f in ln or ln.startswith(f"propulsor: {stem}")]
        assert f"propulsor: building {f}" in mine
        assert sum(ln.endswith(f"{f}: {stem}: solids") for ln in err) == 1, err  # the board's, while it runs
        assert not any(ln.endswith(f"s] {stem}: solids") for ln in err), err  # not again in its output at its end
        assert any(ln.endswith(f"{f}: {stem}: proof: phase 0/3") for ln in mine), err
        assert any(ln.endswith(f"{f}: {stem}: proof: phase 3/3") for ln in mine), err


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


@pytest.mark.parametrize("makeflags, live", [(None, True), ("", True), (" -j2 --jobserver-auth=3,4", False),
                                             (" -j", False)])
def test_live_on_a_terminal_but_not_under_a_parallel_make(monkeypatch, makeflags, live):
    """`make -jN` may run other commands drawing on the same terminal at once: plain lines there."""
    if makeflags is None:
        monkeypatch.delenv("MAKEFLAGS", raising=False)
    else:
        monkeypatch.setenv("MAKEFLAGS", makeflags)
    assert Renderer(stream=_Terminal()).live is live and Board(stream=_Terminal()).live is live
    assert not Renderer(quiet=True, stream=_Terminal()).live


def _ticking_job(n: int) -> int:
    import time

    from propulsor.parallel import tick

    for i in range(1, n + 1):
        time.sleep(0.02)
        tick(i, n)
    return n


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_job_counts_to_the_build_that_started_it(monkeypatch, jobs):
    """parallel.start(..., counter=): a job's ticks reach the counter — at once when it runs inline (a budget of
    one process), through a pipe while parallel.result waits for it when forked (the last always)."""
    from propulsor import job_ticks, parallel

    monkeypatch.setenv("PROPULSOR_JOBS", jobs)
    monkeypatch.delenv("MAKEFLAGS", raising=False)
    got = []
    with parallel.Workers():
        job = parallel.start(_ticking_job, 20, counter=lambda done, total: got.append((done, total)))
        assert parallel.result(job) == 20
        assert parallel.result(parallel.start(_ticking_job, 3)) == 3  # without a counter: as before
    if jobs == "1":
        assert isinstance(job, parallel.Done) and got == [(i, 20) for i in range(1, 21)]
    else:
        assert not isinstance(job, parallel.Done) and got[-1] == (20, 20) and 1 <= len(got) < 20
        assert job.propulsor_ticks.fd == -1  # its pipe closed once collected
    assert job_ticks._TICK is None


def test_a_count_read_late_paces_from_its_first_count(clock):
    """A worker's count read only when the build waits for it starts at, say, 2500/7200: the time left is at
    the pace from there, not as if those 2500 had taken no time."""
    out = io.StringIO()
    r = Renderer(stream=out, live=False)
    r(Event("c: 2500/7200", PROGRESS, "c", 2500, 7200))
    clock.t += 10
    r(Event("c: 3000/7200", PROGRESS, "c", 3000, 7200))
    assert out.getvalue().splitlines()[-1] == "[  10.0 s] c: 3000/7200, about 84 s left"


def test_no_time_left_from_the_first_few_items_of_a_step():
    from propulsor.render import _eta

    assert _eta(4, 216, 100.0, 101.8) is None  # 4 of 216 in 1.8 s: too few to give a pace
    assert _eta(4, 240, 100.0, 119.1) is None  # 4 of 240 in 19 s (the trial's "19 min left", 2 s left): still too few
    assert _eta(11, 216, 100.0, 101.0) == pytest.approx(1.0 / 11 * 205)  # a twentieth done: the pace
    assert _eta(10, 216, 100.0, 101.0) is None
    assert _eta(4, 216, 100.0, 130.0) == pytest.approx(30.0 / 4 * 212)  # 30 s spent: the pace
    assert _eta(4, 216, 100.0, 129.9) is None


def test_check_counts_the_files_it_checks(tmp_path):
    """`propulsor check` of a folder: the files with checks counted (the others are not models)."""
    from propulsor.checks.files import check_path
    from propulsor.progress import Reporter

    (tmp_path / "a.stl").write_bytes(b"solid a\nendsolid a\n")
    (tmp_path / "b.dxf").write_text("0\nEOF\n")
    (tmp_path / "notes.csv").write_text("x\n1\n")
    seen = []
    check_path(tmp_path, progress=Reporter(seen.append))
    counts = [(e.done, e.total) for e in seen if getattr(e, "total", None) is not None]
    assert counts[0] == (0, 2) and counts[-1] == (2, 2)
    assert seen[0] == f"check: reading {tmp_path}"


def _ticks_then_nests(n: int) -> int:
    """In a worker: its own ticks, and a nested job (started without a counter) that ticks too."""
    from propulsor.parallel import result, start, tick

    import time

    tick(1, n)
    assert result(start(_ticking_job, 7)) == 7  # the nested job's ticks are not this job's
    time.sleep(0.5)  # (the pump reads what came meanwhile)
    for i in range(2, n + 1):
        tick(i, n)
    return n


@pytest.mark.parametrize("jobs", ["1", "2", "3"])  # inline; the nested job forked from the worker
def test_a_forked_jobs_ticks_reach_the_counter_while_the_build_works_on(monkeypatch, jobs):
    """The build does other work after starting a counted job (the seed-002 pair's animations and assembly while
    both contact directions run): the job's count is shown as it comes, not when the build waits for the result
    (before: 8 s of silence, then "7201/7201" at once).  A nested job's ticks stay out of its count."""
    import time

    from propulsor import job_ticks, parallel

    monkeypatch.setenv("PROPULSOR_JOBS", jobs)
    monkeypatch.delenv("MAKEFLAGS", raising=False)
    got = []
    with parallel.Workers():
        job = parallel.start(_ticking_job, 30, counter=lambda done, total: got.append((done, total)))
        deadline = time.monotonic() + 30.0
        while not got and time.monotonic() < deadline:  # busy here, never in parallel.result
            sum(range(10000))
        seen_before_result = list(got)
        assert parallel.result(job) == 30
        nested = parallel.start(_ticks_then_nests, 5, counter=lambda done, total: got.append((done, total)))
        assert parallel.result(nested) == 5
    assert seen_before_result and seen_before_result[0][1] == 30
    assert got[-1] == (5, 5) and all(total in (30, 5) for _, total in got)
    assert not job_ticks._LIVE_TICKS


class _Params:
    """Parameters (the designs are kept beside the parameter object)."""


def _design_says(params, w):
    w.progress("the design's first step")
    w.progress.count("the design's teeth", 3, 3, "tooth")
    return ("designed", params)


def test_the_design_computed_apart_shows_its_steps(monkeypatch):
    """The design computed in a forked process while the build loads the CAD kernel (pipeline.design_apart) shows
    its steps and counts (before: none of them, 4-7 s of silence on the seed-002 pair)."""
    from propulsor import parallel
    from propulsor.parts.pipeline import design_apart

    monkeypatch.setenv("PROPULSOR_JOBS", "2")
    monkeypatch.delenv("MAKEFLAGS", raising=False)
    got = []

    class W:
        progress = Reporter(got.append)

        def warm_up(self):
            got.append("warm-up")

    params = _Params()
    with parallel.Workers():
        made = design_apart(_design_says, params, W())
    assert made[0] == "designed" and isinstance(made[1], _Params)
    events = [e for e in got if e != "warm-up"]
    assert [str(e) for e in events] == ["the design's first step", "the design's teeth: tooth 3/3"]
    assert events[1].counted and events[1].phase == "the design's teeth" and "warm-up" in got


def test_counts_of_jobs_side_by_side_are_one_count(clock):
    from propulsor.progress import count_shared

    got = []
    a, b = count_shared(Reporter(got.append), "contact", 2, "position")
    a(10, 100)  # b not heard from: taken as large as a
    clock.t += 1.0
    b(5, 80)
    clock.t += 1.0
    a(100, 100)
    clock.t += 1.0
    b(80, 80)
    assert [(e.done, e.total) for e in got] == [(10, 200), (15, 180), (105, 180), (180, 180)]
    assert got[0] == "contact: position 10/200"
    assert count_shared(lambda e: None, "contact", 2) == [None, None]
    assert count_shared(Reporter(None), "contact", 2) == [None, None]  # nobody listens: no counter


def test_two_counts_at_once_keep_their_own_pace_and_lines(clock):
    """A worker's count and the build's own interleave: each keeps its pace, and the live view prints a step's
    line once, not at every switch."""
    out = io.StringIO()
    r = Renderer(stream=out, live=True)
    for i in range(0, 11):
        r(Event(f"a: {i}/10", PROGRESS, "a", i, 10))
        r(Event(f"b: {10 * i}/100", PROGRESS, "b", 10 * i, 100))
        clock.t += 1.0
    r.close()
    drawn = out.getvalue()
    assert drawn.count("[   0.0 s] a") == 1 and drawn.count("[   0.0 s] b") == 1 and drawn.count(" s] ") == 2
    out = io.StringIO()
    clock.t = 1000.0
    r = Renderer(stream=out, live=False)
    r(Event("a: 0/10", PROGRESS, "a", 0, 10))
    clock.t += 4.0
    r(Event("b: 50/100", PROGRESS, "b", 50, 100))
    clock.t += 2.0
    r(Event("a: 6/10", PROGRESS, "a", 6, 10))  # 6 in 6 s: 4 s left (b's count between did not restart a's pace)
    assert out.getvalue().splitlines()[-1] == "[   6.0 s] a: 6/10, about 4 s left"


def test_check_in_a_pipe_shows_its_count_and_q_silences_it(tmp_path, capsys):
    """`propulsor check` shows its steps as the other commands do when its stderr is a pipe or a log (before: only
    on a terminal, 39 s of silence over one pair's folder); -q leaves stderr to the refusals."""
    from propulsor.cli import main

    (tmp_path / "a.stl").write_bytes(b"solid a\nendsolid a\n")
    (tmp_path / "b.dxf").write_text("0\nEOF\n")
    main(["check", str(tmp_path)])
    err = capsys.readouterr().err
    assert f"check: reading {tmp_path}" in err and "2/2" in err
    main(["check", "-q", str(tmp_path)])
    assert capsys.readouterr().err == ""
