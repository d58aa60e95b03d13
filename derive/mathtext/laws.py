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
        "v^2=u^2+2gh",
        "v^2=u^2-2gh",
        "v=u+gt",
        "v=u-gt",
        "s=ut+1/2gt^2",
        "s=ut-1/2gt^2",
    }
)


def quoted_law(sides: tuple[str, ...]) -> bool:
    """Whether a relation of two sides is a law of motion quoted in its textbook letters (either
    side first), after words that lead to it or not (``using v^2 = u^2 + 2as``), or after a label
    and a colon (``(iii) Upwards positive: v^2 = u^2 + 2as``): a formula stated before it is used."""
    if len(sides) != 2:
        return False
    lead = re.sub(r"^[^=]*:\s*", "", sides[0])  # "(iii) Upwards positive: v^2 = …": a label before a colon
    sides = (re.sub(r"^\s*(?:[A-Za-z]{2,}[,:]?\s+)+", "", lead), sides[1])  # "using v^2 = …": words before it
    plain = [re.sub(r"[\s*·×]", "", s).replace("²", "^2").replace("½", "1/2").replace("(1/2)", "1/2") for s in sides]
    return f"{plain[0]}={plain[1]}" in _LAWS or f"{plain[1]}={plain[0]}" in _LAWS


#: A clause after a quoted law that gives its letters values (``with u = 0``, ``where v = 0``).
_CLAUSE = re.compile(r"\s+(?:with|where|when|taking|given|and)\s+(?=[A-Za-z]\s*=)", re.I)
#: One of a law's letters set to a value, its unit after it (``u = 0``, ``s = 2 m``, ``a = 9.8 m/s^2``).
_LETTER_VALUE = re.compile(
    r"^\s*(?:(?:with|where|when|taking|given|and)\s+)?[uvsatgh]\s*=\s*[-+−]?(?:\d+\.?\d*|\.\d+)"
    r"(?:\s*(?:m|s|m/s|m\s?s\^?-1|m/s\^?2|m/s²|m\s?s\^?-2|ft|ft/s|ft/s\^?2|ft/s²))?\s*[.,;]?\s*$"
)


#: A law and its letters fit in a line of this many characters (a longer piece is not searched).
_SHORT = 160


def with_its_letters(parts: list[str]) -> list[str]:
    """``parts`` (a line's relations, split at commas) without a law quoted in its textbook letters
    and the values of its letters stated with it (``v^2 = u^2 + 2as with u = 0, s = 2 m``): the
    formula and what its letters stand for, stated before it is used, which a teacher does not
    mark. A relation after them (``so v = 6.26``, split at the "so") is kept."""
    out: list[str] = []
    law = False
    for part in parts:
        head, *clause = _CLAUSE.split(part, maxsplit=1) if len(part) <= _SHORT else [part]
        if "=" in head and quoted_law(tuple(head.split("="))):
            law = True
            out += [] if clause and _LETTER_VALUE.match(clause[0]) else [part]
        elif not (law and _LETTER_VALUE.match(part)):
            law = False
            out.append(part)
    return out


def law_and_letters(aside: list[str], main: list[str]) -> list[tuple[str, bool]]:
    """A line's relations, each with whether it is in its aside (after "with", "where"); the aside
    left out where it gives only the values of the letters of the law the main part quotes
    (``Fall: v^2 = u^2 + 2as with u = 0, s = 2 m``), as :func:`with_its_letters` leaves them out."""
    if main and aside and quoted_law(tuple(main[-1].split("="))) and all(_LETTER_VALUE.match(p) for p in aside):
        aside = []
    return [(p, True) for p in aside] + [(p, False) for p in main]
