"""The marks a student puts after the result a question gave them to show, as a mark scheme
writes them: ``(A.G.)``, ``(AG)``, ``[AG]``, ``(answer given)``, ``(as req'd)``, ``(shown)``,
``(proved)``, ``Q.E.D.``, ``∎``. The mark says "this is the answer given", no part of the value."""

from __future__ import annotations

import re

#: The mark in brackets (round or square) at the end of a line.
_BRACKETED = re.compile(
    r"\s*[(\[]\s*(?:A\.?\s?G\.?|answer\s+given|given\s+answer|as\s+(?:req(?:uired|'?d|\.)?|expected|given)"
    r"|(?:hence\s+)?(?:shown|proved|proven)|Q\.?E\.?D\.?)\s*[)\]]\s*\.?\s*$",
    re.I,
)
#: The mark with no brackets, after a value (``= mu^2(1 - e^2)  A.G.``, ``… ∎``).
_BARE = re.compile(r"(?<=[\w)°.²³])\s+(?:A\.G\.?|AG|Q\.E\.D\.?|QED)\s*$|\s*[∎□■]\s*$")


def without_given_mark(text: str) -> str:
    """``text`` without the mark of an answer given at its end."""
    return _BARE.sub("", _BRACKETED.sub("", text))
