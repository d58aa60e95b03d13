"""A given of one body (the problem's ``W_A``, ``r_B``: a weight, a radius) under the marks the student
names that body's other quantities with: ``W1``, ``W_1``, ``W_{1}``, ``W_a``, the exam's ``W_P``, the
statement's word (``W_car``). The letter is the problem's; only the body's mark is the student's, as for
the masses (``m1`` for ``m_A``). Velocities (u, v, w, V, and a speed
given by any letter) are left to the habits and the name grammar, whose marks say a time as well.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context
from derive.checking.namegrammar import body_marks
from derive.problem.units import VELOCITY

#: A base letter and a body's mark after it, with or without the underscore (``W1``, ``W_a``, ``r_{2}``).
_NAME = re.compile(r"([A-Za-z][A-Za-z]?)_?\{?([A-Za-z0-9]+)\}?")
_LEFT_TO_OTHERS = frozenset("uvwVUm")


def body_givens(ctx: Context, used: set[str], problem: dict[str, sympy.Expr]) -> dict:
    """The names of ``used`` that are a body's given under another mark for the body -> its symbol
    (the marks of :func:`.namegrammar.body_marks`, with 1 and 2 and a and b)."""
    marks = {**body_marks(ctx), "1": "A", "2": "B", "a": "A", "b": "B"}
    speeds = {g.name for g in ctx.problem.givens if g.dim == VELOCITY}  # s_A a speed after: s1 is suvat's
    out: dict[str, sympy.Expr] = {}
    for name in used - set(problem):
        m = _NAME.fullmatch(name)
        if m is None or m.group(1) in _LEFT_TO_OTHERS or m.group(2) not in marks:
            continue
        given = f"{m.group(1)}_{marks[m.group(2)]}"
        if given in problem and given not in speeds:
            out[name] = problem[given]
    return out
