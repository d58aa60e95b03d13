"""A velocity the problem gives put in with its sign lost: ``b_sign``, not ``arithmetic``.

A line found wrong as an arithmetic slip whose one wrong step puts numbers into a rule in
letters may hold once a velocity the problem gives, negative in the student's convention, is
taken the other way: ``e = (v_B' - v_A')/(u_A - u_B) = (3.55 - 0.2)/(6 - 2)`` with A moving
back at 0.2 m/s, ``Δp = m(v_f - v_i) = 0.240(2.40 - 3.00)`` with v_f = -2.40 declared. A
teacher names it as a velocity taken in the wrong direction (``b_sign``), as in the momentum.
So is a component of B's velocity before the impact worked out with its sign lost
(``110 cos 100° = 19.10``). A value the student worked out (an unknown) put in with its sign
lost stays a slip in the algebra (:func:`~.termslips.working_slip`).
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import sympy

from derive.checking import nestedsigns
from derive.checking.carried import sides
from derive.checking.context import DEG

#: What a report says of a line that puts a given velocity in with its sign lost.
WORDS = (
    ": a step of its working puts a velocity in with its sign lost (a velocity taken in the wrong "
    "direction: in your own convention it is negative)."
)
COMPONENT = ": it has the sign of B's component lost (B moves against that direction: a velocity taken the wrong way)."


def named(trace: Any, line: Any, item: Any) -> Any:
    """``item`` (the verdict of ``line``) named ``b_sign`` where its arithmetic slip is a given
    velocity's sign lost (see the module), ``algebra`` where a slip not named is a sign lost inside
    a formula (:mod:`.nestedsigns`); ``item`` as it is otherwise."""
    if item is not None and item.status == "wrong" and not item.slip and line.exprs is not None:
        return nestedsigns.sign_inside(trace, line, item)  # a sign lost inside a formula: algebra
    if item is None or item.status != "wrong" or item.slip != "arithmetic" or item.again or line.exprs is None:
        return item
    if len(line.sides) < 2 or len(line.exprs) != len(line.sides):
        return item
    worlds = [trace.truth[0]] + ([trace.world[0]] if trace.world else [])  # before the slip, or the student's
    try:
        words = next((w for w in (_sign_lost(trace, line, values) for values in worlds) if w), "")
    except (TypeError, ValueError, ArithmeticError, AttributeError):
        return item
    if not words:
        return item
    return replace(item, slip="b_sign", message=f"{item.message.split(':')[0]}{words}")


def _sign_lost(trace: Any, line: Any, values: dict) -> str:
    ctx, unknowns = trace.ctx, set(trace.U)
    for i in range(len(line.sides) - 1):
        p = sides(trace, line, i, i + 1)
        if p.raw is None:
            continue
        rule, numbers = p.raw
        if numbers.free_symbols - {DEG}:
            continue
        right = _number(ctx.in_unknowns(numbers))
        left = _number(ctx.in_unknowns(rule).xreplace(values))
        if right is None or left is None or _near(left, right):
            continue
        if not (rule.free_symbols - {DEG}):  # a line of numbers: B's component before, its sign lost
            return COMPONENT if right and _near(left, -right) and _b_component(ctx, left) else ""
        for s in sorted(rule.free_symbols - unknowns - {DEG}, key=str):
            value = _number(ctx.in_unknowns(s))
            if value is None or value >= 0 or s.name[:1] not in "uvw":
                continue
            flipped = _number(ctx.in_unknowns(rule.xreplace({s: -s})).xreplace(values))
            if flipped is not None and _near(flipped, right):
                return WORDS
        return ""
    return ""


def _b_component(ctx: Any, value: float) -> bool:
    """Whether ``value`` is one of B's components before the impact (nonzero)."""
    nm = ctx.model.nm
    for c in (getattr(nm, "B1n", None), getattr(nm, "B1t", None)):
        x = _number(ctx.in_unknowns(c)) if c is not None else None
        if x and _near(x, value):
            return True
    return False


def _number(x: sympy.Expr) -> float | None:
    try:
        return float(sympy.N(x))
    except (TypeError, ValueError):
        return None


def _near(a: float, b: float) -> bool:
    """Equal to the three or four figures a line of working is written with."""
    return abs(a - b) <= 2e-3 * max(abs(a), abs(b), 1e-9)
