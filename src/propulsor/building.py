"""One part file (or its print kit) built into its output folder: the part file loaded and vetted, the
build run into a temporary folder under the folder's lock and put in place in one step, the gallery
beside it rewritten, the make depfile written."""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

from .errors import EnvironmentFailure, InputError
from .signals import EXIT_CHECK_FAILED, EXIT_OK, check_signalled, fail_environment, fail_input, hold_signals


def named_files(params, part_file: Path) -> tuple[tuple[str, str, Path], ...]:
    """(key, value as written, path) of the part file and of every file it names (string parameters
    ending in `_file`, relative to it)."""
    import dataclasses

    files = [("part file", str(part_file), part_file)]
    for f in dataclasses.fields(params):
        v = getattr(params, f.name)
        if f.name.endswith("_file") and isinstance(v, str) and v:
            p = Path(v)
            files.append((f.name, v, p if p.is_absolute() else part_file.resolve().parent / p))
    return tuple(files)


def files_read(params, part_file: Path) -> tuple[Path, ...]:
    """The part file and every file it names (:func:`named_files`)."""
    return tuple(p for _, _, p in named_files(params, part_file))


def _make_path(p: Path) -> str:
    """`p` relative to the current folder, as the depfile names it."""
    import os

    return os.path.relpath(Path(p).resolve())


def vet_depfile(depfile, out: Path, out_value: str, params, part_file: Path) -> None:
    """Before a build that writes a depfile: InputError (key and value) when make cannot name its
    target or a file it reads (make_names.refusal); such a file builds without --depfile."""
    if not depfile:
        return
    from .make_names import vet

    vet([(key, value, _make_path(p)) for key, value, p in named_files(params, part_file)] +
        [("--out", out_value, _make_path(out / "manifest.json"))])


#: part files loaded by the command that forks their builds (batch.side_by_side): a forked build takes its
#: own entry instead of loading the file again (the parameters, and the design their validation computed)
LOADED: dict[Path, tuple] = {}


def load_part(part_file: Path):
    """(part type, validated parameters, size estimate) of a part file; InputError otherwise."""
    if part_file in LOADED:
        return LOADED.pop(part_file)
    from .params import load_params, read_part_file
    from .parts import check_size, get_part_type, size_needs_design, vet

    part_type_name, mapping = read_part_file(part_file)
    part_type = get_part_type(part_type_name)
    params = load_params(part_type.params_cls, mapping, validate=False)
    # the size estimate first where it needs only the values (a design can itself be the long part)
    early = not size_needs_design(part_type)
    estimate = check_size(part_type, params, part_file) if early else None
    vet(part_type, params, part_file)  # the rules between fields, then the design's own feasibility (may take seconds)
    estimate = estimate or check_size(part_type, params, part_file)
    return part_type, params, estimate


def write_depfile(depfile: Path, target: Path, files) -> None:
    """A make rule ``target: files`` (paths relative to the current folder, escaped for make), written in
    one step: the files a build read besides its part file (``road_wheel_file`` …) become prerequisites
    of its manifest; each also gets an empty rule and is added to PROPULSOR_READ (make_names)."""
    import os

    from .make_names import depfile_text

    text = depfile_text(_make_path(target), [_make_path(f) for f in files])
    depfile.parent.mkdir(parents=True, exist_ok=True)
    tmp = depfile.with_name(depfile.name + f".tmp{os.getpid()}")
    tmp.write_text(text, encoding="utf-8", errors="surrogateescape")
    os.replace(tmp, depfile)


def into_output(args, out: Path, keep: tuple[Path, ...], produce, progress, depfile=None) -> int:
    """Run ``produce(tmp) -> (failures, what)`` into a fresh temporary folder beside `out` with the
    lock of `out` held, check that the folder holds exactly what the manifest lists, then put the result
    in place of `out` in one step (or drop it when a check failed and --keep-failed is not given).  The
    gallery beside it is rewritten after the lock is let go.  Exit codes as in signals.py."""
    from . import output_folder as of
    from .parallel import close_in_workers, kill_workers
    from .write_root import writing_into

    lock = of.OutputLock(out)
    tmp = None
    published = False
    try:
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
            before = of.snapshot(out)  # what the swap may remove: nothing saved there from now on
            tmp = of.make_temp(out)
            with writing_into(tmp) as ident:
                failures, what = produce(tmp)
                check_signalled()  # a swallowed interrupt: the output is not put in place
                for f in failures:
                    print(f"propulsor: check failed: {f}", file=sys.stderr)
                if failures and not args.keep_failed:
                    print(f"propulsor: {what}: {len(failures)} check(s) failed; nothing written "
                          f"(use --keep-failed to keep the outputs)", file=sys.stderr)
                    return EXIT_CHECK_FAILED
                of.verify_built(tmp, ident)
                of.replace(tmp, out, before)
                published = True
        except OSError as exc:  # a write refused (a file's write names no path: the folder it went to)
            if exc.filename is None:
                exc.filename = str(tmp if tmp is not None else out)
            raise EnvironmentFailure.from_oserror(exc, "cannot build:") from None
    except InputError as exc:
        return fail_input(exc)
    except EnvironmentFailure as exc:
        return fail_environment(exc)
    finally:
        hold_signals()
        kill_workers()
        if tmp is not None and os.path.lexists(tmp):
            shutil.rmtree(tmp, ignore_errors=True)
        close_in_workers(None)
        lock.release()
    if published and gallery_folder(out.parent):
        regenerate_gallery(out.parent, progress)
    if failures:
        print(f"propulsor: {what}: built into {out} but {len(failures)} check(s) failed", file=sys.stderr)
        return EXIT_CHECK_FAILED
    progress(f"{what}: built into {out}, all checks passed")
    if depfile:
        write_depfile(Path(depfile), out / "manifest.json", keep)
    return EXIT_OK


def gallery_folder(folder: Path) -> bool:
    """Whether a build into a sub-folder of `folder` rewrites ``folder/index.html``: the default
    output folder (./output), or a folder whose gallery propulsor already wrote (``propulsor gallery
    DIR``).  Elsewhere nothing is written beside the output."""
    from .export.gallery import INDEX, is_ours

    try:
        return folder.resolve() == Path("output").resolve() or is_ours(folder / INDEX)
    except OSError:
        return False


def write_gallery_locked(folder: Path) -> Path | None:
    """``folder/index.html`` written under the gallery's own lock (export.gallery.write_gallery): its
    path, or None when an index.html there is not one propulsor wrote.  Errors pass."""
    from . import output_folder as of
    from .export.gallery import INDEX, write_gallery

    lock = of.OutputLock(folder / INDEX)
    try:
        lock.acquire(wait=True)
        return write_gallery(folder)
    finally:
        lock.release()


def regenerate_gallery(folder: Path, progress) -> Path | None:
    """Rewrite ``folder/index.html`` (the gallery of every part built there) after a build put its
    output in place.  Under the gallery's own lock, so that of two builds finishing together the later
    one writes a page that shows both; never over an index.html propulsor did not write."""
    from .export.gallery import INDEX

    try:
        path = write_gallery_locked(folder)
    except Exception as exc:  # noqa: BLE001 - the build's output is in place; the page is not worth failing it
        print(f"propulsor: the gallery {folder / INDEX} was not written: {type(exc).__name__}: {exc}", file=sys.stderr)
        return None
    if path is None:
        progress(f"{folder / INDEX} was not written by propulsor: left as it is")
    else:
        progress(f"gallery: {path}")
    return path


def build_one(args, part_file: Path, depfile: Path | None) -> int:
    """Build one part file into its output folder (``--out`` or output/<file name>): vetted, built into a
    temporary folder, put in place (:func:`into_output`); ``--dry-run`` validates and estimates only.
    Returns the exit code (signals.py)."""
    from . import output_folder as of
    from .progress import Progress

    progress = Progress(enabled=not args.quiet, check=check_signalled)
    try:
        out = of.vet_target(of.out_arg(args.out) or Path("output") / part_file.stem,
                            force=args.force, keep=(part_file,))
        part_type, params, estimate = load_part(part_file)
        keep = files_read(params, part_file)
        out = of.vet_target(out, force=args.force, keep=keep)
        vet_depfile(depfile, out, args.out or str(out), params, part_file)
    except InputError as exc:
        return fail_input(exc)
    if args.dry_run:
        print(f"{part_type.name}: {part_file} is valid; would build into {out}; "
              f"size estimate {estimate.text()}")
        return EXIT_OK

    return into_output(args, out, keep, lambda tmp: produce_build(part_type, params, part_file, tmp, progress)[:2],
                       progress, depfile)


def produce_build(part_type, params, part_file: Path | None, folder: Path, progress):
    """Build a part into `folder` (the files of ``propulsor build``): (unexpected check failures, what was
    built, the finished OutputWriter)."""
    from .parts.writer import OutputWriter

    writer = OutputWriter(folder, part_type.name, params, progress=progress, source=part_file)
    try:
        part_type.build(params, writer)
        return writer.finish(), part_type.name, writer
    finally:
        writer.close()
