"""A variant's pages, answers and givens: its own problem (the file with its numbers written
in, :meth:`Compiled.solved`) through the writers every page goes through."""

from __future__ import annotations

from typing import Any

import sympy

from derive.homework.variants.compile import Compiled
from derive.homework.variants.record import Variant
from derive.numbers import float_decimal, format_number
from derive.problem.units import plain_unit


def fill(compiled: Compiled, variant: Variant, fmt: str = "md", digits: int | None = None) -> str:
    """The worked solution of one variant, as ``derive solve`` writes it for the file with the
    variant's numbers (Markdown, or a LaTeX document for tex and pdf)."""
    from derive.writers.view import render

    return render(compiled.solved(variant.values), "tex" if fmt in ("tex", "pdf") else "md", digits=digits)


def sheet(compiled: Compiled, variant: Variant, fmt: str = "md", digits: int | None = None) -> str:
    """A student's sheet of one variant (Given, Find, the set-up before the impact, the sign
    convention in words; no Source line, no answers): Markdown, or a LaTeX document."""
    from derive.writers.view import student_page

    fmt = "tex" if fmt in ("tex", "pdf") else "md"
    return student_page(compiled.solved(variant.values), fmt, digits=digits)


def answers(compiled: Compiled, variant: Variant, digits: int | None = None) -> dict[str, dict]:
    """The answer key of one variant: each result with a number, its value, unit and shown text
    ("yes" or "no" for whether a chain's bodies collide again). A result that is a given of the
    file (v_A2 given in an inverse problem) is no answer: the key has it once, among the givens."""
    sol = compiled.solved(variant.values)
    d = digits if digits is not None else compiled.problem.digits
    verdicts = {a.name for a in sol.answers if a.verdict is not None}  # a chain's "collide again?"
    known = {g.name for g in compiled.problem.givens if not g.unknown}
    out = {}
    for name, r in sol.results.items():
        if r.value is None or name in known:
            continue
        z = complex(sympy.N(r.value, 17))
        if abs(z.imag) > 1e-9 * max(1.0, abs(z.real)):
            continue
        x = z.real
        shown = ("yes" if x else "no") if name in verdicts else format_number(float_decimal(x), d)
        out[name] = {"value": x, "unit": "deg" if r.unit == "deg" else plain_unit(r.unit), "shown": shown}
    return out


def given_values(compiled: Compiled, variant: Variant) -> dict[str, dict]:
    """The varied givens of a variant, in the problem's units (angles in degrees)."""
    out = {}
    for n in compiled.names:
        g = compiled.givens[n]
        v = variant.values[n]
        value = float(v * 180 / sympy.pi) if g.unit == "deg" else float(v)
        out[n] = {"value": value, "unit": "deg" if g.unit == "deg" else plain_unit(g.unit)}
    return out


def fill_view(compiled: Compiled, variant: Variant, digits: int | None = None) -> dict[str, Any]:
    """One variant's page as the writers' data, in one problem's shape
    (:func:`derive.writers.view.problem_view`): what an LMS shows, the statement (as a student's
    sheet) and the worked solution."""
    from derive.writers.view import problem_view

    return problem_view(compiled.solved(variant.values), digits)


def setup_figure(compiled: Compiled, variant: Variant, fmt: str = "md") -> str:
    """A variant's figure before the impact (a chain's: its first impact) as SVG or (tex, pdf)
    TikZ, for the student's statement; empty when its page has none."""
    from derive.writers import figure

    sol = compiled.solved(variant.values)
    impacts = [st.part for st in sol.stages if st.part is not None] or [sol]  # a chain's, or the impact
    if not impacts or not any(st.figure == "before" for st in impacts[0].stages):
        return ""
    drawn = figure.describe(sol, after=False)
    return figure.to_tikz(drawn) if fmt in ("tex", "pdf") else figure.to_svg(drawn)


def variant_html(compiled: Compiled, v: Variant, stem: str, digits: int | None = None) -> tuple[str, str]:
    """One variant as HTML, typeset together: a student's sheet (Given, Find, the set-up before
    the impact, the sign convention in words; no Source line, no answers) and the worked
    solution as ``derive solve -f html`` writes it."""
    from derive.writers.targets import HTML
    from derive.writers.view import problem_view, student_sheet, view
    from derive.writers.view.html import html_pages

    sol = compiled.solved(v.values)
    student = student_sheet(problem_view(sol, digits, figures=False, layout=HTML))
    student.update(title=stem.replace("variant-", "Variant "), setup_svg=setup_figure(compiled, v, "html"))
    problems = {"title": compiled.problem.title, "mode": "problems", "problems": [student], "theory": None}
    worked = view(sol, digits, layout=HTML)
    student_page, worked_page = html_pages([("handout", {**problems, "numbered": False}), ("solution", worked)])
    return student_page, worked_page
