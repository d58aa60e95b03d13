"""Quantities a student says in words rather than names, as a teacher reads them: an ``x`` for
times beside one (``speed after = e x speed before``), and bodies said to move off together by
the problem's givens (the same velocity after given to both, as e = 0 is).
"""

from __future__ import annotations

import re

#: An ``x`` for times beside a quantity said in words, rewritten as a name (``e x speed_before``,
#: ``speed_before x e``): never the letter x.
_TIMES_WORDS = re.compile(r"(?<=\S)\s+x\s+(?=(?:speed|velocity)_(?:after|before)\b)|(?<=_after|before)\s+x\s+(?=\S)")


def times_beside_words(text: str) -> str:
    """``text`` with each ``x`` beside a quantity said in words written as ``*``."""
    return _TIMES_WORDS.sub(" * ", text)


def together(problem: object) -> bool:
    """Whether the bodies move off together: e = 0 given, or the same velocity after given to both
    (``v_A2 = v_B2 = 6 m/s``: "they lock together and move off at 6 m/s")."""
    givens = getattr(problem, "givens", ())
    after = {g.name: g.value for g in givens if g.name in ("v_A2", "v_B2") and not g.unknown}
    return any(g.name == "e" and g.value == 0 for g in givens) or (len(after) == 2 and len(set(after.values())) == 1)
