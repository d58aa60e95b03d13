"""LaTeX for the mathematics of a solution: SymPy's printer, set up for the notes.

A :class:`StepPrinter` prints symbols with the notes' names, numbers at the
problem's significant figures, a given's number in place of its symbol on a
substitution line, struck-out (cancelled) masses, and sums in the order the
equations were written. Renderers call :func:`latex_eqn` and
:func:`latex_inline`; no LaTeX string is patched afterwards.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from decimal import Decimal

import sympy
from sympy.printing.latex import LatexPrinter

from derive.numbers import (
    PRECISION,
    as_written,
    exactify,
    floatify,
    format_number,
    format_places,
    places_that_add_up,
    short_decimal,
    structural,
    to_decimal,
)
from derive.problem.units import latex_unit, parse_unit
from derive.steps.model import Block, Eqn, Side
from derive.symbols import latex_name, relabel, vector_latex
from derive.writers.width import width_pt


@dataclass(frozen=True)
class Slot:
    """A number left open when a solution is compiled for many variants: ``expr`` in
    the varied givens, printed as ``kind`` says at ``digits``(+``extra``) figures or
    with its block's places after the point."""

    expr: sympy.Expr
    kind: str  # given | number | result | lead | signed | leadcoef | signedcoef
    digits: int | None
    extra: int
    block: int | None


class SlotBook:
    """Collects the open numbers of a compiled solution; each prints as a token."""

    def __init__(self) -> None:
        self.slots: list[Slot] = []
        self.claims: dict[int, list[tuple[tuple[sympy.Expr, ...], sympy.Expr]]] = {}

    def token(self, expr: sympy.Expr, kind: str, digits: int | None, extra: int, block: int | None) -> str:
        self.slots.append(Slot(expr, kind, digits, extra, block))
        return f"DRVSLOT{len(self.slots) - 1}X"


@dataclass(frozen=True)
class Style:
    """How numbers print: the answer's figures (None: textbook rule) and the extra
    figures intermediates carry; ``values`` and ``angles`` feed substitution lines;
    ``strike`` False prints a cancelled symbol without its stroke (for converters
    that have no ``\\cancel``); ``derived`` symbols have numbers worked out, not
    written in the file (a chain's carried values), rounded where long."""

    digits: int | None
    extra: int = 1
    values: Mapping[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    angles: frozenset[sympy.Symbol] = frozenset()
    decimals: int | None = None
    varied: frozenset[sympy.Symbol] = frozenset()
    slots: SlotBook | None = field(default=None, compare=False)
    block: int | None = None
    hide_optional: bool = False
    strike: bool = True
    decimal: frozenset[sympy.Symbol] = frozenset()
    letters: frozenset[sympy.Symbol] = frozenset()
    letter_units: Mapping[sympy.Symbol, str] = field(default_factory=dict)
    labels: tuple[str, str] = ("A", "B")
    derived: frozenset[sympy.Symbol] = frozenset()


def number_latex(value: sympy.Expr | Decimal, digits: int | None, extra: int = 0) -> str:
    """A number at ``digits`` (+``extra``) significant figures, in LaTeX."""
    return power_latex(format_number(value, digits, extra=extra))


def power_latex(text: str) -> str:
    """``1.67e-27`` as ``1.67 \\times 10^{-27}``; plain numbers as they are."""
    if "e" in text:
        mant, exp = text.split("e")
        return rf"{mant} \times 10^{{{int(exp)}}}"
    return text


def exact_latex(value: sympy.Expr, digits: int | None, extra: int, *, derived: bool = False) -> str:
    """A given's number as the file wrote it when short and exact (0.6, 20, 1.67e-27), else rounded.

    A ``derived`` number was worked out, not written (a value carried from an earlier
    stage of a chain): exact and short, it is still rounded where it has more figures
    than an intermediate shows (4.538, not the 4.5375 of 8.25 · 0.55)."""
    if value.is_Integer and abs(value) < 10**6:
        return str(value)
    if short_decimal(value) and not (derived and _longer(value, digits, extra)):
        return power_latex(as_written(value))
    return number_latex(value, digits, extra)


def _longer(value: sympy.Expr, digits: int | None, extra: int) -> bool:
    """True when ``value`` written out exactly shows more figures than ``digits`` (+``extra``)."""
    return _figures(to_decimal(value)) > _figures(Decimal(format_number(value, digits, extra=extra)))


def _as_angle(expr: sympy.Expr) -> sympy.Expr:
    """An angle in letters as a textbook writes it, tan^-1(...), not (180/pi) tan^-1(...) =
    57.3 tan^-1(...): the inverse function gives the angle, whatever its unit."""
    arcs = (sympy.atan, sympy.atan2, sympy.asin, sympy.acos)

    def degrees(e: sympy.Expr) -> bool:
        return e.is_Mul and (1 / sympy.pi) in e.args and any(isinstance(a, arcs) for a in e.args)

    def radians(e: sympy.Expr) -> sympy.Expr:
        factor = sympy.Mul(*[a for a in e.args if not isinstance(a, arcs)]) * sympy.pi / 180
        arc = sympy.Mul(*[a for a in e.args if isinstance(a, arcs)])
        return arc if factor == 1 else (-arc if factor == -1 else e)

    return expr.replace(degrees, radians) if expr.has(sympy.pi) else expr


def _figures(x: Decimal) -> int:
    """Significant figures of a decimal as written (trailing zeros of a whole number not counted)."""
    return len(x.normalize().as_tuple().digits) if x else 1


def substitute(expr: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``expr`` with ``values`` put in, its structure kept (no re-evaluation: 5(x + 2)
    stays 5(x + 2) instead of becoming 5x + 10)."""
    if not values or not (expr.free_symbols & set(values)):
        return expr
    if isinstance(expr, sympy.Symbol):
        return values.get(expr, expr)
    if expr.is_Atom:
        return expr
    args = [substitute(a, values) for a in expr.args]
    if isinstance(expr, (sympy.Add, sympy.Mul, sympy.Pow)):
        return expr.func(*args, evaluate=False)
    return expr.func(*args)


def is_negative_term(expr: sympy.Expr) -> bool:
    """True for a term written with a leading minus: -3, -v_B1 cos(theta), -5 · 9.507."""
    if expr.is_Number:
        return bool(expr < 0)
    return isinstance(expr, sympy.Mul) and bool(expr.args) and expr.args[0].is_Number and bool(expr.args[0] < 0)


def negate(expr: sympy.Expr) -> sympy.Expr:
    """``-expr``, keeping an unevaluated product unevaluated: -(-5 · 9.507) is 5 · 9.507."""
    if isinstance(expr, sympy.Mul) and expr.args and expr.args[0].is_Number and expr.args[0] < 0:
        first = -expr.args[0]
        rest = expr.args[1:]
        if first == 1:
            return rest[0] if len(rest) == 1 else sympy.Mul(*rest, evaluate=False)
        return sympy.Mul(first, *rest, evaluate=False)
    return -expr


def _factor_key(a: sympy.Expr) -> int:
    """Order of factors in a printed product: number, mass, symbol, function, sum, unit vector."""
    if a.is_Number:
        return 0
    if isinstance(a, sympy.Symbol):
        if a.name.startswith("vec:"):
            return 5
        return 1 if a.name.startswith(("m", "M")) else 2
    if isinstance(a, sympy.Pow) and isinstance(a.base, sympy.Symbol):
        return 2
    if isinstance(a, sympy.Add):
        return 4
    return 3


def _factors(expr: sympy.Expr):
    for a in expr.args:
        if isinstance(a, sympy.Mul):
            yield from _factors(a)
        else:
            yield a


class StepPrinter(LatexPrinter):
    """SymPy's LaTeX printer with the notes' conventions (see module docstring)."""

    def __init__(
        self,
        values: Mapping[sympy.Symbol, str] | None = None,
        cancel: frozenset[sympy.Symbol] = frozenset(),
        digits: int | None = None,
        extra: int = 1,
        round_integers: bool = False,
        decimals: int | None = None,
        decimal_rationals: bool = False,
        slots: SlotBook | None = None,
        varied: frozenset[sympy.Symbol] = frozenset(),
        slot_kind: str = "number",
        block: int | None = None,
        trim_floats: bool = False,
        fractions: bool = False,
        labels: tuple[str, str] = ("A", "B"),
    ) -> None:
        super().__init__({"order": "none", "fold_func_brackets": True, "inv_trig_style": "power"})
        self._labels = labels
        self._trim_floats = trim_floats
        self._fractions = fractions
        self._slots = slots
        self._varied = varied
        self._slot_kind = slot_kind
        self._block = block
        self._values = dict(values or {})
        self._cancel = cancel
        self._digits = digits
        self._extra = extra
        self._round_integers = round_integers
        self._decimals = decimals
        self._decimal_rationals = decimal_rationals

    def _print(self, expr, **kwargs) -> str:
        """A part that depends only on varied givens becomes an open number (a slot)."""
        if isinstance(expr, sympy.UnevaluatedExpr):  # a display structure: its own node printed, its parts open
            return super()._print(expr.args[0], **kwargs)
        if self._slots is not None and isinstance(expr, sympy.Expr) and not expr.is_Number:
            free = expr.free_symbols
            if free and free <= self._varied and (self._slot_kind != "given" or isinstance(expr, sympy.Symbol)):
                kind = self._slot_kind
                return self._slots.token(expr, kind, self._digits, self._extra, self._block)
        return super()._print(expr, **kwargs)

    def _print_atan(self, expr: sympy.Function, exp: object = None) -> str:
        return r"\tan^{-1}\left(" + self._print(expr.args[0]) + r"\right)"

    def _print_asin(self, expr: sympy.Function, exp: object = None) -> str:
        return r"\sin^{-1}\left(" + self._print(expr.args[0]) + r"\right)"

    def _print_acos(self, expr: sympy.Function, exp: object = None) -> str:
        return r"\cos^{-1}\left(" + self._print(expr.args[0]) + r"\right)"

    def _print_atan2(self, expr: sympy.Function, exp: object = None) -> str:
        y, x = expr.args
        return r"\operatorname{atan2}\left(" + self._print(y) + ", " + self._print(x) + r"\right)"

    def _print_Symbol(self, expr: sympy.Symbol, style: str = "plain") -> str:
        if expr in self._values:
            return self._values[expr]
        name = relabel(expr.name, self._labels)
        tex = vector_latex(name) or (name if name.startswith("\\") else latex_name(name))
        if expr in self._cancel:
            return r"\cancel{" + tex + "}"
        return tex

    def _print_Float(self, expr: sympy.Float) -> str:
        if self._decimals is not None:
            return power_latex(format_places(expr, self._decimals, self._digits, self._extra))
        if self._trim_floats:  # a decimal beside letters: 0.2 u, not 0.2000 u
            text = format_number(expr, self._digits, extra=self._extra)
            mantissa, _, power = text.partition("e")
            trimmed = mantissa.rstrip("0").rstrip(".") if "." in mantissa else mantissa
            short = trimmed + ("e" + power if power else "")
            value = to_decimal(expr)
            if abs(Decimal(short) - value) > abs(value) * Decimal("1e-12"):
                return power_latex(text)  # rounded: 1.00 v, 49.0 m (not 1 v, 49 m, read as exact)
            return power_latex(short)
        return number_latex(expr, self._digits, self._extra)

    def _as_decimal(self, r: sympy.Rational) -> bool:
        """Whether a short decimal prints as one: beside letters, a half or three quarters
        stays a fraction (m u²/2), fifths and tenths and larger numbers are decimals
        (0.6 u, 62.5 e²)."""
        if not short_decimal(r):
            return False
        return not (self._fractions and abs(r.p) <= 3 and r.q <= 12 and r.q % 5 != 0)

    def _print_Rational(self, expr: sympy.Rational) -> str:
        if self._decimal_rationals and not self._round_integers and self._as_decimal(expr):
            if _figures(to_decimal(expr)) > _figures(Decimal(format_number(expr, self._digits, extra=self._extra))):
                return number_latex(expr, self._digits, self._extra)  # exact, but too long: 9.435, not 9.43536
            return power_latex(as_written(expr))
        return super()._print_Rational(expr)

    def _print_Integer(self, expr: sympy.Integer) -> str:
        if self._round_integers and expr != 0:
            return number_latex(expr, self._digits, self._extra)
        if abs(expr.p) >= 10**6:
            if _figures(to_decimal(expr)) > _figures(Decimal(format_number(expr, self._digits, extra=self._extra))):
                return number_latex(expr, self._digits, self._extra)  # 7.350 x 10^22, not all its digits
            return power_latex(as_written(expr))
        return str(expr.p)

    def _print_Add(self, expr: sympy.Add, order: str | None = None) -> str:
        return join_terms(self.add_terms(expr))

    def add_terms(self, expr: sympy.Add) -> list[tuple[str, str]]:
        """The terms of a sum as printed, each with its sign: ``("+", "m v")``, ``("-", "3")``
        (a sign ``""`` when the text carries its own, as an open number does)."""
        out: list[tuple[str, str]] = []
        terms = expr.args
        if len(terms) > 1 and terms[0].is_Rational and any(t.free_symbols for t in terms):
            terms = terms[1:] + terms[:1]  # e - 1, not -1 + e
        if is_negative_term(terms[0]) and any(t.free_symbols for t in terms):
            positive = [t for t in terms if not is_negative_term(t)]
            if positive:  # 1 - 2 e, not -2 e + 1
                terms = tuple(positive) + tuple(t for t in terms if is_negative_term(t))
        for i, term in enumerate(terms):
            if (
                self._slots is not None
                and self._slot_kind != "given"
                and term.free_symbols
                and term.free_symbols <= self._varied
            ):
                role = "lead" if i == 0 else "signed"
                out.append(
                    ("", self._slots.token(term, f"{role}:{self._slot_kind}", self._digits, self._extra, self._block))
                )
                continue
            if is_negative_term(term):
                s = self._print(negate(term))
                s = self._paren_if_sum(negate(term), s)
                if s.startswith("-"):
                    s = r"\left(" + s + r"\right)"
                out.append(("-", s))
            else:
                s = self._print(term)
                if i and s.startswith("-"):
                    s = r"\left(" + s + r"\right)"
                out.append(("+", s))
        return out

    def _paren_if_sum(self, expr: sympy.Expr, s: str) -> str:
        return r"\left(" + s + r"\right)" if isinstance(expr, sympy.Add) else s

    def _print_Mul(self, expr: sympy.Mul) -> str:
        """A product as the notes write it: numbers, masses, other symbols, functions;
        ``\\cdot`` between two numbers; negative powers as a fraction."""
        if is_negative_term(expr):
            factors = list(_factors(expr))
            sums = [a for a in factors if isinstance(a, sympy.Add) and a.free_symbols]
            numbers = [a for a in factors if a.is_Number and a < 0]
            if len(sums) == 1 and len(numbers) == 1 and self._fractions:  # -u (2e - 1)/3 is u (1 - 2e)/3
                turned = [-a if a is sums[0] or a is numbers[0] else a for a in factors]
                return self._print(sympy.Mul(*[a for a in turned if a != 1], evaluate=False))
            inner = negate(expr)
            if inner != expr:
                s = self._print(inner)
                wrap = isinstance(inner, sympy.Add) or s.startswith("-")
                return "-" + (r"\left(" + s + r"\right)" if wrap else s)
        args = [a for a in expr.args if a != 1] or [sympy.Integer(1)]  # 1 (v + 4u/3) is v + 4u/3
        if len(args) == 1:
            return self._print(args[0])
        # beside a surd a fraction stays a fraction: sqrt(2)/2, not 0.5 sqrt(2)
        surd = any(isinstance(a, sympy.Pow) and a.base.is_Rational and not a.exp.is_Integer for a in args)
        decimal = self._decimal_rationals and not surd
        num, den = [], []

        def first(a: sympy.Expr) -> bool:  # numbers before letters (not a sum: v (20 + 5))
            return self._open(a) or self._numberish(a) or (a.is_number and not isinstance(a, sympy.Add))

        for a in sorted(args, key=lambda a: 0 if first(a) else _factor_key(a)):
            if isinstance(a, sympy.Rational) and not a.is_Integer and not (decimal and self._as_decimal(a)):
                if a.p != 1:
                    num.insert(0, sympy.Integer(a.p))
                den.insert(0, sympy.Integer(a.q))
                continue
            if isinstance(a, sympy.Pow) and a.exp.is_Number and a.exp < 0:
                den.append(a.base if a.exp == -1 else sympy.Pow(a.base, -a.exp, evaluate=False))
            else:
                num.append(a)
        if den:
            top = self._join(num, bare=True) if num else "1"
            bottom = self._join(den, bare=True)
            return r"\frac{" + top + "}{" + bottom + "}"
        return self._join(num)

    def _open(self, a: sympy.Expr) -> bool:
        """True for a part that becomes an open number (a homework variant's slot)."""
        return (
            self._slots is not None
            and self._slot_kind != "given"
            and isinstance(a, sympy.Expr)
            and bool(a.free_symbols)
            and a.free_symbols <= self._varied
        )

    def _numberish(self, a: sympy.Expr) -> bool:
        if self._slots is not None and isinstance(a, sympy.Expr) and a.free_symbols and a.free_symbols <= self._varied:
            return True
        return a.is_Number or a in self._values or (isinstance(a, sympy.Pow) and a.base in self._values)

    def _join(self, factors: list[sympy.Expr], bare: bool = False) -> str:
        if bare and len(factors) == 1:
            return self._print(factors[0])
        out = ""
        prev = None
        for a in factors:
            s = self._print(a)
            wrap = isinstance(a, sympy.Add) and not self._open(a)
            wrap = wrap or (prev is not None and s.startswith("-"))
            wrap = wrap or (len(factors) > 1 and r"\times 10^" in s)  # (2 × 10^6)(1.67 × 10^-27)
            if wrap:
                s = r"\left(" + s + r"\right)"
            if prev is None:
                out = s
            elif self._numberish(prev) and (self._numberish(a) or s[:1].isdigit() or s.startswith(r"\left(")):
                out += r" \cdot " + s if not s.startswith(r"\left(") else s
            else:
                out += " " + s
            prev = a
        return out

    def _print_Pow(self, expr: sympy.Pow) -> str:
        if expr.base in self._values and expr.exp.is_Integer and expr.exp > 0:
            base = self._values[expr.base]
            if base.startswith("-") or " " in base:
                base = r"\left(" + base + r"\right)"
            return f"{base}^{{{expr.exp}}}"
        if isinstance(expr.base, sympy.Float) and expr.exp.is_Integer:
            base = self._print(expr.base)
            base = r"\left(" + base + r"\right)" if base.startswith("-") else base
            return f"{base}^{{{expr.exp}}}"
        if expr.exp.is_Number and expr.exp < 0 and not expr.base.is_Number:
            # 1/tan(x), not SymPy's power form of a function (which read "-1 tan x")
            inverse = expr.base if expr.exp == -1 else sympy.Pow(expr.base, -expr.exp, evaluate=False)
            return r"\frac{1}{" + self._print(inverse) + "}"
        saved, self._round_integers = self._round_integers, False
        try:
            return super()._print_Pow(expr)
        finally:
            self._round_integers = saved


def values_map(style: Style, digits: int | None, extra: int, symbols: set[sympy.Symbol]) -> dict[sympy.Symbol, str]:
    """The substitution line's numbers: each symbol's value, angles in degrees."""
    out = {}
    for s in symbols:
        if s not in style.values:
            continue
        v = style.values[s]
        derived = s in style.derived
        if s in style.angles:
            deg = v * 180 / sympy.pi
            out[s] = exact_latex(deg, digits, extra, derived=derived) + r"^\circ"
        else:
            out[s] = exact_latex(v, digits, extra, derived=derived)
    return out


def _prepared(
    expr: sympy.Expr, mode: str, style: Style, extra: int, cancel: frozenset[sympy.Symbol]
) -> tuple[StepPrinter, sympy.Expr]:
    """The printer for ``mode`` (see :data:`derive.steps.model.Mode`) and ``expr`` made ready for it."""
    book, varied = style.slots, style.varied
    if mode == "symbolic":
        return StepPrinter(cancel=cancel, digits=style.digits, extra=extra, labels=style.labels), expr
    if mode == "values":
        vals = values_map(style, style.digits, extra, expr.free_symbols)
        printer = StepPrinter(
            vals,
            cancel,
            style.digits,
            extra,
            decimal_rationals=True,
            slots=book,
            varied=varied,
            slot_kind="given",
            labels=style.labels,
        )
        return printer, expr
    if mode in ("numeric", "result") and _letters(expr, style):
        # letters remain: numbers exact where the data are (u (1 - 2e)/3), decimals
        # where the data are decimal (0.6 u), never 1.000 e
        values = {
            s: sympy.Float(v.evalf(PRECISION), PRECISION) if s in style.decimal else v for s, v in style.values.items()
        }
        expr = _one_term_per_letters(exactify(substitute(_as_angle(expr), values)))
        extra = 0 if mode == "result" else extra
        decimal = bool(style.decimal)  # with decimal data, 2.4 u; with exact data, 12 u/5
        # a fraction no textbook writes (4225 v^2/724808, from g = 9.8) as a decimal: 0.005829 v^2
        long = {
            r: sympy.Float(r, PRECISION)
            for r in expr.atoms(sympy.Rational)
            if not short_decimal(r) and (r.q > (12 if decimal else 1000) or abs(r.p) > 10**4)
        }
        expr = expr.xreplace(long)
        if decimal and mode == "result":  # an answer at the answer's figures: 3.86 m, not 3.856 m
            printer = StepPrinter(fractions=True)
            rounded = {r: sympy.Float(r, PRECISION) for r in expr.atoms(sympy.Rational) if printer._as_decimal(r)}
            expr = expr.xreplace(rounded)
        printer = StepPrinter(
            cancel=cancel,
            digits=style.digits,
            extra=extra,
            trim_floats=True,
            decimal_rationals=decimal,
            fractions=True,
            labels=style.labels,
        )
        return printer, expr
    if mode == "numeric":
        expr = substitute(expr, style.values)
        printer = StepPrinter(
            cancel=cancel,
            digits=style.digits,
            extra=extra,
            decimals=style.decimals,
            decimal_rationals=True,
            slots=book,
            varied=varied,
            block=style.block,
            labels=style.labels,
        )
        return printer, floatify(expr)
    if mode == "result":
        expr = substitute(expr, style.values)
        if expr.is_number and not isinstance(expr, sympy.UnevaluatedExpr):
            expr = sympy.Float(expr.evalf(PRECISION), PRECISION)
        printer = StepPrinter(
            cancel=cancel,
            digits=style.digits,
            extra=0,
            round_integers=True,
            slots=book,
            varied=varied,
            slot_kind="result",
            labels=style.labels,
        )
        return printer, floatify(expr, keep_integers=False)
    raise ValueError(mode)


def _one_term_per_letters(expr: sympy.Expr) -> sympy.Expr:
    """Terms that differ only in an irrational number as one term: -0.717 U, not
    -0.555 U - 0.1624 U (the parts of a nested radical, each rounded); in a sum at any
    depth (a component beside its unit vector too)."""
    if expr.is_Atom or not expr.args:
        return expr
    args = tuple(_one_term_per_letters(a) for a in expr.args)
    if args != expr.args:
        expr = expr.func(*args)
    return _one_sum(expr) if isinstance(expr, sympy.Add) else expr


def _one_sum(expr: sympy.Expr) -> sympy.Expr:
    groups: dict[sympy.Expr, list[sympy.Expr]] = {}
    for term in expr.args:
        number, letters = term.as_independent(*term.free_symbols, as_Add=False)
        groups.setdefault(letters, []).append(number)
    totals = {letters: sympy.Add(*numbers) for letters, numbers in groups.items() if len(numbers) > 1}
    if not totals or all(t.is_Rational for t in totals.values()):
        return expr  # nothing to join (2 u + u is left as the page wrote it)
    out = []
    for letters, numbers in groups.items():
        total = totals.get(letters, numbers[0])
        if not total.is_Rational and len(numbers) > 1:
            total = sympy.Float(total.evalf(PRECISION), PRECISION)
        out.append(total * letters)
    return sympy.Add(*out)


def _letters(expr: sympy.Expr, style: Style) -> bool:
    """True when ``expr`` keeps a given that the problem keeps as a letter (u, m, e) once
    its numbers are in; unknowns alone (v_A2) do not count, nor a variant's open numbers."""
    if style.slots is not None:
        return False
    return bool(substitute(expr, style.values).free_symbols & style.letters)


def latex_expr(
    expr: sympy.Expr, mode: str, style: Style, extra: int, cancel: frozenset[sympy.Symbol] = frozenset()
) -> str:
    """One expression printed in ``mode`` (see :data:`derive.steps.model.Mode`)."""
    printer, ready = _prepared(expr, mode, style, extra, cancel)
    return printer.doprint(ready)


def latex_terms(
    expr: sympy.Expr, mode: str, style: Style, extra: int, cancel: frozenset[sympy.Symbol] = frozenset()
) -> list[tuple[str, str]]:
    """``expr`` printed as :func:`latex_expr` prints it, as its terms with their signs
    (one term, sign ``"+"``, unless it is a sum); :func:`join_terms` gives the line back."""
    printer, ready = _prepared(expr, mode, style, extra, cancel)
    if isinstance(ready, sympy.UnevaluatedExpr):
        ready = ready.args[0]
    if isinstance(ready, sympy.Add) and style.slots is None:
        return printer.add_terms(ready)
    return [("+", printer.doprint(ready))]


def join_terms(terms: list[tuple[str, str]]) -> str:
    """Signed terms as one sum: ``a - b + c``; a sign ``""`` leaves the text as it is."""
    out = ""
    for i, (sign, text) in enumerate(terms):
        if not sign:
            out += text
        elif i == 0:
            out = ("-" if sign == "-" else "") + text
        else:
            out += f" {sign} {text}"
    return out


def side_terms(side: Side, style: Style, extra: int, cancel: frozenset[sympy.Symbol]) -> list[tuple[str, str]]:
    """A side of an equation as its printed terms with their signs, in order; a side
    of one term that is a sum gives that sum's terms."""
    out: list[tuple[str, str]] = []
    for i, term in enumerate(side.terms):
        if side.mode in ("numeric", "result") and not _letters(term, style):
            term = substitute(term, style.values)
            collapse = side.mode == "result" and not isinstance(term, sympy.UnevaluatedExpr)
            if term.is_number and (collapse or not structural(term)):
                term = floatify(term, keep_integers=side.mode == "numeric")
                if term == 0:
                    term = sympy.Integer(0)
            if style.slots is not None and term.free_symbols & style.varied:
                token = _slot_term(term, side.mode, style, extra, cancel, first=i == 0)
                if token is not None:
                    out.append(("", token))
                    continue
        neg = is_negative_term(term)
        body = negate(term) if neg else term
        if side.mode in ("numeric", "result") and _letters(term, style):
            if len(side.terms) == 1:  # the printer picks the sign; a sum gives its terms
                return latex_terms(term, side.mode, style, extra, cancel)
            s = latex_expr(term, side.mode, style, extra, cancel)  # the printer picks the sign: u (1 - 2e)/3
            neg, body = s.startswith("-"), term
            s = s[1:].lstrip() if neg else s
        elif len(side.terms) == 1 and not neg and isinstance(body, sympy.Add):
            return latex_terms(body, side.mode, style, extra, cancel)
        else:
            s = latex_expr(body, side.mode, style, extra, cancel)
        if neg and s.startswith("-"):
            neg, s = False, s[1:].lstrip()
        if isinstance(body, sympy.Add) and len(side.terms) > 1:
            s = r"\left(" + s + r"\right)"
        if i and not neg and s.startswith("-"):
            s = s[1:].lstrip()
            neg = True
        out.append(("-" if neg else "+", s))
    return out


def latex_side(side: Side, style: Style, extra: int, cancel: frozenset[sympy.Symbol]) -> str:
    """A side of an equation: its terms joined with their signs, in order."""
    return join_terms(side_terms(side, style, extra, cancel))


_UNITLESS = {sympy.Symbol(f"vec:e_{a}", commutative=True) for a in "tnxy"}


def _slot_term(
    term: sympy.Expr, mode: str, style: Style, extra: int, cancel: frozenset[sympy.Symbol], first: bool
) -> str | None:
    """A term whose number (or coefficient) depends on varied givens: its sign is
    known only per variant, so the slot prints the sign too."""
    assert style.slots is not None
    if isinstance(term, sympy.UnevaluatedExpr):
        return None  # a display structure: its parts are left open, not the whole
    others = term.free_symbols - style.varied
    if isinstance(term, sympy.Mul) and any(
        isinstance(a, sympy.Add) and a.free_symbols - style.varied for a in term.args
    ):
        return None  # a product with a sum in it: the printer leaves open the parts inside
    digits, ext = style.digits, (0 if mode == "result" else extra)
    kind = "result" if mode == "result" else "number"
    if not others:
        return style.slots.token(term, ("lead" if first else "signed") + ":" + kind, digits, ext, style.block)
    coeff, rest = term.as_independent(*others, as_Add=False)
    if not (coeff.free_symbols & style.varied):
        return None
    printer = StepPrinter(cancel=cancel, digits=digits, extra=ext, decimal_rationals=True, labels=style.labels)
    if first and isinstance(coeff, sympy.Add) and all(a.free_symbols <= style.varied for a in coeff.args):
        # a sum of coefficients stays a sum, v_A2n (12 + 6) as the notes write v_A2n (20 + 5):
        # one number there would read v_A2n = 2.25 + 0, a velocity without its unit, where it is 1
        parts = [
            style.slots.token(a, ("lead" if i == 0 else "signed") + ":" + kind, digits, ext, style.block)
            for i, a in enumerate(coeff.args)
        ]
        return printer.doprint(rest) + r" \left(" + "".join(parts) + r"\right)"
    token = style.slots.token(coeff, ("leadcoef" if first else "signedcoef") + ":" + kind, digits, ext, style.block)
    return token + " " + printer.doprint(rest)


def _unit_beside_letters(eqn: Eqn, style: Style) -> str | None:
    """The unit a value in letters still needs: none where its letters give its dimension
    (v_A2 = 0.6 u), the whole unit where they are pure numbers (3.5 + 3.5 e m/s), the rest
    where one letter gives part of it (T_1 = 22 m J/kg, m a mass in kg)."""
    last = eqn.sides[-1]
    if not eqn.unit or eqn.unit in ("%", "deg") or last.mode == "symbolic" or len(last.terms) != 1:
        return None
    term = last.terms[0].xreplace(dict(style.values))
    letters = term.free_symbols - _UNITLESS - style.varied
    if not letters or not letters <= style.letters | set(style.letter_units):
        return None
    dims = {s: parse_unit(style.letter_units[s]).dim if s in style.letter_units else (0, 0, 0, 0) for s in letters}
    have = _dimension(term, dims)
    if have is None or have == parse_unit(eqn.unit).dim:
        return None
    if not any(have):
        return eqn.unit
    if have == tuple(w - m for w, m in zip(parse_unit(eqn.unit).dim, (1, 0, 0, 0), strict=True)):
        # a mass short (T_1 = 4.8 v_A1^2 with the masses in numbers): the mass unit
        return "slug" if any("ft" in u for u in style.letter_units.values()) else "kg"
    alone = [s for s in letters if dims[s] == have and not any(c in style.letter_units[s] for c in "/*^")]
    return f"{eqn.unit}/{style.letter_units[alone[0]]}" if alone and "/" not in eqn.unit else None


def _dimension(expr: sympy.Expr, dims: Mapping[sympy.Symbol, tuple[int, ...]]) -> tuple[int, ...] | None:
    """The dimension of a value in letters of known dimensions (None where it cannot tell)."""
    if expr.is_number:
        return (0, 0, 0, 0)
    if isinstance(expr, sympy.Symbol):
        return tuple(dims[expr]) if expr in dims else None
    if isinstance(expr, sympy.Add):
        found = {_dimension(a, dims) for a in expr.args if not a.is_number}
        return found.pop() if len(found) == 1 else None
    if isinstance(expr, sympy.Mul):
        total = [0, 0, 0, 0]
        for a in expr.args:
            d = _dimension(a, dims)
            if d is None:
                return None
            total = [t + x for t, x in zip(total, d, strict=True)]
        return tuple(total)
    if isinstance(expr, sympy.Pow) and expr.exp.is_Rational:
        d = _dimension(expr.base, dims)
        return None if d is None or any(x * expr.exp % 1 for x in d) else tuple(int(x * expr.exp) for x in d)
    return None


def _struck(eqn: Eqn, style: Style) -> frozenset[sympy.Symbol]:
    """The symbols the line strikes out, unless the style prints no strokes."""
    return eqn.cancel if style.strike else frozenset()


def _line_unit(eqn: Eqn, style: Style) -> tuple[str | None, bool]:
    """The unit after the line's last side, and whether that side, a sum in letters, goes in
    brackets before it ((3.5 + 3.5 e) m/s)."""
    last = eqn.sides[-1]
    symbolic = last.mode == "symbolic" or any(
        t.xreplace(dict(style.values)).free_symbols - _UNITLESS - style.varied for t in last.terms
    )
    if not symbolic:
        return eqn.unit, False
    unit = _unit_beside_letters(eqn, style)
    return unit, bool(unit) and isinstance(last.terms[0].xreplace(dict(style.values)), sympy.Add)


def unit_latex(eqn: Eqn, style: Style) -> str:
    """The unit after the line's last side ('' where that side is still in symbols and its
    letters give its dimension)."""
    unit, _ = _line_unit(eqn, style)
    if not unit:
        return ""
    if unit == "%":
        return r"\ \%"
    return latex_unit(unit) if unit == "deg" else r"\ " + latex_unit(unit)


#: Around an optional side of a compiled variant page (with the " = " before it), for
#: the variant to keep where its numbers add up to the total after it (:func:`adds_up`).
SIDE_BEGIN, SIDE_END = "%%derive-side%", "%%derive-side-end%"

_NUMBER = re.compile(r"(?:\\left\()?(-?\d+(?:\.\d+)?)(?: \\times 10\^\{(-?\d+)\})?(?:\\right\))?")


def printed_number(text: str) -> Decimal | None:
    """The number a printed term shows (``-5.926``, ``1.6 \\times 10^{-3}``, ``\\left(-3\\right)``);
    None for anything else (letters, a product)."""
    m = _NUMBER.fullmatch(text.strip())
    if m is None:
        return None
    return Decimal(m.group(1)).scaleb(int(m.group(2) or 0))


def adds_up(terms: str, total: str) -> bool:
    """True when the printed sum ``terms`` (``-5.926 + 15.21``), added as written, gives
    the printed ``total`` to the total's last figure, as a reader checks it; True also
    where a term or the total is not a plain number (nothing to add)."""
    parts = re.split(r" ([+-]) ", terms.strip())
    value = printed_number(parts[0])
    shown = printed_number(total)
    if value is None or shown is None:
        return True
    for sign, text in zip(parts[1::2], parts[2::2], strict=True):
        term = printed_number(text)
        if term is None:
            return True
        value += term if sign == "+" else -term
    m = _NUMBER.fullmatch(total.strip())
    assert m is not None
    places = len(m.group(1).partition(".")[2]) - int(m.group(2) or 0)
    return abs(value - shown) <= Decimal(1).scaleb(-places) / 2


def _printed_sides(eqn: Eqn, style: Style, extra: int) -> list[tuple[list[tuple[str, str]], bool]]:
    """Each side's printed terms, and whether a variant's page decides to keep it; a side
    printed the same as the one before it is shown once (v_2 = -u, not v_2 = -u = -u). An
    optional side whose terms do not add up to the total after it is left out."""
    texts = [side_terms(side, style, extra, _struck(eqn, style)) for side in eqn.sides]
    printed: list[tuple[list[tuple[str, str]], bool]] = []
    for side, terms in zip(eqn.sides, texts, strict=True):
        open_ = side.optional and style.slots is not None
        if side.optional and not open_ and not adds_up(join_terms(terms), join_terms(texts[-1])):
            continue
        if not printed or join_terms(terms) != join_terms(printed[-1][0]):
            printed.append((terms, open_))
    return printed


def latex_eqn(eqn: Eqn, style: Style, extra: int = 1) -> tuple[str, str | None]:
    """The line's LaTeX (without delimiters) and its tag."""
    printed = _printed_sides(eqn, style, extra)
    texts = [join_terms(terms) for terms, _ in printed]
    if _line_unit(eqn, style)[1]:
        texts[-1] = r"\left(" + texts[-1] + r"\right)"
    body = ""
    for i, (text, (_, open_)) in enumerate(zip(texts, printed, strict=True)):
        piece = (" = " if i else "") + text
        body += SIDE_BEGIN + piece + SIDE_END if open_ else piece
    body += unit_latex(eqn, style)
    if eqn.boxed:
        body = r"\boxed{" + body + "}"
    if eqn.implies:
        body = IMPLIES + body
    return body, eqn.tag


IMPLIES = r"\Rightarrow\quad "
_RELATION_PT = 13.33  # '=' with its spaces (Computer Modern, 10 pt)
_CONTINUED_PT = 10.0 + 12.22  # '\quad +' at the start of a continued row
_BOX_PT = 6.8  # what \boxed adds


@dataclass(frozen=True)
class Row:
    """One row of an equation line too wide for the page: ``lhs rel rhs``.

    The first row holds the left side (``lhs``) and ``=``; each later side starts a
    row of its own (``lhs`` empty, ``rel`` "="); a side still too wide goes on in
    rows that start with its next sign (``rel`` "+" or "-", ``continued``).
    """

    lhs: str
    rel: str
    rhs: str
    continued: bool = False


def latex_rows(eqn: Eqn, style: Style, width: float, extra: int = 1, reserve: float = 0.0) -> tuple[Row, ...]:
    """The line set on rows that each fit ``width`` pt (10 pt type, display style), as
    :func:`derive.writers.width.width_pt` estimates it; ``reserve`` pt more go beside it
    (the ANSWER mark). Empty when the line fits on one row, or has one side only.

    One side per row after the first (``T_2 = a``, ``= b``, ``= c``); a side still too
    wide is broken before one of its own terms' signs, never inside a term.
    """
    sides = [terms for terms, _ in _printed_sides(eqn, style, extra)]
    if len(sides) < 2:
        return ()
    unit = unit_latex(eqn, style)
    if unit:
        sign, text = sides[-1][-1]
        sides[-1][-1] = (sign, text + unit)
    room = width - reserve - (_BOX_PT if eqn.boxed else 0.0)
    lhs = (IMPLIES if eqn.implies else "") + join_terms(sides[0])
    if width_pt(lhs + " = " + " = ".join(join_terms(t) for t in sides[1:])) <= room:
        return ()
    left = width_pt(lhs)
    rows: list[Row] = []
    for terms in sides[1:]:
        chunks = [terms[:1]]
        for term in terms[1:]:
            trial = [*chunks[-1], term]
            lead = _RELATION_PT if len(chunks) == 1 else _CONTINUED_PT
            if term[0] in "+-" and left + lead + width_pt(_continued(trial)) > room:
                chunks.append([term])
            else:
                chunks[-1] = trial
        rows.append(Row(lhs if not rows else "", "=", join_terms(chunks[0])))
        rows.extend(Row("", chunk[0][0], _continued(chunk), continued=True) for chunk in chunks[1:])
    return tuple(rows)


def _continued(terms: list[tuple[str, str]]) -> str:
    """Terms joined, the first without its sign (the row's ``rel`` shows it)."""
    return join_terms([("+", terms[0][1]), *terms[1:]])


def block_style(block: Block, style: Style) -> Style:
    """The style for one block: where it shows a sum term by term, every
    intermediate gets the same places after the point, enough that the rounded
    terms add up to the rounded total (79.23 - 59.42 = 19.81)."""
    if block.answer_figures:
        style = replace(style, extra=0)
    if not block.sums:
        return style
    if style.slots is not None and any(
        (t.xreplace(dict(style.values)).free_symbols & style.varied)
        for terms, total in block.sums
        for t in (*terms, total)
    ):
        block_id = len(style.slots.claims)
        style.slots.claims[block_id] = [
            (tuple(t.xreplace(dict(style.values)) for t in terms), total.xreplace(dict(style.values)))
            for terms, total in block.sums
        ]
        return replace(style, block=block_id)
    sums = [
        ([to_decimal(floatify(t, False)) for t in terms], to_decimal(floatify(total, False)))
        for terms, total in block.sums
    ]
    places = places_that_add_up(sums, style.digits, style.extra, each=block.answer_figures)
    # no places at which the rounded terms add up: leave out the line that shows them
    return replace(style, decimals=places, hide_optional=places is None)


def latex_inline(expr: sympy.Basic, style: Style) -> str:
    """Inline mathematics in a sentence."""
    if isinstance(expr, sympy.Interval):
        lo = "(" if expr.left_open else "["
        hi = ")" if expr.right_open else "]"
        p = StepPrinter(digits=style.digits, labels=style.labels)
        return rf"\left{lo}{p.doprint(expr.start)}, {p.doprint(expr.end)}\right{hi}"
    printer = StepPrinter(digits=style.digits, decimal_rationals=True, fractions=True, labels=style.labels)
    if isinstance(expr, sympy.Eq):
        return printer.doprint(expr.lhs) + " = " + printer.doprint(expr.rhs)
    return printer.doprint(expr)
