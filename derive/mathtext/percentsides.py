"""A percentage worked as a fraction times 100 (``64/352 × 100 = 18.2 %``, ``100 × 0.182 = 18.2%``):
the ``%`` after the number is the label of what was worked, not a division by 100, as a teacher
reads it (``18.2 %`` there is 18.2, the side before it times 100 already)."""

from __future__ import annotations

import re

#: A side that is something times 100 (the 100 first or last, ``x``, ``×``, ``*``, ``·`` between).
_TIMES_100 = re.compile(r"(?:[x×*·]\s*\(?\s*100(?:\.0*)?\s*\)?\s*$|^\s*\(?\s*100(?:\.0*)?\s*\)?\s*[x×*·])")
#: A side that is a number and a percent sign after it.
_PERCENT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+))\s*(?:\\?%|per\s?cent)\s*$", re.I)


def percent_labels(sides: tuple[str, ...]) -> tuple[str, ...]:
    """``sides`` with the ``%`` taken off a percentage that follows a side times 100: the number
    the student worked (``64/352 x 100 = 18.2%`` is 18.18 = 18.2, not 18.18 = 0.182)."""
    out = list(sides)
    for i in range(1, len(out)):
        m = _PERCENT.match(out[i])
        if m and _TIMES_100.search(out[i - 1]):
            out[i] = m.group(1)
    return tuple(out)
