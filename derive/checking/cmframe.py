"""Velocities in the centre-of-mass (zero-momentum) frame: a body's velocity relative to the
centre of mass, under a name the habits read as that body's velocity in the laboratory.

A student who works in the frame of the centre of mass writes ``v_cm = (4·12 + 8·4)/12 = 20/3``,
then ``u_A = 12 − 20/3 = 16/3`` (A's velocity before, relative to the centre of mass), reverses
and scales it, ``u_A' = −0.5(16/3) = −8/3``, and comes back, ``v_A' = u_A' + v_cm = 4``. A
teacher reads u_A, u_A' as the velocities the lines define, not as the habit's A before and A
after. The rule: once the centre of mass's velocity is written, a name met first alone on the
left of a relation, which the habits read as a body's velocity (or its component along the
line of centres) and which is false in that reading but holds as that velocity minus the centre
of mass's, is that relative velocity on every line. The centre of mass's velocity is the same
before and after the impact, so the reading holds for both instants. A name of the centre's own
letter (``v_i' = v_cm - v_i`` beside ``v_cm``) is the laboratory's: the student's letter for the
velocities the centre's is one of (there, a slip of the rule 2v_cm - v_i). A name set to 0 keeps the
habit (a body at rest in the laboratory, or a slip: never excused as the centre's own velocity).
"""

from __future__ import annotations

import sympy

from derive.checking.centremass import common_velocity
from derive.checking.context import Context
from derive.checking.lonenames import lone_name
from derive.checking.naming import PREFIX, placeholders
from derive.checking.numeric import number_of


def relative_to_centre(
    ctx: Context, raw: list, meanings: dict[str, sympy.Expr], at: tuple[dict, dict], kept: set[str]
) -> None:
    """Names defined as a body's velocity relative to the centre of mass: read so in
    ``meanings`` (changed in place). ``at``: the sample point of the givens and the true values
    of the unknowns there; ``kept``: names declared in words, never read anew."""
    if ctx.problem.fixed_B:
        return
    centre = common_velocity(ctx)
    bodies = _velocities(ctx)
    if _value(ctx, centre, {}, at) in (None, 0) or not bodies:
        return  # a centre at rest: each relative velocity is the laboratory's
    seen: set[sympy.Symbol] = set()
    centred = ""  # the letter of the name the centre of mass's velocity was written under ("v" for v_cm)
    own: dict[sympy.Symbol, sympy.Expr] = {}  # a name of the student's own set alone to a value: V = 2u
    for r in raw:
        if not r.exprs or len(r.exprs) < 2:
            continue
        left = r.exprs[0]
        name = left.name[len(PREFIX) :] if left.is_Symbol and left.name.startswith(PREFIX) else ""
        held = meanings.get(name)
        values = [_value(ctx, e.xreplace(own), meanings, at) for e in r.exprs[1:]]
        if (
            centred
            and held in bodies
            and name[:1].lower() != centred
            and name not in kept
            and left not in seen
            and lone_name(r.sides[0])
        ):
            lab, frame = _value(ctx, held, {}, at), _value(ctx, held - centre, {}, at)
            if (
                None not in (lab, frame, *values)
                and abs(frame) > 1e-12
                and not _near(lab, values)
                and _near(frame, values)
            ):
                meanings[name] = held - centre
        elif name and name not in meanings and left not in seen and lone_name(r.sides[0]) and None not in values:
            own[left] = r.exprs[-1]
        for e in r.exprs:
            seen |= placeholders(e)
        if not centred and None not in values and _near(_value(ctx, centre, {}, at), values):
            centred = name[:1].lower() or "?"  # a number alone: no letter


def _velocities(ctx: Context) -> set[sympy.Expr]:
    """The bodies' velocities (along the line of centres) before and after, in derive's names."""
    nm = ctx.model.nm
    return {x for x in (nm.A1n, nm.B1n, nm.A2n, nm.B2n) if x is not None and x.free_symbols}


def _value(ctx: Context, expr: sympy.Expr, meanings: dict[str, sympy.Expr], at: tuple[dict, dict]) -> complex | None:
    """``expr``'s value, its names read by ``meanings``, at the sample point ``at``."""
    reading = {s: meanings[s.name[len(PREFIX) :]] for s in expr.free_symbols if s.name[len(PREFIX) :] in meanings}
    pt, truth = at
    return number_of(ctx.in_unknowns(ctx.num(expr.xreplace(reading))).xreplace(pt).xreplace(truth))


def _near(x: complex, values: list[complex]) -> bool:
    return all(abs(v - x) <= 0.01 * max(abs(v), abs(x), 1e-9) for v in values)
