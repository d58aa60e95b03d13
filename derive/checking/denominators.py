"""A term brought over a fraction's denominator without being multiplied by it: algebra.

``(11 − 7e)u/3 + 7eu = 11u/3`` (the 7eu put over the 3 as it is: ``(11 − 7e + 7e)u/3``),
``x/4 + 2 = (x + 2)/4``: the terms of a sum put over one denominator, one of them not
multiplied up. The step treats one term unlike the others, which is how the corpus's
teachers name a slip ``algebra`` (docs/checking.md, "Naming a slip"); a number of such a
sum worked wrongly, every term alike, stays ``arithmetic``.
"""

from __future__ import annotations

import sympy

from derive.checking.worlds import Pair

#: The most terms of a side tried (each term over each other term's denominator once).
MAX_TERMS = 6


def _denominator(term: sympy.Expr) -> sympy.Expr:
    """The term's denominator as written (``(10 − 15e)u/5``: 5, not cancelled into the bracket)."""
    return term.as_numer_denom()[1]


def _same(a: sympy.Expr, b: sympy.Expr) -> bool:
    d = sympy.expand(a - b)
    return d == 0 or sympy.simplify(d) == 0


def term_not_multiplied(bad: Pair) -> bool:
    """Whether one side of ``bad`` (a false pair, its sides as written) is the other with one
    term of its sum divided by another term's denominator: that term taken over the common
    denominator without being multiplied by it."""
    if bad.raw is None or len(bad.raw) != 2:
        return False
    for i in (0, 1):
        side, other = bad.raw[i], bad.raw[1 - i]
        terms = sympy.Add.make_args(side)
        if not 2 <= len(terms) <= MAX_TERMS:
            continue
        below = [_denominator(t) for t in terms]
        for t, own in zip(terms, below, strict=True):
            for k in {d for d in below if d != 1 and d != own}:
                if _same(side - t + t / k, other):
                    return True
    return False
