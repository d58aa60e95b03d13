""" "Show that" results and ranges of a letter, decided from the closed forms.

A relation to show holds when its two sides, with every result put in by its closed
form, are equal for all values the letters may take; where SymPy cannot simplify the
difference to zero, it is evaluated at many points of the assumed ranges, and a point
where the sides differ is a counterexample. A range is the set of values of one letter
(e in [0, 1], another letter positive) for which an inequality between results holds.
"""

from __future__ import annotations

import math
import random
from collections.abc import Mapping

import sympy

from derive.physics.results import Result
from derive.problem import Problem
from derive.problem.symbolic import Range, Relation
from derive.records import dataclass

POINTS = 24


@dataclass(frozen=True)
class Shown:
    """A relation to show, decided: ``lhs``/``rhs`` in the letters; ``holds``; ``how`` it
    was decided ("exactly" or "at N points"); a ``counterexample`` where it fails."""

    relation: Relation
    lhs: sympy.Expr
    rhs: sympy.Expr
    holds: bool
    how: str
    counterexample: dict[sympy.Symbol, float] | None = None


@dataclass(frozen=True)
class Found:
    """A range: ``expr op 0`` in the letter, ``reduced`` once positive factors are
    dropped, and the ``interval`` of the letter where it holds (None if undecided)."""

    range: Range
    expr: sympy.Expr
    reduced: sympy.Expr
    interval: sympy.Set | None
    dropped: tuple[sympy.Expr, ...] = ()


def in_letters(expr: sympy.Expr, problem: Problem, results: Mapping[str, Result]) -> sympy.Expr:
    """``expr`` (in result and given names) in the letters alone: each result by its closed
    form, each direction's tangent as its ratio of components, every number put in."""
    comps = {"theta": ("n", "t"), "beta": ("t", "n")}
    for name, r in results.items():
        kind, _, body = name.partition("_")
        if kind in comps and body in ("A2", "B2"):
            y, x = (results[f"v_{body}{c}"].closed for c in comps[kind])
            speed = sympy.sqrt(y**2 + x**2)
            s = r.symbol
            expr = expr.replace(sympy.tan(s), y / x).replace(sympy.sin(s), y / speed).replace(sympy.cos(s), x / speed)
    subs = {r.symbol: r.closed for r in results.values()}
    for g in problem.givens:  # an unknown given (e = "?") is its result, found by name
        if g.unknown and g.name in results:
            subs.setdefault(g.symbol, results[g.name].closed)
    for g in problem.givens:
        if g.value is None and g.definition is not None:
            subs.setdefault(g.symbol, g.definition)
    out = expr.xreplace(subs)
    for _ in range(4):  # definitions that name other givens
        out = out.xreplace(
            {g.symbol: g.definition for g in problem.givens if g.value is None and g.definition is not None}
        )
    out = out.xreplace(problem.numeric())
    # a letter the closed forms name by its component symbol (v_A1) is the given's letter, with
    # what the given says of it (a speed kept as a letter is positive)
    letters = {g.name: g.symbol for g in problem.givens if g.value is None}
    return out.xreplace({s: letters[s.name] for s in out.free_symbols if s.name in letters})


def decide(rel: Relation, problem: Problem, results: Mapping[str, Result]) -> Shown:
    """Whether ``rel`` follows from the closed forms, for every value of the letters."""
    lhs, rhs = in_letters(rel.lhs, problem, results), in_letters(rel.rhs, problem, results)
    difference = sympy.simplify(lhs - rhs)
    lhs = sympy.factor(sympy.simplify(lhs))
    if difference == 0:
        return Shown(rel, lhs, rhs, True, "exactly")
    points = sample(problem, difference.free_symbols)
    for point in points:
        a, b = _number(lhs, point), _number(rhs, point)
        if a is None or b is None:
            continue
        if abs(a - b) > 1e-9 * (1 + abs(a) + abs(b)):
            return Shown(rel, lhs, rhs, False, f"at {len(points)} points", dict(point))
    return Shown(rel, lhs, rhs, True, f"at {len(points)} points")


def sample(problem: Problem, letters: set[sympy.Symbol], n: int = POINTS) -> list[dict[sympy.Symbol, float]]:
    """Points of the letters' assumed ranges: e in (0, 1), an acute angle in (0°, 90°),
    another letter positive (or any sign where assumed real), reproducibly."""
    rng = random.Random(7)
    words = {g.symbol: problem.assume.get(g.name, "") for g in problem.givens}
    angles = {g.symbol for g in problem.givens if g.unit == "deg"}
    out = []
    for _ in range(n):
        point = {}
        for s in sorted(letters, key=str):
            word = words.get(s, "")
            if s.name == "e":
                point[s] = rng.uniform(0.05, 0.95)
            elif word == "acute" or s in angles:
                point[s] = rng.uniform(0.1, 1.4)  # radians, within (0°, 90°)
            elif word in ("real",):
                point[s] = rng.uniform(-3, 3)
            elif word == "negative":
                point[s] = -rng.uniform(0.3, 3)
            else:
                point[s] = rng.uniform(0.3, 3)
        out.append(point)
    return out


def _number(expr: sympy.Expr, point: dict[sympy.Symbol, float]) -> float | None:
    try:
        value = complex(sympy.N(expr.xreplace({s: sympy.Float(v) for s, v in point.items()})))
    except (TypeError, ValueError):
        return None
    if not math.isfinite(value.real) or abs(value.imag) > 1e-9 * (1 + abs(value.real)):
        return None
    return value.real


def solve_range(rng: Range, problem: Problem, results: Mapping[str, Result]) -> Found:
    """The values of ``rng.of`` (e within [0, 1], another letter positive) where the
    inequality holds, the other letters taken positive."""
    expr = sympy.factor(in_letters(rng.lhs, problem, results) - in_letters(rng.rhs, problem, results))
    x = rng.of
    reduced, dropped = drop_positive(expr, x)
    domain = sympy.Interval(0, 1) if x.name == "e" else sympy.Interval.open(0, sympy.oo)
    if reduced.free_symbols - {x}:
        return Found(rng, expr, reduced, None, dropped)
    relation = {"<": sympy.StrictLessThan, "<=": sympy.LessThan, ">": sympy.StrictGreaterThan, ">=": sympy.GreaterThan}
    try:
        found = sympy.solve_univariate_inequality(relation[rng.op](reduced, 0), x, relational=False)
    except (NotImplementedError, ValueError):
        return Found(rng, expr, reduced, None, dropped)
    return Found(rng, expr, reduced, found.intersect(domain), dropped)


def drop_positive(expr: sympy.Expr, x: sympy.Symbol) -> tuple[sympy.Expr, tuple[sympy.Expr, ...]]:
    """``expr`` without the factors known to be positive (u, m, 3, u^2): the sign is kept."""
    if not isinstance(expr, sympy.Mul):
        return expr, ()
    kept, dropped = [], []
    for f in expr.args:
        if not f.has(x) and f.is_positive:
            dropped.append(f)
        else:
            kept.append(f)
    return sympy.Mul(*kept), tuple(dropped)
