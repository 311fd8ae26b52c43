"""Several part files built by one command (`propulsor build a.toml b.toml …`, what `make` runs): the
imports paid once, each build in a child forked from the same state, as many side by side as the
process budget allows, the longest first.  Part of the command line's face (it runs the command line's
``build_one`` in each child and gathers their exit codes and output); the builds are the build service's."""

from __future__ import annotations

import os
import signal
import sys
from pathlib import Path

from .collector import off_then_frozen
from .progress import Reporter
from .render import Board, forward_to
from .signals import Interrupted, check_signalled, hold_signals


def longest_first(files: list[Path], progress=None) -> list[int]:
    """Indices of the part files, the longest build first by its size estimate (a file that cannot be read or
    whose values are refused first of all: it fails at once), so that the builds running side by side end close
    together.  The estimate is made before the design's feasibility is checked (``building.early_estimate``: from
    the values, or the validated values where the part type's estimate needs them): the design's feasibility
    (which computes the design: up to half a second a file) is checked by each build's own load, in its forked
    child, side by side with the others (checked here, it took 3-4 s of wall before the first build, one core
    idle; the balancer's arm outline alone 0.7 s).  A file refused there fails when its turn comes, with the same
    message and exit code.  `progress`: told the files checked (a count)."""
    from .building import early_estimate

    tick = Reporter.of(progress).counter("checking the part files", len(files), "file")
    keys = {}
    for k in range(len(files)):
        try:
            seconds = early_estimate(files[k])
        except Exception:  # noqa: BLE001 - its own build reports it
            keys[k] = (-float("inf"), k)
        else:
            keys[k] = (-seconds, k)
        tick(k + 1)
    return sorted(range(len(files)), key=keys.__getitem__)


def build_many(args, files: list[Path], budget: int, jobserver, each, placed: tuple[int, ...]) -> list[int]:
    """``propulsor build`` of several part files: the modules loaded once (:func:`preload`), each build
    (``each(args, part_file, depfile) -> exit code``) in a forked child, side by side within `budget` where it may
    fork, else one after the other; then the gallery beside them once (when it is one: building.gallery_folder).
    Returns each build's exit code, in the order they ended.  `placed`: the codes of a build whose output is in place.
    A signal: the gallery written for the builds in place and the command line's one line told of them
    (``Interrupted.kept``), then raised on."""
    from .parallel import can_fork
    from .parts import solid_cache
    from .render import Renderer

    def depfile(part_file):
        return Path(args.depfile_dir) / f"{part_file.stem}.mk" if args.depfile_dir else None

    finished: list[int] = []
    try:
        with Renderer(args.quiet) as render:
            render(f"{len(files)} part files: loading the CAD kernel and the checks")
            apart = budget > 1 and can_fork() and not args.dry_run
            with off_then_frozen():  # the part types' modules the estimates import, frozen with the rest
                preload()
                order = longest_first(files, render) if apart else None
            with solid_cache.batch_scope():  # a solid two builds share: written and checked once
                if apart:
                    side_by_side(args, files, order, depfile, budget, each, jobserver, progress=render,
                                 finished=finished)
                else:
                    render.close()
                    for f in files:
                        finished.append(in_child(each, args, f, depfile(f), label=str(f)))
        if not args.dry_run and any(c in placed for c in finished):
            _gallery_once(args)
    except Interrupted as exc:
        hold_signals()
        built = sum(c in placed for c in finished) + exc.placed_before
        if built and not args.dry_run:
            page = _gallery_once(args, told=False)  # no progress line: the command line's one line says it
            exc.kept = (f"{built} of {len(files)} builds finished, their output in {args.out_dir or 'output'}/"
                        + (" (the gallery shows them)" if page is not None else "") + "; nothing else written")
        raise
    return finished


def _gallery_once(args, told: bool = True) -> Path | None:
    """The gallery beside a batch's output folders, once after its builds (as each build alone would have written
    it: building.publish): the page written, or None (no gallery's folder, or not written).  `told`: the progress
    lines and a notice if it could not be written."""
    from .building import gallery_folder, regenerate_gallery
    from .render import Renderer

    folder = Path(args.out_dir or "output")
    if not (folder.is_dir() and gallery_folder(folder)):
        return None
    if not told:
        return regenerate_gallery(folder)
    with Renderer(args.quiet) as render:
        return regenerate_gallery(folder, render)


def side_by_side(args, files: list[Path], order: list[int], depfile, slots: int, build, jobserver=None,
                 progress=None, finished: list[int] | None = None) -> list[int]:
    """Build the part files (``build(args, part_file, depfile) -> exit code``) in forked children, as many
    at once as `slots` (the process budget, shared with the children's own workers once the last build
    has started: parallel.share_slots; under make's `jobserver` a slot beyond the first also takes one
    of make's tokens), the longest first.  Each child's output is held in a temporary file and written
    out whole when it ends, so that the lines of two builds do not interleave; meanwhile each sends its events
    through a pipe to a :class:`~.render.Board` (one live line per build on a terminal, a plain line per step
    elsewhere).  `progress`: told the part files checked before the first build starts (then closed).  A
    signal stops every build; `finished` (a list) is given the exit code of each build as it ends, so that what
    ended before a signal is known.  `order`: the files' indices in the order to start them
    (:func:`longest_first`'s)."""
    import select
    import tempfile

    from .parallel import open_slots_to_workers, share_slots

    pool = share_slots(slots, jobserver)
    pending = list(order)
    if progress is not None and hasattr(progress, "close"):
        progress.close()
    running: dict[int, tuple[int, object, object, bytes | None]] = {}
    pipes: dict[int, int] = {}  # pid -> the read end of its events' pipe
    words: dict[int, _PlacedWord] = {}  # pid -> its word that its output is in place
    codes: list[int] = [0] * len(files)  # each the exit code its build ends with
    board = Board(args.quiet, t0=getattr(progress, "t0", None))

    def drain(timeout: float) -> None:
        if not pipes:
            return
        ready, _, _ = select.select(list(pipes.values()), [], [], timeout)
        for pid, fd in list(pipes.items()):
            if fd in ready:
                _read_into(board, pid, fd)

    try:
        while pending or running:
            check_signalled()  # a signal swallowed where Python could not raise it (a fork's callbacks, a finaliser)
            drain(0.0)
            # a slot of the budget for the next build; with none running, a slot still held by a worker that
            # was killed would never come back: start anyway after a moment
            slot = pool.take(timeout=0.05) if pending else None
            if pending and slot is None and not running:
                slot = pool.take(timeout=2.0)
                if slot is None:
                    _started_without_slot()
            if pending and (slot is not None or not running):
                k = pending.pop(0)
                out, err = tempfile.TemporaryFile(), tempfile.TemporaryFile()
                rfd, wfd = os.pipe()
                os.set_blocking(rfd, False)
                word = _PlacedWord()
                others = tuple(pipes.values()) + tuple(w.r for w in words.values()) + (rfd,)
                pid = fork(_forwarding, (build, wfd, word, others, not board.live, args, files[k], depfile(files[k])),
                           out.fileno(), err.fileno(), str(files[k]))
                os.close(wfd)
                word.parent()
                pipes[pid] = rfd
                words[pid] = word
                board.start(pid, str(files[k]))
                running[pid] = (k, out, err, slot)
                if not pending:  # the last builds may use the slots the others leave
                    open_slots_to_workers()
                continue
            if not pending:
                drain(0.2)
            pid, status = os.waitpid(-1, os.WNOHANG)
            if pid == 0 or pid not in running:
                continue
            k, out, err, slot = running.pop(pid)
            if slot is not None:
                pool.give(slot)
            codes[k] = os.waitstatus_to_exitcode(status)
            if finished is not None:
                finished.append(codes[k])
            _read_into(board, pid, pipes[pid])
            os.close(pipes.pop(pid))
            words.pop(pid).close()
            board.end(pid)
            for f, stream in ((out, sys.stdout), (err, sys.stderr)):
                f.seek(0)
                board.write(stream, f.read())
                f.close()
    except Interrupted as exc:
        for pid in running:
            try:
                os.kill(pid, exc.signum)
            except ProcessLookupError:
                pass
        for pid, (_k, _out, _err, slot) in running.items():
            try:
                os.waitpid(pid, 0)
            except ChildProcessError:
                pass
            words.pop(pid).count_into(exc)  # ended or stopped, not yet seen here
            if slot:  # make's token goes back to make
                pool.give(slot)
        raise
    finally:
        board.close()
        for fd in pipes.values():
            os.close(fd)
        for word in words.values():
            word.close()
        share_slots(None)
    return codes


def _read_into(board: Board, key, fd: int) -> None:
    """What build `key`'s pipe holds now, to the board."""
    while True:
        try:
            data = os.read(fd, 65536)
        except (BlockingIOError, InterruptedError):
            return
        if not data:
            return
        board.feed(key, data)


def _forwarding(build, wfd: int, word: "_PlacedWord", close: tuple[int, ...], shown_there: bool, *args) -> int:
    """In a forked build: its events also to `wfd` (never blocking it: a full pipe drops them), its output put in
    place told through `word`, the read ends of the pipes in `close` closed, its steps printed by the board alone
    when `shown_there` (plain lines: its own output, written out when it ends, keeps its notices and errors); then
    ``build(*args)``."""
    word.child()
    for fd in close:
        os.close(fd)
    os.set_blocking(wfd, False)
    forward_to(wfd, shown_there)
    return build(*args)


def with_jobserver(fn, slots: int, jobserver):
    """fn() -> exit code for one build, its workers taking make's tokens (`slots` processes at most)."""
    from .parallel import open_slots_to_workers, share_slots

    pool = share_slots(slots, jobserver)
    own = pool.take(timeout=2.0)  # the slot make started this command for
    open_slots_to_workers()
    try:
        return fn()
    finally:
        if own is not None:
            pool.give(own)
        share_slots(None)


def _started_without_slot() -> None:
    print("propulsor: no free process slot (a killed worker kept one); building anyway", file=sys.stderr, flush=True)


#: what every build imports and what costs (OCCT, cadquery, matplotlib, scipy, trimesh, manifold3d):
#: imported once before the builds of several part files are forked
PRELOAD = ("propulsor.parts", "propulsor.parts.writer", "propulsor.solids.build", "propulsor.solids.kernel",
           "propulsor.export.step", "propulsor.export.mesh", "propulsor.export.plots", "propulsor.export.dxf",
           "propulsor.checks.mesh", "propulsor.checks.brep", "propulsor.checks.motion", "scipy.optimize",
           "scipy.integrate", "scipy.interpolate", "markdown", "propulsor.export.animation", "propulsor.export.html",
           "propulsor.export.render", "propulsor.export.glb_check", "propulsor.output_folder")


def preload() -> None:
    """The modules every build uses and the compiled kernels, loaded once before the builds fork (each child has
    them); then what is loaded is moved out of the garbage collector's sight (``gc.freeze``), so that the children's
    full collections do not scan the ~400 000 objects of the imported modules again (nor write to every page that
    holds one, which a forked child then copies).  Only objects made afterwards are collected; the frozen ones live
    as long as the process anyway.  The collector is off while they load (:func:`.collector.off_then_frozen`)."""
    import importlib

    with off_then_frozen():
        for name in PRELOAD:
            importlib.import_module(name)
        # the CAD kernel's wrapper (its VTK deferred): imported here once, not in every build (0.7 CPU s each)
        from .solids.cq_import import import_cadquery

        import_cadquery()
        # the compiled kernels (mesh checks, sweeps, contact): loaded (or compiled, once per machine) before the
        # builds fork
        from .checks.kernels import warm

        warm()
        # the first figure's costs (pyplot's backend module, the font search) paid once, here, for every build and
        # worker that draws (13-19 processes in make, about 20 ms each); the throwaway figure's garbage (about 5 000
        # objects) frozen with the rest
        from .export.plots import warm as warm_plots

        warm_plots()


def in_child(fn, *args, label: str | None = None) -> int:
    """fn(*args) -> exit code, in a forked child (where fork is missing: here).  Each build of several
    starts from the same process state — OCCT's process-wide counters (the STEP writer numbers assembly
    occurrences with one), caches, figures — so it writes the same bytes as a build on its own.  A
    signal to this process is passed on to the child, and waited for; `label` (the part file) names the child in
    its line when a signal stops it."""
    if not hasattr(os, "fork"):
        return fn(*args)
    word = _PlacedWord()
    pid = fork(_telling, (word, fn) + args, label=label)
    word.parent()
    try:
        check_signalled()  # a signal that came while the fork's own callbacks ran in this process (swallowed there)
        _, status = os.waitpid(pid, 0)
    except Interrupted as exc:
        os.kill(pid, exc.signum)
        os.waitpid(pid, 0)
        word.count_into(exc)  # its output put in place before the signal stopped it
        raise
    finally:
        word.close()
    return os.waitstatus_to_exitcode(status)


def _telling(word: "_PlacedWord", fn, *args) -> int:
    """In a forked build: its output put in place told through `word`; then ``fn(*args)``."""
    word.child()
    return fn(*args)


class _PlacedWord:
    """A forked build's word that its output is in place (:func:`.building.tell_placed`): one byte through a pipe of
    its own, read once the child has ended or been stopped, so that a batch stopped by a signal counts a build whose
    output was placed before the batch saw it end (its exit code lost, or 130 from the signal that came after).  The
    events' pipe cannot say it: a full buffer drops what it cannot take."""

    def __init__(self):
        self.r, self.w = os.pipe()
        os.set_blocking(self.r, False)

    def child(self) -> None:
        from .building import tell_placed_to

        os.close(self.r)
        tell_placed_to(self.w)

    def parent(self) -> None:
        os.close(self.w)

    def told(self) -> bool:
        """Whether the byte came (the child has ended: what it wrote is in the pipe)."""
        try:
            return os.read(self.r, 1) == b"1"
        except (BlockingIOError, OSError):
            return False

    def count_into(self, exc: Interrupted) -> None:
        """Once the child has ended or been stopped: count it in ``exc.placed_before`` if it told; then close."""
        if self.told():
            exc.placed_before += 1
        self.close()

    def close(self) -> None:
        if self.r >= 0:
            os.close(self.r)
            self.r = -1


def fork(fn, args, stdout_fd: int | None = None, stderr_fd: int | None = None, label: str | None = None) -> int:
    """Fork a child that runs fn(*args) -> exit code (its standard output and error sent to the given file
    descriptors, when given) and leaves; returns its pid.  A signal that stops the child: one line, naming `label`
    (the part file of a build of several) when given."""
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:  # the child: run, report, and leave without unwinding the parent's stack
        if stdout_fd is not None:
            os.dup2(stdout_fd, sys.stdout.fileno())
        if stderr_fd is not None:
            os.dup2(stderr_fd, sys.stderr.fileno())
        code = 70
        try:
            code = fn(*args)
        except Interrupted as exc:
            from .parallel import kill_workers

            hold_signals()
            kill_workers()
            print(f"propulsor: {label + ': ' if label else ''}interrupted by {signal.Signals(exc.signum).name}; "
                  f"{getattr(exc, 'kept', 'nothing written')}", file=sys.stderr)
            code = 128 + exc.signum
        except BaseException:  # noqa: BLE001 - reported as the traceback Python would print
            import traceback

            traceback.print_exc()
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os._exit(code)
    return pid
