"""A speed said in a sentence, as a teacher reads a conclusion: "so the sports car was doing about
21.5 m/s (≈ 77.5 km/h)", "B is moving at 2.4 m/s (= 8.6 km/h)". The body is the sentence's subject
and the verb says its speed: the line is read as ``speed of the sports car = 21.5 m/s``.

Only a sentence that holds a relation's sign after its number (the same speed in another unit,
``(≈ 77.5 km/h)``) is read so: a teacher marks a line with ``=`` or ``≈`` and does not mark one
without (``the car was doing about 15.2 m/s (~55 km/h)`` is prose).

>>> said_doing("so the car was doing about 21.5 m/s (≈ 77.5 km/h).")
'speed of the car = 21.5 m/s (≈ 77.5 km/h).'
"""

from __future__ import annotations

import re

#: The subject, a verb of motion and the number, with a relation's sign after its unit.
_DOING = re.compile(
    r"^\s*(?:so\s+|hence\s+|therefore\s+|thus\s+)?(?P<body>(?:the\s+)?(?:[A-Za-z][A-Za-z'’]*\s+){0,2}?[A-Za-z][A-Za-z'’]*)"
    r"\s+(?:was|is|were|are)\s+(?:doing|going|travell?ing|moving|driving|heading)(?:\s+at)?"
    r"\s+(?:about\s+|approximately\s+|approx\.?\s+|roughly\s+|around\s+|nearly\s+|just\s+(?:over|under)\s+)?"
    r"(?=[-+−]?\d[\d.]*\s*(?:m/s|km/h|kmh|kph|mph|ft/s|mi/h|m\s*s\^?-1)\s*\(?\s*(?:=|≈))",
    re.I,
)
#: Subjects that are no body (``it is going``, ``this was``): pronouns and words of the working.
_NOT_A_BODY = re.compile(r"^(?:it|this|that|which|answer|result|value|number)$", re.I)


def said_doing(text: str) -> str:
    """``text`` with a body's speed said by a verb of motion written as a relation (``speed of the
    car = 21.5 m/s …``); any other text as it is."""
    m = _DOING.match(text)
    if m is None or _NOT_A_BODY.match(m["body"]) or "=" in text[: m.end()]:
        return text
    return f"speed of {m['body']} = {text[m.end() :]}"
