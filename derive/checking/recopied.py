"""A number the student worked out on an earlier line, copied into a later one wrongly: its
digits in another order (``(v_B)_2 = 3.45`` then ``e = (3.54 − 0.20)/4``; ``0.5196`` written
``0.5916`` in ``e(0.3 + 0.5916)``) or one digit changed.

A teacher names a number by where it came from: worked out on this line and wrong, it is
``arithmetic`` (``0.077/0.049 = 1.517``); taken from a line above and written down wrongly, the
working of this line right with it, it is ``copied_wrong``. The number must stand in the line's
working (joined to other numbers, not a side that is its result alone), be none of the
problem's data, and the line must hold once the earlier number is put back in its place.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace
from typing import TYPE_CHECKING

import sympy

from derive.checking.misread import against, bare, side_number
from derive.checking.workedslips import SWAPPED, energy_masses_swapped
from derive.checking.worlds import Pair

if TYPE_CHECKING:
    from derive.checking.inference import Read
    from derive.checking.tracing import Trace

#: A decimal as written: three significant figures or more are a number worth copying.
_DECIMAL = re.compile(r"(?<![\w.])\d*\.\d+(?![\w.])")
#: The most earlier numbers compared (bounded: a long derivation's numbers).
MAX_EARLIER = 200


def _digits(token: str) -> str:
    return token.replace(".", "").lstrip("0")


def _copy_of(written: str, earlier: str) -> bool:
    """``written`` is ``earlier`` with its digits in another order, or one digit changed (the
    same places)."""
    a, b = _digits(written), _digits(earlier)
    if written == earlier or len(a) < 3 or len(a) != len(b) or len(written) != len(earlier):
        return False
    if sorted(a) == sorted(b):
        return True
    return sum(p != q for p, q in zip(written, earlier, strict=True)) == 1


def _put_back(trace: Trace, bad: Pair, was: sympy.Rational, now: sympy.Rational, held: Callable) -> bool:
    """Whether ``bad`` holds with ``was`` put back as ``now``: where the number stands alone, or
    where it has been added into another (0.3 + 0.5916 read as 0.8916) or multiplied."""
    assert bad.raw is not None
    atoms = set().union(*(x.atoms(sympy.Number) for x in bad.raw)) - {sympy.Integer(0)}
    for a in atoms:
        for b in {a + (now - was), a * now / was} if a != was else {now}:
            sides = [trace.ctx.in_unknowns(x.xreplace({a: b})) for x in bad.raw]
            if held(replace(bad, left=sides[0], right=sides[1])):
                return True
    return False


def _side_put_back(trace: Trace, line: Read, bad: Pair, token: str, e: str, held: Callable) -> bool:
    """Whether a side of numbers of ``line`` that holds ``token``, with ``e`` put back in its
    place, comes to the quantity the line names first (``KE = ½(70.15)(0.0784)² = 0.216``: the
    side, not the result worked from the copy)."""
    first = (line.exprs or (None,))[0]
    if first is None or bad.raw is None:
        return False
    at = re.compile(rf"(?<![\w.]){re.escape(token)}(?![\w.])")
    put = [side_number(at.sub(e, side)) for side in line.sides[1:] if at.search(side)]
    return any(x is not None and held(against(trace, bad, first, x)) for x in put)


def recopied(trace: Trace, typed: list[str], line: Read, bad: Pair, held: Callable) -> str:
    """The words of a ``copied_wrong`` slip where a number in the working of ``line`` (the
    ``typed`` lines before it are read for it) is a copy of one written on a line above, and
    one of its false pairs holds (``held``) with that number put back; "" otherwise."""
    false = [p for p in trace.pairs(line) if p.raw is not None and not held(p)]
    if not false or not 0 < line.number <= len(typed) + 1:
        return ""
    earlier = list(dict.fromkeys(t for row in typed[: line.number - 1] for t in _DECIMAL.findall(row)))[-MAX_EARLIER:]
    data = set(trace.ctx.data)
    for token in dict.fromkeys(t for side in line.sides if not bare(side) for t in _DECIMAL.findall(side)):
        if token in earlier or sympy.Rational(token) in data:
            continue
        for e in reversed(earlier):  # the nearest line first
            was, now = sympy.Rational(token), sympy.Rational(e)
            if _copy_of(token, e) and (
                any(_put_back(trace, p, was, now, held) for p in false)
                or _side_put_back(trace, line, bad, token, e, held)
            ):
                return f": {e}, worked out above, is copied into it as {token} (the line is right with {e})."
    return ""


def named_first(trace: Trace, line: Read, bad: Pair) -> tuple[int | None, str, str] | None:
    """A slip no common mistake explains, named by what the line's numbers show before its
    working is searched: a kinetic energy worked with the masses exchanged (its world kept,
    0), a number of a line above copied wrongly (None: the line's equation takes its place)."""
    held = lambda p: trace.holds([p], trace.world or trace.truth)  # noqa: E731
    if energy_masses_swapped(trace, bad, held):
        return 0, SWAPPED, "masses_swapped"
    said = recopied(trace, getattr(trace, "typed", []), line, bad, held)
    return (None, said, "copied_wrong") if said else None
