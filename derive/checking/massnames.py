"""A Greek letter's name set equal to masses alone is the student's own name, not a product.

``mu = (m)(9m)/(10m) = 9m/10`` (the reduced mass, μ = m₁m₂/(m₁ + m₂)): where m and u are the
problem's, "mu" is read as m times u; but a momentum is never a mass alone, so a name whose
relation has masses and numbers only on its other sides is a name of the student's own.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from derive.checking.context import Context
from derive.mathtext.reader import Relation
from derive.problem.units import MASS

_MASS_LETTER = re.compile(r"[mM](?:_?[AB12])?")


def mass_named(ctx: Context, relations: Iterable[Relation]) -> set[str]:
    """The one-word left sides of ``relations`` whose other sides hold masses and numbers only."""
    masses = {g.name for g in ctx.problem.givens if g.dim == MASS}
    out = set()
    for r in relations:
        left = r.sides[0].strip()
        if not re.fullmatch(r"[A-Za-z]\w*", left) or len(r.sides) < 2:
            continue
        names = re.findall(r"[A-Za-z]\w*", " ".join(r.sides[1:]))
        if names and all(n in masses or _MASS_LETTER.fullmatch(n) for n in names):
            out.add(left)
    return out
