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
from derive.checking.worlds import Pair, solve_world

NAME = "angle_other_axis"
#: A velocity before the impact resolved with the sine for the cosine: a given body's angle.
RESOLVED = "sin_cos_swapped"
#: The names of an angle's functions exchanged; a line making one again is that mistake again.
NAMES = (NAME, RESOLVED)


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
            name = RESOLVED if _resolves_before(ctx, raw) and RESOLVED in REGISTRY else NAME
            return (
                f"it {REGISTRY[name].phrase} (its angle's sine and cosine, or tangent and cotangent, exchanged).",
                name,
            )
    return None


def _resolves_before(ctx: Context, raw: tuple[sympy.Expr, sympy.Expr]) -> bool:
    """Whether ``raw`` is a component of a velocity before the impact (``B_n = 110 sin 100°``,
    B's angle from n the student's own) worked by a sine or cosine, not a tangent: a velocity
    resolved with sin and cos swapped, as a teacher names it."""
    nm = ctx.model.nm
    before = {getattr(nm, f"{b}1{k}", None) for b in "AB" for k in "nt"} - {None}
    trig = set().union(*(x.atoms(sympy.sin, sympy.cos, sympy.tan) for x in raw))
    return raw[0] in before and bool(trig) and not any(isinstance(f, sympy.tan) for f in trig)


def plain(
    ctx: Context, bad: Pair, holds: Callable[[Pair], bool], exprs: tuple[sympy.Expr, ...] = ()
) -> tuple[str, str] | None:
    """The words (": …") and name of a slip in a line of a known value that a model of its own
    names: the kinetic energy worked with the wrong formula, an angle from the other axis."""
    if name := slipnames.ke_formula(ctx, bad, holds):
        return f": {slipnames.ENERGY_WORDS[name]}", name
    other = other_axis(ctx, bad, holds, exprs)
    return (f": {other[0]}", other[1]) if other is not None else None


def asked_angle(trace, line, bad: Pair, holds: Callable[[Pair], bool]) -> tuple[int | None, str, str] | None:
    """The slip of ``bad``, a relation in an angle the problem asks for (α with the wall), that
    holds once each sine and cosine (tangent and cotangent) of that angle is put as its
    cofunction: the angle resolved as if from the other axis (``U sin α`` into the wall for
    ``U cos α``), ``angle_other_axis``; the student's relation takes the place of the one it
    stands for (the world solved with it), so the lines after are carried. None otherwise."""
    p = trace.ctx.problem
    asked = {g.symbol for g in p.givens if g.unknown} & set(trace.U)
    angles = {x.angle for x in (p.motion_A, p.motion_B) if x is not None and x.angle is not None} & asked
    if bad.raw is None or not angles or NAME not in REGISTRY:
        return None
    subs: dict[sympy.Expr, sympy.Expr] = {}
    for f in set().union(*(x.atoms(sympy.sin, sympy.cos, sympy.tan) for x in bad.raw)):
        if f.args[0].free_symbols & angles:
            a = f.args[0]
            subs[f] = sympy.cos(a) if f.func is sympy.sin else sympy.sin(a) if f.func is sympy.cos else 1 / sympy.tan(a)
    if not subs:
        return None
    put = tuple(x.xreplace(subs) for x in bad.raw)
    left, right = (trace.ctx.in_unknowns(x) for x in put)
    if not holds(replace(bad, left=left, right=right, raw=put)):
        return None
    words = f": it {REGISTRY[NAME].phrase} (its angle's sine and cosine, or tangent and cotangent, exchanged)."
    return _in_place_of(trace, line, bad.difference, angles), words, NAME


def _in_place_of(trace, line, F: sympy.Expr, angles: set) -> int | None:
    """0 (kept), with the student's relation ``F`` (its factors free of the unknowns taken out:
    ``½mU²(…) = 0.6(½mU²)`` is ``…`` = 0.6) put in place of the first equation in the asked
    angle whose place it can take, and the world solved with it; None where none can."""
    _factor, G = sympy.factor_terms(sympy.expand(F)).as_independent(*trace.U, as_Add=False)
    G = G if G.free_symbols & set(trace.U) else F
    for k, E in trace.equations.items():
        if not E.free_symbols & angles:
            continue
        world = solve_world({**trace.equations, k: G}, trace.U, trace.pts, trace.world or trace.truth)
        if world is not None:
            trace.displaced, trace.equations[k] = (k, trace.equations[k]), G
            trace.replaced.append((line.number, k))
            trace.world = world
            return 0  # kept: the equation replaced here, not by the caller
    return None
