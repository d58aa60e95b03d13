"""Quantities a student introduces in a chain's derivation, with no name derive has for them.

"Let s be the total compression", ``ω² = k/(M + m)``, ``y_0 = M g/k``: the student names a
quantity, relates it to the givens, solves for it and uses it. A teacher marks those lines by
whether they hold given what the quantity is, so such a name is known for every line of the
derivation, the lines before the one that solves for it too (``10 000 s² - 392.4 s - 439.74 = 0``
before ``s = 0.2302``), and a value worked with rounded numbers carries their rounding into the
lines that use it (``x = s - s_0`` with s found as 0.2302).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import sympy

from derive.checking import chainnames
from derive.checking.figures import literal_tolerance
from derive.checking.naming import PREFIX, placeholders
from derive.checking.report import Item
from derive.checking.stageslips import numbers_written
from derive.checking.worlds import number_at_figures
from derive.problem.expr import ParseError


class Defs(dict):
    """The true values of the student's own names, and the relative slack of each (the
    rounding of the numbers it was worked from)."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.slack: dict[sympy.Symbol, float] = {}


def slack_of(defs: dict, names: set[sympy.Symbol]) -> float:
    """The largest rounding slack among ``names`` (0 where none was worked from rounded numbers)."""
    slack = getattr(defs, "slack", {})
    return max((slack.get(s, 0.0) for s in names), default=0.0)


def defined(left: sympy.Expr, known: dict) -> tuple[sympy.Symbol, sympy.Expr] | None:
    """The student's own name a relation's first side defines, and its power: the name itself
    (``s = …``) or a power of it (``ω² = k/(M + m)``, ``v^2 = 2gh``); None where the first side
    is no such name, or the name is known already."""
    p, n = (left.base, left.exp) if left.is_Pow else (left, sympy.Integer(1))
    if not p.is_Symbol or not p.name.startswith(PREFIX) or p in known:
        return None
    return (p, n) if n.is_number and n.is_positive else None


def solved_somewhere(read: list) -> set[sympy.Symbol]:
    """The student's own names some line defines from known values only (``F = 0.80(3010)(9.8)``,
    ``a = F/3010`` once F is so defined): where such a name is first met set equal to other
    unknowns (``F = 3010 a``), that line is a relation to judge with them, not its definition."""
    out: set[sympy.Symbol] = set()
    for _r, _sides, exprs in read + read:  # twice: a name defined after the line that uses it
        name = defined(exprs[0], {}) if len(exprs) > 1 else None
        if name and placeholders(exprs[1]) <= out:
            out.add(name[0])
    return out


def provisional(name: tuple[sympy.Symbol, sympy.Expr], exprs: list, known: dict, later: set) -> bool:
    """Whether a line that seems to define ``name`` only relates it to names not yet known that
    another line defines (see :func:`solved_somewhere`)."""
    unknown = placeholders(exprs[1]) - set(known)
    return bool(unknown) and name[0] in later


def define(
    ctx, name: tuple[sympy.Symbol, sympy.Expr], line: tuple, defs: tuple[Defs, dict], values: dict, number
) -> None:
    """Keep the true and the student's value of a name the line defines (``name``: the name and
    its power on the left; ``line``: the sides and expressions). A power's root is the positive
    one (``ω² = 500``: ω = √500). ``number`` says whether a side is a number as written. A formula
    in a name the student never defines (``ω² = k/M = 20000/40``, M the masses together) is known
    by the first side after it in known names: its working in numbers, as a name defined by numbers
    alone is (``d = (30)(9.81)/20000``)."""
    (p, n), (sides, exprs), (true_defs, own_defs) = name, line, defs
    known = [x for x in exprs[1:] if not placeholders(x.xreplace(true_defs))]
    true = (known[0] if known else exprs[1]).xreplace(true_defs).xreplace(values)
    own = sympy.Rational(sides[-1]) if number(sides[-1]) else exprs[-1].xreplace(own_defs)
    true_defs[p], own_defs[p] = (true, own) if n == 1 else (true ** (1 / n), own ** (1 / n))
    used = set().union(*(x.free_symbols for x in exprs[1:]))
    rounding = literal_tolerance(" = ".join(sides[1:]), ctx.data) + slack_of(true_defs, used)
    if rounding and hasattr(true_defs, "slack"):
        true_defs.slack[p] = float(rounding / n)


def defined_rest(p: sympy.Symbol, line: tuple, state: tuple, number: Callable, worked: list) -> tuple[list, tuple]:
    """The sides after a name's definition (``line``: its expressions and sides; ``state``: the
    true values of the student's names and the slips so far). A name set to a number alone
    (``x = -1``) that no value of the chain's fits is the student's value only, never the truth
    to judge other lines with, before a slip; a number that is two givens' product or quotient
    (``m_A = 0.4658``: 15/32.2, ``worked``; three figures at least) is right, as the relation ``0.4658 = 0.4658``."""
    (exprs, sides), (true_defs, slips) = line, state
    if len(sides) == 2 and number(sides[1]):
        figures = len(sides[1].strip().lstrip("-+").replace(".", "").lstrip("0"))
        if any(float(sympy.Rational(sides[1].strip())) == x for x in worked[0]):  # e = 0: a given restated
            return exprs[1:], sides[1:]
        if figures >= 3 and any(number_at_figures(sides[1], complex(w)) for w in worked[1]):  # not 7.0 = 9.8/1.4
            return [exprs[1], exprs[1]], (sides[1], sides[1])
        if not slips:
            true_defs.pop(p, None)
    return exprs[1:], sides[1:]


def from_givens(ctx) -> list[float]:
    """The givens' values (a stage's too) and 0, and the products and quotients of two of them
    (a mass from a weight: 15/32.2)."""
    parts = [getattr(st, "part", None) for st in getattr(ctx.solution, "stages", ())]
    givens = [g for p in parts if p is not None for g in p.problem.givens] + list(getattr(ctx.problem, "givens", ()))
    xs = [float(g.value) for g in givens if g.value is not None and g.value.is_number]
    return [0.0, *xs], [a * b for a in xs for b in xs] + [a / b for a in xs for b in xs if b]


def judged_later(
    items: list[Item], pending: list[tuple[int, tuple, list]], defs: dict, holds: Callable, wrong: tuple = ((), [])
) -> None:
    """The lines not read for a name of the student's own that a later line defines, judged with
    it: a line that holds is correct (one that does not stays not read: the name may have been
    defined from a slip). ``pending``: each such line's index in ``items``, sides, expressions;
    ``wrong``: the numbers the student got wrong, and the lines of the slips: a line that
    holds worked from one of them (``0.4658(13.90)``, 13.90 wrong) is carried."""
    for k, sides, exprs in pending:
        own = {s for x in exprs for s in x.free_symbols if s.name.startswith(PREFIX)}
        if own and own <= set(defs) and holds(sides, exprs):
            names = ", ".join(sorted(s.name[len(PREFIX) :] for s in own))
            message = f"True for this problem, with {names} as the later lines find it."
            if wrong[1] and set(wrong[0]) & numbers_written(sides, set(), working=True, small=True):
                said = f"Right given the slip in line {wrong[1][0]}: a carried error, not a new mistake."
                items[k] = replace(items[k], status="carried", message=said)
                continue
            items[k] = replace(items[k], status="correct", message=message)


def paired(read: list, found: dict, values: dict, holds: Callable, own: set) -> dict[sympy.Symbol, sympy.Symbol]:
    """Two names of the student's own met only together (``m*v0 = (m+M)*V``, the givens never
    restated as names): the one pair of the chain's values, each of the name's letter, that
    makes the relation hold. ``holds(sides, exprs, subs)``; ``own``: the names the student
    defines (never the chain's)."""
    out: dict[sympy.Symbol, sympy.Symbol] = {}
    for _r, sides, exprs in read:
        subs = {**found, **out}
        names = {s for x in exprs for s in x.xreplace(subs).free_symbols if s.name.startswith(PREFIX)}
        if len(names) != 2 or names & own:
            continue
        p, q = sorted(names, key=str)
        cands = [[v for v, x in values.items() if x.is_number and x != 0 and _letter(v, n)] for n in (p, q)]
        fits = [(a, b) for a in cands[0] for b in cands[1] if a != b and holds(sides, exprs, {**subs, p: a, q: b})]
        if len(fits) == 1 or (fits and fits[0][::-1] in fits):  # ½(m1 + m2)V² = μ(m1 + m2)g d: either way
            out[p], out[q] = fits[0]  # the chain's order: m1 its first mass
    return out


def _letter(value: sympy.Symbol, name: sympy.Symbol) -> bool:
    return value.name[0].lower() == name.name[len(PREFIX)].lower()


def carried_on(item: Item, sides: tuple, exprs: list[sympy.Expr], defs: tuple, holds: Callable, slips: tuple) -> Item:
    """A further slip that holds once each number the student got wrong in it is put back as
    its true value (``8.92 = 4.02(9.81)h`` with 8.92 the student's KE after, 4.478) is carried:
    the rule is right, worked from the wrong number. ``defs``: the true and the student's values
    of the student's names, and the chain's values; ``holds(exprs)``: whether the sides are equal
    for the problem; ``slips``: the slips so far, the carried message of them, and how a side
    is read in the chain's names."""
    (true_defs, own_defs, values), (lines, carried, reread) = defs, slips
    truth = {**values, **{k: v.xreplace(values) for k, v in true_defs.items()}}
    fixed = [_fixed(chainnames.put_back(side, own_defs, truth), reread) for side in sides]
    if all(x is None for x in fixed) or not holds([x if y is None else y for x, y in zip(exprs, fixed, strict=True)]):
        return item
    lines.pop()
    return replace(item, status="carried", message=carried(lines))


def _fixed(text: str | None, reread: Callable) -> sympy.Expr | None:
    try:
        return None if text is None else reread(text)
    except (ParseError, ValueError, TypeError):
        return None
