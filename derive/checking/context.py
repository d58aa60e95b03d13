"""What every check needs to know about one solved problem: its names, numbers, data and mistakes.

A :class:`Context` is built once per :func:`~derive.checking.check.check` and
handed to each judge (numbers, formulas, equations, derivation lines); it reads
the :class:`~derive.Solution` and the mistakes' model, and re-derives nothing.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import TYPE_CHECKING

import sympy

from derive.checking.entries import Entry
from derive.checking.numeric import plain, with_unit
from derive.checking.report import Diagnosis
from derive.checking.sampler import Sampler
from derive.checking.statementangles import statement_angles
from derive.numbers import format_number
from derive.physics.energy import impulse_n, kinetic_energy
from derive.physics.results import Result
from derive.problem import Problem, units
from derive.problem.units import ANGLE, DIMENSIONLESS, VELOCITY, Dim
from derive.steps.model import Solution
from derive.symbols import symbol

if TYPE_CHECKING:  # the mistakes' model is imported when a check first needs it (a wrong answer)
    from derive.checking import mistakes

#: ``deg`` and ``rad`` in formulas: units of angle (``5*sin(37.6*deg)``).
DEG = sympy.Symbol("deg", positive=True)
RAD = sympy.Symbol("rad", positive=True)
NUMBER = re.compile(r"^\s*([-+]?(?:\d{1,40}\.?\d{0,40}|\.\d{1,40})(?:[eE][-+]?\d{1,2})?)\s*(.*?)\s*$")

Names = dict[str, tuple[sympy.Symbol, Dim]]


class Context:
    """One solved problem, as the checks see it."""

    def __init__(self, solution: Solution, tolerance: sympy.Rational | None) -> None:
        self.solution = solution
        self.problem = solution.problem
        self.tolerance = tolerance
        self.results = solution.results
        self.chain = solution.is_chain  # a chain: its values as worked out; no mistake model (a single impact's)
        self.numeric = dict(solution.values) if self.chain else self.problem.numeric()
        self._model: mistakes.Model | None = None
        self.data = _data(self.problem)
        self._derived: dict[str, tuple[sympy.Symbol, sympy.Expr]] | None = None
        self.memo: dict[tuple, object] = {}  # what the judges work out once per check (rounded values)
        self.fixed: dict[sympy.Symbol, sympy.Rational] = {}  # givens a derivation puts a number for ("m = 1")
        self._in_unknowns: dict[sympy.Expr, sympy.Expr] = {}

    @property
    def model(self) -> mistakes.Model:
        """The problem's equations as the mistakes see them (cached per solution)."""
        if self._model is None:
            from derive.checking.mistakes import model

            self._model = model(self.solution)
        return self._model

    @property
    def ind(self) -> dict[sympy.Symbol, sympy.Expr]:
        """Givens defined from symbolic givens -> their definition (m_A -> m)."""
        return self.model.ind

    def sampler(self) -> Sampler:
        """Random admissible values of the givens."""
        return Sampler(self.problem, self.ind, self.fixed)

    def definitions(self) -> dict[sympy.Symbol, sympy.Expr]:
        """Every given defined from others -> its definition in the base givens."""
        defs = {g.symbol: g.definition for g in self.problem.givens if g.definition is not None and not g.unknown}
        for _ in range(10):
            new = {k: v.xreplace(defs) for k, v in defs.items()}
            if new == defs:
                break
            defs = new
        return defs

    def num(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` with the numeric givens in."""
        return expr.xreplace(self.ind).xreplace(self.numeric)

    def result(self, e: Entry) -> Result:
        """The result an answer names; bad input when there is none of that name."""
        r = self.results.get(e.name)
        if r is not None:
            return r
        names = ", ".join(self.results)
        hint = ""
        if not getattr(self.problem, "oblique", True) and re.fullmatch(r"v_[AB]2[nt]", e.name):
            hint = f" (a direct impact has one component: {e.name[:-1]})"
        raise e.error(f"unknown result{hint}; expected one of: {names}")

    # showing ---------------------------------------------------------------
    def work(self, r: Result) -> units.Unit:
        """The unit ``r`` is worked in."""
        return units.parse_unit(r.unit)

    def shown(self, x: sympy.Expr, figures: int, unit: units.Unit) -> str:
        """A value as the report shows it: a figure more than written (4 to 10)."""
        return with_unit(format_number(x, max(4, min(10, figures + 1))), unit.text)

    def expected_text(self, r: Result) -> str:
        """The expected value (or formula, where it depends on symbols) as shown."""
        work = self.work(r)
        if r.value is not None:
            return self.shown(r.value, 3, work)
        return with_unit(plain(r.partial), work.text if work.dim != ANGLE else "")

    def target(self, r: Result) -> sympy.Expr:
        """The expected value with the numbers in (radians for angles)."""
        x = r.value if r.value is not None else r.partial
        return x * sympy.pi / 180 if r.unit == "deg" else x

    # mistakes --------------------------------------------------------------
    def diagnosis(self, m: mistakes.Mistake, value: str | None = None) -> tuple[Diagnosis, ...]:
        """The report's record of mistake ``m`` in this problem: one, or one for each of
        two mistakes made together (``e_on_t+system_t``), each with the value they give."""
        from derive.checking.mistakes import REGISTRY

        numbers = self.model.numbers
        parts = [REGISTRY.get(n) for n in m.name.split("+")] if "+" in m.name else [m]
        return tuple(
            Diagnosis(
                k.name, k.title, k.description, k.where_in(numbers), tuple(i for i in k.enters if i in numbers), value
            )
            for k in parts
            if k is not None
        )

    def singles(self) -> list[mistakes.Outcome]:
        """Every common mistake that applies here, solved (none are modelled for a chain)."""
        from derive.checking.mistakes import outcomes

        return [] if self.chain else outcomes(self.solution)

    def forms(self) -> list[mistakes.Outcome]:
        """The mistakes' equations that no outcome has (unsolvable, or on one side only)."""
        from derive.checking.mistakes import forms

        return [] if self.chain else forms(self.solution)

    def pairs(self) -> list[mistakes.Outcome]:
        """Every pair of common mistakes that applies here, solved (bounded; slower)."""
        from derive.checking.mistakes import pair_outcomes

        return [] if self.chain else pair_outcomes(self.solution)

    def diagnose(
        self, fits: Callable[[mistakes.Outcome], str | None], found: list[mistakes.Outcome]
    ) -> tuple[Diagnosis, ...]:
        """The mistakes of ``found`` whose outcome ``fits``: it returns the value the
        mistake gives as shown ("" to show none), or None where the outcome does not fit.
        A pair of mistakes gives a record for each (a mistake named twice is named once)."""
        out: dict[str, Diagnosis] = {}
        for o in found:
            shown = fits(o) if o.mistake is not None else None
            if shown is not None and o.mistake is not None:
                for d in self.diagnosis(o.mistake, shown or None):
                    out.setdefault(d.mistake, d)
        return tuple(out.values())

    # names in formulas and equations ----------------------------------------
    def answer_names(self, dimensionless: bool = False) -> Names:
        """The names a formula may use: the givens, the components before the impact, deg, rad."""
        names: Names = {}
        for g in self.problem.givens:
            names[g.name] = (g.symbol, DIMENSIONLESS if dimensionless else g.dim)
        for c in self.model.pre:
            if c.name not in names:
                names[c.name] = (c, DIMENSIONLESS if dimensionless else VELOCITY)
        for s, dim in ((DEG, ANGLE), (RAD, ANGLE)):
            names.setdefault(s.name, (s, DIMENSIONLESS if dimensionless else dim))
        return names

    def unit_subs(self) -> dict[sympy.Symbol, sympy.Expr]:
        """``deg`` and ``rad`` as numbers of radians."""
        return {DEG: sympy.pi / 180, RAD: sympy.Integer(1)}

    def equation_names(self) -> Names:
        """The names an equation may use: a formula's, the components after the impact,
        and the results that stand for expressions in them (speeds, angles, energies)."""
        names = self.answer_names(dimensionless=True)
        nm = self.model.nm
        for c in (nm.A1n, nm.B1n, nm.A2n, nm.B2n, nm.A1t, nm.B1t, nm.A2t, nm.B2t):
            if c is not None:
                names.setdefault(c.name, (c, DIMENSIONLESS))
        for name, (sym, _expr) in self.derived().items():
            names.setdefault(name, (sym, DIMENSIONLESS))
        return names

    def derived(self) -> dict[str, tuple[sympy.Symbol, sympy.Expr]]:
        """Result names that stand for expressions in the components (speeds, angles, energies);
        built once (the reader asks for them at each line: 20000 lines took half a minute)."""
        if self._derived is None:
            self._derived = self._derive()
        return dict(self._derived)

    def _derive(self) -> dict[str, tuple[sympy.Symbol, sympy.Expr]]:
        model, p = self.model, self.problem
        nm = model.nm
        out: dict[str, tuple[sympy.Symbol, sympy.Expr]] = {}
        if p.oblique:
            for b in "AB":
                n, t = getattr(nm, f"{b}2n"), getattr(nm, f"{b}2t")
                out[f"v_{b}2"] = (symbol(f"v_{b}2", "positive"), sympy.sqrt(n**2 + t**2))
                out[f"theta_{b}2"] = (symbol(f"theta_{b}2"), sympy.atan2(n, t))
                out[f"beta_{b}2"] = (symbol(f"beta_{b}2"), sympy.atan2(t, n))
                out[f"alpha_{b}2"] = (symbol(f"alpha_{b}2"), sympy.atan2(abs(t), abs(n)))  # with n, acute
                out[f"gamma_{b}2"] = (symbol(f"gamma_{b}2"), sympy.atan2(abs(n), abs(t)))  # with t, acute
                n1, t1 = getattr(nm, f"{b}1n"), getattr(nm, f"{b}1t")
                if n1 is not None and t1 is not None:  # the angle its velocity turns through
                    out[f"delta_{b}"] = (symbol(f"delta_{b}"), sympy.atan2(abs(n1 * t - t1 * n), n1 * n + t1 * t))
        tA1, tB1, tA2, tB2 = (nm.A1t, nm.B1t, nm.A2t, nm.B2t) if p.oblique else (0, 0, 0, 0)
        T1 = kinetic_energy(model.m_A, nm.A1n, tA1) + kinetic_energy(model.m_B, nm.B1n, tB1)
        T2 = kinetic_energy(model.m_A, nm.A2n, tA2) + kinetic_energy(model.m_B, nm.B2n, tB2)
        out["T_1"] = (symbol("T_1"), T1)
        out["T_2"] = (symbol("T_2"), T2)
        out["T_lost"] = (symbol("T_lost"), T1 - T2)
        out["J_n"] = (symbol("J_n"), impulse_n(model.m_A, nm.A1n, nm.A2n))
        for d in p.asks.defined:  # the file's own quantities (beta = -theta_A2: the statement's β)
            by_name = {s: out[s.name][1] for s in d.expr.free_symbols if s.name in out}
            out.setdefault(d.name, (d.symbol, d.expr.xreplace(by_name)))
        for letter, name in statement_angles(p).items():  # "just after, it makes an angle β with it"
            if name in out:
                out.setdefault(letter, (symbol(letter), out[name][1]))
        return out

    def in_unknowns(self, expr: sympy.Expr) -> sympy.Expr:
        """A user's ``lhs - rhs`` in the unknowns, with everything known put in (kept for the check,
        by value: a reading puts each candidate of each name in every mapping it tries)."""
        key = expr if isinstance(expr, sympy.Basic) else None  # a Basic is immutable and hashable
        hit = self._in_unknowns.get(key) if key is not None else None
        if hit is not None:
            return hit
        model = self.model
        derived = {sym: ex for sym, ex in self.derived().values()}
        x = expr.xreplace(derived).xreplace(self.unit_subs())
        x = self.num(x.xreplace(model.zeros).xreplace(model.pre))
        if key is not None and len(self._in_unknowns) < 4096:
            self._in_unknowns[key] = x
        return x


def _data(p: Problem) -> set[sympy.Rational]:
    """The numbers of the problem's data as given (e = 0.6, 37.6 for θ = 37.6°)."""
    data: set[sympy.Rational] = set()
    for g in p.givens:
        if g.value is not None and g.value.is_Rational:
            data.update((g.value, abs(g.value)))  # -0.120 m/s is written 0.120 "the other way"
        if g.value is not None and g.dim == ANGLE:
            deg = g.value * 180 / sympy.pi
            if deg.is_Rational:
                data.add(deg)
        if g.written:
            m = NUMBER.match(g.written)
            if m:
                data.add(sympy.Rational(m.group(1)))
    return data
