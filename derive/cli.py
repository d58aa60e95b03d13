"""The command line: ``derive solve``, ``list``, ``check``, ``variants``, ``handout``, ``plot``. A thin layer over the library.

Exit codes: 0 done, 2 bad input or usage, 1 anything else (a run over its time budget too).

Every command has a time budget (:data:`TIME_BUDGETS`, ``--timeout SECONDS`` to change it,
0 for none): past it the command stops with a one-line error, and its outputs are as
they were. Whatever it prints goes through :func:`visible`: a control character from a
file (an ESC that would recolour the terminal or set its title) is shown as ``\\u001b``,
never sent raw; JSON stays valid, since that is how JSON writes it.
"""

from __future__ import annotations

import argparse
import contextlib
import functools
import math
import re
import signal
import sys
import threading
import time
import traceback
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any, TextIO

from derive import __version__
from derive.errors import DeriveError, InputError
from derive.writers.targets import FRAGMENT_PACKAGES, MARKDOWN_TARGETS

if TYPE_CHECKING:
    from derive.steps.model import Solution

FORMATS = ("md", "tex", "pdf", "html", "json", "docx")
#: Seconds each command may run by default (``--timeout`` changes it).
TIME_BUDGETS = {"solve": 60.0, "check": 60.0, "list": 60.0, "variants": 600.0, "handout": 600.0, "plot": 60.0}
#: Characters never written raw to a terminal: C0 and C1 controls but tab and newline,
#: DEL, and the invisible ones that reorder or break lines (bidi controls, U+2028/9).
_HIDDEN = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069]")
FRAGMENT_PREAMBLE = rf"\usepackage{{{','.join(FRAGMENT_PACKAGES)}}}"


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # type: ignore[override]
        raise InputError(f"{message} (see 'derive --help')", where="usage")


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of seconds, not {text!r}") from None
    if not math.isfinite(value) or value < 0:
        raise argparse.ArgumentTypeError(f"expected a number of seconds, 0 or more, not {text!r}")
    return value


@functools.cache
def _parser() -> argparse.ArgumentParser:
    """The argument parser (built once: it keeps no state between runs)."""
    parser = _Parser(
        prog="derive",
        description="Worked solutions of central-impact problems, in the layout of the course notes.",
        epilog="Time budgets (--timeout): "
        + ", ".join(f"{k} {v:g} s" for k, v in TIME_BUDGETS.items())
        + "; past it a command stops with an error (exit code 1).",
    )
    parser.add_argument("--version", action="version", version=f"derive {__version__}")
    parser.add_argument("--debug", action="store_true", help="show the traceback of an error")
    parser.add_argument(
        "--timeout", type=_seconds, metavar="SECONDS", help="stop after this long (default: the command's budget)"
    )
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    p_solve = sub.add_parser("solve", help="write the worked solution of a problem")
    p_solve.add_argument("problem", help="a problem file (.toml) or the name of a bundled problem")
    p_solve.add_argument(
        "--format",
        "-f",
        choices=FORMATS,
        default=None,
        help="output format (default: the extension of -o, else md; docx through pandoc)",
    )
    p_solve.add_argument("-o", "--output", help="write to this file (default: standard output; pdf and docx need -o)")
    p_solve.add_argument(
        "--digits", type=int, help="significant figures (default: the file's, else 3, or 4 when the leading digit is 1)"
    )
    p_solve.add_argument(
        "--fragment",
        action="store_true",
        help="with --format tex: a fragment to \\input, not a whole document; "
        f"its preamble needs {FRAGMENT_PREAMBLE} (see docs/interop.md)",
    )
    p_solve.add_argument("--no-figure", action="store_true", help="leave the figures out")
    _add_interop_options(p_solve)
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
    for p in (p_solve, p_list, p_check, p_var, p_hand, p_plot):
        p.add_argument(
            "--timeout",
            type=_seconds,
            metavar="SECONDS",
            default=argparse.SUPPRESS,
            help=f"stop after this long (default: {TIME_BUDGETS[p.prog.split()[-1]]:g} s; 0: no limit)",
        )
    return parser


def _add_interop_options(p_solve: argparse.ArgumentParser) -> None:
    """The options for putting the output into other tools (docs/interop.md)."""
    p_solve.add_argument(
        "--for",
        dest="target",
        choices=tuple(MARKDOWN_TARGETS),
        help="with --format md: where the Markdown goes (default: github; mkdocs is the same; "
        "jupyter loads \\cancel for MathJax 2; pandoc: for pandoc -t docx or latex)",
    )
    p_solve.add_argument(
        "--heading-level",
        type=int,
        choices=range(1, 7),
        default=1,
        metavar="N",
        help="the title at heading level N (1: # or \\section*), the stages below it (default: 1)",
    )
    p_solve.add_argument(
        "--no-title", action="store_true", help="leave the title out (your heading stands); stages at --heading-level"
    )


def _interop_options(args: argparse.Namespace) -> dict[str, Any]:
    """The render options of --for, --heading-level and --no-title, checked against --format."""
    if args.target is not None and args.format != "md":
        raise InputError("--for is for --format md (docx uses --for pandoc itself)", where="usage")
    if (args.heading_level != 1 or args.no_title) and args.format in ("html", "json"):
        raise InputError("--heading-level and --no-title are for md, tex, pdf and docx", where="usage")
    options: dict[str, Any] = {"heading_level": args.heading_level, "title": not args.no_title}
    if args.target is not None:
        options["target"] = args.target
    return options


def _docx(solution: Solution, args: argparse.Namespace, options: dict[str, Any]) -> bytes:
    from derive.writers.docx import build_docx

    if not args.output:
        raise InputError("--format docx writes a file: give one with -o FILE.docx", where="usage")
    return build_docx(
        solution,
        digits=args.digits,
        figures=not args.no_figure,
        heading_level=options["heading_level"],
        show_title=options["title"],
    )


def _format_of(args: argparse.Namespace) -> str:
    """The output format: --format, else the extension of -o when it names one (out.pdf:
    pdf, out.tex: tex), else md (out.txt, out.markdown, standard output)."""
    if args.format is not None:
        return args.format
    suffix = Path(args.output).suffix.lower().lstrip(".") if args.output else ""
    return suffix if suffix in FORMATS else "md"


def _solve(args: argparse.Namespace) -> int:
    import derive
    from derive.fileio import write_atomic

    args.format = _format_of(args)

    if args.digits is not None and not 1 <= args.digits <= 10:  # as the schema's digits field
        raise InputError(
            "expected a whole number of significant figures from 1 to 10",
            where="usage",
            field=f"--digits {args.digits}",
        )
    options = _interop_options(args)
    problem = derive.load(args.problem)
    solution = derive.solve(problem)
    inputs = (Path(problem.path),)
    if args.format == "pdf":
        from derive.writers.pdf import build_pdf

        if not args.output:
            raise InputError("--format pdf writes a file: give one with -o FILE.pdf", where="usage")
        data: str | bytes = build_pdf(
            derive.render(solution, "tex", digits=args.digits, figures=not args.no_figure, plot=args.plot, **options)
        )
    elif args.format == "docx":
        data = _docx(solution, args, options)
    else:
        fmt = "tex-fragment" if args.format == "tex" and args.fragment else args.format
        data = derive.render(solution, fmt, digits=args.digits, figures=not args.no_figure, plot=args.plot, **options)
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
    errors = [item for item in report.items if item.status == "error"]
    if errors:  # items that could not be read are in the report; the first is named here, in one line
        more = f" (and {len(errors) - 1} more, in the report)" if len(errors) > 1 else ""
        print(f"Error: {_one_line(errors[0].message)}{more}", file=sys.stderr)
    return report.exit_code


def _variants(args: argparse.Namespace) -> int:
    import derive
    from derive.homework.variants import MAX_COUNT, write_variants

    if not 1 <= args.count <= MAX_COUNT:
        raise InputError(f"expected a count from 1 to {MAX_COUNT}", where="usage", field=f"--count {args.count}")
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


def visible(text: str) -> str:
    """``text`` with every control character shown as an escape (``\\u001b``), not sent raw.

    In JSON the escape is the character itself, written the JSON way: the document is unchanged.
    """
    return _HIDDEN.sub(lambda m: f"\\u{ord(m.group()):04x}", text)


class _Visible:
    """A text stream that passes everything written to it through :func:`visible`."""

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream

    def write(self, text: str) -> int:
        self.stream.write(visible(text))
        return len(text)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.stream, name)


@contextlib.contextmanager
def _terminal_safe() -> Iterator[None]:
    """Standard output and error, for the time of a command, show control characters escaped."""
    out, err = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = _Visible(out), _Visible(err)  # type: ignore[assignment]
    try:
        yield
    finally:
        sys.stdout, sys.stderr = out, err


class OutOfTime(BaseException):
    """A command ran past its time budget. Not an Exception: no ``except Exception`` inside SymPy
    may swallow it."""


@contextlib.contextmanager
def time_budget(seconds: float) -> Iterator[None]:
    """Raise :class:`OutOfTime` in the main thread after ``seconds`` (0: no limit).

    An alarm already set (by a caller) is put back afterwards, less the time spent.
    """
    usable = seconds > 0 and hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()
    if not usable:
        yield
        return

    def alarm(signum: int, frame: object) -> None:
        raise OutOfTime(seconds)

    start = time.monotonic()
    old_handler = signal.signal(signal.SIGALRM, alarm)
    old_delay, _ = signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old_handler)
        if old_delay > 0:
            signal.setitimer(signal.ITIMER_REAL, max(0.001, old_delay - (time.monotonic() - start)))


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; returns the exit code."""
    with _terminal_safe():
        return _main(list(sys.argv[1:] if argv is None else argv))


def _main(argv: list[str]) -> int:
    debug = "--debug" in argv
    command = "derive"
    try:
        args = _parser().parse_args(argv)
        command = f"derive {args.command}"
        commands = {
            "solve": _solve,
            "list": _list,
            "check": _check,
            "variants": _variants,
            "handout": _handout,
            "plot": _plot,
        }
        budget = args.timeout if args.timeout is not None else TIME_BUDGETS[args.command]
        with time_budget(budget):
            return commands[args.command](args)
    except OutOfTime as exc:
        if debug:
            traceback.print_exc()
        print(
            f"Error: {command} stopped after {exc.args[0]:g} s, its time budget (--timeout SECONDS to change it, "
            "0 for no limit); its outputs were not changed",
            file=sys.stderr,
        )
        return 1
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
