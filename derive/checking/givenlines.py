"""Givens restated: a line of givens, headed ``Given:``, ``Data:``, ``Known:`` (in Markdown's bold,
LaTeX's ``\\textbf{}``, a heading). A teacher does not mark a given said again there: whatever the
checker makes of its names (``v_1 = v_2 = 28 m/s`` for the speeds before and after at a wall,
``(v_A)_2 = 2.40 m/s straight back`` in the student's own sign), a relation there that sets names
to the value of a given of the same kind (to the figures written, either sign: the student's
positive is their own) restates it, and is not marked. A number there that is no given's value of
that kind (``(v_A)_1 = 5`` where A moves at 6 m/s) is a given copied wrongly, and is judged as any
line is.
Without a header, a line of data before the working is a restatement only at a given's exact value
(:mod:`.datalines`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from typing import Any

from derive.checking.datalines import data_line, exact_given, kind_of
from derive.checking.restated import written_number
from derive.problem.units import ANGLE

#: A line that says it lists the givens.
_HEADER = re.compile(
    r"^\s*(?:[#>*\-]\s*)*(?:\\textbf\{|\\emph\{|\*\*|__)?\s*(?:given|data|known|knowns|we\s+know)\b", re.I
)
#: A side that is a name alone (``v_1``, ``(v_A)_2``, ``m_B``, ``\theta``).
_NAME = re.compile(r"\(?\\?[A-Za-z][\w{}\\,]*\)?(?:_\{?\w+\}?)?['′]*")


def restated_item(trace: Any, line: Any, lines: Sequence[Any], typed: list[str]) -> Any:
    """The item of a line that restates a given and, as its names are read, does not hold for the
    problem: not a slip, nothing learned from it (:func:`restates_givens`); None for any other line
    (a restatement that holds is judged as it always was: correct)."""
    if not restates_givens(trace, line, lines, typed):
        return None
    try:
        if trace.holds(trace.pairs(line), trace.truth):
            return None
    except (TypeError, ValueError, ArithmeticError):
        pass
    return trace._item(line, "correct", "A given said again, in your own names and signs: not marked.", "")


def restates_givens(trace: Any, line: Any, lines: Sequence[Any], typed: list[str]) -> bool:
    """Whether ``line`` (a :class:`~.inference.Read`) restates a given on a line of givens. Only under
    its header: a name set to a number elsewhere, against a way the student declared (``positive:
    from A toward B``, then ``u = -4``), is a sign slip."""
    if line.exprs is None or line.defines or not 0 < line.number <= len(typed):
        return False
    if _HEADER.match(typed[line.number - 1]) is None:  # elsewhere only the data's exact value (datalines)
        return data_line(trace.ctx, line, lines) and exact_given(trace.ctx, line, set(trace.U))
    return _given(trace.ctx, line)


def _stated(r: Any) -> bool:
    """Whether the relation sets names to a number (``v_1 = v_2 = 28``), and nothing else."""
    sides = [s.strip() for s in r.sides]
    return len(sides) >= 2 and all(_NAME.fullmatch(s) for s in sides[:-1]) and _number(sides[-1]) is not None


def _number(side: str) -> tuple[float, float] | None:
    return written_number(re.sub(r"\s*(?:°|\^\\circ|\^\{\\circ\}|deg\w*)\s*$", "", side))


def _given(ctx: Any, r: Any) -> bool:
    """Whether the relation is stated and its number is the value, in size, of a given of the kind
    its first name is read as (a mass for a mass, a velocity for a velocity)."""
    if not _stated(r) or r.exprs is None:
        return False
    kinds = {kind_of(ctx, x) for x in r.exprs[:-1]}
    if len(kinds) != 1 or None in kinds:
        return False
    kind = kinds.pop()
    value, half = _number(r.sides[-1].strip())
    for g in ctx.problem.givens:
        if g.value is None or not getattr(g.value, "is_number", False) or getattr(g, "dim", None) != kind:
            continue
        size = abs(float(g.value)) * (180 / math.pi if kind == ANGLE and re.search(r"°|circ|deg", r.sides[-1]) else 1)
        if size and abs(abs(value) - size) <= half:
            return True
    return False
