"""Asides a student writes around a relation, as a teacher reads them: a rejection that is a sentence
of its own after the case it turns down (``If x = 5u/6 then y = u/3 < x. Reject.``), and a condition
in brackets after a value (``e = 2/3 (e > 0)``, ``v = 3 (v > 0, to the right)``), which says why the
value was taken, not a relation to mark."""

from __future__ import annotations

import re

#: What may stand before a rejection that is a sentence of its own (``… through Q. Reject.``,
#: ``So impossible.``): the sentence it turns down is the one before.
_ALONE = re.compile(r"[\s.;,:]*(?:(?:so|hence|therefore|thus|which\s+is|(?:this|it)\s+is|that's|it's|we)\s+)?", re.I)
#: A rejection that names what it turns down, not the sentence before (``v = 1.36. Reject the other
#: root.``, ``… Discard the negative value.``): the value before is the one kept.
_ELSEWHERE = re.compile(r"\w+\s+(?:the\s+)?(?:other|negative|positive|second|first|smaller|larger|remaining)\b", re.I)
#: A full stop between sentences (``$x = 3$. Reject`` is read ``x = 3 ; . Reject``).
_FULL_STOP = re.compile(r"(?<=[\w)°²³;])\s?\.(?=\s+[A-Z(])")


def case_before(text: str, at: int, start: int) -> int:
    """Where what a rejection at ``at`` turns down starts: its sentence from ``start``, or, where it
    is a sentence of its own (``… P would go through Q. Reject.``), the sentence before it (to the
    full stop before that, not a ";" the reader put between the pieces of mathematics)."""
    if start > 0 and text[start - 1] == ";" and "=" not in text[start:at]:
        # "If $x = 5u/6$ then $y = u/3$, so P goes through Q -- impossible": the words after the
        # last piece of mathematics go on its sentence (the ";" between them is the reader's)
        stops = [s.end() for s in _FULL_STOP.finditer(text) if s.end() <= start]
        return stops[-1] if stops else 0
    stops = [s.end() for s in _FULL_STOP.finditer(text) if s.end() <= at]
    if stops and _ELSEWHERE.match(text, at):
        return max(start, stops[-1])  # "v = 1.36. Reject the other root.": its own sentence only
    if not stops or not _ALONE.fullmatch(text[stops[-1] : at]):
        return start
    return stops[-2] if len(stops) > 1 else 0


def named_after(text: str, end: int) -> int | None:
    """Where the relation a rejection names after it ends (``x = 3. Reject x = -1.``: the rejected
    ``x = -1``, not the ``x = 3`` kept): the end of its sentence; None where no relation follows."""
    if not re.search(r"(?:reject|discard)(?:ed)?$", text[:end], re.I) or not _NAMED.match(text, end):
        return None  # "… is impossible as w < v, so v = u/2": what follows is the value kept
    return next((s.start() for s in _FULL_STOP.finditer(text, end)), len(text))


#: The relation a rejection names right after it (``reject x = -1``, ``discard the root e = -0.8``).
_NAMED = re.compile(r"\s+(?:the\s+(?:root|value|solution|case)\s+)?\$?[A-Za-z][\w{}]*\$?\s*=(?!=)", re.I)


#: An inequality: ``>``, ``<``, ``>=``, ``≥``, ``\\geq`` (LaTeX's made plain: ``>=``).
_INEQUALITY = r"(?:[<>]=?|[≤≥⩽⩾]|=<|=>)"
#: A condition in brackets at the end of a relation (``(e > 0)``, ``(since 0 <= e <= 1)``, ``(v > 0,
#: so to the right)``): an inequality, and no ``=`` but an inequality's.
_CONDITION = re.compile(
    rf"(?<!\s)\s*\(\s*(?:(?:since|as|because|for|with|taking|and|so|need|must\s+have)\s+)?"
    rf"(?=[^()]*{_INEQUALITY})(?:[^()=<>≤≥⩽⩾]|{_INEQUALITY})*\)\s*[.!]?\s*$",
    re.I,
)


#: A clause after a comma that checks the value by an inequality (``= 3 J, fine since e < 1``,
#: ``…, OK as 0 <= e <= 1``): a remark.
_CLAUSE = re.compile(
    rf",\s*(?:[A-Za-z']+\s+){{0,3}}(?:since|as|because|given)\s+(?=[^()=]*{_INEQUALITY})"
    rf"(?:[^()=<>≤≥⩽⩾]|{_INEQUALITY})*[.!]?\s*$",
    re.I,
)


def without_condition(plain: str) -> str:
    """``plain`` without a condition in brackets after its last relation (``e = 2/3 (e > 0)``:
    ``e = 2/3``); unchanged where there is no ``=`` before it (``(e > 0)`` alone is a remark too)."""
    clause = _CLAUSE.search(plain)
    plain = plain[: clause.start()] if clause and "=" in plain[: clause.start()] else plain
    m = _CONDITION.search(plain)
    head = plain[: m.start()].rstrip() if m else ""
    if m is None or "=" not in head.replace("<=", "").replace(">=", "") or head.endswith("="):
        return plain
    return plain[: m.start()]


#: A sign convention in brackets among a quantity's words (``impulse from ground (up +ve) = …``,
#: ``momentum (taking left as positive) = …``, ``J (+ve upwards) = …``): said for the line, no part
#: of the name. (Each pattern's leading gap starts after a character that is not a gap: searched
#: from inside a run of thousands of spaces, it scanned the rest of the run from every one.)
_CONVENTION = re.compile(r"(?<!\s)\s*\(\s*(?=[^()=]*(?:\+\s?ve\b|\bpositive\b))[^()=]{1,60}\)(?=\s*$)", re.I)


def without_convention(plain: str) -> str:
    """``plain`` without a sign convention in brackets at the end of its first side (before its
    first ``=``); the words of the convention stay on the line as written, for the reader of
    conventions."""
    at = plain.find("=")
    if at < 0:
        return plain
    return _CONVENTION.sub("", plain[:at]).rstrip() + " " + plain[at:]
