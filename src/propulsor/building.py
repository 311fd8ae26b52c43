"""The build service: one part (or its print kit) built into its output folder — the one core below both faces.

    part = load(Path("parts/road_wheel.toml"))                 # Loaded: part type, validated parameters, estimate
    result = build(part, Path("output/road_wheel"), progress=print)   # BuildResult, or an exception

It speaks values and exceptions: :func:`build` and :func:`build_kit` return a :class:`BuildResult` and raise
the typed errors of :mod:`.errors` — ``InputError`` (bad input, found before any work; ``FolderBusy`` when the
folder's lock is held and ``wait`` is False), ``CheckFailed`` (built, a check failed: nothing published unless
``keep_failed``), ``EnvironmentFailure`` (the file system refused).  It prints nothing and knows no exit code:
what happens on the way goes as :class:`~.progress.Event` s to the ``progress`` callback.  The command line
(``cli.py``) parses the arguments, calls it, renders the events and turns each exception into its exit code and
one line; the Python API (``api.py``) calls it directly.

Each build owns its worker processes (:class:`~.parallel.Workers`): builds in several threads of one process,
or in a long-running process (a notebook, a Dask worker), neither see nor stop each other's.  The CAD kernel and
the plotting library hold process-wide state, so the build steps themselves (:data:`TURN`) take turns between
threads; the locks, folders, workers and clean-up of each build are its own.
"""

from __future__ import annotations

import dataclasses
import os
import shutil
import threading
from pathlib import Path
from typing import Callable

from .errors import CheckFailed, EnvironmentFailure, FolderBusy, InputError
from .loading import Loaded, default_named, early_estimate, files_read, load, load_part, named_files  # noqa: F401
from .progress import Reporter
from .signals import Interrupted, check_signalled, held_signals, hold_signals

__all__ = ["Loaded", "BuildResult", "ProofResult", "KeptFiles", "load", "target", "build", "build_kit", "build_in_memory", "design",
           "prove", "solids", "solids_alone", "SolidsResult", "publish",
           "as_path", "files_read", "named_files", "vet_depfile", "write_depfile", "gallery_folder", "regenerate_gallery",
           "write_gallery_locked", "TURN"]

#: the build steps of one process take turns between threads: OCCT's STEP writer numbers assembly occurrences
#: with a process-wide counter, matplotlib's state is the process's, and a fork while another thread is inside
#: the kernel would copy its held locks.  Re-entrant (a write may run the design first).  Folders, locks,
#: workers and clean-up are each build's own and do not take it.
TURN = threading.RLock()


@dataclasses.dataclass(frozen=True)
class BuildResult:
    """What one build put in place: the folder, what was built, every check and derived value, the solids,
    outlines and assemblies it made (in memory), the files it read and the gallery page it rewrote."""

    out: Path
    what: str
    checks: tuple
    derived: dict
    solids: dict
    profiles: dict
    assemblies: dict
    failures: tuple[str, ...] = ()
    files_read: tuple[Path, ...] = ()
    gallery: Path | None = None
    #: path of every derived value -> (unit, meaning): the manifest's ``glossary``
    glossary: dict = dataclasses.field(default_factory=dict)
    #: the build's files kept for a later :func:`build` into a folder (:func:`build_in_memory` with `keep_files`)
    files: "KeptFiles | None" = dataclasses.field(default=None, repr=False, compare=False)


def _make_path(p: Path) -> str:
    """`p` relative to the current folder, as the depfile names it."""
    return os.path.relpath(Path(p).resolve())


def vet_depfile(depfile, out: Path, out_value: str, params, part_file: Path) -> None:
    """Before a build that writes a depfile: InputError (key and value) when make cannot name its
    target or a file it reads (make_names.refusal); such a file builds without --depfile."""
    if not depfile:
        return
    from .make_names import vet

    vet([(key, value, _make_path(p)) for key, value, p in named_files(params, part_file)] +
        [("--out", out_value, _make_path(out / "manifest.json"))])


def target(out, default: Path, force: bool = False, keep: tuple[Path, ...] = ()) -> Path:
    """The absolute output folder a build may use: `out` (text, bytes or a path; None: `default`), vetted
    (output_folder.vet_target: not a protected folder, nothing there propulsor did not write unless `force`,
    none of the files in `keep` inside).  InputError naming ``--out``."""
    from . import output_folder as of

    if out is None:
        chosen = default
    elif isinstance(out, str):
        chosen = of.out_arg(out)
    else:
        chosen = Path(os.fsdecode(out)) if isinstance(out, (bytes, bytearray)) else Path(out)
    return of.vet_target(chosen, force=force, keep=keep)


def write_depfile(depfile: Path, target: Path, files) -> None:
    """A make rule ``target: files`` (paths relative to the current folder, escaped for make), written in
    one step: the files a build read besides its part file (``road_wheel_file`` …) become prerequisites
    of its manifest; each also gets an empty rule and is added to PROPULSOR_READ (make_names)."""
    from .make_names import depfile_text

    text = depfile_text(_make_path(target), [_make_path(f) for f in files])
    depfile.parent.mkdir(parents=True, exist_ok=True)
    tmp = depfile.with_name(depfile.name + f".tmp{os.getpid()}")
    try:
        tmp.write_text(text, encoding="utf-8", errors="surrogateescape")
        os.replace(tmp, depfile)
    finally:
        if os.path.lexists(tmp):
            os.unlink(tmp)


#: where this process tells that its output is in place (:func:`tell_placed_to`: a build of several, forked by
#: the batch, tells its parent, which counts it when a signal stops the batch before it has seen the build end)
_PLACED_TO: list[int] = []


def tell_placed_to(fd: int) -> None:
    """From now on, each build's output put in place is told by one byte written to `fd` (a pipe's write end)."""
    _PLACED_TO[:] = [fd]


def tell_placed() -> None:
    """Tell it (:func:`tell_placed_to`): one byte into a pipe of this build's own, which holds it whole; nothing
    where no one asked."""
    for fd in _PLACED_TO:
        try:
            os.write(fd, b"1")
        except OSError:  # the parent has gone: no one to tell
            pass


def publish(out: Path, keep: tuple[Path, ...], produce: Callable, *, force: bool = False,
            keep_failed: bool = False, wait: bool = True, progress=None, gallery: bool = True) -> BuildResult:
    """:func:`_publish`; a signal that arrives once the output is in place (while the lock is let go, the gallery
    written, the last line said) leaves it there: the gallery written for it (no progress line), and the command
    line's one line told so (``Interrupted.kept``), not "nothing written"."""
    placed: list[bool] = []
    try:
        return _publish(out, keep, produce, placed, force=force, keep_failed=keep_failed, wait=wait,
                        progress=progress, gallery=gallery)
    except Interrupted as exc:
        if placed:
            hold_signals()
            page = regenerate_gallery(out.parent) if gallery and gallery_folder(out.parent) else None
            exc.kept = f"{out} is built" + (" (the gallery shows it)" if page is not None else "") + \
                "; nothing else written"
        raise


def _publish(out: Path, keep: tuple[Path, ...], produce: Callable, placed: list, *, force: bool = False,
             keep_failed: bool = False, wait: bool = True, progress=None, gallery: bool = True) -> BuildResult:
    """Run ``produce(tmp, say) -> (failures, what, writer)`` into a fresh temporary folder beside `out` with the
    lock of `out` held and this build's own workers, check that the folder holds exactly what the manifest
    lists, then put it in place of `out` in one step (or drop it when a check failed and not `keep_failed`).
    The gallery beside it is rewritten after the lock is let go (`gallery` False: not; a command that builds
    several part files into one folder writes it once, after the last).  Returns the :class:`BuildResult`; raises
    FolderBusy (held, `wait` False), InputError, EnvironmentFailure, CheckFailed (with ``.out`` set when the
    failed build was kept)."""
    from . import output_folder as of
    from .parallel import Workers
    from .write_root import writing_into

    say = Reporter.of(progress)
    lock = of.OutputLock(out)
    tmp = None
    failures: list[str] = []
    workers = Workers().open()  # this build's workers: killed when it ends
    try:
        try:
            of.prepare_parent(out)
            try:
                lock.acquire(wait=wait, on_wait=lambda pid: say.notice(f"{out} is being built by process "
                                                                       f"{pid}; waiting"))
            except of.Busy as busy:
                raise FolderBusy(str(out), busy.pid) from None
            workers.close_in_workers(lock.fd)
            of.vet_target(out, force=force, keep=keep)  # as it is now, after the wait
            for stale in of.clean_stale(out):
                say(f"removed {stale.name}, left by a build that was killed")
            before = of.snapshot(out)  # what the swap may remove: nothing saved there from now on
            tmp = of.make_temp(out)
            with writing_into(tmp) as ident:
                with TURN:
                    failures, what, w = produce(tmp, say)
                check_signalled()  # a swallowed interrupt: the output is not put in place
                for f in failures:
                    say.notice(f"check failed: {f}")
                if failures and not keep_failed:  # nothing published; what was made is in the error
                    raise CheckFailed(failures, what=what, result=_result(out, what, w, failures, keep))
                of.verify_built(tmp, ident)
                of.replace(tmp, out, before, notice=say.notice)
                placed.append(True)
                tell_placed()
        except OSError as exc:  # a write refused (a file's write names no path: the folder it went to)
            if exc.filename is None:
                exc.filename = str(tmp if tmp is not None else out)
            raise EnvironmentFailure.from_oserror(exc, "cannot build:") from None
    finally:
        with held_signals():  # a second Ctrl-C must not leave debris: workers, temporary folder, lock
            try:
                workers.close()
            finally:
                try:
                    if tmp is not None and os.path.lexists(tmp):
                        shutil.rmtree(tmp, ignore_errors=True)
                finally:
                    lock.release()
    page = regenerate_gallery(out.parent, say) if gallery and gallery_folder(out.parent) else None
    result = _result(out, what, w, failures, keep, page)
    if failures:
        raise CheckFailed(failures, what=what, out=out, result=result)
    say(f"{what}: built into {out}, all checks passed")
    return result


def _result(out: Path, what: str, w, failures, keep, page: Path | None = None) -> BuildResult:
    if isinstance(w, BuildResult):  # the files of a build made before, copied (build's `reuse`)
        return dataclasses.replace(w, out=out, what=what, failures=tuple(failures), files_read=tuple(keep),
                                   gallery=page)
    return BuildResult(out, what, tuple(w.checks), dict(w.derived), dict(getattr(w, "built_solids", {})),
                       dict(getattr(w, "built_profiles", {})), dict(getattr(w, "built_assemblies", {})),
                       tuple(failures), tuple(keep), page, glossary_of_writer(w))


def glossary_of_writer(w) -> dict:
    """{path: (unit, meaning)} of every derived value of writer `w` that has a meaning (the manifest's
    ``glossary``: the part type's glossary and what the build described); {} for a writer that keeps none."""
    explained = getattr(w, "explained", None)
    return {e.path: (e.unit, e.meaning) for e in explained()} if explained is not None else {}


def _digests(paths) -> dict:
    """{path: (size, sha256)} of each file (None for one that cannot be read as a regular file)."""
    from .regular_file import sha256_regular

    out: dict = {}
    for p in paths:
        try:
            out[Path(p)] = sha256_regular(p)
        except (OSError, ValueError):
            out[Path(p)] = None
    return out


def _remove_kept(folder: str, owner: int) -> None:
    """Remove a kept build's folder — in the process that made it only (a forked worker or a forked build
    that lets go of its copy of the object leaves it)."""
    if os.getpid() == owner:
        shutil.rmtree(folder, ignore_errors=True)


class KeptFiles:
    """The files a build made in memory wrote, kept in its private temporary folder for a later
    :func:`build` into an output folder (copied there under the folder's rules instead of building again).
    The folder is removed when this object is collected, by :meth:`drop`, or when the interpreter exits (by
    the process that made it only)."""

    def __init__(self, folder: Path, read: dict):
        import weakref

        self.folder = Path(folder)
        self.read = dict(read)  # {file the build read: (size, sha256)} taken before it started
        self._remove = weakref.finalize(self, _remove_kept, str(self.folder), os.getpid())

    def current(self) -> bool:
        """Whether the files may stand for a new build: still there, and every file the build read (the
        part file and the files it names) unchanged since."""
        return self._remove.alive and (self.folder / "manifest.json").is_file() and \
            _digests(self.read) == self.read

    def copy_into(self, folder: Path) -> None:
        """Every kept file into `folder` (existing, empty): sub-folders made as the build makes them, each
        file's bytes copied (new files, their times now: as written by a build)."""
        from .write_root import prepare

        for dirpath, _, filenames in os.walk(self.folder):
            rel = os.path.relpath(dirpath, self.folder)
            for name in sorted(filenames):
                shutil.copyfile(os.path.join(dirpath, name), prepare(Path(folder) / rel / name))

    def drop(self) -> None:
        """Remove the kept folder now."""
        self._remove()


def as_path(value, key: str) -> Path:
    """A path given as text, bytes (the file system's own encoding) or os.PathLike; InputError naming `key`
    for anything else or an empty one."""
    from .errors import InputError

    try:
        path = Path(os.fsdecode(bytes(value)) if isinstance(value, (bytes, bytearray)) else os.fspath(value))
    except (TypeError, ValueError):
        raise InputError(key, value, "must be a path (text, bytes or a pathlib.Path)") from None
    if not str(path) or str(path) == ".":
        raise InputError(key, value, "must name a file or folder")
    return path


def build(part: Loaded, out, *, force: bool = False, keep_failed: bool = False, wait: bool = True,
          progress=None, vetted: bool = False, reuse: BuildResult | None = None, gallery: bool = True) -> BuildResult:
    """Build `part` into folder `out` (text, bytes or a path): the files ``propulsor build`` writes, under the
    folder's rules (vetted, locked, built into a temporary folder, put in place in one step).  `progress`:
    a callback for the :class:`~.progress.Event` s on the way (None: none).  `vetted`: `out` is already the
    absolute folder :func:`target` made of it with this part's files (the command line vets before it loads
    the part file); it is vetted again once the lock is held either way.  `reuse`: a build of this same
    part made before by :func:`build_in_memory` with its files kept — its files are copied into the
    temporary folder instead of building again (the same bytes: they are that build's), when they are still
    there and no file the build read has changed since (else it builds).  `gallery`: rewrite the gallery beside
    `out` when it is one (:func:`gallery_folder`).  See :func:`publish` for what it raises."""
    keep = part.files_read
    if not vetted:
        out = target(out, Path("output") / (part.source.stem if part.source else part.part_type.name), force, keep)

    def produce(tmp: Path, say):
        if reuse is not None and reuse.files is not None and reuse.files.current():
            say(f"{reuse.what}: the files of the build made in memory")
            reuse.files.copy_into(tmp)
            return list(reuse.failures), reuse.what, reuse
        return produce_build(part.part_type, part.params, part.source, tmp, say)

    return publish(out, keep, produce, force=force, keep_failed=keep_failed, wait=wait, progress=progress,
                   gallery=gallery)


def build_kit(part: Loaded, out, printer, *, scale: float | None = None, sliced: bool = False,
              force: bool = False, keep_failed: bool = False, wait: bool = True, progress=None,
              printer_file: Path | None = None, vetted: bool = False) -> BuildResult:
    """The print kit of `part` on `printer` (a ``printing.printers.Printer``) into folder `out`: pieces at print
    scale 1:`scale` (None: the largest standard scale that fits) with the FDM allowances, the rig, the plates
    (sliced when `sliced`), ``print_report.md``.  `printer_file`: the user's profile file the kit also depends
    on.  As :func:`build` otherwise."""
    from .parts import get_kit

    make_kit = get_kit(part.part_type.name)
    keep = part.files_read + ((printer_file,) if printer_file is not None else ())
    if not vetted:
        stem = part.source.stem if part.source else part.part_type.name
        out = target(out, Path("output") / f"{stem}_kit", force, keep)
    name = part.part_type.name

    def produce(tmp: Path, say):
        from .parts.writer import OutputWriter
        from .printing.kit import write_kit

        import inspect

        say(f"{name}: print kit for the {printer.name} printer")
        told = {"progress": say} if "progress" in inspect.signature(make_kit).parameters else {}
        kit = make_kit(part.params, printer, scale, source=part.source, **told)
        writer = OutputWriter(tmp, name, part.params, progress=say, source=part.source)
        writer.report_name = "print_report.md"
        writer.title = f"Print kit: {writer.title}, for {printer.label}"  # two kits of one part tell apart
        try:
            write_kit(kit, writer, sliced)
            return writer.finish(), f"{name} print kit", writer
        finally:
            writer.close()

    return publish(out, keep, produce, force=force, keep_failed=keep_failed, wait=wait, progress=progress)


def build_in_memory(part: Loaded, progress=None, keep_files: bool = False) -> BuildResult:
    """One real build of `part` into a private temporary folder: its checks, values, solids, outlines
    and assemblies in memory.  The folder is removed after, or with `keep_files` kept as
    ``BuildResult.files`` (:class:`KeptFiles`, removed with it) for a later :func:`build`'s `reuse`.  Never
    raises CheckFailed: the failures are in the result."""
    import tempfile

    from .parallel import Workers
    from .write_root import writing_into

    say = Reporter.of(progress)
    read = _digests(part.files_read) if keep_files else {}
    folder = Path(tempfile.mkdtemp(prefix="propulsor-api-"))
    kept = False
    try:
        with Workers(), writing_into(folder), TURN:
            failures, what, w = produce_build(part.part_type, part.params, part.source, folder, say)
        result = _result(folder, what, w, failures, part.files_read)
        if keep_files:
            result, kept = dataclasses.replace(result, files=KeptFiles(folder, read)), True
    finally:
        if not kept:
            shutil.rmtree(folder, ignore_errors=True)
    return result


def design(part: Loaded, progress=None):
    """The part's design (frozen), computed once per parameter values (``pipeline.design_of``: the dry run's,
    the proofs' and the build's are the same object).  InputError for a part type without a separate design.
    `progress`: told its steps where the design function takes a ``progress`` (a non-circular pair's)."""
    import inspect

    from .errors import InputError
    from .parallel import Workers
    from .parts.pipeline import design_of

    fn = part.part_type.design
    if fn is None:
        raise InputError("design", part.part_type.name, "this part type has no separate design")
    said = {"progress": Reporter.of(progress)} if progress is not None and "progress" in inspect.signature(
        fn).parameters else {}
    with Workers(), TURN:
        if "source" in inspect.signature(fn).parameters:
            return design_of(part.params, fn, part.source, **said)
        return design_of(part.params, fn, **said)


@dataclasses.dataclass(frozen=True)
class ProofResult:
    """What the design and the full-cycle proofs of a part gave, without its solids or files (in memory)."""

    failures: tuple[str, ...]  # unexpected failed checks, "name: message"
    checks: tuple  # the Checks of the design and the proofs, in the build's order
    derived: dict  # their derived values (the same values the build's manifest gives them)
    whole_build: bool  # True where the part type declares no proof steps: this is its whole build's
    glossary: dict = dataclasses.field(default_factory=dict)  # path -> (unit, meaning), as the manifest's


def proves_alone(part: Loaded) -> bool:
    """Whether the part type declares proof steps (``Pipeline.proves_alone``): else its proof is its build."""
    from .parts.pipeline import Pipeline

    pipeline = part.part_type.build
    return isinstance(pipeline, Pipeline) and pipeline.proves_alone


def prove(part: Loaded, progress=None) -> ProofResult:
    """The design and the part type's proof steps only (the full-cycle proofs, their checks and derived values:
    no solid, no file); a part type that declares none runs its whole build in memory (:func:`build_in_memory`)."""
    if not proves_alone(part):
        b = build_in_memory(part, progress)
        return ProofResult(b.failures, b.checks, b.derived, True, b.glossary)
    from .parallel import Workers
    from .parts.proof_writer import ProofWriter

    with Workers(), TURN:
        w = ProofWriter(part.part_type.name, part.params, progress=Reporter.of(progress), source=part.source)
        try:
            part.part_type.build.prove(part.params, w)
            failures = w.finish()
        finally:
            w.close()
    return ProofResult(tuple(failures), tuple(w.checks), dict(w.derived), False, glossary_of_writer(w))


@dataclasses.dataclass(frozen=True)
class SolidsResult:
    """What the design and the solid steps of a part made, without their files or checks (in memory)."""

    solids: dict  # name -> cadquery Shape (the solids the build writes as <name>.step)
    profiles: dict  # DXF name -> list of Profile
    assemblies: dict  # name -> [(component, solid, (x, y, z) mm, rotation about z rad)]
    derived: dict  # each solid's <name>_volume_mm3


def solids_alone(part: Loaded) -> bool:
    """Whether the part type declares its solid steps (``Pipeline.solids_alone``): else its solids come
    from its whole build."""
    from .parts.pipeline import Pipeline

    pipeline = part.part_type.build
    return isinstance(pipeline, Pipeline) and pipeline.solids_alone


def solids(part: Loaded, progress=None) -> SolidsResult:
    """The design and the part type's solid steps only: the solids, assemblies and DXF outlines the build
    makes, without writing a file or running the files' checks; a part type that declares no solid steps
    runs its whole build in memory (:func:`build_in_memory`)."""
    if not solids_alone(part):
        b = build_in_memory(part, progress)
        return SolidsResult(b.solids, b.profiles, b.assemblies,
                            {k: v for k, v in b.derived.items() if k.endswith("_volume_mm3")})
    from .parallel import Workers
    from .parts.proof_writer import SolidWriter

    with Workers(), TURN:
        w = SolidWriter(part.part_type.name, part.params, progress=Reporter.of(progress), source=part.source)
        try:
            part.part_type.build.solids(part.params, w)
        finally:
            w.close()
    return SolidsResult(dict(w.built_solids), dict(w.built_profiles), dict(w.built_assemblies), dict(w.derived))


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
    from .export.gallery import write_gallery

    lock = of.OutputLock(folder / "index.html")
    try:
        lock.acquire(wait=True)
        return write_gallery(folder)
    finally:
        lock.release()


def regenerate_gallery(folder: Path, progress=None) -> Path | None:
    """Rewrite ``folder/index.html`` (the gallery of every part built there) after a build put its
    output in place.  Under the gallery's own lock, so that of two builds finishing together the later
    one writes a page that shows both; never over an index.html propulsor did not write.  A page that cannot
    be written is a notice, not the build's failure (its output is in place)."""
    from .export.gallery import INDEX

    say = Reporter.of(progress)
    try:
        path = write_gallery_locked(folder)
    except Exception as exc:  # noqa: BLE001 - the build's output is in place; the page is not worth failing it
        say.notice(f"the gallery {folder / INDEX} was not written: {type(exc).__name__}: {exc}")
        return None
    if path is None:
        say(f"{folder / INDEX} was not written by propulsor: left as it is")
    else:
        say(f"gallery: {path}")
    return path


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
