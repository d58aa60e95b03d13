"""A chain's numbered names counted from the student's own first station, read as a teacher reads them.

An engineering student numbers the instants of a chain as stations, "(1) thrown, (2) just before
impact, (3) just after, (4) top of rebound": their ``v_2`` is the speed the body lands with, the
chain's ``v_1``, and their ``v_3`` the rebound's, the chain's ``v_2``. The rule a teacher follows:
a name's number counts the student's own instants; where the student's numbered names of one
letter run past the chain's last (a ``v_3`` where the chain has ``v_0``, ``v_1``, ``v_2``), every one
of them is read shifted back by that many (``v_k`` as the chain's ``v_{k-1}``), when each shifted
name is one of the chain's and more of the relations they are in hold so than as written
(``v_2^2 = v_1^2 + 2 g h_0``: the chain's v_1² = v_0² + 2gh_0). A name of that letter with a
number the chain has, the relations holding no better shifted, is the chain's as written.
"""

from __future__ import annotations

import re
from collections.abc import Callable

import sympy

from derive.checking.naming import PREFIX, Open
from derive.checking.suvat import fall_letters

#: A numbered name: its letter and its number (``v_3``, the student's own ``?v_3``).
_NUMBERED = re.compile(r"([A-Za-z])_?(\d)")


def opening_letters(ctx, read: list, names: Open, said: dict, holds: Callable) -> tuple[list, list[str]]:
    """``read`` with the student's stations read as the chain's instants (see the module's words),
    then suvat's letters in the opening fall (:func:`.suvat.fall_letters`); the notes that say so."""
    start = _start(ctx)
    read, notes = stations(read, {str(s) for s in ctx.solution.values} | set(start), holds, start)
    read, more = fall_letters(ctx, read, names, said, holds)
    return read, notes + more


def stations(read: list, chain: set[str], holds: Callable, start: dict | None = None) -> tuple[list, list[str]]:
    """``read`` with each letter's numbered names shifted back where the student's numbers run past
    the chain's (``chain``: the chain's names; ``start``: a name before the chain's first, the
    fall's start from rest, and its value), and the notes that say so."""
    numbers: dict[str, set[int]] = {}
    for name in chain:
        m = _NUMBERED.fullmatch(name)
        if m:
            numbers.setdefault(m.group(1), set()).add(int(m.group(2)))
    notes = []
    for letter, theirs in sorted(numbers.items()):
        used = _used(read, letter)
        shift = max(used.values(), default=0) - max(theirs)
        own_below = {s for s, k in used.items() if k - shift not in theirs and s.name.startswith(PREFIX)}
        used = {s: k for s, k in used.items() if s not in own_below}  # v0 = 5: the given restated, not a station
        if shift <= 0 or len(theirs) < 2 or any(k - shift not in theirs for k in used.values()):
            continue
        if all(s.name.startswith(PREFIX) for s in used):  # none of the chain's: the student's own names
            continue
        subs = {
            s: (start or {}).get(f"{letter}_{k - shift}", sympy.Symbol(f"{letter}_{k - shift}"))
            for s, k in used.items()
        }
        shifted = [(r, sides, [x.xreplace(subs) for x in exprs]) for r, sides, exprs in read]
        if _score(shifted, set(subs.values()), holds) > _score(read, set(subs), holds):
            read = shifted
            said = ", ".join(f"{s.name.lstrip(PREFIX)} as {x}" for s, x in sorted(subs.items(), key=str))
            notes.append(f"Read {said}: your numbers count your own instants.")
    return read, notes


def _start(ctx) -> dict[str, sympy.Expr]:
    """The instant before the chain's first: a fall from rest whose result is ``v_1`` starts at
    ``v_0`` = 0, the student's first station (released from rest) where the chain names none."""
    stages = getattr(ctx.problem, "stages", ())
    fall = stages[0] if stages and stages[0].get("type") == "fall" and not stages[0].get("speed") else None
    m = _NUMBERED.fullmatch(str(fall.get("result", ""))) if fall else None
    if m is None or int(m.group(2)) == 0:
        return {}
    return {f"{m.group(1)}_{int(m.group(2)) - 1}": sympy.Integer(0)}


def _used(read: list, letter: str) -> dict[sympy.Symbol, int]:
    """The student's numbered names of ``letter`` (the chain's and their own), by their numbers."""
    out = {}
    for _r, _sides, exprs in read:
        for x in exprs:
            for s in x.free_symbols:
                m = _NUMBERED.fullmatch(s.name.lstrip(PREFIX))
                if m and m.group(1) == letter:
                    out[s] = int(m.group(2))
    return out


def _score(read: list, names: set, holds: Callable) -> int:
    """How many of the relations with one of ``names`` in them, and no name of the student's own
    (a definition holds whatever it says), hold."""
    count = 0
    for _r, sides, exprs in read:
        free = set().union(*(x.free_symbols for x in exprs))
        if names & free and not any(s.name.startswith(PREFIX) for s in free):
            count += bool(holds(sides, exprs))
    return count
