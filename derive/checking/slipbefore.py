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

import sympy

from derive.checking.mistakes import REGISTRY, Variant
from derive.checking.numeric import decimals

if TYPE_CHECKING:
    from derive.checking.inference import Read
    from derive.checking.tracing import Trace
    from derive.checking.worlds import Pair


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


def as_slipped(trace: Trace, x: sympy.Expr, before: bool = True) -> sympy.Expr:
    """``x`` (a result in the values before, the masses and the velocities after) with the values
    before and the masses as the mistake of the slip's world has them: the student's kinetic
    energy before after the masses swapped (``½(0.027)(3.5)²`` for ``½(0.022)(3.5)²``); the masses
    only where not ``before``."""
    model, variant = trace.ctx.model, trace.variant if before else Variant()
    for name in sorted(set().union(*trace.named.values())) if trace.named else ():
        m = REGISTRY.get(name)  # a mistake in the masses named by its equation (no variant kept): its masses
        v = m.build(model) if m is not None and variant.masses is None else None
        variant = replace(variant, masses=v.masses) if v is not None and v.masses is not None else variant
    if variant.pre is None and not variant.values and variant.masses is None:
        return x
    under = model.under(variant)
    put = {k: under.num(v) for k, v in under.pre.items()}
    if variant.masses is not None:
        put |= {model.m_A: variant.masses[0], model.m_B: variant.masses[1]}
    derived = {sym: ex for sym, ex in trace.ctx.derived().values()}  # T_1 in the masses and the values before
    return under.num(x.xreplace(derived).xreplace(put))


def holds_slipped(trace: Trace, pairs: list[Pair]) -> bool:
    """Whether ``pairs``, false for the problem, hold in the slip's world with the masses as its
    mistake has them (``KE before: ½(8)(12)² + ½(4)(4)² = 608`` after the masses were swapped in the
    momentum): the student's own energy, carried. (A value before resolved afresh the same wrong
    way is the mistake again, not carried: :func:`holds_as_slipped` takes those from a number.)"""
    if trace.world is None or not pairs or any(p.raw is None for p in pairs) or trace.holds(pairs, trace.truth):
        return False
    out = []
    for p in pairs:
        raw = tuple(as_slipped(trace, x, before=False) for x in p.raw)  # a value before afresh: again
        if raw == p.raw:
            return False
        out.append(replace(p, left=trace.ctx.in_unknowns(raw[0]), right=trace.ctx.in_unknowns(raw[1]), raw=raw))
    return trace.holds(out, trace.world)
