"""Command line: `propulsor build | check | list | params`.

Exit codes: 0 built and every check passed; 1 built but a check failed (outputs
kept only with --keep-failed) or `check` found invalid files; 2 bad input
(one line on stderr, nothing written).
"""

from __future__ import annotations

import argparse
import shutil
import sys
from pathlib import Path

from .errors import InputError

EXIT_OK, EXIT_CHECK_FAILED, EXIT_BAD_INPUT = 0, 1, 2


def _fail_input(exc: Exception) -> int:
    print(f"propulsor: error: {exc}", file=sys.stderr)
    return EXIT_BAD_INPUT


def cmd_build(args) -> int:
    from .params import load_params, read_part_file
    from .parts import get_part_type
    from .progress import Progress

    progress = Progress(enabled=not args.quiet)
    try:
        part_type_name, mapping = read_part_file(args.part_file)
        part_type = get_part_type(part_type_name)
        params = load_params(part_type.params_cls, mapping)
    except InputError as exc:
        return _fail_input(exc)

    out = Path(args.out) if args.out else Path("output") / Path(args.part_file).stem
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.parent / f".{out.name}.tmp"
    if tmp.exists():
        shutil.rmtree(tmp)
    tmp.mkdir()
    from .parts.writer import OutputWriter

    writer = OutputWriter(tmp, part_type.name, params, progress=progress, source=Path(args.part_file))
    try:
        part_type.build(params, writer)
        failures = writer.finish()
    except InputError as exc:
        writer.close()
        shutil.rmtree(tmp, ignore_errors=True)
        return _fail_input(exc)
    except BaseException:
        writer.close()
        shutil.rmtree(tmp, ignore_errors=True)
        raise

    if failures and not args.keep_failed:
        shutil.rmtree(tmp, ignore_errors=True)
        for f in failures:
            print(f"propulsor: check failed: {f}", file=sys.stderr)
        print(f"propulsor: {part_type.name}: {len(failures)} check(s) failed; nothing written "
              f"(use --keep-failed to keep the outputs)", file=sys.stderr)
        return EXIT_CHECK_FAILED
    if out.exists():
        shutil.rmtree(out)
    tmp.rename(out)
    if failures:
        for f in failures:
            print(f"propulsor: check failed: {f}", file=sys.stderr)
        print(f"propulsor: {part_type.name}: built into {out} but {len(failures)} check(s) failed", file=sys.stderr)
        return EXIT_CHECK_FAILED
    progress(f"{part_type.name}: built into {out}, all checks passed")
    return EXIT_OK


def cmd_check(args) -> int:
    from .checks.files import check_path

    path = Path(args.path)
    if not path.exists():
        return _fail_input(InputError("PATH", str(path), "does not exist"))
    results = check_path(path)
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

    b = sub.add_parser("build", help="build a part from its parameter file")
    b.add_argument("part_file")
    b.add_argument("--out", help="output folder (default output/<file name>)")
    b.add_argument("--keep-failed", action="store_true", help="keep the outputs of a part whose checks fail")
    b.add_argument("-q", "--quiet", action="store_true", help="no progress messages")
    b.set_defaults(func=cmd_build)

    c = sub.add_parser("check", help="validate existing output files (a file or a folder)")
    c.add_argument("path")
    c.add_argument("-v", "--verbose", action="store_true")
    c.set_defaults(func=cmd_check)

    ls = sub.add_parser("list", help="part types and the parameter files in parts/")
    ls.add_argument("--parts-dir", default="parts")
    ls.set_defaults(func=cmd_list)

    pa = sub.add_parser("params", help="every parameter of a part type with unit, default and limits")
    pa.add_argument("part_type")
    pa.set_defaults(func=cmd_params)
    return p


def main(argv=None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse uses 2 for usage errors, which matches bad input
        return int(exc.code or 0)
    return args.func(args)


if __name__ == "__main__":
    sys.exit(main())
