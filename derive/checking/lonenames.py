"""A relation's left side written as a name alone: the mark of a definition (a relation is a
definition only where its left side is the name alone)."""

from __future__ import annotations

import re


def lone_name(side: str) -> bool:
    """Whether a relation's left side is written as a name alone (``w``, ``v_B'``, ``(v_B)_2``),
    not as an equation the student goes on to solve that only simplifies to one: a difference
    ``w - 0``, a multiple ``1 w``, a product or a quotient (the law of restitution's
    ``b - 0 = 0.8(a - sqrt3)``, which a teacher marks as that law, not as naming b)."""
    return re.search(r"[-+*/×÷−·]|^\s*\d|[\w')}]\s+[\w(\\]", side.strip()) is None
