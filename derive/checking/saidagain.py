"""A value of the student's own said again: ``J = 0.060(14.7) - 0.060(-14.7) = 1.76 N s`` worked
on one line, then ``So J ≈ 1.76 N s, away from the wall`` on a later one. Nothing gave ``J`` a
meaning (no declaration, habit or inference), so the first line is judged by its working alone; the
later line restates the number it came to, and a teacher marks it as that number: right where the
working was right, carried where it was built on a slip. It is read with the name as that number.
"""

from __future__ import annotations

from dataclasses import replace

import sympy

from derive.checking.naming import PREFIX, placeholders


def said_again(raw: list, mapping: dict[sympy.Symbol, sympy.Expr]) -> None:
    """Read each line ``NAME = number`` whose NAME an earlier line worked out to a number (``NAME
    = … = number``, in numbers only) with NAME as that number (``raw`` changed in place)."""
    worked: dict[sympy.Symbol, sympy.Expr] = {}
    for i, r in enumerate(raw):
        exprs = r.exprs
        if exprs is None or r.defines or not _own(exprs[0], mapping):
            continue
        rest = exprs[1:]
        if any(placeholders(e) or e.free_symbols for e in rest):
            continue
        if len(exprs) >= 3 and exprs[0] not in worked:
            worked[exprs[0]] = rest[-1]
        elif len(exprs) == 2 and exprs[0] in worked:
            raw[i] = replace(r, exprs=(worked[exprs[0]], rest[0]))


def _own(e: sympy.Expr, mapping: dict) -> bool:
    return isinstance(e, sympy.Symbol) and e.name.startswith(PREFIX) and e not in mapping
