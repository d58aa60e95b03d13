"""A chain's line after a slip judged in the student's own world: the values the student's own
relations since the slip give the chain's unknowns.

After ``v2 = 3.5 + 7e`` (a slip: both terms should be halved) and ``8 = v2(1 + e)`` (right), the
student's ``(3.5 + 7e)(1 + e) = 8`` is false for the problem and for the problem's e, yet it is
what the student's two relations give: the slip carried, not a new mistake. The student's
relations from the first slip on (the latest first) are solved for the chain's unknowns until
they fix those of the line; a line that holds at one of those values is carried, and the values
are kept as the student's for the lines after it.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace

import sympy

from derive.checking.chainnames import at
from derive.checking.chainsteps import from_wrong_step, rounded_on
from derive.checking.numeric import number_of
from derive.checking.report import Item
from derive.errors import InputError
from derive.problem.expr import ParseError

#: At most this many of the student's relations are solved together (each solve is SymPy's).
_MOST = 4


def own_world(ctx, item: Item, line: tuple, done: tuple, defs: tuple, how: tuple[Callable, Callable]) -> Item:
    """``item`` (a further slip after the first) as carried where it holds in the student's own
    world (see the module's words), or once each number the student worked wrongly is put back
    as its true value; ``line``: its sides and expressions; ``done``: the items judged so far,
    their relations and the slips' lines; ``defs``: the chain's values, the declared names' true
    values and the student's own; ``how``: ``holds(exprs, subs)``, whether the relation holds
    with ``subs`` (the student's values first, then the chain's), and ``reread(side)``."""
    (sides, exprs), (holds, reread) = line, how
    items, written, slips = done
    values, true_defs, own_defs, _stages = defs
    if item.status == "wrong" and slips == [item.name]:  # the first slip: d = 15.34^2/25.76, 15.34 for 15.3325
        item = rounded_on(item, (sides, exprs), (values, _known(ctx, values), true_defs, own_defs), how, slips)
    if item.status != "wrong" or len(slips) < 2 or slips[-1] != item.name:
        return item
    first = next((k for k, it in enumerate(items) if it.status == "wrong"), None)
    known = _known(ctx, values)
    names = {str(k) for k in values if k not in known} | {str(p) for p in true_defs}
    if first is None:
        return item
    base = _conditions(ctx, values, known) + _aliases(true_defs, values, known)
    worlds = _worlds(ctx, written[first:], base, known, names) if _unknowns(exprs, known, names) else []
    for world in worlds:
        if holds(exprs, [{**own_defs, **world}, values]):
            own_defs.update(world)
            return _carried(item, slips)
    later = later_stages(ctx, own_defs, values, known)  # h_2 from the student's V: the rise worked from it
    if later and holds(exprs, [{**later, **own_defs}, values]):
        return _carried(item, slips)
    if from_wrong_step(sides, exprs, written, (values, true_defs), (holds, reread)):  # sqrt(25 + 3.136)
        return _carried(item, slips)
    fixed = _put_right(sides, own_defs, values, reread)
    if fixed is not None and holds(fixed, [true_defs, values]):  # 900 = 4.02(9.81)h, 900 the student's KE after
        return _carried(item, slips)
    return item


def later_stages(ctx, own_defs: dict, values: dict, known: dict) -> dict[sympy.Symbol, sympy.Expr]:
    """The chain's values with its stages run again, each value the student has wrong (a result,
    not a given) put in as the student has it once its stage has found it: the later stages'
    values worked from the student's (h_2 = V^2/(2g) with the student's V); {} where none is
    wrong or the chain does not run so."""
    from derive.physics.chain import STAGES
    from derive.physics.state import ChainState

    wrong = {
        str(k): v for k, v in own_defs.items() if k in values and k not in known and v.is_number and v != values[k]
    }
    chain = getattr(ctx.solution, "problem", None)
    if not wrong or chain is None or not hasattr(chain, "stages"):
        return {}
    state = ChainState(chain)
    try:
        for i, st in enumerate(chain.stages, 1):
            STAGES[st["type"]](state, i, st)
            for name, v in wrong.items():
                g = state.known.get(name)
                if g is not None and g.value is not None and g.value != v:
                    state.known[name] = replace(g, value=v)
        out = {g.symbol: state.value(g.symbol) for g in state.known.values()}
    except (InputError, ValueError, TypeError, ArithmeticError, KeyError, IndexError):
        return {}
    by_name = {str(k): k for k in values}
    return {by_name[str(s)]: v for s, v in out.items() if str(s) in by_name and v.is_number and str(s) not in wrong}


def _carried(item: Item, slips: list[str]) -> Item:
    slips.pop()
    message = f"Right given the slip in line {slips[0]}: a carried error, not a new mistake."
    return replace(item, status="carried", message=message)


#: A number as written: whole or decimal.
_NUMBER = re.compile(r"(?<![\w.])\d+(?:\.\d+)?(?![\w.]|\.\d)")


def _put_right(sides, own_defs: dict, values: dict, reread: Callable) -> list[sympy.Expr] | None:
    """The sides with each number the student worked wrongly (a chain value the student has
    otherwise, as written: 900 for a KE of 4.48) put back as its true value, read again; None
    where none is in them or they do not read."""
    wrong = {}
    for k, v in own_defs.items():
        true = values.get(k)
        if (
            true is not None
            and v.is_number
            and true.is_number
            and abs(float(v) - float(true)) > 1e-9 * abs(float(true))
        ):
            wrong[float(v)] = true
    found = False

    def true_of(m: re.Match) -> str:
        nonlocal found
        x, half = float(m.group(0)), 0.5 * 10 ** -len(m.group(0).partition(".")[2])
        hit = next((t for v, t in wrong.items() if v and abs(v - x) <= half), None)
        if hit is None:
            return m.group(0)
        found = True
        return f"({sympy.N(hit, 15)})"

    texts = [_NUMBER.sub(true_of, s) for s in sides]
    if not found:
        return None
    try:
        return [reread(t) for t in texts]
    except (ParseError, ValueError, TypeError, ArithmeticError):
        return None


def _known(ctx, values: dict) -> dict[sympy.Symbol, sympy.Expr]:
    """The chain's givens that have a value (not those it solves for, ``e = ?``)."""
    given = {g.name for g in getattr(ctx.problem, "givens", ()) if not g.unknown}
    return {k: v for k, v in values.items() if str(k) in given}


def _aliases(true_defs: dict, values: dict, known: dict) -> list[sympy.Expr]:
    """A declared name that is one of the chain's unknowns (``v2``, B's velocity after, is u_B):
    the two the same in the student's world too (``v2 - u_B``)."""
    out = []
    for p, x in true_defs.items():
        v = number_of(x)
        for k, w in values.items():
            u = number_of(w) if k not in known else None
            if v is not None and u is not None and abs(v - u) <= 1e-9 * max(1.0, abs(u)):
                out.append(p - k)
                break
    return out


def _equation(ctx, rel: list[sympy.Expr], known: dict) -> sympy.Expr | None:
    if len(rel) < 2 or any(x is None for x in rel):
        return None
    eq = at(rel[0] - rel[-1], known).xreplace(ctx.unit_subs())
    return eq if eq.free_symbols else None


def _unknowns(exprs: list[sympy.Expr], known: dict, names: set[str]) -> set[sympy.Symbol]:
    """The unknowns in a relation (empty where it has a name neither the chain's nor declared)."""
    found = set().union(*(x.free_symbols for x in exprs)) - set(known)
    return found if found and all(str(s) in names for s in found) else set()


def _worlds(ctx, rels: list, base: list[sympy.Expr], known: dict, names: set[str]) -> list[dict]:
    """The real values of the unknowns the student's relations ``rels`` fix with ``base`` (the
    latest first; one that contradicts those chosen, as rounded numbers do, or adds nothing, is
    passed over)."""
    chosen: list[sympy.Expr] = list(base)
    before = None
    for rel in reversed(rels):
        eq = _equation(ctx, rel, known)
        if eq is None or len(chosen) >= len(base) + _MOST or not _unknowns([eq], known, names):
            continue
        symbols = sorted(set().union(*(x.free_symbols for x in [*chosen, eq])), key=str)
        try:
            found = sympy.solve([*chosen, eq], symbols, dict=True)
        except (NotImplementedError, ValueError, TypeError, ArithmeticError):
            return []
        if not found or (before is not None and found == before):
            continue
        chosen.append(eq)
        before = found
        fixed = [s for s in found if all(v.is_number for v in s.values()) and len(s) == len(symbols)]
        if fixed and len(fixed) == len(found):
            return [s for s in fixed if all(v.is_real is not False for v in s.values())]
    return []


def _conditions(ctx, values: dict, known: dict) -> list[sympy.Expr]:
    """The conditions the chain's solve stages set (``u_C = v_C``: C leaves at the given 4 m/s),
    the givens put in: facts of the problem, so of the student's world too."""
    by_name = {str(k): k for k in values}
    out = []
    for st in getattr(getattr(ctx.solution, "problem", None), "stages", ()):
        text = st.get("condition") if isinstance(st, dict) else None
        if not isinstance(text, str) or text.count("=") != 1:
            continue
        try:
            left, right = (sympy.sympify(t, locals=dict(by_name)) for t in text.split("="))
        except (sympy.SympifyError, TypeError, ValueError, SyntaxError):
            continue
        eq = at(left - right, known).xreplace(ctx.unit_subs())
        if eq.free_symbols and all(str(s) in by_name for s in eq.free_symbols):
            out.append(eq)
    return out


def student_values(ctx, rels: list, values: dict, true_defs: dict) -> dict[sympy.Symbol, sympy.Expr]:
    """The chain's unknowns as the student's relations ``rels`` (from the first slip on) fix them,
    where they fix them one way only; {} otherwise."""
    known = _known(ctx, values)
    names = {str(k) for k in values if k not in known} | {str(p) for p in true_defs}
    base = _conditions(ctx, values, known) + _aliases(true_defs, values, known)
    worlds = _worlds(ctx, rels, base, known, names)
    return worlds[0] if len(worlds) == 1 else {}
