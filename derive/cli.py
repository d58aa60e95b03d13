"""The command line: ``derive solve``, ``list``, ``check``, ``variants``, ``handout``, ``plot``. A thin layer over the library.

Exit codes: 0 done, 2 bad input or usage, 1 anything else.
"""

from __future__ import annotations

import argparse
import sys
import traceback
from pathlib import Path

from derive import __version__
from derive.errors import DeriveError, InputError

FORMATS = ("md", "tex", "pdf", "html", "json")


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # type: ignore[override]
        raise InputError(f"{message} (see 'derive --help')", where="usage")


def _parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="derive", description="Worked solutions of central-impact problems, in the layout of the course notes."
    )
    parser.add_argument("--version", action="version", version=f"derive {__version__}")
    parser.add_argument("--debug", action="store_true", help="show the traceback of an error")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    p_solve = sub.add_parser("solve", help="write the worked solution of a problem")
    p_solve.add_argument("problem", help="a problem file (.toml) or the name of a bundled problem")
    p_solve.add_argument("--format", "-f", choices=FORMATS, default="md", help="output format (default: md)")
    p_solve.add_argument("-o", "--output", help="write to this file (default: standard output; pdf needs -o)")
    p_solve.add_argument(
        "--digits", type=int, help="significant figures (default: the file's, else 3, or 4 when the leading digit is 1)"
    )
    p_solve.add_argument(
        "--fragment", action="store_true", help="with --format tex: a fragment to \\input, not a whole document"
    )
    p_solve.add_argument("--no-figure", action="store_true", help="leave the figures out")
    p_solve.add_argument("--verify", action="store_true", help="check every line; print failing lines, exit 1 if any")
    p_solve.add_argument("--plot", action="store_true", help="add the plot of the outcome against e to the answer")
    p_solve.add_argument("--debug", action="store_true", help=argparse.SUPPRESS)
    p_list = sub.add_parser("list", help="list the bundled problems")
    p_list.add_argument("--debug", action="store_true", help=argparse.SUPPRESS)
    p_check = sub.add_parser("check", help="check hand answers: which are right, and what went wrong")
    p_check.add_argument("problem", help="a problem file (.toml) or the name of a bundled problem")
    p_check.add_argument("--answer", "-a", action="append", metavar="NAME=VALUE", help="an answer (repeatable)")
    p_check.add_argument("--answers", metavar="FILE", help="answers (and equations) in a TOML file")
    p_check.add_argument("--equation", action="append", metavar="'N: LHS = RHS'", help="an equation (repeatable)")
    p_check.add_argument(
        "--derivation", metavar="FILE", help="a typed derivation (.md, .tex or plain lines), judged line by line"
    )
    p_check.add_argument("--tolerance", help="relative tolerance, e.g. 0.01 or 1%% (default: the figures written)")
    p_check.add_argument("--format", "-f", choices=("text", "md", "json"), default="text", help="default: text")
    p_check.add_argument("--debug", action="store_true", help=argparse.SUPPRESS)
    p_var = sub.add_parser("variants", help="homework variants of a problem with a [vary] table, and an answer key")
    p_var.add_argument("problem", help="a problem file (.toml) or the name of a bundled problem")
    p_var.add_argument("--count", "-n", type=int, default=40, help="how many variants (default: 40)")
    p_var.add_argument("--seed", type=int, default=1, help="the same seed and file give the same variants")
    p_var.add_argument("--format", "-f", choices=("md", "tex", "pdf", "json"), default="md")
    p_var.add_argument("-o", "--output", required=True, help="the folder to write into")
    p_var.add_argument("--digits", type=int, help="significant figures")
    p_var.add_argument("--moodle", metavar="FILE.xml", help="also write Moodle XML: one numerical question per variant")
    p_var.add_argument("--prairielearn", metavar="DIR", help="also write a PrairieLearn question folder")
    p_var.add_argument(
        "--result", metavar="NAME", help="the result the LMS questions ask for (default: the first asked)"
    )
    p_var.add_argument("--debug", action="store_true", help=argparse.SUPPRESS)
    p_hand = sub.add_parser("handout", help="gather problems into one document: problems, answers or solutions")
    p_hand.add_argument("problems", nargs="+", metavar="PROBLEM", help="problem files (.toml) or bundled names")
    p_hand.add_argument("-o", "--output", required=True, help="the file to write: FILE.pdf, FILE.tex or FILE.md")
    p_hand.add_argument("--title", help="the handout's title (default: after the mode)")
    p_hand.add_argument(
        "--theory", action=argparse.BooleanOptionalAction, default=True, help="a theory page first (default: yes)"
    )
    p_hand.add_argument("--mode", choices=("problems", "answers", "solutions"), default="solutions")
    p_hand.add_argument("--digits", type=int, help="significant figures (default: each problem's)")
    p_hand.add_argument("--plot", action="store_true", help="with --mode solutions: each impact's plot against e")
    p_hand.add_argument("--debug", action="store_true", help=argparse.SUPPRESS)
    p_plot = sub.add_parser("plot", help="plot the outcome against e (0 to 1): velocities along n, energy lost")
    p_plot.add_argument("problem", help="a problem file (.toml) or the name of a bundled problem")
    p_plot.add_argument(
        "-o", "--output", help="FILE.svg, FILE.pdf, FILE.png or FILE.tex (default: SVG to standard output)"
    )
    p_plot.add_argument("--stage", type=int, help="in a chain, the impact stage to plot (default: the first)")
    p_plot.add_argument("--debug", action="store_true", help=argparse.SUPPRESS)
    return parser


def _solve(args: argparse.Namespace) -> int:
    import derive
    from derive.fileio import write_atomic

    if args.digits is not None and not 1 <= args.digits <= 10:
        raise InputError(
            "expected a whole number of significant figures from 1 to 10",
            where="usage",
            field=f"--digits {args.digits}",
        )
    problem = derive.load(args.problem)
    solution = derive.solve(problem)
    inputs = (Path(problem.path),)
    if args.format == "pdf":
        from derive.writers.pdf import build_pdf

        if not args.output:
            raise InputError("--format pdf writes a file: give one with -o FILE.pdf", where="usage")
        tex = derive.render(solution, "tex", digits=args.digits, figures=not args.no_figure, plot=args.plot)
        data: str | bytes = build_pdf(tex)
    else:
        fmt = "tex-fragment" if args.format == "tex" and args.fragment else args.format
        data = derive.render(solution, fmt, digits=args.digits, figures=not args.no_figure, plot=args.plot)
    if args.output:
        write_atomic(args.output, data, inputs=inputs)
    else:
        assert isinstance(data, str)
        sys.stdout.write(data)
    if args.verify:  # the page written, when it is Markdown or LaTeX; else its Markdown
        page = data if args.format in ("md", "tex") and isinstance(data, str) else None
        fmt = "tex" if args.format in ("tex", "pdf") else "md"
        report = derive.verify(solution, fmt, digits=args.digits, text=page)
        print(report.format(), file=sys.stderr)
        return 0 if report.ok else 1
    return 0


def _plot(args: argparse.Namespace) -> int:
    import derive
    from derive.fileio import write_atomic
    from derive.writers import plot

    fmt = Path(args.output).suffix.lower().lstrip(".") if args.output else "svg"
    writers = {"svg": plot.to_svg, "tex": plot.to_tikz, "pdf": plot.to_pdf, "png": plot.to_png}
    if fmt not in writers:
        raise InputError("the extension sets the format: give -o FILE.svg, .pdf, .png or .tex", where="usage")
    problem = derive.load(args.problem)
    data = writers[fmt](plot.chart(plot.impact_of(problem, args.stage)))
    if args.output:
        write_atomic(args.output, data, inputs=(Path(problem.path),))
    else:
        sys.stdout.write(data if isinstance(data, str) else "")
    return 0


def _list(args: argparse.Namespace) -> int:
    from derive import problem, resources

    found = resources.bundled()
    width = max((len(n) for n in found), default=0) + 2
    for name, path in found.items():
        try:
            title = problem.title(path)
        except DeriveError as exc:
            title = f"(broken: {exc})"
        print(f"{name:{width}s}{title}")
    return 0


def _check(args: argparse.Namespace) -> int:
    from derive.checking.answers import run

    report, text = run(
        args.problem, args.answer, args.answers, args.equation, args.tolerance, args.format, args.derivation
    )
    sys.stdout.write(text)
    for item in report.items:  # an item that could not be read is in the report, and named here
        if item.status == "error":
            print(f"Error: {_one_line(item.message)}", file=sys.stderr)
    return report.exit_code


def _variants(args: argparse.Namespace) -> int:
    import derive
    from derive.homework.variants import write_variants

    if not 1 <= args.count <= 100_000:
        raise InputError("expected a count from 1 to 100000", where="usage", field=f"--count {args.count}")
    problem = derive.load(args.problem)
    exports = None
    if args.moodle or args.prairielearn:  # built first: a bad --result writes nothing
        from derive.homework.lms import build_exports

        exports = build_exports(
            problem,
            count=args.count,
            seed=args.seed,
            digits=args.digits,
            result=args.result,
            moodle=args.moodle,
            prairielearn=args.prairielearn,
        )
    elif args.result:
        raise InputError("--result is for --moodle or --prairielearn", where="usage")
    failures = write_variants(
        problem, args.output, count=args.count, seed=args.seed, fmt=args.format, digits=args.digits
    )
    if exports is not None:
        exports.write(inputs=(Path(problem.path),))
    for line in failures:
        print(f"Error: {line}", file=sys.stderr)
    return 1 if failures else 0


def _handout(args: argparse.Namespace) -> int:
    """Write the handout; a problem that fails is left out and reported at the end (exit 1)."""
    from derive.fileio import write_atomic
    from derive.homework.handout import DEFAULT_TITLES, NoProblemsError, build_handout
    from derive.homework.handout import FORMATS as HANDOUT_FORMATS

    fmt = Path(args.output).suffix.lower().lstrip(".")
    if fmt not in HANDOUT_FORMATS:
        raise InputError(
            "the extension sets the format: give -o FILE.pdf, FILE.tex or FILE.md", where="usage", field=args.output
        )
    title = args.title if args.title is not None else DEFAULT_TITLES[args.mode]
    try:
        data, failures = build_handout(
            args.problems, title=title, theory=args.theory, mode=args.mode, fmt=fmt, digits=args.digits, plot=args.plot
        )
    except NoProblemsError as exc:
        for failure in exc.failures:
            print(f"Error: {_one_line(failure.line())}", file=sys.stderr)
        raise
    write_atomic(args.output, data, inputs=tuple(Path(p) for p in args.problems if Path(p).is_file()))
    for failure in failures:
        print(f"Error: {_one_line(failure.line())}", file=sys.stderr)
    if failures:
        print(f"Error: {len(failures)} of {len(args.problems)} problems left out of {args.output}", file=sys.stderr)
    return 1 if failures else 0


def _one_line(text: str) -> str:
    """A message as one line of plain text: a key or value from a file may hold a newline or a
    terminal escape (ESC [31m); those are shown escaped, never sent to the terminal."""
    import unicodedata

    out = []
    for ch in text:
        if ch in "\r\n\t":
            out.append(" ")
        elif unicodedata.category(ch) in ("Cc", "Cf", "Zl", "Zp", "Cs"):
            out.append(f"\\x{ord(ch):02x}" if ord(ch) < 256 else f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return "".join(out)


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; returns the exit code."""
    argv = list(sys.argv[1:] if argv is None else argv)
    debug = "--debug" in argv
    try:
        args = _parser().parse_args(argv)
        commands = {
            "solve": _solve,
            "list": _list,
            "check": _check,
            "variants": _variants,
            "handout": _handout,
            "plot": _plot,
        }
        return commands[args.command](args)
    except DeriveError as exc:
        if debug:
            traceback.print_exc()
        print(f"Error: {_one_line(str(exc))}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        print("Error: interrupted", file=sys.stderr)
        return 1
    except BrokenPipeError:  # the reader (head, less) stopped early: nothing to report
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except Exception as exc:
        if debug:
            traceback.print_exc()
        else:
            print(
                f"Error: {_one_line(f'internal error ({type(exc).__name__}: {exc})')}; run with --debug for the traceback",
                file=sys.stderr,
            )
        return 1


def run() -> None:
    """Console-script entry point."""
    sys.exit(main())


if __name__ == "__main__":
    run()
