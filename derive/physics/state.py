"""What the stages of a chain share while it is solved: the quantities known so far.

How a chain is solved, stage by stage, is said in :mod:`derive.physics.chain`; the stage
types are in :mod:`derive.physics.stages`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy

from derive.errors import ExpressionError, InputError
from derive.physics.results import Result
from derive.problem import ChainProblem, Given, units
from derive.problem.expr import ParseError, number_with_unit, parse
from derive.symbols import symbol


@dataclass(frozen=True)
class StageOutcome:
    """A stage solved: its number, type and title, the names it defines for later
    stages, and ``data``, the stage type's own record (see :mod:`derive.physics.stages`).
    ``values`` are the numbers known when the stage starts (an unknown that this or a
    later stage solves for is not among them)."""

    number: int
    type: str
    title: str
    data: Any
    outputs: tuple[str, ...] = ()
    values: dict[sympy.Symbol, sympy.Expr] | None = None


@dataclass(frozen=True)
class ChainOutcome:
    """A chain solved: each stage's outcome and every named quantity's value."""

    chain: ChainProblem
    stages: tuple[StageOutcome, ...]
    results: dict[str, Result]
    values: dict[sympy.Symbol, sympy.Expr]
    angles: frozenset[sympy.Symbol]


class ChainState:
    """What the stages solved so far know: every named quantity as a Given (the chain's
    givens, then each stage's results), the unknowns and the roots found for them."""

    def __init__(self, chain: ChainProblem) -> None:
        self.chain = chain
        self.known: dict[str, Given] = {g.name: g for g in chain.givens}
        self.unknowns = [g.symbol for g in chain.givens if g.unknown]
        self.solved: dict[sympy.Symbol, sympy.Expr] = {}
        self.approaches: list[sympy.Expr] = []  # each impact's v_A1n - v_B1n, in the chain's names

    def err(
        self, i: int, key: str | None, what: str, value: Any = None, cls: type[InputError] = InputError
    ) -> InputError:
        """A one-line error at stage ``i``'s field ``key``."""
        return self.chain.stage_source(i).error(what, key=key, value=value, cls=cls)

    def quantity(self, i: int, st: dict, key: str, dim: units.Dim | None, default: Any = None) -> sympy.Expr:
        """A stage field: a name or an expression of known quantities, as an exact expression."""
        raw = st.get(key, default)
        if raw is None:
            raise self.err(i, key, "is missing")
        if isinstance(raw, (int, float)) and not isinstance(raw, bool):
            raw = repr(raw)
        if not isinstance(raw, str):
            raise self.err(i, key, "expected a name or an expression", raw)
        try:
            parsed = parse(raw, self.names(), self.chain.system)  # "200 N/m": in the working unit
        except ParseError as exc:
            raise self.err(i, key, _with_unit_hint(str(exc), raw, key), raw, ExpressionError) from None
        if dim is not None and parsed.dim != dim and not (parsed.expr == 0):
            raise self.err(i, key, f"expected {units.describe(dim)}, not {units.describe(parsed.dim)}", raw)
        return parsed.expr

    def names(self) -> dict[str, tuple[sympy.Symbol, units.Dim]]:
        """Name -> (symbol, dimension) of every known quantity, for the expression parser."""
        return {n: (g.symbol, g.dim) for n, g in self.known.items()}

    def value(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` in the givens' numbers (symbols without numbers, unknowns, stay)."""
        vals = {g.symbol: g.value for g in self.known.values() if g.value is not None}
        defs = {g.symbol: g.definition for g in self.known.values() if g.value is None and g.definition is not None}
        return resolve(expr, defs).xreplace(vals).xreplace(self.solved)

    def in_givens(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` with every earlier result replaced by its definition, down to the givens."""
        given = {g.name for g in self.chain.givens}
        defs = {g.symbol: g.definition for n, g in self.known.items() if g.definition is not None and n not in given}
        return resolve(expr, defs)

    def define(self, i: int, name: str, expr: sympy.Expr, dim: units.Dim, unit: str | None = None) -> Given:
        """A new named quantity for the stages after ``i``, defined by ``expr``."""
        if not isinstance(name, str) or not name.isidentifier() or name in self.known:
            raise self.err(i, "result", f"{name!r} is not a new name (letters, digits and _)", name)
        val = self.value(expr)
        value = None if val.free_symbols else val
        if value is not None and not finite_number(value):
            raise self.err(i, "result", f"{name} works out beyond what derive computes with (at most 1e300)", name)
        if value is not None and not real_number(value):
            raise self.err(
                i, "result", f"{name} works out to a complex number (a square root of a negative number?)", name
            )
        if unit is None:
            unit = units.working_unit(dim, self.chain.system).text if dim in units.SYSTEMS[self.chain.system] else ""
        used = [k for k in self.known.values() if k.symbol in sympy.sympify(expr).free_symbols]
        inexact = any(k.decimal or k.inexact for k in used)  # from decimal data: shown as decimals
        g = Given(name, symbol(name), dim, value, unit, definition=expr, inexact=inexact)
        self.known[name] = g
        return g

    def g_symbol(self) -> sympy.Symbol:
        """Standard gravity's symbol: the given g, else 9.81 m/s² (32.2 ft/s²) added once."""
        g = self.known.get("g")
        if g is None:
            number, unit_text = {"SI": ("9.81", "m/s^2"), "US": ("32.2", "ft/s^2")}[self.chain.system]
            g = Given("g", symbol("g", "positive"), units.ACCELERATION, sympy.Rational(number), unit_text)
            self.known["g"] = g
        return g.symbol

    def snapshot(self) -> dict[sympy.Symbol, sympy.Expr]:
        """Every quantity with a number now: the givens, earlier results, unknowns solved so far."""
        values = {g.symbol: g.value for g in self.known.values() if g.value is not None}
        values.update(self.solved)
        return values

    def positive(self, r: sympy.Expr) -> bool:
        """True when ``r`` is (or, with symbols, is known to be) a positive real number."""
        v = self.value(r)
        if v.free_symbols:
            return bool(v.is_positive)
        c = complex(sympy.N(v))
        return abs(c.imag) < 1e-12 and c.real > 0


def _with_unit_hint(what: str, raw: str, key: str) -> str:
    """A stage field written as a number with its unit ("200 N/m"): say that a stage's field
    takes names and expressions, and where the number with its unit goes."""
    try:
        found = number_with_unit(raw)
        if found is None:
            return what
        units.parse_unit(found[1])
    except (ParseError, ValueError):
        return what
    return (
        f'a stage\'s field takes names, not units: put {key}_s = "{raw.strip()}" in [given] and write {key} = "{key}_s"'
    )


def finite_number(value: sympy.Expr) -> bool:
    """True when ``value`` is a number of magnitude at most 1e300 (finite in every output)."""
    try:
        size = abs(complex(sympy.N(value, 15)))
    except (TypeError, ValueError, OverflowError):
        return True  # not a plain number (a complex or undefined one): reported where it is used
    return size <= 1e300


def real_number(value: sympy.Expr) -> bool:
    """False when ``value`` is a number with an imaginary part (sqrt(-1)): no output can show it."""
    try:
        c = complex(sympy.N(value, 15))
    except (TypeError, ValueError, OverflowError):
        return True  # not a plain number: reported where it is used
    return abs(c.imag) <= 1e-12 * max(1.0, abs(c.real))


def resolve(expr: sympy.Expr, defs: dict[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``expr`` with ``defs`` put in until none is left (definitions refer to earlier ones)."""
    for _ in range(len(defs) + 1):
        new = expr.xreplace(defs)
        if new == expr:
            break
        expr = new
    return expr
