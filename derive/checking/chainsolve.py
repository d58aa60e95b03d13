"""A chain stage's names as the student has them after a slip, solved from the student's own
relations: the stage's mistaken values give way to what the student's lines make them.

A stage's slip is named by the common mistake whose values make it hold, and those values
are kept as the student's (:mod:`.stageslips`). But a mistake changes every equation of the
stage (B's sign lost changes the momentum and the approach), while the student may have made
it in one only: ``0.9 + 0.4 = 0.3 u_A + 0.2 u_B`` (B's sign lost), then ``u_B - u_A = 0.8(3 + 2)``
right. The student's u_A and u_B are then those two relations solved (1 and 5), and the lines
worked from them are carried, not further slips.
"""

from __future__ import annotations

import sympy

from derive.checking.chainnames import at
from derive.checking.mistakes.outcomes import model as stage_model
from derive.checking.mistakes.records import Mistake, Variant
from derive.checking.slipnames import same_but_number
from derive.errors import InputError


def resolved(
    ctx, exprs: list[sympy.Expr], written: list[list[sympy.Expr]], own: dict, values: dict, names_of: tuple
) -> None:
    """Where the relation ``exprs`` (right for the problem, after a slip) does not hold with the
    student's own values of the chain's names in it, those names solved from it and the latest
    of the student's relations ``written`` before it in the same names, kept in ``own`` (with
    the declared names that are those values: ``names_of`` is the chain's givens and the
    declared names' aliases, x for u_A)."""
    given, alias = names_of
    if len(exprs) < 2:
        return
    named = set(values) | set(alias)  # the chain's names, and the declared ones that are its values
    names = {x for x in exprs[0].free_symbols | exprs[-1].free_symbols if x in own and x in named and x not in given}
    if len(names) < 2:
        return  # one name: own_root's

    def equation(rel: list[sympy.Expr]) -> sympy.Expr | None:
        rest = {k: v for k, v in own.items() if k not in names}
        known = {k: v for k, v in values.items() if k not in names}
        eq = at((rel[0] - rel[-1]).xreplace(rest), known).xreplace(ctx.unit_subs())
        return eq if eq.free_symbols & names and eq.free_symbols <= names else None

    current = equation(exprs)
    if current is None:
        return
    chosen = [current]
    for rel in reversed(written):
        eq = equation(rel)
        if eq is None:
            continue
        try:
            found = sympy.solve([*chosen, eq], sorted(names, key=str), dict=True)
        except (NotImplementedError, ValueError, TypeError):
            return
        if len(found) != 1:
            continue  # inconsistent with the relations chosen (rounded), or no new information
        chosen.append(eq)
        if set(found[0]) == names and not any(x.free_symbols for x in found[0].values()):
            for p, x in found[0].items():
                own.update({p: x, **{q: x for q, k in alias.items() if k == p}})
                if p in alias:
                    own[alias[p]] = x
            return


#: Not a mistake: the stage solved with the student's own values handed on to it.
_OWN = Mistake("own_values", "the student's own values", "", (), "", "", lambda model: None)


def downstream(ctx, own: dict, values: dict, given: set, written: list[list[sympy.Expr]]) -> None:
    """The results of each impact stage that takes a value the student has wrong (B's 5 m/s
    for 3.4 into the wall), solved with the student's value (``w_B`` = -3.5 for -2.38): the
    lines of that stage worked from it are carried. Not a name the student has written a
    value of (``written``: the relations so far)."""
    wrong = {k: v for k, v in own.items() if k in values and k not in given and v != values[k] and v.is_number}
    if not wrong:
        return
    for st in getattr(ctx.solution, "stages", ()):
        part = getattr(st, "part", None)
        if part is None:
            continue
        overrides = {}
        for g in part.problem.givens:
            if g.unknown or g.value is None or not g.value.is_number or g.value == 0:
                continue
            k = next((k for k in wrong if values[k] in (g.value, -g.value)), None)
            if k is not None:
                overrides[g.symbol] = wrong[k] if values[k] == g.value else -wrong[k]
        if overrides:
            _solved_with(st, part, overrides, own, {r[0] for r in written if len(r) > 1 and r[-1].is_number})


def _solved_with(st, part, overrides: dict, own: dict, theirs: set) -> None:
    names = {}
    for eqn in getattr(st, "carried", ()):
        outer, inner = (eqn.sides[0].terms[0], eqn.sides[1].terms[0])
        if isinstance(outer, sympy.Symbol) and isinstance(inner, sympy.Symbol):
            names[sympy.Symbol(outer.name)] = inner.name
    for inner_name, outer_name in getattr(part, "names", {}).items():
        names.setdefault(sympy.Symbol(outer_name), inner_name)
    names = {k: v for k, v in names.items() if k not in theirs}
    if not names:
        return
    try:
        model = stage_model(part)
        out = model.outcome(Variant(values=overrides), _OWN)
    except (InputError, ValueError, TypeError, ArithmeticError, NotImplementedError):
        return
    if out is None:
        return
    post = {u.name: x for u, x in out.post.items()}
    for outer, inner in names.items():
        q = out.results.get(inner)
        x = q.value if q is not None and q.value is not None else post.get(inner)
        if x is not None and x.is_number:
            own[outer] = x


def number_worked(exprs: list[sympy.Expr], previous: list[sympy.Expr]) -> bool:
    """``0.3x + 0.2y = 0.6`` after ``0.3(3) + 0.2(-2) = 0.3x + 0.2y`` (which held): the relation
    just before, its terms kept (up to a factor) and only its number worked wrongly."""
    if len(exprs) < 2 or len(previous) < 2:
        return False
    F, G = exprs[0] - exprs[-1], previous[0] - previous[-1]
    names = tuple(sorted(F.free_symbols, key=str))
    return bool(names) and F.free_symbols == G.free_symbols and same_but_number(F, G, names, {})


def said_in_own(said: dict, true: dict, own: dict, values: dict) -> None:
    """The names declared in words (``KE lost``: ½ m v_1² (1 − e²)) as the student has them,
    worked from the chain's values the student has wrong (their v_1 after a slip in the fall),
    kept in ``own`` where the student has not worked them out otherwise."""
    wrong = {k: v for k, v in own.items() if k in values and v != values[k] and not v.free_symbols}
    for p, x in said.items():
        if wrong and x.free_symbols & set(wrong) and own.get(p, true.get(p)) == true.get(p):
            own[p] = at(x, {**values, **wrong})
