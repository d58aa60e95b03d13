"""Arrows a student types that are not "so": a sign convention's mark before a relation, as the
engineering texts write it (``(+→)``, ``(→+)``, ``(+->)``, ``(+↑)``), and an arrow after a value
where its relation ends (``= 1.6 m/s ←``, ``4 m/s (→)``, ``0.5 m/s ->,``): the direction it points,
said in words ("to the left"), as the reader reads a direction in words.

>>> arrows_said("(+->) 2x = 3, v = 1.6 m/s (<-)")
'  2x = 3, v = 1.6 m/s to the left'
"""

from __future__ import annotations

import re

#: An arrow after a value, where the relation ends (``= 1.6 m/s ←``, ``4 m/s (→)``, ``0.5 m/s ->,``): the
#: direction it points, as words say it ("to the left"), not "so".
_ARROW_DIRECTION = re.compile(
    r"(?<=[\w/)°.²³¹}])[ \t]{0,8}(?:\([ \t]{0,3})?(?:(←|⟵|<-{1,2}|\\(?:long)?leftarrow)|(↓|\\downarrow)|(↑|\\uparrow)|→|⟶|-{1,2}>|\\(?:long)?rightarrow)"
    r"[ \t]{0,3}\)?(?=(?:\s|\\q?quad\b|\\[,;:! ])*(?:$|[,;]|\.\s*$|(?:\**|\\text(?:bf|it)?\{)\s*\(?\s*[Aa]ns\b\.?\s*\)?\s*[*}]*\s*(?:$|;)))"
    # "← **Ans.**", "\leftarrow \qquad \textbf{Ans.}" (LaTeX's spacing between); a pointer "<- answer" is no direction
)
_ARROWS = r"→|⟶|-{1,2}>|←|⟵|<-{1,2}|↑|↓|\\(?:long)?(?:right|left)arrow|\\(?:up|down)arrow"
#: A sign convention's mark before a relation, as engineering texts write it: ``(+→)``, ``(→+)``,
#: ``(+->)``, ``(+↑)``, ``+→:`` (the direction itself is read from the values, as words are).
_CONVENTION_MARK = re.compile(rf"\(\s*(?:\+\s*(?:{_ARROWS})|(?:{_ARROWS})\s*\+)\s*\)|^\s*\+\s*(?:{_ARROWS})\s*:?")


def arrows_said(plain: str) -> str:
    """``plain`` without the marks of a sign convention and with each arrow after a value in
    words; an arrow between two relations (``x = 2 -> y = 3``) is left to mean "so"."""
    plain = _CONVENTION_MARK.sub(" ", plain)
    return _ARROW_DIRECTION.sub(_said, plain)


def _said(m: re.Match[str]) -> str:
    """The direction an arrow after a value points, in words (``↓``: downwards)."""
    said = " to the left" if m[1] else " downwards" if m[2] else " upwards" if m[3] else " to the right"
    after = m.string[m.end() : m.end() + 1]
    said += " " if after and (after.isalnum() or after in "*(\\") else ""  # "← **Ans.**": a word apart
    return said + ")" if m[0].rstrip().endswith(")") and "(" not in m[0] else said  # "(0.2 ←)": its bracket stays


#: A line of a display that starts with an arrow that means "so" (``\quad\Longrightarrow\quad \tan\beta = …``,
#: ``\implies v = 2``, ``⇒ v = 2``): a new relation, on the line it is typed on.
_SO_FIRST = re.compile(
    r"^\s*(?:&\s*)?(?:\\(?:q?quad|[,;:! ])\s*)*(?:⇒|⟹|\\(?:Rightarrow|Longrightarrow|implies|therefore)(?![A-Za-z])|∴)"
)


def starts_with_so(row: str) -> bool:
    """Whether ``row`` (a line of a display, LaTeX as typed) starts with an arrow that means "so"."""
    return _SO_FIRST.match(row) is not None
