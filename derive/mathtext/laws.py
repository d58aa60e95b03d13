"""Laws of motion quoted in their textbook letters before they are used: a formula stated, not a
claim about the problem, which a teacher does not mark."""

from __future__ import annotations

import re

#: Laws of motion quoted in their textbook letters before they are used (``v^2 = u^2 + 2as``,
#: ``v = u + at``, ``s = ut + ½at²``, ``F = ma``): a formula stated, not a claim about the problem,
#: which a teacher does not mark. Written without spaces or times signs, ``²`` as ``^2``.
_LAWS = frozenset(
    {
        "v^2=u^2+2as",
        "v^2=u^2-2as",
        "v^2-u^2=2as",
        "v=u+at",
        "v=u-at",
        "s=ut+1/2at^2",
        "s=ut-1/2at^2",
        "s=ut+at^2/2",
        "s=1/2(u+v)t",
        "s=(u+v)t/2",
        "s=(u+v)/2t",
        "s=((u+v)/2)t",
        "s=vt-1/2at^2",
        "F=ma",
        "v^2=u^2+2gs",
        "v^2=u^2-2gs",
        "v=u+gt",
        "v=u-gt",
        "s=ut+1/2gt^2",
        "s=ut-1/2gt^2",
    }
)


def quoted_law(sides: tuple[str, ...]) -> bool:
    """Whether a relation of two sides is a law of motion quoted in its textbook letters (either
    side first), after words that lead to it or not (``using v^2 = u^2 + 2as``): a formula stated
    before it is used."""
    if len(sides) != 2:
        return False
    sides = (re.sub(r"^\s*(?:[A-Za-z]{2,}[,:]?\s+)+", "", sides[0]), sides[1])  # "using v^2 = …": words before it
    plain = [re.sub(r"[\s*·×]", "", s).replace("²", "^2").replace("½", "1/2").replace("(1/2)", "1/2") for s in sides]
    return f"{plain[0]}={plain[1]}" in _LAWS or f"{plain[1]}={plain[0]}" in _LAWS
