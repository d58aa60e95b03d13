"""A kinetic energy labelled in words before its working: ``KE before: ½(2m)(4)² + ½(3m)(2) =
19m``, ``Kinetic energy after: …``, ``KE lost: …``. The reader leaves the label out (words before
a colon), so the line alone is arithmetic and holds; a teacher marks it against the energy the
label names. :func:`energy_labelled` gives the relation "that energy = the line's first side"
where it does not hold, so the trace judges the line as the slip it is (a speed not squared, a
mass left out: ``ke_formula``) and carries the lines worked from it.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace

from derive.checking.context import Context
from derive.checking.inference import Read
from derive.checking.numeric import decimals
from derive.checking.worlds import Pair

#: The words of a kinetic energy, and of each instant: before, after, lost.
_ENERGY = re.compile(r"(?i)(?<![A-Za-z])(?:K\.?\s?E\.?|E_?\{?k\}?|kinetic\s+energy)(?![A-Za-z])")
_TIMES = (
    ("T_lost", re.compile(r"(?i)\b(?:lost|loss|lose|decrease|dissipated)\b")),
    ("T_1", re.compile(r"(?i)\b(?:before|initial(?:ly)?)\b")),
    ("T_2", re.compile(r"(?i)\b(?:after|final(?:ly)?|afterwards)\b")),
)


#: A label that is an instant alone (``- before:``, ``* after:``, ``**lost:**``): its quantity is the heading's.
_INSTANT = re.compile(
    r"^[-*•+>\s]*(?:\*\*|__)?\s*(?:before|after|lost|loss|initial(?:ly)?|final(?:ly)?)\s*(?:\*\*|__)?$", re.I
)


def under_heading(line: Read, typed: list[str], label_of: Callable[[Read], str]) -> Read:
    """``line`` as written under its heading where its label is an instant alone and the heading
    above the list it is in names a kinetic energy (``**KE**``, then ``- before: ½(2m)(4)² …``):
    the heading's words put before the label, so the label says the energy."""
    label = label_of(line)
    if not label or not _INSTANT.match(label) or not 0 < line.number <= len(typed):
        return line
    for row in reversed(typed[: line.number - 1]):
        row = row.strip()
        if not row or (re.match(r"[-*•+]\s", row) and "=" in row):
            continue  # a blank line, or the list's other items
        if "=" in row or not _ENERGY.search(row):
            return line
        return replace(line, written=f"{re.sub(r'[^A-Za-z ]', ' ', row).strip()} {line.written.lstrip(' -*•+>')}")
    return line


def energy_labelled(
    ctx: Context, line: Read, holds: Callable[[Pair], bool], wrong: frozenset[str], label_of: Callable[[Read], str]
) -> Pair | None:
    """The pair "the energy the label names = the line's first side" where the line is labelled
    a kinetic energy before, after or lost and that pair does not hold for the problem; None
    where the line works from a number the student got wrong (``wrong``: it is carried)."""
    exprs = line.exprs or ()
    numbers = re.findall(r"(?<![\d.])\d+(?:\.\d+)?", " ".join(line.sides))
    written = {n for n in numbers if "." in n or len(n) >= 3} | decimals(line.sides)  # 7452, not the 2 of 2m
    if written & wrong or re.fullmatch(r"\s*[A-Za-z][\w{}]*'?\s*", line.sides[0]):
        return None  # worked from a number got wrong (carried), or a name of its own first (mu = …)
    label = label_of(line)
    before = line.written.split(line.sides[0].strip())[0]
    if len(exprs) < 2 or not label or not re.search(r":\s*[$*_]*\s*$", before):  # the working just after
        return None
    if not _ENERGY.search(label):
        return None
    times = [name for name, word in _TIMES if word.search(label)]
    derived = ctx.derived()
    if len(times) != 1 or times[0] not in derived:
        return None
    sym = derived[times[0]][0]
    pair = Pair(f"{label} = {line.sides[0]}", ctx.in_unknowns(sym), ctx.in_unknowns(exprs[0]), 1e-3, (sym, exprs[0]))
    return None if holds(pair) else pair
