"""The student's frame: which way along the line of centres is positive, for derive's own names too.

A student who takes the other way as positive ("left as positive", "away from the wall is +ve",
or no words at all) and writes derive's names (``(v_A)_1 = -3``, ``v_A2 = +1.6``) means derive's
components with the sign changed. :mod:`.inference` reads the relations both ways and keeps the
way the values written hold in; this module flips derive's n components for the other way, and
scores a reading: how many ``=`` hold of those that a reading can move (a name of the student's
own, or one of derive's n components).
"""

from __future__ import annotations

from dataclasses import replace

import sympy

from derive.checking.context import Context
from derive.checking.figures import literal_tolerance
from derive.checking.naming import PREFIX
from derive.checking.numeric import number_of


def n_components(ctx: Context) -> dict[sympy.Symbol, sympy.Expr]:
    """derive's components along n (before and after, A and B) -> the same in the reversed frame."""
    nm = ctx.model.nm
    out: dict[sympy.Symbol, sympy.Expr] = {}
    for c in (nm.A1n, nm.B1n, nm.A2n, nm.B2n):
        if isinstance(c, sympy.Symbol):
            out[c] = -c
    return out


def uses_n_components(ctx: Context, raw: list) -> bool:
    """Whether a relation the student wrote has one of derive's n components in it."""
    ns = set(n_components(ctx))
    return any(ns & e.free_symbols for r in raw if r.exprs for e in r.exprs)


def flipped(ctx: Context, raw: list, sign: int) -> list:
    """The relations with derive's n components read in the student's frame (``sign`` -1: the
    reversed one, so ``v_A1 = -3`` is A's velocity before, 3 along derive's n)."""
    if sign == 1:
        return list(raw)
    flip = n_components(ctx)
    out = []
    for r in raw:
        if r.exprs is None or not any(flip.keys() & e.free_symbols for e in r.exprs):
            out.append(r)
            continue
        out.append(replace(r, exprs=tuple(e.xreplace(flip) for e in r.exprs)))
    return out


Pair = tuple[float, tuple[sympy.Expr, sympy.Expr], bool]


def pairs(ctx: Context, raw: list, pt: dict, truth: dict) -> list[list[Pair]]:
    """For each relation, each ``=`` as (tolerance, (left, right) with the true values in,
    whether a reading moves it: a student's name or derive's n component in it)."""
    ns = set(n_components(ctx))
    out = []
    for r in raw:
        if r.exprs is None or r.defines or r.direction:  # a direction in words is derive's: no sign to infer
            out.append([])
            continue
        diffs = []
        for i in range(len(r.exprs) - 1):
            tol = max(literal_tolerance(f"{r.sides[i]} = {r.sides[i + 1]}", ctx.data), 1e-9)
            pair = r.exprs[i : i + 2]
            moved = any(s.name.startswith(PREFIX) or s in ns for x in pair for s in x.free_symbols)
            left, right = (ctx.in_unknowns(x).xreplace(pt).xreplace(truth) for x in pair)
            diffs.append((tol, (left, right), moved))
        out.append(diffs)
    return out


def score(found: list[list[Pair]], mapping: dict, ctx: Context, pt: dict, truth: dict) -> int:
    """How many ``=`` hold (of those a reading moves) under ``mapping``."""
    subs = {k: ctx.in_unknowns(v).xreplace(pt).xreplace(truth) for k, v in mapping.items()}
    n = 0
    for line in found:
        for tol, (left, right), moved in line:
            if not moved:
                continue
            a, b = number_of(left.xreplace(subs)), number_of(right.xreplace(subs))
            if a is not None and b is not None and abs(a - b) <= 2 * tol * max(abs(a), abs(b)) + 1e-12:
                n += 1
    return n
