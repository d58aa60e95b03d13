"""Names given to a chain's bodies in a list after "after:" or "before:", written out in words.

Students name the velocities of an impact by listing each body's letter with its name:
``After: A v1, B v2``, ``after impact: A -> x, B -> y``, ``Before: B: u1, C: u2``; and may go on
with a value for the last (``After: B w1, C w2 = 4 (given)``: C's velocity after is the given 4).
Each pair is written out as the declaration a checker reads (``v1 = A after, v2 = B after``),
and a value after the list as a relation of the last name (``w2 = 4 (given)``).
"""

from __future__ import annotations

import re

#: A name a student gives a velocity: a letter, its digits or a short subscript (``v1``, ``w_2``, ``x``).
_NAME = r"[a-z](?:_?\{?[A-Za-z0-9]{1,2}\}?)?"
#: Words after a body's letter that are no name of its velocity (``B at rest``).
_NOT_NAMES = {"at", "is", "in", "on", "to", "of", "by", "be"}
_HEAD = re.compile(r"\b(after|before)\b(?:\s+(?:the\s+)?(?:impact|collision))?\s*:?\s*", re.I)
#: A body's letter, its name, and a value said for it (``C w2 = 4 (given)``, ``A -> p``).
_PAIR = re.compile(rf"([A-Z])\s*(?::|->|→)?\s*({_NAME})(?![\w(])(?:\s*=(?!=)\s*([^,;]*?))?\s*(?=,|;|\band\b|\.?\s*$)")
_SEP = re.compile(r"\s*(?:,|;|\band\b)\s*")


def _labels(ctx) -> set[str]:
    """The letters of the bodies of the chain's impacts."""
    out: set[str] = set()
    for st in getattr(ctx.solution, "stages", ()):
        part = getattr(st, "part", None)
        if part is not None:
            out |= set(part.problem.labels)
    return out


def written_out(ctx, text: str) -> str:
    """``text`` with each list of a body's letter and its name after "after:"/"before:" written
    out as declarations (see the module's words); lines keep their numbers."""
    labels = _labels(ctx)
    return "\n".join(_line(line, labels) for line in text.split("\n")) if labels else text


def _line(line: str, labels: set[str]) -> str:
    for head in reversed(list(_HEAD.finditer(line))):
        pairs, at = [], head.end()
        while (m := _PAIR.match(line, at)) is not None and m.group(1) in labels and m.group(2) not in _NOT_NAMES:
            pairs.append(m)
            sep = _SEP.match(line, m.end())
            at = sep.end() if sep else m.end()
            if sep is None:
                break
        if not pairs:
            continue
        when = head.group(1).lower()
        said = "; ".join(
            f"{_plain(m[2])} = {m[1]} {when}" + (f"; {_plain(m[2])} = {m[3]}" if m[3] else "") for m in pairs
        )
        line = f"{line[: head.end()]}{said}{line[pairs[-1].end() :]}"
    return line


def _plain(name: str) -> str:
    """``v1``, ``v_{1}`` -> ``v_1``: a name as a declaration in words spells it."""
    return re.sub(r"^([a-z])_?\{?([A-Za-z0-9]{1,2})\}?$", r"\1_\2", name)
