"""A line's slip named by its fresh mistake, not by an earlier one whose number it carries.

``(v_A)y2 = e(v_A)y1 = 0.5 × 9 = 4.5`` after A's components were resolved with sin and cos
swapped (9 for 12): its side of numbers holds only with that swap, made again, but the 9 is the
student's own carried value; what is new in the line is e put on the t component (``e_on_t``),
which a teacher names. Where the relation first judged is only the earlier mistake made again
and another false relation of the line, in the unknowns, is a fresh common mistake, that one is
the line's slip.
"""

from __future__ import annotations

import re

import sympy

from derive.checking import slipnames, stepnames
from derive.checking.mistakes import REGISTRY
from derive.checking.worlds import Pair
from derive.problem.units import ANGLE

#: What :meth:`~.lines.Trace._explain` returns: the mistakes, the equation, the words, the name.
Explained = tuple


def explained(trace, line, bad: Pair, pairs: list[Pair], answer) -> tuple[Pair, Explained]:
    """The relation of ``line`` its slip is named by, and its explanation (``trace._explain``)."""
    found = stepnames.step_first(trace, line, bad, trace._explain(line, bad, answer))
    found = _angle_stated(trace, line, bad, found)
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


def _angle_stated(trace, line, bad: Pair, found: Explained) -> Explained:
    """A line that works out an angle (a side a number of degrees, ``cos θ = r/2r ⇒ θ = 60°``, not a
    given angle restated) whose value is the one sin and cos swapped give: the angle taken from the
    other axis (``angle_other_axis``), as a teacher names a wrong angle, and the components worked
    from it are that mistake again (sin and cos swapped); components resolved with sin and cos
    swapped (``5 sin 37.6° = 3.05``: no angle worked out) keep their name."""
    if {d.mistake for d in found[0]} != {"sin_cos_swapped"} or "angle_other_axis" not in REGISTRY:
        return found
    given = {
        float(g.value * 180 / sympy.pi) for g in trace.ctx.problem.givens if g.dim == ANGLE and g.value is not None
    }
    worked = [float(m[1]) for m in _ANGLE_WORKED.finditer(getattr(line, "written", ""))]
    asked = not any(all(abs(a - b) > 1e-6 for b in given) for a in worked)  # else an angle worked out
    if asked and not _in_asked_angle(trace, bad):
        return found
    other = trace.ctx.diagnosis(REGISTRY["angle_other_axis"])
    said = str(found[2]).replace(REGISTRY["sin_cos_swapped"].phrase, REGISTRY["angle_other_axis"].phrase)
    both = other if asked else (*other, *found[0])  # an angle worked out: the components swapped too
    return (both, found[1], said, *found[3:]) if other else found


#: An angle worked out to a number of degrees on a line as typed: ``θ = 60°``, ``\theta = 60^\circ``.
_ANGLE_WORKED = re.compile(
    r"(?:(?<![\w\\])[A-Za-z]\w*|\\[a-z]+|[αβγθφψ])(?:_\{?\w+\}?)?\s*&?\s*=\s*(\d+(?:\.\d+)?)\s*(?:°|\^\s*\{?\s*\\circ)"
)


def _in_asked_angle(trace, bad: Pair) -> bool:
    """Whether ``bad`` has the angle the problem asks for (α with the wall, a velocity's own angle)
    inside a sine, cosine or tangent: sin and cos swapped there is that angle taken from the other
    axis, as a teacher names it (``½m(U² sin²α + 9/16 U² cos²α) = 0.6(½mU²)``)."""
    p = trace.ctx.problem
    asked = {g.symbol for g in p.givens if g.unknown} & set(trace.U)
    angles = {x.angle for x in (p.motion_A, p.motion_B) if x is not None and x.angle is not None} & asked
    trig = set().union(*(x.atoms(sympy.sin, sympy.cos, sympy.tan) for x in bad.raw or ()))
    return any(f.args[0].free_symbols & angles for f in trig)
