"""The physics of central impact: equations (1)-(4) of the notes, solved in closed form.

Three systems (A alone, B alone, A and B together) give, with n the line of
impact (from A's centre toward B's) and t the plane of contact::

    (1) m_A v_A1t = m_A v_A2t                              t-momentum of A
    (2) m_B v_B1t = m_B v_B2t                              t-momentum of B
    (3) m_A v_A1n + m_B v_B1n = m_A v_A2n + m_B v_B2n      n-momentum of A+B
    (4) e = (v_B2n - v_A2n) / (v_A1n - v_B1n)              restitution, n only

A direct impact has no t components and names its n components ``v_A1``,
``v_A2``, ... This module sets the equations up, solves them and derives the
speeds, angles and kinetic energies; it formats nothing.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from derive.errors import SolveError
from derive.problem import Problem
from derive.symbols import symbol


@dataclass(frozen=True)
class Names:
    """The component symbols of a problem (n and t, before and after)."""

    A1n: sympy.Symbol
    B1n: sympy.Symbol
    A2n: sympy.Symbol
    B2n: sympy.Symbol
    A1t: sympy.Symbol | None
    B1t: sympy.Symbol | None
    A2t: sympy.Symbol | None
    B2t: sympy.Symbol | None


def names(problem: Problem) -> Names:
    """Component symbols: ``v_A1n`` ... for an oblique impact, ``v_A1`` ... for a direct one."""
    if problem.oblique:
        s = {k: symbol(f"v_{k}") for k in ("A1n", "B1n", "A2n", "B2n", "A1t", "B1t", "A2t", "B2t")}
        return Names(**s)
    s = {k + "n": symbol(f"v_{k}") for k in ("A1", "B1", "A2", "B2")}
    return Names(**s, A1t=None, B1t=None, A2t=None, B2t=None)


@dataclass(frozen=True)
class Impact:
    """Equations (1)-(4) and what the solution needs from them.

    ``equations`` are in the component symbols; ``pre`` maps each pre-impact
    component to its expression in the givens; ``independent`` maps a given
    defined from symbolic givens (m_A = m) to that definition; ``closed`` maps
    each unknown to its closed form in the givens' symbols.
    """

    problem: Problem
    names: Names
    equations: dict[int, sympy.Eq]
    pre: dict[sympy.Symbol, sympy.Expr]
    independent: dict[sympy.Symbol, sympy.Expr]
    unknowns: tuple[sympy.Symbol, ...]
    closed: dict[sympy.Symbol, sympy.Expr]
    by_components: dict[sympy.Symbol, sympy.Expr]

    def in_givens(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` (in component symbols) with the pre-impact components in the givens."""
        return expr.xreplace(self.pre).xreplace(self.independent)


def independent_map(problem: Problem) -> dict[sympy.Symbol, sympy.Expr]:
    """Symbolic givens defined from other givens -> their definition (m_A -> m).

    Replacing them lets a mass shared by A and B cancel, as in Example 4.C.12.
    """
    out: dict[sympy.Symbol, sympy.Expr] = {}
    for g in problem.givens:
        if g.value is None and g.definition is not None:
            out[g.symbol] = g.definition.xreplace(out)
    return out


def setup(problem: Problem) -> Impact:
    """Set up equations (1)-(4) for ``problem`` and solve them in closed form."""
    nm = names(problem)
    sym = problem.symbols()
    m_A, m_B, e = sym["m_A"], sym["m_B"], sym["e"]
    eqs: dict[int, sympy.Eq] = {}
    if problem.oblique:
        eqs[1] = sympy.Eq(m_A * nm.A1t, m_A * nm.A2t, evaluate=False)
        eqs[2] = sympy.Eq(m_B * nm.B1t, m_B * nm.B2t, evaluate=False)
    eqs[3] = sympy.Eq(m_A * nm.A1n + m_B * nm.B1n, m_A * nm.A2n + m_B * nm.B2n, evaluate=False)
    eqs[4] = sympy.Eq(e, (nm.B2n - nm.A2n) / (nm.A1n - nm.B1n), evaluate=False)
    pre: dict[sympy.Symbol, sympy.Expr] = {}
    if problem.oblique:
        pre = {
            nm.A1n: problem.motion_A.n,
            nm.A1t: problem.motion_A.t,
            nm.B1n: problem.motion_B.n,
            nm.B1t: problem.motion_B.t,
        }
    ind = independent_map(problem)
    unknowns = (nm.A2t, nm.B2t, nm.A2n, nm.B2n) if problem.oblique else (nm.A2n, nm.B2n)
    system = []
    for k, eq in eqs.items():
        lhs, rhs = eq.lhs, eq.rhs
        if k == 4:  # clear the denominator: e (v_A1n - v_B1n) = v_B2n - v_A2n
            lhs, rhs = e * (nm.A1n - nm.B1n), nm.B2n - nm.A2n
        system.append(sympy.expand((lhs - rhs).xreplace(ind)))
    # Solved in the component symbols, the system is linear with rational
    # coefficients: fast and exact. The givens go in afterwards.
    sol = sympy.solve(system, unknowns, dict=True)
    if len(sol) != 1 or set(sol[0]) != set(unknowns):
        raise SolveError(
            "equations (1)-(4) do not determine the velocities after the impact for these givens",
            where=problem.path,
        )
    by_comp = {u: sympy.factor(sol[0][u]) for u in unknowns}
    closed = {u: sympy.factor_terms(c.xreplace(pre).xreplace(ind)) for u, c in by_comp.items()}
    return Impact(problem, nm, eqs, pre, ind, unknowns, closed, by_comp)


def evaluate(expr: sympy.Expr, problem: Problem) -> sympy.Expr:
    """``expr`` with every numeric given substituted (exact); symbols without numbers stay."""
    ind = independent_map(problem)
    return expr.xreplace(ind).xreplace(problem.numeric())


def is_numeric(expr: sympy.Expr) -> bool:
    """True when ``expr`` has no free symbols left."""
    return not expr.free_symbols
