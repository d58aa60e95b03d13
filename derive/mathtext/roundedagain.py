"""A value in letters said again in brackets to fewer figures: ``KE lost = 27.216m J  (27.2m J)``,
``= 0.3888mu^2 (0.389mu^2)``. The bracket is the student's rounding, not a factor of the side.

>>> without_rounded_again("KE lost = 28m - 0.784m = 27.216m J  (27.2m J)")
'KE lost = 28m - 0.784m = 27.216m J'
>>> without_rounded_again("T = 2.56m (2.7m)")
'T = 2.56m (2.7m)'
"""

from __future__ import annotations

import re

#: A number with letters (and a unit) after it, then the same letters after another number in brackets.
_AGAIN = re.compile(
    r"(?<![\w.])(?P<value>\d+\.\d+)\s*(?P<rest>[A-Za-z][\w^ ]{0,12}?)\s+"
    r"\(\s*(?:≈|=|~|\\approx)?\s*(?P<more>\d+\.\d+)\s*(?P=rest)\s*\)\s*$"
)


def without_rounded_again(text: str) -> str:
    """``text`` without a bracket at its end that says its last value again, rounded (the same
    letters after it); any other text as it is."""
    m = _AGAIN.search(text)
    if m is None or not _rounded(m["value"], m["more"]):
        return text
    return text[: m.end("rest")].rstrip()


def _rounded(value: str, more: str) -> bool:
    """Whether ``more`` is ``value`` at fewer decimal places (27.2 of 27.216; not 2.7 of 2.56)."""
    places = len(more.partition(".")[2])
    if places >= len(value.partition(".")[2]):
        return False
    return abs(float(value) - float(more)) <= 0.5 * 10**-places + 1e-12
