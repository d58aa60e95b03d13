"""An answer written as a formula (``sqrt(2)/4*(1+e)*v_A1``, ``5*sin(37.6°)``): judged by equivalence.

A formula is read by the restricted parser (students' notation written out by
:mod:`.notation` where the plain text does not parse), its unit checked, and then
compared with the closed form: as a formula in the givens, else with this
problem's numbers. Each comparison tries simplification first and evaluation at
random admissible points where that cannot decide (:func:`equivalent`).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING

import sympy

from derive.checking.context import DEG, RAD, Context, Names
from derive.checking.entries import Entry
from derive.checking.figures import literal_tolerance
from derive.checking.numeric import close, number_of, plain, simplified, tidy
from derive.checking.report import Item
from derive.checking.sampler import POINTS
from derive.mathtext.notation import student
from derive.physics.results import Result
from derive.problem import units
from derive.problem.expr import Parsed, ParseError, parse
from derive.problem.units import ANGLE, DIMENSIONLESS

if TYPE_CHECKING:
    from derive.checking.mistakes import Outcome


@dataclass(frozen=True)
class Formula:
    """A formula read for result ``r``: ``expr`` in the working unit (radians for
    angles), ``has_symbols`` where it uses givens, ``missing`` where no unit was given."""

    expr: sympy.Expr
    has_symbols: bool
    missing: bool = False


def read(text: str, names: Names) -> Parsed:
    """``text`` parsed as written, else as students write it; the error is the one for
    the text as written."""
    try:
        return parse(text, names)
    except ParseError as exc:
        rewritten = student(text)
        if rewritten == text:
            raise
        try:
            return parse(rewritten, names)
        except ParseError:
            raise exc from None


def expression_item(ctx: Context, e: Entry, r: Result, text: str, unit_problem: str | None) -> Item:
    """The verdict on the formula ``text`` for result ``r``."""
    read_ = _formula(ctx, e, r, text, unit_problem)
    if isinstance(read_, Item):
        return read_
    return _judged(ctx, r, text, read_)


def _formula(ctx: Context, e: Entry, r: Result, text: str, unit_problem: str | None) -> Formula | Item:
    """``text`` read as a formula for ``r`` (or the unit mismatch it is)."""
    work = ctx.work(r)
    try:
        parsed, unit = _parsed(ctx, text)
    except ParseError as exc:
        if unit_problem:
            raise e.error(unit_problem) from None
        try:
            read(text, ctx.answer_names(dimensionless=True))
        except ParseError:
            raise e.error(str(exc)) from None
        return _mismatch(ctx, r, text, f"Unit mismatch: {exc}.")
    expr = parsed.expr.xreplace({**ctx.model.pre, **ctx.unit_subs()})
    dim = parsed.dim
    has_symbols = bool(expr.free_symbols & {g.symbol for g in ctx.problem.givens})
    if unit is not None:
        if dim != DIMENSIONLESS:
            raise e.error("a unit after an expression in the givens is not needed: the givens carry their units")
        if unit.dim != work.dim:
            why = f"{unit.text} is {units.describe(unit.dim)}, but {r.name} is {units.describe(work.dim)}"
            return _mismatch(ctx, r, text, f"Unit mismatch: {why}.")
        return Formula(expr * unit.factor / (work.factor if work.dim != ANGLE else 1), has_symbols)
    if dim == DIMENSIONLESS and work.dim == ANGLE:
        return Formula(expr * sympy.pi / 180, has_symbols)  # a pure number for an angle is in degrees
    if dim == DIMENSIONLESS and work.dim != DIMENSIONLESS and not has_symbols:
        return Formula(expr, has_symbols, missing=True)
    if dim != work.dim:
        why = f"the expression is {units.describe(dim)}, but {r.name} is {units.describe(work.dim)}"
        unit_text = f" ({units.plain_unit(work.text)})." if work.text else "."
        return _mismatch(ctx, r, text, f"Unit mismatch: {why}{unit_text}")
    return Formula(expr, has_symbols)


def _parsed(ctx: Context, text: str) -> tuple[Parsed, units.Unit | None]:
    """The formula and the unit written after it, if any (``EXPR UNIT``)."""
    names = ctx.answer_names()
    try:
        return parse(text, names), None
    except ParseError as exc:
        split = _split_unit(text)
        if split is not None:
            try:
                return read(split[0], names), split[1]
            except ParseError:
                pass
        try:
            return read(text, names), None
        except ParseError:
            raise exc from None


def _mismatch(ctx: Context, r: Result, text: str, message: str) -> Item:
    return Item("answer", r.name, text, "unit mismatch", ctx.expected_text(r), message)


def _judged(ctx: Context, r: Result, text: str, f: Formula) -> Item:
    """Correct when equivalent to the closed form; else the mistakes that give it."""
    work = ctx.work(r)
    tol = literal_tolerance(text, ctx.data)
    target, user = ctx.target(r), ctx.num(f.expr)
    same, how, scope = _compare(ctx, r, f, tol)
    a, b = number_of(user), number_of(target)
    fields = dict(
        relative_error=float(((a - b) / abs(b)).real) if a is not None and b is not None and b != 0 else None,
        value=float(a.real) * (180 / math.pi if work.dim == ANGLE else 1) if a is not None else None,
        unit=work.text,
        unit_missing=f.missing,
        expected_value=float(r.value) if r.value is not None else None,
        method=how,
        notes=(f"No unit given: read as {units.plain_unit(work.text)}.",) if f.missing else (),
    )
    expected = ctx.expected_text(r)
    if same:
        return Item("answer", r.name, text, "correct", expected, f"Correct: {scope}, by {how}.", **fields)

    def fits(out: Outcome) -> str | None:
        q = out.results.get(r.name)
        if q is None or q.partial is None or not equivalent(ctx, user, q.partial, tol, quick=True)[0]:
            return None
        return ctx.shown(q.value, 3, work) if q.value is not None else plain(tidy(q.partial))

    diags, together = ctx.diagnose(fits, ctx.singles()), False
    if not diags:
        diags, together = ctx.diagnose(fits, ctx.pairs()), True
    hints = []
    if equivalent(ctx, user, -target, tol, quick=True)[0]:
        hints.append("It has the right size but the wrong sign: check the positive senses of n and t.")
    msg = f"Wrong: not equivalent to the expected value, by {how}."
    if not diags:
        msg += " No common mistake reproduces it."
    elif together:
        msg += " Two common mistakes made together reproduce it."
    return Item("answer", r.name, text, "wrong", expected, " ".join([msg, *hints]), diagnosis=diags, **fields)


def _compare(ctx: Context, r: Result, f: Formula, tol: float) -> tuple[bool, str, str]:
    """(equivalent?, by which method, in what sense)."""
    user, target = ctx.num(f.expr), ctx.target(r)
    if not f.has_symbols:
        same, how = equivalent(ctx, user, target, tol)
        return same, how, "equal to the exact value"
    defs = ctx.definitions()
    full_user = f.expr.xreplace(ctx.ind).xreplace(defs)
    full_target = r.closed.xreplace(ctx.ind).xreplace(defs)
    same, how = equivalent(ctx, full_user, full_target, tol)
    if same:
        return same, how, "equivalent to the closed form as a formula in the givens"
    same, how = equivalent(ctx, user, target, tol)
    return same, how, "equivalent with this problem's numbers (not as a formula in all the givens)"


def equivalent(ctx: Context, a: sympy.Expr, b: sympy.Expr, tol: float, quick: bool = False) -> tuple[bool, str]:
    """Whether ``a`` and ``b`` are the same: by simplification, else at random admissible points."""
    exact = tol == 0
    d = a - b
    if exact and not quick:
        s = simplified(d)
        if s == 0:
            return True, "simplification"
        if s is not None and s.is_number and number_of(s) not in (None, 0):
            return False, "simplification"
    elif exact and d == 0:
        return True, "simplification"
    syms = (a.free_symbols | b.free_symbols) - {DEG, RAD}
    if not syms:
        x, y = number_of(a), number_of(b)
        if x is None or y is None:
            return False, "evaluation"
        how = (
            "evaluation to 30 digits" if exact else f"evaluation, to the precision of the decimals written (±{tol:.2g})"
        )
        return close(x, y, tol), how
    return _at_points(ctx, a, b, syms, tol, 3 if quick else POINTS)


def _at_points(ctx: Context, a: sympy.Expr, b: sympy.Expr, syms: set, tol: float, n: int) -> tuple[bool, str]:
    checked = 0
    for pt in ctx.sampler().points(syms, n):
        x, y = number_of(a.xreplace(pt)), number_of(b.xreplace(pt))
        if x is None or y is None:
            continue
        checked += 1
        if not close(x, y, tol):
            where = ", ".join(f"{s.name} = {float(v):g}" for s, v in pt.items())
            return False, f"evaluation at a random admissible point, {where}"
    if checked == 0:
        return False, "evaluation (no admissible point could be evaluated)"
    how = f"evaluation at {checked} random admissible points"
    if tol != 0:
        how += f", to the precision of the decimals written (±{tol:.2g})"
    return True, how


def _split_unit(text: str) -> tuple[str, units.Unit] | None:
    """``EXPR UNIT`` -> (EXPR, unit) when the last word is a unit."""
    m = re.match(r"^(.*\S)\s+([A-Za-z°][A-Za-z°/*^·\d]*)\s*$", text)
    if not m:
        return None
    try:
        return m.group(1), units.parse_unit(m.group(2))
    except ValueError:
        return None
