"""Check a hand derivation: which answers are right, and what went wrong.

A student or an instructor gives their answers (``v_B2n = 8.40 m/s``, or a
formula such as ``sqrt(2)/4*(1+e)*v_A1``) and, optionally, their own equations
((3), (4), with or without numbers). :func:`check` judges each one against the
problem's :class:`~derive.Solution`:

- a number at the precision it is written with (8.4 is right when the value
  rounds to 8.4, with ±1 in the last digit for rounded intermediates), or within
  an explicit relative tolerance; units are converted, a missing one is flagged;
- a formula by equivalence with the closed form: simplification first, then
  evaluation at random admissible points where simplification cannot decide;
- an equation by comparison with equations (1)-(4), up to a factor.

Where an answer or an equation is wrong, the common mistakes of
:mod:`derive.mistakes` are tried, and the one that reproduces it is named with
the equation where it enters. The :class:`Report` renders as text, Markdown or
JSON. User text goes only through :func:`derive.expr.parse` and
:func:`derive.units.parse_unit`; nothing is evaluated as Python.
"""

from __future__ import annotations

import math
import random
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from decimal import ROUND_HALF_UP, Decimal, InvalidOperation, localcontext
from pathlib import Path
from typing import Any

import sympy

from derive import escape
from derive.checking import mistakes
from derive.errors import InputError
from derive.fileio import dumps_json
from derive.numbers import format_number, to_decimal
from derive.physics.results import Result
from derive.problem import Problem, units
from derive.problem.expr import ParseError, parse
from derive.problem.units import ACCELERATION, ANGLE, DIMENSIONLESS, FORCE, LENGTH, MASS, VELOCITY, Dim
from derive.steps.model import Solution

FORMATS = ("text", "md", "json")
#: Random points at which two formulas are compared when simplification cannot decide.
POINTS = 8
#: Relative difference below which two exact values count as equal (30-digit evaluation).
EXACT = 1e-15

_NUMBER = re.compile(r"^\s*([-+]?(?:\d{1,40}\.?\d{0,40}|\.\d{1,40})(?:[eE][-+]?\d{1,2})?)\s*(.*?)\s*$")
_LITERAL = re.compile(r"[A-Za-z_][A-Za-z0-9_]*|((?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)")
_LABEL = re.compile(r"^\s*(?:\(\s*([A-Za-z0-9]{1,8})\s*\)\s*:?|([A-Za-z0-9]{1,8})\s*:)\s*")
_DEG = sympy.Symbol("deg", positive=True)
_RAD = sympy.Symbol("rad", positive=True)
#: Other units a value may have been worked out in, by dimension (for the "right value, wrong unit" hint).
_ALTERNATIVES: dict[Dim, tuple[str, ...]] = {
    VELOCITY: ("m/s", "ft/s", "km/h", "mi/h"),
    units.ENERGY: ("J", "ft*lb", "kJ"),
    MASS: ("kg", "slug", "g"),
    units.IMPULSE: ("N*s", "lb*s"),
    ANGLE: ("deg", "rad"),
}
_MARK = {"correct": "✓", "wrong": "✗", "unit mismatch": "✗"}


# ---------------------------------------------------------------- the report


@dataclass(frozen=True)
class Diagnosis:
    """A common mistake that reproduces a wrong answer or equation."""

    mistake: str
    title: str
    description: str
    where: str
    equations: tuple[int, ...] = ()
    value: str | None = None

    def as_dict(self) -> dict[str, Any]:
        return {
            "mistake": self.mistake,
            "title": self.title,
            "description": self.description,
            "where": self.where,
            "equations": list(self.equations),
            "value": self.value,
        }


@dataclass(frozen=True)
class Item:
    """The verdict on one answer or one equation.

    ``status`` is "correct", "wrong" or "unit mismatch"; ``expected`` the value
    (or equation) expected, as shown; ``relative_error`` (written − expected) /
    |expected|; ``method`` how the verdict was reached; ``message`` says it in a
    sentence; ``diagnosis`` the mistakes that reproduce a wrong one.
    """

    kind: str
    name: str
    written: str
    status: str
    expected: str
    message: str
    method: str = ""
    relative_error: float | None = None
    value: float | None = None
    expected_value: float | None = None
    unit: str = ""
    unit_missing: bool = False
    notes: tuple[str, ...] = ()
    diagnosis: tuple[Diagnosis, ...] = ()

    @property
    def correct(self) -> bool:
        """True when the answer or equation is right."""
        return self.status == "correct"

    def as_dict(self) -> dict[str, Any]:
        return {
            "kind": self.kind,
            "name": self.name,
            "written": self.written,
            "status": self.status,
            "correct": self.correct,
            "value": self.value,
            "unit": self.unit,
            "unit_missing": self.unit_missing,
            "expected": self.expected,
            "expected_value": self.expected_value,
            "relative_error": self.relative_error,
            "method": self.method,
            "message": self.message,
            "notes": list(self.notes),
            "diagnosis": [d.as_dict() for d in self.diagnosis],
        }


@dataclass(frozen=True)
class Report:
    """The verdicts on a set of answers and equations for one problem."""

    problem: str
    title: str
    items: tuple[Item, ...]
    tolerance: float | None = None

    @property
    def all_correct(self) -> bool:
        """True when every answer and equation is right."""
        return all(i.correct for i in self.items)

    @property
    def exit_code(self) -> int:
        """0 when everything is right, 1 when anything is wrong (the CLI's exit code)."""
        return 0 if self.all_correct else 1

    def counts(self) -> dict[str, int]:
        """How many items have each status."""
        return {s: sum(1 for i in self.items if i.status == s) for s in ("correct", "wrong", "unit mismatch")}

    def as_dict(self) -> dict[str, Any]:
        return {
            "problem": self.problem,
            "title": self.title,
            "all_correct": self.all_correct,
            "counts": self.counts(),
            "tolerance": self.tolerance,
            "items": [i.as_dict() for i in self.items],
        }

    def render(self, fmt: str = "text") -> str:
        """The report as "text" (a terminal), "md" (Markdown) or "json"."""
        if fmt == "text":
            return self.text()
        if fmt == "md":
            return self.markdown()
        if fmt == "json":
            return self.json()
        raise InputError(f"unknown format {fmt!r} (expected one of: {', '.join(FORMATS)})", field="format")

    def json(self) -> str:
        return dumps_json(self.as_dict())

    def _summary(self) -> str:
        c = self.counts()
        total = len(self.items)
        parts = [f"{c['correct']} of {total} correct"]
        if c["wrong"]:
            parts.append(f"{c['wrong']} wrong")
        if c["unit mismatch"]:
            parts.append(f"{c['unit mismatch']} with a unit mismatch")
        return ", ".join(parts) + "."

    def text(self) -> str:
        rows = []
        for i in self.items:
            shown = i.name if i.kind == "answer" else (f"({i.name})" if i.name else "eq.")
            expected = f"expected {i.expected}" if i.expected else ""
            err = _percent(i.relative_error) if i.relative_error is not None else ""
            rows.append((_MARK[i.status], shown, i.written, expected, err, i.status))
        widths = [max(len(r[c]) for r in rows) for c in range(6)]
        widths[2] = min(widths[2], 36)
        lines = [f"derive check: {self.title} ({self.problem})", ""]
        for i, row in zip(self.items, rows, strict=True):
            cells = [row[c].ljust(widths[c]) for c in range(5)]
            lines.append(("  " + "  ".join(cells) + "  " + row[5]).rstrip())
            for detail in _details(i):
                lines.append("        " + detail)
        lines += ["", self._summary()]
        return "\n".join(lines) + "\n"

    def markdown(self) -> str:
        md = escape.markdown
        out = [f"## Check: {md(self.title)}", ""]
        out.append("| | | Written | Expected | Error | Verdict |")
        out.append("|---|---|---|---|---|---|")
        for i in self.items:
            shown = i.name if i.kind == "answer" else (f"({i.name})" if i.name else "equation")
            err = _percent(i.relative_error) if i.relative_error is not None else ""
            out.append(
                f"| {_MARK[i.status]} | {md(shown)} | {md(i.written)} | {md(i.expected)} | {md(err)} | {i.status} |"
            )
        out += ["", f"**{self._summary()}**", ""]
        for i in self.items:
            shown = i.name if i.kind == "answer" else (f"({i.name})" if i.name else "equation")
            out.append(f"- **{md(shown)}** ({i.status}): " + md(" ".join(_details(i))))
        return "\n".join(out) + "\n"


def _details(i: Item) -> list[str]:
    lines = [i.message]
    lines += list(i.notes)
    for d in i.diagnosis:
        value = f" (it gives {d.value})" if d.value else ""
        lines.append(f"Mistake: {d.title}{value}. {d.description} It enters in {d.where}.")
    return lines


def _percent(x: float) -> str:
    p = x * 100
    if p == 0:
        return "0 %"
    if abs(p) >= 1:
        return f"{p:+.1f} %"
    if abs(p) < 0.001:
        return "< 0.001 %"
    return f"{p:+.2g} %"


# ---------------------------------------------------------------- input


@dataclass(frozen=True)
class Entry:
    """One answer (``name = text``) or equation (``label = text``), with where it came from."""

    name: str
    raw: Any
    where: str | None = None
    field: str | None = None

    def error(self, what: str) -> InputError:
        return InputError(what, where=self.where, field=self.field)


@dataclass(frozen=True)
class Answers:
    """Answers and equations to check, as read from a file or the command line."""

    answers: tuple[Entry, ...] = ()
    equations: tuple[Entry, ...] = ()
    tolerance: Any = None

    def merged(self, other: Answers) -> Answers:
        """These answers with ``other``'s added (``other`` wins for the same name)."""
        names = {e.name for e in other.answers}
        answers = tuple(e for e in self.answers if e.name not in names) + other.answers
        tol = other.tolerance if other.tolerance is not None else self.tolerance
        return Answers(answers, self.equations + other.equations, tol)


def parse_tolerance(value: Any, option: str = "--tolerance") -> sympy.Rational | None:
    """A relative tolerance: 0.01, "0.01" or "1%"; None stays None."""
    if value is None:
        return None
    if isinstance(value, sympy.Rational):
        value = str(sympy.Float(value, 15))
    text = str(value).strip() if not isinstance(value, bool) else ""
    pct = text.endswith("%")
    body = text[:-1].strip() if pct else text
    try:
        if isinstance(value, bool) or not re.fullmatch(r"(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d{1,2})?", body):
            raise ValueError
        tol = sympy.Rational(body) / (100 if pct else 1)
    except (ValueError, TypeError):
        raise InputError('expected a relative tolerance such as 0.01 or "1%"', field=f"{option} {value!r}") from None
    if not 0 < tol < 1:
        raise InputError("expected a relative tolerance between 0 and 1 (0 % and 100 %)", field=f"{option} {value!r}")
    return tol


def answer_option(text: str) -> Entry:
    """``NAME=VALUE`` from ``--answer``."""
    name, sep, value = text.partition("=")
    if not sep or not name.strip():
        raise InputError("expected NAME=VALUE, such as v_B2n=8.40 m/s", field=f"--answer {text!r}")
    return Entry(name.strip(), value.strip(), field=f"--answer {name.strip()}")


def equation_option(text: str) -> Entry:
    """``[LABEL:] LHS = RHS`` from ``--equation`` (the label as "3:" or "(3)")."""
    m = _LABEL.match(text)
    label = (m.group(1) or m.group(2)) if m else ""
    body = text[m.end() :] if m else text
    return Entry(label, body, field=f"--equation {text!r}")


def load_answers(path: str | Path) -> Answers:
    """Read an answers file (TOML: ``[answers]``, optional ``[equations]`` and ``tolerance``)."""
    from derive.fileio import read_user_text

    shown = str(path)
    text = read_user_text(path, "an answers file")
    return loads_answers(text, path=shown)


def loads_answers(text: str, *, path: str = "<answers>") -> Answers:
    """Read answers given as TOML text (``path`` only names it in messages); the file is
    checked against the answers table of :mod:`derive.problem.schema` first."""
    from derive.problem import Source, parse_toml, validate
    from derive.problem.schema import ANSWERS
    from derive.problem.source import printable

    data = parse_toml(text, path)
    lines = Source(path, text)
    validate.check(data, ANSWERS, lines)
    out_a, out_e = [], []
    for section, out in (("answers", out_a), ("equations", out_e)):
        for key, value in data.get(section, {}).items():
            where = lines.where(lines.line_of(section, key))
            out.append(Entry(str(key), value, where=where, field=f"[{section}] {printable(key)}"))
    if not out_a and not out_e:
        raise InputError("has nothing to check: give an [answers] table (or [equations])", where=path)
    return Answers(tuple(out_a), tuple(out_e), data.get("tolerance"))


def _as_answers(answers: Any, equations: Any) -> Answers:
    if isinstance(answers, Answers):
        base = answers
    elif answers is None:
        base = Answers()
    elif isinstance(answers, Mapping):
        if "answers" in answers or "equations" in answers:
            return _as_answers(answers.get("answers"), answers.get("equations"))
        base = Answers(tuple(Entry(str(k), v, field=f"answers[{k}]") for k, v in answers.items()))
    elif isinstance(answers, Iterable) and not isinstance(answers, (str, bytes)):
        base = Answers(tuple(answer_option(str(a)) for a in answers))
    else:
        raise InputError("expected answers as a mapping {name: value} or a list of 'NAME=VALUE'", field="answers")
    if equations is None:
        return base
    if isinstance(equations, Mapping):
        eqs = tuple(Entry(str(k), v, field=f"equations[{k}]") for k, v in equations.items())
    elif isinstance(equations, Iterable) and not isinstance(equations, (str, bytes)):
        eqs = tuple(equation_option(str(x)) for x in equations)
    else:
        raise InputError("expected equations as a mapping {label: equation} or a list", field="equations")
    return Answers(base.answers, base.equations + eqs, base.tolerance)


# ---------------------------------------------------------------- checking


def check(
    solution: Solution | Problem,
    answers: Any = None,
    *,
    equations: Any = None,
    tolerance: Any = None,
) -> Report:
    """Check hand answers (and equations) against ``solution``.

    ``answers`` maps result names to values (``{"v_B2n": "8.40 m/s", "v_A2n": -1.11}``),
    or is a list of ``"NAME=VALUE"`` strings, or what :func:`load_answers` read;
    ``equations`` maps labels ("3", "4") to equations (``"20*v_A2n + 5*v_B2n = 19.8"``);
    ``tolerance`` is relative (0.01 or "1%"): without it numbers are judged at the
    precision they are written with. Raises :class:`~derive.errors.InputError` on
    bad input. ``report.exit_code`` is 0 when everything is right, else 1.

    >>> import derive  # doctest: +SKIP
    >>> derive.check(derive.solve(derive.load("notes-4c11-two-spheres")), {"v_B2n": "8.40 m/s"}).all_correct  # doctest: +SKIP
    True
    """
    if isinstance(solution, Problem):
        from derive.steps import solve

        solution = solve(solution)
    given = _as_answers(answers, equations)
    tol = parse_tolerance(tolerance if tolerance is not None else given.tolerance, "tolerance")
    if not given.answers and not given.equations:
        raise InputError("nothing to check: give answers (--answer NAME=VALUE or --answers FILE)", field="answers")
    checker = _Checker(solution, tol)
    items = [checker.answer(e) for e in given.answers] + [checker.equation(e) for e in given.equations]
    p = solution.problem
    return Report(p.name or p.path, p.title, tuple(items), float(tol) if tol is not None else None)


def _figures(d: Decimal) -> int:
    digits = d.as_tuple().digits
    return len(digits) if d != 0 else 0


def _round_figures(d: Decimal, figures: int) -> Decimal:
    """``d`` rounded half up to ``figures`` significant figures (9.996 to 3 is 10.0)."""
    r = d.quantize(Decimal(1).scaleb(d.adjusted() - figures + 1), rounding=ROUND_HALF_UP)
    if r.adjusted() != d.adjusted():
        r = r.quantize(Decimal(1).scaleb(r.adjusted() - figures + 1), rounding=ROUND_HALF_UP)
    return r


def _literal_tolerance(text: str, data: set[sympy.Rational]) -> float:
    """Relative slack for the decimals written in ``text``: ±1 in the last digit of each,
    except numbers with one significant figure and numbers that are the problem's data
    as given (0.6 for e = 0.6); at most 5 %."""
    tol = 0.0
    for m in _LITERAL.finditer(text):
        tok = m.group(1)
        if not tok or not re.search(r"[.eE]", tok):
            continue
        if len(tok) > 30 or abs(Decimal(tok).adjusted()) > 30:
            continue  # the parser has refused such numbers already
        d = Decimal(tok)
        if d == 0 or _figures(d) < 2 or sympy.Rational(tok) in data:
            continue  # one figure (0.5, 0.6) is data, not a rounded intermediate
        tol += float(Decimal(1).scaleb(d.as_tuple().exponent) / abs(d))
    return min(tol, 0.05)


class _Sampler:
    """Random admissible values of the givens: masses positive, 0 < e < 1, speeds positive,
    angles between 6° and 83°, and bodies that approach along n."""

    def __init__(self, problem: Problem, ind: Mapping[sympy.Symbol, sympy.Expr]) -> None:
        self.by_symbol = {g.symbol: g for g in problem.givens}
        self.approach = (problem.motion_A.n - problem.motion_B.n).xreplace(dict(ind))
        self.numeric = problem.numeric()

    def _range(self, s: sympy.Symbol) -> tuple[float, float]:
        g = self.by_symbol.get(s)
        dim = g.dim if g is not None else None
        if s.name == "e":
            return (0.05, 0.95)
        if dim == MASS:
            return (0.5, 5.0)
        if dim == VELOCITY:
            return (0.5, 10.0) if s.is_nonnegative else (-10.0, 10.0)
        if dim == ANGLE:
            return (0.1, 1.45)
        if dim == FORCE:
            return (5.0, 50.0)
        if dim == ACCELERATION:
            return (9.0, 33.0)
        if dim == LENGTH:
            return (0.5, 3.0)
        return (0.5, 3.0)

    def points(self, symbols: Iterable[sympy.Symbol], n: int = POINTS, seed: int = 7) -> list[dict]:
        rng = random.Random(seed)
        syms = sorted(set(symbols), key=lambda s: s.name)
        out: list[dict] = []
        tries = 0
        while len(out) < n and tries < 50 * n:
            tries += 1
            pt = {}
            for s in syms:
                lo, hi = self._range(s)
                pt[s] = sympy.Rational(rng.randint(int(lo * 1000), int(hi * 1000)), 1000)
            a = self.approach.xreplace(pt).xreplace(self.numeric)
            if not a.free_symbols:
                try:
                    if float(a.evalf(20)) <= 0:
                        continue
                except (TypeError, ValueError):
                    continue
            out.append(pt)
        return out


def _number_of(x: sympy.Expr) -> complex | None:
    try:
        c = complex(x.evalf(30))
    except (TypeError, ValueError, ZeroDivisionError):
        return None
    if not (math.isfinite(c.real) and math.isfinite(c.imag)):
        return None
    return c


def _close(a: complex, b: complex, tol: float) -> bool:
    return abs(a - b) <= max(tol, EXACT) * max(abs(a), abs(b)) + 1e-25


class _Checker:
    def __init__(self, solution: Solution, tolerance: sympy.Rational | None) -> None:
        self.solution = solution
        self.problem = solution.problem
        self.tolerance = tolerance
        self.results = solution.results
        p = self.problem
        self.numeric = p.numeric()
        self._model: mistakes.Model | None = None
        data: set[sympy.Rational] = set()
        for g in p.givens:
            if g.value is not None and g.value.is_Rational:
                data.add(g.value)
            if g.value is not None and g.dim == ANGLE:
                deg = g.value * 180 / sympy.pi
                if deg.is_Rational:
                    data.add(deg)
            if g.written:
                m = _NUMBER.match(g.written)
                if m:
                    data.add(sympy.Rational(m.group(1)))
        self.data = data

    # shared ---------------------------------------------------------------
    @property
    def model(self) -> mistakes.Model:
        if self._model is None:
            self._model = mistakes.model(self.solution)
        return self._model

    @property
    def ind(self) -> dict[sympy.Symbol, sympy.Expr]:
        return self.model.ind

    def sampler(self) -> _Sampler:
        return _Sampler(self.problem, self.ind)

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
        return expr.xreplace(self.ind).xreplace(self.numeric)

    def _unknown_name(self, e: Entry) -> InputError:
        names = ", ".join(self.results)
        hint = ""
        if not self.problem.oblique and re.fullmatch(r"v_[AB]2[nt]", e.name):
            hint = f" (a direct impact has one component: {e.name[:-1]})"
        return e.error(f"unknown result{hint}; expected one of: {names}")

    # answers --------------------------------------------------------------
    def answer(self, e: Entry) -> Item:
        r = self.results.get(e.name)
        if r is None:
            raise self._unknown_name(e)
        raw = e.raw
        if isinstance(raw, bool) or not isinstance(raw, (str, int, float)):
            raise e.error('expected a number or text such as "8.40 m/s"')
        if isinstance(raw, float):
            if not math.isfinite(raw):
                raise e.error("expected a finite number")
            text = repr(raw)
        else:
            text = str(raw)
        text = text.replace("−", "-").strip()
        if not text:
            raise e.error('is empty: expected a number with a unit ("8.40 m/s") or an expression')
        if len(text) > 500:
            raise e.error("is too long (at most 500 characters)")
        m = _NUMBER.match(text)
        unit_problem = None
        if m:
            number, unit_text = m.groups()
            if not unit_text:
                return self._number(e, r, text, number, None)
            try:
                unit = units.parse_unit(unit_text)
            except ValueError as exc:
                unit_problem = str(exc) if re.fullmatch(r"[A-Za-z°][A-Za-z°/*^·\d\s]*", unit_text) else None
            else:
                return self._number(e, r, text, number, unit)
        return self._expression(e, r, text, unit_problem)

    def _work(self, r: Result) -> units.Unit:
        return units.parse_unit(r.unit)

    def _shown(self, x: sympy.Expr, figures: int, unit: units.Unit) -> str:
        return _with_unit(format_number(x, max(4, min(10, figures + 1))), unit.text)

    def _judge(self, u: Decimal, x: sympy.Expr) -> bool:
        xd = to_decimal(x)
        with localcontext() as ctx:
            ctx.prec = 60
            if self.tolerance is not None:
                tol = to_decimal(self.tolerance)
                return abs(u - xd) <= tol * abs(xd) if xd != 0 else abs(u) <= tol
            if u == 0 or xd == 0:  # a zero is judged at the last place written
                q = Decimal(1).scaleb(u.as_tuple().exponent)
                return u == 0 if xd == 0 else abs(xd) * 2 < q
            try:
                r = _round_figures(xd, _figures(u))
            except InvalidOperation:
                return False
            # ±1 in the last digit the user wrote (not of the rounded value: "1" is not 10.65)
            return abs(u - r) <= Decimal(1).scaleb(u.as_tuple().exponent)

    def _method(self, u: Decimal) -> str:
        if self.tolerance is not None:
            return f"within the relative tolerance of {_pct_plain(self.tolerance)}"
        figs = _figures(u)
        if figs == 0:
            return "as written (zero, to the last place written)"
        return f"at the {figs} significant figure{'s' if figs > 1 else ''} written (±1 in the last digit)"

    def _number(self, e: Entry, r: Result, text: str, number: str, unit: units.Unit | None) -> Item:
        work = self._work(r)
        if r.value is None:
            syms = ", ".join(sorted(s.name for s in self.num(r.closed).free_symbols)) or "a symbolic given"
            raise e.error(f"{r.name} depends on the symbolic given(s) {syms}: answer with an expression in them")
        u = Decimal(number)
        notes: list[str] = []
        missing = False
        unit_written = unit is not None
        if unit is None:
            unit = work
            missing = work.dim not in (DIMENSIONLESS, ANGLE)
            if missing:
                notes.append(f"No unit given: read as {units.plain_unit(work.text)}.")
        figures = _figures(u)
        if unit.dim != work.dim:
            expected = self._shown(r.value, figures, work)
            what = units.describe(work.dim) if work.dim != DIMENSIONLESS else "a pure number"
            return Item(
                "answer",
                r.name,
                text,
                "unit mismatch",
                expected,
                f"Unit mismatch: {unit.text} is {units.describe(unit.dim)}, but {r.name} is {what}"
                + (f" ({units.plain_unit(work.text)})." if work.text else "."),
                value=float(u),
                unit=unit.text,
                expected_value=float(r.value),
            )
        x = r.value * work.factor / unit.factor
        ok = self._judge(u, x)
        rel = float((u - to_decimal(x)) / abs(to_decimal(x))) if x != 0 else None
        method = self._method(u)
        expected = self._shown(x, figures, unit)
        base = dict(
            value=float(u),
            unit=unit.text,
            unit_missing=missing,
            expected_value=float(x),
            relative_error=rel,
            method=method,
        )
        if ok:
            return Item("answer", r.name, text, "correct", expected, f"Correct {method}.", notes=tuple(notes), **base)
        diags = []
        for out in mistakes.outcomes(self.solution):
            q = out.results.get(r.name)
            if q is None or q.value is None or out.mistake is None:
                continue
            mx = q.value * work.factor / unit.factor
            if self._judge(u, mx):
                diags.append(self._diagnosis(out.mistake, self._shown(mx, figures, unit)))
        hints = []
        if x != 0 and self._judge(u, -x):
            hints.append("It has the right size but the wrong sign: check the positive senses of n and t.")
        for alt in _ALTERNATIVES.get(work.dim, ()):
            alt_unit = units.parse_unit(alt)
            if alt_unit.text == unit.text or alt_unit.factor == unit.factor:
                continue
            if self._judge(u, r.value * work.factor / alt_unit.factor):
                fix = "the unit is wrong" if unit_written else "give its unit"
                hints.append(f"{number} is the right value in {units.plain_unit(alt_unit.text)}: {fix}.")
        if diags:
            msg = f"Wrong: {number} is what {'this mistake' if len(diags) == 1 else 'these mistakes'} give{'s' if len(diags) == 1 else ''}."
        else:
            msg = f"Wrong. No common mistake reproduces {number}."
        return Item(
            "answer",
            r.name,
            text,
            "wrong",
            expected,
            " ".join([msg, *hints]),
            notes=tuple(notes),
            diagnosis=tuple(diags),
            **base,
        )

    def _diagnosis(self, m: mistakes.Mistake, value: str | None = None) -> Diagnosis:
        return Diagnosis(
            m.name,
            m.title,
            m.description,
            m.where_in(self.model),
            tuple(k for k in m.enters if k in self.model.numbers),
            value,
        )

    # formulas --------------------------------------------------------------
    def _answer_names(self, dimensionless: bool = False) -> dict[str, tuple[sympy.Symbol, Dim]]:
        names: dict[str, tuple[sympy.Symbol, Dim]] = {}
        for g in self.problem.givens:
            names[g.name] = (g.symbol, DIMENSIONLESS if dimensionless else g.dim)
        for c in self.model.pre:
            if c.name not in names:
                names[c.name] = (c, DIMENSIONLESS if dimensionless else VELOCITY)
        for s, dim in ((_DEG, ANGLE), (_RAD, ANGLE)):
            names.setdefault(s.name, (s, DIMENSIONLESS if dimensionless else dim))
        return names

    def _unit_subs(self) -> dict[sympy.Symbol, sympy.Expr]:
        return {_DEG: sympy.pi / 180, _RAD: sympy.Integer(1)}

    def _expression(self, e: Entry, r: Result, text: str, unit_problem: str | None) -> Item:
        work = self._work(r)
        names = self._answer_names()
        unit: units.Unit | None = None
        try:
            parsed = parse(text, names)
        except ParseError as exc:
            split = _split_unit(text)
            parsed = None
            if split is not None:
                try:
                    parsed = parse(split[0], names)
                    unit = split[1]
                except ParseError:
                    parsed = None
            if parsed is None:
                if unit_problem:
                    raise e.error(unit_problem) from None
                try:
                    parse(text, self._answer_names(dimensionless=True))
                except ParseError:
                    raise e.error(str(exc)) from None
                return Item(
                    "answer",
                    r.name,
                    text,
                    "unit mismatch",
                    self._expected_text(r),
                    f"Unit mismatch: {exc}.",
                )
        expr = parsed.expr.xreplace({**self.model.pre, **self._unit_subs()})
        dim = parsed.dim
        given_syms = {g.symbol for g in self.problem.givens}
        has_symbols = bool(expr.free_symbols & given_syms)
        notes: list[str] = []
        missing = False
        if unit is not None:
            if dim != DIMENSIONLESS:
                raise e.error("a unit after an expression in the givens is not needed: the givens carry their units")
            if unit.dim != work.dim:
                return Item(
                    "answer",
                    r.name,
                    text,
                    "unit mismatch",
                    self._expected_text(r),
                    f"Unit mismatch: {unit.text} is {units.describe(unit.dim)}, but {r.name} is "
                    f"{units.describe(work.dim)}.",
                )
            expr = expr * unit.factor / (work.factor if work.dim != ANGLE else 1)
            dim = work.dim
        elif dim == DIMENSIONLESS and work.dim == ANGLE:
            expr, dim = expr * sympy.pi / 180, ANGLE  # a pure number for an angle is in degrees
        elif dim == DIMENSIONLESS and work.dim != DIMENSIONLESS and not has_symbols:
            missing = True
            notes.append(f"No unit given: read as {units.plain_unit(work.text)}.")
            dim = work.dim
        if dim != work.dim:
            return Item(
                "answer",
                r.name,
                text,
                "unit mismatch",
                self._expected_text(r),
                f"Unit mismatch: the expression is {units.describe(dim)}, but {r.name} is {units.describe(work.dim)}"
                + (f" ({units.plain_unit(work.text)})." if work.text else "."),
            )
        tol = _literal_tolerance(text, self.data)
        angle = work.dim == ANGLE
        target_num = self._target(r)
        user_num = self.num(expr)
        scope = ""
        if has_symbols:
            defs = self.definitions()
            full_user = expr.xreplace(self.ind).xreplace(defs)
            full_target = r.closed.xreplace(self.ind).xreplace(defs)
            same, how = self._equivalent(full_user, full_target, tol)
            if same:
                scope = "equivalent to the closed form as a formula in the givens"
            else:
                same, how = self._equivalent(user_num, target_num, tol)
                scope = "equivalent with this problem's numbers (not as a formula in all the givens)"
        else:
            same, how = self._equivalent(user_num, target_num, tol)
            scope = "equal to the exact value"
        rel = None
        a, b = _number_of(user_num), _number_of(target_num)
        if a is not None and b is not None and b != 0:
            rel = float(((a - b) / abs(b)).real)
        shown_expected = self._expected_text(r)
        value = float(a.real) * (180 / math.pi if angle else 1) if a is not None else None
        base = dict(
            relative_error=rel,
            value=value,
            unit=work.text,
            unit_missing=missing,
            expected_value=float(r.value) if r.value is not None else None,
        )
        if same:
            return Item(
                "answer",
                r.name,
                text,
                "correct",
                shown_expected,
                f"Correct: {scope}, by {how}.",
                method=how,
                notes=tuple(notes),
                **base,
            )
        diags = []
        for out in mistakes.outcomes(self.solution):
            q = out.results.get(r.name)
            if q is None or q.partial is None or out.mistake is None:
                continue
            if self._equivalent(user_num, q.partial, tol, quick=True)[0]:
                shown = self._shown(q.value, 3, work) if q.value is not None else _plain(_tidy(q.partial))
                diags.append(self._diagnosis(out.mistake, shown))
        hints = []
        if self._equivalent(user_num, -target_num, tol, quick=True)[0]:
            hints.append("It has the right size but the wrong sign: check the positive senses of n and t.")
        msg = f"Wrong: not equivalent to the expected value, by {how}."
        if not diags:
            msg += " No common mistake reproduces it."
        return Item(
            "answer",
            r.name,
            text,
            "wrong",
            shown_expected,
            " ".join([msg, *hints]),
            method=how,
            notes=tuple(notes),
            diagnosis=tuple(diags),
            **base,
        )

    def _target(self, r: Result) -> sympy.Expr:
        """The expected value with the numbers in (radians for angles)."""
        x = r.value if r.value is not None else r.partial
        return x * sympy.pi / 180 if r.unit == "deg" else x

    def _expected_text(self, r: Result) -> str:
        work = self._work(r)
        if r.value is not None:
            return self._shown(r.value, 3, work)
        return _with_unit(_plain(r.partial), work.text if work.dim != ANGLE else "")

    def _equivalent(self, a: sympy.Expr, b: sympy.Expr, tol: float, quick: bool = False) -> tuple[bool, str]:
        """Whether ``a`` and ``b`` are the same: by simplification, else at random admissible points."""
        exact = tol == 0
        d = a - b
        if exact and not quick:
            s = _simplify(d)
            if s == 0:
                return True, "simplification"
            if s is not None and s.is_number and _number_of(s) not in (None, 0):
                return False, "simplification"
        elif exact and d == 0:
            return True, "simplification"
        syms = (a.free_symbols | b.free_symbols) - {_DEG, _RAD}
        if not syms:
            x, y = _number_of(a), _number_of(b)
            if x is None or y is None:
                return False, "evaluation"
            how = (
                "evaluation to 30 digits"
                if exact
                else f"evaluation, to the precision of the decimals written (±{tol:.2g})"
            )
            return _close(x, y, tol), how
        points = self.sampler().points(syms, 3 if quick else POINTS)
        checked = 0
        for pt in points:
            x, y = _number_of(a.xreplace(pt)), _number_of(b.xreplace(pt))
            if x is None or y is None:
                continue
            checked += 1
            if not _close(x, y, tol):
                where = ", ".join(f"{s.name} = {float(v):g}" for s, v in pt.items())
                return False, f"evaluation at a random admissible point, {where}"
        if checked == 0:
            return False, "evaluation (no admissible point could be evaluated)"
        how = f"evaluation at {checked} random admissible points"
        if not exact:
            how += f", to the precision of the decimals written (±{tol:.2g})"
        return True, how

    # equations -------------------------------------------------------------
    def equation(self, e: Entry) -> Item:
        raw = e.raw
        if not isinstance(raw, str):
            raise e.error('expected an equation as text, such as "v_B2n - v_A2n = 9.5"')
        text = raw.replace("−", "-").strip()
        if len(text) > 500:
            raise e.error("is too long (at most 500 characters)")
        if text.count("=") != 1 or re.search(r"[<>!]=|==", text):
            raise e.error("an equation needs exactly one '=' between its two sides")
        lhs_text, rhs_text = text.split("=")
        names = self._equation_names()
        try:
            lhs = parse(lhs_text, names).expr
            rhs = parse(rhs_text, names).expr
        except ParseError as exc:
            raise e.error(str(exc)) from None
        model = self.model
        label = e.name.strip().strip("()").strip()
        k = int(label) if label in ("1", "2", "3", "4") else None
        notes = []
        if k is not None and k not in model.numbers:
            if self.problem.fixed_B:
                surface = self.problem.name_B or "surface"
                why = f"against a fixed {surface} only (1) and (4) apply (its supports exert an impulse)"
                if not self.problem.oblique:
                    why = f"against a fixed {surface} in a direct impact only (4) applies"
            else:
                why = "a direct impact has no t equations (1), (2)"
            notes.append(f"There is no equation ({k}) here: {why}. It was checked against each of them.")
            k = None
        F = self._in_unknowns(lhs - rhs)
        tol = max(_literal_tolerance(text, self.data), 1e-9)
        base = mistakes.correct(self.solution)
        outs = [o for o in mistakes.outcomes(self.solution) if o.mistake is not None]
        U = model.unknowns
        extra = set(F.free_symbols) - set(U)
        pts = self.sampler().points(extra, 3) if extra else [{}]
        shown_label = label or ""
        who = f"Your ({shown_label})" if shown_label else "This equation"
        expected = self._format_equation(base.equations[k], k) if (k is not None and base is not None) else ""

        def item(status: str, message: str, diags: tuple[Diagnosis, ...] = (), method: str = "") -> Item:
            return Item(
                "equation",
                shown_label,
                text,
                status,
                expected,
                message,
                method=method,
                notes=tuple(notes),
                diagnosis=diags,
            )

        order = [k] if k is not None else list(model.numbers)
        others = [j for j in model.numbers if j not in order]
        if base is None:
            raise e.error("this problem's equations cannot be set up for checking")

        # 1) the equation itself, up to a factor
        def named(j: int) -> str:
            title = mistakes.EQUATION_TITLES[j]
            return title if j == k else f"({j}), {title}"

        for j in order:
            if _proportional(F, base.equations[j], U, pts, tol):
                return item("correct", f"{who} is {named(j)}: correct.", method="comparison")
        for j in order:
            found = []
            for o in outs:
                if (
                    j in o.equations
                    and not _proportional(o.equations[j], base.equations[j], U, pts, 1e-9)
                    and _proportional(F, o.equations[j], U, pts, tol)
                ):
                    found.append(self._diagnosis(o.mistake))
            if found:
                phrase = " / ".join(_phrase(d) for d in found)
                msg = f"{who} {phrase}." if j == k else f"{who} is {named(j)}, but it {phrase}."
                return item("wrong", msg, tuple(found), "comparison")
        for j in others:
            if _proportional(F, base.equations[j], U, pts, tol):
                notes.append(f"It is labelled ({k}) but it is ({j}).")
                return item("correct", f"{who} is {named(j)}: correct.", method="comparison")
        # 2) with the other equations, does it give the right velocities (or a mistake's)?
        for j in order:
            roots = _solve_with(F, base, j, U, pts)
            if roots is None:
                continue
            rest = _and([f"({i})" for i in model.numbers if i != j])
            with_rest = f"with {rest}" if rest else "on its own"
            if _matches(roots, base, U, pts, tol):
                msg = (
                    f"{who} is not written as {named(j)}, but {with_rest} it gives the correct velocities: correct."
                    if j == k
                    else f"{who} gives the correct velocities {with_rest}: correct."
                )
                return item(
                    "correct",
                    msg,
                    method="solving with the other equations",
                )
            found = [self._diagnosis(o.mistake) for o in outs if _matches(roots, o, U, pts, tol)]
            if found:
                phrase = " / ".join(_phrase(d) for d in found)
                return item(
                    "wrong",
                    f"{who} {phrase}: {with_rest} it gives the velocities of that mistake.",
                    tuple(found),
                    "solving with the other equations",
                )
        # 3) at least consistent with the solution?
        if _satisfied(F, base, U, pts, tol):
            tail = f", though it is not ({k}), {mistakes.EQUATION_TITLES[k]}" if k is not None else ""
            return item(
                "correct",
                f"{who} is consistent with the physics: the correct velocities satisfy it{tail}.",
                method="substituting the correct velocities",
            )
        if k is not None:
            msg = f"{who} does not agree with ({k}), {mistakes.EQUATION_TITLES[k]}. No common mistake reproduces it."
        else:
            listed = " or ".join(f"({j})" for j in model.numbers)
            msg = (
                f"{who} is not {listed}, and the correct velocities do not satisfy it. No common mistake reproduces it."
            )
        return item("wrong", msg, method="comparison")

    def _equation_names(self) -> dict[str, tuple[sympy.Symbol, Dim]]:
        names = self._answer_names(dimensionless=True)
        nm = self.model.nm
        for c in (nm.A1n, nm.B1n, nm.A2n, nm.B2n, nm.A1t, nm.B1t, nm.A2t, nm.B2t):
            if c is not None:
                names.setdefault(c.name, (c, DIMENSIONLESS))
        for name, (sym, _expr) in self._derived().items():
            names.setdefault(name, (sym, DIMENSIONLESS))
        return names

    def _derived(self) -> dict[str, tuple[sympy.Symbol, sympy.Expr]]:
        """Result names that stand for expressions in the components (speeds, angles, energies)."""
        from derive.symbols import symbol

        model, p = self.model, self.problem
        nm = model.nm
        out: dict[str, tuple[sympy.Symbol, sympy.Expr]] = {}
        if p.oblique:
            for b in "AB":
                n, t = getattr(nm, f"{b}2n"), getattr(nm, f"{b}2t")
                out[f"v_{b}2"] = (symbol(f"v_{b}2", "positive"), sympy.sqrt(n**2 + t**2))
                out[f"theta_{b}2"] = (symbol(f"theta_{b}2"), sympy.atan2(n, t))
                out[f"beta_{b}2"] = (symbol(f"beta_{b}2"), sympy.atan2(t, n))
        half = sympy.Rational(1, 2)
        tA1, tB1, tA2, tB2 = (nm.A1t, nm.B1t, nm.A2t, nm.B2t) if p.oblique else (0, 0, 0, 0)
        T1 = half * model.m_A * (nm.A1n**2 + tA1**2) + half * model.m_B * (nm.B1n**2 + tB1**2)
        T2 = half * model.m_A * (nm.A2n**2 + tA2**2) + half * model.m_B * (nm.B2n**2 + tB2**2)
        out["T_1"] = (symbol("T_1"), T1)
        out["T_2"] = (symbol("T_2"), T2)
        out["T_lost"] = (symbol("T_lost"), T1 - T2)
        out["J_n"] = (symbol("J_n"), model.m_A * (nm.A1n - nm.A2n))
        return out

    def _in_unknowns(self, expr: sympy.Expr) -> sympy.Expr:
        """A user's ``lhs - rhs`` in the unknowns, with everything known put in."""
        model = self.model
        derived = {sym: ex for sym, ex in self._derived().values()}
        x = expr.xreplace(derived).xreplace(self._unit_subs())
        x = x.xreplace(model.zeros).xreplace(model.pre)
        return self.num(x)

    def _format_equation(self, expr: sympy.Expr, k: int | None) -> str:
        U = list(self.model.unknowns)
        nm = self.model.nm
        if k == 4:
            first = [nm.B2n, nm.A2n]
            U = first + [u for u in U if u not in first]
        try:
            poly = sympy.Poly(sympy.expand(sympy.numer(sympy.together(expr))), *U)
        except sympy.PolynomialError:
            return _plain(expr) + " = 0"
        terms = [(m, c) for m, c in poly.terms() if any(m)]
        const = poly.coeff_monomial(1)
        if not terms:
            return _plain(expr) + " = 0"

        def order(mc: tuple) -> tuple:
            m = mc[0]
            return (-sum(m), [-x for x in m])

        terms.sort(key=order)
        sign = -1 if _is_negative(terms[0][1]) else 1
        if len(terms) == 1:  # one unknown: solved for it
            sign = sympy.Integer(1) / terms[0][1]
        out = ""
        for i, (m, c) in enumerate(terms):
            c = sign * c
            mono = "*".join(u.name + (f"^{p}" if p > 1 else "") for u, p in zip(U, m, strict=True) if p)
            neg = _is_negative(c)
            mag = -c if neg else c
            coef = "" if mag == 1 else _coef(mag) + " "
            piece = f"{coef}{mono}"
            if i == 0:
                out = ("-" if neg else "") + piece
            else:
                out += (" - " if neg else " + ") + piece
        return f"{out} = {_coef(-sign * const) if const != 0 else '0'}"


def _and(words: list[str]) -> str:
    return " and ".join(words) if len(words) < 3 else ", ".join(words[:-1]) + " and " + words[-1]


def _with_unit(number: str, unit_text: str) -> str:
    if not unit_text:
        return number
    shown = units.plain_unit(unit_text)
    return number + shown if shown == "°" else f"{number} {shown}"


def _is_negative(c: sympy.Expr) -> bool:
    x = _number_of(c) if not c.free_symbols else None
    if x is not None:
        return x.real < 0
    return c.could_extract_minus_sign()


def _coef(c: sympy.Expr) -> str:
    if c.is_Rational:
        if c.q == 1:
            return str(c.p)
        q = c.q
        for p in (2, 5):
            while q % p == 0:
                q //= p
        if q == 1 and len(str(c.q)) <= 6:
            return format(Decimal(c.p) / Decimal(c.q), "f")
    if not c.free_symbols:
        x = _number_of(c)
        if x is not None:
            return format_number(sympy.Float(x.real, 30), 4)
    return _plain(sympy.N(c, 4))


def _tidy(x: sympy.Expr) -> sympy.Expr:
    """A short form of ``x`` for showing (simplified when that is cheap)."""
    if sympy.count_ops(x) > 80:
        return x
    try:
        return sympy.simplify(x)
    except (TypeError, ValueError, NotImplementedError):
        return x


def _plain(x: sympy.Expr) -> str:
    return str(x).replace("**", "^")


def _pct_plain(x: sympy.Expr) -> str:
    return f"{float(x) * 100:g} %"


def _phrase(d: Diagnosis) -> str:
    m = mistakes.REGISTRY.get(d.mistake)
    return m.phrase if m is not None else d.title


def _split_unit(text: str) -> tuple[str, units.Unit] | None:
    """``EXPR UNIT`` -> (EXPR, unit) when the last word is a unit."""
    m = re.match(r"^(.*\S)\s+([A-Za-z°][A-Za-z°/*^·\d]*)\s*$", text)
    if not m:
        return None
    try:
        return m.group(1), units.parse_unit(m.group(2))
    except ValueError:
        return None


def _simplify(d: sympy.Expr) -> sympy.Expr | None:
    if sympy.count_ops(d) > 400:
        return None
    try:
        return sympy.simplify(d)
    except (TypeError, ValueError, NotImplementedError, RecursionError):
        return None


def _coefficients(expr: sympy.Expr, U: tuple[sympy.Symbol, ...]) -> dict[tuple[int, ...], complex] | None:
    try:
        poly = sympy.Poly(sympy.expand(sympy.numer(sympy.together(expr))), *U)
    except (sympy.PolynomialError, sympy.GeneratorsError):
        return None
    out = {}
    for m, c in poly.terms():
        x = _number_of(c)
        if x is None:
            return None
        out[m] = x
    return out


def _proportional(a: sympy.Expr, b: sympy.Expr, U: tuple[sympy.Symbol, ...], pts: list[dict], tol: float) -> bool:
    """Whether equations ``a = 0`` and ``b = 0`` are the same up to a nonzero factor."""
    for pt in pts:
        ca, cb = _coefficients(a.xreplace(pt), U), _coefficients(b.xreplace(pt), U)
        if not ca or not cb:
            return False
        key = max(cb, key=lambda m: abs(cb[m]))
        if abs(ca.get(key, 0)) == 0:
            return False
        c = ca[key] / cb[key]
        scale = abs(cb[key])
        for m in set(ca) | set(cb):
            if abs(ca.get(m, 0) - c * cb.get(m, 0)) > max(tol, 1e-12) * abs(c) * scale:
                return False
    return True


def _solve_with(
    F: sympy.Expr, base: mistakes.Outcome, k: int, U: tuple[sympy.Symbol, ...], pts: list[dict]
) -> list[list[dict]] | None:
    """Solve the correct equations with (k) replaced by ``F = 0``, at each point."""
    out = []
    for pt in pts:
        eqs = [sympy.N(x.xreplace(pt), 30) for j, x in base.equations.items() if j != k]
        eqs.append(sympy.N(sympy.numer(sympy.together(F.xreplace(pt))), 30))
        try:
            roots = sympy.solve(eqs, list(U), dict=True)
        except (NotImplementedError, ValueError, TypeError):
            return None
        roots = [r for r in roots if set(r) == set(U)]
        if not roots:
            return None
        out.append(roots)
    return out


def _matches(
    roots: list[list[dict]], outcome: mistakes.Outcome, U: tuple[sympy.Symbol, ...], pts: list[dict], tol: float
) -> bool:
    slack = max(5 * tol, 1e-8)
    for found, pt in zip(roots, pts, strict=True):
        target = {}
        for u in U:
            x = _number_of(outcome.post[u].xreplace(pt))
            if x is None:
                return False
            target[u] = x
        scale = max([abs(v) for v in target.values()] + [1e-12])
        ok = False
        for r in found:
            vals = [_number_of(r[u]) for u in U]
            if any(v is None for v in vals):
                continue
            if all(abs(v - target[u]) <= slack * scale for v, u in zip(vals, U, strict=True)):
                ok = True
                break
        if not ok:
            return False
    return True


def _satisfied(F: sympy.Expr, base: mistakes.Outcome, U: tuple[sympy.Symbol, ...], pts: list[dict], tol: float) -> bool:
    for pt in pts:
        G = sympy.expand(sympy.numer(sympy.together(F.xreplace(pt))))
        sol = {u: base.post[u].xreplace(pt) for u in U}
        terms = G.args if isinstance(G, sympy.Add) else (G,)
        vals = [_number_of(t.xreplace(sol)) for t in terms]
        if any(v is None for v in vals):
            return False
        scale = max(abs(v) for v in vals) if vals else 0
        if scale == 0:
            return False
        if abs(sum(vals)) > max(tol, 1e-9) * scale * 2:
            return False
    return True


# ---------------------------------------------------------------- the command line


def run(
    problem: str,
    answers: list[str] | None = None,
    answers_file: str | None = None,
    equations: list[str] | None = None,
    tolerance: str | None = None,
    fmt: str = "text",
) -> tuple[Report, str]:
    """What ``derive check`` does: load, solve, check; returns the report and its rendering."""
    from derive.problem import load
    from derive.steps import solve

    given = Answers()
    if answers_file:
        given = load_answers(answers_file)
    extra = Answers(
        tuple(answer_option(a) for a in answers or ()),
        tuple(equation_option(x) for x in equations or ()),
    )
    given = given.merged(extra)
    tol = parse_tolerance(tolerance) if tolerance is not None else given.tolerance
    if not given.answers and not given.equations:
        raise InputError("nothing to check: give answers with --answer NAME=VALUE or --answers FILE", where="usage")
    solution = solve(load(problem))
    report = check(solution, given, tolerance=tol)
    return report, report.render(fmt)


__all__ = [
    "Answers",
    "Diagnosis",
    "Entry",
    "Item",
    "Report",
    "answer_option",
    "check",
    "equation_option",
    "load_answers",
    "loads_answers",
    "parse_tolerance",
    "run",
]
