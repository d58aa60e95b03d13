"""Words after a piece of inline mathematics that holds a whole relation: the student's prose,
not part of the relation (``Sub $v_Q = v_P + 5ue$ into (1):``, ``From (2), $x = y - 5eu$. Put
into (1):``), unless they still say its value: a unit (``$v = 3$ m/s``) or a direction in words
(``$v = 1.2$ to the left``).

>>> words_end_it("v_Q = v_P + 5ue", " into (1):")
True
>>> words_end_it("v = 3", " m/s to the left")
False
>>> words_end_it("= 6.5v", ", speed of Q before")
False
"""

from __future__ import annotations

import re

from derive.mathtext.sides import direction_of
from derive.mathtext.units import is_unit

#: Words after a piece of mathematics (``$x = y - 5eu$. Put into (1)``, ``$… = 2u$ into (2)``).
#: (``… \quad (check: $…$)``: TeX's spacing before the words, or a bracket that opens with a word and a colon.)
#: (``…$, A's part along the line of centres.``: a body's possessive opens words too.)
_PROSE_AFTER = re.compile(
    r"^[\s.,;:]*(?:\\q?quad\b\s*|\\[,;: ]\s*)*(?:([A-Za-z]{2,})\b|[A-Z]['’]s\s+[A-Za-z]{2,}|\(\s*([A-Za-z]{2,})[A-Za-z ]*:)"
)


def _whole_relation(plain: str) -> bool:
    """Whether a piece of mathematics is a relation with both sides in it (``x = y - 5eu``, ``μ = 2m/3``; not
    ``= 6.5v``, whose name is in the words before it, nor rows joined by ";")."""
    s = plain.strip()
    signs = [k for k, c in enumerate(s) if c in "=≈"]
    if ";" in plain or not signs:
        return False  # plain code, not one pattern: a long line must not backtrack (hostile input)
    return bool(re.search(r"[^\W_]", s[: signs[0]])) and bool(re.search(r"[A-Za-z0-9)]", s[signs[-1] + 1 :]))


def _said_after(text: str) -> bool:
    """Whether the words after a relation's mathematics still say its value: a unit (``$v = 3$ m/s``)
    or a direction (``$v = 1.2$ to the left``)."""
    token = re.match(r"^[\s.,;:]*([^\s,;]+)", text)
    head = token.group(1).rstrip(".:") if token else ""
    return is_unit(head) or bool(direction_of(f"1 {text.strip(' .,;:')}")) or _UNITISH.match(text) is not None


#: The start of a unit after a number (``kg·m/s``, ``N s``, ``m s^-1``): the unit's, not words.
_UNITISH = re.compile(r"^\s*(?:kg|k?N|k?J|m|s|ft|lb|slugs?|g|km|mph|Ns|rad|deg|degrees)(?![A-Za-z])")


def words_end_it(plain: str, after: str, before: str = "") -> bool:
    """Whether the words ``after`` a piece of mathematics (``plain``, made plain) end the relation
    it holds: a relation with both sides inside, followed by prose that is no unit and no direction,
    or by the bracket that closes one the words ``before`` it opened (``(should lose … with $\\mu =
    \\frac{2m}{3}$):``, ``(And $x = …$)``)."""
    if not _whole_relation(plain):
        return False
    if _CLOSES_PROSE.match(after) and _open_brackets(before) > 0 and _open_brackets(plain) == 0:
        return True
    return _PROSE_AFTER.match(after) is not None and not _said_after(after)


#: A bracket closed right after a piece of mathematics, then the end of the sentence or more words.
_CLOSES_PROSE = re.compile(r"^\s*\)(?:[\s.,;:!?]*$|[\s.,;:]+[A-Za-z])")


def _open_brackets(text: str) -> int:
    """How many round brackets ``text`` leaves open."""
    depth = 0
    for ch in text:
        depth = max(depth + {"(": 1, ")": -1}.get(ch, 0), 0)
    return depth


#: The value said again in brackets that open with "=" (``= 0.346 (= 0.2√3)``, ``≈ 5.29 (= 2√7)``,
#: ``(≈ 0.837)``): the chain goes on, the brackets only set the exact or rounded form aside.
_EQUALS_IN_BRACKETS = re.compile(r"(?<=[\w)}.%°\s])\(\s*([=≈])((?:[^()=≈]|\([^()=≈]*\))+)\)")


def equals_in_brackets(plain: str) -> str:
    """``plain`` with a value said again in brackets that open with ``=`` or ``≈`` written as one
    more side of the chain (``v = 0.346 (= 0.2 sqrt(3))``: ``v = 0.346 = 0.2 sqrt(3)``)."""

    def one(m: re.Match) -> str:
        if not re.search("[=≈]", plain[: m.start()]):
            return m[0]  # "(= …)" before any relation: not a value said again
        last = m[2].split()[-1] if m[2].split() else ""
        if (re.search(r"[A-Za-z]{2}", last) and is_unit(last)) or "%" in m[2]:
            return m[0]  # "E = 2400 J (= 2.4 kJ)", "ΔT = 1385 (≈ 48 %)": another unit or a share, a remark
        return f" {m[1]} {m[2].strip()} "

    return _EQUALS_IN_BRACKETS.sub(one, plain)


#: Where the student says a relation goes next, after it (``v1 = v2 + 4eu, into (1):``, ``… sub into
#: eqn 2``, ``…, put this in the momentum equation``, ``… into CLM``): words, no part of its value.
_VERB = r"(?:sub(?:stitute[ds]?|stituting)?|put(?:ting)?|plug(?:ged|ging)?|insert(?:ed|ing)?|use[ds]?|using)"
_TARGET = (
    r"(?:\(\s*(?:\d{1,2}[a-z]?|[ivx]{1,4})\s*\)|eq(?:n|uation)?s?\.?\s*\(?\d{1,2}\)?|(?:the\s+)?(?:first|second|other|last|momentum"
    r"|restitution|energy|CLM|NEL|PCLM|NLR|COLM)(?:\s+(?:one|equation|eqn|law|relation|line))?)"
)
_INTO_END = re.compile(
    rf"(?:,\s*|\s+)(?:(?:and|then|now)\s+)?(?:{_VERB}\s+(?:(?:this|it|that|them)\s+)?(?:back\s+)?(?:into|in|to)"
    rf"|(?:(?:this|it|that)\s+)?(?:back\s+)?into|(?:in|to)(?=\s+{_TARGET}))(?:\s+{_TARGET})?\s*[.:;!]?\s*$",
    re.I,
)


def without_into(side: str) -> str:
    """``side`` without the words after it that say where it is put next (``v2 + 4eu, into (1):``)."""
    return _INTO_END.sub("", side)
