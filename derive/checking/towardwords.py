"""Speeds before named in words for bodies that move towards each other (``let p = speed of P
before, q = speed of Q before (towards each other)``): B's speed is minus its velocity along
derive's n (from A toward B), A's is its velocity, as the words make them.
"""

from __future__ import annotations

import re

#: Words that say the bodies approach head-on.
_TOWARD = re.compile(r"\b(?:towards?|approaching)\s+each\s+other\b|\bhead[\s-]on\b", re.I)


def toward(plain: str, when: str, body: str) -> int:
    """-1 where ``plain`` names B's speed before (``body`` "B", ``when`` "before") and says the
    bodies move towards each other; else 1."""
    if body != "B" or when.lower() != "before" or not re.search(r"\bspeeds?\b", plain, re.I):
        return 1
    return -1 if _TOWARD.search(plain) else 1
