"""A chain's line after a slip that comes to the student's own value, not the problem's: carried.

The rule a teacher follows: after a slip, a line that names one of the chain's quantities and
comes to the value the student's own slip gives it, at the figures written, and not to the
problem's value at those figures, is carried, however loosely its rounded working lets it pass.
``V = 6.0/4.0 = 1.50`` after ``(0.020)(300) = (4.0) V`` (the bullet's mass left out: V = 1.5,
the problem's 1.493 is 1.49 at three figures), then ``K = ½(4.020)(1.50)² = 4.52`` (4.48) and
``h = (1.50)²/(2 × 9.81) = 0.115`` (0.114): the 2 s.f. of ``6.0`` and ``4.0`` let all three
pass as the problem's, yet each is the student's slip carried stage by stage.

The student's own values are those the student's relations from the first slip on fix (the
chain's unknowns they hold, :func:`.chainworld.student_values`), with the later stages run
again from them (:func:`.chainworld.later_stages`: the rise from the student's V).
"""

from __future__ import annotations

from decimal import Decimal, InvalidOperation

import sympy

from derive.checking.chainnames import at
from derive.checking.chainroots import worked_wrong
from derive.checking.chainworld import later_stages, student_values
from derive.checking.numeric import number_of
from derive.mathtext.notation import student


def from_wrong(ctx, line: tuple, where: tuple, done: tuple, defs: tuple) -> bool:
    """Whether a chain's line right for the problem, after a slip, is right only as the student's
    slip carried: worked from a number the student got wrong (:func:`.chainroots.worked_wrong`,
    ``where`` = those numbers, its line, the relations read, the names), or coming to the slip's
    own value at the figures written (:func:`own_figures`; ``line``: its sides and expressions)."""
    wrong, at, read, mapping = where
    items, _written, slips = done
    if not slips:
        return False
    return worked_wrong(line[0], wrong, (at, read, mapping, items)) or own_figures(ctx, *line, done, defs)


def own_figures(ctx, sides: tuple[str, ...], exprs: list[sympy.Expr], done: tuple, defs: tuple) -> bool:
    """Whether a line judged right, after a slip, names a chain quantity and comes to the value the
    student's slip gives it at the figures written, not the problem's (see the module's words).
    ``done``: the items so far, the relations read, the slips' lines; ``defs``: the chain's values,
    the declared names' true and own values."""
    items, written, slips = done
    values, true_defs, own_defs = defs[:3]
    if not slips or len(exprs) < 2 or not isinstance(exprs[0], sympy.Symbol):
        return False
    written_value = _decimal(sides[-1])
    name = exprs[0]
    if written_value is None or (name not in values and name not in true_defs):
        return False
    true = number_of(at(name, {**true_defs, **values}))
    own = _own(ctx, name, (items, written), values, (true_defs, own_defs))
    if true is None or own is None:
        return False
    half = float(Decimal(1).scaleb(written_value.as_tuple().exponent)) / 2
    x = float(written_value)
    return abs(abs(own) - abs(x)) <= half and abs(abs(true) - abs(x)) > half


def _own(ctx, name: sympy.Symbol, done: tuple, values: dict, defs: tuple) -> float | None:
    """The student's own value of ``name``: as the student's relations since the first slip fix it,
    or as the later stages give it from those."""
    items, written = done
    true_defs, own_defs = defs
    first = next((k for k, it in enumerate(items) if it.status == "wrong"), None)
    if first is None:
        return None
    world = {**student_values(ctx, written[first:], values, true_defs), **own_defs}
    if name in world and number_of(world[name]) is not None:
        return number_of(world[name])
    later = later_stages(ctx, world, values, _givens(ctx, values))
    return number_of(later[name]) if name in later else None


def _givens(ctx, values: dict) -> dict:
    given = {g.name for g in getattr(ctx.problem, "givens", ()) if not g.unknown}
    return {k: v for k, v in values.items() if str(k) in given}


def _decimal(side: str) -> Decimal | None:
    """The number a side is alone (a unit after it taken off), as written: ``1.50`` keeps its 0."""
    text = student(side.strip()).split()[0] if side.strip() else ""
    try:
        d = Decimal(text.replace("−", "-"))
    except (InvalidOperation, ValueError):
        return None
    return d if d.is_finite() and d != 0 else None
