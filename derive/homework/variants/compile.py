"""A problem with a ``[vary]`` table made ready for its variants: each drawn value written as
the file's ``[given]`` table would write it, and a quick test of whether a draw is physical.

A variant is the problem file with other numbers: its ``[given]`` table with the drawn
values written in (a choice as the file types it, "4 km/h"; a range's value in the unit its
``min`` is typed in), read and solved as ``derive solve`` reads and solves a file, and
written by the same writers (:mod:`derive.homework.variants.fill`). Nothing printed is ever
edited: a variant's page is the page of its own problem.

A single impact is also solved once with its varied givens kept as symbols: its closed
forms give the test of a draw (bodies that approach, 0 <= e <= 1, positive masses, the
file's conditions) as a plain function of the drawn numbers, and the common mistakes of the
LMS exports (:mod:`derive.homework.lms.mistake_model`). A chain is tested by solving it.
"""

from __future__ import annotations

import copy
import functools
import math
import re
from dataclasses import dataclass, field, replace
from decimal import Decimal, localcontext
from typing import Any

import sympy

from derive.errors import DeriveError, InputError
from derive.numbers import terminates
from derive.physics.impact import independent_map
from derive.problem import ChainProblem, Condition, Given, Problem, Source, parse_toml
from derive.problem.givens import QUANTITY
from derive.problem.units import ANGLE, DIMENSIONLESS, Dim, parse_unit
from derive.steps.model import Solution

#: Solved variants kept per process (a chain's draw is solved to be tested, then written).
CACHE = 256


@dataclass
class Compiled:
    """A problem with a ``[vary]`` table, ready to solve any variant.

    ``solution``: a single impact solved with its varied givens as symbols (its closed
    forms), a chain solved with its own numbers (what its results are named and described
    by); ``written``: each varied given's values as ``[given]`` writes them; ``conditions``:
    a chain's conditions with its results' names (a single impact's are in ``check``)."""

    problem: Problem | ChainProblem
    solution: Solution
    names: tuple[str, ...]
    givens: dict[str, Given]
    written: dict[str, dict[sympy.Expr, str | int | float]]
    check: Any = None
    #: Each varied range's ``[vary]`` entry: its values are written as they are drawn.
    ranges: dict[str, dict[str, Any]] = field(default_factory=dict)
    conditions: tuple[Condition, ...] = ()
    #: Why the last refused draw was refused (for the message when too few are physical).
    refusal: str = ""

    def values_written(self, values: dict[str, sympy.Expr]) -> tuple[tuple[str, str | int | float], ...]:
        """Each varied given as the variant's ``[given]`` table writes it (a value no ``[vary]``
        entry gives, as the file's ``[given]`` entry is written)."""
        out = []
        for n in self.names:
            typed = self.written.setdefault(n, {}).get(values[n])
            if typed is None:
                spec = self.ranges.get(n)
                if spec is None:
                    spec = {"min": _parsed(self.problem.path, self.problem.ctx.text).get("given", {}).get(n)}
                typed = self.written[n][values[n]] = in_range_unit(self.givens[n], values[n], spec, self.problem.path)
            out.append((n, typed))
        return tuple(out)

    def solved(self, values: dict[str, sympy.Expr]) -> Solution:
        """The variant solved: the file with these values in its ``[given]`` table, as ``derive
        solve`` solves it; a :class:`~derive.errors.DeriveError` when it is not physical."""
        p = self.problem
        return _solve(p.path, p.ctx.text, p.name, self.values_written(values))

    def accepts(self, values: dict[str, sympy.Expr]) -> bool:
        """True for a physical variant that meets the file's conditions."""
        if self.check is not None:
            return bool(self.check(*(float(values[n]) for n in self.names)))
        try:
            sol = self.solved(values)
        except DeriveError as exc:
            self.refusal = " ".join(str(exc).split()).removeprefix(f"{self.problem.path}: ")
            return False
        for c in self.conditions:
            if not holds(c, sol):
                self.refusal = f"{c.text} does not hold"
                return False
        return True


def compile_problem(problem: Problem | ChainProblem) -> Compiled:
    """``problem`` made ready for its variants (figures and format are the writers' business).
    Every value of ``[vary]`` is checked to be writable in the file."""
    from derive.steps import solve

    if not problem.vary:
        raise InputError("has no [vary] table: nothing to draw variants from", where=problem.path, field="[vary]")
    givens = {g.name: g for g in problem.givens}
    names = tuple(sorted(problem.vary))
    written, ranges = _written(problem, givens, names)
    if problem.kind == "chain":
        return _compile_chain(problem, givens, names, written, ranges)  # type: ignore[arg-type]
    symbolic = _symbolic(problem)
    solution = solve(symbolic)
    symbols = tuple(givens[n].symbol for n in names)
    fixed = dict(symbolic.numeric())
    ind = independent_map(symbolic)

    def prep(expr: sympy.Expr) -> sympy.Expr:
        return _exact_zero(sympy.sympify(expr).xreplace(ind).xreplace(fixed))

    # a result that needs no varied given is a number already: ``value`` (an angle in degrees;
    # its ``partial`` would be radians, atan2(x, 0) = pi/2)
    results = {name: r.found for name, r in solution.results.items()}
    check = _checks(symbolic, symbols, results, prep)
    return Compiled(problem, solution, names, givens, written, check, ranges=ranges)


def _compile_chain(
    problem: ChainProblem, givens: dict[str, Given], names: tuple[str, ...], written: dict, ranges: dict
) -> Compiled:
    """A chain solved once with its own numbers, its conditions read with its results' names."""
    from derive.problem import fields
    from derive.steps import solve

    solution = solve(problem)
    dims = {name: (r.symbol, _dim(r.unit)) for name, r in solution.results.items()}
    conditions = fields.conditions(list(problem.conditions), givens, problem.ctx, results=dims, system=problem.system)
    known = _numbers(solution)
    for c in conditions:
        left = (c.lhs - c.rhs).xreplace(known).free_symbols
        if left:
            shown = ", ".join(sorted(str(s) for s in left))
            raise InputError(f"{c.text} depends on {shown}, which no variant gives a number", field="conditions")
    return Compiled(problem, solution, names, givens, written, conditions=conditions, ranges=ranges)


@functools.lru_cache(maxsize=CACHE)
def _solve(path: str, text: str, name: str, written: tuple[tuple[str, str | int | float], ...]) -> Solution:
    """The problem file ``text`` with the ``written`` givens in its ``[given]`` table, read and
    solved (its ``[vary]`` table and conditions left out: they print nothing)."""
    from derive.problem.chain import build_chain
    from derive.problem.reader import build_problem
    from derive.steps import solve

    data = copy.deepcopy(_parsed(path, text))
    data.pop("vary", None)
    data.pop("conditions", None)
    data.setdefault("given", {}).update(dict(written))
    if data.get("kind") == "chain":
        return solve(build_chain(data, Source(path, text), name))
    problem = build_problem(data, Source(path, text), name)
    drawn = {n for n, _ in written}
    if drawn & {"m_A", "m_B", "W_A", "W_B"} and {"r_A", "r_B"} & (set(data["given"]) - drawn):
        problem = replace(problem, sizes_schematic=True)  # radii stated, masses drawn
    return solve(problem)


@functools.lru_cache(maxsize=8)
def _parsed(path: str, text: str) -> dict[str, Any]:
    return parse_toml(text, path)


# ---------------------------------------------------------------- the drawn values, as the file writes them


def _written(
    problem: Problem | ChainProblem, givens: dict[str, Given], names: tuple[str, ...]
) -> tuple[dict[str, dict[sympy.Expr, str | int | float]], dict[str, dict[str, Any]]]:
    """Each varied given's choices as its ``[given]`` entry is written in a variant (as
    ``[vary]`` types them: "4 km/h", unrounded, in its own unit), and each range's ``[vary]``
    entry, its ends and first step checked to be writable in the unit its ``min`` is typed in."""
    data = _parsed(problem.path, problem.ctx.text)
    raw_vary = data.get("vary", {})
    written: dict[str, dict[sympy.Expr, str | int | float]] = {}
    ranges: dict[str, dict[str, Any]] = {}
    for n in names:
        spec, values = raw_vary.get(n, {}), problem.vary[n]
        if "choices" in spec:
            written[n] = _choices(problem, givens[n], spec["choices"], values)
            continue
        ranges[n] = spec
        written[n] = {
            v: in_range_unit(givens[n], v, spec, problem.path) for v in dict.fromkeys((*values[:2], values[-1]))
        }
    return written, ranges


def in_range_unit(g: Given, value: sympy.Expr, spec: dict[str, Any], where: str | None = None) -> str | int | float:
    """A value of a ``[vary]`` range written in the unit its ``min`` is typed in, at the places
    its ``min`` and ``step`` are typed with (where both are in that unit)."""
    lo, step = spec.get("min"), spec.get("step")
    m_lo = QUANTITY.match(lo) if isinstance(lo, str) else None
    m_step = QUANTITY.match(step) if isinstance(step, str) else None
    same = (m_lo is not None and m_step is not None and m_lo.group(2) == m_step.group(2)) or (
        isinstance(lo, (int, float)) and isinstance(step, (int, float))
    )
    places = max(_places(lo), _places(step)) if same else None
    return written_value(g, value, lo, where, places=places)


def _places(raw: object) -> int:
    """Places after the point a number is typed with ("0.001 kg": 3; 2.5: 1; "1e-3 kg": 0)."""
    text = raw if isinstance(raw, str) else repr(raw) if isinstance(raw, (int, float)) else ""
    m = QUANTITY.match(text)
    number = m.group(1) if m is not None else ""
    return 0 if "e" in number.lower() else len(number.partition(".")[2])


def _choices(
    problem: Problem | ChainProblem, g: Given, choices: list, values: tuple[sympy.Expr, ...]
) -> dict[sympy.Expr, str | int | float]:
    """Each value of a ``choices`` list with the choice that gave it, as typed (the first, where
    two choices are the same value)."""
    from derive.problem import fields

    system = problem.system
    oblique = getattr(problem, "oblique", False)
    out: dict[sympy.Expr, str | int | float] = {}
    for choice in choices:
        one = fields.vary({g.name: {"choices": [choice]}}, {g.name: g}, problem.ctx, oblique, system)
        out.setdefault(one[g.name][0], _with_places(choice, g))
    missing = [v for v in values if v not in out]
    if missing:  # not expected: the same reading gives the same values
        raise InputError(f"a value of [vary] {g.name} could not be matched to its choice", where=problem.path)
    return out


def _with_places(choice: str | int | float, g: Given) -> str | int | float:
    """A choice as typed ("4 km/h", "-1 m/s"), its number with at least the places the file's
    ``[given]`` typed (-1.20 m/s given: "-1.00 m/s")."""
    m = QUANTITY.match(choice) if isinstance(choice, str) else None
    places = len(g.typed.partition(".")[2]) if g.typed is not None else 0
    if m is None or places == 0:
        return choice
    number = m.group(1)
    if "e" in number.lower():
        return choice
    have = len(number.partition(".")[2])
    if have < places:
        number += ("" if "." in number else ".") + "0" * (places - have)
    return f"{number} {m.group(2)}".strip()


def written_value(
    g: Given, value: sympy.Expr, raw: object, where: str | None = None, places: int | None = None
) -> str | int | float:
    """``value`` (in the working unit, an angle in radians) written as ``raw`` is written: a
    number where ``raw`` is a number, else a number in the unit ``raw`` types ("10 kg"), with
    at least the places the file's ``[given]`` typed. With ``places``, a number within a
    millionth of the last place of one at those places is that number (a range of decimals
    read as floats: 0.001 + 448 x 0.001 is 0.449)."""
    m = QUANTITY.match(raw) if isinstance(raw, str) else None
    unit = m.group(2) if m is not None else ("deg" if g.unit == "deg" else g.unit)
    if isinstance(raw, (int, float)) and not isinstance(raw, bool):
        unit = ""
    base = sympy.Integer(1) if g.unit == "deg" else parse_unit(g.unit).factor
    try:
        factor = parse_unit(unit).factor if unit else sympy.Integer(1)
    except ValueError:  # not expected: the file's own unit was read when it was loaded
        factor = base
    number = value * base / factor
    text = _decimal(sympy.nsimplify(number)) if places is None else _at_places(number, places)
    if text is None:
        raise InputError(
            f"{sympy.N(number, 8)} {unit} is no decimal number in {unit}, the unit [vary] types "
            f"{g.name} in: a variant's [given] could not hold it (give [vary] in another unit)",
            where=where,
            field=f"[vary] {g.name}",
        )
    places = len(g.typed.partition(".")[2]) if g.typed is not None else 0
    have = len(text.partition(".")[2])
    if have < places:
        text += ("" if "." in text else ".") + "0" * (places - have)
    if not unit:
        return float(text) if "." in text else int(text)
    return f"{text} {unit}"


def _at_places(number: sympy.Expr, places: int) -> str | None:
    """``number`` as a decimal at ``places`` places where it is one (to a millionth of the last place)."""
    with localcontext() as ctx:
        ctx.prec = 60
        exact = Decimal(str(sympy.N(number, 40)))
        near = exact.quantize(Decimal(1).scaleb(-places))
        if abs(exact - near) > Decimal(1).scaleb(-places - 6):
            return None
    return _decimal(sympy.Rational(str(near)))


def _decimal(q: sympy.Expr) -> str | None:
    """A rational number as a terminating decimal ("0.25", "-3", "12.5"), else None."""
    if not isinstance(q, sympy.Rational) or not terminates(q):
        return None
    with localcontext() as ctx:
        ctx.prec = 100
        d = Decimal(int(q.p)) / Decimal(int(q.q))
    text = format(d.normalize(), "f")
    return re.sub(r"^-0$", "0", text)


# ---------------------------------------------------------------- is a draw physical?


def _symbolic(problem: Problem) -> Problem:
    """The problem with its varied givens (and givens defined from them) made symbolic."""
    varied = set(problem.vary)
    givens = []
    changed: set[sympy.Symbol] = set()
    for g in problem.givens:
        if g.name in varied or (g.definition is not None and g.definition.free_symbols & changed):
            g = replace(g, value=None)
            changed.add(g.symbol)
        givens.append(g)
    return replace(problem, givens=tuple(givens))


def _exact_zero(expr: sympy.Expr) -> sympy.Expr:
    """0 for a polynomial in the varied givens that is 0 (T_lost = T_1 - T_2 at e = 1, with
    m_B found), which floating point would give as 4.34 × 10⁻¹⁹; any other expression as it is."""
    if isinstance(expr, sympy.Expr) and expr.free_symbols and expr.is_polynomial() and sympy.expand(expr) == 0:
        return sympy.Integer(0)
    return expr


def _checks(problem: Problem, symbols: tuple[sympy.Symbol, ...], results: dict[str, sympy.Expr], prep) -> Any:
    """One function of the varied values that is True for a physical variant: the
    bodies approach, e in [0, 1], masses positive, and the file's conditions hold.

    An unknown of an inverse problem (``e = "?"``, ``m_B = "? kg"``) is checked as the
    variant solves it, so a draw that makes it unphysical (e > 1, a negative mass) is
    refused. A built-in check on a given kept as a letter (``m = "kg"``: positive by
    its assumptions) is left out: it has no number to check."""
    allowed = set(symbols)

    def solved(expr: sympy.Expr) -> sympy.Expr:
        # by name: an unknown's symbol (e, with its assumptions) is not the condition's e
        expr = sympy.sympify(expr)
        to_results = {s: results[s.name] for s in expr.free_symbols if s.name in results and s not in allowed}
        return prep(expr.xreplace(to_results))

    sym = problem.symbols()
    built_in = [(solved(problem.motion_A.n - problem.motion_B.n), ">")]
    for name in ("m_A", "m_B"):
        if name in sym:
            built_in.append((solved(sym[name]), ">"))
    e = solved(sym["e"])
    built_in += [(e, ">="), (1 - e, ">=")]
    lower = [(x, op) for x, op in built_in if x.free_symbols <= allowed]
    for c in problem.conditions:
        diff = solved(c.lhs - c.rhs)
        if not diff.free_symbols <= allowed:
            names = ", ".join(sorted(str(s) for s in diff.free_symbols - allowed))
            raise InputError(f"{c.text} depends on {names}, which no variant gives a number", field="conditions")
        lower.append((diff if c.op in (">", ">=") else -diff, ">" if c.op in ("<", ">") else ">="))
    if not lower:
        return lambda *args: True
    fn = sympy.lambdify(symbols, [x for x, _ in lower], modules=["math"], cse=True)
    ops = [op for _, op in lower]

    def ok(*args: float) -> bool:
        try:
            vals = fn(*args)
        except (ZeroDivisionError, ValueError, OverflowError):
            return False
        for v, op in zip(vals, ops, strict=True):
            v = complex(v)
            if abs(v.imag) > 1e-12 or not math.isfinite(v.real):
                return False
            if (op == ">" and not v.real > 1e-12) or (op == ">=" and not v.real >= -1e-12):
                return False
        return True

    return ok


def _dim(unit: str) -> Dim:
    if unit == "deg":
        return ANGLE
    if not unit:
        return DIMENSIONLESS
    try:
        return parse_unit(unit).dim
    except ValueError:
        return DIMENSIONLESS


def _numbers(sol: Solution) -> dict[sympy.Symbol, sympy.Expr]:
    """Every given's and result's number of a solved chain, by symbol."""
    out = {g.symbol: g.value for g in sol.problem.givens if g.value is not None}
    out.update({r.symbol: r.value for r in sol.results.values() if r.value is not None})
    return out


def holds(c: Condition, sol: Solution) -> bool:
    """True when the condition holds for the solved chain (to 1e-12)."""
    diff = (c.lhs - c.rhs).xreplace(_numbers(sol))
    if diff.free_symbols:
        return False
    z = complex(sympy.N(diff, 20))
    if abs(z.imag) > 1e-12 or not math.isfinite(z.real):
        return False
    x = z.real if c.op in (">", ">=") else -z.real
    return x > 1e-12 if c.op in (">", "<") else x >= -1e-12
