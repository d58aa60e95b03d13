"""The command line's arguments: the parser, each command's options, their time budgets."""

from __future__ import annotations

import argparse
import functools
import math

from derive import __version__
from derive.errors import InputError
from derive.writers.targets import FRAGMENT_PACKAGES, MARKDOWN_TARGETS

FORMATS = ("md", "tex", "pdf", "html", "json", "docx")
#: Seconds each command may run by default (``--timeout`` changes it).
TIME_BUDGETS = {"solve": 60.0, "check": 60.0, "list": 60.0, "variants": 600.0, "handout": 600.0, "plot": 60.0}
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
def build_parser() -> argparse.ArgumentParser:
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
    commands = (
        _add_solve(sub),
        sub.add_parser("list", help="list the bundled problems"),
        _add_check(sub),
        _add_variants(sub),
        _add_handout(sub),
        _add_plot(sub),
    )
    for command in commands:  # after each command's own options
        command.add_argument("--debug", action="store_true", help=argparse.SUPPRESS)
        _add_timeout(command)
    return parser


def _with_problem(sub: argparse._SubParsersAction, name: str, help_: str) -> argparse.ArgumentParser:
    """The parser of command ``name``, whose first argument is one problem."""
    command = sub.add_parser(name, help=help_)
    command.add_argument("problem", help="a problem file (.toml) or the name of a bundled problem")
    return command


def _add_solve(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """The options of ``derive solve``."""
    p_solve = _with_problem(sub, "solve", "write the worked solution of a problem")
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
    return p_solve


def _add_check(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """The options of ``derive check``."""
    p_check = _with_problem(sub, "check", "check hand answers: which are right, and what went wrong")
    p_check.add_argument("--answer", "-a", action="append", metavar="NAME=VALUE", help="an answer (repeatable)")
    p_check.add_argument("--answers", metavar="FILE", help="answers (and equations) in a TOML file")
    p_check.add_argument("--equation", action="append", metavar="'N: LHS = RHS'", help="an equation (repeatable)")
    p_check.add_argument(
        "--derivation", metavar="FILE", help="a typed derivation (.md, .tex or plain lines), judged line by line"
    )
    p_check.add_argument("--tolerance", help="relative tolerance, e.g. 0.01 or 1%% (default: the figures written)")
    p_check.add_argument("--format", "-f", choices=("text", "md", "json"), default="text", help="default: text")
    return p_check


def _add_variants(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """The options of ``derive variants``."""
    p_var = _with_problem(sub, "variants", "homework variants of a problem with a [vary] table, and an answer key")
    p_var.add_argument(
        "--count", "-n", type=int, default=None, help="how many variants (default: 40; 20 with --stack, at most 50)"
    )
    p_var.add_argument("--seed", type=int, default=1, help="the same seed and file give the same variants")
    p_var.add_argument(
        "--format",
        "-f",
        choices=("md", "tex", "pdf", "html", "json"),
        default="md",
        help="each variant's sheet and worked solution as md, tex, pdf or html; json: its numbers (default: md)",
    )
    p_var.add_argument("-o", "--output", required=True, help="the folder to write into")
    p_var.add_argument("--digits", type=int, help="significant figures")
    p_var.add_argument("--moodle", metavar="FILE.xml", help="also write Moodle XML: one numerical question per variant")
    p_var.add_argument("--prairielearn", metavar="DIR", help="also write a PrairieLearn question folder")
    p_var.add_argument(
        "--stack",
        metavar="FILE.xml",
        help="also write STACK questions (Moodle XML): one per asked result, all variants",
    )
    p_var.add_argument(
        "--result", metavar="NAME", help="the result the LMS questions ask for (default: the first asked)"
    )
    return p_var


def _add_handout(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """The options of ``derive handout``."""
    p_hand = sub.add_parser("handout", help="gather problems into one document: problems, answers or solutions")
    p_hand.add_argument("problems", nargs="+", metavar="PROBLEM", help="problem files (.toml) or bundled names")
    p_hand.add_argument(
        "-o", "--output", required=True, help="the file to write: FILE.pdf, FILE.tex, FILE.md or FILE.html"
    )
    p_hand.add_argument(
        "--format", "-f", choices=("md", "tex", "pdf", "html"), help="the format (default: the extension of -o)"
    )
    p_hand.add_argument("--title", help="the handout's title (default: after the mode)")
    p_hand.add_argument(
        "--theory", action=argparse.BooleanOptionalAction, default=True, help="a theory page first (default: yes)"
    )
    p_hand.add_argument("--mode", choices=("problems", "answers", "solutions"), default="solutions")
    p_hand.add_argument("--digits", type=int, help="significant figures (default: each problem's)")
    p_hand.add_argument("--plot", action="store_true", help="with --mode solutions: each impact's plot against e")
    return p_hand


def _add_plot(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """The options of ``derive plot``."""
    p_plot = _with_problem(sub, "plot", "plot the outcome against e (0 to 1): velocities along n, energy lost")
    p_plot.add_argument(
        "-o", "--output", help="FILE.svg, FILE.pdf, FILE.png or FILE.tex (default: SVG to standard output)"
    )
    p_plot.add_argument("--stage", type=int, help="in a chain, the impact stage to plot (default: the first)")
    return p_plot


def _add_timeout(p: argparse.ArgumentParser) -> None:
    """--timeout, after a command's own options."""
    p.add_argument(
        "--timeout",
        type=_seconds,
        metavar="SECONDS",
        default=argparse.SUPPRESS,
        help=f"stop after this long (default: {TIME_BUDGETS[p.prog.split()[-1]]:g} s; 0: no limit)",
    )


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
