"""Closed forms written as the notes write them: ``(1 - e)``, not ``-(e - 1)``; no
``|sin θ₁|`` where the sign of sin θ₁ is known; no fraction inside a fraction.

Each rewrite keeps the value: only how the expression is built for printing changes.
"""

from __future__ import annotations

import itertools
from collections.abc import Collection, Mapping

import sympy


def notes_form(
    expr: sympy.Expr, numeric: Mapping[sympy.Symbol, sympy.Expr], acute: Collection[sympy.Symbol] = ()
) -> sympy.Expr:
    """``expr`` in the notes' style; ``numeric`` the givens' numbers and ``acute`` the angles
    assumed acute (they decide signs: |cos α| is cos α for an acute α)."""
    if not isinstance(expr, sympy.Expr) or expr.is_number:
        return expr
    expr = _known_signs(expr, numeric, acute)
    expr = _flat(expr)
    expr = expr.replace(_even_power_of_minus, lambda p: sympy.Pow(_flipped(p.base), p.exp, evaluate=False))
    if isinstance(expr, sympy.Add):
        return sympy.Add(*(_one_minus(t) for t in expr.args), evaluate=False)
    return _one_minus(expr)


def _known_signs(
    expr: sympy.Expr, numeric: Mapping[sympy.Symbol, sympy.Expr], acute: Collection[sympy.Symbol] = ()
) -> sympy.Expr:
    """|x| as x (or -x) where the numbers of the givens decide the sign of x (|sin θ₁| at 45°),
    or the assumption that an angle is acute does (|cos α|: an acute α is atan(t), t > 0)."""
    inside = {a: sympy.atan(sympy.Dummy(positive=True)) for a in acute if a not in numeric}

    def resolved(a: sympy.Abs) -> sympy.Expr:
        inner = a.args[0]
        value = inner.xreplace(dict(numeric))
        if inside and not value.is_number:
            value = sympy.simplify(value.xreplace(inside))
        if value.is_positive or (value.is_number and value.evalf() > 0):
            return inner
        if value.is_negative or (value.is_number and value.evalf() < 0):
            return -inner
        return a

    return expr.replace(lambda x: isinstance(x, sympy.Abs), resolved)


def _fractional_sum(f: sympy.Expr) -> bool:
    """A sum with a fraction among its terms, or a power of one: (v² + v² (1 - e)²/4), (1/2 - 1/e)²."""
    base = f.base if isinstance(f, sympy.Pow) and f.exp.is_Integer and f.exp > 0 else f
    return isinstance(base, sympy.Add) and any(t.as_numer_denom()[1] != 1 for t in base.args)


def _flat(expr: sympy.Expr) -> sympy.Expr:
    """A fraction whose numerator holds a sum of fractions, over one denominator:
    m (v² cos²θ + v² sin²θ (1 - e)²/4)/2 as m (4 v² cos²θ + v² sin²θ (1 - e)²)/8;
    3 m v² (1/2 - 1/e)²/2 as 3 m v² (e - 2)²/(8 e²)."""
    if isinstance(expr, sympy.Add):
        return sympy.Add(*(_flat(t) for t in expr.args))
    if not isinstance(expr, sympy.Mul):
        return expr
    factors = expr.args
    over = any((f.is_Rational and f.q != 1) or (f.is_Pow and f.exp.is_negative) for f in factors)
    nested = any(_fractional_sum(f) for f in factors)
    return sympy.together(expr) if nested and over else expr


def _even_power_of_minus(x: sympy.Basic) -> bool:
    """(e - 1)^2: an even power of a sum whose number is negative."""
    return (
        isinstance(x, sympy.Pow)
        and x.exp.is_even
        and isinstance(x.base, sympy.Add)
        and any(t.is_number and t.is_negative for t in x.base.args)
    )


def _flipped(f: sympy.Add) -> sympy.Expr:
    """-f with its number first: 1 - e for e - 1."""
    terms = sorted((-t for t in f.args), key=lambda t: not t.is_number)
    return sympy.Add(*terms, evaluate=False)


def _minuses(f: sympy.Add) -> float:
    """How a sum reads against the notes' style: a term with a minus counts one, a number
    with a minus half more (e - 1 reads worse than 1 - e)."""
    return sum(1 + 0.5 * bool(t.is_number) for t in f.args if t.could_extract_minus_sign())


def _one_minus(term: sympy.Expr) -> sympy.Expr:
    """-c x (e - 1) as c x (1 - e), -√3 (e + 1)/(3e - 5) as √3 (e + 1)/(5 - 3e),
    (-kλ - 1)/(k (λ - 1)) as (kλ + 1)/(k (1 - λ)): each sum, in the numerator or the
    denominator, taken with the sign that reads best, the minus in front only where it must."""
    if not isinstance(term, sympy.Mul):
        return term
    sums = [i for i, f in enumerate(term.args) if isinstance(_base(f), sympy.Add)]
    if not sums or len(sums) > 6:
        return term
    best, best_cost = None, _cost(term.args, term.could_extract_minus_sign())
    for flips in itertools.product((False, True), repeat=len(sums)):
        if not any(flips):
            continue
        factors, sign = list(term.args), 1
        for i, flip in zip(sums, flips, strict=True):
            if flip:
                base, exp = _base(factors[i]), _exp(factors[i])
                factors[i] = sympy.Pow(_flipped(base), exp, evaluate=False) if exp != 1 else _flipped(base)
                sign *= -1 if exp % 2 else 1
        rest = [f for i, f in enumerate(factors) if i not in sums]
        coeff = sign * sympy.Mul(*rest)
        cost = _cost(factors, coeff.could_extract_minus_sign())
        if cost < best_cost:
            kept = [factors[i] for i in sums]
            best, best_cost = sympy.Mul(*sympy.Mul.make_args(coeff), *kept, evaluate=False), cost
    return term if best is None else best


def _base(f: sympy.Expr) -> sympy.Expr:
    return f.base if isinstance(f, sympy.Pow) and f.exp.is_Integer else f


def _exp(f: sympy.Expr) -> int:
    return int(f.exp) if isinstance(f, sympy.Pow) and f.exp.is_Integer else 1


def _cost(factors: tuple | list, minus: bool) -> float:
    return sum(_minuses(_base(f)) for f in factors if isinstance(_base(f), sympy.Add)) + 2 * minus
