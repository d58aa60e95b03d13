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

from derive.checking.axisnames import AXIS_LETTERS, sub_axis
from derive.checking.labelled import resolved
from derive.checking.worlds import Pair

#: An axis's letter or word in a name's subscript other than parallel and perpendicular (those are
#: :func:`.axisnames.sub_axis`'s): along the line of centres "n", across it "t"; at a wall n is into
#: it and t along it, and x and y say nothing of the wall (the student's to place). Not i and j: in
#: a name's subscript they are initial, or a body.
_LETTERS = {k: v for k, v in AXIS_LETTERS.items() if k not in "ij"} | {"normal": "n", "tangent": "t"}
_AT_A_WALL = {k: v for k, v in _LETTERS.items() if k not in "xy"}
#: A velocity's letter and an axis in its subscript, with no body and no time (``v_perp``, ``ux``).
_NAME = re.compile(r"(?i)[uvw]_?\{?([a-z]+)\}?")


def axis_of(name: str, wall: bool) -> str:
    """The axis a name says by its subscript alone (``v_perp`` at a wall: n), "" where it says
    none or says more (a body, a time)."""
    m = _NAME.fullmatch(name)
    if not m:
        return ""
    word = m.group(1).lower()
    return (_AT_A_WALL if wall else _LETTERS).get(word, "") or sub_axis(word, wall)


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
