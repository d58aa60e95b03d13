"""A typed derivation of a chain problem, judged line by line against the chain's values.

A chain has no single set of equations (1)-(4) to solve again, so its lines are judged as
numbers: every given and every stage's result is known by its name (``u_A``, ``w_B``,
``e_floor``), and a name the student introduces with a value (``v1 = sqrt(2 x 9.8 x 2) =
6.26``) is known for the lines after it, both as it truly is and as the student worked it.
A line that holds is correct; the first that does not is the slip; a later line that holds
only with the student's own earlier numbers is carried.
"""

from __future__ import annotations

import sympy

from derive.checking.context import Context
from derive.checking.figures import literal_tolerance
from derive.checking.lines import merged
from derive.checking.naming import PREFIX, Open, declaration, read_side, rewrite
from derive.checking.numeric import number_of
from derive.checking.report import Item
from derive.mathtext.reader import Relation, read_relations
from derive.problem.expr import ParseError


def chain_items(ctx: Context, text: str) -> tuple[list[Item], list[str]]:
    """One item per relation of a chain's derivation, and what was read of its names."""
    values = {sympy.Symbol(str(k)): v for k, v in ctx.solution.values.items()}
    names = Open({s.name: s for s in values})
    true_defs: dict[sympy.Symbol, sympy.Expr] = {}
    own_defs: dict[sympy.Symbol, sympy.Expr] = {}
    items: list[Item] = []
    slips: list[str] = []
    for r in read_relations(text):
        if declaration(r.written):
            continue
        try:
            exprs = [
                read_side(rewrite(s, set(names.known)), names, i == 0, i == len(r.sides) - 1)
                for i, s in enumerate(r.sides)
            ]
        except (ParseError, ValueError, TypeError):
            continue
        left = exprs[0]
        if left.is_Symbol and left.name.startswith(PREFIX) and left not in true_defs and len(exprs) > 1:
            true_defs[left] = exprs[1].xreplace(true_defs).xreplace(values)
            own_defs[left] = sympy.Rational(r.sides[-1]) if _number(r.sides[-1]) else exprs[-1].xreplace(own_defs)
            exprs = exprs[1:]
            sides = r.sides[1:]
        else:
            sides = r.sides
        items.append(_verdict(ctx, r, sides, exprs, values, true_defs, own_defs, slips))
        if left.is_Symbol and _number(r.sides[-1]) and len(exprs) > 1:  # the student's value, carried on
            own_defs[left] = sympy.Rational(r.sides[-1].strip())
    return merged(items), []


def _number(text: str) -> bool:
    try:
        sympy.Rational(text.strip())
    except (TypeError, ValueError):
        return False
    return True


def _holds(ctx: Context, sides, exprs, subs: list[dict]) -> bool | None:
    for i in range(len(exprs) - 1):
        tol = max(literal_tolerance(f"{sides[i]} = {sides[i + 1]}", ctx.data), 1e-9)
        a, b = (number_of(x.xreplace(subs[0]).xreplace(subs[1]).xreplace(ctx.unit_subs())) for x in exprs[i : i + 2])
        if a is None or b is None:
            return None
        if abs(a - b) > 2 * tol * max(abs(a), abs(b)) + 1e-12:
            return False
    return True


def _verdict(ctx, r: Relation, sides, exprs, values, true_defs, own_defs, slips: list[str]) -> Item:
    def item(status: str, message: str) -> Item:
        return Item("line", str(r.line), r.written, status, "", message, "the chain's values")

    if len(exprs) < 2:
        return item("correct", "Defines a name for the lines after it.")
    truly = _holds(ctx, sides, exprs, [true_defs, values])
    if truly is None:
        return item("not read", "Not read: a name in it is not the chain's.")
    if truly:
        return item("correct", "True for this problem.")
    if slips and _holds(ctx, sides, exprs[:1] + [x.xreplace(own_defs) for x in exprs[1:]], [own_defs, values]):
        return item("carried", f"Right given the slip in line {slips[0]}: a carried error, not a new mistake.")
    first = not slips
    slips.append(str(r.line))
    lead = "The first line that is false for this problem" if first else "False: a further slip"
    return item("wrong", f"{lead}.")
