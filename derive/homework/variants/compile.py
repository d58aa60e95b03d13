"""A problem derived once with its varied givens symbolic, its page printed once with open
numbers (slots), each slot, result and check compiled to a plain Python function."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, ClassVar

import sympy

from derive.errors import InputError
from derive.physics.impact import independent_map
from derive.problem import Given, Problem
from derive.steps.model import Solution
from derive.writers.printing import SlotBook

if TYPE_CHECKING:
    from derive.homework.variants.chain import ChainCompiled

_TOKEN = re.compile(r"DRVSLOT(\d+)X")

#: Where a stage's figure ("before" or "after" the impact), and the note under it, go in
#: a compiled page.
FIGURE = "DRVFIGURE{}-{}-X"


@dataclass
class Compiled:
    """A problem derived once, ready to print any variant."""

    problem: Problem
    solution: Solution
    names: tuple[str, ...]
    givens: dict[str, Given]
    templates: dict[str, list[str | int]]
    book: SlotBook
    slot_fn: object
    claim_fns: dict[int, list[tuple[list[object], object]]]
    result_fns: dict[str, object]
    check_fn: object
    #: The figures' numbers, compiled as they are first needed (:class:`~.fill.FigureNumbers`).
    figure_numbers: object = None
    #: The page's data (:func:`derive.writers.view.view`) with the slots open, for a variant's
    #: HTML (see :func:`derive.homework.variants.fill_view`).
    view: dict | None = None
    is_chain: ClassVar[bool] = False

    def accepts(self, values: dict[str, sympy.Expr]) -> bool:
        """True for a physical variant (bodies that approach, 0 <= e <= 1, positive masses,
        the file's conditions met); ``values`` in the order of :attr:`names`."""
        return bool(self.check_fn(*(float(values[n]) for n in self.names)))


def _symbolic(problem: Problem) -> Problem:
    """The problem with its varied givens (and givens defined from them) made symbolic."""
    varied = set(problem.vary)
    givens = []
    changed: set[sympy.Symbol] = set()
    for g in problem.givens:
        if g.name in varied or (g.definition is not None and g.definition.free_symbols & changed):
            g = replace(g, value=None)
            changed.add(g.symbol)
        givens.append(g)
    return replace(problem, givens=tuple(givens))


def _exact_zero(expr: sympy.Expr) -> sympy.Expr:
    """0 for a polynomial in the varied givens that is 0 (T_lost = T_1 - T_2 at e = 1, with
    m_B found: m_A v_A1²/2 - m_A v_A2²/2 - m_A (v_A1 - v_A2)(v_A1 + v_A2)/2), which floating
    point would print as 4.34 × 10⁻¹⁹; any other expression as it is."""
    if isinstance(expr, sympy.Expr) and expr.free_symbols and expr.is_polynomial() and sympy.expand(expr) == 0:
        return sympy.Integer(0)
    return expr


def _lambdify(symbols: tuple[sympy.Symbol, ...], exprs: list[sympy.Expr]) -> object:
    return sympy.lambdify(symbols, exprs, modules=["math"], cse=True)


def compile_problem(problem: Problem, digits: int | None = None, fmt: str = "md") -> Compiled | ChainCompiled:
    """Derive ``problem`` once (its varied givens symbolic) and compile its page; a chain
    is solved once, and each of its variants again (:mod:`derive.homework.variants.chain`)."""
    from derive.steps import solve
    from derive.writers.targets import GITHUB, TEX_DOCUMENT
    from derive.writers.view import environment, view

    if getattr(problem, "kind", None) == "chain":
        from derive.homework.variants.chain import compile_chain

        return compile_chain(problem)  # type: ignore[arg-type]
    if not problem.vary:
        raise InputError("has no [vary] table: nothing to draw variants from", where=problem.path, field="[vary]")
    names = tuple(sorted(problem.vary))
    symbolic = _symbolic(problem)
    solution = solve(symbolic)
    givens = {g.name: g for g in problem.givens}
    symbols = tuple(givens[n].symbol for n in names)
    book = SlotBook()
    layout = TEX_DOCUMENT if fmt in ("tex", "pdf") else GITHUB  # long lines on rows, as a solve's page
    data = view(solution, digits, figures=False, slots=book, varied=frozenset(symbols), layout=layout)
    for entry, stage in zip(data["stages"], solution.stages, strict=True):
        if stage.figure is not None:  # each variant's own figure goes here when it is filled in
            entry["figure_svg"] = entry["figure_tikz"] = FIGURE.format("", stage.figure)
            entry["figure_note_html"] = entry["figure_note_tex"] = FIGURE.format("NOTE", stage.figure)
    templates = {}
    if fmt in ("md", "json", "html"):
        page = environment("md").get_template("solution.md.j2").render(**data)
        templates["md"] = _split(page)
    if fmt in ("tex", "pdf"):
        page = environment("tex").get_template("solution.tex.j2").render(**data)
        templates["tex"] = _split(page)
    fixed = {k: v for k, v in symbolic.numeric().items()}
    ind = independent_map(symbolic)

    def prep(expr: sympy.Expr) -> sympy.Expr:
        return _exact_zero(sympy.sympify(expr).xreplace(ind).xreplace(fixed))

    slot_fn = _lambdify(symbols, [prep(s.expr) for s in book.slots]) if book.slots else None
    claim_fns = {
        block: [
            (_lambdify(symbols, [prep(t) for t in terms]), _lambdify(symbols, prep(total))) for terms, total in claims
        ]
        for block, claims in book.claims.items()
    }
    # a result that needs no varied given is a number already: ``value`` (an angle in degrees;
    # its ``partial`` would be radians, atan2(x, 0) = pi/2)
    results = {name: r.value if r.value is not None else r.partial for name, r in solution.results.items()}
    result_fns = {name: _lambdify(symbols, prep(expr)) for name, expr in results.items()}
    check_fn = _checks(symbolic, symbols, results, prep)
    return Compiled(
        problem, solution, names, givens, templates, book, slot_fn, claim_fns, result_fns, check_fn, view=data
    )


def _split(page: str) -> list[str | int]:
    parts: list[str | int] = []
    pos = 0
    for m in _TOKEN.finditer(page):
        parts.append(page[pos : m.start()])
        parts.append(int(m.group(1)))
        pos = m.end()
    parts.append(page[pos:])
    return parts


def _checks(problem: Problem, symbols: tuple[sympy.Symbol, ...], results: dict[str, sympy.Expr], prep) -> object:
    """One function of the varied values that is True for a physical variant: the
    bodies approach, e in [0, 1], masses positive, and the file's conditions hold.

    An unknown of an inverse problem (``e = "?"``, ``m_B = "? kg"``) is checked as the
    variant solves it, so a draw that makes it unphysical (e > 1, a negative mass) is
    refused. A built-in check on a given kept as a letter (``m = "kg"``: positive by
    its assumptions) is left out: it has no number to check."""
    allowed = set(symbols)

    def solved(expr: sympy.Expr) -> sympy.Expr:
        # by name: an unknown's symbol (e, with its assumptions) is not the condition's e
        expr = sympy.sympify(expr)
        to_results = {s: results[s.name] for s in expr.free_symbols if s.name in results and s not in allowed}
        return prep(expr.xreplace(to_results))

    sym = problem.symbols()
    built_in = [(solved(problem.motion_A.n - problem.motion_B.n), ">")]
    for name in ("m_A", "m_B"):
        if name in sym:
            built_in.append((solved(sym[name]), ">"))
    e = solved(sym["e"])
    built_in += [(e, ">="), (1 - e, ">=")]
    lower = [(x, op) for x, op in built_in if x.free_symbols <= allowed]
    for c in problem.conditions:
        diff = solved(c.lhs - c.rhs)
        if not diff.free_symbols <= allowed:
            names = ", ".join(sorted(str(s) for s in diff.free_symbols - allowed))
            raise InputError(f"{c.text} depends on {names}, which no variant gives a number", field="conditions")
        lower.append((diff if c.op in (">", ">=") else -diff, ">" if c.op in ("<", ">") else ">="))
    if not lower:
        return lambda *args: True
    fn = _lambdify(symbols, [x for x, _ in lower])
    ops = [op for _, op in lower]

    def ok(*args: float) -> bool:
        try:
            vals = fn(*args)
        except (ZeroDivisionError, ValueError, OverflowError):
            return False
        for v, op in zip(vals, ops, strict=True):
            v = complex(v)
            if abs(v.imag) > 1e-12 or not math.isfinite(v.real):
                return False
            if (op == ">" and not v.real > 1e-12) or (op == ">=" and not v.real >= -1e-12):
                return False
        return True

    return ok
