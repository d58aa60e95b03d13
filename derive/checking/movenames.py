"""A name declared by the way a body moves after an impact, in words: "let B move at c afterwards",
"B then moves off with speed w after the impact", "A moves at x just after". The name is the
body's velocity after the impact (a chain's stage that the line names, :mod:`.chainnames`);
"speed" makes it the velocity's size. Only a name right after "at" or "with", and then "after"
or "afterwards", is one: "C moves off at 4 m/s" gives a number, no name."""

from __future__ import annotations

import re

_MOVES = re.compile(
    r"(?<![\w\\])([A-Z])\s+(?:then\s+|now\s+)?(?:moves?|moving|travels?|travell?ing|goes|continues|rebounds?)"
    r"(?:\s+(?:off|on|away|back))?\s+(?:at|with)\s+(?:(?:a\s+|the\s+)?(speed|velocity)\s+(?:of\s+)?)?"
    r"([A-Za-z](?:_\{?\w{1,3}\}?)?)\s+(?:just\s+|immediately\s+)?after(?:wards|\b)"
)


def moves_after(plain: str) -> list[tuple[str, str, bool]]:
    """(name, body, a speed) of each name declared by how a body moves after, in ``plain``."""
    return [(m[3], m[1], bool(m[2]) and m[2].lower() == "speed") for m in _MOVES.finditer(plain)]
