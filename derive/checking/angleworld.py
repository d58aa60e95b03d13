"""A world whose unknowns include an angle (an inverse problem: "find α" from a share of the
kinetic energy kept): the student's equations in sin α, cos α and tan α, made polynomial.

The momentum, restitution and energy equations are polynomials in the velocities, but an
unknown angle enters them through its sine and cosine, which neither elimination
(:mod:`.polyroots`) nor a linear solve can take apart, and SymPy's ``solve`` of a trigonometric
system takes seconds. With ``t = tan(α/2)`` (``sin α = 2t/(1 + t²)``, ``cos α = (1 - t²)/(1 + t²)``)
each equation's numerator is a polynomial in ``t`` and the velocities: its roots are found in
milliseconds, and ``α = 2 atan t``. The same substitution gives the coefficients by which a
slip in the angle (``sin²α + 9/16 cos²α = 0.6``, α taken from the other axis) is matched with
the equation it stands for (here the energy's, the one whose terms in sin² and cos² it shares).
"""

from __future__ import annotations

import math

import sympy

from derive.checking.polyroots import polynomial_roots
from derive.checking.relations import Values, coefficients, cosine

_TRIG = (sympy.sin, sympy.cos, sympy.tan)


def angles_in(exprs: list[sympy.Expr], U: tuple[sympy.Symbol, ...]) -> tuple[sympy.Symbol, ...]:
    """The unknowns of ``U`` that some expression of ``exprs`` has inside a sine, cosine or tangent."""
    found: set[sympy.Symbol] = set()
    for x in exprs:
        for f in x.atoms(*_TRIG):
            found |= f.args[0].free_symbols & set(U)
    return tuple(u for u in U if u in found)


def _halves(angles: tuple[sympy.Symbol, ...]) -> dict[sympy.Symbol, sympy.Symbol]:
    return {a: sympy.Symbol(f"_t_{a.name}") for a in angles}


def _in_halves(x: sympy.Expr, half: dict[sympy.Symbol, sympy.Symbol]) -> sympy.Expr | None:
    """``x`` with each angle's sine, cosine and tangent written in ``t = tan(α/2)`` (None where
    an angle is left outside them: ``α = 17°`` alone is not a polynomial in t)."""
    x = sympy.expand_trig(x)
    put: dict[sympy.Expr, sympy.Expr] = {}
    for a, t in half.items():
        s, c = 2 * t / (1 + t**2), (1 - t**2) / (1 + t**2)
        put |= {sympy.sin(a): s, sympy.cos(a): c, sympy.tan(a): s / c}
    y = x.xreplace(put)
    return None if y.free_symbols & set(half) else y


def roots(eqs: list[sympy.Expr], U: tuple[sympy.Symbol, ...]) -> list[Values] | None:
    """The real roots of ``eqs = 0`` (numbers in but the unknowns) where an unknown angle is in
    a sine, cosine or tangent; None where none is, or the system is not one this takes apart."""
    angles = angles_in(eqs, U)
    if not angles:
        return None
    half = _halves(angles)
    ys = []
    for x in eqs:
        y = _in_halves(x, half)
        if y is None:
            return None
        ys.append(y)
    ys, given = _velocities_out(ys, [u for u in U if u not in half])
    polys = [sympy.N(sympy.numer(sympy.together(y)), 30) for y in ys]
    V = tuple(half.get(u, u) for u in U if u not in given)
    found = polynomial_roots(polys, V)
    if found is None:
        return None
    out = []
    for r in found:
        for u, x in reversed(given.items()):  # the velocities each equation gave in t, in turn
            z = sympy.N(x.xreplace(r), 30)
            r[u] = complex(z) if z.is_number and z.is_finite else complex("nan")
        if any(z != z or abs(z.imag) > 1e-9 * max(1.0, abs(z)) for z in r.values()):
            continue  # a complex root: no angle, no velocity
        out.append({u: sympy.Float(2 * math.atan(r[half[u]].real) if u in half else r[u].real, 20) for u in U})
    return out


def _velocities_out(
    ys: list[sympy.Expr], velocities: list[sympy.Symbol]
) -> tuple[list[sympy.Expr], dict[sympy.Symbol, sympy.Expr]]:
    """The equations (in ``t = tan(α/2)``) with each velocity that one of them gives to the first
    power (``(1 + t²) v_t = ¾U(1 - t²)``) put into the others as that fraction in t, the common
    factors cancelled: their numerators taken at once would carry ``1 + t²`` as roots many times
    over, where a polynomial's roots are not found. The velocities so given, in order."""
    given: dict[sympy.Symbol, sympy.Expr] = {}
    ys = list(ys)
    for u in velocities:
        for i, y in enumerate(ys):
            top = sympy.expand(sympy.numer(sympy.together(y)))
            if not top.has(u) or sympy.degree(top, u) != 1:
                continue
            a, b = top.coeff(u, 1), top.coeff(u, 0)
            if a.has(u) or a.is_zero:
                continue
            x = sympy.cancel(-b / a)
            given[u] = x
            ys = [sympy.cancel(sympy.together(z.xreplace({u: x}))) for j, z in enumerate(ys) if j != i]
            given = {k: v.xreplace({u: x}) for k, v in given.items()}
            break
    return ys, given


def angle_coefficients(
    F: sympy.Expr, G: sympy.Expr, U: tuple[sympy.Symbol, ...]
) -> tuple[dict[tuple[int, ...], complex], dict[tuple[int, ...], complex]] | None:
    """The coefficients of ``F`` and ``G`` (numbers in) in the velocities and each angle's sine and
    cosine (``sin²α + 9/16 cos²α - 3/5`` and ``½(v_n² + v_t²) - 3/10 (sin²α + cos²α)``), so that
    they can be compared (:func:`alike`); None where no unknown angle is in them."""
    angles = angles_in([F, G], U)
    if not angles:
        return None
    put, V = {}, [u for u in U if u not in angles]
    for a in angles:
        s, c = sympy.Symbol(f"_s_{a.name}"), sympy.Symbol(f"_c_{a.name}")
        put |= {sympy.sin(a): s, sympy.cos(a): c, sympy.tan(a): s / c}
        V += [s, c]
    cf, cg = (coefficients(sympy.expand_trig(x).xreplace(put), tuple(V)) for x in (F, G))
    if cf is None or cg is None:
        return None
    return cf, cg


def alike(a: dict, b: dict) -> float:
    """|cos| of the angle between the coefficients of a line ``a`` and an equation ``b`` over the
    line's terms in the unknowns (not only the linear ones: ``sin²α`` is not, and the velocities'
    terms of an equation the line has them eliminated from do not count against it)."""
    return cosine(a, b, [m for m in a if sum(m) >= 1])
