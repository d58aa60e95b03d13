"""A chain's givens in letters, as a student multiplies them by a name of their own.

``7m = ma + mb`` on a chain whose particles all have mass ``m`` (a given with no number) is
m times a plus m times b: ``m`` is a letter the student may write beside another one. Such a
letter is read as one mass that is not a number a student writes (√2): the chain's results do
not depend on it, a relation that holds for every mass holds for it, and it is never the student's
own name to infer (as 0, which made any relation with m in every term hold).
"""

from __future__ import annotations

import re

import sympy

from derive.checking.chainnames import lone_restitution
from derive.checking.context import Context
from derive.checking.naming import Open


def given_letters(ctx: Context, values: dict[sympy.Symbol, sympy.Expr]) -> dict[str, sympy.Expr]:
    """The chain's single-letter givens with no number (``m``), each as a value no student writes."""
    named = {s.name for s in values}
    return {
        g.name: sympy.sqrt(2)  # any mass: the chain's results do not depend on it
        for g in getattr(ctx.problem, "givens", ())
        if g.value is None and not g.unknown and re.fullmatch(r"[A-Za-z]", g.name) and g.name not in named
    }


def chain_names(ctx: Context, values: dict[sympy.Symbol, sympy.Expr]) -> Open:
    """The names a chain's sides may use: its values' (``e`` for ``e_floor`` too) and its letters; the
    word impulse (``∫F dt`` read so) inside a side, a name of the student's own, inferred by value."""
    known = {**given_letters(ctx, values), **lone_restitution(values), **{s.name: s for s in values}}
    return Open(known, {"impulse"})
