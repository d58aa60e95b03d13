"""A line worked from a decimal the student rounded to two figures (rounded too early).

The notes round intermediates to three figures and carry them: a line that ends in a number is
allowed a unit in its last place for them. A decimal the student rounded to two figures and
worked on (``v1 = 6.3`` for 6.261, then ``J = 0.3(5.24 + 6.3) = 3.46``) earns none: the name the
line works out is put to the working itself (:func:`.figures.working_side`), at the slack of its
other decimals only (:func:`.figures.side_slack` allows the two-figure ones none in working).
A chain's line is judged so here (:mod:`.chainlines`); a typed line's sides, in :mod:`.sidepairs`.
"""

from __future__ import annotations

from collections.abc import Callable

from derive.checking.dependency import side_value
from derive.checking.figures import EARLY, side_slack, two_figure, working_side


def worked_early(sides: tuple[str, ...], exprs: list, ctx, value: Callable) -> bool:
    """Whether the line's working with a two-figure decimal (:func:`working_side`) misses the value
    of the name it works out by more than two units in the last places of its other decimals
    (:func:`side_slack` allows the two-figure ones none in working); ``value(expr)``: its value.
    Where it does, ``ctx.memo`` keeps the line's sides, for the slip's name (``rounded_too_early``)."""
    data = ctx.data
    j = working_side(sides, exprs, data, set())
    name, worked = (value(exprs[k]) for k in (0, j)) if j is not None else (None, None)
    if name is None or worked is None:
        return False
    slack = side_slack(sides[j], data, side_value)  # type: ignore[index]
    missed = slack is not None and abs(name - worked) > 2 * slack + 1e-9 * max(abs(name), abs(worked))
    if missed and abs(name - worked) <= 0.03 * max(abs(name), abs(worked)):  # by rounding, not a slip's size
        ctx.memo[(EARLY, tuple(sides))] = two_figure(sides[j], data)  # type: ignore[index]
    return missed
