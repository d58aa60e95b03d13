"""A kinetic energy written without its half, named by what the line shows: ``ke_formula``.

Where B is twice as heavy as A and at rest, the masses swapped give the energy before as
½(m_B)u² = m_A u², the very value of A's energy with its half left out: ``KE before: K = 3m u²``
for A (3m) at u onto B (6m) is both. A teacher names what the line shows: A's own mass and no
half, the formula of the energy written wrongly (``ke_formula``), not masses the line does not
write; a mass swapped shows in the momentum, where it enters. So a slip that the masses swapped
explain only through the value of an energy, on a line that writes no half and whose wrong
formula of that energy explains it too, is ``ke_formula``.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from derive.checking.context import Context
from derive.checking.mistakes import Mistake
from derive.checking.worlds import Pair

#: A half as students type it: ½, 1/2, 0.5, .5, \frac12, \tfrac{1}{2}, ``/2`` after a product.
HALF = re.compile(
    r"½|(?<![\d.])1\s*/\s*2(?![\d.])|(?<![\d.])0?\.50*(?!\d)|\\[dt]?frac\s*\{\s*1\s*\}\s*\{\s*2\s*\}|\\[dt]?frac\s*12(?!\d)"
    r"|(?:(?<![\d.\s])|(?<=\^2))/\s*2(?![\d.])"  # m v²/2, (mv^2)/2, mv^2/2: not 3/2
)


def shown(
    ctx: Context, bad: Pair, found: list[Mistake], holds: Callable[[Pair], bool], where: tuple[str, ...] | Pair
) -> list[Mistake]:
    """``found`` (the mistakes whose value of a result makes ``bad`` hold) with the masses swapped
    left out where the line (``where``: every side of it, else the pair) writes no half and a kinetic
    energy's wrong formula explains it too (``K = 3mu²``: no ½ on the whole line)."""
    from derive.checking.slipnames import ke_formula  # slipnames imports this module's neighbours

    text = " = ".join(where) if isinstance(where, tuple) else where.text

    if not found or any(m.name != "masses_swapped" for m in found) or HALF.search(text):
        return found
    return [] if ke_formula(ctx, bad, holds) == "ke_formula" else found
