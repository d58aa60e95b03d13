"""Expressions and sides of equations printed in a step's mode (symbolic, values, numeric,
result): the printer for the mode, and the expression made ready for it."""

from __future__ import annotations

import sympy

from derive.numbers import PRECISION, exactify, floatify, short_decimal, structural
from derive.steps.model import Side
from derive.writers.printing.numerals import exact_latex
from derive.writers.printing.printer import StepPrinter, is_negative_term, negate, substitute
from derive.writers.printing.style import Style


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


def _prepared(
    expr: sympy.Expr, mode: str, style: Style, extra: int, cancel: frozenset[sympy.Symbol]
) -> tuple[StepPrinter, sympy.Expr]:
    """The printer for ``mode`` (see :data:`derive.steps.model.Mode`) and ``expr`` made ready for it."""
    if mode == "symbolic":
        return StepPrinter(cancel=cancel, digits=style.digits, extra=extra, labels=style.labels), expr
    if mode == "values":
        return _values_printer(expr, style, extra, cancel), expr
    if mode in ("numeric", "result") and _letters(expr, style):
        return _in_letters(expr, mode, style, extra, cancel)
    if mode == "numeric":
        return _numeric_printer(style, extra, cancel), floatify(substitute(expr, style.values))
    if mode == "result":
        return _result(expr, style, cancel)
    raise ValueError(mode)


def _values_printer(expr: sympy.Expr, style: Style, extra: int, cancel: frozenset[sympy.Symbol]) -> StepPrinter:
    """A substitution line: each given's number in place of its symbol; in a line that keeps
    letters, with no decimal data in it, a fraction no decimal writes exactly as a fraction
    (2/3 (2u - 0), not 0.6667 (2u - 0): one precision per line, a symbolic page stays exact)."""
    vals = values_map(style, style.digits, extra, expr.free_symbols)
    if _letters(expr, style) and not expr.free_symbols & style.decimal:
        for s in expr.free_symbols & set(style.values):
            v = style.values[s]
            if s not in style.angles and v.is_Rational and v.q <= 12 and not short_decimal(v):
                vals[s] = ("-" if v < 0 else "") + rf"\frac{{{abs(v.p)}}}{{{v.q}}}"
    return StepPrinter(vals, cancel, style.digits, extra, decimal_rationals=True, labels=style.labels)


def _in_letters(
    expr: sympy.Expr, mode: str, style: Style, extra: int, cancel: frozenset[sympy.Symbol]
) -> tuple[StepPrinter, sympy.Expr]:
    """A numeric or result line where letters remain: numbers exact where the data are
    (u (1 - 2e)/3), decimals where the data are decimal (0.6 u), never 1.000 e."""
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
    expr = _longer_than_digits(expr.xreplace(long), style.digits, extra)
    if decimal:
        expr = _one_kind_of_coefficient(expr)
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


def _mixed(e: sympy.Basic) -> bool:
    """A sum whose coefficients would print some as decimals, some as fractions (3u/2 - 3.5 e u)."""
    if not isinstance(e, sympy.Add):
        return False
    printer = StepPrinter(fractions=True)
    coeffs = [t.as_coeff_Mul()[0] for t in e.args] if e.free_symbols else []
    short = [c for c in coeffs if c.is_Rational and not c.is_Integer and short_decimal(c)]
    return any(printer._as_decimal(c) for c in short) and not all(printer._as_decimal(c) for c in short)


def _one_kind_of_coefficient(expr: sympy.Expr) -> sympy.Expr:
    """A sum whose coefficients print some as decimals and some as fractions (3u/2 - 3.5 e u)
    with every short one a decimal (1.5 u - 3.5 e u): one precision per line."""
    mixed = _mixed

    def decimals(e: sympy.Add) -> sympy.Expr:
        out = []
        for t in e.args:
            c, rest = t.as_coeff_Mul()
            if c.is_Rational and not c.is_Integer and short_decimal(c):
                t = sympy.Mul(sympy.Float(c, PRECISION), rest, evaluate=False)
            out.append(t)
        return sympy.Add(*out, evaluate=False)

    return expr.replace(mixed, decimals)


def _longer_than_digits(expr: sympy.Expr, digits: int | None, extra: int) -> sympy.Expr:
    """At a set number of figures, an exact number whose whole numbers show more (755/8, √105/35
    at one figure) as a decimal, which then prints at the line's figures: one precision per line."""
    if digits is None:
        return expr
    allowed = digits + extra

    def long(x: sympy.Expr) -> bool:
        whole = [abs(x.p), x.q] if x.is_Rational else []
        return any(len(str(w).rstrip("0")) > allowed for w in whole)

    swap: dict[sympy.Expr, sympy.Expr] = {}
    for p in expr.atoms(sympy.Pow):
        if p.is_number and not p.exp.is_Integer and any(long(a) for a in p.atoms(sympy.Rational)):
            swap[p] = sympy.Float(p.evalf(PRECISION), PRECISION)
    expr = expr.xreplace(swap)
    swap = {r: sympy.Float(r, PRECISION) for r in expr.atoms(sympy.Rational) if long(r)}
    return expr.xreplace(swap)


def _numeric_printer(style: Style, extra: int, cancel: frozenset[sympy.Symbol]) -> StepPrinter:
    """An intermediate line in numbers: intermediates' figures, the block's places after the point."""
    return StepPrinter(
        cancel=cancel,
        digits=style.digits,
        extra=extra,
        decimals=style.decimals,
        decimal_rationals=True,
        labels=style.labels,
        data=_data_integers(style),
    )


def _data_integers(style: Style) -> frozenset[sympy.Expr]:
    """The whole numbers of the data (a mass of 150000 kg), which a line shows as given."""
    whole = [v for v in style.values.values() if isinstance(v, sympy.Expr) and v.is_Integer]
    return frozenset(whole) | frozenset(-v for v in whole)


def _result(expr: sympy.Expr, style: Style, cancel: frozenset[sympy.Symbol]) -> tuple[StepPrinter, sympy.Expr]:
    """A result line: one number at the answer's figures."""
    expr = substitute(expr, style.values)
    if expr.is_number and not isinstance(expr, sympy.UnevaluatedExpr):
        expr = sympy.Float(expr.evalf(PRECISION), PRECISION)
    printer = StepPrinter(cancel=cancel, digits=style.digits, extra=0, round_integers=True, labels=style.labels)
    return printer, floatify(expr, keep_integers=False)


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
    its numbers are in; unknowns alone (v_A2) do not count."""
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
    if isinstance(ready, sympy.Add):
        return printer.add_terms(ready)
    return [("+", printer.doprint(ready))]


def side_terms(side: Side, style: Style, extra: int, cancel: frozenset[sympy.Symbol]) -> list[tuple[str, str]]:
    """A side of an equation as its printed terms with their signs, in order; a side
    of one term that is a sum gives that sum's terms."""
    out: list[tuple[str, str]] = []
    for i, term in enumerate(_one_kind_of_number(side, style)):
        if side.mode in ("numeric", "result") and not _letters(term, style):
            term = substitute(term, style.values)
            collapse = side.mode == "result" and not isinstance(term, sympy.UnevaluatedExpr)
            if term.is_number and (collapse or not structural(term)):
                term = floatify(term, keep_integers=side.mode == "numeric")
                if term == 0:
                    term = sympy.Integer(0)
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


def _one_kind_of_number(side: Side, style: Style) -> tuple[sympy.Expr, ...]:
    """A numeric side's terms, each coefficient a decimal where one of them is: 0.7071 v_A1 +
    0.6364 v_A1, not (√2/2) v_A1 + 0.6364 v_A1 (one precision per line); 0.293 U ê_t − 0.717 U ê_n,
    not √105/35 U ê_t − 0.717 U ê_n, where a nested radical's parts are joined as a decimal."""
    terms = side.terms
    if side.mode not in ("numeric", "result") or len(terms) < 2:
        return terms
    subbed = [substitute(t, style.values) for t in terms]
    # a decimal already, or the parts of a nested radical joined as one (-0.717 U ê_n beside √105/35 U ê_t)
    decimals = [t.atoms(sympy.Float) or _one_term_per_letters(t).atoms(sympy.Float) for t in subbed]
    if not any(t.free_symbols and (d or t.free_symbols & style.decimal) for t, d in zip(subbed, decimals, strict=True)):
        return terms
    out = []
    for t in terms:
        coeff, rest = t.as_independent(*t.free_symbols, as_Add=False) if t.free_symbols else (t, sympy.Integer(1))
        if coeff.is_number and not coeff.is_Rational and rest.free_symbols:
            t = sympy.Float(coeff.evalf(PRECISION), PRECISION) * rest
        out.append(t)
    return tuple(out)


def latex_inline(expr: sympy.Basic, style: Style) -> str:
    """Inline mathematics in a sentence."""
    if isinstance(expr, sympy.Interval):
        lo = "(" if expr.left_open else "["
        hi = ")" if expr.right_open else "]"
        p = StepPrinter(digits=style.digits, labels=style.labels)
        return rf"\left{lo}{p.doprint(expr.start)}, {p.doprint(expr.end)}\right{hi}"
    # a sum of exact data in fractions (3/2 - 7e/2 < 0), not half in decimals (3/2 - 3.5e)
    exact = not style.decimal and isinstance(expr, sympy.Basic) and any(expr.atoms(sympy.Add)) and expr.find(_mixed)
    printer = StepPrinter(digits=style.digits, decimal_rationals=not exact, fractions=True, labels=style.labels)
    if isinstance(expr, sympy.Eq):
        return printer.doprint(expr.lhs) + " = " + printer.doprint(expr.rhs)
    return printer.doprint(expr)
