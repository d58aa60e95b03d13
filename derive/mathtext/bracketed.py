"""A name in brackets with its marks after them, as the engineering textbooks write it
(Hibbeler, Beer & Johnston): ``(v_A)_1``, ``(v_A)_2``, ``(v_A)'``, ``(v_B)_{2x}``, ``(v_A)_n'``,
and typed in plain text ``(vA)1``, ``(vB)2``, ``(vA)n1`` (the component before the time: ``v_A1n``),
``(vA1)n``, ``(v_B2)t`` (body and instant inside, the component glued after: ``v_A1n``, ``v_B2t``;
a bare ``(v)t``, with no body inside, stays a product);
one body's ``(v)_1``, ``(v)2`` (its velocity before and after) the same way (``v_1``, ``v_2``). The brackets only hold the name together: what
follows them (a time, a component, a prime) is the name's own mark, so the whole is one name
(``v_A1``, ``v_A'``, ``v_B2x``, ``v_An'``; marks parted by a comma too, ``(v_A)_{n,2}``: ``v_An2``),
and a factor written before it stays a factor (``20 (v_A)'`` is 20 times ``v_A'``, ``mA(vA)1``
is ``mA`` times ``v_A1``).

A bracket around a name with no mark after it (``(v_A) - (v_B)``) is left as it is; so is one
around more than a name (``(v_A - v_B)_2`` is not a name).

>>> bracketed_names("20 (v_A)' + 35(0.3) = mA(vA)1 + (v_B)_{2x}")
"20 v_A' + 35(0.3) = mA v_A1 + v_B2x"
>>> bracketed_names(r"m(v_A)_{2x} + (v_{B})_n'", tex=True)
"m v_{A2x} + v_{Bn}'"
"""

from __future__ import annotations

import re

#: Primes typed inside the brackets, after the name or before its subscript (``(v_1')_n``,
#: ``(v'_1)_n``, ``(v_A^{\\prime})_t``): after, as a prime outside them is.
_PRIMES_IN = r"((?:\s*(?:'|’|\^\s*\\prime|\^\s*\{\s*\\prime\s*\}))*)"
#: The name inside: a letter and its subscript (``v_A``, ``v_{A}``, ``vA``, ``v_1``); without an
#: underscore the subscript is a capital or a digit (``vA``, ``v1``), never a second small letter.
_INSIDE = (
    r"\(\s*([A-Za-z])"
    + _PRIMES_IN
    + r"(?:_\s*\{?\s*([A-Za-z0-9]{1,2})\s*\}?|([A-Z][0-9]?|[0-9]))?"
    + _PRIMES_IN
    + r"\s*\)"
)
#: A character of a name (a letter, a digit, ``_``), not a power typed as a superscript (``²``):
#: ``(v_B)_2²`` is ``v_B2`` squared.
_NAME_CHAR = r"[^\W¹²³⁰⁴⁵⁶⁷⁸⁹]"
#: The marks after the brackets: a subscript (``_2``, ``_{2x}``, ``_(2)``, ``_n``), or a time
#: glued to them (``(vA)1``, ``(vB)2x``), then primes (``'``, ``^\\prime``, ``^{\\prime}``).
_MARKS = (
    r"(?:_\s*(?:\{\s*([A-Za-z0-9]{1,3}|[A-Za-z0-9]\s*,\s*[A-Za-z0-9])\s*\}|\(\s*([A-Za-z0-9]{1,3}|[A-Za-z0-9]\s*,\s*[A-Za-z0-9])\s*\)"
    rf"|([A-Za-z0-9]{{1,3}})(?!{_NAME_CHAR}|\())"
    rf"|([012][xyntXYNT]?|[xyntXYNT][012]?)(?!{_NAME_CHAR}|[.(]))?"
    r"((?:'|’|\s*\^\s*\\prime|\s*\^\s*\{\s*\\prime\s*\})*)"
)
_BRACKETED = re.compile(_INSIDE + _MARKS)


def bracketed_names(text: str, tex: bool = False) -> str:
    """``text`` with each name in brackets that has marks after them written as one name
    (``v_{A2x}`` in LaTeX), a space before it where a factor is written against it."""

    def one(m: re.Match) -> str:
        letter, sub = m[1], m[3] or m[4] or ""
        after = re.sub(r"\s*,\s*", "", m[6] or m[7] or m[8] or m[9] or "")  # (v_A)_{n,2}: the marks n and 2
        if not sub and (letter not in "uvVw" or not re.fullmatch(r"[12][nt]?|[nt][12]?", after)):
            return m[0]  # "(v)_1", "(v)2": one body's velocity at an instant; "(x)_1", "(v)'" left as they are
        if m[9] and m[9][0].isalpha():
            after = after[::-1]  # "(vA)n1", Hibbeler's component then time: v_A1n
        primes = "'" * sum(_primes(m[i]) for i in (2, 5, 10))
        if not after and not primes:
            return m[0]  # "(v_A) - (v_B)": brackets around a name, nothing after them
        if m[9] and sub and not sub.isalpha() and not (m[9].isalpha() and sub[-1].isdigit()):
            return m[0]  # "(v_1)2": a time glued on only after a body's letter ("(vA)1")
        if m[9] and m[9].isalpha() and not sub:
            return m[0]  # "(v)t": a component glued on only after a body's name ("(vA1)n")
        marks = f"{sub}{after}"
        name = f"{letter}_{{{marks}}}" if tex else f"{letter}_{marks}"
        before = m.string[m.start() - 1] if m.start() else ""
        return (" " if re.fullmatch(r"[\w)]", before) else "") + name + primes

    return _BRACKETED.sub(one, text)


def _primes(marks: str) -> int:
    """How many primes ``marks`` holds (``'``, ``’``, ``\\prime``)."""
    return marks.count("'") + marks.count("’") + marks.count("prime")
