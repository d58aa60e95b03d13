"""The outcome of an impact against e, from the physics' closed forms.

Each curve is ``solve_impact(problem).results[name].closed`` with every given but e
substituted, evaluated at evenly spaced e from 0 to 1: the velocities along n after
the impact and the fraction of the kinetic energy lost, T_lost / T_1. Nothing is
re-derived here. An inverse problem (e, or a mass, marked "?") is first turned into
the forward problem at the values it found, so that e can vary.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import sympy

from derive.errors import InputError
from derive.physics.impact import independent_map
from derive.physics.outcome import ImpactOutcome, solve_impact
from derive.problem import Problem, units
from derive.problem.reader import POST

SAMPLES = 101


@dataclass(frozen=True)
class Series:
    """One curve: a result's name, its values at the plot's e, and which panel it is in."""

    name: str
    values: tuple[float, ...]
    panel: str  # "velocity" or "energy"


@dataclass(frozen=True)
class Curves:
    """The outcome against e: ``e`` the abscissae, ``mark`` the problem's own e (None if symbolic).

    ``per`` names the symbolic speed the velocities are divided by (Example 4.C.12:
    v_A1), else None; ``unit`` is the velocity unit.
    """

    title: str
    e: tuple[float, ...]
    series: tuple[Series, ...]
    mark: float | None
    unit: str
    per: str | None = None

    def at(self, name: str, e: float) -> float:
        """A curve's value at one of the sampled e."""
        i = min(range(len(self.e)), key=lambda k: abs(self.e[k] - e))
        return next(s for s in self.series if s.name == name).values[i]


def forward(problem: Problem, outcome: ImpactOutcome) -> Problem:
    """An inverse problem as the forward one: its unknowns at the values found, the
    velocities after the impact left for the equations to find."""
    if not problem.unknowns():
        return problem
    givens = []
    for g in problem.givens:
        if g.name in POST[problem.kind]:
            continue
        if g.unknown:
            found = outcome.results[g.name].value
            if found is None:
                raise InputError(f"{g.name} is found only in symbols, so the outcome cannot be plotted against e")
            g = replace(g, value=sympy.nsimplify(found) if g.unit != "deg" else found * sympy.pi / 180, unknown=False)
        givens.append(g)
    return replace(problem, givens=tuple(givens))


def _function(expr: sympy.Expr, e: sympy.Symbol, per: sympy.Symbol | None, what: str) -> Callable[[float], float]:
    """``expr`` (e and at most one symbolic speed left) as a float function of e."""
    if per is not None:
        expr = expr / per
    expr = sympy.simplify(expr)
    extra = expr.free_symbols - {e}
    if extra:
        names = ", ".join(sorted(str(s) for s in extra))
        raise InputError(f"{what} depends on {names}, which the problem leaves symbolic: give numbers to plot it")
    return sympy.lambdify(e, expr, "math")


def curves(problem: Problem) -> Curves:
    """The velocities along n after the impact and the fraction of kinetic energy lost, for e in [0, 1]."""
    outcome = solve_impact(problem)
    problem = forward(problem, outcome)
    if problem is not outcome.problem:
        outcome = solve_impact(problem)
    ind = independent_map(problem)
    e = problem.given("e").symbol
    e = ind.get(e, e) if isinstance(ind.get(e, e), sympy.Symbol) else e  # in a chain, e = e_floor
    known = {s: v for s, v in problem.numeric().items() if s != e}

    def closed(name: str) -> sympy.Expr:
        return outcome.results[name].closed.xreplace(ind).xreplace(known)

    speeds = [
        g
        for g in problem.givens
        if g.dim == units.VELOCITY and g.value is None and g.definition is None and not g.unknown
    ]
    per = speeds[0].symbol if len(speeds) == 1 else None
    names = ["v_A2n", "v_B2n"] if problem.oblique else ["v_A2", "v_B2"]
    if problem.fixed_B:
        names = names[:1]
    grid = tuple(k / (SAMPLES - 1) for k in range(SAMPLES))
    series = []
    for name in names:
        f = _function(closed(name), e, per, name)
        series.append(Series(name, tuple(float(f(x)) for x in grid), "velocity"))
    lost = _function(closed("T_lost") / closed("T_1"), e, None, "T_lost/T_1")
    series.append(Series("T_lost/T_1", tuple(float(lost(x)) for x in grid), "energy"))
    e_value = outcome.values.get(e, problem.numeric().get(e, problem.numeric().get(problem.given("e").symbol)))
    mark = float(e_value) if e_value is not None and not sympy.sympify(e_value).free_symbols else None
    unit = units.working_unit(units.VELOCITY, problem.system).text
    return Curves(problem.title, grid, tuple(series), mark, unit, str(per) if per is not None else None)
