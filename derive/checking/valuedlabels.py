"""A quantity said in words with its value written straight after it, no "=" or ":" between:
``with approach speed 2 - (-6) = 8``, ``KE before 0.5(2)(9) + 0.5(1)(4) = 11``, ``momentum before
4(3) + 2(-1) = 10``. A teacher reads the words as the quantity the value is worked for ("the
approach speed is 2 - (-6) = 8"), never as that quantity times the first number: a student who
multiplies writes ``2 × approach speed``. So where a relation's first side is words that are one of
the quantities said in words (:data:`.naming.PHRASES`, read whole) followed by a number, the words
are a side of their own, set equal to the working after them.
"""

from __future__ import annotations

import re
from dataclasses import replace

from derive.checking.naming import PHRASES
from derive.mathtext.reader import Relation

#: Words (a quantity said in words), then a space and a number or a bracket that opens one.
#: The working is numbers alone (``x`` or ``×`` for times): no other words, no second quantity after a comma.
_WORDS_THEN_NUMBER = re.compile(
    r"\s*([A-Za-z][A-Za-z'’ ]*?[A-Za-z])\s+([-+−]?\s*(?:\d|\(\s*[-+−]?\s*\d)(?:[^A-Za-z,;]|(?<![A-Za-z])x(?![A-Za-z]))*)"
)


def _one_quantity(words: str) -> bool:
    """Whether ``words`` are, whole, one quantity said in words (``approach speed``: speed_app)."""
    for pattern, name in PHRASES:
        said = re.sub(pattern, name, words, flags=re.I)
        if said != words:
            return re.fullmatch(r"\s*[A-Za-z]\w*'?\s*", said) is not None
    return False


def valued_labels(relations: tuple[Relation, ...]) -> tuple[Relation, ...]:
    """``relations`` with a first side that is a quantity in words and its value
    (``approach speed 2 - (-6)``) split into the two: ``approach speed = 2 - (-6) = 8``."""
    out = []
    for r in relations:
        m = _WORDS_THEN_NUMBER.fullmatch(r.sides[0]) if len(r.sides) >= 2 else None
        if m and _one_quantity(m[1]):
            r = replace(r, sides=(m[1], m[2].strip(), *r.sides[1:]))
        out.append(r)
    return tuple(out)
