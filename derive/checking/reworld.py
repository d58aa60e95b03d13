"""Which of the student's equations a slip took the place of, settled by what they write next.

A slip in a line worked from two equations at once (``5x = 10u + 15eu`` after substituting
``y = x + 5eu`` into the momentum) stands for neither of them more than the other: the student
still believes both, and finds the other velocity from whichever they like. The trace guesses
one (:func:`~.worlds.closest`); where a later line holds only if the slip had taken the place
of another equation (``y = (10u - 2x)/3`` with their own x, the momentum kept), that line is
carried, and the slip's world is the one it shows. So is a line worked from the exact value a
carried line rounded (:func:`unrounded`), and one that holds with the velocities as the student
last stated each of them (:func:`stated`).
"""

from __future__ import annotations

from decimal import Decimal
from typing import TYPE_CHECKING

import sympy

from derive.checking import workedslips
from derive.checking.numeric import number_of
from derive.checking.relations import coefficients
from derive.checking.slipbefore import holds_slipped
from derive.checking.tracing import Trace
from derive.checking.worlds import NUMBER_SIDE, Pair, alike, solve_world
from derive.mathtext.notation import student

if TYPE_CHECKING:
    from derive.checking.inference import Read


def in_world(trace: Trace, pairs: list[Pair]) -> bool:
    """Whether ``pairs`` hold given the slips so far: in their world (a speed of a velocity
    reversed too), or in another the student's own earlier lines allow (the world before a
    rounding refined it, or the last slip in place of another equation)."""
    if trace.world is None:
        return False
    if trace.holds(pairs, trace.world) or workedslips.speed_of_reversed(trace, pairs):
        return True
    return unrounded(trace, pairs) or moved(trace, pairs) or stated(trace, pairs) or holds_slipped(trace, pairs)


def stated(trace: Trace, pairs: list[Pair]) -> bool:
    """Whether ``pairs`` hold with the velocities as the student last stated each of them (a
    right one from a line that held, a wrong one from their slip: ``v_B = ⅓u(1 + e)`` then
    ``v_A = u - 2v_B = ⅓u(1 + 2e)``), where the slip's world solved again moves one they kept;
    that is then the world."""
    own = {u: x for u, x in trace.own.items() if u in trace.U}
    if not own or trace.holds(pairs, trace.truth):
        return False
    world = []
    for pt, truth in zip(trace.pts, trace.truth, strict=True):
        values = dict(truth)
        for u, x in own.items():
            v = number_of(trace.ctx.in_unknowns(x).xreplace(pt).xreplace(truth))
            if v is None or abs(v.imag) > 1e-12:
                return False
            values[u] = sympy.Float(v.real, 20)
        world.append(values)
    if not trace.holds(pairs, world) or not trace.holds(list(trace.worked), world):
        return False
    trace.world = world
    return True


def unrounded(trace: Trace, pairs: list[Pair]) -> bool:
    """Whether ``pairs`` hold in the slip's world as it was before a carried line's rounded value
    refined it (``b = a + 3 ≈ -0.714`` from a = -26/7, after ``a = -26/7 ≈ -3.71``): the student
    goes on from their exact value, not the rounded one."""
    if trace.unrefined is None or trace.unrefined[0] != len(trace.replaced):
        return False  # a slip since: that world is not the student's any more
    return trace.holds(pairs, trace.unrefined[1]) and not trace.holds(pairs, trace.truth)


def moved(trace: Trace, pairs: list[Pair], written_wrong: bool = False) -> bool:
    """Whether ``pairs`` (a line false for the problem and in the slip's world) hold once the
    last slip takes the place of another of the equations, the one it displaced put back; every
    carried relation so far must hold there too. The trace's world is then that one. The equation
    put back may be the student's own earlier slip (``b - a = 4`` the wrong way round, then
    ``-0.5 = 0.5a + 4`` worked from it into the momentum: b = a + 4 is still theirs). A line that
    writes a number the student got wrong (``written_wrong``: ``v1f = 0.160 - 35.0`` after ``v2f =
    10.5/70.15 = 0.160``) may hold for the problem too, at its figures: it is the student's all the same."""
    U = set(trace.U)
    if trace.world is None or not trace.replaced or trace.displaced is None:
        return False
    if not any(p.difference.free_symbols & U for p in pairs) or (trace.holds(pairs, trace.truth) and not written_wrong):
        return False
    n, j = trace.replaced[-1]
    at, before = trace.displaced
    if at != j:
        return False  # the slip's place was settled since: nothing to put back
    F = trace.equations[j]
    cf = coefficients(F.xreplace(trace.pts[0]), trace.U)
    vectors = {k: coefficients(x.xreplace(trace.pts[0]), trace.U) for k, x in trace.equations.items()}
    every = set().union(*(_linear(c or {}) for c in vectors.values()))  # the unknowns the equations hold
    for k, cg in vectors.items():
        if k == j or not cf or not cg or (alike(cf, cg) < 0.5 and not _eliminated_from(cf, cg, every)):
            continue  # only an equation much like it in its unknowns (the momentum or the impact rule it was worked from)
        equations = {**trace.equations, j: before, k: F}
        world = solve_world(equations, trace.U, trace.pts, trace.world)
        if world is None or not trace.holds(pairs, world) or not trace.holds(list(trace.worked), world):
            continue
        trace.displaced = (k, trace.equations[k])
        trace.equations, trace.world = equations, world
        trace.replaced[-1] = (n, k)
        return True
    return False


def _linear(c: dict) -> set[int]:
    """The unknowns (by index) a coefficient vector has a linear term in."""
    return {m.index(1) for m, x in c.items() if sum(m) == 1 and abs(x) > 1e-12}


def _eliminated_from(cf: dict, cg: dict, every: set[int]) -> bool:
    """Whether a slip in fewer unknowns than the impact's equations hold (``12 v_A = 46`` after
    putting ``v_B = v_A + 4`` into the momentum) may have been worked from the equation of
    ``cg`` (``every``: the unknowns the equations hold): the slip has an unknown of it, and the one
    eliminated is in it too. Worked from the two at once, it stands for either: the student finds
    the other velocity from whichever."""
    mine, theirs = _linear(cf), _linear(cg)
    return bool(mine & theirs) and bool((theirs - mine) & (every - mine))


def nearer_the_slip(trace: Trace, line: Read, pairs: list[Pair]) -> bool:
    """Whether a velocity stated as a number (``v_1 = -35.0`` after ``70.15 v_1 = -2455.25``) is
    the slip's value rounded to its figures (-35.000) and the problem's only within the unit the
    figures allow (-34.85 is not -35.0 rounded, half a unit in its last place): the student's
    number, carried."""
    if trace.world is None or not line.exprs or len(line.sides) < 2:
        return False
    m = NUMBER_SIDE.match(student(line.sides[-1].strip()))
    first = trace.ctx.in_unknowns(line.exprs[0])
    if m is None or m.group(3) or not first.free_symbols or not first.free_symbols <= set(trace.U):
        return False
    written = Decimal(m.group(1) + m.group(2))
    half = Decimal(5).scaleb(int(written.as_tuple().exponent) - 1)  # rounded, not ±1 in the last digit
    near = []
    for values in (trace.world, trace.truth):
        v = number_of(first.xreplace(values[0]))
        if v is None or abs(v.imag) > 1e-12:
            return False
        near.append(abs(Decimal(repr(v.real)) - written) <= half)
    return near[0] and not near[1] and trace.holds(pairs, trace.world)
