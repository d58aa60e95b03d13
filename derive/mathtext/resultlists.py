"""Results listed by body, each a body's letter, a colon and a speed (``A: 6.94 ft/s, B: 3.60 ft/s
along the line of centers, J = 169 lb·s``, ``P: 2.4 m/s; Q: 1.2 m/s``): the speeds after the
impact, as a teacher reads a line of answers, written out as relations (``speed of A = 6.94 ft/s``).

Only a line that lists two bodies or more so, and says nothing of before, the givens or the start
(``Given: … A: 8 ft/s at 30°. B at rest.`` is the data, not a result; nor is ``Speeds: A: 5 m/s, B:
5 m/s (towards each other)``), and lists no number with a sign (``A: -1 m/s, B: 7 m/s`` are
velocities, which a speed is not).

>>> listed_speeds("A: 6.94 ft/s, B: 3.60 ft/s along the line of centers, J = 169 lb·s")
'speed of A = 6.94 ft/s, speed of B = 3.60 ft/s along the line of centers, J = 169 lb·s'
>>> listed_speeds("Given: A: 8 ft/s, B: 0 m/s")
'Given: A: 8 ft/s, B: 0 m/s'
>>> listed_speeds("Final velocities: A: -1 m/s, B: 7 m/s")
'Final velocities: A: -1 m/s, B: 7 m/s'
"""

from __future__ import annotations

import re

#: A speed's unit after its number.
_SPEED = r"(?:m\s*/\s*s|ft\s*/\s*s|km\s*/\s*h|mph|ms\^?-1|m\s*s\^?\(?-1\)?)"
#: A body's letter, a colon, a number and a speed's unit (not a lead-in before a relation).
_ITEM = re.compile(rf"(?<![\w'’])([A-Z])\s*:\s*(?=[-+]?\d[\d.]*\s*{_SPEED}(?![\w/]))")
#: Words that put a line before the impact or among the givens.
_BEFORE = re.compile(
    r"\b(?:before|given|initial(?:ly)?|at\s+first|approach\w*|data|towards?\s+each\s+other|head[\s-]on)\b", re.I
)
#: A listed number with a sign (``A: -1 m/s``): a velocity, not the speed this reads it as.
_SIGNED = re.compile(r"\s*[-+−]")


#: A conclusion's one result typed on a phone, a body's letter and its speed with no colon, another
#: relation after it: ``so B 1.5m/s e=0.1``, ``ans A 2 m/s, e = 0.5``.
_CONCLUDED = re.compile(
    rf"^(\s*(?:so|ans(?:wer)?s?|therefore|hence)\b[\s:]*)([A-Z])\s+([-+]?\d[\d.]*\s*{_SPEED})(?![\w/])\s*,?\s*(?=\S+\s*=)",
    re.I,
)


def listed_speeds(plain: str) -> str:
    """``plain`` with each body's speed listed as ``X: 2.4 m/s`` written ``speed of X = 2.4 m/s``,
    where it lists two bodies or more and is no line of givens (or one body in a conclusion, ``so B
    1.5m/s e=0.1``, before another relation); unchanged otherwise."""
    concluded = _CONCLUDED.match(plain)
    if concluded and not _BEFORE.search(plain):
        return f"{concluded[1]}speed of {concluded[2]} = {concluded[3]}, " + plain[concluded.end() :]
    items = list(_ITEM.finditer(plain))
    if len({m[1] for m in items}) < 2 or _BEFORE.search(plain) or any(_SIGNED.match(plain, m.end()) for m in items):
        return plain
    return _ITEM.sub(lambda m: f"speed of {m[1]} = ", plain)
