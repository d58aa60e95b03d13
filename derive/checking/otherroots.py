"""Lines a teacher does not mark: the other root of a quadratic, and a value the line rejects.

``(6x - 5u)(2x - u) = 0 so x = 5u/6 or x = u/2``: the student gives both roots, and the one that
is not the answer is no slip (the next lines choose between them). ``If x = 5u/6 then y = u/3,
slower than P ... Reject.``: a value tried and rejected is not marked either. Either relation is
left out where it is false for the problem (and for the slips so far); a true one is still judged.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

import sympy

from derive.mathtext.latex import REJECTED

_OR = re.compile(r"(?<![\w\\])or(?![\w])", re.I)


def not_marked(trace: Any, line: Any, lines: Sequence[Any], typed: list[str]) -> bool:
    """Whether ``line`` (a :class:`~.inference.Read` of ``trace``'s derivation) is a root given
    beside another for the same name on an "or" line, or a value on a line that rejects it after
    such roots, and false where the other root (or nothing) holds."""
    if line.exprs is None or line.defines or len(line.exprs) != 2 or not 0 < line.number <= len(typed):
        return False
    siblings = _siblings(line, lines, typed)
    rejected = REJECTED.search(typed[line.number - 1]) is not None and any(
        _siblings(r, lines, typed) for r in lines if r.number <= line.number
    )
    if not (siblings or rejected) or _holds(trace, line) or not _quadratic_before(trace, line, lines):
        return False
    return rejected or any(_holds(trace, r) for r in siblings)


def _quadratic_before(trace: Any, line: Any, lines: Sequence[Any]) -> bool:
    """Whether a relation up to ``line`` is of degree two or more in the unknowns (``x^2 + 9y^2 =
    u^2/2``, ``(6y - u)(30y - u) = 0``): only then are there two roots. Two values for a velocity
    that linear relations fix (``v_A = -1.04 or v_A = -1.4``) are a guess, and the wrong one a slip."""
    unknowns = set(trace.U)
    for r in lines:
        if r.number > line.number or r.exprs is None or len(r.exprs) < 2:
            continue
        d = sympy.numer(sympy.together(r.exprs[0] - r.exprs[-1]))
        names = sorted(d.free_symbols & unknowns, key=str)
        if not names:
            continue
        try:
            if sympy.Poly(sympy.expand(d), *names).total_degree() >= 2:
                return True
        except sympy.PolynomialError:
            return True  # a root or a sine of an unknown: not linear either
    return False


def _siblings(line: Any, lines: Sequence[Any], typed: list[str]) -> list[Any]:
    """The other values given for ``line``'s name on its line, where "or" joins them."""
    if line.exprs is None or len(line.exprs) != 2 or not 0 < line.number <= len(typed):
        return []
    if not _OR.search(typed[line.number - 1]):
        return []
    return [
        r
        for r in lines
        if r is not line and r.number == line.number and r.exprs is not None and len(r.exprs) == 2
        if r.exprs[0] == line.exprs[0] and r.exprs[1] != line.exprs[1]
    ]


def _holds(trace: Any, line: Any) -> bool:
    """Whether ``line`` holds for the problem, or for the slips made so far."""
    pairs = trace.pairs(line)
    return trace.holds(pairs, trace.truth) or (trace.world is not None and trace.holds(pairs, trace.world))
