"""The ``define`` stage (a quantity from others) and the ``solve`` stage (an unknown of
the chain, a given marked "?", from a condition such as ``h_2 = 40 m``)."""

from __future__ import annotations

from dataclasses import dataclass, replace

import sympy

from derive.errors import ExpressionError, SolveError
from derive.physics.state import ChainState, StageOutcome
from derive.problem import Given, units
from derive.problem.expr import Parsed, ParseError, parse


@dataclass(frozen=True)
class Definition:
    """``result = expr``, with ``text`` the file's sentence before it."""

    expr: sympy.Expr
    value: sympy.Expr
    result: Given
    text: str


@dataclass(frozen=True)
class Condition:
    """``lhs = rhs`` fixing the unknown ``given``: ``in_unknown`` is lhs in the unknown
    (with every number known so far), ``root`` its one admissible value out of
    ``roots`` found; ``updated`` the
    earlier quantities that depended on the unknown, each with its number now."""

    lhs: sympy.Expr
    rhs: sympy.Expr
    given: Given
    root: sympy.Expr
    in_unknown: sympy.Expr | None = None
    roots: int = 1
    lhs_unit: str | None = None
    updated: tuple[tuple[Given, sympy.Expr, sympy.Expr], ...] = ()


def define(state: ChainState, i: int, st: dict) -> StageOutcome:
    """A new quantity ``result = expr`` from known ones."""
    raw = st.get("expr")
    expr = state.quantity(i, st, "expr", None)
    dim = parse(str(raw), state.names(), state.chain.system).dim
    out = state.define(i, st.get("result", f"q_{i}"), expr, dim)
    data = Definition(expr, state.value(expr), out, str(st.get("text", "Then:")))
    return StageOutcome(i, "define", st.get("title", "Then"), data, (out.name,))


def solve(state: ChainState, i: int, st: dict) -> StageOutcome:
    """The one unknown (``for``, or the only one left) from ``condition``: its one admissible root."""
    raw = st.get("condition")
    if not isinstance(raw, str) or raw.count("=") != 1:
        raise state.err(i, "condition", 'expected one equation such as "h_2 = 40 m"', raw)
    left, right = raw.split("=")
    try:
        lhs = parse(left.strip(), state.names(), state.chain.system)
        rhs = parse(right.strip(), state.names(), state.chain.system)  # a number may carry its unit
        rhs_expr = _same_kind(lhs, rhs)
    except (ParseError, ValueError) as exc:
        raise state.err(i, "condition", str(exc), raw, ExpressionError) from None
    target = st.get("for")
    unknown = [u for u in state.unknowns if u not in state.solved and (target is None or u.name == target)]
    if len(unknown) != 1:
        raise state.err(i, "for", 'expected exactly one unknown (a given marked "?") to solve for', target)
    u = unknown[0]
    in_unknown = state.value(lhs.expr)
    # the right side in its numbers too (h_2 = h_0: the roots are numbers, each checked)
    found = sympy.solve(in_unknown - state.value(rhs_expr), u)
    roots = [r for r in found if admissible(state, u, r)]
    if len(roots) != 1:
        listed = f" ({', '.join(_shown(state.value(r)) for r in roots)})" if roots else ""
        if not roots and found:  # say what the equation gave, so that a sign or unit slip shows
            listed = f" (its roots {', '.join(_shown(state.value(r)) for r in found)} are not physical)"
        elif not found:
            listed = f" (it has no root{f' with {u.name} ≥ 0' if u.is_nonnegative else ''}: check the signs and units)"
        hint = "; the data do not choose between them: give one more value" if len(roots) > 1 else ""
        raise SolveError(
            f"stage {i}: {raw} gives {len(roots)} admissible values of {u.name}{listed}{hint}", where=state.chain.path
        )
    waiting = {n: state.value(g.symbol) for n, g in state.known.items() if g.value is None and g.definition is not None}
    state.solved[u] = roots[0]
    updated = []
    for name, before in waiting.items():
        now = state.value(before)
        if before.has(u) and not now.free_symbols:
            state.known[name] = replace(state.known[name], value=now)
            updated.append((state.known[name], before, now))
    g = state.known[u.name]
    system = units.SYSTEMS[state.chain.system]
    lhs_unit = units.working_unit(lhs.dim, state.chain.system).text if lhs.dim in system else None
    data = Condition(lhs.expr, rhs_expr, g, roots[0], in_unknown, len(found), lhs_unit, tuple(updated))
    return StageOutcome(i, "solve", f"Solve for {u.name}", data, (u.name,))


def _same_kind(lhs: Parsed, rhs: Parsed) -> sympy.Expr:
    """The right side of a condition in the left side's working unit: a number with a unit of
    another kind is an error; a bare number is in the working unit (an angle's in degrees,
    unless written in pi)."""
    if rhs.dim == lhs.dim or rhs.expr == 0:
        return rhs.expr
    if rhs.dim != units.DIMENSIONLESS or rhs.expr.free_symbols:
        raise ParseError(f"compares {units.describe(lhs.dim)} with {units.describe(rhs.dim)}")
    if lhs.dim == units.ANGLE and not rhs.expr.has(sympy.pi):
        return rhs.expr * sympy.pi / 180
    return rhs.expr


def _shown(v: sympy.Expr) -> str:
    """A root as a reader would quote it: 4 figures where it is a number."""
    return f"{float(sympy.N(v)):.4g}" if v.is_number and v.is_real else str(v)


def admissible(state: ChainState, u: sympy.Symbol, r: sympy.Expr) -> bool:
    """A root is admissible when real, e in [0, 1], a speed not negative, and every
    impact of the chain still has its bodies approaching."""
    for approach in state.approaches:
        a = state.value(approach).xreplace({u: r})
        if not a.free_symbols and not complex(sympy.N(a)).real > 0:
            return False
    v = state.value(r)
    if v.free_symbols:
        return True
    c = complex(sympy.N(v))
    if abs(c.imag) > 1e-12:
        return False
    if u.name.startswith("e") and not (-1e-12 <= c.real <= 1 + 1e-12):
        return False
    return not ((u.is_positive or u.is_nonnegative) and c.real < 0)
