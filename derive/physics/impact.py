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

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import sympy

from derive.errors import SolveError
from derive.physics.forms import factored
from derive.physics.periodic import periodic_roots
from derive.physics.recent import Recent
from derive.physics.roots import distinct, holds, known_angles, polar_roots, singular, tidy
from derive.physics.roots import roots as _roots  # the cache tests read as impact._roots
from derive.problem import Problem
from derive.problem.units import VELOCITY
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
    inverse: bool = False
    others: tuple[dict[sympy.Symbol, sympy.Expr], ...] = ()
    #: velocities given as 0 (B at rest), put in the closed forms (not in the equations shown)
    rest: tuple[tuple[sympy.Symbol, sympy.Expr], ...] = ()

    def in_givens(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` (in component symbols) with the pre-impact components in the givens."""
        return expr.xreplace(self.pre).xreplace(self.independent).xreplace(dict(self.rest))


def independent_map(problem: Problem) -> dict[sympy.Symbol, sympy.Expr]:
    """Symbolic givens defined from other givens -> their definition (m_A -> m).

    Replacing them lets a mass shared by A and B cancel, as in Example 4.C.12.
    """
    out: dict[sympy.Symbol, sympy.Expr] = {}
    for g in problem.givens:
        if g.value is None and g.definition is not None:
            out[g.symbol] = g.definition.xreplace(out)
    return out


def equation_numbers(problem: Problem) -> tuple[int, ...]:
    """Which of (1)-(4) carry information: no t equations in a direct impact, and
    against a fixed B neither (2) (B does not move) nor (3) (the supports of a wall
    exert an impulse, so A + B is not free along n)."""
    nums = [1, 2, 3, 4] if problem.oblique else [3, 4]
    if problem.fixed_B:
        nums = [k for k in nums if k not in (2, 3)]
    return tuple(nums)


#: The impacts set up lately, found again by the problem's value (:mod:`.recent`): a check sets
#: up its problem twice (for the worked solution and for the mistakes' model), and a problem
#: loaded again from its file is set up once.
_SET_UP: Recent[Impact] = Recent(8)


def setup(problem: Problem) -> Impact:
    """Equations (1)-(4) for ``problem`` solved in closed form (:func:`_setup`), once per problem
    value: the Impact is frozen and nothing changes its dictionaries."""
    return _SET_UP.get(problem, lambda: _setup(problem), lambda imp: dataclasses.replace(imp, problem=problem))


def _setup(problem: Problem) -> Impact:
    """Set up equations (1)-(4) for ``problem`` and solve them in closed form.

    The unknowns are the velocities after the impact that the file does not give,
    plus the givens it marks "?". Their number must equal the number of
    equations; of several roots only the physical one is kept.
    """
    nm = names(problem)
    sym = problem.symbols()
    m_A, e = sym["m_A"], sym["e"]
    m_B = sym.get("m_B", symbol("m_B", "positive"))
    eqs = _equations(problem, nm, m_A, m_B, e)
    # a velocity given as 0 (v_B1 = 0, B at rest) is 0 in the closed forms too, unless variants vary it
    rest = {
        g.symbol: sympy.Integer(0)
        for g in problem.givens
        if g.value == 0 and g.definition is None and g.dim == VELOCITY and g.name not in problem.vary
    }
    pre = _pre(problem, nm)
    ind = independent_map(problem)
    post_all = (nm.A2t, nm.B2t, nm.A2n, nm.B2n) if problem.oblique else (nm.A2n, nm.B2n)
    given_names = {g.name for g in problem.givens}
    post_unknown = tuple(u for u in post_all if u.name not in given_names and u not in pre)
    unknowns = post_unknown + problem.unknowns()
    directions = []
    for j, rel in enumerate(problem.asks.equations, start=5):  # conditions beyond (1)-(4)
        eqs[j], direction = extra_equation(problem, nm, rel, (m_A, m_B))
        if direction is not None:
            directions.append(direction)
    _check_count(problem, tuple(eqs), unknowns)
    system = []
    for k, eq in eqs.items():
        lhs, rhs = eq.lhs, eq.rhs
        if k == 4:  # clear the denominator: e (v_A1n - v_B1n) = v_B2n - v_A2n
            lhs, rhs = e * (nm.A1n - nm.B1n), nm.B2n - nm.A2n
        system.append(sympy.expand((lhs - rhs).xreplace(ind)))
    inverse = (
        bool(problem.unknowns())
        or len(eqs) > 4
        or len(post_unknown)
        < len(post_all) - (2 if problem.fixed_B and problem.oblique else 1 if problem.fixed_B else 0)
    )
    if not inverse:
        # Solved in the component symbols, the system is linear with rational
        # coefficients: fast and exact. The givens go in afterwards; the factored
        # forms depend on the problem's structure only (derive.physics.forms).
        forms = general_solution(nm, m_A, m_B, e, problem.fixed_B)
        zero = {k: v for k, v in pre.items() if v == 0}
        by_comp = {u: factored(forms[u].xreplace(ind).xreplace(zero)) for u in unknowns}
        closed = {u: sympy.factor_terms(c.xreplace(pre).xreplace(ind).xreplace(rest)) for u, c in by_comp.items()}
        return Impact(problem, nm, eqs, pre, ind, unknowns, closed, by_comp, rest=tuple(rest.items()))
    full = [sympy.expand(s.xreplace(pre).xreplace(ind).xreplace(rest)) for s in system]
    angles = known_angles(problem, full, unknowns)
    full = [sympy.expand(s.xreplace(angles)) for s in full]
    turned = [tuple(x.xreplace(pre).xreplace(angles) for x in d) for d in directions]
    by_comp, *others = _solve_inverse(problem, full, unknowns, turned)
    closed = {u: sympy.factor_terms(c) for u, c in by_comp.items()}
    kept = {"inverse": True, "others": tuple(others), "rest": tuple(rest.items())}
    return Impact(problem, nm, eqs, pre, ind, unknowns, closed, by_comp, **kept)


def _equations(problem: Problem, nm: Names, m_A: sympy.Expr, m_B: sympy.Expr, e: sympy.Expr) -> dict[int, sympy.Eq]:
    """Equations (1)-(4), those of them that carry information (:func:`equation_numbers`)."""
    eqs: dict[int, sympy.Eq] = {}
    nums = equation_numbers(problem)
    if 1 in nums:
        eqs[1] = sympy.Eq(m_A * nm.A1t, m_A * nm.A2t, evaluate=False)
    if 2 in nums:
        eqs[2] = sympy.Eq(m_B * nm.B1t, m_B * nm.B2t, evaluate=False)
    if 3 in nums:
        eqs[3] = sympy.Eq(m_A * nm.A1n + m_B * nm.B1n, m_A * nm.A2n + m_B * nm.B2n, evaluate=False)
    eqs[4] = sympy.Eq(e, (nm.B2n - nm.A2n) / (nm.A1n - nm.B1n), evaluate=False)
    return eqs


def _pre(problem: Problem, nm: Names) -> dict[sympy.Symbol, sympy.Expr]:
    """Each component known before the solve -> its expression in the givens: the
    pre-impact components, and a fixed B's (0, before and after)."""
    pre: dict[sympy.Symbol, sympy.Expr] = {}
    if problem.oblique:
        pre = {
            nm.A1n: problem.motion_A.n,
            nm.A1t: problem.motion_A.t,
            nm.B1n: problem.motion_B.n,
            nm.B1t: problem.motion_B.t,
        }
    elif problem.fixed_B:
        pre = {nm.B1n: sympy.Integer(0)}
    if problem.fixed_B:
        pre[nm.B2n] = sympy.Integer(0)
        if problem.oblique:
            pre[nm.B2t] = sympy.Integer(0)
    return pre


def general_solution(
    nm: Names, m_A: sympy.Expr, m_B: sympy.Expr, e: sympy.Expr, fixed_B: bool
) -> dict[sympy.Symbol, sympy.Expr]:
    """Equations (1)-(4) solved once for all, in the component symbols:

        v_A2t = v_A1t,  v_B2t = v_B1t,
        v_A2n = (m_A v_A1n + m_B v_B1n - e m_B (v_A1n - v_B1n)) / (m_A + m_B),
        v_B2n = (m_A v_A1n + m_B v_B1n + e m_A (v_A1n - v_B1n)) / (m_A + m_B);

    against a fixed B (infinite mass, at rest), v_A2n = -e v_A1n. A problem puts its
    numbers in; nothing is solved again (tests/test_physics.py checks these forms
    against (1)-(4))."""
    if fixed_B:
        forms = {nm.A2n: -e * nm.A1n}
    else:
        momentum = m_A * nm.A1n + m_B * nm.B1n
        approach = nm.A1n - nm.B1n
        forms = {
            nm.A2n: (momentum - e * m_B * approach) / (m_A + m_B),
            nm.B2n: (momentum + e * m_A * approach) / (m_A + m_B),
        }
    if nm.A2t is not None:
        forms[nm.A2t] = nm.A1t
        forms[nm.B2t] = nm.B1t
    return forms


def _check_count(problem: Problem, nums: tuple[int, ...], unknowns: tuple[sympy.Symbol, ...]) -> None:
    listed = ", ".join(f"({k})" for k in nums)
    names_ = ", ".join(u.name for u in unknowns) or "none"
    if len(unknowns) > len(nums):
        raise SolveError(
            f"{len(nums)} equations {listed} cannot determine {len(unknowns)} unknowns ({names_}): "
            f"give {len(unknowns) - len(nums)} more of them a value",
            where=problem.path,
            field="[given]",
        )
    if len(unknowns) < len(nums):
        extra = len(nums) - len(unknowns)
        raise SolveError(
            f"{len(nums)} equations {listed} but only {len(unknowns)} unknown{'' if len(unknowns) == 1 else 's'} ({names_}): the givens over-determine the impact; "
            f'mark {extra} more given(s) "?" or remove {extra} of the velocities after the impact',
            where=problem.path,
            field="[given]",
        )


def _solve_inverse(
    problem: Problem,
    system: list[sympy.Expr],
    unknowns: tuple[sympy.Symbol, ...],
    directions: list[tuple[sympy.Expr, sympy.Expr, sympy.Expr]] = (),  # type: ignore[assignment]
) -> list[dict[sympy.Symbol, sympy.Expr]]:
    """Solve a system that may be nonlinear (an unknown angle, e times a velocity)
    and keep the physical roots; a direction given after the impact, (y, x, angle),
    keeps only the roots that point that way (not the opposite way).

    Where several distinct roots are physical the data do not choose: all are kept
    (listed, not refused), the one with the smallest unknowns first."""
    numeric = problem.numeric()
    roots = periodic_roots(problem, system, unknowns, numeric, _roots)
    if roots is None:
        roots = [dict(root) for root in _roots(tuple(system), tuple(unknowns))]
    if any(singular(root, numeric) for root in roots):  # a closed form 0/0 at these numbers: solve with them
        numbers = tuple(sympy.sympify(x).xreplace(numeric) for x in system)
        roots = [dict(root) for root in _roots(numbers, tuple(unknowns))]
    roots = [r for r in roots if set(r) == set(unknowns) and holds(system, r, numeric)]
    if not roots:  # SymPy found no whole root in the letters (an unknown line of impact): in the numbers
        in_numbers = tuple(sympy.expand(s.xreplace(numeric)) for s in system)
        roots = [dict(root) for root in _roots(in_numbers, tuple(unknowns))]
        roots = [r for r in roots if set(r) == set(unknowns) and holds(list(in_numbers), r, numeric)]
        if not roots:
            roots = [r for r in polar_roots(in_numbers, tuple(unknowns)) if holds(list(in_numbers), r, numeric)]
    kept = [r for r in roots if _physical(problem, r, numeric) and all(_points(r, numeric, d) for d in directions)]
    if not kept:  # measured velocities may imply e > 1 (a gain of kinetic energy): solved, and the page says so
        kept = [
            r
            for r in roots
            if _physical(problem, r, numeric, gain=True) and all(_points(r, numeric, d) for d in directions)
        ]
    kept = [{u: tidy(v) for u, v in root.items()} for root in kept]
    if not kept:
        found = [r for r in roots if set(r) == set(unknowns)]
        shown = ""
        if found:
            from derive.numbers import format_number

            parts = []
            for u in unknowns:
                v = found[0][u].xreplace(numeric)
                parts.append(
                    f"{u.name} = {format_number(v, 4)}" if not v.free_symbols and v.is_real else f"{u.name} = {v}"
                )
            shown = f": the solution {', '.join(parts)} is not physical (e must lie between 0 and 1, masses be positive, speeds not negative, and the bodies approach)"
        raise SolveError(
            "the equations have no physical solution for these givens"
            + (shown or " (check the signs and the numbers)"),
            where=problem.path,
        )
    asked = set(problem.unknowns())
    return distinct(kept, tuple(sorted(unknowns, key=lambda u: u not in asked)), numeric)


def _points(root: dict[sympy.Symbol, sympy.Expr], numeric: dict[sympy.Symbol, sympy.Expr], direction: tuple) -> bool:
    """True when the root's (y, x) points at the given angle (not 180° away from it)."""
    y, x, angle = (sympy.sympify(d).xreplace(root).xreplace(numeric) for d in direction)
    if y.free_symbols | x.free_symbols | angle.free_symbols:
        return True
    yv, xv, a = (complex(sympy.N(v)).real for v in (y, x, angle))
    return yv * math.sin(a) + xv * math.cos(a) > 0


def extra_equation(
    problem: Problem, nm: Names, rel: Any, masses: tuple[sympy.Expr, sympy.Expr]
) -> tuple[sympy.Eq, tuple[sympy.Expr, sympy.Expr, sympy.Expr] | None]:
    """A condition of the file (``T_2 = 3/4*T_1``, a direction after the impact) as an
    equation in the component symbols; for a direction, also (y, x, angle) to pick the root."""
    forms = result_forms(problem, nm, masses)
    directions = {
        "theta_A2": (nm.A2n, nm.A2t),
        "theta_B2": (nm.B2n, nm.B2t),
        "beta_A2": (nm.A2t, nm.A2n),
        "beta_B2": (nm.B2t, nm.B2n),
    }
    name = rel.lhs.name if isinstance(rel.lhs, sympy.Symbol) else None
    if name in directions and not rel.rhs.free_symbols:  # theta_A2 = 30°: v_A2n cos 30° = v_A2t sin 30°
        y, x = directions[name]
        angle = rel.rhs * sympy.pi / 180
        return sympy.Eq(y * sympy.cos(angle), x * sympy.sin(angle), evaluate=False), (y, x, angle)
    return sympy.Eq(rel.lhs.xreplace(forms), rel.rhs.xreplace(forms), evaluate=False), None


def result_forms(problem: Problem, nm: Names, masses: tuple[sympy.Expr, sympy.Expr]) -> dict[sympy.Symbol, sympy.Expr]:
    """Each result a condition may name, in the component symbols (T_2 = 1/2 m_A v_A2^2 + ...)."""
    m_A, m_B = masses
    half = sympy.Rational(1, 2)
    zero = sympy.Integer(0)
    t = {k: (getattr(nm, k) if problem.oblique else zero) for k in ("A1t", "A2t", "B1t", "B2t")}
    b = zero if problem.fixed_B else m_B
    T1 = half * m_A * (nm.A1n**2 + t["A1t"] ** 2) + half * b * (nm.B1n**2 + t["B1t"] ** 2)
    T2 = half * m_A * (nm.A2n**2 + t["A2t"] ** 2) + half * b * (nm.B2n**2 + t["B2t"] ** 2)
    forms = {symbol("T_1"): T1, symbol("T_2"): T2, symbol("T_lost"): T1 - T2, symbol("J_n"): m_A * (nm.A1n - nm.A2n)}
    if problem.oblique:
        for body in "AB":
            n, tt = getattr(nm, f"{body}2n"), getattr(nm, f"{body}2t")
            forms[symbol(f"v_{body}2")] = sympy.sqrt(n**2 + tt**2)
            forms[symbol(f"theta_{body}2")] = sympy.atan2(n, tt)
            forms[symbol(f"beta_{body}2")] = sympy.atan2(tt, n)
            if problem.phi is not None:  # x-y axes: n at phi from +x toward +y, t at phi + 90 deg
                c, s_ = sympy.cos(problem.phi), sympy.sin(problem.phi)
                forms[symbol(f"v_{body}2x")] = n * c - tt * s_
                forms[symbol(f"v_{body}2y")] = n * s_ + tt * c
    return forms


def _physical(
    problem: Problem, root: dict[sympy.Symbol, sympy.Expr], numeric: dict[sympy.Symbol, sympy.Expr], gain: bool = False
) -> bool:
    """A root is physical when it is real and e lies in [0, 1], masses are positive,
    speeds are not negative, angles lie in (-180°, 180°] and the bodies approach. With
    ``gain``, an e found above 1 from numbers alone passes too (velocities measured after
    the impact that imply a gain of kinetic energy: the page says so)."""
    for u, val in root.items():
        v = val.xreplace(numeric)
        if v.free_symbols:
            continue
        num = complex(sympy.N(v, 30))
        if abs(num.imag) > 1e-9 * max(1.0, abs(num.real)):
            return False
        x = num.real
        g = next((g for g in problem.givens if g.symbol == u), None)
        if u.name == "e" and not (-1e-12 <= x <= 1 + 1e-12) and not (gain and x > 1):
            return False
        if u.is_positive and x <= 0:
            return False
        if u.is_nonnegative and x < -1e-12:
            return False
        if g is not None and g.unit == "deg" and not (-math.pi < x <= math.pi):
            return False
        if g is not None and problem.assume.get(g.name) == "acute" and not (0 < x < math.pi / 2):
            return False
    approach = (
        (problem.motion_A.n - problem.motion_B.n).xreplace(independent_map(problem)).xreplace(root).xreplace(numeric)
    )
    if approach.free_symbols:  # letters: physical unless their assumptions say they part (U sin(-73°) < 0)
        return sympy.sympify(approach).is_positive is not False
    return complex(sympy.N(approach)).real > 0


def evaluate(expr: sympy.Expr, problem: Problem, *, decimals: bool = False) -> sympy.Expr:
    """``expr`` with every numeric given substituted (exact); symbols without numbers stay.

    With ``decimals``, the givens the file wrote as decimals go in as Floats, so that an
    expression that keeps a letter shows where its numbers came from (0.9 u, not 9u/10).
    """
    ind = independent_map(problem)
    numeric = problem.numeric()
    if decimals:
        numeric.update({g.symbol: sympy.Float(g.value.evalf(30), 30) for g in problem.givens if g.decimal})
    return expr.xreplace(ind).xreplace(numeric)


def numbered(imp: Impact) -> dict[int, sympy.Expr]:
    """Each of the impact's equations as ``lhs - rhs``, in the givens, with every number in."""
    out = {}
    for k, eq in imp.equations.items():
        lhs, rhs = eq.lhs, eq.rhs
        if k == 4:  # e (v_A1n - v_B1n) = v_B2n - v_A2n
            lhs, rhs = eq.lhs * (imp.names.A1n - imp.names.B1n), imp.names.B2n - imp.names.A2n
        out[k] = evaluate((lhs - rhs).xreplace(imp.pre), imp.problem)
    return out


def root_rule(imp: Impact, u: sympy.Symbol) -> str | None:
    """Which rule picks the physical root of the unknown ``u`` where its equations are not
    linear in it: 'e' (0 <= e <= 1), 'angle' (between -180° and 180°, the bodies
    approaching) or 'sign' (a speed or mass not negative); None when the root is unique."""
    eqs = [ex for ex in numbered(imp).values() if ex.has(u)]
    if not any(not ex.is_polynomial(u) or sympy.degree(ex, u) > 1 for ex in eqs):
        return None
    if u.name == "e":
        return "e"
    g = next((g for g in imp.problem.givens if g.symbol == u), None)
    if g is not None and g.unit == "deg":
        return "angle"
    if u.is_positive or u.is_nonnegative:
        return "sign"
    return None
