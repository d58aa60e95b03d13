"""Speeds before named in words for bodies that move towards each other (``let p = speed of P
before, q = speed of Q before (towards each other)``): B's speed is minus its velocity along
derive's n (from A toward B), A's is its velocity, as the words make them. Only where B does move
toward A in the problem: "head-on" says a direct impact, also of a body catching up with another.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

import sympy

if TYPE_CHECKING:
    from derive.checking.context import Context

#: Words that say the bodies approach head-on.
_TOWARD = re.compile(
    r"\b(?:towards?|approaching)\s+each\s+other\b|\bhead[\s-]on\b|\bin\s+opposite\s+directions\b", re.I
)


def toward(plain: str, when: str, body: str, ctx: Context | None = None) -> int:
    """-1 where ``plain`` names B's speed before (``body`` "B", ``when`` "before") and it or the
    problem's statement says the bodies move towards each other (or in opposite directions), as B
    does in the problem (``ctx``'s, where given); else 1."""
    if body != "B" or when.lower() != "before" or not re.search(r"\bspeeds?\b", plain, re.I):
        return 1
    if ctx is not None and original_way(ctx, -1) >= 0:  # B at rest, or moving A's way (caught up): not towards A
        return 1
    statement = (getattr(ctx.problem, "statement", "") or "") if ctx is not None else ""
    return -1 if _TOWARD.search(plain) or _TOWARD.search(statement) else 1  # the line's words, or the problem's


def original_way(ctx: Context, body: int) -> int:
    """The way along derive's n the body moved before the impact (``body`` 1 for A, -1 for B):
    +1, -1, or 0 where it was at rest; the usual way (A toward B, B toward A) where the problem
    does not say (its velocity before an unknown)."""
    nm = ctx.model.nm
    name = nm.A1n if body == 1 else nm.B1n
    try:
        x = sympy.sympify(ctx.in_unknowns(name))
    except (TypeError, ValueError, AttributeError):
        return body
    if x == sympy.sympify(name):  # the velocity before is itself what is asked: the usual way
        return body
    x = x.xreplace({s: sympy.Dummy(positive=True) for s in x.free_symbols})
    if x == 0:
        return 0
    return 1 if x.is_positive else -1 if x.is_negative else body
