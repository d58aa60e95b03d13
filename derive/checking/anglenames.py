"""An angle after the impact declared in words where the velocity it is the angle of is written
as a name, not as words: "Let β be the angle $\\mathbf{v}_A$ makes with the line of centres",
"θ = the angle between v_B and the wall", "v_A' makes an angle φ with the l.o.c.". A teacher
reads ``v_A`` there as "A's velocity after" (v for a velocity after, u for one before, as the
notes and the textbooks write them), so the words are read as those of :mod:`.wordnames`.
"""

from __future__ import annotations

import re

#: A velocity after written as a name: ``v_A``, ``v_{B}``, ``V_A'``, ``v'_A``, ``\mathbf{v}_A``,
#: ``\vec v_B``, ``\underline{v}_A`` (braces already dropped), the body's letter its subscript.
_VELOCITY_NAME = re.compile(
    r"(?<![\w\\])(?:\\(?:mathbf|vec|boldsymbol|bm|underline|overrightarrow)\s*)?[vV]\s*['’′]?\s*_\s*([A-Za-z])(?:2|f)?(?![A-Za-z0-9])(?:\s*['’′])?"
)

#: Words after the name that say already that it is after the impact.
_SAID_AFTER = re.compile(r"\s*(?:after|afterwards|now)\b", re.I)


def velocities_in_words(plain: str) -> str:
    """``plain`` with each velocity after written as a name put in words: ``the angle v_A makes
    with`` -> ``the angle A's velocity after makes with``."""

    def words(m: re.Match) -> str:
        said = _SAID_AFTER.match(plain, m.end()) is not None  # "v_A after the impact": said already
        return f"{m[1]}'s velocity" + ("" if said else " after")

    return _VELOCITY_NAME.sub(words, plain)
