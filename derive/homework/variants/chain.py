"""Variants of a chain: each drawn chain is the file with the variant's numbers written into
its ``[given]`` table, solved by the chain solver and written by the chain writer, so that a
variant's pages are the pages ``derive solve`` writes for that file.

A chain is short and has few stages, so no page is compiled once for all its variants as
for a single impact (:mod:`derive.homework.variants.compile`): a variant costs one solve of
the chain (a few tenths of a second). A draw is physical when the chain solves (every
impact's bodies approach, a ``solve`` stage has exactly one admissible root, no square root
of a negative number) and meets the file's ``conditions``.
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass
from decimal import Decimal, localcontext
from typing import Any, ClassVar

import sympy

from derive.errors import DeriveError, InputError
from derive.homework.variants.record import Variant
from derive.numbers import terminates
from derive.problem import ChainProblem, Condition, Given, Source, parse_toml
from derive.problem.givens import QUANTITY
from derive.problem.units import ANGLE, DIMENSIONLESS, Dim, parse_unit, plain_unit
from derive.steps.model import Solution

#: Solved variants kept (a variant is drawn, checked and then written: solved once).
CACHE = 256


@dataclass
class ChainCompiled:
    """A chain with a ``[vary]`` table, ready to solve and print any variant.

    ``solution`` is the file's own chain solved (what a variant's results are named and
    described by); ``conditions`` the file's conditions with the chain's names."""

    problem: ChainProblem
    solution: Solution
    names: tuple[str, ...]
    givens: dict[str, Given]
    conditions: tuple[Condition, ...]
    #: Why the last refused draw was refused (for the message when too few are physical).
    refusal: str = ""
    is_chain: ClassVar[bool] = True

    def written(self, values: dict[str, sympy.Expr]) -> tuple[tuple[str, str | int | float], ...]:
        """Each varied given as the file's ``[given]`` table writes it at these values."""
        raw = parse_toml(self.problem.ctx.text, self.problem.path).get("given", {})
        return tuple((n, written_value(self.givens[n], values[n], raw.get(n))) for n in self.names)

    def solved(self, values: dict[str, sympy.Expr]) -> Solution:
        """The chain solved with these values in its givens (as ``derive solve`` solves the
        file with them written in); a :class:`~derive.errors.DeriveError` when it is not physical."""
        p = self.problem
        return _solve(p.path, p.ctx.text, p.name, self.written(values))

    def accepts(self, values: dict[str, sympy.Expr]) -> bool:
        """True when the chain solves with these values and they meet the file's conditions."""
        try:
            sol = self.solved(values)
        except DeriveError as exc:
            self.refusal = " ".join(str(exc).split()).removeprefix(f"{self.problem.path}: ")
            return False
        for c in self.conditions:
            if not holds(c, sol):
                self.refusal = f"{c.text} does not hold"
                return False
        return True


def compile_chain(problem: ChainProblem) -> ChainCompiled:
    """A chain with a ``[vary]`` table, solved once with its own numbers: every value of the
    table checked to be writable in the file's units, the conditions read with its names."""
    from derive.problem import fields
    from derive.steps import solve

    if not problem.vary:
        raise InputError("has no [vary] table: nothing to draw variants from", where=problem.path, field="[vary]")
    givens = {g.name: g for g in problem.givens}
    names = tuple(sorted(problem.vary))
    raw = parse_toml(problem.ctx.text, problem.path).get("given", {})
    for n in names:
        for v in problem.vary[n]:
            written_value(givens[n], v, raw.get(n), where=problem.path)
    solution = solve(problem)
    dims = {name: (r.symbol, _dim(r.unit)) for name, r in solution.results.items()}
    conditions = fields.conditions(list(problem.conditions), givens, problem.ctx, results=dims, system=problem.system)
    known = _numbers(solution)
    for c in conditions:
        left = (c.lhs - c.rhs).xreplace(known).free_symbols
        if left:
            shown = ", ".join(sorted(str(s) for s in left))
            raise InputError(f"{c.text} depends on {shown}, which no variant gives a number", field="conditions")
    return ChainCompiled(problem, solution, names, givens, conditions)


def _dim(unit: str) -> Dim:
    if unit == "deg":
        return ANGLE
    if not unit:
        return DIMENSIONLESS
    try:
        return parse_unit(unit).dim
    except ValueError:
        return DIMENSIONLESS


def _numbers(sol: Solution) -> dict[sympy.Symbol, sympy.Expr]:
    """Every given's and result's number of a solved chain, by symbol."""
    out = {g.symbol: g.value for g in sol.problem.givens if g.value is not None}
    out.update({r.symbol: r.value for r in sol.results.values() if r.value is not None})
    return out


def holds(c: Condition, sol: Solution) -> bool:
    """True when the condition holds for the solved chain (to 1e-12)."""
    diff = (c.lhs - c.rhs).xreplace(_numbers(sol))
    if diff.free_symbols:
        return False
    z = complex(sympy.N(diff, 20))
    if abs(z.imag) > 1e-12 or not math.isfinite(z.real):
        return False
    x = z.real if c.op in (">", ">=") else -z.real
    return x > 1e-12 if c.op in (">", "<") else x >= -1e-12


@functools.lru_cache(maxsize=CACHE)
def _solve(path: str, text: str, name: str, written: tuple[tuple[str, str | int | float], ...]) -> Solution:
    """The chain file ``text`` with the ``written`` givens in its ``[given]`` table, solved
    (its ``[vary]`` table and conditions left out: they print nothing)."""
    from derive.problem.chain import build_chain
    from derive.steps import solve

    data = parse_toml(text, path)
    data.pop("vary", None)
    data.pop("conditions", None)
    data.setdefault("given", {}).update(dict(written))
    return solve(build_chain(data, Source(path, text), name))


def written_value(g: Given, value: sympy.Expr, raw: object, where: str | None = None) -> str | int | float:
    """``value`` (in the working unit, an angle in radians) as the file's ``[given]`` table
    writes ``g``: a number where the file typed a number, else the number and the unit the
    file typed, with at least the places it typed (2.50 m/s at 3.1 is "3.10 m/s")."""
    m = QUANTITY.match(raw) if isinstance(raw, str) else None
    if g.unit == "deg":
        number, unit = value * 180 / sympy.pi, m.group(2) if m is not None else "deg"
    elif g.written is not None and g.typed is not None and g.value and m is not None:  # typed in another unit: 22 g
        number, unit = value * sympy.Rational(g.typed) / g.value, m.group(2)
    elif g.written is not None:  # converted, its number not plain: in the working unit
        number, unit = value, g.unit
    else:
        number, unit = value, m.group(2) if m is not None else g.unit
    text = _decimal(sympy.nsimplify(number))
    if text is None:
        raise InputError(
            f"{sympy.N(number, 8)} {unit} is no decimal number in {unit}, the unit [given] types "
            f"{g.name} in: a variant's [given] could not hold it (give [vary] in {unit})",
            where=where,
            field=f"[vary] {g.name}",
        )
    places = len(g.typed.partition(".")[2]) if g.typed is not None else 0
    have = len(text.partition(".")[2])
    if have < places:
        text += ("" if "." in text else ".") + "0" * (places - have)
    if isinstance(raw, (int, float)) and not isinstance(raw, bool):
        return float(text) if "." in text else int(text)
    return f"{text} {unit}" if unit else text


def _decimal(q: sympy.Expr) -> str | None:
    """A rational number as a terminating decimal ("0.25", "-3", "12.5"), else None."""
    if not isinstance(q, sympy.Rational) or not terminates(q):
        return None
    with localcontext() as ctx:
        ctx.prec = 100
        d = Decimal(int(q.p)) / Decimal(int(q.q))
    text = format(d.normalize(), "f")
    return re.sub(r"^-0$", "0", text)


def chain_answers(c: ChainCompiled, variant: Variant, digits: int | None = None) -> dict[str, dict]:
    """The answer key of one chain variant: each result with a number (a given of the file is
    no answer), its value, unit and shown text ("yes" or "no" for whether they collide again)."""
    from derive.numbers import float_decimal, format_number

    sol = c.solved(variant.values)
    d = digits if digits is not None else c.problem.digits
    verdicts = {a.name for a in sol.answers if a.verdict is not None}
    out = {}
    for name, r in sol.results.items():
        if r.value is None or (name in c.givens and not c.givens[name].unknown):
            continue
        x = float(sympy.N(r.value, 17))
        shown = ("yes" if x else "no") if name in verdicts else format_number(float_decimal(x), d)
        out[name] = {"value": x, "unit": "deg" if r.unit == "deg" else plain_unit(r.unit), "shown": shown}
    return out


def chain_fill(c: ChainCompiled, variant: Variant, fmt: str = "md", digits: int | None = None) -> str:
    """The worked solution of one chain variant, as ``derive solve`` writes it (Markdown, or
    a LaTeX document for tex and pdf)."""
    from derive.writers.view import render

    return render(c.solved(variant.values), "tex" if fmt in ("tex", "pdf") else "md", digits=digits)


def chain_view_of(c: ChainCompiled, variant: Variant, digits: int | None = None) -> dict[str, Any]:
    """One chain variant's page as data in one problem's shape (:func:`derive.writers.view.chain_as_problem`),
    without figures: what an LMS shows (the statement with each impact's sign convention, the
    worked solution)."""
    from derive.writers.view import chain_as_problem, student_sheet

    # as a student's sheet: the convention of each impact (later impacts are not drawn), an
    # unknown "to find", no Source line
    return student_sheet(chain_as_problem(c.solved(variant.values), digits, figures=False))


def chain_setup_figure(c: ChainCompiled, variant: Variant, fmt: str = "md") -> str:
    """The figure before the chain's first impact, drawn to the variant's numbers, as SVG or
    (tex, pdf) TikZ; empty when no impact stage has one."""
    from derive.writers import figure

    sol = c.solved(variant.values)
    falls = figure.chain_falls(sol)
    for st in sol.stages:
        if st.part is not None and any(sub.figure == "before" for sub in st.part.stages):
            drawn = figure.describe(st.part, after=False, falls=falls.get(st.number, False), values=sol.values)
            return figure.to_tikz(drawn) if fmt in ("tex", "pdf") else figure.to_svg(drawn)
    return ""


def chain_sign_convention(c: ChainCompiled, fmt: str = "md") -> str:
    """The sign convention of every impact stage in words, as Markdown or (tex, pdf) LaTeX."""
    from derive import escape
    from derive.writers.view import chain_convention, chain_view

    parts = chain_convention(chain_view(c.solution, figures=False))
    text = escape.tex if fmt in ("tex", "pdf") else escape.markdown
    return "".join(f"${s}$" if kind == "math" else text(s) for kind, s in parts)


def chain_html(c: ChainCompiled, variant: Variant, stem: str, digits: int | None = None) -> tuple[str, str]:
    """One chain variant as HTML, typeset together: a student's sheet (the statement, Given,
    Find, the set-up before the first impact, the sign convention of each impact; no Source
    line, no answers) and the worked solution as ``derive solve -f html`` writes it."""
    from derive.writers.targets import HTML
    from derive.writers.view import chain_as_problem, chain_view, student_sheet
    from derive.writers.view.html import html_pages

    sol = c.solved(variant.values)
    student = student_sheet(chain_as_problem(sol, digits, figures=False, layout=HTML))
    student.update(title=stem.replace("variant-", "Variant "), setup_svg=chain_setup_figure(c, variant, "html"))
    sheet = {"title": c.problem.title, "mode": "problems", "problems": [student], "theory": None, "numbered": False}
    student_page, worked = html_pages([("handout", sheet), ("chain", chain_view(sol, digits, layout=HTML))])
    return student_page, worked


def chain_result_words(c: ChainCompiled, name: str) -> list[tuple[str, str]]:
    """What a chain's result is, as text and mathematics (for an LMS question): an impact's
    result by the impact's own name ("v_A2 after A and B collide"), an energy stage's by what
    it finds ("the height reached"), a ``define`` stage's by its title, an unknown as such."""
    from derive.problem.chain import stage_results
    from derive.problem.schema.chain import STAGES
    from derive.symbols import latex_name, relabel

    steps = {st.number: st for st in c.solution.stages}
    for i, raw in enumerate(c.problem.stages, 1):
        st = steps.get(i)
        title = str(st.title if st is not None else raw.get("title", f"stage {i}"))
        if raw["type"] == "impact" and st is not None and st.part is not None:
            for slot, new in (raw.get("results") or {}).items():
                if new == name:
                    lead = "t" + title[1:] if title.startswith("The ") else title
                    return [
                        ("math", latex_name(relabel(str(slot), st.part.problem.labels))),
                        ("text", f" after {lead}"),
                    ]
        elif any(new == name for _, new in stage_results(i, raw)):
            if raw["type"] in ("fall", "rise", "slide", "spring"):
                return [("text", STAGES[raw["type"]].meaning.partition(":")[0])]
            if title.startswith("The "):  # a define stage's title: "The rebound speed"
                return [("text", "t" + title[1:])]
            return [("text", f"the result of stage {i} ({title})")]
    g = c.givens.get(name)
    if g is not None and g.unknown:
        return [("text", "the unknown of the problem")]
    return [("text", f"the result {name}")]
