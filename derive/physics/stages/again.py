"""The ``again`` stage: will the body behind (at smaller n) and the one ahead collide
again? Yes when the one behind moves faster along +n; with ``range_of``, for which
values of a coefficient they do."""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from derive.physics.asks import drop_positive
from derive.physics.state import ChainState, StageOutcome, resolve
from derive.problem import units


@dataclass(frozen=True)
class Again:
    """``behind - ahead`` and its value; the verdict (None while a symbol remains);
    with ``range_of``, the separation ``general`` as a function of ``param`` and the
    ``interval`` of it in [0, 1] for which they collide again."""

    behind: sympy.Expr
    ahead: sympy.Expr
    difference: sympy.Expr
    verdict: bool | None = None
    param: sympy.Symbol | None = None
    general: sympy.Expr | None = None
    interval: sympy.Set | None = None


def again(state: ChainState, i: int, st: dict) -> StageOutcome:
    """Compare the velocities along +n of the body behind and the one ahead."""
    va = state.quantity(i, st, "behind", units.VELOCITY)
    vb = state.quantity(i, st, "ahead", units.VELOCITY)
    diff = state.value(va) - state.value(vb)
    outputs = []
    verdict = None
    if not diff.free_symbols:
        verdict = bool(diff > 0)
        flag = sympy.Integer(int(verdict))
        g = state.define(i, st.get("result", "again"), flag, units.DIMENSIONLESS, "")
        outputs.append(g.name)
    data = Again(va, vb, diff, verdict)
    param = st.get("range_of")
    if param is not None:
        p = state.known.get(param)
        if p is None or p.dim != units.DIMENSIONLESS:
            raise state.err(i, "range_of", "expected the name of a known coefficient such as e", param)
        defs = {g.symbol: g.definition for g in state.known.values() if g.definition is not None and g.name != param}
        general = resolve(va - vb, defs)
        keep = {g.symbol: g.value for n, g in state.known.items() if g.value is not None and n != param}
        general = sympy.simplify(general.xreplace(keep).xreplace(state.solved))
        letters = {n: g.symbol for n, g in state.known.items() if g.value is None}
        general = general.xreplace({s: letters[s.name] for s in general.free_symbols if s.name in letters})
        reduced, _ = drop_positive(sympy.factor(general), p.symbol)  # a speed u > 0 does not change the sign
        try:
            rng = sympy.solve_univariate_inequality(reduced > 0, p.symbol, relational=False)
        except (NotImplementedError, ValueError, TypeError):
            raise state.err(
                i, "range_of", "the range depends on other letters and cannot be worked out", param
            ) from None
        interval = rng.intersect(sympy.Interval(0, 1))
        data = Again(va, vb, diff, verdict, p.symbol, general, interval)
        if verdict is None:  # the answer is the range: named, so that find and the JSON have it
            relation = interval.as_relational(p.symbol)
            if relation in (sympy.true, sympy.false):  # for every value of e, or for none: yes or no
                relation = sympy.Integer(int(bool(relation)))
            g = state.define(i, st.get("result", "again"), relation, units.DIMENSIONLESS, "")
            outputs.append(g.name)
    return StageOutcome(i, "again", st.get("title", "Will they collide again?"), data, tuple(outputs))
