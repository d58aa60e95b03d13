"""A result worked from values the student got wrong: the student's own value of it.

``E_k after = E_k before − ΔE_k = 91.9 − 91.5 = 0.4`` after ``ΔE_k = ½ m (v − v')² = 91.5``
(a wrong formula) works the energy after from the wrong loss. Its first side is a result of
the problem (T_2), whose true value the line cannot come to; the rest of it, with the values
the student got wrong put in, holds. Such a line is carried, and its number is the student's
own value of the result for the lines after (as a wrong line's is, :meth:`.carrying.Carrying._own_value`).
"""

from __future__ import annotations

from dataclasses import replace

import sympy


def worked_from_own(trace, line, exprs: tuple[sympy.Expr, ...]) -> bool:
    """Whether ``line`` (its ``exprs`` with the student's own values put in) names a result on
    its first side and its other sides, which use an own value, hold; if so the result's value
    as the line ends is the student's own."""
    first = line.exprs[0] if line.exprs else None
    results = {s for s, _x in trace.ctx.derived().values()}
    if not isinstance(first, sympy.Symbol) or first not in results or first in trace.own or len(exprs) < 3:
        return False
    if exprs[1:] == tuple(line.exprs[1:]):
        return False  # nothing the student got wrong is worked on: not carried from it
    if any(first in x.free_symbols for x in exprs[1:]):
        return False
    said = {n: x for n, x in trace.said.items() if x.is_number}  # the results as the student said them
    rest = replace(line, sides=line.sides[1:], exprs=tuple(x.xreplace(said) for x in exprs[1:]))
    if not trace.holds(trace.pairs(rest), trace.world or trace.truth):
        return False
    value = exprs[-1]
    if value.is_number:
        trace.own[first] = value
    return True
