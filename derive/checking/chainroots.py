"""A chain's name of the student's own whose value a relation of numbers solved, worked from a
wrong number: the student's own value, not the chain's.

``910u = 3010 × 4.601`` after a slip gave V = 4.601 (the chain's V is 6.507): no value of the
chain fits u, so u is what that relation solves it to be, 15.22 (:func:`.chainlines._infer`).
That relation is carried; so u is the student's wrong speed of the car, and a later line right
with it (``u = 13849/910 = 15.22``) is right only in the student's world: carried, not correct.
"""

from __future__ import annotations

from decimal import ROUND_HALF_UP, Decimal, InvalidOperation

import sympy

from derive.checking.naming import PREFIX
from derive.checking.report import Item
from derive.checking.stageslips import numbers_written


def worked_wrong(sides: tuple[str, ...], wrong: set[str], where: tuple[int, list, dict, list[Item]]) -> bool:
    """Whether a chain's line right for the problem is worked from a number the student got wrong
    (``wrong``, written in its ``sides``) or uses a name solved from a wrong or carried relation
    (:func:`solved_from_wrong`, ``where`` = its line, the relations read, the names, the items)."""
    used = numbers_written(sides, set(), working=True, small=True)
    return bool(used & wrong) or any(more_figures(x, w) for x in used for w in wrong) or solved_from_wrong(*where)


def more_figures(x: str, w: str) -> bool:
    """Whether ``x`` is the number ``w`` (of three figures or more) to more decimals: ``7.3756`` is
    ``7.38`` unrounded, the student's note of the value they carry on."""
    try:
        a, b = Decimal(x), Decimal(w)
    except InvalidOperation:
        return False
    places, figures = -b.as_tuple().exponent, len(w.replace(".", "").lstrip("-+0"))
    return -a.as_tuple().exponent > places >= 0 and figures >= 3 and a.quantize(b, ROUND_HALF_UP) == b


def solved_from_wrong(line: int, read: list, mapping: dict, items: list[Item]) -> bool:
    """Whether relation ``line`` uses a name ``mapping`` gives a number (solved from the first
    relation of two sides it is in) whose relation was judged wrong or carried."""
    status = {i.name: i.status for i in items}
    for p in _own_in(read, line):
        if not (mapping.get(p) is not None and mapping[p].is_number):
            continue
        first = next((r.line for r, _sd, ex in read if len(ex) == 2 and p in _own_in([(r, _sd, ex)], r.line)), None)
        if first is not None and first != line and status.get(str(first)) in ("wrong", "carried"):
            return True
    return False


def _own_in(read: list, line: int) -> set[sympy.Symbol]:
    return {s for r, _sd, ex in read if r.line == line for x in ex for s in x.free_symbols if s.name.startswith(PREFIX)}
