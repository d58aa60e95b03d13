"""An angle taken from the other axis in a line of a known value (``v_B = 0.3 tan 60° = 0.5196``
where the path makes 60° with the line of centres, so that the component along it is
0.3/tan 60°): the line holds once each sine, cosine and tangent of a number of degrees on it is
put as its cofunction (sin ↔ cos, tan ↔ 1/tan). A given body's angle resolved that way is
``sin_cos_swapped`` (the mistakes' model names it before this is asked); any other angle the
student works with is the angle from the other axis, as a teacher names it."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import sympy

from derive.checking import slipnames
from derive.checking.context import DEG, Context
from derive.checking.mistakes import REGISTRY
from derive.checking.worlds import Pair

NAME = "angle_other_axis"


def _swapped(x: sympy.Expr) -> sympy.Expr:
    """``x`` with each sine, cosine and tangent of an angle in degrees put as its cofunction."""
    subs: dict[sympy.Expr, sympy.Expr] = {}
    for f in x.atoms(sympy.sin, sympy.cos, sympy.tan):
        if not f.args[0].has(DEG):
            continue
        a = f.args[0]
        subs[f] = (
            sympy.cos(a) if isinstance(f, sympy.sin) else sympy.sin(a) if isinstance(f, sympy.cos) else 1 / sympy.tan(a)
        )
    return x.xreplace(subs) if subs else x


def other_axis(
    ctx: Context, bad: Pair, holds: Callable[[Pair], bool], exprs: tuple[sympy.Expr, ...] = ()
) -> tuple[str, str] | None:
    """The words and name of the slip where ``bad`` (no unknowns), or the line's first side
    against a side of its working (``exprs``: ``v_B = 0.3 tan 60° = 0.5196``), holds with its
    angles taken from the other axis; None otherwise."""
    if bad.raw is None or NAME not in REGISTRY or not getattr(ctx.problem, "oblique", False):
        return None
    tries = [bad.raw] + [(exprs[0], x) for x in exprs[1:] if _swapped(x) != x]
    for raw in tries:
        put = (_swapped(raw[0]), _swapped(raw[1]))
        if put == tuple(raw):
            continue
        left, right = (ctx.in_unknowns(x) for x in put)
        if holds(replace(bad, left=left, right=right, raw=put)):
            return (
                f"it {REGISTRY[NAME].phrase} (its angle's sine and cosine, or tangent and cotangent, exchanged).",
                NAME,
            )
    return None


def plain(
    ctx: Context, bad: Pair, holds: Callable[[Pair], bool], exprs: tuple[sympy.Expr, ...] = ()
) -> tuple[str, str] | None:
    """The words (": …") and name of a slip in a line of a known value that a model of its own
    names: the kinetic energy worked with the wrong formula, an angle from the other axis."""
    if slipnames.ke_formula(ctx, bad, holds):
        return f": {slipnames.KE_FORMULA}", "ke_formula"
    other = other_axis(ctx, bad, holds, exprs)
    return (f": {other[0]}", other[1]) if other is not None else None
