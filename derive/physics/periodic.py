"""Equations periodic in e (``tan(100 e) = 1``): every root with 0 ≤ e ≤ 1, where SymPy's
``solve`` gives only the principal one, or a one-line refusal where there are too many."""

from __future__ import annotations

from collections.abc import Callable

import sympy

from derive.errors import SolveError
from derive.problem import Problem

#: The most roots in e a periodic equation may have for derive to list them.
MAX_ROOTS = 10


def periodic_roots(
    problem: Problem,
    system: list[sympy.Expr],
    unknowns: tuple[sympy.Symbol, ...],
    numeric: dict,
    solve: Callable[[tuple, tuple], tuple],
) -> list[dict[sympy.Symbol, sympy.Expr]] | None:
    """Every root where an equation of the system is periodic in e alone (``tan(100 e) = 1``):
    SymPy's ``solve`` gives only the principal root, so the roots with 0 ≤ e ≤ 1 are found
    one by one (the other unknowns solved for each by ``solve``, the system and unknowns as
    tuples to their roots as tuples of pairs); more than :data:`MAX_ROOTS`, or a set
    derive cannot enumerate, is refused. None where no equation is periodic in e."""
    for eq in system:
        e = next((u for u in eq.free_symbols & set(unknowns) if u.name == "e"), None)
        trig = eq.atoms(sympy.sin, sympy.cos, sympy.tan)
        if e is None or eq.free_symbols & set(unknowns) != {e} or not any(f.args[0].has(e) for f in trig):
            continue
        try:
            found = sympy.solveset(sympy.sympify(eq).xreplace(numeric), e, sympy.Interval(0, 1))
        except (NotImplementedError, ValueError, TypeError):
            found = None
        if not isinstance(found, sympy.FiniteSet):
            raise SolveError(
                "an equation periodic in e has roots with 0 ≤ e ≤ 1 that derive cannot enumerate", where=problem.path
            )
        if len(found) > MAX_ROOTS:
            raise SolveError(
                f"an equation periodic in e has {len(found)} roots with 0 ≤ e ≤ 1, more than derive lists "
                f"(at most {MAX_ROOTS}): give e, or an equation with one root",
                where=problem.path,
                field="equations",
            )
        if not found:
            return None
        rest = tuple(u for u in unknowns if u != e)
        out = []
        for r in sorted(found, key=float):
            fixed = tuple(sympy.sympify(x).xreplace({e: r}) for x in system)
            out += [{**dict(root), e: r} for root in solve(fixed, rest)] if rest else [{e: r}]
        return out
    return None
