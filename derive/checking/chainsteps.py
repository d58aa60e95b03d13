"""A chain's line worked by the right rule from numbers that are not the problem's own: a step the
student got wrong (carried), or a value the student rounded at a stage's end (correct).

The rule a teacher follows: a line's rule is judged with the true values put back for the numbers
the student worked from, and its working as the student has it. ``v_2 = sqrt(25 + 3.136) = 5.304``
after ``2 g h_0 = 2(9.8)(1.6) = 3.136`` (a slip, 31.36): with 31.36 put back the rule gives the
landing speed, and the working holds: carried. ``d = 15.34^2/(2 x 12.88) = 9.135`` where B's speed
is 15.3325 (15.34 from the student's rounded 9.437 + 5.898): with 15.3325 put back the rule gives
the chain's 9.126, and the working holds: a value rounded at a stage's end and carried is not a
slip, the line is correct.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace

from derive.checking.chainnames import at
from derive.checking.figures import DECIMAL
from derive.checking.numeric import number_of
from derive.checking.report import Item
from derive.problem.expr import ParseError

#: A number as written: whole or decimal.
_NUMBER = re.compile(r"(?<![A-Za-z0-9_.])\d+(?:\.\d+)?(?![A-Za-z0-9_.]|\.\d)")  # 15.34²: its square
#: The words of a line right from the student's rounded values.
ROUNDED = "True for this problem, worked from your values rounded at the stage before (not a slip)."


def from_wrong_step(sides, exprs: list, written: list, defs: tuple, how: tuple) -> bool:
    """Whether the line is worked by the right rule from a step the student got wrong: an earlier
    relation whose first side has no unknown and whose last number is not its value (see the
    module's words). ``defs``: the chain's values, the declared names' true values; ``how``:
    ``holds(exprs, subs)`` and ``reread(side)``."""
    values = defs[0]
    steps = {}
    for rel in written:
        first = at(rel[0], values) if len(rel) >= 2 else None
        theirs, true = (number_of(rel[-1]), number_of(first)) if first is not None else (None, None)
        if theirs is not None and true is not None and abs(theirs - true) > 1e-3 * max(abs(true), 1e-9):
            steps[theirs] = true
    return _put_back(
        sides, exprs, lambda x, half: next((t for v, t in steps.items() if abs(v - x) <= half), None), defs, how
    )


def rounded_on(item: Item, line: tuple, defs: tuple, how: tuple, slips: list[str]) -> Item:
    """``item`` (a first slip) as correct where its working's numbers are values the student stated
    before (``own``) that are the chain's results rounded (each of three figures or more, within
    0.5 % of one of them) and the rule holds with those results put back (see the module's words);
    never where it works on a value the student stated at two figures (rounded too early).
    ``defs``: the chain's values, its givens, the declared names' true values, the student's own."""
    sides, exprs = line
    values, known, true_defs, own_defs = defs
    results = [v for k, v in ((k, number_of(v)) for k, v in values.items()) if v is not None and k not in known]
    stated = [v for v in (number_of(x) for x in own_defs.values()) if v is not None]

    def near(x: float, half: float) -> complex | None:
        if not any(abs(v - x) <= half for v in stated):
            return None
        close = [t for t in results if abs(t - x) <= 0.005 * abs(t) and abs(t - x) > 1e-12]
        return min(close, key=lambda t: abs(t - x)) if close else None

    early = [t for t in DECIMAL.findall(sides[1]) if len(t.replace(".", "").lstrip("0")) == 2]
    if any(abs(float(t) - v) < 1e-9 for t in early for v in stated):  # 6.3 stated, worked on: rounded early
        return item
    if _put_back(sides, exprs, near, (values, true_defs), how, figures=3):
        slips.pop()
        return replace(item, status="correct", message=ROUNDED)
    return item


def _put_back(sides, exprs: list, true_of: Callable, defs: tuple, how: tuple, figures: int = 1) -> bool:
    """Whether the line's rule holds for the problem once each number of its first working side that
    ``true_of(number, half a unit of its last place)`` gives a true value for (of ``figures``
    significant figures at least) is put back as that value, and its working holds as written."""
    (values, true_defs), (holds, reread) = defs, how
    if len(exprs) < 3 or any(x.free_symbols for x in exprs[1:]):
        return False

    def put(m: re.Match) -> str:
        text = m.group(0)
        half = 0.5 * 10 ** -len(text.partition(".")[2])
        hit = true_of(float(text), half) if len(text.replace(".", "").lstrip("0")) >= figures else None
        return text if hit is None else f"({complex(hit).real!r})"

    fixed_text = _NUMBER.sub(put, sides[1])
    if fixed_text == sides[1]:
        return False
    try:
        fixed = reread(fixed_text)
    except (ParseError, ValueError, TypeError, ArithmeticError):
        return False
    return bool(holds([exprs[0], fixed], [true_defs, values])) and bool(
        holds([exprs[1], *exprs[1:]], [true_defs, values])
    )
