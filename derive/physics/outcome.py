"""One impact solved: equations (1)-(4) in closed form, every result, and the numbers.

This is what the physics hands on: the writer (:mod:`derive.steps`) turns it into
worked steps, the checker compares hand answers with it, and a chain keeps one per
impact stage.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace

import sympy

from derive.physics.asks import Found, Shown, decide, solve_range
from derive.physics.impact import Impact, evaluate, setup
from derive.physics.recent import Recent
from derive.physics.results import Result, results
from derive.problem import Motion, Problem
from derive.symbols import symbol


@dataclass(frozen=True)
class ImpactOutcome:
    """An impact solved: ``values`` maps each symbol with a number (givens, and the
    n-t components of velocities given in x-y axes) to its exact value; ``angles``
    are the givens held in radians and shown in degrees; ``others`` the results of each
    other physical solution where the data do not choose one (listed, not refused)."""

    problem: Problem
    impact: Impact
    results: Mapping[str, Result]
    values: dict[sympy.Symbol, sympy.Expr]
    angles: frozenset[sympy.Symbol]
    shown: tuple[Shown, ...] = ()
    ranges: tuple[Found, ...] = ()
    others: tuple[Mapping[str, Result], ...] = ()


def xy_motions(imp: Impact) -> list[tuple[Motion, tuple[sympy.Symbol, sympy.Symbol]]]:
    """The bodies whose velocity was given in x-y axes, with their n-t component symbols."""
    p, nm = imp.problem, imp.names
    out = []
    for motion, comps in ((p.motion_A, (nm.A1n, nm.A1t)), (p.motion_B, (nm.B1n, nm.B1t))):
        if motion.x is not None:
            out.append((motion, comps))
    return out


def solve_impact(problem: Problem) -> ImpactOutcome:
    """Solve ``problem``'s equations (1)-(4) in closed form and evaluate every result.

    >>> from derive import load  # doctest: +SKIP
    >>> solve_impact(load("notes-4c11-two-spheres")).results["v_A2n"].value  # doctest: +SKIP
    -7*cos(47*pi/225)/5
    """
    return _SOLVED.get(problem, lambda: _solve_impact(problem), lambda out: _adopted(out, problem))


def _adopted(out: ImpactOutcome, problem: Problem) -> ImpactOutcome:
    """``out``, solved for a problem equal to ``problem``, as ``problem``'s."""
    return replace(out, problem=problem, impact=replace(out.impact, problem=problem))


#: The impacts solved lately, by the problem's value (:mod:`.recent`); each result is worked
#: out when first read, and read again from here by the next check of the same problem.
_SOLVED: Recent[ImpactOutcome] = Recent(8)


def _solve_impact(problem: Problem) -> ImpactOutcome:
    imp = setup(problem)
    found = results(imp)
    values: dict[sympy.Symbol, sympy.Expr] = dict(problem.numeric())
    for motion, (cn, ct) in xy_motions(imp):
        b = motion.body
        xy = ((symbol(f"v_{b}1x"), motion.x), (symbol(f"v_{b}1y"), motion.y))
        for c, expr in ((cn, motion.n), (ct, motion.t), *xy):
            v = evaluate(expr, problem)
            if not v.free_symbols:
                values[c] = v
    angles = {g.symbol for g in problem.givens if g.unit == "deg"}
    for rel in problem.asks.equations:  # a direction given after the impact is a known angle
        if isinstance(rel.lhs, sympy.Symbol) and rel.lhs.name.startswith(("theta", "beta")) and rel.rhs.is_number:
            values[rel.lhs] = rel.rhs * sympy.pi / 180
            angles.add(rel.lhs)
    shown = tuple(decide(rel, problem, found) for rel in problem.asks.show)
    ranges = tuple(solve_range(rng, problem, found) for rng in problem.asks.ranges)
    others = tuple(results(_case(imp, root)) for root in imp.others)
    return ImpactOutcome(problem, imp, found, values, frozenset(angles), shown, ranges, others)


def _case(imp: Impact, root: dict[sympy.Symbol, sympy.Expr]) -> Impact:
    """``imp`` with another of its physical roots in place of the first."""
    closed = {u: sympy.factor_terms(c) for u, c in root.items()}
    return replace(imp, closed=closed, by_components=root, others=())
