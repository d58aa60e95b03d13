"""A symbolic given the student puts a number for to work with a calculator (``everything has an m in
it so I'm putting m = 1``, ``calculator (quadratic mode, put u = 1): x = 0.8333333333``): their
numbers are then the quantities in units of that given, and a teacher reads them so. derive draws
that given as the number put for it, so the lines hold as they were worked.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

import sympy

if TYPE_CHECKING:
    from derive.checking.context import Context

#: A given put equal to a positive number in words (``put u = 1``, ``putting $m = 1$``, ``set m = 1``).
_PUT = re.compile(r"\b(?:put|putting|set|setting|sub(?:stitut(?:e|ing))?)\s+(?=\$?\s*[A-Za-z]\s*\$?\s*=)", re.I)
#: One given and its number (``m = 1``, ``$u = 1$``; no more digits than a calculator's), and the next after "and" or a comma.
_VALUE = re.compile(r"\$?\s*([A-Za-z])\s*\$?\s*=\s*\$?\s*(\d{1,15}(?:\.\d{1,15})?)(?!\w|\.\d)\$?")
_AND = re.compile(r"\s*(?:,|and|&)\s*", re.I)


def put_values(ctx: Context, text: str) -> dict[sympy.Symbol, sympy.Rational]:
    """The symbolic givens of the problem that ``text`` says it puts a number for -> that number
    (a mass or a speed, never e or an angle; the number positive)."""
    symbolic = {
        g.symbol.name: g.symbol
        for g in ctx.problem.givens
        if g.definition is None and g.symbol not in ctx.numeric and not getattr(g, "unknown", False)
    }
    out: dict[sympy.Symbol, sympy.Rational] = {}
    for put in _PUT.finditer(text):
        at = put.end()
        while (m := _VALUE.match(text, at)) is not None:  # "putting m = 1 and u = 1": both
            s = symbolic.get(m.group(1))
            if s is not None and s.name != "e" and float(m.group(2)) > 0:
                out[s] = sympy.Rational(m.group(2))
            more = _AND.match(text, m.end())
            if more is None:
                break
            at = more.end()
    return out
