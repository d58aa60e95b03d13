"""What a chain's lines say as the student wrote them: a given's name used for an unknown they
solve for, and a value's way said in words.

A chain file may name its givens as a student names velocities after an impact: ``v_A``, ``v_B``
for the speeds of approach (AQA's "A at 3 m/s, B at 2 m/s"), where the A-level habit reads
``vA``, ``vB`` as the velocities after. The rule a teacher follows: a name the student solves for
is an unknown. Where the student first uses the name in working with others (``0.3(3) + 0.2(2) =
0.3vA + 0.2vB``) and then sets it alone to a number that is not the given's (``vA = 1 m/s``), the
name is theirs, read by the habit (the impact's velocity after), never the given: the given's
value would make the momentum line hold whatever sign the student put on the numbers in it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import sympy

from derive.checking.conventions import signed_by_words
from derive.checking.naming import PREFIX
from derive.checking.worlds import number_at_figures

#: The habit's names of the velocities after an impact (``vA``, ``v_B``): a given so named is the
#: student's unknown where they solve for it.
_AFTER = frozenset({"v_A", "v_B"})


def as_written(read: list, values: dict[sympy.Symbol, sympy.Expr], givens: set[sympy.Symbol]) -> list:
    """``read`` (relation, sides, expressions) as the student means it: names solved for made
    theirs (:func:`solved_for`), and each value signed by the way its words say (:func:`by_way`)."""
    return [by_way(x, givens) for x in solved_for(read, values, givens)]


@dataclass(frozen=True)
class _Said:
    """A relation as :func:`.conventions.signed_by_words` reads it."""

    sides: tuple[str, ...]
    exprs: tuple
    direction: int
    written: str


def by_way(line: tuple, givens: set[sympy.Symbol]) -> tuple:
    """A relation whose last number has a way said in words (``u_A = 0.6 m/s to the left``,
    ``= 3.5 m/s ←``) with that number signed by it, as for a single impact: right (forwards) along
    the chain's n, from A toward B, left against it; a way is a fact, whatever the student takes as
    positive. A given restated (``v_B = 2 m/s ←``, the chain's v_B a speed) keeps its size."""
    r, sides, exprs = line
    if not getattr(r, "direction", 0) or len(exprs) < 2 or exprs[0] in givens:
        return line
    said = signed_by_words(_Said(tuple(sides), tuple(exprs), r.direction, r.written), 1)
    return (replace(r, direction=0), said.sides, list(said.exprs))


def solved_for(read: list, values: dict[sympy.Symbol, sympy.Expr], givens: set[sympy.Symbol]) -> list:
    """``read`` (relation, sides, expressions) with each given of the habit's names that the
    student solves for made a name of their own (:data:`PREFIX`), to be read by the habit."""
    theirs = {}
    for s in givens:
        if s.name in _AFTER and s in values and values[s].is_number and _solved(read, s, values[s]):
            theirs[s] = sympy.Symbol(PREFIX + s.name)
    if not theirs:
        return read
    return [(r, sides, [x.xreplace(theirs) for x in exprs]) for r, sides, exprs in read]


def _solved(read: list, s: sympy.Symbol, value: sympy.Expr) -> bool:
    """Whether ``s`` is first met in working with another name and later set alone to a number
    that is not ``value`` at its figures, and never to ``value`` itself (a given restated)."""
    worked = solved = False
    for _r, sides, exprs in read:
        if not any(s in x.free_symbols for x in exprs):
            continue
        alone = len(exprs) == 2 and exprs[0] == s and not exprs[1].free_symbols
        if alone and number_at_figures(sides[1], complex(value)):
            return False  # "v_A = 3": the given restated
        if alone and worked:
            solved = True
        elif not alone and any(len(x.free_symbols - {s}) for x in exprs):
            worked = True
        elif alone:
            return False  # set to a number before any working: a given copied (wrongly?), not solved for
    return solved
