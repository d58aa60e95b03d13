"""A velocity before the impact as the slip made it: the student's own value, carried on.

A slip in the values before the impact (the calculator in radian mode, ``cos37.6 = 0.99509``;
sin and cos swapped; B's sign lost) changes the components before the impact themselves, not
only the velocities after. A later line that states one of those components from the student's
wrong number (``vAn = 5(0.99509) = 4.9755``) holds once the components before are as the slip's
mistake has them: a teacher reads it as carried, since it writes the number the slip came to;
it resolves nothing afresh. (A line that resolves a component afresh the same wrong way, writing
no number the slip came to, is the mistake made again: :func:`~.carried.made_again`.)
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from derive.checking.numeric import decimals

if TYPE_CHECKING:
    from derive.checking.inference import Read
    from derive.checking.tracing import Trace


def holds_as_slipped(trace: Trace, line: Read) -> bool:
    """Whether ``line``, false for the problem and worked from a number the slip came to, holds
    with the components before the impact as the mistake of the slip's world (its variant) has
    them, and the velocities after as that world has them."""
    model, variant = trace.ctx.model, trace.variant
    if (
        trace.world is None
        or (variant.pre is None and not variant.values)
        or not writes_slips_number(trace, line.sides)
    ):
        return False
    pairs = trace.pairs(line)
    under = model.under(variant)
    pre = {k: under.num(x) for k, x in under.pre.items()}
    if all(trace.ctx.model.num(x) == pre[k] for k, x in model.pre.items()):
        return False  # the mistake leaves the values before as they are
    moved, out = False, []  # a line of the values before: the slip's mistake moves one of them
    for p in pairs:
        if p.raw is None:
            return False
        raw = tuple(x.xreplace(pre) for x in p.raw)
        moved = moved or raw != p.raw
        left, right = (trace.ctx.in_unknowns(x) for x in raw)
        out.append(replace(p, left=left, right=right, raw=raw))
    return moved and not trace.holds(pairs, trace.truth) and trace.holds(out, trace.world)


def writes_slips_number(trace: Trace, sides: tuple[str, ...] | list[str]) -> bool:
    """Whether the working of ``sides`` (all but the last) writes a decimal a wrong or carried
    line came to (``5(0.99509)`` after ``cos37.6 = 0.99509``)."""
    return bool(decimals(list(sides[:-1])) & trace.wrong_values)
