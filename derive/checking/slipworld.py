"""The slip's world made as the student has it: a given written as another number in a relation
(the problem solved with it so), and a carried line's own equation, barely different from the
world's, put in its place (its rounded numbers), so that the lines after are judged from what
the student wrote, not from what derive would have had them write."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

import sympy

from derive.checking.mistakes import Variant
from derive.checking.numeric import number_of, shown
from derive.checking.tracing import Trace
from derive.checking.worlds import NUMBER_SIDE, Pair, solve_world
from derive.mathtext.notation import student

if TYPE_CHECKING:
    from derive.checking.relations import Values


def number_copied(trace: Trace, bad: Pair, rule: str = "") -> str:
    """``2(5) + 1(0) = 2(3) + v_B`` where A goes on at 2 m/s: a relation in one unknown (which
    a wrong velocity from any mistake would also let hold; ``rule``, the judge's, one of a
    mistaken equation) that writes a number that is none of the data and holds with the problem
    solved with a given copied as that number (or a datum that is a given with its decimal
    point moved: 2 for A's 0.2 m/s where B's mass is 2 kg); or in any unknowns, where the number is in a
    total with another given on the line too (``0.20(300) = 4.20 V``: a bullet's 0.020 kg
    copied, alone and with the 4.0 kg block). The slip's world is then the problem so; the
    words of the verdict ("" where it is not so)."""
    unknowns = bad.difference.free_symbols & set(trace.U)
    if bad.raw is None or trace.world is not None or not unknowns:
        return ""
    working = [t for t in bad.text.split(" = ") if not NUMBER_SIDE.match(student(t.strip()))]  # not a result
    written = {sympy.Rational(t) for t in re.findall(r"(?<![\w.^])\d+(?:\.\d+)?(?![\w.^])", " ".join(working))}
    alone = len(unknowns) == 1 and rule != "no_match"
    numbers = written | {abs(x) for x in set().union(*(x.atoms(sympy.Rational) for x in bad.raw))}  # (0.2 + 4)
    givens = [g for g in trace.ctx.problem.givens if not g.unknown and g.value is not None and g.value.is_Rational]
    moved = {c for c in written for g in givens if g.value and abs(c / g.value) in _TENS}  # 2 for 0.2, 2 a datum too
    for c in (written - set(trace.ctx.data) | moved) - {0, 1}:
        if not alone and not any(c + abs(h) in numbers for h in trace.ctx.data if h and h.is_Rational):
            continue  # 4.20 = 0.20 + 4.0: the copied number in a total too
        for g in givens if c not in trace.ctx.data else [g for g in givens if abs(c / g.value) in _TENS]:
            copy = -c if c in moved and g.value < 0 else c  # -0.2 written -2: its sign kept
            model, variant = trace.ctx.model, Variant(values={g.symbol: copy})
            world = solved_with(trace, variant) if abs(c) != abs(g.value) else None  # a find-e problem too
            if world is None or not trace.holds([bad], world):
                continue
            trace.copied[g.symbol], trace.variant, trace.world = copy, variant, world
            trace.equations = {j: F for j, F in model.numbered(variant).items() if j in trace.equations}
            return f": a given is copied wrongly: the problem gives {g.name} = {shown(g.value)}, not {shown(copy)}."
    return ""


#: A number's decimal point moved one or two places: what it is times.
_TENS = {sympy.Integer(10), sympy.Integer(100), sympy.Rational(1, 10), sympy.Rational(1, 100)}


def solved_with(trace: Trace, variant: Variant) -> list[Values] | None:
    """The unknowns at each sample point with the problem solved with ``variant``'s values (a
    given copied as another number), an inverse problem's unknown (e, a speed before) too: its
    outcome keeps the true unknowns; None where it does not solve so."""
    model = trace.ctx.model
    sol = model.solve(variant)
    if not sol or any(u not in sol for u in trace.U):
        return None
    return [{u: model.num(sympy.sympify(sol[u]), variant.values).xreplace(pt) for u in trace.U} for pt in trace.pts]


def refine(trace: Trace, pair: Pair) -> None:
    """Put a carried line's own equation in place of one of the world's that it barely
    changes (its rounded numbers), so that later lines are judged from the student's."""
    assert trace.world is not None
    F = pair.difference
    if any(not p.exp.is_Integer and p.base.free_symbols & set(trace.U) for p in F.atoms(sympy.Pow)):
        return  # a speed (the size of a velocity) stands for none of the world's equations
    if any(f.free_symbols & set(trace.U) for f in F.atoms(sympy.Function)):
        return  # an unknown angle's sine: its equation solved again costs seconds, for a rounding
    for j in list(trace.equations):
        trial = solve_world({**trace.equations, j: F}, trace.U, trace.pts, trace.world)
        if trial is None:
            continue
        near = all(
            abs((number_of(t[u]) or 0) - (number_of(w[u]) or 0)) <= 0.02 * max(1.0, abs(number_of(w[u]) or 0))
            for t, w in zip(trial, trace.world, strict=True)
            for u in trace.U
        )
        if near:
            trace.unrefined = (len(trace.replaced), trace.world)  # the student may go on from the exact value
            trace.equations[j] = F
            trace.world = trial
            return
