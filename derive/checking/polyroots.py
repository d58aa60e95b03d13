"""The roots of a small polynomial system with numeric coefficients, in floating point.

A derivation's equations at a sample point are polynomials of low degree in the unknowns:
momentum and restitution are linear in the velocities (``e u`` and ``m_B v_B2`` are products
where ``e`` or ``m_B`` is unknown), an energy condition is quadratic. SymPy's ``solve`` finds
their roots with a Gröbner basis over its floating-point field, which takes from a tenth of a
second to minutes for three equations (a check solves them hundreds of times). Here an unknown
that enters one equation alone and linearly is eliminated from the others, then an equation in
one unknown is solved (a quadratic by its formula, a higher degree by mpmath), and each branch
goes on with the rest. A system this cannot take apart gives None, and the caller asks SymPy.
Every root is put back into the equations it came from and kept only where they hold.
"""

from __future__ import annotations

import cmath

import mpmath
import sympy

#: A polynomial: the exponents of the unknowns -> the coefficient.
Poly = dict[tuple[int, ...], complex]

#: The most steps (eliminations tried, roots branched on) for one system; more: SymPy's.
MAX_STEPS = 200


def polynomial_roots(eqs: list[sympy.Expr], U: tuple[sympy.Symbol, ...]) -> list[dict[sympy.Symbol, complex]] | None:
    """Every root of ``eqs = 0`` in the unknowns ``U`` (each a complex number), [] where there
    is none or no single one (more unknowns than the equations fix), None where the system is
    not one this can take apart (not polynomial, a coefficient not a number, too many roots)."""
    polys = [_poly(e, U) for e in eqs]
    if any(p is None for p in polys):
        return None
    found = _solve([p for p in polys if p], list(range(len(U))), len(U), [0])
    if found is None:
        return None
    return [{u: r[k] for k, u in enumerate(U)} for r in _distinct(found) if all(_holds(p, r) for p in polys if p)]


def _poly(expr: sympy.Expr, U: tuple[sympy.Symbol, ...]) -> Poly | None:
    try:
        poly = sympy.Poly(sympy.expand(sympy.numer(sympy.together(expr))), *U)
    except (sympy.PolynomialError, sympy.GeneratorsError):
        return None
    out: Poly = {}
    for m, c in poly.terms():
        try:
            out[m] = complex(c)
        except TypeError:
            return None
    return _trimmed(out)


def _trimmed(p: Poly) -> Poly:
    """``p`` without the coefficients that are rounding noise beside its largest."""
    big = max((abs(c) for c in p.values()), default=0.0)
    return {m: c for m, c in p.items() if abs(c) > 1e-13 * big}


def _solve(polys: list[Poly], free: list[int], n: int, work: list[int]) -> list[dict[int, complex]] | None:
    """The roots of ``polys`` in the unknowns ``free``: an equation in one unknown solved first,
    else an unknown that one equation gives linearly eliminated (each choice tried in turn
    until one takes the system apart; ``work`` counts the steps, at most :data:`MAX_STEPS`)."""
    polys = [p for p in polys if any(any(m[k] for k in free) for m in p)]  # a constant left: checked at the end
    if not free:
        return [{}]
    if not polys:
        return []  # an unknown no equation fixes: no single root
    work[0] += 1
    if work[0] > MAX_STEPS:
        return None
    for p in polys:
        ks = [k for k in free if any(m[k] for m in p)]
        if len(ks) == 1:
            return _branch(polys, free, n, work, ks[0], _univariate(p, ks[0]))
    for i, k in _linear(polys, free):
        p, unit = polys[i], _unit(k, n)
        q = {m: -x / p[unit] for m, x in p.items() if m != unit}
        rest = _solve(
            [_substitute(r, k, q) for j, r in enumerate(polys) if j != i], [f for f in free if f != k], n, work
        )
        if rest is not None:
            return [{**r, k: _value(q, r)} for r in rest]
    return None


def _branch(
    polys: list[Poly], free: list[int], n: int, work: list[int], k: int, roots: list[complex] | None
) -> list[dict[int, complex]] | None:
    """The roots of ``polys`` with each of ``roots`` put in for the unknown ``k``."""
    if roots is None:
        return None
    work[0] += len(roots)
    out = []
    for x in roots:
        rest = _solve([_substitute(r, k, {(0,) * n: x}) for r in polys], [f for f in free if f != k], n, work)
        if rest is None:
            return None
        out += [{**r, k: x} for r in rest]
    return out


def _unit(k: int, n: int) -> tuple[int, ...]:
    return tuple(int(i == k) for i in range(n))


def _linear(polys: list[Poly], free: list[int]) -> list[tuple[int, int]]:
    """(equation, unknown) where the unknown enters the equation only as itself, to the first
    power (``e u + v_A2 - v_B2``: any of the three; ``m_B v_B2``: neither), the largest
    coefficients for their equation's size first."""
    found = []
    for i, p in enumerate(polys):
        scale = max(abs(c) for c in p.values())
        for k in free:
            with_k = [m for m in p if m[k]]
            if len(with_k) == 1 and sum(with_k[0]) == 1 and abs(p[with_k[0]]) > 1e-9 * scale:
                found.append((-abs(p[with_k[0]]) / scale, i, k))
    return [(i, k) for _, i, k in sorted(found)]


def _substitute(p: Poly, k: int, q: Poly) -> Poly:
    """``p`` with the unknown ``k`` replaced by the polynomial ``q`` (free of ``k``)."""
    out: Poly = {}
    powers: list[Poly] = [{(0,) * len(m): 1.0 + 0j for m in p}]
    for m, c in p.items():
        while len(powers) <= m[k]:
            powers.append(_times(powers[-1], q))
        base = (*m[:k], 0, *m[k + 1 :])
        for mq, cq in powers[m[k]].items():
            key = tuple(a + b for a, b in zip(base, mq, strict=True))
            out[key] = out.get(key, 0) + c * cq
    return _trimmed(out)


def _times(a: Poly, b: Poly) -> Poly:
    out: Poly = {}
    for ma, ca in a.items():
        for mb, cb in b.items():
            key = tuple(x + y for x, y in zip(ma, mb, strict=True))
            out[key] = out.get(key, 0) + ca * cb
    return out


def _value(q: Poly, r: dict[int, complex]) -> complex:
    total = 0j
    for m, c in q.items():
        term = c
        for k, power in enumerate(m):
            if power:
                term *= r[k] ** power
        total += term
    return total


def _univariate(p: Poly, k: int) -> list[complex] | None:
    """The roots of ``p``, a polynomial in the unknown ``k`` alone."""
    degree = max(m[k] for m in p)
    coeffs = [sum(c for m, c in p.items() if m[k] == d) for d in range(degree, -1, -1)]
    while coeffs and abs(coeffs[0]) <= 1e-12 * max(abs(c) for c in coeffs):
        coeffs.pop(0)
    if len(coeffs) <= 1:
        return []
    if len(coeffs) == 2:
        return [-coeffs[1] / coeffs[0]]
    if len(coeffs) == 3:
        a, b, c = coeffs
        d = cmath.sqrt(b * b - 4 * a * c)
        big = -(b + d) / 2 if abs(b + d) >= abs(b - d) else -(b - d) / 2  # no cancellation
        if big == 0:
            return [0j, 0j]
        return [big / a, c / big]
    try:
        return [complex(z) for z in mpmath.polyroots(coeffs, maxsteps=200, extraprec=60)]
    except (mpmath.libmp.NoConvergence, ZeroDivisionError, ValueError):
        return None


def _holds(p: Poly, r: dict[int, complex]) -> bool:
    """Whether the root ``r`` makes ``p`` zero, beside the size of its terms."""
    terms = [_value({m: c}, r) for m, c in p.items()]
    scale = max(abs(t) for t in terms)
    return abs(sum(terms)) <= 1e-8 * scale or scale == 0


def _distinct(roots: list[dict[int, complex]]) -> list[dict[int, complex]]:
    out: list[dict[int, complex]] = []
    for r in roots:
        if not any(all(abs(r[k] - s[k]) <= 1e-9 * max(1.0, abs(s[k])) for k in r) for s in out):
            out.append(r)
    return out
