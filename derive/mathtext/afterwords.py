"""A body's letter that words say is after the impact (``so after the impact B = (w, 2.5)``,
``After the collision A = (a, 12) and B = (b, 0)``): primed, so that ``A = (6, 0)`` before and
``A = (v, 0)`` after are two velocities, as the words make them."""

from __future__ import annotations

import re
from dataclasses import replace
from typing import Any

#: Words that say what follows is after the impact (``so after the impact B = (w, 2.5)``, ``After: A = …``).
_AFTER_WORDS = re.compile(r"\b(?:after(?:wards)?|finally|final)\b(?![^,;]*\bbefore\b)", re.I)


def body_after(written: str, name: str, label: str) -> str:
    """A body's letter alone (``B``) that words before it or its lead-in say is after the impact,
    primed (``B'``): ``A = (6, 0)`` before and ``after the impact A = (v, 0)`` are two velocities."""
    if not re.fullmatch(r"\s*[A-Z]\s*", name) or name.strip() in "UVWIJKEFGT":  # U, V, W: a speed's own name
        return name
    dropped = written[: len(written) - len(name.lstrip())] if written.rstrip().endswith(name.strip()) else ""
    if _AFTER_WORDS.search(dropped) or _AFTER_WORDS.fullmatch(label.strip()):
        return name.strip() + "'"
    return name


def after_on_line(r: Any, main: str, part: str) -> Any:
    """``r`` (a :class:`~.reader.Relation`, or None) with a body's letter alone primed where words earlier on its line say after the impact
    (``After the collision A = (a, 12) and B = (b, 0)``: both after)."""
    at = main.find(part)
    if r is None or at <= 0 or not re.fullmatch(r"[A-Z]", r.sides[0].strip()):
        return r
    before = main[:at]
    m = list(_AFTER_WORDS.finditer(before))
    if not m or re.search(r"\bbefore\b", before[m[-1].end() :], re.I):
        return r
    return replace(r, sides=(body_after(r.sides[0], r.sides[0], "after"), *r.sides[1:]))


#: Words that say what follows is before the impact (``before: vA = 4j``, ``Initially v_A = 3``).
_BEFORE_WORDS = re.compile(r"\b(?:before|initially|initial)\b(?![^,;]*\b(?:after(?:wards)?|final(?:ly)?)\b)", re.I)
#: Words of before that end the lead-in to the one body's ``v`` (``before:``, ``Before the impact,``).
_BEFORE_END = re.compile(
    r"\b(?:before|initially|initial)(?:\s+(?:the\s+)?(?:impact|collision|bounce|rebound))?\s*[:,=(\-–]*\s*$", re.I
)
#: A body's velocity with no time mark (``v_A``, ``vB``, ``V_A``; a component: ``v_An``, ``v_Bx``):
#: after by the habits, unless words say before.
_TIMELESS = re.compile(r"\s*([vV])_?([A-Z])([ntxy]?)\s*")


def before_on_line(r: Any, lead: str) -> Any:
    """``r`` (a :class:`~.reader.Relation`) with a body's velocity that has no time mark given the
    time before (``v_A`` as ``v_A1``, ``v_An`` as ``v_A1n``) where its label or ``lead`` (the words
    before it on its line) say before the impact (``before: vA = 4j , vB = -4i``); else as it is."""
    m = _TIMELESS.fullmatch(r.sides[0]) if r.sides else None
    alone = re.fullmatch(r"\s*v\s*", r.sides[0]) if r.sides else None  # "before: v = -4": the one body's
    words = f"{r.label or ''} {lead}"
    said = _BEFORE_WORDS.search(words)
    if (m is None and alone is None) or said is None or _AFTER_WORDS.search(words[said.end() :]):
        return r
    head = re.sub(r"\bv\s*$", "", words.rstrip())  # the words before the v itself
    if m is None and ("=" in head or not _BEFORE_END.search(head)):
        # the one body's v only right after "before:" / "Before the impact," with no relation before
        # it on the line (not "u = -4 m/s before the impact, v = 0.3(4)": that v is the rebound's)
        return r
    return replace(r, sides=(f"{m[1]}_{m[2]}1{m[3]}" if m else "v_i", *r.sides[1:]))


#: A body's letter said before a name, as a lead-in: ``B has u = -2``, ``(so Q has v = 3)``, ``for Q, v = 3``.
_BODY_HAS = re.compile(
    r"^\s*\(?\s*(?:(?:so|and|then|while|whereas)\s+)?(?:[Ff]or\s+([A-Z])\s*,|([A-Z])\s+has)\s+(?=[A-Za-z][\w{}]{0,5}'*\s*=)"
)


def body_lead(text: str) -> tuple[str, str]:
    """(the body's letter as a lead-in, the rest) where ``text`` opens by saying whose the name is
    (``B has u = -2``); ("", ``text``) where it does not."""
    m = _BODY_HAS.match(text)
    return (m.group(1) or m.group(2), text[m.end() :]) if m else ("", text)
