"""Numbers a figure draws a letter at where 1, every other letter's stand-in (:func:`.frame.number`),
would misdraw it: a coefficient of restitution kept as a symbol. The caption names the value."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

import sympy

from derive.problem import Problem

#: The values a coefficient of restitution left as a letter is drawn at, the first that stops no
#: body that e moves (at 1/2, P of edexcel-m2-2015-january-q7, v = u - 2ue, stood still). Drawn
#: as 1, the elastic extreme, equal spheres' A went off along t whatever e
#: (pre-u-9795-2-specimen-q2: v_A2n = sqrt(3)/4 u (1 - e)).
E_DRAWN = tuple(sympy.Rational(k, 10) for k in (5, 6, 4, 7, 3))


def restitution_drawn(
    problem: Problem, known: Mapping, moved: Sequence[object], numbers: Callable[[object, Mapping], float | None]
) -> dict:
    """The letter of a coefficient of restitution kept as a symbol (the given ``e``, or the
    letters it is defined as) that ``known`` does not give, each with the value it is drawn at:
    the first of :data:`E_DRAWN` at which no velocity of ``moved`` (after the impact) that e
    changes is 0. Empty where there is none."""
    letters: set = set()
    for g in problem.givens:
        if g.name == "e" and g.value is None and not g.unknown:
            letters |= g.definition.free_symbols if isinstance(g.definition, sympy.Expr) else {g.symbol}
    letters -= set(known)
    if not letters:
        return {}

    def stops(value: sympy.Rational) -> bool:  # a velocity that e changes is 0 there
        drawn = [numbers(c, {**known, **dict.fromkeys(letters, value)}) for c in moved]
        other = [numbers(c, {**known, **dict.fromkeys(letters, value / 3)}) for c in moved]
        return any(
            d is not None and abs(d) < 1e-9 and o is not None and abs(o) > 1e-9
            for d, o in zip(drawn, other, strict=True)
        )

    return dict.fromkeys(letters, next((v for v in E_DRAWN if not stops(v)), E_DRAWN[0]))
