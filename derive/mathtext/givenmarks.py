"""What a student writes around a result that is no part of its value, as a teacher reads it:
the mark of an answer the question gave (``(A.G.)``, ``(AG)``, ``[AG]``, ``(answer given)``,
``(as req'd)``, ``(shown)``, ``Q.E.D.``, ``∎``, a star: ``* as required``); the figures it is given to (``(to 3 s.f.)``,
``(2 d.p.)``); a doubt after it (``e = 2.5 ??? supposed to be 0.8``), a remark after a dash
(``… --- not the 5 - 3e in the question``) or in brackets of five words or more; words after a
comma with no relation in them (``= 3.46 m/s, B at 5 m/s along the line of impact``); square
brackets around a whole line of answers (``[ speed of Q = u , e = 1/2 ]``)."""

from __future__ import annotations

import re

#: The mark in brackets (round or square) at the end of a line.
_BRACKETED = re.compile(
    r"(?<!\s)\s*[(\[]\s*(?:A\.?\s?G\.?|answer\s+given|given\s+answer|as\s+(?:req(?:uired|'?d|\.)?|expected|given)"
    r"|(?:hence\s+)?(?:shown|proved|proven)|Q\.?E\.?D\.?)\s*[)\]]\s*\.?\s*$",
    re.I,
)
#: The mark with no brackets, after a value (``= mu^2(1 - e^2)  A.G.``, ``… ∎``), the mark schemes'
#: star of a printed answer, alone or with words (``tan β = e tan α  *``, ``* as required``, ``shown``).
_BARE = re.compile(
    r"(?<=[\w)°.²³}])\s+(?:\*\s*)?(?:A\.G\.?|AG|Q\.E\.D\.?|QED|as\s+(?:req(?:uired|'?d|\.))|(?:hence\s+)?shown)"
    r"\s*[.!]?\s*$|(?<=[\w)°.²³}])\s+\*\s*$|(?<!\s)\s*[∎□■]\s*$",
    re.I,
)
#: The figures a value is given to, in brackets (``(to 3 s.f.)``, ``(3sf)``, ``(2 d.p.)``).
_FIGURES = re.compile(
    r"(?<!\s)\s*\(\s*(?:(?:correct\s+)?to\s+)?\d\s*(?:s\.?\s?f\.?|d\.?\s?p\.?|sig\.?\s*figs?\.?|significant\s+figures"
    r"|decimal\s+places)\s*\)",
    re.I,
)
#: A doubt after a value: two question marks or more, then words (``= 2.5 ??? supposed to be 0.8``).
_DOUBT = re.compile(r"(?<=[\w)°%.])\s*\?{2,}\s*(?:[A-Za-z](?:[^=()]|\([^=()]*\))*)?$")
#: A remark after a dash, words to the end with no relation in them (an expression in brackets among
#: them, ``-- the question has (e + 3), must have a sign wrong``, is what the words talk about).
_DASH = re.compile(
    r"(?<!\s)\s+(?:-{2,3}|—|–)\s+(?=[A-Za-z']{2,}\s+[A-Za-z']{2,}"
    r"|(?!(?:sin|cos|tan|sqrt|exp|log)\b)[A-Za-z']{3,}\b[^=]*?\b[A-Za-z']{2,})(?:[^=()]|\([^=()]*\))*$"
)  # "-- not 4, check?": a number among the words too
#: A remark in brackets at the end: five words or more, no relation (``(B only gets … but ok)``).
_WORDY = re.compile(r"(?<!\s)\s+\((?=(?:[^()=]*?[A-Za-z']{2,}\b){5})[^()=]*\)\s*[.!?]*\s*$")
#: Words after a comma that ends a relation's value, none of them a relation nor in brackets.
_TRAILING = re.compile(r"(=[^=,()]*\d[^=,()]*?)\s*,\s+(?=[^=()]*\b[A-Za-z]{2,}\s+[A-Za-z]{2,}\b)[^=()]*$")
#: Words that say which way a value points (``, to the left``, ``(in the opposite direction)``):
#: its sign, kept for the reader of directions.
_WAY = re.compile(
    r"\b(?:left|right|up|down|upwards?|downwards?|away|towards?|back|backwards?|forwards?|opposite|reverse[ds]?"
    r"|direction|same\s+way|other\s+way|rebounds?|bounces?)\b",
    re.I,
)
#: Words by which a student takes the value before them back (``-- wrong, redo below``, ``?? no``):
#: the line withdrawn, not a remark to take off (``?? can't find my mistake`` is a doubt, kept).
_TAKEN_BACK = re.compile(
    r"^[\W_]*(?:nope|no)\b(?!\s+(?:idea|clue))|\b(?:redo(?:ne)?|ignore|scrap|scratch|crossed\s+out|start(?:ing)?\s+again)\b",
    re.I,
)
#: A way after a dash (``-- in the opposite direction to A``), said as a way, not ``the t part is right``.
_DASH_WAY = re.compile(
    r"\b(?:to\s+the\s+(?:left|right)|leftwards?|rightwards?|upwards?|downwards?|away\s+from|towards?|backwards?"
    r"|forwards?|opposite|reverse[ds]?|(?:same|other)\s+(?:way|direction)|rebounds?|bounces?\s+back)\b",
    re.I,
)
#: Square brackets around a whole line of relations.
_SQUARE_LINE = re.compile(r"^\s*\[([^\[\]]*=[^\[\]]*)\]\s*$")


def without_doubt(text: str) -> str:
    """``text`` without a doubt after its value (``e = 2.5 ??? e can't be more than 1``): read
    before a rejection in words is, as the doubt is the student's about the value, no rejection."""
    return _DOUBT.sub(lambda m: m.group(0) if _TAKEN_BACK.search(m.group(0).lstrip(" ?")) else "", text)


#: The figures of a value rounded in brackets after the value (``= 0.7125 (0.713 3sf)``, ``(0.71, 2 d.p.)``).
_FIGURES_INSIDE = re.compile(
    r"(?<=\d)(?:\s*,\s*|\s+)(?:(?:correct\s+)?to\s+)?\d\s*(?:s\.?\s?f\.?|d\.?\s?p\.?|sig\.?\s*figs?\.?)\s*(?=\)\s*\.?\s*$)",
    re.I,
)


def without_given_mark(text: str) -> str:
    """``text`` without the marks and remarks around its result (no part of its value)."""
    text = _SQUARE_LINE.sub(r"\1", _FIGURES.sub("", _FIGURES_INSIDE.sub("", text)))
    text = _DASH.sub(_unless_taken_back, without_doubt(_WORDY.sub(_unless_a_way, text)))
    text = _TRAILING.sub(lambda m: m.group(0) if _WAY.search(m.group(0)[len(m.group(1)) :]) else m.group(1), text)
    return _BARE.sub("", _BRACKETED.sub("", text))


def _unless_a_way(m: re.Match) -> str:
    """A remark in brackets taken off, unless it says which way the value points (and is no
    musing: ``…`` or ``...`` in it)."""
    remark = m.group(0)
    return remark if _WAY.search(remark) and not re.search(r"\.{3}|…", remark) else ""


def _unless_taken_back(m: re.Match) -> str:
    """A remark after a dash taken off, unless it takes the value back (``-- wrong, redo``) or
    says which way it points (``-- in the opposite direction to A``)."""
    remark = re.sub(r"^\s*(?:-+|—|–)", "", m.group(0))
    return m.group(0) if _TAKEN_BACK.search(remark) or _DASH_WAY.search(remark) else ""
