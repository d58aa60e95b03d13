"""A relation in several unknowns worked on wrongly: its terms kept, its number not.

:func:`.slipnames.solving_slip` names a line solved from the relation just before it in one
unknown; a line that only tidies a relation in two unknowns (``0.3(3) + 0.2(-2) = 0.3 v_A +
0.2 v_B, so 0.3 v_A + 0.2 v_B = 0.6``: the momentum's number worked out) and gets that number
wrong is the same slip, an arithmetic one, whether the relation it works on is on the line
before or earlier on the same line. Without it such a line looks like a given copied wrongly
(a mass put in for another can make it hold within its rounding).
"""

from __future__ import annotations

import re
from dataclasses import replace

import sympy

from derive.checking import slipnames
from derive.checking.carrying import GOES_ON
from derive.checking.slipnames import Holds, Previous, same_but_number
from derive.checking.worlds import Pair


def number_worked_wrongly(pairs: list[Pair], previous: Previous, at: tuple[tuple, dict], holds: Holds) -> str:
    """``arithmetic`` where the first failing relation of a line is one that holds (the line
    before's, or one earlier on the line) with the same terms in the same unknowns, up to a
    factor, and only its number changed; "" otherwise. ``at``: the unknowns and a sample point."""
    U, pt = at
    unknowns = set(U)
    if any(not p.difference.free_symbols & unknowns and not holds(p) for p in pairs):
        return ""  # a side of numbers wrong is the arithmetic of that side, named elsewhere
    failing = next((p for p in pairs if p.difference.free_symbols & unknowns and not holds(p)), None)
    if failing is None:
        return ""
    own = pairs[: pairs.index(failing)]
    held = [p for p in (*(previous[1] if previous else ()), *own) if p.difference.free_symbols & unknowns]
    held = [p for p in held if holds(p)]
    names = failing.difference.free_symbols & unknowns
    for p in held:
        if p.difference.free_symbols & unknowns == names and same_but_number(failing.difference, p.difference, U, pt):
            return "arithmetic"
    return ""


def wrong_energy_worked(trace, line, pairs: list[Pair]) -> bool:
    """A line that goes on ("= ...") from a wrong line and whose side of numbers is a kinetic
    energy by one of the wrong formulas (``KE lost = ½m(u − v)²``, then ``= 0.5 × 0.8 × (4 −
    1.2)²``: of the speeds): the wrong formula's working, carried, not a further slip."""
    if not trace.went_wrong or GOES_ON.match(line.written) is None:
        return False
    unknowns = set(trace.U)
    numbers = [(p, x) for p in pairs for x in (p.left, p.right) if not x.free_symbols & unknowns]
    world = trace.world if trace.world is not None else trace.truth
    for form in slipnames.wrong_energies(trace.ctx):
        for value in form.values():
            energy = trace.ctx.in_unknowns(value)
            if any(trace.holds([replace(p, left=energy, right=x, raw=None)], world) for p, x in numbers):
                return True
    return False


def works_from_slip(trace, line, slip_line: int) -> bool:
    """Whether ``line`` writes a number the slip at ``slip_line`` came to, or a line after it (not data):
    ``7.2 = -0.96 + 0.4v`` after ``momentum before = 0.8(6) + 0.4(6) = 7.2`` (B's sign lost)
    works from that line's number, a carried error, not the mistake made again."""
    stated = set().union(*(t for n, t in trace.stated.items() if slip_line <= n < line.number))  # and lines after it
    written = set(re.findall(r"\d+\.?\d*", " ".join(line.sides)))
    return any(sympy.Rational(t) not in trace.ctx.data for t in written & stated if t.strip("0."))


def into_world(trace, line, pairs: list[Pair]) -> None:
    """A relation right for the problem after a slip whose world it does not hold in (B's sign
    lost in the momentum, then ``v_B - v_A = 0.8(3 + 2)`` right: the mistake changed the
    approach too, the student did not): the student's world takes it in place of the equation
    it stands for, so the lines worked from both are carried, not further slips."""
    if trace.world is None or not re.search(r"\d", " ".join(line.sides)):
        return  # a law in names (the givens as the problem has them) is not the student's numbers
    givens = {g.symbol for g in trace.ctx.problem.givens if not g.unknown}
    own = [p for p in pairs if p.difference.free_symbols & set(trace.U) and not trace.holds([p], trace.world)]
    if len(own) == 1 and not set().union(*(x.free_symbols for x in own[0].raw or ())) & givens:
        trace._replace(line, own[0], slip=False)
