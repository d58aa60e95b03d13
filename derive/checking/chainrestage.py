"""A habit's name of a body's velocity carried on into the chain's next stage of that body.

Students name a body's velocity once and keep the letter through the chain: ``vB = 5 m/s`` after the
impact of A and B, then ``(b) B rebounds: 0.7 x 5 = 3.5, so vB = -3.5`` at the wall. The rule a teacher
follows: a name's meaning changes only where the student says so or a new stage starts; a name the
habit reads as a body's velocity after one stage (the chain's ``u_B``), set alone to a number and later
set alone again to another number, is from that line on the same body's velocity after the next stage
that body enters (the stage whose velocity before is ``u_B``: its result ``w_B``). A name set twice to
the same number (a value restated) keeps its meaning.
"""

from __future__ import annotations

import sympy

from derive.checking.chainnames import at
from derive.checking.context import Context
from derive.checking.naming import PREFIX
from derive.checking.numeric import number_of


def next_of(ctx: Context, x: sympy.Expr) -> tuple[int, str]:
    """(the sign, the chain's value) of the velocity after the next stage of the body whose velocity
    before it is ``x`` (a velocity the habit reads, in the chain's givens), or (1, "") where none."""
    values = {str(k): v for k, v in ctx.solution.values.items()}
    value = _real(at(x, ctx.solution.values))
    for st in getattr(ctx.problem, "stages", ()):
        if not isinstance(st, dict) or st.get("type") != "impact" or value is None:
            continue
        given, results = st.get("given", {}), st.get("results", {})
        for b in "AB":
            before, after = str(given.get(f"v_{b}1", "")).strip(), str(results.get(f"v_{b}2", ""))
            was = _real(values[before]) if before in values and after in values else None
            if was is not None and abs(abs(was) - abs(value)) <= 1e-9 * max(abs(value), 1.0) and was:
                return (1 if was * value > 0 else -1), after
    return 1, ""


def restaged(ctx: Context, read: list, said: dict) -> tuple[dict, list]:
    """``said`` and ``read`` with each habit's name set alone to a second number read from there on
    as its body's velocity after the next stage (the chain's name of it)."""
    for p, x in list(said.items()):
        k = _second_value(read, p)
        sign, later = next_of(ctx, x) if k is not None else (1, "")
        if not later:
            continue
        q = sign * sympy.Symbol(later)  # the chain's own name from there on
        read = read[:k] + [(r, sides, [e.xreplace({p: q}) for e in exprs]) for r, sides, exprs in read[k:]]
    return said, read


def _second_value(read: list, p: sympy.Symbol) -> int | None:
    """The index of the line that sets ``p`` alone to a number other than the one it was first set to."""
    first = None
    for k, (_r, _sides, exprs) in enumerate(read):
        if len(exprs) < 2 or exprs[0] != p or not p.name.startswith(PREFIX):
            continue
        value = _real(exprs[-1]) if not exprs[-1].free_symbols else None
        if value is None:
            continue
        if first is None:
            first = value
        elif abs(value - first) > 0.01 * max(abs(first), abs(value), 1e-9):
            return k
    return None


def _real(x: sympy.Expr) -> float | None:
    c = number_of(x) if isinstance(x, sympy.Basic) else None
    return c.real if c is not None and abs(c.imag) < 1e-12 else None
