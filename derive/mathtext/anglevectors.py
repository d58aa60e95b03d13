"""Vectors as US intro-physics students type them: components in angle brackets
(``<4cos30°, 4sin30°> = <3.464, 2>``, ``⟨2, 0⟩``, LaTeX's ``\\langle u\\cos30^\\circ,\\ u\\sin30^\\circ\\rangle``),
a bold letter with its body after it (``**u**_A``), and a LaTeX ``tabular`` row whose cells are
set apart by ``&``. Each is written as the rest of the reader reads it: a pair in round brackets
(:mod:`.vectors` reads ``(a, b)`` as the components along and across the line of centres), the
name ``u_A``, cells set apart by ``;`` as a Markdown table's are (:mod:`.tables`)."""

from __future__ import annotations

import re

#: LaTeX's and Unicode's angle brackets: never an inequality.
_ANGLES = {"\\langle": "(", "\\rangle": ")", "⟨": "(", "⟩": ")", "〈": "(", "〉": ")", "❬": "(", "❭": ")"}
_ANGLE = re.compile("|".join(re.escape(a) for a in _ANGLES))
#: ``<a, b>`` typed with the keyboard's signs: opened where a value starts (the line's start, after
#: ``=``, ``:``, ``;``, ``(``, ``,`` or a table's cell), one comma inside and no other sign of a
#: relation, closed with no ``=`` after it (``>=`` is "at least"). ``e < 1`` opens after a value.
_TYPED = re.compile(r"(^\s*|[=:;(,&≈]\s*)<([^<>=;,]+,[^<>=;,]+)>(?!=)")
#: Words that make ``<…, …>`` prose between two inequalities (``0 < e, so v > 0``), not a vector.
_PROSE = re.compile(r"\b(?:and|so|or|but|if|then|is|are|thus|hence|since)\b", re.I)
#: A bold vector's letter with its subscript after the bold (``**u**_A``, ``__v__'``).
_BOLD = re.compile(r"(\*\*|__)([A-Za-z])\1(?=[_'])")


def angle_vectors(text: str) -> str:
    """``text`` with each vector in angle brackets as a pair in round ones, a bold letter with
    its subscript after it as the plain name, and a ``tabular`` row's ``&`` as a cell's end."""
    text = _ANGLE.sub(lambda m: _ANGLES[m.group(0)], text)
    text = _TYPED.sub(_typed, text)
    text = _BOLD.sub(r"\2", text)
    if text.count("&") >= 2:  # "A & ⟨2, 3.464⟩ & ⟨v_Ax, v_Ay⟩": a table's row (align's & are gone)
        text = text.replace("&", " ; ")
    return text


def _typed(m: re.Match) -> str:
    """One ``<a, b>``: ``(a, b)`` where it is a vector's components, as it was where it is prose."""
    inner = m.group(2)
    if _PROSE.search(inner) or not inner.strip():
        return m.group(0)
    return f"{m.group(1)}({inner})"
