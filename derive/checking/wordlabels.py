"""A relation's first side in words that names a quantity of the problem, where no letter does:
``impulse = -11.2 N s`` (the impact's impulse, its size signed as the number written), ``mass of
the parked car = 800 kg`` (the one mass the problem asks for, where the student names it M).

:func:`word_label` is what :func:`.inference._parse` asks of a first side it cannot read.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.naming import Open

#: "impulse", "the impulse on the ball": the word alone (a body by its letter is :mod:`.valuenames`').
_IMPULSE = re.compile(r"\s*(?:the\s+)?impulse(?:\s+on\s+the\s+(?:ball|sphere|particle))?\s*", re.I)
#: "mass of parked car", "the mass of the second car": a mass named by words, not by its letter.
_MASS_OF = re.compile(r"\s*(?:the\s+)?mass\s+of\s+(?:the\s+)?(?![AB]\b)[A-Za-z][A-Za-z ]{0,30}?\s*", re.I)


def word_label(side: str, names: Open, last: str) -> sympy.Expr | None:
    """What the words ``side`` name (``last``: the relation's last side, for a sign), in the
    problem's symbols or the student's placeholder for M (the one mass to find, by habit); None
    for words that name nothing."""
    if _IMPULSE.fullmatch(side) and "J_n" in names.known:
        return sympy.sqrt(names.known["J_n"] ** 2) * (-1 if last.strip()[:1] in "-−" else 1)
    if _MASS_OF.fullmatch(side) and "M" in names.extra and "M" not in names.known:
        return names["M"][0]
    return None
