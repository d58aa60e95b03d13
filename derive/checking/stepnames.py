"""A slip named by the step that made it, before any common mistake whose values it meets.

A teacher names a wrong line by the single change to the true working that gives what the
student wrote, and looks nearest first: where the line works on the relation just before it,
which holds (the physics written right) with its numbers in (no given's letter left to put
in), and a slip of algebra in that step reproduces it (a number moved across with its sign
kept, a sign, a factor or a letter lost: :func:`.slipnames.solving_slip`), the slip is that
step's, ``algebra``, even where its result is also what a common mistake gives. A number
worked wrongly on the way is left to the mistakes, but for a velocity's sign: where the line
before wrote it with its sign right (``4(72.505) + 3(−19.101)``) and this line's number comes
out as if it were not (``= 347.32``, the 57.30 added), the sign was lost in the working, not
in taking the velocity, and the slip is ``arithmetic``, as the corpus's teachers name it
(xh12; mb07, za11 worked on one line); a velocity first put in with its sign lost stays
``b_sign``.
In an elastic collision with B at rest, ``m_A(u − v) = m_B V`` worked as ``m_B V = m_A u +
m_A v`` always gives m_B = m_A, the value of the masses swapped; the line before shows the
masses where they belong. The order of preference is: the step from the
relation before (this module), then a common mistake's equations, then a slip of the line's
own numbers (:meth:`~.lines.Trace._explain`).
"""

from __future__ import annotations

from derive.checking import slipnames
from derive.checking.termslips import SOLVING
from derive.checking.worlds import Pair

#: What :meth:`~.lines.Trace._explain` returns: the mistakes, the equation, the words, the name.
Explained = tuple


def step_first(trace, line, bad: Pair, found: Explained) -> Explained:
    """``found`` (a common mistake's explanation of ``bad``) replaced by the step's slip where
    the line works wrongly on the relation just before it, which held (``trace.previous``);
    ``found`` as it is otherwise."""
    if not found[0] or trace.previous is None or line.number in trace.named:
        return found
    world = trace.world if trace.world is not None else trace.truth

    def held(p: Pair) -> bool:
        return trace.holds([p], world)

    previous = trace.previous[1]
    names = set().union(*(x.free_symbols for p in previous for x in p.raw or ()))
    symbolic = set(trace.pts[0])  # a symbolic given (u, m) has no number to put in: it is algebra's letter
    letters = [s for s in names if s not in symbolic and not trace.ctx.in_unknowns(s).free_symbols & set(trace.U)]
    if letters or not all(p.raw is not None and held(p) for p in previous):  # numbers put in: not a step
        return found
    name = slipnames.solving_slip(line.sides, trace.pairs(line), trace.previous, (trace.U, trace.pts[0]), held)
    signs = all(d.mistake == "b_sign" for d in found[0])  # the sign written right just before: not taken again
    if name != "algebra" and not (name == "arithmetic" and signs):  # weights for masses: weight_as_mass
        return found
    j = found[1] if found[1] in trace.equations else trace._closest(bad.difference)  # not a mistake's world kept
    return (), j, SOLVING[name], name
