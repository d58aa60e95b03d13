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
            terms.append(_simplified(c) * u)
    const = _simplified(-(expr - sum(terms)))
    if len(terms) == 1 and terms[0].could_extract_minus_sign():
        return (-terms[0],), (-const,)  # v_A2n = -4.8, not -v_A2n = 4.8
    return tuple(terms) or (sympy.Integer(0),), (const,)


def _simplified(expr: sympy.Expr) -> sympy.Expr:
    """``sympy.simplify(expr)``, skipped for a number it returns as it is (:func:`_plain`):
    the first ``simplify`` of a process imports sympy.physics.units, about 0.2 s."""
    return expr if _plain(expr) else sympy.simplify(expr)


def _plain(expr: sympy.Expr) -> bool:
    """True for a number already in its simplest form: a rational, k sqrt(n), k cos(q pi)
    or k sin(q pi) with k rational and 0 < q <= 1/4 (an angle up to 45°: beyond it,
    ``simplify`` may write cos(15 pi/32) as sin(pi/32)), or a rational plus one k sqrt(n)
    (tests/test_algebra.py)."""
    if expr.is_Rational:
        return True
    if expr.is_Add:
        parts = [a for a in expr.args if not a.is_Rational]
        return len(expr.args) - len(parts) == 1 and len(parts) == 1 and _root(parts[0])
    return _root(expr) or _trig(expr)


def _factors(expr: sympy.Expr) -> list[sympy.Expr] | None:
    """The factors of ``expr`` other than its one rational coefficient (None when it has more)."""
    args = list(expr.args) if expr.is_Mul else [expr]
    rest = [a for a in args if not a.is_Rational]
    return rest if len(args) - len(rest) <= 1 and len(rest) == 1 else None


def _root(expr: sympy.Expr) -> bool:
    """k sqrt(n), k rational, n a whole number."""
    rest = _factors(expr)
    return rest is not None and rest[0].is_Pow and rest[0].base.is_Integer and rest[0].exp == sympy.Rational(1, 2)


def _trig(expr: sympy.Expr) -> bool:
    """k cos(q pi) or k sin(q pi), k rational, 0 < q <= 1/4."""
    rest = _factors(expr)
    if rest is None or not isinstance(rest[0], (sympy.cos, sympy.sin)):
        return False
    arg = rest[0].args[0]
    q = arg.args[0] if arg.is_Mul and len(arg.args) == 2 and arg.args[1] is sympy.pi else None
    return q is not None and q.is_Rational and 0 < q <= sympy.Rational(1, 4)


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


#: Values for the letters left in an equation when a root is checked: positive (a letter is a
#: mass, a speed, a length) and unrelated to each other and to a file's numbers.
_GENERIC = tuple(sympy.Rational(n, 97) for n in (131, 173, 229, 283, 331, 389, 443, 499))


def satisfies(system: list[sympy.Expr], root: dict[sympy.Symbol, sympy.Expr]) -> bool:
    """Whether ``root`` solves ``system`` (expressions equal to zero), as SymPy's own check
    decides it, with a numeric test first that spares that check's simplifying (seconds for
    an unknown angle among letters) wherever a root passes: each residual, any letter left at
    a generic value, is zero to 30 digits."""
    for eq in system:
        expr = eq.xreplace(root)
        letters = sorted(expr.free_symbols, key=lambda s: s.name)
        if len(letters) <= len(_GENERIC):
            expr = expr.xreplace(dict(zip(letters, _GENERIC, strict=False)))
        if expr.free_symbols or not _nearly_zero(expr):
            return sympy.checksol(eq, root) is not False
    return True


def _nearly_zero(expr: sympy.Expr) -> bool:
    """True when ``expr``, a number, is zero to 30 digits relative to its largest term (False
    where it is not a plain number: the caller then asks SymPy)."""
    try:
        terms = [complex(sympy.N(t, 30)) for t in sympy.Add.make_args(expr)]
        total = complex(sympy.N(expr, 30))
    except (TypeError, ValueError):  # AccumBounds and the like: not a number
        return False
    if any(not (abs(t) < float("inf")) for t in [*terms, total]):  # zoo, nan: a zero denominator
        return False
    return abs(total) <= 1e-20 * max(1.0, *(abs(t) for t in terms))
