"""A sign lost inside a formula: a line that holds with one sign changed deep in it is ``algebra``.

A compound-angle formula written ``tan(φ - 30°) = (tan φ - tan 30°)/(1 - tan φ tan 30°)``
has the sign in its denominator wrong: the line holds for the problem once that one term's
sign is changed. :func:`~.slipnames.sign_flipped` looks at the terms of the sides only; this
looks inside every sum of a side (a numerator, a denominator, a bracket), and names the line
``algebra`` (a sign lost in the algebra) where exactly one term in letters, changed in sign,
makes it hold. A line of numbers only, or a term of the given velocities only, is not named
so (its slip is arithmetic or a velocity's sign, named elsewhere).
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import sympy

from derive.checking.carried import sides
from derive.checking.context import DEG

#: What a report says of a line that holds with one sign inside it changed.
WORDS = ": it holds with the sign of one term inside it changed (a slip in the algebra: a sign lost)."
#: At most this many sums are tried in a side (a long line is not searched).
MOST = 12


def sign_inside(trace: Any, line: Any, item: Any) -> Any:
    """``item`` named ``algebra`` where ``line`` (two sides, in letters) holds with the sign of
    exactly one term in letters inside one of its sums changed; ``item`` otherwise."""
    if item.status != "wrong" or item.slip or item.again or line.exprs is None or len(line.sides) != 2:
        return item
    p = sides(trace, line, 0, 1)
    if p.raw is None or not any(x.free_symbols - {DEG} for x in p.raw):
        return item
    world = trace.world if trace.world is not None else trace.truth
    velocities = {g.symbol for g in trace.ctx.problem.givens if g.name[:1] in "uvw" and g.value is not None}
    found = 0
    for i, side in enumerate(p.raw):
        sums = [a for a in sympy.preorder_traversal(side) if a.is_Add][:MOST]
        for s in sums:
            for t in s.args:
                if not (t.free_symbols - {DEG} - velocities):  # numbers, or a velocity given: b_sign's
                    continue
                raw = list(p.raw)
                raw[i] = side.xreplace({s: s - 2 * t})
                try:
                    left, right = (trace.ctx.in_unknowns(x) for x in raw)
                    ok = trace.holds([replace(p, left=left, right=right, raw=(raw[0], raw[1]))], world)
                except (TypeError, ValueError, ArithmeticError, ZeroDivisionError):
                    ok = False
                found += bool(ok)
    if found != 1:
        return item
    lead = item.message.split(":")[0].split(". No common mistake")[0].rstrip(".")
    return replace(item, slip="algebra", message=f"{lead}{WORDS}")
