"""Closed forms written as the notes write them: ``(1 - e)``, not ``-(e - 1)``; no
``|sin θ₁|`` where the sign of sin θ₁ is known; no fraction inside a fraction.

Each rewrite keeps the value: only how the expression is built for printing changes.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy


def notes_form(expr: sympy.Expr, numeric: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``expr`` in the notes' style; ``numeric`` the givens' numbers (they decide signs)."""
    if not isinstance(expr, sympy.Expr) or expr.is_number:
        return expr
    expr = _known_signs(expr, numeric)
    expr = _flat(expr)
    expr = expr.replace(_even_power_of_minus, lambda p: sympy.Pow(_flipped(p.base), p.exp, evaluate=False))
    if isinstance(expr, sympy.Add):
        return sympy.Add(*(_one_minus(t) for t in expr.args), evaluate=False)
    return _one_minus(expr)


def _known_signs(expr: sympy.Expr, numeric: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """|x| as x (or -x) where the numbers of the givens decide the sign of x (|sin θ₁| at 45°)."""

    def resolved(a: sympy.Abs) -> sympy.Expr:
        inner = a.args[0]
        value = inner.xreplace(dict(numeric))
        if value.is_positive or (value.is_number and value.evalf() > 0):
            return inner
        if value.is_negative or (value.is_number and value.evalf() < 0):
            return -inner
        return a

    return expr.replace(lambda x: isinstance(x, sympy.Abs), resolved)


def _flat(expr: sympy.Expr) -> sympy.Expr:
    """A fraction whose numerator holds a sum of fractions, over one denominator:
    m (v² cos²θ + v² sin²θ (1 - e)²/4)/2 as m (4 v² cos²θ + v² sin²θ (1 - e)²)/8."""
    if isinstance(expr, sympy.Add):
        return sympy.Add(*(_flat(t) for t in expr.args))
    if not isinstance(expr, sympy.Mul):
        return expr
    factors = expr.args
    over = any((f.is_Rational and f.q != 1) or (f.is_Pow and f.exp.is_negative) for f in factors)
    nested = any(isinstance(f, sympy.Add) and any(t.as_numer_denom()[1] != 1 for t in f.args) for f in factors)
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


def _one_minus(term: sympy.Expr) -> sympy.Expr:
    """-c x (e - 1) as c x (1 - e): the minus sign taken into the factor (e - 1)."""
    if not isinstance(term, sympy.Mul) or not term.could_extract_minus_sign():
        return term
    factors = list(term.args)
    for i, f in enumerate(factors):
        if isinstance(f, sympy.Add) and any(t.is_number and t.is_negative for t in f.args):
            rest = sympy.Mul(*factors[:i], *factors[i + 1 :])
            return sympy.Mul(-rest, _flipped(f), evaluate=False)
    return term
