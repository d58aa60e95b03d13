"""A velocity taken the wrong way in one equation only: ``3.45 - 0.2 = e(6 + 2)`` where B moves
the same way at 2 (the approach 6 - 2), its momentum line right before it.

:func:`.carried.given_negated` solves the whole problem with a given velocity the other way
(the momentum and the restitution both with it so). A student who writes the momentum right and
then takes one velocity's sign wrongly in the restitution line (or the other way round) made the
slip in that equation alone: a teacher names it ``b_sign`` all the same, and the line takes that
equation's place (the lines worked from it carried). Numbers summed at once on the line
(``3.45 - 0.2``, ``6 + 2``) leave no term to flip, so the slip is found in the equations.
"""

from __future__ import annotations

import copy
from dataclasses import replace

import sympy

from derive.checking.tracing import Trace
from derive.checking.worlds import Pair, solve_world


def negated_in_one(trace: Trace, bad: Pair) -> int | None:
    """The equation ``bad`` stands for where it holds with one given velocity (before, or after
    where given) taken the other way in that equation alone, the others as the student has them;
    None where no such equation (or more than one) makes it hold."""
    if not bad.difference.free_symbols & set(trace.U):
        return None
    model, found = trace.ctx.model, set()
    base = trace.variant
    own = {j for _n, j in trace.replaced}  # equations the student's own lines stand for: kept
    as_base = model.numbered(base)
    for g in trace.ctx.problem.givens:
        value = g.value if g.value is not None else g.definition
        if g.unknown or value is None or value == 0 or g.name[:1] not in "uvw" or g.symbol is None:
            continue
        variant = replace(base, values={**dict(base.values), g.symbol: -value})
        turned = copy.copy(model)  # a velocity after given (A moves back): among the known components
        turned.zeros = {k: (-x if x == value else x) for k, x in model.zeros.items()}
        turned.ind = {k: (-x if x == value else x) for k, x in model.ind.items()}
        changed = turned.numbered(variant)
        for j in trace.equations:
            if j in own or j not in changed or j not in as_base or sympy.expand(changed[j] - as_base[j]) == 0:
                continue
            world = solve_world({**trace.equations, j: changed[j]}, trace.U, trace.pts, trace.world or trace.truth)
            if world is not None and trace.holds([bad], world) and keeps_own(trace, world):
                found.add(j)  # the student's own laws so far still right: the slip is this line's
    return next(iter(found)) if len(found) == 1 else None


def keeps_own(trace: Trace, world: list, given=None) -> bool:
    """Whether the student's own relations that held so far (in the unknowns) hold in ``world``
    too: a velocity reversed in every equation that makes the student's laws just written false
    (``u = v_A + v_B``, ``v_B - v_A = eu``, then ``2v_A = eu - u`` from their difference) is not
    the slip; the signs lost in combining them are (algebra). A relation that writes the given
    taken the other way (``given``) by its name (``m_A v_A2 + m_B v_B2``) holds whatever its value
    is: it is not put to ``world``."""

    def named(p) -> bool:
        return given is not None and p.raw is not None and any(given in x.free_symbols for x in p.raw)

    return all(trace.holds([p], world) for p in trace.held[-12:] if not named(p))
