"""The fixed body of a wall problem named as a body, as the engineering texts write restitution at a
fixed surface: ``e = ((v_W)_2 - (v_A)_2)/((v_A)_1 - (v_W)_1)``, ``(v_C)_1 = (v_C)_2 = 0`` for a
cushion. A velocity named by the surface's word or its capital is the surface's, 0: it does not move.
"""

from __future__ import annotations

import re

#: A fixed body's words; "wall" whatever the statement calls the surface.
_FIXED_WORDS = ("wall", "cushion", "barrier", "buffer")


def fixed_marks(statement: str) -> dict[str, str]:
    """The marks that name the fixed body B: its words the statement uses (and "wall"), and their
    capitals (``W``, ``C``)."""
    out: dict[str, str] = {}
    for word in _FIXED_WORDS:
        if word == "wall" or re.search(rf"\b{word}s?\b", statement, re.I):
            out[word] = "B"
            if word[0].upper() not in "AB":  # a barrier's B is B's letter already, not a mark of its own
                out[word[0].upper()] = "B"
    return out


def names_fixed(name: str, bodies: dict[str, str]) -> bool:
    """Whether ``name``'s marks say the fixed body by its word or capital (``v_C1``, ``v_wall2``), not
    by B's letter or a digit (``bodies``: the marks the caller has, the fixed ones among them)."""
    marks = set(_FIXED_WORDS) | {w[0].upper() for w in _FIXED_WORDS} - {"A", "B"}
    return any(bodies.get(k) == "B" and k in name[1:] for k in marks)
