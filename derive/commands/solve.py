"""``derive solve`` and ``derive plot``: one problem's worked solution or plot."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from derive.errors import InputError

if TYPE_CHECKING:
    from derive.steps.model import Solution

from derive.commands.parser import FORMATS


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


def run_solve(args: argparse.Namespace) -> int:
    """derive solve: the worked solution in a format, to a file or standard output; exit 1 where --verify finds a failing line."""
    import derive
    from derive.fileio import write_atomic
    from derive.steps import solve  # the solution itself: no notebook display hooks on a command line

    args.format = _format_of(args)

    if args.digits is not None and not 1 <= args.digits <= 10:  # as the schema's digits field
        raise InputError(
            "expected a whole number of significant figures from 1 to 10",
            where="usage",
            field=f"--digits {args.digits}",
        )
    options = _interop_options(args)
    problem = derive.load(args.problem)
    solution = solve(problem)
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


def run_plot(args: argparse.Namespace) -> int:
    """derive plot: the outcome against e as SVG, PDF, PNG or TikZ."""
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
