"""A chain's data stated before the working, with no header (``Before: $u_A = 3$, $u_B = -1.5$.
After: $v_A = 2$, $v_B = 2.9$.``): the rule of :mod:`.datalines` for a chain, whose names are the
stages'. A line before the working whose relations each set a name to a number, where the number is
exactly (to the figures written, with its sign) the value one of the chain's stages gives a
quantity of the body the name is written for (``u_B``: B's), states the problem's data: a teacher
does not mark it, whatever quantity of the chain the name is read as (the chain's ``u_B`` is B's
velocity after the first impact). A number that is no stage's given of that body, or the given with
its sign turned (``u_B = 1.5`` for B moving toward A at 1.5 m/s), is judged as any line is.
"""

from __future__ import annotations

import re
from typing import Any

import sympy

from derive.checking.context import Context
from derive.checking.naming import PREFIX
from derive.checking.restated import stated, written_number
from derive.checking.stageslips import given_turned
from derive.checking.worlds import number_at_figures

#: A body's letter in a name as the student writes it (``u_B``, ``(v_A)_1``, ``vA``, ``m_{B}``).
_BODY = re.compile(r"^\(?[A-Za-z](?:_\{?|\{)?([AB])(?![a-z])")


def given_said(ctx: Context, relation: tuple[Any, list], exprs: list, subs: tuple[dict, dict]) -> bool:
    """Whether the relation (with every relation read, each as (relation, sides, exprs)) restates a given: in the convention its line
    takes (:func:`~.stageslips.given_turned`), or on a line of data before the working."""
    r, read = relation
    return given_turned(ctx, r.written, exprs, subs) or _data(ctx, r, read)


def _data(ctx: Context, r: Any, read: list) -> bool:
    if not all(stated(x[0].sides) for x in read if x[0].line <= r.line):
        return False  # after the working, a name set to a number is a result
    number = written_number(r.sides[1])
    m = _BODY.match(r.sides[0].strip())
    if number is None or m is None:
        return False
    value, half = number
    for st in getattr(ctx.solution, "stages", ()):
        part = getattr(st, "part", None)
        for g in part.problem.givens if part is not None else ():
            body = re.search(r"_([AB])", g.name)
            if g.value is None or g.value.free_symbols or body is None or body.group(1) != m.group(1):
                continue
            if abs(float(g.value) - value) <= half:
                return True
    return False


def shadowed(ctx: Context, read: list, values: dict[sympy.Symbol, sympy.Expr]) -> list:
    """``read`` (relation, sides, expressions) with each of the chain's names that a line of data
    before the working sets to another value of the same body's (``After: $v_A = 2$`` where the
    chain's v_A is A's 3 m/s before, and the impact gives A 2 m/s after) made the student's own
    (:data:`PREFIX`), to be read by the habit (``u`` before, ``v`` after) on every line: the student
    says what the name is. A name set to its value, or to it with the sign turned, stays the chain's."""
    theirs: dict[sympy.Symbol, sympy.Symbol] = {}
    for r, sides, exprs in read:
        s = exprs[0] if len(exprs) == 2 else None
        if s is None or not s.is_Symbol or s.name.startswith(PREFIX) or not values.get(s, s).is_number:
            continue
        if not exprs[1].is_number or any(number_at_figures(sides[1], complex(w)) for w in (values[s], -values[s])):
            continue
        if _data(ctx, r, read):
            theirs[s] = sympy.Symbol(PREFIX + s.name)
    if not theirs:
        return read
    return [(r, sides, [x.xreplace(theirs) for x in exprs]) for r, sides, exprs in read]
