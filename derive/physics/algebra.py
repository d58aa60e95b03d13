"""Small pieces of algebra the worked steps show: an equation collected into unknown
terms and a constant, and a symbol that every term of a sum shares."""

from __future__ import annotations

import sympy


def collect(
    lhs: sympy.Expr, rhs: sympy.Expr, order: tuple[sympy.Symbol, ...], unknowns: tuple[sympy.Symbol, ...]
) -> tuple[tuple[sympy.Expr, ...], tuple[sympy.Expr, ...]]:
    """``lhs = rhs`` as unknown terms (in ``order``, then the other ``unknowns``) = constant;
    an equation not linear in its unknowns is left as it stands.

    >>> x, y = sympy.symbols("x y")
    >>> collect(2 * x + 3, y + 1, (x, y), ())
    ((2*x, -y), (-2,))
    """
    expr = sympy.expand(lhs - rhs)
    us = [u for u in order if expr.has(u)] + [u for u in unknowns if expr.has(u) and u not in order]
    poly = expr.is_polynomial(*us) if us else False
    if (
        not poly
        or any(sympy.degree(expr, u) > 1 for u in us)
        or any(expr.coeff(u).has(*[w for w in us if w != u]) for u in us)
    ):
        return (lhs,), (rhs,)
    terms = []
    for u in us:
        c = expr.coeff(u)
        if c != 0:
            terms.append(sympy.simplify(c) * u)
    const = sympy.simplify(-(expr - sum(terms)))
    if len(terms) == 1 and terms[0].could_extract_minus_sign():
        return (-terms[0],), (-const,)  # v_A2n = -4.8, not -v_A2n = 4.8
    return tuple(terms) or (sympy.Integer(0),), (const,)


def common_factor(
    terms: tuple[sympy.Expr, ...], numeric: set[sympy.Symbol], unknowns: tuple[sympy.Symbol, ...]
) -> sympy.Symbol | None:
    """A symbolic positive factor (a mass m, as in Example 4.C.12) that every nonzero
    term has to the first power, and so cancels; None when there is none."""
    nonzero = [t for t in terms if t != 0]
    for cand in sorted(set(nonzero[0].free_symbols), key=str) if nonzero else []:
        if cand in numeric or not cand.is_positive or cand in unknowns:
            continue
        if all(
            sympy.cancel(t / cand).free_symbols.isdisjoint({cand}) and (t / cand).is_polynomial(cand) for t in nonzero
        ) and all(sympy.Poly(t, cand).degree() == 1 for t in nonzero):
            return cand
    return None
