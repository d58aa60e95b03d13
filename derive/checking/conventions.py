"""A sign convention a student states in words ("taking away from the wall as positive").

Holds the phrases for derive's n and its reverse; imports nothing of derive.
"""

from __future__ import annotations

import re

#: Fixed bodies students name in their sign conventions.
_FIXED = r"(?:the\s+)?(?:wall|cushion|floor|ground|barrier|plate|surface|board|buffer|bank|side|goal)"
_REVERSED = re.compile(
    rf"revers|opposite|negative|away\s+from\s+{_FIXED}|from\s+b\s+to(?:wards?)?\s+a\b|-n\b"
    r"|\bb'?s\s+(?:initial\s+)?(?:direction|motion)|direction\s+of\s+b\b",
    re.I,
)
_FORWARD = re.compile(
    rf"to(?:wards?)?\s+{_FIXED}|from\s+a\s+to(?:wards?)?\s+b\b|\ba'?s\s+(?:initial\s+)?(?:direction|motion)"
    r"|direction\s+(?:that\s+|in\s+which\s+)?a\s+(?:moves|travels|is\s+(?:moving|travelling)|goes|starts)"
    r"|direction\s+of\s+a\b|\+n\b|^\s*n\b|derive",
    re.I,
)


def sign_of(words: str) -> int:
    """The sign convention a phrase states: -1 reversed (away from the wall, B's direction), +1
    derive's n (from A toward B, toward the wall, A's direction), 0 where it does not say
    (up, down, left, right: inferred from the values)."""
    if _REVERSED.search(words):
        return -1
    return 1 if _FORWARD.search(words) else 0
