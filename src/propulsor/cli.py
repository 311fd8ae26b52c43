"""Command line: `propulsor build | print | gallery | check | list | params | explore`.

Exit codes: 0 built and every check passed; 1 built but a check failed (outputs
kept only with --keep-failed) or `check` found invalid files; 2 bad input
(one line on stderr after the progress lines, nothing written); 3 the environment refused (disk full, read-only file
system, permission: one line naming the path and the errno, nothing published); 130 / 143
interrupted by SIGINT / SIGTERM (one line, no temporary folder and no worker process left).
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
import threading
import time
from pathlib import Path

# one BLAS / OpenMP thread a process, as the study's workers run (study/engine.py): a build runs its steps side by
# side in processes of its own and its linear algebra is small (2 x 2 turns, banded spline systems), so OpenBLAS's
# own threads only spin between calls (7 % of a seed-002 design's CPU in perf).  Set before numpy is first imported
# (the package's root imports none); a value the user gave is kept.
for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

from . import building  # noqa: E402
from .building import gallery_folder, regenerate_gallery, vet_depfile, write_depfile, write_gallery_locked  # noqa: E402
from .errors import CheckFailed, EnvironmentFailure, InputError  # noqa: E402
from .render import Renderer  # noqa: E402
from .program_end import leave  # noqa: E402
from .signals import SIGNALLED, Interrupted, check_signalled, hold_signals, raise_interrupted, unraisable  # noqa: E402

#: the exit codes (README, «Command line»): the command line's alone; the build service raises exceptions
EXIT_OK, EXIT_CHECK_FAILED, EXIT_BAD_INPUT, EXIT_ENVIRONMENT = 0, 1, 2, 3


def fail_input(exc: Exception) -> int:
    print(f"propulsor: error: {exc}", file=sys.stderr)
    return EXIT_BAD_INPUT


def fail_environment(exc: Exception) -> int:
    print(f"propulsor: error: {exc}", file=sys.stderr)
    return EXIT_ENVIRONMENT


def fail(exc: Exception) -> int:
    """The exit code of an exception of the build service, and its one line on stderr."""
    if isinstance(exc, CheckFailed):
        n = len(exc.failures)
        if exc.out is not None:
            print(f"propulsor: {exc.what}: built into {exc.out} but {n} check(s) failed", file=sys.stderr)
        else:
            print(f"propulsor: {exc.what}: {n} check(s) failed; nothing written (use --keep-failed to keep the "
                  f"outputs)", file=sys.stderr)
        return EXIT_CHECK_FAILED
    if isinstance(exc, EnvironmentFailure):
        return fail_environment(exc)
    return fail_input(exc)


def cmd_gallery(args) -> int:
    """output/index.html: one page for every part built in the folder."""
    from .export.gallery import INDEX, built_parts
    from .export.gallery_studies import found_studies

    folder = Path(args.folder)
    if not folder.is_dir():
        return fail_input(InputError("folder", str(folder), "must be a folder of built parts (e.g. output/)"))
    if not built_parts(folder) and not found_studies(folder):
        return fail_input(InputError("folder", str(folder), "holds no built part (no */manifest.json) and no "
                                     "design study (no */study.json)"))
    progress = Renderer(args.quiet, live=False)
    try:
        path = write_gallery_locked(folder)
    except EnvironmentFailure as exc:
        return fail_environment(exc)
    except OSError as exc:
        return fail_environment(EnvironmentFailure.from_oserror(exc, "cannot write the gallery"))
    if path is None:
        return fail_input(InputError("folder", str(folder), f"its {INDEX} was not written by propulsor: "
                                      "not replaced"))
    progress(f"gallery: {path}")
    return EXIT_OK


def cmd_build(args) -> int:
    """Build every part file given, one after the other in this process (the imports are paid once):
    each into its own output folder, then the gallery beside them once (when it is one: building.gallery_folder);
    the exit code is the worst of them (2 before 3 before 1 before 0)."""
    files = [Path(f) for f in args.part_files]
    if args.out is not None and args.out_dir is not None:
        return fail_input(InputError("--out-dir", args.out_dir, "not with --out: give --out (the part's own folder) "
                                     "or --out-dir (<dir>/<file name>)"))
    if len(files) > 1 and (args.out is not None or args.depfile):
        name = "--out" if args.out is not None else "--depfile"
        return fail_input(InputError(name, args.out if args.out is not None else args.depfile, f"names one file or folder: give one part "
                                      f"file, not {len(files)} (several go to <--out-dir>/<file name>, output/ by default; --depfile-dir)"))
    from .parallel import Jobserver, can_fork, jobs_budget

    # make's jobserver (a `+` recipe under make -jN): the builds and their workers take make's tokens
    jobserver = None if os.environ.get("PROPULSOR_JOBS", "").strip() or args.dry_run else Jobserver.from_makeflags()
    budget = (os.cpu_count() or 1) if jobserver is not None else jobs_budget()
    if len(files) == 1:
        def one():
            return build_one(args, files[0], args.depfile or (Path(args.depfile_dir) / f"{files[0].stem}.mk"
                                                               if args.depfile_dir else None))
        if jobserver is None or budget < 2:
            return one()
        from .batch import with_jobserver

        return with_jobserver(one, budget, jobserver)
    from .batch import build_many

    def each(args, part_file, depfile):  # the gallery once, after the last (batch.build_many)
        return build_one(args, part_file, depfile, gallery=False)

    # the codes of a build whose output is in place (a part whose checks fail: only with --keep-failed)
    placed = (EXIT_OK, EXIT_CHECK_FAILED) if args.keep_failed else (EXIT_OK,)
    codes = build_many(args, files, budget, jobserver, each, placed)
    return max(codes, key=lambda c: (c == EXIT_BAD_INPUT, c))


def build_one(args, part_file: Path, depfile: Path | None, gallery: bool = True) -> int:
    """Build one part file into its output folder (``--out`` or output/<file name>) through the build service;
    ``--dry-run`` validates and estimates only.  `gallery`: rewrite the gallery beside the output when it is one
    (a command building several part files writes it once, after the last).  Returns the exit code."""
    with Renderer(args.quiet) as render:
        return _build_one(args, part_file, depfile, render, gallery)


def _build_one(args, part_file: Path, depfile: Path | None, render: Renderer, gallery: bool = True) -> int:
    from . import output_folder as of

    render(f"{part_file}: reading the part file")
    try:
        out = building.target(args.out, Path(args.out_dir or "output") / part_file.stem, args.force,
                              keep=(part_file,))
        part = building.load(part_file, progress=render)
        out = of.vet_target(out, force=args.force, keep=part.files_read)
        vet_depfile(depfile, out, args.out or str(out), part.params, part_file)
    except InputError as exc:
        return fail_input(exc)
    if args.dry_run:
        render.close()
        print(f"{part.part_type.name}: {part_file} is valid; would build into {out}; "
              f"size estimate {part.estimate.text()}")
        return EXIT_OK
    import gc

    # what this process has loaded lives through the build: out of the garbage collector's sight, its full collections
    # do not scan it again and again (a build of the Fourier pair: 7 full collections, 0.70 -> 0.45 CPU s); in sight
    # again after it (the interpreter's exit collects it: a wrapped kernel object left uncollected is reported leaked)
    gc.freeze()
    try:
        result = building.build(part, out, force=args.force, keep_failed=args.keep_failed, wait=not args.no_wait,
                                progress=render, vetted=True, gallery=gallery)
    except (InputError, EnvironmentFailure, CheckFailed) as exc:
        return fail(exc)
    finally:
        gc.unfreeze()
    if depfile:
        write_depfile(Path(depfile), result.out / "manifest.json", result.files_read)
    return EXIT_OK


def _scale_arg(text: str) -> float | None:
    """'auto' → None; '3', '1:3' → 3.0 (a reduction 1:S); InputError otherwise."""
    from .numbers import parse

    if text == "auto":
        return None
    try:
        S = float(parse(text.split(":", 1)[1] if text.startswith("1:") else text, "--scale"))
    except InputError:
        raise InputError("--scale", text, "must be auto, S or 1:S with S >= 1 in plain digits (e.g. 1:2.5)") from None
    if not (S >= 1.0 and S <= 1000.0):
        raise InputError("--scale", text, "S must be within 1 ... 1000 (a reduction 1:S)")
    return S


def _slice_arg(text: str) -> bool:
    """--slice auto|yes|no: whether the kit's plates are sliced (auto: when PrusaSlicer is installed)."""
    from .printing.slicer import slicer_path

    if text not in ("auto", "yes", "no"):
        raise InputError("--slice", text, "must be auto, yes or no")
    if text == "yes" and slicer_path() is None:
        raise InputError("--slice", text, "prusa-slicer is not installed (Debian/Ubuntu: apt-get install prusa-slicer); "
                         "--slice no estimates the filament instead")
    return text == "yes" or (text == "auto" and slicer_path() is not None)


def _settings(pairs) -> dict:
    """--set KEY=VALUE pairs as TOML values (numbers, booleans, strings)."""
    import tomllib

    out = {}
    for item in pairs or []:
        key, sep, value = item.partition("=")
        if not sep or not key.strip():
            raise InputError("--set", item, "must be KEY=VALUE, e.g. backlash_mm=0.35")
        if any(ord(c) < 32 or ord(c) == 127 for c in item):
            raise InputError("--set", item, "must be one KEY=VALUE on one line (no newline or control character)")
        from .numbers import parse

        if value.strip()[:1].isdigit() or value.strip()[:1] in ("+", "-", "."):  # a number: the one parser
            out[key.strip()] = parse(value, f"--set {key.strip()}")
            continue
        try:
            parsed = tomllib.loads(f"v = {value.strip()}")
        except RecursionError:
            raise InputError("--set", item[:40], "nests arrays or tables too deeply") from None
        except ValueError:  # not TOML: a word, taken as text
            parsed = {"v": value.strip()}
        from .numbers import nesting

        nesting(parsed["v"], f"--set {key.strip()}", 2)
        out[key.strip()] = parsed["v"]
    return out


def cmd_print(args) -> int:
    """A print kit of a part file: pieces at print scale with the FDM allowances, a rig, plates."""
    with Renderer(args.quiet) as render:
        return _print(args, render)


def _print(args, render: Renderer) -> int:
    part_file = Path(args.part_file)
    render(f"{part_file}: reading the part file and the printer profile")
    from . import output_folder as of
    from .parts import get_kit
    from .printing.printers import is_profile_path, load_printer

    try:
        out = building.target(args.out, Path("output") / f"{part_file.stem}_kit", args.force, keep=(part_file,))
        printer = load_printer(args.printer, _settings(args.set), bed=args.bed)
        sliced = _slice_arg(args.slice)
        S = _scale_arg(args.scale)
        part = building.load(part_file, progress=render)
        get_kit(part.part_type.name)  # a part type without a kit is refused here
        profile = Path(args.printer) if args.bed is None and is_profile_path(args.printer) else None
        keep = part.files_read + ((profile,) if profile is not None else ())  # the user's profile file too
        out = of.vet_target(out, force=args.force, keep=keep)
        vet_depfile(args.depfile, out, args.out or str(out), part.params, part_file)
    except InputError as exc:
        return fail_input(exc)
    try:
        result = building.build_kit(part, out, printer, scale=S, sliced=sliced, force=args.force,
                                    keep_failed=args.keep_failed, wait=not args.no_wait, progress=render,
                                    printer_file=profile, vetted=True)
    except (InputError, EnvironmentFailure, CheckFailed) as exc:
        return fail(exc)
    if args.depfile:
        write_depfile(Path(args.depfile), result.out / "manifest.json", result.files_read)
    return EXIT_OK


def cmd_check(args) -> int:
    from .checks.files import check_path, one_line
    from .checks.memory import memory_ceiling

    path = Path(args.path)
    if not os.path.lexists(path):
        return fail_input(InputError("PATH", str(path), "does not exist"))
    try:
        # the files' count as the other commands show theirs (a live line on a terminal, plain lines in a pipe or a
        # log); -q: a script reading check's stderr gets its refusals alone
        from .progress import Reporter

        with memory_ceiling(), Renderer(args.quiet) as render:
            results = check_path(path, progress=Reporter(render))
    except EnvironmentFailure as exc:
        return fail_environment(exc)
    if not results:
        return fail_input(InputError("PATH", str(path), "holds no STEP, STL, 3MF, DXF or manifest.json to check"))
    n_bad = 0
    for file, checks in results.items():
        bad = [c for c in checks if not c.passed]
        n_bad += bool(bad)
        status = "FAIL" if bad else "ok"
        if bad or args.verbose:
            print(f"{status:4s} {one_line(file)}")
            for c in (checks if args.verbose else bad):
                print(f"     {'PASS' if c.passed else 'FAIL'} {one_line(c.name)}: {one_line(c.message)}")
    print(f"{len(results)} file(s) checked, {n_bad} invalid")
    return EXIT_CHECK_FAILED if n_bad else EXIT_OK


def cmd_list(args) -> int:
    from .params import read_part_file
    from .parts import part_type_names, summary

    print("part types:")
    for name in part_type_names():
        print(f"  {name:28s} {summary(name)}")
    files = sorted(Path(args.parts_dir).glob("*.toml"))
    print(f"parameter files in {args.parts_dir}/:")
    for f in files:
        try:
            t, _ = read_part_file(f)
        except InputError as exc:
            t = f"(invalid: {exc})"
        print(f"  {f.name:28s} {t}")
    from .printing.printers import load_printer, printer_names

    print("printer profiles (propulsor print --printer NAME, or the path of your own .toml, or --bed WxDxH):")
    for name in printer_names():
        print(f"  {name:28s} {load_printer(name).label}")
    return EXIT_OK


def cmd_params(args) -> int:
    from .params import describe_params
    from .parts import params_class, summary

    if args.part_type == "printer":  # a printer profile's settings (--printer FILE, --set KEY=VALUE)
        from .printing.printers import Printer

        cls, what = Printer, ("a printer profile: the keys of your own profile file (propulsor print --printer "
                              "FILE.toml) and of --set KEY=VALUE")
    else:
        try:
            cls = params_class(args.part_type)
        except InputError as exc:
            return fail_input(exc)
        what = summary(args.part_type)
    rows = describe_params(cls)
    print(f"{args.part_type}: {what}")
    print(f"{'parameter':28s} {'unit':6s} {'default':>14s}  {'limits':24s} description")
    for r in rows:
        print(f"{r['name']:28s} {r['unit']:6s} {'(not given)' if r['default'] is None else str(r['default']):>14s}  {r['limits']:24s} {r['doc']}")
    return EXIT_OK


def cmd_explore(args) -> int:
    """A design study: every variant of the study file evaluated on a Dask cluster, one table, ranked.  This process
    runs as long as the study: its garbage collector at Python's own thresholds (:func:`.collector.untune`)."""
    from .collector import untune

    untune()
    with Renderer(args.quiet) as progress:
        return _explore(args, progress)


def _explore(args, progress: Renderer) -> int:
    progress(f"{args.study}: reading the study file")
    from .study import load_study
    from .study.engine import run

    try:
        cores = os.cpu_count() or 1
        if args.workers is not None and not 1 <= args.workers <= cores:
            raise InputError("--workers", args.workers, f"must be within 1 ... {cores} (this machine's cores: a "
                             "variant runs on one core)")
        if args.scheduler is not None:
            from .study.cluster import scheduler_address

            scheduler_address(args.scheduler)
        if args.workers is not None and args.scheduler is not None:
            raise InputError("--workers", args.workers, "sizes the local cluster; with --scheduler the cluster's own "
                             "workers run the study")
        if args.worker_wait is not None:
            from .study.cluster import worker_wait

            worker_wait(args.worker_wait)
        if args.build_best < 0:
            raise InputError("--build-best", args.build_best, "must be >= 0")
        study = load_study(args.study)
        out = Path(args.out) if args.out else Path("output") / Path(args.study).stem
        outcome = run(study, out, scheduler=args.scheduler, workers=args.workers, resume=args.resume,
                      progress=progress, build_best=args.build_best, wait=not args.no_wait,
                      worker_wait=args.worker_wait)
    except InputError as exc:
        return fail_input(exc)
    ok = sum(r["status"] == "ok" for r in outcome.rows)
    progress(f"{len(outcome.rows)} variants ({outcome.ran} run now, {outcome.seconds:.1f} s): {ok} meet every "
             f"requirement; {out / 'results.csv'} (and .parquet), {out / 'front.csv'}, {out / 'study.html'}")
    if gallery_folder(out.parent):  # the study in a gallery's folder (./output): the gallery links its page
        regenerate_gallery(out.parent, progress)
    return EXIT_OK


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="propulsor", description=__doc__.splitlines()[0])
    from .version import __version__

    p.add_argument("--version", action="version", version=f"propulsor {__version__}")
    sub = p.add_subparsers(dest="command", required=True)

    b = sub.add_parser("build", help="build parts from their parameter files (several: one after the other, "
                       "each into output/<file name>)")
    b.add_argument("part_files", nargs="+", metavar="part_file")
    b.add_argument("--out", help="output folder (default output/<file name>); replaced only when empty or "
                   "written by propulsor")
    b.add_argument("--out-dir", help="the folder each part goes into as <dir>/<file name> (default output); "
                   "make's OUT")
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
    pr.add_argument("--printer", default="generic", help="a built-in printer profile (propulsor list names them) "
                    "or the path of your own profile file (TOML: bed_x_mm, bed_y_mm, bed_z_mm, ...)")
    pr.add_argument("--bed", help="a quick profile: the bed WIDTHxDEPTHxHEIGHT in mm (e.g. 180x180x180; "
                    "WIDTHxDEPTH: the height is the smaller side), the generic printer's other settings")
    pr.add_argument("--scale", default="auto", help="auto (largest standard scale that fits), S or 1:S")
    pr.add_argument("--set", action="append", metavar="KEY=VALUE", help="override a printer setting "
                    "(e.g. backlash_mm=0.35; every setting: propulsor params printer)")
    pr.add_argument("--slice", default="auto", help="auto (when PrusaSlicer is installed), yes or no: slice every "
                    "plate with the printer's settings for the print time and filament (slow: tens of seconds a "
                    "plate); no: estimate the filament")
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
    c.add_argument("-q", "--quiet", action="store_true", help="no progress messages (the files checked are still "
                   "counted on stdout)")
    c.set_defaults(func=cmd_check)

    ls = sub.add_parser("list", help="part types and the parameter files in parts/")
    ls.add_argument("--parts-dir", default="parts")
    ls.set_defaults(func=cmd_list)

    g = sub.add_parser("gallery", help="output/index.html: one page for every part built in the folder")
    g.add_argument("folder", nargs="?", default="output")
    g.add_argument("-q", "--quiet", action="store_true", help="no progress messages")
    g.set_defaults(func=cmd_gallery)

    pa = sub.add_parser("params", help="every parameter of a part type (or of a printer profile: params printer) "
                        "with unit, default and limits")
    pa.add_argument("part_type", help="a part type (propulsor list names them) or printer")
    pa.set_defaults(func=cmd_params)

    ex = sub.add_parser("explore", help="a design study: the variants of a study file on a Dask cluster, "
                        "one table, the Pareto front")
    ex.add_argument("study", help="the study file (studies/*.toml)")
    ex.add_argument("--out", help="the study's folder (default output/<study file name>)")
    ex.add_argument("--scheduler", help="the address of a running Dask scheduler (tcp://host:8786); default: "
                    "a local cluster of worker processes")
    ex.add_argument("--workers", type=int, help="worker processes of the local cluster (default and most: the "
                    "cores)")
    ex.add_argument("--worker-wait", type=float, metavar="S", help="seconds to wait for a Dask worker when the "
                    "cluster has none, at the start or when every worker has left (default 60); then exit 3")
    ex.add_argument("--resume", action="store_true", help="keep the rows of results.csv and run only the rest")
    ex.add_argument("--build-best", type=int, default=0, metavar="K", help="then build the K best variants "
                    "fully into <out>/best/<rank>/")
    ex.add_argument("--no-wait", action="store_true", help="exit 2 instead of waiting when another study or "
                    "build holds the lock of --out")
    ex.add_argument("-q", "--quiet", action="store_true", help="no progress line")
    ex.set_defaults(func=cmd_explore)
    return p


#: the options that take a list (all others take one text)
_LISTS = {"part_files": str, "set": str}


def _valueless(args) -> str | None:
    """The option whose value argparse turned into a list (``--out=--``: it drops the "--"), or None."""
    for dest, value in vars(args).items():
        if dest in _LISTS:
            if isinstance(value, list) and not all(isinstance(v, str) for v in value):
                return f"--{dest.replace('_', '-')}"
        elif isinstance(value, list):
            return f"--{dest.replace('_', '-')}"
    return None


def main(argv=None) -> int:
    """Run one command; SIGINT and SIGTERM end it with 130 / 143 and one line."""
    in_main_thread = threading.current_thread() is threading.main_thread()
    saved = {}
    SIGNALLED.clear()
    saved_hook = sys.unraisablehook
    sys.unraisablehook = unraisable
    if in_main_thread:
        for sig in (signal.SIGINT, signal.SIGTERM):
            saved[sig] = signal.signal(sig, raise_interrupted)
    args = None
    try:
        parser = build_parser()
        try:
            args = parser.parse_args(argv)
        except SystemExit as exc:  # argparse uses 2 for usage errors, which matches bad input
            return int(exc.code or 0)
        bad = _valueless(args)
        if bad is not None:
            return fail_input(InputError(bad, "--", "needs a value ('--' ends the options; write ./-- for a file "
                                         "named --)"))
        try:
            os.getcwd()
        except OSError as exc:
            return fail_environment(EnvironmentFailure(".", exc.errno, "cannot work in the current folder",
                                                       "it was removed or cannot be read"))
        return args.func(args)
    except EnvironmentFailure as exc:
        return fail_environment(exc)
    except BrokenPipeError:  # the reader of our output went away (`propulsor params ... | head`)
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 128 + int(signal.SIGPIPE)
    except OSError as exc:  # the file system refused (disk full, read-only, permission, …): one line, exit 3
        if SIGNALLED:
            raise
        return fail_environment(EnvironmentFailure.from_oserror(exc, "cannot continue:"))
    except BaseException as exc:
        # the signal's exception itself, or any exception it caused (an extension module whose
        # initialisation it interrupted raises ImportError "initialization failed")
        if not (SIGNALLED or isinstance(exc, (Interrupted, KeyboardInterrupt))):
            raise
        signum = exc.signum if isinstance(exc, Interrupted) else (SIGNALLED[0] if SIGNALLED else int(signal.SIGINT))
        hold_signals()
        from .parallel import kill_workers

        kill_workers()
        kept = (_study_kept(args) if getattr(args, "command", None) == "explore"
                else getattr(exc, "kept", "nothing written"))
        print(f"propulsor: interrupted by {signal.Signals(signum).name}; {kept}", file=sys.stderr)
        return 128 + signum
    finally:
        for sig, handler in saved.items():
            signal.signal(sig, handler)
        if not SIGNALLED:  # after a signal the process is ending: the hook stays for the finalisers that run at exit
            sys.unraisablehook = saved_hook


def run() -> None:
    """The ``propulsor`` program: its garbage collector tuned (:func:`.collector.tune`, before any large import),
    :func:`main`, then the process leaves (:func:`leave`)."""
    from .collector import tune

    tune()
    leave(main())


def _study_kept(args) -> str:
    """What an interrupted study left: its finished variants' rows (results.csv), or nothing."""
    out = Path(args.out) if getattr(args, "out", None) else Path("output") / Path(getattr(args, "study", "")).stem
    table = out / "results.csv"
    try:
        with open(table, "rb") as f:
            rows = sum(1 for line in f if line.strip()) - 1
    except OSError:
        rows = 0
    if rows <= 0:
        return "no variant had finished: nothing written"
    return f"{rows} finished variant{'s' if rows != 1 else ''} in {table} (--resume runs the rest)"


if __name__ == "__main__":
    run()
