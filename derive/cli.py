"""The command line: ``derive solve``, ``derive list``. A thin layer over the library.

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
    p_solve.add_argument("--debug", action="store_true", help=argparse.SUPPRESS)
    p_list = sub.add_parser("list", help="list the bundled problems")
    p_list.add_argument("--debug", action="store_true", help=argparse.SUPPRESS)
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
        from derive.pdf import build_pdf

        if not args.output:
            raise InputError("--format pdf writes a file: give one with -o FILE.pdf", where="usage")
        data: str | bytes = build_pdf(derive.render(solution, "tex", digits=args.digits, figures=not args.no_figure))
    else:
        fmt = "tex-fragment" if args.format == "tex" and args.fragment else args.format
        data = derive.render(solution, fmt, digits=args.digits, figures=not args.no_figure)
    if args.output:
        write_atomic(args.output, data, inputs=inputs)
    else:
        assert isinstance(data, str)
        sys.stdout.write(data)
    return 0


def _list(args: argparse.Namespace) -> int:
    from derive import problem, resources

    for name, path in resources.bundled().items():
        try:
            title = problem.load(path).title
        except DeriveError as exc:
            title = f"(broken: {exc})"
        print(f"{name:40s} {title}")
    return 0


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; returns the exit code."""
    argv = list(sys.argv[1:] if argv is None else argv)
    debug = "--debug" in argv
    try:
        args = _parser().parse_args(argv)
        return _solve(args) if args.command == "solve" else _list(args)
    except DeriveError as exc:
        if debug:
            traceback.print_exc()
        print(f"Error: {exc}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        print("Error: interrupted", file=sys.stderr)
        return 1
    except Exception as exc:
        if debug:
            traceback.print_exc()
        else:
            print(
                f"Error: internal error ({type(exc).__name__}: {exc}); run with --debug for the traceback",
                file=sys.stderr,
            )
        return 1


def run() -> None:
    """Console-script entry point."""
    sys.exit(main())


if __name__ == "__main__":
    run()
