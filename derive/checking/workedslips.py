"""A relation in several unknowns worked on wrongly: its terms kept, its number not.

:func:`.slipnames.solving_slip` names a line solved from the relation just before it in one
unknown; a line that only tidies a relation in two unknowns (``0.3(3) + 0.2(-2) = 0.3 v_A +
0.2 v_B, so 0.3 v_A + 0.2 v_B = 0.6``: the momentum's number worked out) and gets that number
wrong is the same slip, an arithmetic one, whether the relation it works on is on the line
before or earlier on the same line. Without it such a line looks like a given copied wrongly
(a mass put in for another can make it hold within its rounding).
"""

from __future__ import annotations

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
