"""A given copied wrongly, put back where the student used it: alone, and in a total with
another given (a bullet of 0.020 kg copied as 0.20 with a 4.0 kg block: ``0.20 x 300 = 4.20 V``,
the 4.20 being the copied mass and the block's together). A teacher sees one slip, the given
copied; the line holds once it is put back in both places."""

from __future__ import annotations

import re
from dataclasses import replace

import sympy

from derive.errors import InputError

#: A number as a student writes it in working.
NUMBER = re.compile(r"(?<![\w.])\d+(?:\.\d+)?(?![\w.]|\.\d)")


def put_back(sides: tuple[str, ...], i: int, token: str, value: str, givens: set) -> list[str]:
    """``sides`` with the number ``token`` of side ``i`` written as the given's ``value``, and
    each number of the other sides that is ``token`` plus another of the ``givens`` (a total
    mass) written as ``value`` plus that given."""
    n, v = sympy.Rational(token), sympy.Rational(value)
    fixed = list(sides)
    fixed[i] = NUMBER.sub(lambda m: value if m.group(0) == token else m.group(0), sides[i])
    totals = {n + h: v + h for h in givens if h and h != v}

    def total(m: re.Match) -> str:
        x = sympy.Rational(m.group(0))
        return f"({sympy.N(totals[x], 15)})" if x in totals else m.group(0)

    for k, side in enumerate(sides):
        if k != i:
            fixed[k] = NUMBER.sub(total, side)
    return fixed


def solved_with(chain, name: str, value: sympy.Expr) -> dict | None:
    """The chain's values with the given ``name`` as ``value`` (None where it does not solve)."""
    from derive.physics.chain import run_chain

    givens = tuple(replace(g, value=value) if g.name == name else g for g in chain.givens)
    try:
        return dict(run_chain(replace(chain, givens=givens)).values)
    except (InputError, ValueError, TypeError, ArithmeticError, KeyError, IndexError):
        return None
