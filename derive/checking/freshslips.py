"""A line's slip named by its fresh mistake, not by an earlier one whose number it carries.

``(v_A)y2 = e(v_A)y1 = 0.5 × 9 = 4.5`` after A's components were resolved with sin and cos
swapped (9 for 12): its side of numbers holds only with that swap, made again, but the 9 is the
student's own carried value; what is new in the line is e put on the t component (``e_on_t``),
which a teacher names. Where the relation first judged is only the earlier mistake made again
and another false relation of the line, in the unknowns, is a fresh common mistake, that one is
the line's slip.
"""

from __future__ import annotations

from derive.checking import slipnames, stepnames
from derive.checking.worlds import Pair

#: What :meth:`~.lines.Trace._explain` returns: the mistakes, the equation, the words, the name.
Explained = tuple


def explained(trace, line, bad: Pair, pairs: list[Pair], answer) -> tuple[Pair, Explained]:
    """The relation of ``line`` its slip is named by, and its explanation (``trace._explain``)."""
    found = stepnames.step_first(trace, line, bad, trace._explain(line, bad, answer))
    if not _again(trace, {d.mistake for d in found[0]}):
        return bad, found
    world = trace.world if trace.world is not None else trace.truth
    unknowns = set(trace.U)
    for p in pairs:
        if p is bad or not p.difference.free_symbols & unknowns or trace.holds([p], world):
            continue
        other = trace._explain(line, p, answer)
        fresh = {d.mistake for d in other[0]}
        if fresh and not _again(trace, fresh):
            return p, other
    return bad, found


def _again(trace, made: set[str]) -> bool:
    """Whether the mistakes ``made`` are those named at an earlier slip (made again)."""
    return bool(made) and any(slipnames.same_mistake(names, made) for names in trace.named.values())
