"""A momentum named with the common mass cancelled: "I cancel the m straight away", then
``p_before = 2u_P - 3u_Q`` where the masses are 2m and 3m. The student's p is the momentum
divided by m, as a teacher reads it; read as the momentum itself, the right line is false by the
factor m (and a "masses swapped" slip was found for it).
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context

#: Words that say the common mass is cancelled: "cancel the m", "the m's cancel", "divide by m".
_CANCEL = re.compile(
    r"\bcancel\w*\s+(?:the\s+|an?\s+|each\s+)?m\b(?!\w)|\bm\s*['’]?s?\s+cancel|\bdivid\w*\s+(?:through\s+|all\s+)?by\s+m\b",
    re.I,
)

#: A momentum named and set equal to something (``p_before =``, ``p_i =``, ``p =``).
_MOMENTUM = re.compile(r"(?<![\w\\])p(?:_?\w+)?\s*=")


def cancelled_mass(ctx: Context, text: str) -> sympy.Expr | None:
    """The common mass letter m where ``text`` says it is cancelled (before a momentum is first
    named) and each body's mass is a number times m; None otherwise."""
    plain = re.sub(r"[$\\{}]|\\mathrm|\\text", "", text)
    said, first = _CANCEL.search(plain), _MOMENTUM.search(plain)
    if said is None or (first is not None and first.start() < said.start()):  # p = 10mu, then "the m's cancel"
        return None
    names = ctx.equation_names()
    if "m" not in names:
        return None
    m = names["m"][0]
    defs = ctx.definitions()
    masses = [ctx.model.m_A] if ctx.problem.fixed_B else [ctx.model.m_A, ctx.model.m_B]
    ratios = [sympy.simplify(sympy.sympify(x).xreplace(defs) / m) for x in masses]
    return m if all(not r.free_symbols and r != 0 for r in ratios) else None
