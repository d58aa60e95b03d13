"""A name that says its axis and nothing else, set to a body's given speed resolved:
``v_perp = u cos θ`` at a wall, ``u_x = 4 sin 60°``, ``v∥ = U sin 30°``. Alone on the left of a
relation such a name is read as the student's own (a definition, not marked), but a teacher
reads the line as "the component along that axis is …" and marks it against the problem: the
problem's text fixes what the angle is measured from, and the component worked with sin for
cos (the angle from the other axis) is the slip, whatever the student then calls it.

:func:`of_trace` gives the pair "that body's component before on the axis = the working" where
it holds only with a mistake in the values before (sin and cos swapped, ...), so the trace
judges the line as the slip it is and carries the lines worked from it; None otherwise (the
definition stands: a right component, or a name that says no axis).
"""

from __future__ import annotations

import re

from derive.checking.labelled import resolved
from derive.checking.worlds import Pair

#: An axis's word or letter in a name's subscript -> the axis (along the line of centres "n",
#: across it "t"); at a wall parallel is along it (t) and perpendicular into it (n).
_AXES = {
    "n": "n",
    "x": "n",
    "par": "n",
    "para": "n",
    "parallel": "n",
    "along": "n",
    "normal": "n",
    "t": "t",
    "y": "t",
    "perp": "t",
    "perpendicular": "t",
    "across": "t",
    "tangent": "t",
}
#: At a wall: the wall's own words (x and y say nothing of the wall: the student's to place).
_AT_A_WALL = {"par": "t", "para": "t", "parallel": "t", "along": "t", "perp": "n", "perpendicular": "n", "n": "n"}
_AT_A_WALL |= {"normal": "n", "t": "t", "tangent": "t", "across": "n"}
#: A velocity's letter and an axis in its subscript, with no body and no time (``v_perp``, ``ux``).
_NAME = re.compile(r"(?i)[uvw]_?\{?([a-z]+)\}?")


def axis_of(name: str, wall: bool) -> str:
    """The axis a name says by its subscript alone (``v_perp`` at a wall: n), "" where it says
    none or says more (a body, a time)."""
    m = _NAME.fullmatch(name)
    if not m:
        return ""
    word = m.group(1).lower()
    return (_AT_A_WALL if wall else _AXES).get(word, "")


def of_trace(trace, line) -> Pair | None:
    """The component before the line's definition stands for, where the working resolves one
    body's given speed and holds only with a mistake in the values before; None otherwise."""
    ctx = trace.ctx
    if not getattr(ctx.problem, "oblique", False) or not line.defines or len(line.exprs or ()) < 2:
        return None
    axis = axis_of(line.defines, bool(getattr(ctx.problem, "fixed_B", False)))
    if not axis:
        return None
    holds = lambda p: trace.holds([p], trace.truth)  # noqa: E731
    return resolved(ctx, line.sides[1:], line.exprs[1:], axis, (line.sides[0].strip(), holds))
