"""The tangent's sense: which way along the common tangent (or the wall) is positive.

derive's +t is n turned a quarter turn counter-clockwise; a student's t is "along the plane of
contact" or "along the tangent", and which way it points is the student's own choice, as a
teacher reads it. Where the t components BEFORE (the givens, resolved) that a derivation writes
all have the other sign from derive's, and none has derive's, the student's t is derive's turned
round: every one of derive's t components is read with its sign changed. One written with each
sign is a slip, not a frame; a t way said in words (axes placed) is read by :mod:`.frames`.
"""

from __future__ import annotations

from dataclasses import replace

import sympy

from derive.checking.context import Context
from derive.checking.frames import axes_said
from derive.checking.numeric import number_of


def t_components(ctx: Context) -> dict[sympy.Symbol, sympy.Expr]:
    """derive's components along t (before and after, A and B) -> the same with t turned round."""
    nm = ctx.model.nm
    out: dict[sympy.Symbol, sympy.Expr] = {}
    for name in ("A1t", "B1t", "A2t", "B2t"):
        c = getattr(nm, name, None)
        if isinstance(c, sympy.Symbol):
            out[c] = -c
    return out


def _votes(ctx: Context, lines: list, pt: dict, truth: dict) -> set[int]:
    """+1 for a t component before written with derive's sign, -1 for one with the other sign."""
    nm = ctx.model.nm
    before = [c for c in (getattr(nm, "A1t", None), getattr(nm, "B1t", None)) if isinstance(c, sympy.Symbol)]
    ours = set(t_components(ctx)) | {c for c in (nm.A1n, nm.B1n, nm.A2n, nm.B2n) if isinstance(c, sympy.Symbol)}
    votes: set[int] = set()
    for r in lines:
        if r.exprs is None:
            continue
        for c in before:
            if c not in r.exprs:
                continue
            true = number_of(ctx.in_unknowns(c).xreplace(pt).xreplace(truth))
            if true is None or abs(true) < 1e-9:
                continue
            for e in r.exprs:
                if e == c or (sympy.sympify(e).free_symbols & ours):
                    continue
                value = number_of(ctx.in_unknowns(e).xreplace(pt).xreplace(truth))
                if value is None:
                    continue
                if abs(value - true) <= 2e-2 * abs(true):
                    votes.add(1)
                elif abs(value + true) <= 2e-2 * abs(true):
                    votes.add(-1)
    return votes


def in_student_sense(ctx: Context, lines: list, pt: dict, truth: dict, axes: dict) -> tuple[list, list[str]]:
    """``lines`` (read in derive's symbols) with derive's t components turned round where the
    student's t points the other way; and what the report says of it."""
    if not ctx.problem.oblique or axes or _votes(ctx, lines, pt, truth) != {-1}:
        return lines, axes_said(axes)
    flip = t_components(ctx)
    out = []
    for r in lines:
        if r.exprs is not None and any(flip.keys() & sympy.sympify(e).free_symbols for e in r.exprs):
            r = replace(r, exprs=tuple(sympy.sympify(e).xreplace(flip) for e in r.exprs))
        out.append(r)
    return out, [
        "Read your t as pointing the other way along the tangent from derive's (your t components before say so)."
    ]
