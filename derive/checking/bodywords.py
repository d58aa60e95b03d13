"""A body's quantity in words under the problem's own labels of the bodies (``speed of Q after``,
``P's velocity``): read as A and B, as the names in words are, and each line shown as typed.
"""

from __future__ import annotations

import re
from dataclasses import replace

from derive.checking.context import Context
from derive.checking.inference import Read
from derive.checking.statementbodies import statement_bodies
from derive.mathtext.bodysides import WHEN

_WHEN = f"(?i:{WHEN})"

#: A body's quantity in words (``speed of Q after``, ``P's velocity``, ``Q after``), the label between.
_BODY_PHRASE = (
    (r"(\b(?i:speed|velocity|direction|momentum|KE|energy|component|cpt)\s+of\s+)", r"\b"),
    (r"(\b)", r"(?=['’]s\s+(?i:final\s+|initial\s+)?(?i:speed|velocity|momentum|KE|energy|direction|component))"),
    (r"((?:^|[:*,;(]|[⇒→⟹]|[=-]>|\b(?i:so|and|then))\s*)", r"(?=\s+(?i:after|before)\b)"),  # "⇒ Q after ⊥"
    # a whole side, phone-typed: "speed Q = 3U/4", "vel P after = 2", "Q spd = 1.5" (saidwords.BODY_WORD_SIDE)
    (rf"((?:^|[:;,])\s*(?:{_WHEN}\s+)?(?i:speed|spd|velocity|vel\.?)\s+(?:of\s+)?)", rf"(?=(?:\s+{_WHEN})?\s*[=≈])"),
    (r"((?:^|[:;,])\s*)", rf"(?=\s+(?i:speed|spd|velocity|vel\.?)(?:\s+{_WHEN})?\s*[=≈])"),
    # a sign convention: "positive in the direction P was moving"
    (
        r"(\b(?i:direction|way)\s+(?:(?i:that|in\s+which)\s+)?)",
        r"(?=\s+(?i:was|is|had|mov|travel|go|went|head|start)\w*\b)",
    ),
)


def body_words(text: str, ctx: Context) -> str:
    """``text`` with the problem's own labels of the bodies (or the exam's P and Q, matched to A and B
    as the statement says: ``P lies at rest``, Q moving, is derive's A) written A and B where words
    say a body's quantity (``speed of Q after``), as the names in words are read; one letter for
    one, so that every line keeps its length."""
    labels = tuple(getattr(ctx.problem, "labels", ("A", "B")))
    if labels == ("A", "B"):
        said = statement_bodies(ctx)  # {"P": "B", "Q": "A"}: the statement's letters, where it says
        labels = tuple(sorted(said, key=said.get)) if sorted(said.values()) == ["A", "B"] else ("P", "Q")
    if any(len(x) != 1 for x in labels) or set(labels) & {"A", "B"}:
        return text
    for label, body in zip(labels, "AB", strict=True):
        for before, after in _BODY_PHRASE:
            text = re.sub(before + re.escape(label) + after, lambda m, b=body: m.group(1) + b, text, flags=re.M)
    return text


def as_typed(line: Read, text: str, said: str) -> Read:
    """``line`` (read from ``said``, :func:`body_words`) written as the student typed it."""
    if said == text:
        return line
    typed, read = text.splitlines(), said.splitlines()
    n = line.number - 1
    if n >= len(read) or read[n] == typed[n] or line.written not in read[n]:
        return line
    at = read[n].find(line.written)
    return replace(line, written=typed[n][at : at + len(line.written)])
