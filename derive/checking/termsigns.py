"""A sign lost collecting terms in letters, named as a teacher names it: algebra.

``x = u + ue − 3ue = u(1 − 4e)`` (the +ue taken as −ue) and ``y = 3u − 2eu + 5eu = 3u + 7eu``
(the −2eu added as +2eu) are false at the sample points of the givens, where the letters have
become numbers, so the rules for a side of numbers would call them arithmetic. A teacher calls
them algebra: the working side, read again with exactly one of its terms as typed given the
other sign, is the side it was set equal to. A number of the collected terms worked wrongly
otherwise (``2u + 2eu − 5eu = 2u + 3eu``: the answer's sign; ``(u + 2eu)/3 − eu = u(1 − 5e)/3``:
a sign inside a bracket) stays arithmetic, and a line of numbers only is never this.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.naming import Open, read_side, rewrite
from derive.checking.worlds import Pair
from derive.mathtext.notation import student
from derive.problem.expr import ParseError

#: The most terms a working side is tried with (each flipped once): bounded.
MAX_TERMS = 8


def signs(text: str) -> list[int]:
    """Where each term of ``text`` after the first starts, as typed: a ``+`` or ``-`` at the top
    level of the side (not inside a bracket, an exponent, a product or a number's exponent)."""
    out, depth, last = [], 0, ""
    for i, ch in enumerate(text):
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif depth == 0 and ch in "+-" and last and last not in "(*/^=" and not re.search(r"\d[eE]\s*$", text[:i]):
            out.append(i)
        if not ch.isspace():
            last = ch
    return out


def _flipped(text: str) -> list[str]:
    """``text`` with each of its top-level terms in turn given the other sign."""
    out = [text[1:] if text.startswith("-") else "-" + text if not text.startswith("+") else "-" + text[1:]]
    for i in signs(text):
        out.append(text[:i] + ("-" if text[i] == "+" else "+") + text[i + 1 :])
    return out


def _read(ctx, text: str) -> sympy.Expr | None:
    known = {n: s for n, (s, _d) in ctx.equation_names().items()}
    try:
        return read_side(text, Open(known), False, False)
    except (ParseError, ValueError, TypeError, KeyError, RecursionError):
        return None


def _same(a: sympy.Expr, b: sympy.Expr) -> bool:
    d = sympy.expand(a - b)
    return d == 0 or sympy.simplify(d) == 0


def sign_lost(ctx, bad: Pair) -> bool:
    """Whether ``bad``, a false pair in the givens' letters (no unknowns), holds with exactly one
    of the terms of its first side (the working, as typed) given the other sign."""
    if bad.raw is None or not bad.raw[0].free_symbols or not bad.raw[1].free_symbols:
        return False
    sides = bad.text.split(" = ")
    if len(sides) != 2:
        return False
    known = {n for n in ctx.equation_names()}
    working = student(rewrite(sides[0], known)).strip()
    if not 1 <= len(signs(working)) < MAX_TERMS:
        return False
    left = _read(ctx, working)
    if left is None or not _same(left, bad.raw[0]):
        return False  # not read again as it was: nothing said
    found = [x for x in (_read(ctx, t) for t in _flipped(working)) if x is not None and _same(x, bad.raw[1])]
    return len(found) == 1
