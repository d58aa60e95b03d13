"""SymPy's LaTeX printer set up for the notes (:class:`StepPrinter`), and the helpers that
keep an expression's structure as written: substitution, signs of terms."""

from __future__ import annotations

from collections.abc import Mapping
from decimal import Decimal

import sympy
from sympy.printing.latex import LatexPrinter

from derive.numbers import as_written, figures_for, format_number, format_places, short_decimal, to_decimal
from derive.steps.model import Degrees
from derive.symbols import latex_name, relabel, vector_latex
from derive.writers.printing.numerals import number_latex, power_latex, written_figures


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
        trim_floats: bool = False,
        fractions: bool = False,
        labels: tuple[str, str] = ("A", "B"),
        data: frozenset[sympy.Expr] | None = None,
    ) -> None:
        super().__init__({"order": "none", "fold_func_brackets": True, "inv_trig_style": "power"})
        self._data = data  # whole numbers of the data, printed as given; None: every whole number so
        self._labels = labels
        self._trim_floats = trim_floats
        self._fractions = fractions
        self._values = dict(values or {})
        self._cancel = cancel
        self._digits = digits
        self._extra = extra
        self._round_integers = round_integers
        self._decimals = decimals
        self._decimal_rationals = decimal_rationals

    def _print(self, expr, **kwargs) -> str:
        """A display structure (``UnevaluatedExpr``) prints its own node, its parts as they are."""
        if isinstance(expr, sympy.UnevaluatedExpr):
            return super()._print(expr.args[0], **kwargs)
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
        if isinstance(expr, Degrees):  # an angle's number: as written when short, else an intermediate's figures
            deg = expr.degrees
            return (as_written(deg) if short_decimal(deg) else number_latex(deg, self._digits, 1)) + r"^\circ"
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
            if written_figures(to_decimal(expr)) > written_figures(
                Decimal(format_number(expr, self._digits, extra=self._extra))
            ):
                return number_latex(expr, self._digits, self._extra)  # exact, but too long: 9.435, not 9.43536
            return power_latex(as_written(expr))
        return super()._print_Rational(expr)

    def _print_Integer(self, expr: sympy.Integer) -> str:
        if self._round_integers and expr != 0:
            return number_latex(expr, self._digits, self._extra)
        if self._data is not None and expr not in self._data and self._longer_than_shown(expr):
            # worked out, not given: at the line's figures (190, not 188, at one figure)
            if self._decimals is not None:
                return power_latex(format_places(expr, self._decimals, self._digits, self._extra))
            return number_latex(expr, self._digits, self._extra)
        if abs(expr.p) >= 10**6:
            if written_figures(to_decimal(expr)) > written_figures(
                Decimal(format_number(expr, self._digits, extra=self._extra))
            ):
                return number_latex(expr, self._digits, self._extra)  # 7.350 x 10^22, not all its digits
            return power_latex(as_written(expr))
        return str(expr.p)

    def _longer_than_shown(self, expr: sympy.Integer) -> bool:
        """True when the whole number ``expr`` has more figures than an intermediate shows."""
        figures = figures_for(to_decimal(expr), self._digits) + self._extra
        return written_figures(to_decimal(expr)) > figures

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
        args = [a for a in _over_letters(expr.args) if a != 1] or [sympy.Integer(1)]  # 1 (v + 4u/3) is v + 4u/3
        if len(args) == 1:
            return self._print(args[0])
        # beside a surd a fraction stays a fraction: sqrt(2)/2, not 0.5 sqrt(2)
        surd = any(isinstance(a, sympy.Pow) and a.base.is_Rational and not a.exp.is_Integer for a in args)
        decimal = self._decimal_rationals and not surd
        num, den = [], []

        def first(a: sympy.Expr) -> bool:  # numbers before letters (not a sum: v (20 + 5))
            return self._numberish(a) or (a.is_number and not isinstance(a, sympy.Add))

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

    def _numberish(self, a: sympy.Expr) -> bool:
        return a.is_Number or a in self._values or (isinstance(a, sympy.Pow) and a.base in self._values)

    def _join(self, factors: list[sympy.Expr], bare: bool = False) -> str:
        if bare and len(factors) == 1:
            return self._print(factors[0])
        out = ""
        prev = None
        for a in factors:
            s = self._print(a)
            wrap = isinstance(a, sympy.Add)
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
            if base.startswith(("-", "\\frac")) or " " in base:
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


def _over_letters(args: tuple[sympy.Expr, ...]) -> list[sympy.Expr]:
    """A product's factors; beside a fraction's number, a factor that is itself a product
    over letters taken apart, so that the product is one fraction: m u² (kλ + 1)²/(2k),
    never (m u² (kλ + 1)²/k)/2."""
    if not any(a.is_Rational and a.q != 1 for a in args):
        return list(args)
    out: list[sympy.Expr] = []
    for a in args:
        over = isinstance(a, sympy.Mul) and any(
            isinstance(f, sympy.Pow) and f.exp.is_negative and f.base.free_symbols for f in a.args
        )
        out += _over_letters(a.args) if over else [a]
    return out
