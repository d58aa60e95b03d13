"""A problem's correct equations (1)-(4), and how to solve a mistaken version of them.

The equations come from :func:`derive.physics.impact.setup`; a :class:`Variant`
only changes what its mistake changes. :meth:`Model.outcome` solves a variant
and derives every result of the problem from it (:mod:`.quantities`).
"""

from __future__ import annotations

import copy
import functools
import random
from collections.abc import Mapping

import sympy
from sympy.polys.polyerrors import BasePolynomialError

from derive.checking.mistakes.quantities import results_of
from derive.checking.mistakes.records import Mistake, Outcome, Variant
from derive.physics.algebra import satisfies
from derive.physics.energy import kinetic_energy
from derive.physics.impact import Impact, equation_numbers, setup
from derive.steps.model import Solution
from derive.symbols import symbol

#: Stand-ins for the n components of the velocities before the impact as the
#: impact rule (4) uses them (one mistake puts the speeds there).
APPROACH_A = sympy.Symbol("approach_A", real=True)
APPROACH_B = sympy.Symbol("approach_B", real=True)


class Model:
    """A problem's correct equations and numbers, and the machinery to solve a variant of them."""

    def __init__(self, solution: Solution) -> None:
        p = solution.problem
        self.results = solution.results  # not the solution itself: the cache holds models weakly by solution
        self.problem = p
        self.imp: Impact = setup(p)
        nm = self.nm = self.imp.names
        self.numbers = equation_numbers(p)
        sym = p.symbols()
        self.m_A, self.e = sym["m_A"], sym["e"]
        self.m_B = sym.get("m_B", symbol("m_B", "positive"))
        self.ind = self.imp.independent
        self.numeric = p.numeric()
        post = (nm.A2n, nm.B2n, nm.A2t, nm.B2t)
        self.zeros = {k: v for k, v in self.imp.pre.items() if k in post}
        pre_names = [nm.A1n, nm.B1n] + ([nm.A1t, nm.B1t] if p.oblique else [])
        self.pre = {k: self.imp.pre.get(k, k) for k in pre_names}
        self.unknowns = self.imp.unknowns
        self.inverse = self.imp.inverse
        self._structures: dict[tuple, dict[sympy.Symbol, sympy.Expr] | None] = {}

    # numbers ------------------------------------------------------------
    def num(self, expr: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr] | None = None) -> sympy.Expr:
        """``expr`` with the numeric givens in (``values`` overriding some)."""
        vals = {**self.numeric, **(values or {})}
        return sympy.sympify(expr).xreplace(self.ind).xreplace(vals)

    def is_zero(self, expr: sympy.Expr) -> bool:
        """True when ``expr`` (numbers in) is zero, also at a random point for symbolic givens."""
        v = self.num(expr)
        if v == 0:
            return True
        if v.free_symbols:
            v = v.xreplace(point(v.free_symbols))
        try:
            return abs(complex(v.evalf(30))) < 1e-20
        except (TypeError, ValueError):
            return False

    def base(self) -> Variant:
        """The correct equations."""
        return Variant()

    def under(self, v: Variant) -> Model:
        """This model as a student who made ``v``'s mistake sees it: ``v``'s components
        before the impact and numbers in place of the correct ones (to build a second
        mistake on the first)."""
        m = copy.copy(self)  # shares the solved forms of the equations, which hold no numbers
        if v.pre is not None:
            m.pre = dict(v.pre)
        m.numeric = {**self.numeric, **v.values}
        return m

    # equations ------------------------------------------------------------
    def equations(self, v: Variant) -> dict[int, sympy.Expr]:
        """Equations (1)-(4) of ``v`` as ``lhs - rhs`` in the component symbols, with
        placeholders for the masses, e and (in (4)) the approach components."""
        nm, p = self.nm, self.problem
        mA, mB, e = self.m_A, self.m_B, self.e
        k = v.t_factor if v.t_factor is not None else (e if v.t_rule == "scaled" else 1)
        eqs: dict[int, sympy.Expr] = {}
        if p.oblique:
            if v.t_rule == "system":
                eqs[1] = k * (mA * nm.A1t + mB * nm.B1t) - mA * nm.A2t - mB * nm.B2t
                eqs[2] = nm.A2t - nm.B2t
            else:
                if 1 in self.numbers:
                    eqs[1] = mA * (k * nm.A1t - nm.A2t)
                if 2 in self.numbers:
                    eqs[2] = mB * (k * nm.B1t - nm.B2t)
        if 3 in self.numbers:
            eqs[3] = mA * nm.A1n + mB * nm.B1n - mA * nm.A2n - mB * nm.B2n
        sep = nm.B2n - nm.A2n if v.restitution == "normal" else nm.A2n - nm.B2n
        eqs[4] = e * (APPROACH_A - APPROACH_B) - sep
        for k, eq in self.imp.equations.items():  # the file's own conditions (5), (6), ...: kept as they are
            if k > 4:
                eqs[k] = eq.lhs - eq.rhs
        return eqs

    def energy_equation(self) -> sympy.Expr:
        """Kinetic energy before minus after, in the component symbols."""
        nm, p = self.nm, self.problem
        t = (nm.A1t, nm.B1t, nm.A2t, nm.B2t) if p.oblique else (0, 0, 0, 0)
        before = kinetic_energy(self.m_A, nm.A1n, t[0]) + kinetic_energy(self.m_B, nm.B1n, t[1])
        after = kinetic_energy(self.m_A, nm.A2n, t[2]) + kinetic_energy(self.m_B, nm.B2n, t[3])
        return before - after

    def substitutions(self, v: Variant) -> dict[sympy.Symbol, sympy.Expr]:
        """Placeholders -> what ``v`` puts there (components before, masses, e, approach)."""
        pre = dict(v.pre) if v.pre is not None else dict(self.pre)
        approach = v.approach if v.approach is not None else (pre[self.nm.A1n], pre[self.nm.B1n])
        masses = v.masses if v.masses is not None else (self.m_A, self.m_B)
        subs = {**pre, APPROACH_A: approach[0], APPROACH_B: approach[1], self.m_A: masses[0], self.m_B: masses[1]}
        subs[self.e] = v.e if v.e is not None else self.e
        return subs

    def structure(self, v: Variant) -> dict[sympy.Symbol, sympy.Expr] | None:
        """The solution of ``v``'s equations in the component symbols (cached by form)."""
        key = (v.restitution, v.t_rule, v.t_factor)
        if key not in self._structures:
            eqs = [sympy.expand(x.xreplace(self.zeros)) for x in self.equations(v).values()]
            sol = sympy.solve(eqs, self.unknowns, dict=True)
            ok = len(sol) == 1 and set(sol[0]) == set(self.unknowns)
            self._structures[key] = sol[0] if ok else None
        return self._structures[key]

    def solve(self, v: Variant) -> dict[sympy.Symbol, sympy.Expr] | None:
        """The components after the impact (and unknown givens) under ``v``, numbers in."""
        subs = self.substitutions(v)
        if not self.inverse:
            sol = self.structure(v)
            if sol is None:
                return None
            return {u: self.num(sol[u].xreplace(subs), v.values) for u in self.unknowns}
        eqs = [self.num(x.xreplace(self.zeros).xreplace(subs), v.values) for x in self.equations(v).values()]
        return self.roots(eqs)

    def roots(
        self, eqs: list[sympy.Expr], near: Mapping[sympy.Symbol, sympy.Expr] | None = None
    ) -> dict[sympy.Symbol, sympy.Expr] | None:
        """The most plausible real root of ``eqs`` (numbers in) in the unknowns (then the one
        nearest ``near``, the true values), or None."""
        roots = [dict(root) for root in real_roots(tuple(eqs), tuple(self.unknowns)) or ()]
        if not roots:
            return None
        roots.sort(key=lambda r: (-self._plausible(r), _distance(r, near)))
        return roots[0]

    def _plausible(self, root: dict[sympy.Symbol, sympy.Expr]) -> int:
        score = 0
        for u, val in root.items():
            x = as_float(val)
            if x is None:
                continue
            if u.name == "e" and 0 <= x <= 1:
                score += 1
            if u.is_positive and x > 0:
                score += 1
        return score

    def outcome(self, v: Variant, m: Mistake | None = None) -> Outcome | None:
        """Solve ``v`` and derive every result of the problem from it."""
        # the correct inverse problem: the solution's physical root
        sol = {u: self._correct(u) for u in self.unknowns} if m is None and self.inverse else self.solve(v)
        if sol is None:
            return None
        nm, subs = self.nm, self.substitutions(v)
        post = {c: sol.get(c, self.zeros.get(c, c)) for c in (nm.A2n, nm.B2n, nm.A2t, nm.B2t) if c is not None}
        post = {c: self.num(x, v.values) for c, x in post.items()}
        for u in self.unknowns:
            post[u] = sol[u]
        known = dict(sol)
        pre = {c: self.num(subs[c], v.values).xreplace(known) for c in self.pre}
        masses = (self.num(subs[self.m_A], v.values), self.num(subs[self.m_B], v.values))
        if self.problem.fixed_B:
            masses = (masses[0], sympy.Integer(0))
        masses = (masses[0].xreplace(known), masses[1].xreplace(known))
        res = results_of(self.problem, nm, pre, post, masses, known, v.angles, lambda x: self.num(x, v.values))
        return Outcome(m, res, post, self.numbered(v), self.unknowns)

    def numbered(self, v: Variant, equations: dict[int, sympy.Expr] | None = None) -> dict[int, sympy.Expr]:
        """``v``'s equations (or ``equations``, in its placeholders) as ``lhs - rhs`` with the
        numbers in and the unknowns as symbols: what a student who made the mistake writes,
        whether or not they can be solved."""
        eqs = dict(equations) if equations is not None else self.equations(v)
        if v.energy and equations is None:
            eqs[4] = self.energy_equation()
        subs = self.substitutions(v)
        return {k: self.num(x.xreplace(self.zeros).xreplace(subs), v.values) for k, x in eqs.items()}

    def _correct(self, u: sympy.Symbol) -> sympy.Expr:
        r = self.results[u.name]
        if r.unit == "deg":
            return r.value * sympy.pi / 180 if r.value is not None else r.partial * sympy.pi / 180
        return r.value if r.value is not None else r.partial


@functools.lru_cache(maxsize=512)
def real_roots(
    eqs: tuple[sympy.Expr, ...], unknowns: tuple[sympy.Symbol, ...]
) -> tuple[tuple[tuple[sympy.Symbol, sympy.Expr], ...], ...] | None:
    """The real roots of ``eqs`` (numbers in) in ``unknowns`` that fix every one of them (None
    where SymPy cannot solve the system); kept for the process: a problem's mistakes are solved
    again by every check of a derivation of it (a second each, with an unknown angle)."""
    # plain real unknowns: a mistaken e may come out negative, a mistaken mass too
    plain = {u: sympy.Dummy(u.name, real=True) for u in unknowns}
    back = {d: u for u, d in plain.items()}
    try:
        system = [sympy.expand(x.xreplace(plain)) for x in eqs]
        # a mistake's value is a number to show: with surds among the numbers (cos 30° of a
        # drawn variant), solving exactly factors over their number field (a minute for
        # ocr-m3-2013's STACK export), so such a system is solved in 30-digit decimals
        exact = not any(_surd(a) for x in system for a in x.atoms(sympy.Pow, sympy.Function))
        system = system if exact else [x.evalf(30) for x in system]
        # SymPy's check of each root simplifies every equation (seconds for an angle among
        # letters, issue #19); satisfies() decides the same, mostly by numbers
        found = sympy.solve(
            system, list(plain.values()), dict=True, check=False, simplify=False, rational=None if exact else False
        )
        found = [r for r in found if satisfies(system, r)]
    except (NotImplementedError, BasePolynomialError):  # NotInvertible: SymPy's algebraic domain gave up
        return None  # this mistake gives no value here (as with no root)
    roots = [{back[d]: val for d, val in r.items()} for r in found]
    roots = [r for r in roots if set(r) == set(unknowns) and all(is_real(r[u]) for u in unknowns)]
    return tuple(tuple(r.items()) for r in roots)


def _distance(root: Mapping[sympy.Symbol, sympy.Expr], near: Mapping[sympy.Symbol, sympy.Expr] | None) -> float:
    if not near:
        return 0.0
    return sum(abs((as_float(root[u]) or 0.0) - (as_float(near[u]) or 0.0)) for u in root if u in near)


def _surd(a: sympy.Expr) -> bool:
    """A number that is not rational: a root (``sqrt(3)``) or a function of a number (``cos(1)``)."""
    return a.is_number and not a.is_Rational and (not isinstance(a, sympy.Pow) or not a.exp.is_Integer)


def is_real(x: sympy.Expr) -> bool:
    """True unless ``x`` is a number with an imaginary part (symbols count as real)."""
    if x.free_symbols:
        return True
    try:
        c = complex(x.evalf(30))
    except (TypeError, ValueError):
        return False
    return abs(c.imag) <= 1e-12 * max(1.0, abs(c.real))


def as_float(x: sympy.Expr) -> float | None:
    """The real part of the number ``x``; None when it has symbols or no value."""
    if x.free_symbols:
        return None
    try:
        return float(sympy.re(x.evalf(30)))
    except (TypeError, ValueError):
        return None


def point(symbols: set[sympy.Symbol]) -> dict[sympy.Symbol, sympy.Expr]:
    """A fixed, ordinary point for symbolic givens (positive, not special)."""
    rng = random.Random(1729)
    return {s: sympy.Rational(rng.randint(1300, 2900), 1000) for s in sorted(symbols, key=lambda s: s.name)}
