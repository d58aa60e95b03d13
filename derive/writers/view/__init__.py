"""Renderers: any Solution as Markdown, LaTeX (document or fragment), HTML or JSON, from one view.
May import: the rest of writers, steps, physics, problem and the leaves.

Each format's writer is chosen from one table (:data:`WRITERS`); every page comes from one view of
the solution (:func:`~derive.writers.view.page.view`: a single impact is a chain of one untitled stage).

Layout lives in the Jinja2 templates (``templates/``); the mathematics is
printed by :mod:`derive.printing`; user text is escaped by :mod:`derive.escape`.
A renderer never does physics.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple

from derive.errors import InputError
from derive.numbers import format_number
from derive.problem.units import plain_unit
from derive.steps.model import Solution
from derive.writers.targets import FRAGMENT_PACKAGES, GITHUB, HTML, TEX_DOCUMENT, TEX_FRAGMENT, Layout, markdown_target
from derive.writers.view.givens import source_parts
from derive.writers.view.json import to_json
from derive.writers.view.page import problem_view, view
from derive.writers.view.problem import student_sheet

__all__ = [
    "FORMATS",
    "WRITERS",
    "boxed_lines",
    "check_digits",
    "environment",
    "markdown",
    "plain_answers",
    "problem_view",
    "render",
    "source_parts",
    "student_page",
    "student_sheet",
    "view",
]

FORMATS = ("md", "tex", "tex-fragment", "html", "json")


class Writer(NamedTuple):
    """How one format is written: where its page goes (``layout``; None: the Markdown target
    the options name), whether a LaTeX page is a whole document, whether it draws figures,
    and its text from the solution, its view and the options."""

    layout: Layout | None
    write: Callable[[Solution, dict[str, Any], dict[str, Any]], str]
    standalone: bool = True
    figures: bool = True


def _md(solution: Solution, data: dict[str, Any], o: dict[str, Any]) -> str:
    return _markdown(data, markdown_target(o["target"]), o["heading_level"], o["title"])[0]


def _tex(solution: Solution, data: dict[str, Any], o: dict[str, Any]) -> str:
    template = "solution.tex.j2" if data["standalone"] else "fragment.tex.j2"
    return environment("tex").get_template(template).render(**data, **_tex_vars(o["heading_level"], o["title"]))


def _html(solution: Solution, data: dict[str, Any], o: dict[str, Any]) -> str:
    from derive.writers.view.html import html_pages

    (page,) = html_pages([("solution", data)])
    return page


#: The writer of each format, by name.
WRITERS: dict[str, Writer] = {
    "md": Writer(None, _md),
    "tex": Writer(TEX_DOCUMENT, _tex),
    "tex-fragment": Writer(TEX_FRAGMENT, _tex, standalone=False),
    "html": Writer(HTML, _html),
    "json": Writer(GITHUB, lambda solution, data, o: to_json(solution, o["digits"], data), figures=False),
}


def check_digits(digits: object) -> None:
    """Refuses (as ``--digits``) significant figures that are not a whole number from 1 to 10."""
    if digits is not None and not (isinstance(digits, int) and 1 <= digits <= 10):
        raise InputError("expected a whole number of significant figures from 1 to 10", field="--digits")


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
    check_digits(digits)
    _headings(heading_level, title)
    writer = WRITERS.get(fmt)
    if writer is None:
        raise InputError(f"unknown format {fmt!r} (expected one of: {', '.join((*FORMATS, 'pdf'))})", field="--format")
    layout = writer.layout or markdown_target(target)
    data = view(solution, digits, figures and writer.figures, layout=layout, plot=plot, standalone=writer.standalone)
    if plot and not data["plot_svg"]:
        raise InputError("a chain has several impacts: plot one with 'derive plot PROBLEM --stage N'", field="--plot")
    options = {"digits": digits, "target": target, "heading_level": heading_level, "title": title}
    return writer.write(solution, data, options)


def student_page(solution: Solution, fmt: str = "md", *, digits: int | None = None) -> str:
    """A student's sheet of ``solution`` in ``fmt`` ('md', or 'tex': a document): the title,
    Given and Find, the set-up before the impact (a chain's first)
    and the sign convention in words; no Source line, no working (a homework variant's sheet)."""
    from derive.writers import figure

    layout = TEX_DOCUMENT if fmt == "tex" else GITHUB
    sheet = student_sheet(problem_view(solution, digits, figures=False, layout=layout))
    impacts = [st.part for st in solution.stages if st.part is not None] or [solution]
    sheet.update(part="problems", setup_svg="", setup_tikz="")
    if impacts and any(st.figure == "before" for st in impacts[0].stages):
        drawn = figure.describe(solution, after=False)
        sheet.update(setup_svg=figure.to_svg(drawn), setup_tikz=figure.to_tikz(drawn))
    if fmt == "tex":
        return environment("tex").get_template("solution.tex.j2").render(**sheet, **_tex_vars(1, True))
    return environment("md").get_template("solution.md.j2").render(**sheet).rstrip("\n") + "\n"


def environment(kind: str) -> Any:
    """The Jinja environment of ``kind`` ('md', also HTML; 'tex'): jinja2 is imported on first use."""
    from derive.writers.view.jinja import environment as jinja_environment

    return jinja_environment(kind)


def _tex_vars(level: int, title: bool) -> dict[str, Any]:
    """The LaTeX templates' variables: the headings', and the packages a fragment needs."""
    return {**_headings(level, title), "fragment_packages": ",".join(FRAGMENT_PACKAGES)}


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
    data = view(solution, digits, figures, layout=layout, plot=plot)
    return _markdown(data, layout, heading_level, show_title)


def _markdown(data: dict[str, Any], layout: Layout, heading_level: int, show_title: bool) -> tuple[str, dict[str, str]]:
    """A page's view as Markdown for ``layout``, and the figure files it names."""
    files = _figure_images(data, layout)
    page = (
        environment("md")
        .get_template("solution.md.j2")
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
    """Give each figure of the page (each impact's) the address of its image:
    a data URI, or a file name; the files to write, by name."""
    files: dict[str, str] = {}
    if layout.figures == "inline":
        return files
    for stage in (sub for st in data["stages"] for sub in st["stages"]):
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
    """The LaTeX of the solution's boxed answer lines (a chain's answers, an impact's answer stage)."""
    return [line["latex"] for line in problem_view(solution, figures=False)["answers"]]


def plain_answers(solution: Solution) -> list[str]:
    """The answers the problem asks for, as short plain text: ``v_A2 = 3.05 e_t - 1.11 e_n m/s``."""
    p = solution.problem
    verdicts = {a.name: a.verdict for a in solution.answers if a.verdict is not None}
    names = [a.name for a in solution.answers] or list(p.find)  # a chain's answers, or what one impact finds
    out = []
    for name in names:
        if name in verdicts:
            out.append(f"{name}: {verdicts[name]}")
            continue
        t, n = solution.results.get(name + "t"), solution.results.get(name + "n")
        r = solution.results.get(name)
        if p.kind == "oblique" and name in ("v_A2", "v_B2") and t and n:
            if t.value is not None and n.value is not None:
                sign = "-" if n.value < 0 else "+"
                shown_n = format_number(abs(n.value), p.digits)
                out.append(f"{name} = {format_number(t.value, p.digits)} e_t {sign} {shown_n} e_n {plain_unit(t.unit)}")
        elif r is not None and r.value is not None:
            unit = "°" if r.unit == "deg" else (" " + plain_unit(r.unit) if r.unit else "")
            out.append(f"{name} = {format_number(r.value, p.digits)}{unit}")
    return out
