"""A result worked with a mistake's masses (the weights, or the masses swapped) from the
velocities as the student has them: named after an earlier slip too.

:func:`~.slipnames.under_results` names a result's line by the value a common mistake gives
it. After an earlier slip the velocities are the student's own, and a result worked with the
weights as masses from them (``J = (47)(3.60 - 0)`` with 47 lb a weight and 3.60 carried from
sin and cos swapped) is the weight's mistake made afresh on the student's values.
"""

from __future__ import annotations

from collections.abc import Callable

from derive.checking import mistakes
from derive.checking.context import Context
from derive.checking.mistakes import Mistake
from derive.checking.worlds import Pair


def masses_in_results(ctx: Context, bad: Pair, holds_with: Callable[[dict], bool]) -> list[Mistake]:
    """The mistakes of the masses (the weights as masses, the masses swapped) whose masses in the
    results on the line, worked from the velocities after as the judge has them and the values
    before as they are or as a mistake has them (an earlier slip's), make ``bad`` hold
    (``holds_with``: whether it holds with those values put in):
    ``J = (47)(3.60 - 0)`` with 47 lb a weight, 3.60 carried from sin and cos swapped."""
    model = ctx.model
    built = [(m, v) for m in mistakes.REGISTRY.values() if (v := m.build(model)) is not None]
    pres = [{}] + [dict(v.pre) for _m, v in built if v.pre]
    found = []
    for m, v in built:
        subs = dict(v.values) | ({model.m_A: v.masses[0], model.m_B: v.masses[1]} if v.masses else {})
        if not subs.keys() & {model.m_A, model.m_B}:
            continue
        for pre in pres:
            given = {**subs, **pre}
            results = {sym: x.xreplace(given) for sym, x in ctx.derived().values()}
            if holds_with({**results, **given}):
                found.append(m)
                break
    return found
