"""A side that names a body's speed or velocity by the body's letter beside the word, as phones
type it (``speed B = 3U/4``, ``spd A after = 1.2``, ``B vel before = -3``): one quantity of the
problem, read whole, never the letter alone with words before it (``notes.name_after_words``),
so never a name of the student's own that the line would define.

>>> bool(BODY_WORD_SIDE.fullmatch("speed B")), bool(BODY_WORD_SIDE.fullmatch("speed of approach"))
(True, False)
"""

from __future__ import annotations

import re

#: A time said beside a body's quantity: before (initial) or after (final).
WHEN = r"(?:(?:just|immediately)\s+)?(?:after(?:wards)?|before|initial(?:ly)?|final(?:ly)?)"
#: A whole side that is a body's letter beside a word of speed or velocity, in either order, with a
#: time or none (``speed B``, ``spd B after``, ``final speed of B``, ``B vel before``).
BODY_WORD_SIDE = re.compile(
    rf"^\s*(?:(?:(?P<w1>{WHEN})\s+)?(?P<k1>speed|spd|velocity|vel\.?)\s+(?:of\s+)?(?P<b1>(?-i:[AB]))(?:\s+(?P<w2>{WHEN}))?"
    rf"|(?P<b2>(?-i:[AB]))\s+(?P<k2>speed|spd|velocity|vel\.?)(?:\s+(?P<w3>{WHEN}))?)\s*$",
    re.I,
)


def named(m: re.Match) -> str | None:
    """:data:`BODY_WORD_SIDE`'s quantity: that body's speed (``speed_B``, before ``speed_B1``) or
    velocity (``v_B2``, ``v_B1``) at the time said, after where none is said; a velocity only with
    its time said (``vel A = 6`` may be a given velocity before as well as a result): None."""
    body, kind = m["b1"] or m["b2"], (m["k1"] or m["k2"]).lower()
    when = (m["w1"] or m["w2"] or m["w3"] or "").lower().split()[-1:] or [""]
    before = when[0].startswith(("before", "initial"))
    if kind.startswith("s"):
        return f"speed_{body}" + ("1" if before else "")
    return (f"v_{body}" + ("1" if before else "2")) if when[0] else None


def body_side(side: str) -> str | None:
    """The quantity a whole side names by a body's letter beside the word (``speed B``), or None."""
    m = BODY_WORD_SIDE.fullmatch(side)
    return named(m) if m else None
