"""What the writer of one impact reads: the solved impact, with the questions every step asks.

A :class:`Page` is read-only: each step function takes it and returns its blocks (and
what later steps need), so no step depends on another having run first.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy

from derive.numbers import short_decimal
from derive.physics.impact import evaluate
from derive.physics.outcome import ImpactOutcome, xy_motions
from derive.physics.results import working_unit
from derive.steps.model import Math, Text
from derive.steps.notation import notes_form
from derive.symbols import symbol


class Tags:
    """Equation numbers on the page. One impact's page numbers its equations as the notes
    do, (1)-(6) (``offset`` 0). Inside a chain (``running`` set) the page numbers its own
    equations 1, 2, 3, ... in the order they are first written, with no gap, so that a
    number is never the notes' number of another equation (a wall's stage writes no (3))."""

    def __init__(self, offset: int = 0, running: Counter | None = None) -> None:
        self.offset = offset
        self.running = running
        self._given: dict[int, str] = {}

    def __call__(self, k: int) -> str:
        """The page's number of the notes' equation ``k`` (given it if this is its first use)."""
        if self.running is None:
            return str(self.offset + k)
        if k not in self._given:
            self._given[k] = self.running.next()
        return self._given[k]

    def peek(self, k: int) -> str | None:
        """The page's number of the notes' equation ``k`` if it has one, without giving one."""
        if self.running is None:
            return str(self.offset + k)
        return self._given.get(k)

    @property
    def own(self) -> bool:
        """Whether the page numbers its own equations (a chain): the notes' equations are then named in words."""
        return self.running is not None


class Counter:
    """The running equation numbers of a chain's page: each stage takes the next ones."""

    def __init__(self) -> None:
        self.last = 0

    def next(self) -> str:
        """The next number."""
        self.last += 1
        return str(self.last)


@dataclass(frozen=True)
class Page:
    """An impact outcome and the questions the steps ask of it."""

    outcome: ImpactOutcome
    tags: Tags = field(default_factory=Tags)
    marks: bool = True

    @property
    def imp(self):
        return self.outcome.impact

    @property
    def p(self):
        return self.outcome.problem

    @property
    def nm(self):
        return self.outcome.impact.names

    @property
    def results(self) -> dict:
        return self.outcome.results

    @property
    def ind(self) -> dict[sympy.Symbol, sympy.Expr]:
        return self.outcome.impact.independent

    @property
    def numeric(self) -> dict[sympy.Symbol, sympy.Expr]:
        return self.p.numeric()

    def notes(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` as the notes write it (:func:`derive.steps.notation.notes_form`): its
        signs decided by the givens' numbers and by the angles assumed acute."""
        acute = [g.symbol for g in self.p.givens if self.p.assume.get(g.name) == "acute"]
        return notes_form(expr, self.numeric, acute)

    @property
    def m_A(self) -> sympy.Symbol:
        return self.p.symbols()["m_A"]

    @property
    def m_B(self) -> sympy.Symbol:
        return self.p.symbols().get("m_B", symbol("m_B", "positive"))

    @property
    def e(self) -> sympy.Symbol:
        return self.p.symbols()["e"]

    @property
    def unit_v(self) -> str:
        return working_unit(self.p, "velocity")

    @property
    def unknowns(self) -> tuple[sympy.Symbol, ...]:
        return self.imp.unknowns

    def label(self, body: str) -> str:
        """The letter the page calls ``body`` ("A" or "B") by."""
        return self.p.labels["AB".index(body)]

    @property
    def a(self) -> str:
        """The letter the page calls body A by (``B`` in a stage where sphere B strikes a wall)."""
        return self.p.labels[0]

    @property
    def b(self) -> str:
        """The letter the page calls body B by."""
        return self.p.labels[1]

    @property
    def surface(self) -> str:
        return self.p.name_B or "surface"

    @property
    def varied(self) -> set[sympy.Symbol]:
        """Givens of homework variants: symbols here only to be filled in later, so they count as numbers."""
        return {g.symbol for g in self.p.givens if g.name in self.p.vary}

    @property
    def letters(self) -> set[sympy.Symbol]:
        """The givens kept as letters (u, m, e): not those of homework variants, which are numbers."""
        return {g.symbol for g in self.p.givens if g.value is None and not g.unknown} - self.varied

    def _xy_components(self) -> set[sympy.Symbol]:
        return {c for _, comps in xy_motions(self.imp) for c in comps}

    def givens(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` in the givens' symbols (pre-impact components resolved, except those
        resolved from x-y axes, which the geometry stage has turned into numbers)."""
        keep = self._xy_components()
        pre = {k: v for k, v in self.imp.pre.items() if k not in keep}
        return expr.xreplace(pre).xreplace(self.ind)

    def has_values(self, expr: sympy.Expr) -> bool:
        """True when a substitution line has numbers to put into ``expr``."""
        known = set(self.numeric) | set(self.outcome.values) | self._xy_components() | self.varied
        return bool(expr.free_symbols & known)

    def num(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` with the pre-impact components and every numeric given put in; where a
        letter stays, those the file wrote as decimals go in as decimals (0.9 u, not 9u/10)."""
        resolved = expr.xreplace(self.imp.pre)
        exact = evaluate(resolved, self.p)
        if (exact.free_symbols | resolved.free_symbols) & self.letters:  # e, or e_floor it stands for
            return evaluate(resolved, self.p, decimals=True)
        return exact

    def value_of(self, s: sympy.Symbol) -> sympy.Expr:
        """A solved quantity: its number, or its closed form with numbers in."""
        r = self.results.get(s.name)
        if r is not None:
            if r.value is not None:
                return r.value
            if (
                r.unit != "deg"
                and any(g.decimal for g in self.p.givens)
                and (r.partial.free_symbols | r.closed.free_symbols) & self.letters
            ):
                shown = evaluate(r.closed, self.p, decimals=True)  # 0.475 v_A1 √2, not 19 v_A1 √2/40
                trig = shown.has(sympy.sin, sympy.cos, sympy.tan)  # simplify can take minutes on these
                return sympy.simplify(shown) if sympy.count_ops(shown) < 40 and not trig else shown
            return r.partial
        return self.num(self.imp.closed[s])

    def unit_of(self, s: sympy.Symbol) -> str | None:
        """The unit a quantity is shown in: a given's own, else a velocity's."""
        g = next((g for g in self.p.givens if g.symbol == s), None)
        if g is not None:
            return g.unit or None
        return self.unit_v


def show(expr: sympy.Expr) -> sympy.Expr:
    """Mark a display structure of numbers (a fraction, a root) to be printed as built."""
    return sympy.UnevaluatedExpr(expr)


def over(num: sympy.Expr, den: sympy.Expr) -> sympy.Expr:
    """``num/den`` as written: a fraction SymPy does not evaluate or reorder."""
    return sympy.Mul(num, sympy.Pow(den, -1, evaluate=False), evaluate=False)


def as_float(x: sympy.Expr) -> sympy.Expr:
    """A pure number as a Float (kept apart in printed sums); other expressions as they are."""

    if x.is_number and not x.is_Integer and not short_decimal(x):
        return sympy.Float(x.evalf(30), 30)
    return x


def nonzero(terms: tuple[sympy.Expr, ...]) -> tuple[sympy.Expr, ...]:
    """The terms that are not zero (a single 0 when none is left)."""
    kept = tuple(t for t in terms if t != 0)
    return kept or (sympy.Integer(0),)


def interval_text(interval: sympy.Set, x: sympy.Symbol) -> Text:
    """``1/2 < e ≤ 1`` as words and inline mathematics."""
    if interval is sympy.S.EmptySet:
        return ("no value of ", Math(x), " at all")
    if not isinstance(interval, sympy.Interval):
        return (Math(interval),)
    lo, hi = interval.start, interval.end
    parts: list[sympy.Expr] = []
    if lo != -sympy.oo:
        parts.append((sympy.StrictLessThan if interval.left_open else sympy.LessThan)(lo, x, evaluate=False))
    if hi != sympy.oo:
        parts.append((sympy.StrictLessThan if interval.right_open else sympy.LessThan)(x, hi, evaluate=False))
    # a bound x's own assumptions already give (0 <= e for an e known not negative) would
    # print as True wherever the relation is rebuilt: left out
    parts = [r for r in parts if r.func(*r.args) is not sympy.true] or parts[:1]
    if not parts or parts[0].func(*parts[0].args) is sympy.true:
        return ("every value of ", Math(x))
    return tuple(p for i, r in enumerate(parts) for p in (((" and ",) if i else ()) + (Math(r),)))
