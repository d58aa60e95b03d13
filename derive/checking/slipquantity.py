"""Which quantity a sign lost belongs to, decided from what the student wrote before.

A line that puts the problem's numbers into a relation written in its names just before
(``m_A (v_A)_2 + m_B (v_B)_2`` then ``(0.5)(0.2) + 2 (v_B)_2``, A's after given as a speed
0.2 m/s, reversed) and holds with a given velocity taken the other way has not rearranged
anything: the sign was lost in taking that velocity's value, and a teacher names it
``b_sign`` (a velocity the wrong way), as the corpus's teachers name every momentum line that
puts a given velocity in with its sign lost (xh04; zg11, w12, yc13). A slip of algebra found in
the same step (the term ``0.5(0.2)`` with its sign changed) is the same change seen as a term's
sign; the quantity it belongs to names it. A line that works on a relation of numbers written
before it (``4(72.505) + 3(−19.101)`` then ``347.32``) is the other case: the sign was there,
and its loss is the working's (:mod:`.stepnames`).
"""

from __future__ import annotations

import sympy

from derive.checking import carried, slipnames
from derive.checking.worlds import Pair


def unnamed(trace, line, bad: Pair, world, j: int | None, name: str):
    """What :func:`.carried.unnamed` finds where no step named the slip (``name`` empty); where the
    step named it ``algebra`` but the line puts numbers in for the names of the relation before
    it and holds with a given velocity taken the other way, that velocity's sign, ``b_sign`` (no
    equation replaced: the problem solved with it so); None otherwise."""
    if not name:
        return carried.unnamed(trace, line, bad, world, j)
    if name != "algebra" or trace.previous is None or bad.raw is None:
        return None
    unknowns = set(trace.U)
    names = set().union(*(x.free_symbols for p in trace.previous[1] for x in p.raw or ()))
    put = {s for s in names if not trace.ctx.in_unknowns(s).free_symbols & unknowns}  # a given's name
    written = set().union(*(x.free_symbols for x in bad.raw))
    if not put or put & written:  # no names put in, or not all of them: not a substitution
        return None
    kept = trace.variant, trace.world, trace.equations
    if carried.given_negated(trace, bad) and _put_in(trace, bad, trace.variant.values):
        trace.copied.update(trace.variant.values)  # its name, written after, is the value as the student took it
        return 0, slipnames.FLIPPED["b_sign"], "b_sign"
    trace.variant, trace.world, trace.equations = kept
    return None


def _put_in(trace, bad: Pair, values: dict) -> bool:
    """Whether ``bad`` is a relation of the line before with ``values`` (a given taken the other way)
    and the other givens put in, each side for its side, nothing moved across (``v_B = 0.200 −
    0.050`` from ``v_B − v_A = 0.200 − 0`` moves v_A: its sign lost there is the move's, algebra)."""
    here = [trace.ctx.in_unknowns(x) for x in bad.raw]
    for p in trace.previous[1]:
        if p.raw is None:
            continue
        there = [trace.ctx.in_unknowns(x.xreplace(values)) for x in p.raw]
        for a, b in ((0, 1), (1, 0)):
            if all(_same(here[i], there[k], trace.pts[0], bad.tol) for i, k in ((0, a), (1, b))):
                return True
    return False


def _same(x: sympy.Expr, y: sympy.Expr, pt: dict, tol: float) -> bool:
    """Whether the sides ``x`` and ``y`` are the same, term by term, within ``tol`` of ``y``'s size."""
    try:
        size = sum(abs(float(t.as_coeff_Mul()[0])) for t in sympy.Add.make_args(sympy.expand(y.xreplace(pt))))
        d = sympy.Add.make_args(sympy.expand((x - y).xreplace(pt)))
        return all(abs(float(t.as_coeff_Mul()[0])) <= max(tol, 1e-6) * max(size, 1e-12) for t in d)
    except (TypeError, ValueError):
        return False
