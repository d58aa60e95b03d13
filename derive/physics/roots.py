"""The roots of an inverse problem's equations: SymPy's, unchecked and unsimplified (its own
check simplifies every root, for seconds each), each checked against the equations at the
problem's numbers (:func:`holds`), and the kept ones simplified (:func:`tidy`). An unknown
angle that enters by its sine and cosine only is solved as a point on the unit circle
(:func:`polar_roots`)."""

from __future__ import annotations

import functools
import math
import random

import sympy

from derive.problem import Problem
from derive.problem.units import ANGLE


@functools.lru_cache(maxsize=32)
def roots(
    system: tuple[sympy.Expr, ...], unknowns: tuple[sympy.Symbol, ...]
) -> tuple[tuple[tuple[sympy.Symbol, sympy.Expr], ...], ...]:
    """SymPy's roots of the system (none where it cannot solve it), kept for the process: the
    same system in a handout, a notebook or the tests is solved once (some, with an unknown
    angle and letters, take SymPy seconds to solve and check)."""
    try:
        # not SymPy's own check (checksol simplifies every root, for seconds each): each root is
        # checked against the equations where they apply (holds), and only the physical ones
        # simplified (tidy)
        roots = sympy.solve(list(system), unknowns, dict=True, check=False, simplify=False)
    except NotImplementedError:
        roots = []
    return tuple(tuple(root.items()) for root in roots)


def polar_roots(
    system: tuple[sympy.Expr, ...], unknowns: tuple[sympy.Symbol, ...]
) -> list[dict[sympy.Symbol, sympy.Expr]]:
    """Roots where an unknown angle enters through its sine and cosine only: each pair put as
    two unknowns S, C with S^2 + C^2 = 1 (a polynomial system SymPy solves), the angle atan2(S, C)."""
    system = tuple(sympy.expand_trig(s) for s in system)
    polar = {}
    for u in unknowns:
        calls = {f for s in system for f in s.atoms(sympy.Function) if f.has(u)}
        if calls and all(isinstance(f, (sympy.sin, sympy.cos)) and f.args[0] == u for f in calls):
            polar[u] = (sympy.Symbol(f"S_{u.name}", real=True), sympy.Symbol(f"C_{u.name}", real=True))
    if not polar:
        return []
    subs = {f(u): p for u, (S, C) in polar.items() for f, p in ((sympy.sin, S), (sympy.cos, C))}
    eqs = [s.xreplace(subs) for s in system] + [S**2 + C**2 - 1 for S, C in polar.values()]
    wanted = [u for u in unknowns if u not in polar] + [x for pair in polar.values() for x in pair]
    try:
        found = sympy.solve(eqs, wanted, dict=True, check=False, simplify=False)
    except NotImplementedError:
        return []
    out = []
    for root in found:
        if not all(x in root for x in wanted):
            continue
        r = {u: root[u] for u in unknowns if u not in polar}
        r.update({u: sympy.atan2(root[S], root[C]) for u, (S, C) in polar.items()})
        out.append(r)
    return out


def holds(
    system: list[sympy.Expr], root: dict[sympy.Symbol, sympy.Expr], numeric: dict[sympy.Symbol, sympy.Expr]
) -> bool:
    """True when ``root`` satisfies every equation of ``system`` at the problem's numbers (and
    at three sets of values of the letters left, each within its assumptions): to 25 of the
    30 digits worked, relative to the size of the equation's terms. A root SymPy found without
    checking it (a branch of a square root, a zero denominator) fails here. A set of values
    where the root is undefined (a denominator lam - 1 at lam = 1) is drawn again."""
    rng = random.Random(27)
    every = set().union(*(sympy.sympify(e).free_symbols for e in system), *(v.free_symbols for v in root.values()))
    letters = sorted(every - set(root) - set(numeric), key=str)
    good = 0
    for _ in range(12 if letters else 1):
        point = {
            s: sympy.Rational(rng.randint(500, 2500), 997) * (1 if _positive(s) else rng.choice((1, -1)))
            for s in letters
        }
        verdict = _holds_at(system, root, {**numeric, **point})
        if verdict is False:
            return False
        good += verdict is True
        if good == (3 if letters else 1):
            return True
    return False


def _holds_at(
    system: list[sympy.Expr], root: dict[sympy.Symbol, sympy.Expr], values: dict[sympy.Symbol, sympy.Expr]
) -> bool | None:
    """Whether ``root`` satisfies ``system`` at ``values``; None where it is undefined there."""
    for eq in system:
        terms = [t.xreplace(root).xreplace(values) for t in _terms(eq)]
        try:
            residual = abs(complex(sympy.N(sympy.Add(*terms), 30)))
            size = max((abs(complex(sympy.N(t, 30))) for t in terms), default=1.0)
        except (TypeError, ValueError, OverflowError, ZeroDivisionError):
            return None
        if not (math.isfinite(residual) and math.isfinite(size)):
            return None
        if residual > 1e-25 * max(1.0, size):
            return False
    return True


def _terms(eq: sympy.Expr) -> tuple[sympy.Expr, ...]:
    """The terms of an equation's side (``lhs - rhs``), expanded one level."""
    eq = sympy.sympify(eq)
    if isinstance(eq, sympy.Equality):
        eq = eq.lhs - eq.rhs
    return sympy.Add.make_args(sympy.expand(eq, deep=False))


def _positive(s: sympy.Symbol) -> bool:
    return bool(s.is_positive or s.is_nonnegative)


def tidy(value: sympy.Expr) -> sympy.Expr:
    """A kept root in its simplest form (SymPy's simplify, on the roots kept only)."""
    if value.is_Atom:
        return value
    return sympy.simplify(value)


def known_angles(
    problem: Problem, system: list[sympy.Expr], unknowns: tuple[sympy.Symbol, ...]
) -> dict[sympy.Symbol, sympy.Expr]:
    """The known angles, by their values, where an unknown is an angle too: sin(alpha + phi)
    with phi a letter makes a quartic SymPy takes minutes over; with phi = 90 deg it is
    cos(alpha). Elsewhere nothing (the closed forms keep every given's letter)."""
    trig = [f for s in system for f in s.atoms(sympy.sin, sympy.cos, sympy.tan)]
    if not any(f.has(u) for f in trig for u in unknowns):
        return {}
    return {
        g.symbol: g.value
        for g in problem.givens
        if g.dim == ANGLE and g.value is not None and not g.unknown and any(f.has(g.symbol) for f in trig)
    }


def singular(root: dict[sympy.Symbol, sympy.Expr], numeric: dict[sympy.Symbol, sympy.Expr]) -> bool:
    """True where a root's closed form has no value at the numbers given (v_B1 = 0 in a
    denominator: zoo, or 0/0: nan), though the system with the numbers put in may have one."""
    return any(sympy.sympify(v).xreplace(numeric).has(sympy.zoo, sympy.nan, sympy.oo) for v in root.values())


def distinct(
    kept: list[dict[sympy.Symbol, sympy.Expr]],
    unknowns: tuple[sympy.Symbol, ...],
    numeric: dict[sympy.Symbol, sympy.Expr],
) -> list[dict[sympy.Symbol, sympy.Expr]]:
    """The physical roots, one per distinct set of values, ordered by the values of the
    unknowns (the first root SymPy gave where a value still holds a letter)."""
    if len(kept) == 1:
        return kept
    seen: dict[tuple, dict[sympy.Symbol, sympy.Expr]] = {}
    for root in kept:
        key = tuple(sympy.N(root[u].xreplace(numeric), 12) for u in unknowns)
        seen.setdefault(key, root)
    if any(x.free_symbols or not x.is_real for key in seen for x in key):
        return list(seen.values())
    return [seen[key] for key in sorted(seen, key=lambda k: [float(x) for x in k])]
