"""A chain's velocities named by the habit, and the givens restated in those names.

``vA``, ``v_B2``, ``(v_A)_1`` name the velocities of the impact of A and B
(:func:`velocities`); once so known, a line of givens before the working that writes a
given in them (``(v_B)_1 = 2 m/s ←`` for B's speed toward A) restates it and is not judged
(:func:`.chainnames.restated`).
"""

from __future__ import annotations

from collections.abc import Callable

import sympy

from derive.checking import chainnames
from derive.checking.chainrestage import restaged
from derive.checking.context import Context


def habit_names(ctx: Context, read: list, said: chainnames.Declared, holds: Callable) -> tuple[dict, list]:
    """``said`` with the impact's velocities the habit names, and ``read`` without the givens
    restated in them."""
    said, read = restaged(ctx, read, {**said, **velocities(ctx, read, said, holds)})  # vB = 5, then vB = -3.5: w_B
    return said, [x for x in read if not chainnames.restated(ctx, x, read, said)]


_VELOCITIES = {
    **{f"v_{b}{w}": f"v_{b}2" for b in "AB" for w in ("", "2", "p", "f")},
    **{f"{u}_{b}{w}": f"v_{b}1" for b in "AB" for u, w in (("u", ""), ("v", "1"), ("v", "i"))},
}


def velocities(ctx: Context, read: list, said: chainnames.Declared, holds: Callable) -> chainnames.Declared:
    """The velocities before and after the impact named by the habit (``vA``, ``vB`` after, ``u_A``
    before, ``v_A'``) where the chain has one impact of A and B moving (a wall's may follow) and does
    not use those names: the impact's own, where a relation in them then holds (``15(19.66) = 15 vA +
    10 vB``); else left to be inferred (``vA`` for A's speed down the ramp). ``holds(sides, exprs, subs)``."""
    impacts = [st for st in getattr(ctx.solution, "stages", ()) if getattr(st, "part", None) is not None]
    clash = any(s.name in _VELOCITIES for _r, _sides, exprs in read for x in exprs for s in x.free_symbols)
    if len(impacts) > 1:  # then B strikes a wall or C: A and B's own impact, where no name is the chain's
        impacts = [st for st in impacts if not st.part.problem.fixed_B and not clash]
    if len(impacts) > 1:
        impacts = [st for st in impacts if tuple(st.part.problem.labels) == ("A", "B")]
    if len(impacts) != 1:
        return {}
    used = {
        s for _r, _sides, exprs in read for x in exprs for s in x.free_symbols if s.name.startswith(chainnames.PREFIX)
    }
    meant = {
        p: chainnames.stage_result(ctx, impacts[0], _VELOCITIES[p.name[1:]])
        for p in used - set(said)
        if p.name[1:] in _VELOCITIES
    }
    meant = {p: chainnames.plain(x) for p, x in meant.items() if x is not None}
    if any(holds(sides, exprs, {**said, **meant}) for _r, sides, exprs in read if _has(exprs, meant)):
        return meant
    return {}


def _has(exprs: list[sympy.Expr], names: dict) -> bool:
    return any(s in names for x in exprs for s in x.free_symbols)
