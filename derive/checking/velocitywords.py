"""A body's velocity in words in an oblique impact where that body moves along the line of centres
(``CLM along x, A's velocity after = a``, A's t component nil before and after), or on a line that
says it is along the line of centres: its n component, signed, as a teacher reads "velocity"
there, not its speed (which is what ``v_A2`` names in an oblique impact, the size of both
components). A line that also has the component across (or a root of the two squared) says the
whole velocity: ``A keeps 4 m/s perpendicular to it, so A's velocity after = sqrt(20)``.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from derive.checking.context import Context
    from derive.mathtext.reader import Relation

#: Words that say a line is along the line of centres (derive's n).
_ALONG = re.compile(
    r"\b(?:along|parallel\s+to)\s+(?:the\s+)?(?:line\s+of\s+(?:centres|centers|impact)|common\s+normal|normal)\b", re.I
)
#: Words or working that put both components in the line (``along the line of centres 2 m/s back,
#: across 4 m/s``, ``= sqrt(2^2 + 4^2)``): a velocity there is the whole of it, its speed.
_BOTH = re.compile(r"\b(?:across|perpendicular|at\s+right\s+angles|tangent\w*|sqrt|resultant)\b|√", re.I)
#: A velocity said in words (not a speed).
_VELOCITY = re.compile(r"\bvelocity\b", re.I)


def along_the_line(ctx: Context, r: Relation, sides: tuple[str, ...]) -> tuple[str, ...]:
    """``sides`` (rewritten from ``r``'s) with a body's velocity in words (``v_A2``, ``v_A1``, its
    speed in an oblique impact) as its n component (``v_A2n``) where the body has no t component
    (``v_A1t = 0`` given: it keeps it at a smooth impact) or the line says along the line of centres."""
    if not ctx.problem.oblique:
        return sides
    still = {g.name[2] for g in ctx.problem.givens if re.fullmatch(r"v_[AB]1t", g.name) and g.value == 0}
    still |= set("AB") if _ALONG.search(r.written) and not _BOTH.search(r.written) else set()
    out = list(sides)
    for i, (said, side) in enumerate(zip(r.sides, sides, strict=True)):
        m = re.fullmatch(r"\s*v_([AB])([12])\s*", side)
        if m and m[1] in still and _VELOCITY.search(said) and not re.search(r"\bspeed\b", said, re.I):
            out[i] = f"v_{m[1]}{m[2]}n"
    return tuple(out)
