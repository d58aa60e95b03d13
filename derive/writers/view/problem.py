"""The view of one impact: the data its templates need, every formula printed as LaTeX."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

import sympy

from derive import escape
from derive.steps.model import Solution
from derive.symbols import latex_name
from derive.writers.printing import Style
from derive.writers.targets import GITHUB, Layout
from derive.writers.view.givens import given_latex, letter_units, letters_of, source_parts, statement, worked_out
from derive.writers.view.lines import blocks_view

if TYPE_CHECKING:  # the figure modules are imported where a page draws one (JSON draws none)
    from derive.writers import figure


def _sentence(text: str) -> str:
    """A caption standing alone under its figure: its first letter a capital."""
    return text[:1].upper() + text[1:]


def _html_name(name: str) -> str:
    """A symbol's name in HTML: ``v_A2`` -> ``<i>v</i><sub>A2</sub>``."""
    base, _, sub = name.partition("_")
    return f"<i>{escape.html_text(base)}</i>" + (f"<sub>{escape.html_text(sub)}</sub>" if sub else "")


def figure_entry(fig: figure.Figure) -> dict[str, str]:
    """A stage's figure as the templates take it: SVG and TikZ, the caption, and the note
    Markdown and LaTeX print under it when an arrow is drawn longer than to scale."""
    from derive.writers import figure

    html_note = fig.scale_note(_html_name, escape.html_text)
    return {
        "figure_svg": figure.to_svg(fig),
        "figure_tikz": figure.to_tikz(fig),
        "figure_caption": f"{fig.title}: {fig.caption}",
        "figure_caption_html": escape.html_text(f"{fig.title}: ") + html_note,
        "figure_note_html": figure_note(fig, tex=False),
        "figure_note_tex": figure_note(fig, tex=True),
    }


def figure_note(fig: figure.Figure, tex: bool) -> str:
    """The note under a figure (HTML for Markdown, or LaTeX) when an arrow is drawn longer
    than to scale, the bodies' sizes are schematic (a variant's) or a letter is drawn at a number
    (e = 0.5); else empty."""
    if not (fig.lengthened or fig.schematic or fig.drawn_for):
        return ""
    if tex:
        return _sentence(fig.scale_note(lambda n: f"${latex_name(n)}$", escape.tex))
    return _sentence(fig.scale_note(_html_name, escape.html_text))


def _named(words: str, labels: tuple[str, str]) -> str:
    """Words about body A or B (``the speed of A``) under the page's letters."""
    return re.sub(r"\b([AB])\b", lambda m: labels["AB".index(m[1])], words) if labels != ("A", "B") else words


_FIND_WORDS = {
    "v_A2": "the speed of A",
    "v_B2": "the speed of B",
    "theta_A2": "the direction of A (from +t)",
    "theta_B2": "the direction of B (from +t)",
    "beta_A2": "the direction of A (from +n)",
    "beta_B2": "the direction of B (from +n)",
    "alpha_A2": "the angle between A's velocity and the line of centres",
    "alpha_B2": "the angle between B's velocity and the line of centres",
    "gamma_A2": "the angle between A's velocity and the plane of contact",
    "gamma_B2": "the angle between B's velocity and the plane of contact",
    "delta_A": "the angle A's velocity turns through",
    "delta_B": "the angle B's velocity turns through",
    "J_n": "the impulse along n",
    "T_1": "the kinetic energy before the impact",
    "T_2": "the kinetic energy after the impact",
    "T_lost": "the kinetic energy lost",
}


def impact_view(
    solution: Solution,
    digits: int | None = None,
    figures: bool = True,
    *,
    layout: Layout = GITHUB,
    outer_letters: dict[sympy.Symbol, str] | None = None,
    outer_decimal: frozenset[sympy.Symbol] = frozenset(),
    falls: bool = False,
    known: dict[sympy.Symbol, sympy.Expr] | None = None,
    plot: bool = False,
) -> dict[str, Any]:
    """One impact's page data: every formula already printed as LaTeX, and the figures
    of stage 1 and of the answer as SVG and TikZ (:func:`derive.writers.view.page.view`
    makes it the one stage of a page, or a stage of a chain).

    ``layout`` says where the page goes (:mod:`derive.writers.targets`): how wide a line may
    be, and whether cancelled terms are struck out. ``falls`` and ``known`` are for
    an impact inside a chain: drawn with n pointing down, and the chain's numbers for
    symbols the impact leaves open. ``plot`` adds the plot of the outcome against e
    (``plot_svg``, ``plot_tikz``).
    """
    p = solution.problem
    style = _style(solution, digits, layout, outer_letters, outer_decimal)
    stages = _stages(solution, style, layout, figures=figures, falls=falls, known=known)
    givens = [dict(zip(("latex", "note"), given_latex(g, style), strict=False)) for g in p.givens]
    found = {n: r.found for n, r in solution.results.items()}
    find = _find(p, style, found)
    plot_svg, plot_tikz = _plot(p) if plot else ("", "")
    return {
        "title": p.title,
        "kind": p.kind,
        "source": p.source,
        "source_parts": source_parts(p.source),
        "plot_svg": plot_svg,
        "plot_tikz": plot_tikz,
        "statement": statement(p, style, found=found),
        "find": find,
        "givens": givens,
        "stages": stages,
        "system": p.system,
    }


def _style(
    solution: Solution,
    digits: int | None,
    layout: Layout,
    outer_letters: dict[sympy.Symbol, str] | None,
    outer_decimal: frozenset[sympy.Symbol],
) -> Style:
    """How the impact's page prints: its digits, its letters and decimals."""
    p = solution.problem
    return Style(
        digits if digits is not None else p.digits,
        1,
        solution.values,
        solution.angles,
        strike=layout.strike,
        decimal=frozenset(g.symbol for g in p.givens if g.decimal) | outer_decimal,
        letters=letters_of(p, solution.values),
        letter_units={**(outer_letters or {}), **letter_units(p)},
        labels=p.labels,
        derived=worked_out(p, solution.values),
    )


def _stages(
    solution: Solution,
    style: Style,
    layout: Layout,
    *,
    figures: bool,
    falls: bool,
    known: dict[sympy.Symbol, sympy.Expr] | None,
) -> list[dict[str, Any]]:
    """Each stage's blocks, printed, and its figure (SVG and TikZ) where it has one."""
    stages = []
    for stage in solution.stages:
        blocks = blocks_view(stage.blocks, style, layout)
        entry = {"number": stage.number, "title": stage.title, "heading": [("text", stage.title)], "blocks": blocks}
        entry.update(figure_svg="", figure_tikz="")
        if figures and stage.figure is not None:
            from derive.writers import figure

            fig = figure.describe(solution, after=stage.figure == "after", falls=falls, values=known)
            entry.update(figure_entry(fig))
        stages.append(entry)
    return stages


def _find(p: Any, style: Style, found: dict[str, Any]) -> list[tuple[str, str]]:
    """What the problem asks for: its question, else words made from what it finds."""
    if p.question:
        return statement(p, style, p.question, found) or []
    unknown = [g.name for g in p.givens if g.unknown]
    words = ("the unknown " + ", ".join(unknown) + "; " if unknown else "") + (
        f"the velocity of {p.labels[0]} immediately after the impact"
        if p.fixed_B
        else f"the velocities of {p.labels[0]} and {p.labels[1]} immediately after the impact"
    )
    extra_words = [
        _named(_FIND_WORDS[f], p.labels)
        for f in p.find
        if f in _FIND_WORDS and not (f in ("v_A2", "v_B2") and not p.oblique)
    ]
    if extra_words:
        words += "; " + ", ".join(extra_words)
    return [("text", words[0].upper() + words[1:] + ".")]


def _plot(p: Any) -> tuple[str, str]:
    """The plot of the outcome against e, as SVG and TikZ."""
    from derive.writers import plot as plots

    chart = plots.chart(p)
    return plots.to_svg(chart), plots.to_tikz(chart)


def convention(stages: list[dict[str, Any]]) -> list[tuple[str, str]]:
    """The sign convention in words, as stage 1 of the solution states it (where n and t
    point; a direct impact's velocities signed along +n): a sentence for a student's sheet."""
    for stage in stages:
        for i, block in enumerate(stage["blocks"]):
            text = block["text"] or []
            if text[:1] == [("text", "Take ")]:
                more = [
                    b["text"] for b in stage["blocks"][i + 1 :] if b["text"] and "signed along +n" in str(b["text"])
                ]
                return [*text, *(part for m in more for part in [("text", " "), *m])]
    return []


def student_sheet(data: dict[str, Any]) -> dict[str, Any]:
    """A problem's page data (:func:`derive.writers.view.page.problem_view`, with the sign
    convention in words) made a student's sheet, in place: no Source line (citations quote the
    published answers), an unknown given marked "to find"."""
    from derive.writers.view.givens import UNKNOWN_NOTE

    data["source"], data["source_parts"] = None, []
    for g in data["givens"]:
        if g.get("note") == UNKNOWN_NOTE:
            g["note"] = "to find"
    return data
