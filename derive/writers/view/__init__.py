"""Renderers: the same Solution as Markdown, LaTeX (document or fragment), HTML or JSON.
May import: the rest of writers, steps, physics, problem and the leaves.

Layout lives in the Jinja2 templates (``templates/``); the mathematics is
printed by :mod:`derive.printing`; user text is escaped by :mod:`derive.escape`.
A renderer never does physics.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from derive.errors import InputError
from derive.numbers import format_number
from derive.problem.units import plain_unit
from derive.steps.model import Solution
from derive.writers.targets import FRAGMENT_PACKAGES, GITHUB, HTML, TEX_DOCUMENT, TEX_FRAGMENT, Layout, markdown_target
from derive.writers.view.chain import chain_as_problem, chain_convention, chain_view
from derive.writers.view.givens import letter_units, source_parts, worked_out
from derive.writers.view.json import chain_json, to_json
from derive.writers.view.lines import ANSWER_MARK, blocks_view, line_view
from derive.writers.view.problem import convention, figure_entry, figure_note, student_sheet, view

__all__ = [
    "ANSWER_MARK",
    "FORMATS",
    "blocks_view",
    "boxed_lines",
    "chain_as_problem",
    "chain_convention",
    "chain_view",
    "convention",
    "environment",
    "figure_entry",
    "figure_note",
    "letter_units",
    "line_view",
    "markdown",
    "plain_answers",
    "problem_view",
    "render",
    "source_parts",
    "student_page",
    "student_sheet",
    "to_json",
    "view",
    "worked_out",
]

FORMATS = ("md", "tex", "tex-fragment", "html", "json")


@dataclass(frozen=True)
class PageKind:
    """How one kind of solution is laid out: its page's data (``view(solution, digits, figures,
    layout, plot, standalone)``), its templates and its HTML and JSON writers."""

    view: Callable[..., dict[str, Any]]
    md: str
    tex: str
    fragment: str
    html: str
    json: Callable[[Solution, int | None], str]


IMPACT = PageKind(
    lambda s, digits, figures, layout, plot, standalone: view(s, digits, figures, layout=layout, plot=plot),
    "solution.md.j2",
    "solution.tex.j2",
    "fragment.tex.j2",
    "solution",
    to_json,
)
CHAIN = PageKind(
    lambda s, digits, figures, layout, plot, standalone: chain_view(s, digits, figures, standalone, layout),
    "chain.md.j2",
    "chain.tex.j2",
    "chain.tex.j2",
    "chain",
    chain_json,
)


def problem_view(
    solution: Solution, digits: int | None = None, figures: bool = True, *, layout: Layout = GITHUB, plot: bool = False
) -> dict[str, Any]:
    """``solution``'s page data in one problem's shape, a chain's as :func:`chain_as_problem`
    gives it (a handout's problem, a variant's sheet): ``plot`` for one impact only."""
    if page_kind(solution) is CHAIN:
        return chain_as_problem(solution, digits, figures=figures, layout=layout)
    return view(solution, digits, figures, layout=layout, plot=plot)


def page_kind(solution: Solution) -> PageKind:
    """The layout of ``solution``'s kind: one impact, or a chain of stages."""
    return CHAIN if solution.is_chain else IMPACT


def _md(solution: Solution, kind: PageKind, o: dict[str, Any]) -> str:
    page, _ = markdown(
        solution,
        markdown_target(o["target"]),
        digits=o["digits"],
        figures=o["figures"],
        heading_level=o["heading_level"],
        show_title=o["title"],
        plot=o["plot"],
    )
    return page


def _tex(solution: Solution, kind: PageKind, o: dict[str, Any], fragment: bool = False) -> str:
    layout = TEX_FRAGMENT if fragment else TEX_DOCUMENT
    data = kind.view(solution, o["digits"], o["figures"], layout, o["plot"], not fragment)
    tex_vars = {**_headings(o["heading_level"], o["title"]), "fragment_packages": ",".join(FRAGMENT_PACKAGES)}
    template = kind.fragment if fragment else kind.tex
    return environment("tex").get_template(template).render(**data, **tex_vars)


def _html(solution: Solution, kind: PageKind, o: dict[str, Any]) -> str:
    from derive.writers.view.html import html_pages

    (page,) = html_pages([(kind.html, kind.view(solution, o["digits"], o["figures"], HTML, o["plot"], True))])
    return page


#: The writer of each format, by name.
WRITERS: dict[str, Callable[[Solution, PageKind, dict[str, Any]], str]] = {
    "md": _md,
    "tex": _tex,
    "tex-fragment": lambda solution, kind, o: _tex(solution, kind, o, fragment=True),
    "html": _html,
    "json": lambda solution, kind, o: kind.json(solution, o["digits"]),
}


def render(
    solution: Solution,
    fmt: str = "md",
    *,
    digits: int | None = None,
    figures: bool = True,
    target: str = "github",
    heading_level: int = 1,
    title: bool = True,
    plot: bool = False,
) -> str:
    """``solution`` as text in ``fmt``: 'md', 'tex' (a document), 'tex-fragment', 'html' or 'json'.

    ``digits`` overrides the significant figures (default: the problem's, else
    the textbook rule); ``figures`` False leaves the figures out. ``target`` names
    where Markdown goes: 'github' (also KaTeX), 'jupyter', 'mkdocs' (long lines on rows) or
    'pandoc' (see :mod:`derive.writers.targets`). ``heading_level`` puts the title at
    that level (1: ``#``/``\\section*``) and the stages below it; ``title`` False
    leaves the title out (the caller's heading stands) and starts the stages at
    ``heading_level``. For a PDF see :func:`derive.writers.pdf.build_pdf`, for Word
    :func:`derive.writers.docx.build_docx`; ``plot`` adds the plot of the outcome against e after the answer.
    """
    if digits is not None and not (isinstance(digits, int) and 1 <= digits <= 10):
        raise InputError("expected a whole number of significant figures from 1 to 10", field="--digits")
    _headings(heading_level, title)
    kind = page_kind(solution)
    if kind is CHAIN and plot:
        raise InputError("a chain has several impacts: plot one with 'derive plot PROBLEM --stage N'", field="--plot")
    writer = WRITERS.get(fmt)
    if writer is None:
        raise InputError(f"unknown format {fmt!r} (expected one of: {', '.join((*FORMATS, 'pdf'))})", field="--format")
    options = {"digits": digits, "figures": figures, "target": target, "plot": plot}
    return writer(solution, kind, {**options, "heading_level": heading_level, "title": title})


def student_page(solution: Solution, fmt: str = "md", *, digits: int | None = None, title: str | None = None) -> str:
    """A student's sheet of ``solution`` in ``fmt`` ('md', or 'tex': a document): the title
    (``title`` in its place), Given and Find, the set-up before the impact (a chain's first)
    and the sign convention in words; no Source line, no working (a homework variant's sheet)."""
    from derive.writers import figure

    layout = TEX_DOCUMENT if fmt == "tex" else GITHUB
    sheet = student_sheet(problem_view(solution, digits, figures=False, layout=layout))
    impacts = [st.part for st in solution.stages if st.part is not None] or [solution]
    sheet.update(part="problems", setup_svg="", setup_tikz="")
    if impacts and any(st.figure == "before" for st in impacts[0].stages):
        drawn = figure.describe(solution, after=False)
        sheet.update(setup_svg=figure.to_svg(drawn), setup_tikz=figure.to_tikz(drawn))
    if title is not None:
        sheet["title"] = title
    if fmt == "tex":
        tex_vars = {**_headings(1, True), "fragment_packages": ",".join(FRAGMENT_PACKAGES)}
        return environment("tex").get_template("solution.tex.j2").render(**sheet, **tex_vars)
    return environment("md").get_template("solution.md.j2").render(**sheet).rstrip("\n") + "\n"


def environment(kind: str) -> Any:
    """The Jinja environment of ``kind`` ('md', also HTML; 'tex'): jinja2 is imported on first use."""
    from derive.writers.view.jinja import environment as jinja_environment

    return jinja_environment(kind)


def _headings(level: int, title: bool) -> dict[str, Any]:
    """The template variables for headings: the title's level, and whether it is shown."""
    if not (isinstance(level, int) and 1 <= level <= 6):
        raise InputError("expected a heading level from 1 to 6", field="--heading-level")
    return {"heading_level": level, "show_title": bool(title)}


def markdown(
    solution: Solution,
    layout: Layout = GITHUB,
    *,
    digits: int | None = None,
    figures: bool = True,
    heading_level: int = 1,
    show_title: bool = True,
    plot: bool = False,
) -> tuple[str, dict[str, str]]:
    """The Markdown for ``layout``, and the figure files it names (``figure-1.svg``: SVG
    text) when the layout writes figures as files for the caller to put beside it."""
    kind = page_kind(solution)
    data = kind.view(solution, digits, figures, layout, plot, True)
    files = _figure_images(data, layout)
    page = (
        environment("md")
        .get_template(kind.md)
        .render(
            **data,
            heading_level=heading_level,
            show_title=show_title,
            figure_images=layout.figures != "inline",
            tags_as_text=layout.tags == "text",
            require_cancel=layout.require_cancel,
            long_lines=layout.long_lines,
            escape_caret=layout.escape_caret,
        )
    )
    return page, files


def _figure_images(data: dict[str, Any], layout: Layout) -> dict[str, str]:
    """Give each figure of the page (a chain's included) the address of its image:
    a data URI, or a file name; the files to write, by name."""
    files: dict[str, str] = {}
    if layout.figures == "inline":
        return files
    stages = [sub for st in data["stages"] for sub in st.get("stages", [st])]
    for stage in stages:
        svg = stage.get("figure_svg")
        if not svg:
            continue
        if layout.figures == "files":
            name = f"figure-{len(files) + 1}.svg"
            files[name] = svg
            stage["figure_src"] = name
        else:
            import base64

            stage["figure_src"] = "data:image/svg+xml;base64," + base64.b64encode(svg.encode("utf-8")).decode("ascii")
    return files


def boxed_lines(solution: Solution) -> list[str]:
    """The LaTeX of the solution's boxed lines (its answers)."""
    if solution.is_chain:
        return [a["latex"] for a in chain_view(solution, figures=False)["answers"]]
    stages = view(solution, figures=False)["stages"]
    return [ln["latex"] for st in stages for b in st["blocks"] for ln in b["lines"] if ln["boxed"]]


def plain_answers(solution: Solution) -> list[str]:
    """The answers the problem asks for, as short plain text: ``v_A2 = 3.05 e_t - 1.11 e_n m/s``."""
    p = solution.problem
    verdicts = {a.name: a.verdict for a in solution.answers if a.verdict is not None}
    names = [a.name for a in solution.answers] if solution.is_chain else list(p.find)
    out = []
    for name in names:
        if name in verdicts:
            out.append(f"{name}: {verdicts[name]}")
            continue
        t, n = solution.results.get(name + "t"), solution.results.get(name + "n")
        r = solution.results.get(name)
        if not solution.is_chain and p.oblique and name in ("v_A2", "v_B2") and t and n:
            if t.value is not None and n.value is not None:
                sign = "-" if n.value < 0 else "+"
                shown_n = format_number(abs(n.value), p.digits)
                out.append(f"{name} = {format_number(t.value, p.digits)} e_t {sign} {shown_n} e_n {plain_unit(t.unit)}")
        elif r is not None and r.value is not None:
            unit = "°" if r.unit == "deg" else (" " + plain_unit(r.unit) if r.unit else "")
            out.append(f"{name} = {format_number(r.value, p.digits)}{unit}")
    return out
