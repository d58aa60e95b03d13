"""``derive variants`` and ``derive handout``."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from derive.commands.terminal import one_line
from derive.errors import InputError


def run_variants(args: argparse.Namespace) -> int:
    """derive variants: the variants, their answer key, and the Moodle and PrairieLearn exports asked for."""
    import derive
    from derive.homework.variants import MAX_COUNT, compile_problem, write_variants

    _resolve_count(args, MAX_COUNT)
    problem = derive.load(args.problem)
    exports = None
    compiled = None
    if args.moodle or args.prairielearn or args.stack:  # built first: a bad --result writes nothing
        from derive.homework.lms import build_exports

        compiled = compile_problem(problem)  # once, for the exports and the pages
        exports = build_exports(
            problem,
            count=args.count,
            seed=args.seed,
            digits=args.digits,
            result=args.result,
            moodle=args.moodle,
            prairielearn=args.prairielearn,
            stack=args.stack,
            compiled=compiled,
        )
    elif args.result:
        raise InputError("--result is for --moodle, --prairielearn or --stack", where="usage")
    if exports is not None:  # every path checked before anything is written
        exports.check(inputs=(Path(problem.path),), output=args.output)
    failures = write_variants(
        problem, args.output, count=args.count, seed=args.seed, fmt=args.format, digits=args.digits, compiled=compiled
    )
    if exports is not None:
        exports.write(inputs=(Path(problem.path),))
    for line in failures:
        print(f"Error: {line}", file=sys.stderr)
    print(_variants_summary(args, len(failures)), file=sys.stderr)
    return 1 if failures else 0


def _resolve_count(args: argparse.Namespace, most: int) -> None:
    """``--count``: 40 by default, 20 with ``--stack``; with ``--stack`` at most 50, since a STACK
    question holds every variant's worked solution and each attempt sends them all to Maxima."""
    from derive.homework.lms.stack import DEFAULT_COUNT, MAX_COUNT

    if args.count is None:
        args.count = DEFAULT_COUNT if args.stack else 40
    if not 1 <= args.count <= most:
        raise InputError(f"expected a count from 1 to {most}", where="usage", field=f"--count {args.count}")
    if args.stack and args.count > MAX_COUNT:
        raise InputError(
            f"a STACK question holds at most {MAX_COUNT} variants (every variant's worked solution goes to "
            "Maxima with each attempt): give --count 50 or less, or leave --stack out",
            where="usage",
            field=f"--count {args.count}",
        )


def _variants_summary(args: argparse.Namespace, failed: int) -> str:
    """What ``derive variants`` wrote, on one line: the folder, the key and the exports."""
    written = args.count - failed
    count = f"{written} of {args.count}" if failed else f"{written}"
    parts = [f"wrote {count} variant{'s' if args.count != 1 else ''} ({args.format}) to {args.output}"]
    parts.append("key.csv, key.json")
    if args.moodle:
        parts.append(str(args.moodle))
    if args.prairielearn:
        parts.append(f"{args.prairielearn} (PrairieLearn question)")
    if args.stack:
        parts.append(f"{args.stack} (STACK questions)")
    return ", ".join(parts)


def run_handout(args: argparse.Namespace) -> int:
    """Write the handout; a problem that fails is left out and reported at the end (exit 1)."""
    from derive.fileio import write_atomic
    from derive.homework.handout import DEFAULT_TITLES, NoProblemsError, build_handout
    from derive.homework.handout import FORMATS as HANDOUT_FORMATS

    suffix = Path(args.output).suffix.lower().lstrip(".")
    fmt = args.format or suffix
    if fmt not in HANDOUT_FORMATS:
        raise InputError(
            "the extension sets the format: give -o FILE.pdf, FILE.tex, FILE.md or FILE.html (or --format)",
            where="usage",
            field=args.output,
        )
    if args.format and suffix in HANDOUT_FORMATS and suffix != args.format:
        raise InputError(f"--format {args.format} but -o names a .{suffix} file", where="usage", field=args.output)
    title = args.title if args.title is not None else DEFAULT_TITLES[args.mode]
    try:
        data, failures = build_handout(
            args.problems, title=title, theory=args.theory, mode=args.mode, fmt=fmt, digits=args.digits, plot=args.plot
        )
    except NoProblemsError as exc:
        for failure in exc.failures:
            print(f"Error: {one_line(failure.line())}", file=sys.stderr)
        raise
    write_atomic(args.output, data, inputs=tuple(Path(p) for p in args.problems if Path(p).is_file()))
    for failure in failures:
        print(f"Error: {one_line(failure.line())}", file=sys.stderr)
    if failures:
        print(f"Error: {len(failures)} of {len(args.problems)} problems left out of {args.output}", file=sys.stderr)
    done = len(args.problems) - len(failures)
    print(f"wrote {args.output} ({fmt}, {args.mode}): {done} problem{'s' if done != 1 else ''}", file=sys.stderr)
    return 1 if failures else 0
