"""A value stored in the calculator's memory and recalled by its letter later: ``KE1 = 0.5(0.240)(3.00^2)
= 1.08 J  [STO -> A]`` then ``KE2 = 0.8^2 * A``; ``(STO A)``, ``→ memory M``, ``(stored in B)``, ``store as
X``. The note is taken off the line it ends, and the letter, where it stands alone in a later
relation, is the stored value (the last side of the relation the note ends), in brackets.

>>> stored("KE1 = 1.08 J     [STO -> A]")
('KE1 = 1.08 J', 'A')
>>> recalled(("KE2", "0.8^2 * A", "0.64*1.08"), {"A": "1.08"})
('KE2', '0.8^2 * (1.08)', '0.64*1.08')
"""

from __future__ import annotations

import re

#: The note that stores a line's value: STO and an arrow, "store(d) in/as", "saved in memory"; a
#: calculator's memory letter (A-F, M, X, Y).
_STORED = re.compile(
    r"(?<!\s)\s*(?:[\[(]\s*)?(?:(?i:sto|stored?|saved?)\s*(?:(?i:in|as|to|into)\s+)?(?:(?i:memory)\s+)?(?:->|→|▶|⇒|=>)?"
    r"|(?:->|→|▶)\s*(?i:sto|memory))\s*([A-FMXY])\s*[\])]?\s*\.?\s*$"
)


def stored(plain: str) -> tuple[str, str]:
    """``plain`` without a note that stores its value in the calculator's memory, and the memory's
    letter ("" where there is no such note)."""
    m = _STORED.search(plain)
    if m is None or "=" not in plain[: m.start()]:
        return plain, ""
    return plain[: m.start()].rstrip(), m.group(1)


def recalled(sides: tuple[str, ...], memory: dict[str, str]) -> tuple[str, ...]:
    """``sides`` with each memory's letter that stands alone (not a name's part, ``v_A``) as the
    value stored in it."""
    if not memory:
        return sides
    letters = re.compile(rf"(?<![\w'.]){'|'.join(map(re.escape, memory))}(?![\w'(])")
    return tuple(letters.sub(lambda m: f"({memory[m.group(0)]})", s) for s in sides)
