"""Numbers as a textbook prints them: significant figures, rounded half up.

The default is the textbook rule: three significant figures, four when the
leading digit is 1 (1.109 but 8.40). A problem or a run may set a fixed number
of figures instead. Trailing zeros are kept (8.40, not 8.4).
"""

from __future__ import annotations

from decimal import ROUND_FLOOR, ROUND_HALF_UP, Context, Decimal

import sympy

#: Digits carried when an exact SymPy number is turned into a Decimal.
WORKING_PRECISION = 40


def to_decimal(value: sympy.Expr | int | float | str | Decimal) -> Decimal:
    """The exact or numeric ``value`` as a Decimal carrying 40 significant digits."""
    if isinstance(value, Decimal):
        return value
    if isinstance(value, (int, str)):
        return Decimal(value)
    expr = sympy.sympify(value)
    if not expr.is_number:
        raise ValueError(f"{expr} is not a number")
    num = expr.evalf(WORKING_PRECISION)
    if not num.is_real:
        raise ValueError(f"{expr} is not a real number")
    text = sympy.Float(num, WORKING_PRECISION).__format__(".39e") if num != 0 else "0"
    return Decimal(text)


#: The context numbers are rounded in: the default one, carrying more digits than any
#: number here (made once: a variant's page rounds hundreds of numbers).
_ROUNDING = Context(prec=WORKING_PRECISION + 10)
#: 1 and 2 times the powers of ten met most (a quantum to round to, the bound of a leading 1).
_ONES = {e: Decimal((0, (1,), e)) for e in range(-60, 61)}
_TWOS = {e: Decimal((0, (2,), e)) for e in range(-60, 61)}


def _round_sig(d: Decimal, figures: int) -> Decimal:
    """``d`` rounded half up to ``figures`` significant figures."""
    if d == 0:
        return Decimal(0).quantize(Decimal(1).scaleb(-(figures - 1)))
    adjusted = d.adjusted()
    exp = adjusted - figures + 1
    r = d.quantize(_ONES.get(exp) or Decimal((0, (1,), exp)), ROUND_HALF_UP, _ROUNDING)
    if r.adjusted() != adjusted:  # 9.995 -> 10.0: one figure fewer after the point
        exp += 1
        r = r.quantize(_ONES.get(exp) or Decimal((0, (1,), exp)), ROUND_HALF_UP, _ROUNDING)
    return r


def figures_for(value: Decimal, digits: int | None) -> int:
    """How many significant figures ``value`` is shown with.

    ``digits`` None means the textbook rule (3, or 4 when the leading digit is 1).
    """
    if digits is not None:
        return digits
    if value == 0:
        return 3
    if value.is_finite():  # the leading digit of |value| (at the context's precision) is 1
        a = abs(value)
        adjusted = a.adjusted()
        return 4 if a < (_TWOS.get(adjusted) or Decimal((0, (2,), adjusted))) else 3
    leading = abs(value).scaleb(-abs(value).adjusted()).to_integral_value(rounding=ROUND_FLOOR)
    return 4 if leading == 1 else 3


def float_decimal(x: object) -> Decimal:
    """A float computed from rounded data, to 12 significant figures: its binary noise gone,
    so that 53.15 rounds half up to 53.2, not as 53.149999999999995 to 53.1."""
    return Decimal(f"{float(x):.12g}")


def format_number(value: sympy.Expr | Decimal | int | str, digits: int | None = None, *, extra: int = 0) -> str:
    """``value`` as text at ``digits`` (+``extra`` for intermediates) significant figures.

    Plain notation between 1e-4 and 1e6, else ``1.23e+7``; never ``-0``.

    >>> format_number(8.4, 3)
    '8.40'
    >>> format_number(-1.1094)
    '-1.109'
    """
    d = to_decimal(value)
    if d == 0:
        return "0"
    r = _round_sig(d, figures_for(d, digits) + extra)
    if -4 <= r.adjusted() < 6:
        text = format(r, "f")
    else:
        mantissa = r.scaleb(-r.adjusted())
        text = f"{format(mantissa, 'f')}e{r.adjusted():+d}"
    return text


#: The contexts :func:`format_fixed` rounds in, by precision.
_FIXED: dict[int, Context] = {}


def format_fixed(value: sympy.Expr | Decimal, decimals: int) -> str:
    """``value`` rounded half up to ``decimals`` places after the point."""
    return format(_fixed(value, decimals), "f")


def _fixed(value: sympy.Expr | Decimal, decimals: int) -> Decimal:
    """:func:`format_fixed`'s number, not yet written out."""
    d = to_decimal(value)
    prec = max(WORKING_PRECISION, d.adjusted() + decimals + 5)  # enough digits for numbers far apart in size
    ctx = _FIXED.get(prec)
    if ctx is None:
        ctx = Context(prec=prec)
        if len(_FIXED) < 64:
            _FIXED[prec] = ctx
    r = d.quantize(_ONES.get(-decimals) or Decimal((0, (1,), -decimals)), ROUND_HALF_UP, ctx)
    if r == 0:
        r = abs(r)
    return r


def shown_figures(text: str) -> int:
    """Significant figures a number written as ``text`` shows (trailing zeros count:
    4.500 shows four, 0.0270 three)."""
    return len(Decimal(text).as_tuple().digits)


def format_places(value: sympy.Expr | Decimal, decimals: int, digits: int | None, extra: int) -> str:
    """``value`` at ``decimals`` places after the point (the places a block's sums share),
    unless that shows more figures than the rule lets the number show (-121.22 where an
    intermediate shows four): then at the rule's figures (-121.2); nor rounded coarser than
    the answer's figures round it (at one figure, a coefficient 0.47 or a denominator 0.78 in
    a block of sums at no places after the point prints 0.5 and 0.8, not 0 and 1)."""
    fixed = format_fixed(value, decimals)
    ruled = format_number(value, digits, extra=extra)
    if _significant(fixed) > _significant(ruled):
        return ruled  # 190, not 188, where an intermediate shows two figures
    d = to_decimal(value)
    if d != 0 and d.is_finite() and decimals < _places_shown(d, digits, extra)[1]:
        return format_number(value, digits)  # not coarser than the answer's rounding (0.5, not 0)
    return fixed


def _significant(text: str) -> int:
    """Significant figures of a number written as ``text``, the trailing zeros of a whole
    number not counted (190 shows two, 190.0 four)."""
    if "." in text or "e" in text:
        return shown_figures(text)
    return len(text.lstrip("-").rstrip("0")) or 1


def decimals_of(text: str) -> int:
    """Places after the point in a plain-notation number string."""
    return len(text.split(".")[1]) if "." in text else 0


def places_that_add_up(
    sums: list[tuple[list[Decimal], Decimal]], digits: int | None, extra: int, *, each: bool = False
) -> int | None:
    """Places after the point for a line of sums shown term by term (79.23 - 59.42 =
    19.81): the largest number's figures to start with (with ``each``, the figures of
    every number), or one more while the rounded terms do not add up to the
    rounded total. None when no such places exist: the numbers
    are too far apart in size for fixed places, or need more figures than the rule."""
    numbers = [x for terms, total in sums for x in (*terms, total)]
    if any(x != 0 and not -4 <= x.adjusted() < 6 for x in numbers):
        return None
    biggest = max((abs(x) for x in numbers), default=Decimal(0))
    text = format_number(biggest, digits, extra=extra) if biggest else ""
    start = decimals_of(text) if text and "e" not in text else 2
    shown = [_places_shown(x, digits, extra) for x in numbers if x != 0]  # (at +extra, at the rule)
    ruled = [at_extra for at_extra, _ in shown]
    if each:  # every number keeps its figures (21.60 - 14.69 = 6.91), the smallest deciding
        start = max(ruled, default=start)
    # no number may show more figures than an intermediate may (290.0185 in a 5-figure
    # solution), nor fewer than the answer's (0.00 for 0.0042)
    most = min(ruled, default=start)
    least = max((at_rule for _, at_rule in shown), default=start)
    start = max(start, least)
    for places in range(start, start + 2):
        if places > most:
            break
        # the rounded numbers as the text :func:`format_fixed` writes them reads back
        if all(sum(_fixed(t, places) for t in terms) == _fixed(total, places) for terms, total in sums):
            return places
    return None


def _places_shown(x: Decimal, digits: int | None, extra: int) -> tuple[int, int]:
    """``decimals_of(format_number(x, digits, extra=k))`` for k = ``extra`` and 0, x not 0,
    read off the rounding (its exponent) where the text would be plain notation."""
    if not x.is_finite():
        return decimals_of(format_number(x, digits, extra=extra)), decimals_of(format_number(x, digits))
    figures = figures_for(x, digits)
    out = []
    adjusted = x.adjusted()
    for k in (extra, 0):
        exp = adjusted - (figures + k) + 1  # as _round_sig rounds
        r = x.quantize(_ONES.get(exp) or Decimal((0, (1,), exp)), ROUND_HALF_UP, _ROUNDING)
        if r.adjusted() != adjusted:
            exp += 1
            r = r.quantize(_ONES.get(exp) or Decimal((0, (1,), exp)), ROUND_HALF_UP, _ROUNDING)
        if -4 <= r.adjusted() < 6:  # format(r, "f"): -exp places after the point
            out.append(-exp if exp < 0 else 0)
        else:
            out.append(decimals_of(format_number(x, digits, extra=k)))
    return out[0], out[1]


def terminates(value: sympy.Expr) -> bool:
    """True for a rational number whose decimal form ends (its denominator has no prime but 2 and 5)."""
    if not value.is_Rational:
        return False
    q = value.q
    for f in (2, 5):
        while q % f == 0:
            q //= f
    return q == 1


def short_decimal(value: sympy.Expr) -> bool:
    """True for an exact number with a short decimal form (0.2, 12.5, 1.67e-27): printed as written."""
    return terminates(value) and len(abs(to_decimal(value)).normalize().as_tuple().digits) <= 6


def as_written(value: sympy.Expr | Decimal) -> str:
    """An exact short decimal as a textbook writes it: plain between 1e-4 and 1e6
    (0.6, 12.5, 20), else with a power of ten (``1.67e-27``, ``2e+6``).

    >>> as_written(sympy.Rational(167, 10**29))
    '1.67e-27'
    >>> as_written(sympy.Integer(2000000))
    '2e+6'
    """
    d = (value if isinstance(value, Decimal) else to_decimal(value)).normalize()
    if d == 0:
        return "0"
    if -4 <= d.adjusted() < 6:
        return format(d, "f")
    return f"{format(d.scaleb(-d.adjusted()), 'f')}e{d.adjusted():+d}"


def nice(x: sympy.Expr) -> bool:
    """True for a number a textbook writes exactly: a fraction, a surd, pi, and sums
    and products of these (1/3, sqrt(2)/2, pi/4); False for cos 37.6° and the like."""
    if x.is_Rational or x is sympy.pi:
        return True
    if isinstance(x, sympy.Pow):
        return x.base.is_Rational and x.exp.is_Rational and x.exp.q <= 3
    if isinstance(x, (sympy.Mul, sympy.Add)):
        return all(nice(a) for a in x.args)
    return False


def exactify(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` with its letters kept and every number in it exact where a textbook
    writes it so (:func:`nice`), else evaluated: u (1 - 2 e)/3, not 0.333 u (1.000 - 2.00 e).

    >>> u, e = sympy.symbols("u e")
    >>> exactify(u * (1 - 2 * e) / 3)  # a factor of 1/3 kept apart, as the page prints it
    (u*(1 - 2*e))/3
    """
    if isinstance(expr, sympy.UnevaluatedExpr):
        return sympy.UnevaluatedExpr(exactify(expr.args[0]))
    if expr.is_number:
        if structural(expr):  # built to be shown as it stands: (20 + 5)
            return floatify(expr)
        return expr if nice(expr) else sympy.Float(expr.evalf(PRECISION), PRECISION)
    if expr.is_Atom:
        return expr
    if isinstance(expr, sympy.Mul):  # one coefficient: 0.672 v_A1, not 0.475 √2 v_A1
        coeff, rest = expr.as_independent(*expr.free_symbols, as_Add=False)
        if coeff != 1 and not structural(coeff):
            return sympy.Mul(exactify(coeff), exactify(rest), evaluate=False)
    return expr.func(*(exactify(a) for a in expr.args), evaluate=False)


def tidy(x: sympy.Expr) -> sympy.Expr:
    """A Float that is a short decimal to 12 figures (0.05) as that exact number, so it is
    printed as written; other numbers as they are."""
    if isinstance(x, sympy.Float) and x != 0:
        r = sympy.Rational(format(to_decimal(x).normalize().__round__(12 - to_decimal(x).adjusted()), "f"))
        if short_decimal(r):
            return r
    return x


def floatify(expr: sympy.Expr, keep_integers: bool = True) -> sympy.Expr:
    """``expr`` with every numeric part evaluated: one Float coefficient per product.

    Structure (the order of terms, unexpanded products) is kept.
    """
    if isinstance(expr, sympy.UnevaluatedExpr):  # shown as built: (19.81 - 5 · 9.507)/25
        inner = expr.args[0]
        if inner.is_Atom:
            return floatify(inner, keep_integers)
        if isinstance(inner, sympy.Pow):
            return sympy.UnevaluatedExpr(sympy.Pow(floatify(inner.base, keep_integers), inner.exp, evaluate=False))
        kept = [floatify(a, keep_integers) for a in inner.args]
        if isinstance(inner, (sympy.Add, sympy.Mul)):
            return sympy.UnevaluatedExpr(inner.func(*kept, evaluate=False))
        return sympy.UnevaluatedExpr(inner.func(*kept, evaluate=False))
    if expr.is_Integer and keep_integers:
        return expr
    if expr.is_Number:
        if keep_integers and short_decimal(expr):
            return expr  # a given as written (0.2 kg), not 0.2000
        return sympy.Float(expr, PRECISION)
    if structural(expr):
        # built unevaluated on purpose, as in (20 + 5) v_A2n: keep it so
        if isinstance(expr, sympy.Pow):
            return sympy.Pow(floatify(expr.base, keep_integers), expr.exp, evaluate=False)
        return expr.func(*(floatify(a, keep_integers) for a in expr.args), evaluate=False)
    if expr.is_number:
        exact = expr.doit()
        if exact.is_Integer and keep_integers:
            return exact
        return sympy.Float(expr.evalf(PRECISION), PRECISION)
    if expr.is_Atom:
        return expr
    if isinstance(expr, sympy.Pow):
        return sympy.Pow(floatify(expr.base, keep_integers), expr.exp, evaluate=False)
    args = [floatify(a, keep_integers) for a in expr.args]
    if isinstance(expr, sympy.Mul):
        nums = [a for a in args if a.is_Number]
        rest = [a for a in args if not a.is_Number]
        coeff: sympy.Expr = sympy.Integer(1)
        for n in nums:
            coeff = coeff * n
        if isinstance(coeff, sympy.Rational) and not coeff.is_Integer and not (keep_integers and short_decimal(coeff)):
            coeff = sympy.Float(coeff, PRECISION)
        if not rest:
            return coeff
        if coeff == 1:
            return rest[0] if len(rest) == 1 else sympy.Mul(*rest, evaluate=False)
        return sympy.Mul(coeff, *rest, evaluate=False)
    return expr.func(*args, evaluate=False)


PRECISION = 30


def structural(expr: sympy.Expr) -> bool:
    """True for a sum, product, power or function of numbers that was built unevaluated
    to be shown as it stands (19.81 - 5 · 9.507), not an exact value such as sqrt(2)/2."""
    if not expr.is_number or expr.is_Number or expr.is_NumberSymbol:
        return False
    parts = expr.args

    def ok(a: sympy.Expr) -> bool:
        return isinstance(a, sympy.Float) or a.is_Rational or structural(a)

    if isinstance(expr, sympy.Pow):
        return ok(parts[0]) and (parts[1].is_Integer or not parts[0].is_Rational) and parts[1].is_Number
    if isinstance(expr, sympy.Function) and not isinstance(expr, sympy.Abs):
        return all(ok(a) for a in parts) and not all(a.is_Rational and not short_decimal(a) for a in parts)
    if isinstance(expr, (sympy.Add, sympy.Mul)):
        # SymPy merges the numbers of an evaluated sum or product into one: two
        # numbers side by side mean it was built unevaluated, to be shown so.
        numbers = sum(1 for a in parts if a.is_Number)
        return all(ok(a) for a in parts) and (
            numbers >= 2 or any(isinstance(a, sympy.Float) or structural(a) for a in parts)
        )
    return False
