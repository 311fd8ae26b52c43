"""Command line: `propulsor build | print | gallery | check | list | params`.

Exit codes: 0 built and every check passed; 1 built but a check failed (outputs
kept only with --keep-failed) or `check` found invalid files; 2 bad input
(one line on stderr, nothing written); 130 / 143 interrupted by SIGINT / SIGTERM
(one line, no temporary folder and no worker process left).
"""

from __future__ import annotations

import argparse
import os
import shutil
import signal
import sys
import threading
from pathlib import Path

from .errors import InputError

EXIT_OK, EXIT_CHECK_FAILED, EXIT_BAD_INPUT = 0, 1, 2


class Interrupted(BaseException):
    """SIGINT or SIGTERM arrived; the exit code is 128 + the signal number."""

    def __init__(self, signum: int):
        self.signum = signum
        super().__init__(signum)


#: signals received; the handler raises at once, but an exception raised inside a finaliser or a
#: weakref callback is swallowed by Python, so the build also stops at the next safe point
_SIGNALLED: list[int] = []


def _raise_interrupted(signum, frame):
    _SIGNALLED.append(signum)
    raise Interrupted(signum)


def _unraisable(info) -> None:
    """Python's hook for exceptions it cannot raise (in finalisers, weakref callbacks): an Interrupted
    there is remembered in _SIGNALLED and acted on at the next safe point, not printed."""
    if isinstance(info.exc_value, Interrupted):
        return
    sys.__unraisablehook__(info)


def check_signalled() -> None:
    """Raise Interrupted when a signal arrived whose exception may have been swallowed."""
    if _SIGNALLED:
        raise Interrupted(_SIGNALLED[0])


def _hold_signals() -> None:
    """Ignore further SIGINT / SIGTERM while cleaning up (a second Ctrl-C must not leave debris)."""
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_IGN)


def _fail_input(exc: Exception) -> int:
    print(f"propulsor: error: {exc}", file=sys.stderr)
    return EXIT_BAD_INPUT


def _files_read(params, part_file: Path) -> tuple[Path, ...]:
    """The part file and every file it names (string parameters ending in `_file`, relative to it)."""
    import dataclasses

    files = [part_file]
    for f in dataclasses.fields(params):
        v = getattr(params, f.name)
        if f.name.endswith("_file") and isinstance(v, str) and v:
            p = Path(v)
            files.append(p if p.is_absolute() else part_file.resolve().parent / p)
    return tuple(files)


def _load_part(part_file: Path):
    """(part type, validated parameters, size estimate) of a part file; InputError otherwise."""
    from .params import load_params, read_part_file
    from .parts import check_size, get_part_type, size_needs_design

    part_type_name, mapping = read_part_file(part_file)
    part_type = get_part_type(part_type_name)
    params = load_params(part_type.params_cls, mapping, validate=False)
    # the size estimate first where it needs only the values (a design can itself be the long part)
    early = not size_needs_design(part_type)
    estimate = check_size(part_type, params, part_file) if early else None
    if callable(getattr(params, "validate", None)):
        params.validate()
    return part_type, params, estimate or check_size(part_type, params, part_file)


def _write_depfile(depfile: Path, target: Path, files) -> None:
    """A make rule ``target: files`` (paths relative to the current folder), written in one step: the
    files a build read besides its part file (``road_wheel_file`` …) become prerequisites of its
    manifest."""
    import os

    def rel(p: Path) -> str:
        return os.path.relpath(Path(p).resolve()).replace(" ", "\\ ")

    depfile.parent.mkdir(parents=True, exist_ok=True)
    tmp = depfile.with_name(depfile.name + f".tmp{os.getpid()}")
    tmp.write_text(f"{rel(target)}: {' '.join(rel(f) for f in files)}\n")
    os.replace(tmp, depfile)


def _into_output(args, out: Path, keep: tuple[Path, ...], produce, progress, depfile=None) -> int:
    """Run ``produce(tmp) -> (failures, what)`` into a fresh temporary folder beside `out` with the
    lock of `out` held, then put the result in place of `out` in one step (or drop it when a check
    failed and --keep-failed is not given).  Exit codes as in the module docstring."""
    from . import output_folder as of
    from .parallel import close_in_workers, kill_workers

    lock = of.OutputLock(out)
    tmp = None
    try:
        of.prepare_parent(out)
        try:
            lock.acquire(wait=not args.no_wait,
                         on_wait=lambda pid: print(f"propulsor: {out} is being built by process {pid}; waiting",
                                                   file=sys.stderr, flush=True))
        except of.Busy as busy:
            raise InputError("--out", str(out), f"is being built by process {busy.pid} (--no-wait)") from None
        close_in_workers(lock.fd)
        of.vet_target(out, force=args.force, keep=keep)  # as it is now, after the wait
        for stale in of.clean_stale(out):
            progress(f"removed {stale.name}, left by a build that was killed")
        tmp = of.make_temp(out)
        failures, what = produce(tmp)
        check_signalled()  # a swallowed interrupt: the output is not put in place
        for f in failures:
            print(f"propulsor: check failed: {f}", file=sys.stderr)
        if failures and not args.keep_failed:
            print(f"propulsor: {what}: {len(failures)} check(s) failed; nothing written "
                  f"(use --keep-failed to keep the outputs)", file=sys.stderr)
            return EXIT_CHECK_FAILED
        of.replace(tmp, out)
        if _gallery_folder(out.parent):
            _regenerate_gallery(out.parent, progress)
        if failures:
            print(f"propulsor: {what}: built into {out} but {len(failures)} check(s) failed", file=sys.stderr)
            return EXIT_CHECK_FAILED
        progress(f"{what}: built into {out}, all checks passed")
        if depfile:
            _write_depfile(Path(depfile), out / "manifest.json", keep)
        return EXIT_OK
    except InputError as exc:
        return _fail_input(exc)
    finally:
        _hold_signals()
        kill_workers()
        if tmp is not None and tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)
        close_in_workers(None)
        lock.release()


def _gallery_folder(folder: Path) -> bool:
    """Whether a build into a sub-folder of `folder` rewrites ``folder/index.html``: the default
    output folder (./output), or a folder whose gallery propulsor already wrote (``propulsor gallery
    DIR``).  Elsewhere nothing is written beside the output."""
    from .export.gallery import INDEX, is_ours

    try:
        return folder.resolve() == Path("output").resolve() or is_ours(folder / INDEX)
    except OSError:
        return False


def _regenerate_gallery(folder: Path, progress) -> Path | None:
    """Rewrite ``folder/index.html`` (the gallery of every part built there) after a build put its
    output in place.  Under the gallery's own lock, so that of two builds finishing together the later
    one writes a page that shows both; never over an index.html propulsor did not write."""
    from . import output_folder as of
    from .export.gallery import INDEX, write_gallery

    lock = of.OutputLock(folder / INDEX)
    try:
        lock.acquire(wait=True)
        path = write_gallery(folder)
    except Exception as exc:  # noqa: BLE001 - the build's output is in place; the page is not worth failing it
        print(f"propulsor: the gallery {folder / INDEX} was not written: {type(exc).__name__}: {exc}", file=sys.stderr)
        return None
    finally:
        lock.release()
    if path is None:
        progress(f"{folder / INDEX} was not written by propulsor: left as it is")
    else:
        progress(f"gallery: {path}")
    return path


def cmd_gallery(args) -> int:
    """output/index.html: one page for every part built in the folder."""
    from .export.gallery import INDEX, built_parts
    from .progress import Progress

    folder = Path(args.folder)
    if not folder.is_dir():
        return _fail_input(InputError("folder", str(folder), "must be a folder of built parts (e.g. output/)"))
    if not built_parts(folder):
        return _fail_input(InputError("folder", str(folder), "holds no built part (no */manifest.json)"))
    path = _regenerate_gallery(folder, Progress(enabled=not args.quiet, check=check_signalled))
    if path is None:
        return _fail_input(InputError("folder", str(folder), f"its {INDEX} was not written by propulsor: "
                                      "not replaced"))
    return EXIT_OK


def cmd_build(args) -> int:
    """Build every part file given, one after the other in this process (the imports are paid once):
    each into its own output folder; the exit code is the worst of them (2 before 1 before 0)."""
    files = [Path(f) for f in args.part_files]
    if len(files) > 1 and (args.out or args.depfile):
        name = "--out" if args.out else "--depfile"
        return _fail_input(InputError(name, args.out or args.depfile, f"names one file or folder: give one part "
                                      f"file, not {len(files)} (several go to output/<file name>; --depfile-dir)"))
    if len(files) == 1:
        return _build_one(args, files[0], args.depfile or (Path(args.depfile_dir) / f"{files[0].stem}.mk"
                                                           if args.depfile_dir else None))
    _preload()
    from .parallel import can_fork, jobs_budget

    def depfile(part_file):
        return Path(args.depfile_dir) / f"{part_file.stem}.mk" if args.depfile_dir else None

    slots = jobs_budget()
    if slots > 1 and can_fork() and not args.dry_run:
        codes = _side_by_side(args, files, depfile, slots)
    else:
        codes = [_in_child(_build_one, args, f, depfile(f)) for f in files]
    return max(codes, key=lambda c: (c == EXIT_BAD_INPUT, c))


def _longest_first(files: list[Path]) -> list[int]:
    """Indices of the part files, the longest build first by its size estimate (a file that does not load
    first of all: it fails at once), so that the builds running side by side end close together."""
    def key(k):
        try:
            return -_load_part(files[k])[2].seconds, k
        except Exception:  # noqa: BLE001 - its own build reports it
            return -float("inf"), k

    return sorted(range(len(files)), key=key)


def _side_by_side(args, files: list[Path], depfile, slots: int) -> list[int]:
    """Build the part files in forked children, as many at once as `slots` (the process budget, shared
    with the children's own workers once the last build has started: parallel.share_slots), the longest
    first.  Each child's output is
    held in a temporary file and written out whole when it ends, so that the lines of two builds do
    not interleave.  A signal stops every build."""
    import tempfile

    from .parallel import open_slots_to_workers, share_slots

    sem = share_slots(slots)
    pending = _longest_first(files)
    running: dict[int, tuple[int, object, object]] = {}
    codes: list[int] = [EXIT_OK] * len(files)
    quiet = args.quiet
    try:
        while pending or running:
            # a slot of the budget for the next build; with none running, a slot still held by a worker that
            # was killed would never come back: start anyway after a moment
            if pending and (sem.acquire(timeout=0.05) or (not running and not sem.acquire(timeout=2.0) and
                                                           _started_without_slot())):
                k = pending.pop(0)
                out, err = tempfile.TemporaryFile(), tempfile.TemporaryFile()
                if not quiet:
                    print(f"propulsor: building {files[k]}", file=sys.stderr, flush=True)
                pid = _fork(_build_one, (args, files[k], depfile(files[k])), out.fileno(), err.fileno())
                running[pid] = (k, out, err)
                if not pending:  # the last builds may use the slots the others leave
                    open_slots_to_workers()
                continue
            pid, status = os.waitpid(-1, os.WNOHANG if pending else 0)
            if pid == 0 or pid not in running:
                continue
            k, out, err = running.pop(pid)
            sem.release()
            codes[k] = os.waitstatus_to_exitcode(status)
            for f, stream in ((out, sys.stdout), (err, sys.stderr)):
                f.seek(0)
                stream.flush()
                os.write(stream.fileno(), f.read())
                f.close()
    except Interrupted as exc:
        for pid in running:
            try:
                os.kill(pid, exc.signum)
            except ProcessLookupError:
                pass
        for pid in running:
            try:
                os.waitpid(pid, 0)
            except ChildProcessError:
                pass
        raise
    finally:
        share_slots(None)
    return codes


def _started_without_slot() -> bool:
    print("propulsor: no free process slot (a killed worker kept one); building anyway", file=sys.stderr, flush=True)
    return True


#: what every build imports and what costs (OCCT, cadquery, matplotlib, scipy, trimesh, manifold3d):
#: imported once before the builds of several part files are forked
_PRELOAD = ("propulsor.parts", "propulsor.parts.writer", "propulsor.solids.build", "propulsor.solids.kernel",
            "propulsor.export.step", "propulsor.export.mesh", "propulsor.export.plots", "propulsor.export.dxf",
            "propulsor.checks.mesh", "propulsor.checks.brep", "propulsor.checks.motion", "scipy.optimize",
            "scipy.integrate", "scipy.interpolate")


def _preload() -> None:
    import importlib

    import numpy as np

    for name in _PRELOAD:
        importlib.import_module(name)
    # the compiled kernels (mesh checks, sweeps): loaded (or compiled, once per machine) before the builds fork
    from .checks.mesh import self_intersections

    self_intersections(np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]), np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]))
    from .checks.motion import Outline
    from .checks.motion.nearest import nearest_edge

    square = Outline([np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])], 0.5)
    nearest_edge(square.points + 1.5, square, square)


def _in_child(fn, *args) -> int:
    """fn(*args) -> exit code, in a forked child (where fork is missing: here).  Each build of several
    starts from the same process state — OCCT's process-wide counters (the STEP writer numbers assembly
    occurrences with one), caches, figures — so it writes the same bytes as a build on its own.  A
    signal to this process is passed on to the child, and waited for."""
    if not hasattr(os, "fork"):
        return fn(*args)
    pid = _fork(fn, args)
    try:
        _, status = os.waitpid(pid, 0)
    except Interrupted as exc:
        os.kill(pid, exc.signum)
        os.waitpid(pid, 0)
        raise
    return os.waitstatus_to_exitcode(status)


def _fork(fn, args, stdout_fd: int | None = None, stderr_fd: int | None = None) -> int:
    """Fork a child that runs fn(*args) -> exit code (its standard output and error sent to the given file
    descriptors, when given) and leaves; returns its pid."""
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

            _hold_signals()
            kill_workers()
            print(f"propulsor: interrupted by {signal.Signals(exc.signum).name}; nothing written", file=sys.stderr)
            code = 128 + exc.signum
        except BaseException:  # noqa: BLE001 - reported as the traceback Python would print
            import traceback

            traceback.print_exc()
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os._exit(code)
    return pid


def _build_one(args, part_file: Path, depfile: Path | None) -> int:
    from . import output_folder as of
    from .progress import Progress

    progress = Progress(enabled=not args.quiet, check=check_signalled)
    try:
        out = of.vet_target(Path(args.out) if args.out else Path("output") / part_file.stem,
                            force=args.force, keep=(part_file,))
        part_type, params, estimate = _load_part(part_file)
        keep = _files_read(params, part_file)
        out = of.vet_target(out, force=args.force, keep=keep)
    except InputError as exc:
        return _fail_input(exc)
    if args.dry_run:
        print(f"{part_type.name}: {part_file} is valid; would build into {out}; "
              f"size estimate {estimate.text()}")
        return EXIT_OK

    def produce(tmp: Path):
        from .parts.writer import OutputWriter

        writer = OutputWriter(tmp, part_type.name, params, progress=progress, source=part_file)
        try:
            part_type.build(params, writer)
            return writer.finish(), part_type.name
        finally:
            writer.close()

    return _into_output(args, out, keep, produce, progress, depfile)


def _scale_arg(text: str) -> float | None:
    """'auto' → None; '3', '1:3' → 3.0 (a reduction 1:S); InputError otherwise."""
    if text == "auto":
        return None
    try:
        S = float(text.split(":", 1)[1] if text.startswith("1:") else text)
    except ValueError:
        raise InputError("--scale", text, "must be auto, S or 1:S with S >= 1 (e.g. 1:2.5)") from None
    if not (S >= 1.0 and S <= 1000.0):
        raise InputError("--scale", text, "S must be within 1 ... 1000 (a reduction 1:S)")
    return S


def _settings(pairs) -> dict:
    """--set KEY=VALUE pairs as TOML values (numbers, booleans, strings)."""
    import tomllib

    out = {}
    for item in pairs or []:
        key, sep, value = item.partition("=")
        if not sep or not key.strip():
            raise InputError("--set", item, "must be KEY=VALUE, e.g. backlash_mm=0.35")
        try:
            out[key.strip()] = tomllib.loads(f"v = {value.strip()}")["v"]
        except tomllib.TOMLDecodeError:
            out[key.strip()] = value.strip()
    return out


def cmd_print(args) -> int:
    """A print kit of a part file: pieces at print scale with the FDM allowances, a rig, plates."""
    from . import output_folder as of
    from .parts import get_kit
    from .printing.printers import load_printer
    from .progress import Progress

    progress = Progress(enabled=not args.quiet, check=check_signalled)
    part_file = Path(args.part_file)
    try:
        out = of.vet_target(Path(args.out) if args.out else Path("output") / f"{part_file.stem}_kit",
                            force=args.force, keep=(part_file,))
        printer = load_printer(args.printer, _settings(args.set))
        S = _scale_arg(args.scale)
        part_type, params, _ = _load_part(part_file)
        make_kit = get_kit(part_type.name)
        keep = _files_read(params, part_file)
        out = of.vet_target(out, force=args.force, keep=keep)
    except InputError as exc:
        return _fail_input(exc)

    def produce(tmp: Path):
        from .parts.writer import OutputWriter
        from .printing.kit import write_kit

        progress(f"{part_type.name}: print kit for the {printer.name} printer")
        kit = make_kit(params, printer, S, source=part_file)
        writer = OutputWriter(tmp, part_type.name, params, progress=progress, source=part_file)
        writer.report_name = "print_report.md"
        writer.title = f"Print kit: {writer.title}"
        try:
            write_kit(kit, writer)
            return writer.finish(), f"{part_type.name} print kit"
        finally:
            writer.close()

    return _into_output(args, out, keep, produce, progress, args.depfile)


def cmd_check(args) -> int:
    from .checks.files import check_path

    path = Path(args.path)
    if not path.exists():
        return _fail_input(InputError("PATH", str(path), "does not exist"))
    results = check_path(path)
    if not results:
        return _fail_input(InputError("PATH", str(path), "holds no STEP, STL, 3MF, DXF or manifest.json to check"))
    n_bad = 0
    for file, checks in results.items():
        bad = [c for c in checks if not c.passed]
        n_bad += bool(bad)
        status = "FAIL" if bad else "ok"
        if bad or args.verbose:
            print(f"{status:4s} {file}")
            for c in (checks if args.verbose else bad):
                print(f"     {'PASS' if c.passed else 'FAIL'} {c.name}: {c.message}")
    print(f"{len(results)} file(s) checked, {n_bad} invalid")
    return EXIT_CHECK_FAILED if n_bad else EXIT_OK


def cmd_list(args) -> int:
    from .params import read_part_file
    from .parts import get_part_type, part_type_names

    print("part types:")
    for name in part_type_names():
        print(f"  {name:28s} {get_part_type(name).summary}")
    files = sorted(Path(args.parts_dir).glob("*.toml"))
    print(f"parameter files in {args.parts_dir}/:")
    for f in files:
        try:
            t, _ = read_part_file(f)
        except InputError as exc:
            t = f"(invalid: {exc})"
        print(f"  {f.name:28s} {t}")
    return EXIT_OK


def cmd_params(args) -> int:
    from .params import describe_params
    from .parts import get_part_type

    try:
        pt = get_part_type(args.part_type)
    except InputError as exc:
        return _fail_input(exc)
    rows = describe_params(pt.params_cls)
    print(f"{pt.name}: {pt.summary}")
    print(f"{'parameter':28s} {'unit':6s} {'default':>14s}  {'limits':24s} description")
    for r in rows:
        print(f"{r['name']:28s} {r['unit']:6s} {str(r['default']):>14s}  {r['limits']:24s} {r['doc']}")
    return EXIT_OK


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="propulsor", description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="command", required=True)

    b = sub.add_parser("build", help="build parts from their parameter files (several: one after the other, "
                       "each into output/<file name>)")
    b.add_argument("part_files", nargs="+", metavar="part_file")
    b.add_argument("--out", help="output folder (default output/<file name>); replaced only when empty or "
                   "written by propulsor")
    b.add_argument("--force", action="store_true", help="replace an --out folder that propulsor did not write "
                   "(never the current folder, its parents, the home folder or /)")
    b.add_argument("--no-wait", action="store_true", help="exit 2 instead of waiting when another build "
                   "holds the lock of --out")
    b.add_argument("--dry-run", action="store_true", help="validate the part file and estimate the size; "
                   "build and write nothing")
    b.add_argument("--keep-failed", action="store_true", help="keep the outputs of a part whose checks fail")
    b.add_argument("-q", "--quiet", action="store_true", help="no progress messages")
    b.add_argument("--depfile", help="after a successful build, write a make rule <out>/manifest.json: <the "
                   "part file and every file it names> to this file (make includes it)")
    b.add_argument("--depfile-dir", help="the same for each of several part files: <dir>/<file name>.mk")
    b.set_defaults(func=cmd_build)

    pr = sub.add_parser("print", help="a print kit: pieces at print scale with FDM allowances, a rig, plates")
    pr.add_argument("part_file")
    pr.add_argument("--out", help="kit folder (default output/<file name>_kit)")
    pr.add_argument("--printer", default="generic", help="printer profile: generic, prusa_mk4, bambu_x1")
    pr.add_argument("--scale", default="auto", help="auto (largest standard scale that fits), S or 1:S")
    pr.add_argument("--set", action="append", metavar="KEY=VALUE", help="override a printer setting "
                    "(e.g. backlash_mm=0.35; see printing/printers.py)")
    pr.add_argument("--force", action="store_true", help="replace an --out folder that propulsor did not write")
    pr.add_argument("--no-wait", action="store_true", help="exit 2 instead of waiting for the lock of --out")
    pr.add_argument("--keep-failed", action="store_true", help="keep the kit when a check fails")
    pr.add_argument("-q", "--quiet", action="store_true", help="no progress messages")
    pr.add_argument("--depfile", help="after a successful kit, write a make rule <out>/manifest.json: <files "
                    "read> to this file")
    pr.set_defaults(func=cmd_print)

    c = sub.add_parser("check", help="validate existing output files (a file or a folder)")
    c.add_argument("path")
    c.add_argument("-v", "--verbose", action="store_true")
    c.set_defaults(func=cmd_check)

    ls = sub.add_parser("list", help="part types and the parameter files in parts/")
    ls.add_argument("--parts-dir", default="parts")
    ls.set_defaults(func=cmd_list)

    g = sub.add_parser("gallery", help="output/index.html: one page for every part built in the folder")
    g.add_argument("folder", nargs="?", default="output")
    g.add_argument("-q", "--quiet", action="store_true", help="no progress messages")
    g.set_defaults(func=cmd_gallery)

    pa = sub.add_parser("params", help="every parameter of a part type with unit, default and limits")
    pa.add_argument("part_type")
    pa.set_defaults(func=cmd_params)
    return p


def main(argv=None) -> int:
    """Run one command; SIGINT and SIGTERM end it with 130 / 143 and one line."""
    in_main_thread = threading.current_thread() is threading.main_thread()
    saved = {}
    _SIGNALLED.clear()
    saved_hook = sys.unraisablehook
    sys.unraisablehook = _unraisable
    if in_main_thread:
        for sig in (signal.SIGINT, signal.SIGTERM):
            saved[sig] = signal.signal(sig, _raise_interrupted)
    try:
        parser = build_parser()
        try:
            args = parser.parse_args(argv)
        except SystemExit as exc:  # argparse uses 2 for usage errors, which matches bad input
            return int(exc.code or 0)
        return args.func(args)
    except BrokenPipeError:  # the reader of our output went away (`propulsor params ... | head`)
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 128 + int(signal.SIGPIPE)
    except BaseException as exc:
        # the signal's exception itself, or any exception it caused (an extension module whose
        # initialisation it interrupted raises ImportError "initialization failed")
        if not (_SIGNALLED or isinstance(exc, (Interrupted, KeyboardInterrupt))):
            raise
        signum = exc.signum if isinstance(exc, Interrupted) else (_SIGNALLED[0] if _SIGNALLED else int(signal.SIGINT))
        _hold_signals()
        from .parallel import kill_workers

        kill_workers()
        print(f"propulsor: interrupted by {signal.Signals(signum).name}; nothing written", file=sys.stderr)
        return 128 + signum
    finally:
        for sig, handler in saved.items():
            signal.signal(sig, handler)
        sys.unraisablehook = saved_hook


if __name__ == "__main__":
    sys.exit(main())
