"""A line that eliminates an unknown between two relations (adding or subtracting the momentum
and the impact rule) and goes wrong in the step: ``subtract: v_A' = 0.7071v − 0.6364v`` from
``0.7071v = v_A' + v_B'`` and ``v_B' − v_A' = 0.6364v`` (the 2 of 2v_A' lost), ``2y = 7 + e``
from ``x + y = 7`` and ``y − x = 7e`` (the 7 of 7e lost).

It works from no single relation before it, so the step from the relation just before does not
name it. A teacher names it as the step from the two it was worked from: the combination that
eliminates the unknown the line no longer has is the relation "before", and the slip is named
from it as any rearranging is (:func:`.rearranging.kind`: a term's sign or coefficient lost,
algebra; the terms in the unknowns as they were and a number worked wrongly, arithmetic).
"""

from __future__ import annotations

from itertools import combinations
from typing import TYPE_CHECKING

import sympy

from derive.checking import rearranging
from derive.checking.slipnames import same_but_number
from derive.checking.termslips import SOLVING
from derive.checking.worlds import Pair

if TYPE_CHECKING:
    from derive.checking.tracing import Trace

#: The right relations looked back over (the most recent), so that the pairs tried stay few.
MAX_BACK = 4
#: What a report says where nothing names the slip.
UNNAMED = ". No common mistake reproduces it."


def _combined(a: Pair, b: Pair, keep: set, unknowns: set) -> sympy.Expr | None:
    """``a`` and ``b`` (left − right) combined to eliminate the one unknown of theirs that is not
    in ``keep``, both linear in it; None where that is not so."""
    F, G = sympy.expand(a.difference), sympy.expand(b.difference)
    gone = ((F.free_symbols | G.free_symbols) & unknowns) - keep
    if len(gone) != 1 or not keep <= (F.free_symbols | G.free_symbols):
        return None
    w = next(iter(gone))
    cf, cg = F.coeff(w, 1), G.coeff(w, 1)
    if not cf or not cg or (cf.free_symbols | cg.free_symbols) & unknowns or F.has(w**2) or G.has(w**2):
        return None
    H = sympy.expand(F * cg - G * cf)
    return H if H != 0 and not H.has(w) else None


def named(trace: Trace, bad: Pair, name: str) -> tuple[str, str]:
    """The words and the name of a slip no step from the relation just before named (``name``
    empty): the step from two right relations before it that eliminates an unknown, where that
    step names it; ``name``'s words otherwise."""
    if name or bad.raw is None:
        return SOLVING.get(name, UNNAMED), name
    unknowns, pt = set(trace.U), trace.pts[0]
    keep = bad.difference.free_symbols & unknowns
    held = trace.held[-MAX_BACK:]
    for a, b in combinations(reversed(held), 2):  # the nearest first
        H = _combined(a, b, keep, unknowns) if keep else None
        if H is None:
            continue
        before = Pair(f"{a.text}; {b.text}", H, sympy.Integer(0), max(a.tol, b.tol))
        how = rearranging.kind(bad, before, trace.U, pt)
        how = how or ("arithmetic" if same_but_number(bad.difference, H, trace.U, pt) else "")
        if how:
            return SOLVING[how].replace("the line before", "the two lines it combines"), how
    return UNNAMED, ""
