"""Every result of a problem (speeds, directions, energies, impulse) from its velocities
after the impact, as a set of equations — correct or mistaken — gives them.

The kinetic energy and the impulse are :mod:`derive.physics.energy`'s; only the
direction may be computed wrongly, as a mistake says.
"""

from __future__ import annotations

import functools
from collections.abc import Callable

import sympy

from derive.checking.mistakes.records import Quantity
from derive.physics.energy import impulse_n, kinetic_energy
from derive.physics.impact import Names
from derive.problem import Problem


def results_of(
    p: Problem,
    nm: Names,
    pre: dict[sympy.Symbol, sympy.Expr],
    post: dict[sympy.Symbol, sympy.Expr],
    masses: tuple[sympy.Expr, sympy.Expr],
    known: dict[sympy.Symbol, sympy.Expr],
    angles: str,
    num: Callable[[sympy.Expr], sympy.Expr],
) -> dict[str, Quantity]:
    """The results by name: ``pre``/``post`` the components before and after (numbers
    in), ``known`` the unknowns solved, ``angles`` how directions are computed
    (see :class:`~.records.Variant`), ``num`` puts the numbers in."""
    res: dict[str, Quantity] = {}
    for g in p.givens:
        if g.unknown:
            if g.unit == "deg":
                val = known[g.symbol]
                res[g.name] = Quantity(val, None if val.free_symbols else val * 180 / sympy.pi)
            else:
                res[g.name] = _quantity(known[g.symbol], known)
    if p.oblique:
        res.update(_oblique(p, nm, post, known, angles, num))
        res.update(_acute(p, nm, pre, post, known, angles))
    else:
        res["v_A2"] = _quantity(post[nm.A2n], known)
        if not p.fixed_B:
            res["v_B2"] = _quantity(post[nm.B2n], known)
    t = (nm.A1t, nm.A2t, nm.B1t, nm.B2t) if p.oblique else (None, None, None, None)
    T1 = kinetic_energy(masses[0], pre[nm.A1n], _t(pre, t[0])) + kinetic_energy(masses[1], pre[nm.B1n], _t(pre, t[2]))
    T2 = kinetic_energy(masses[0], post[nm.A2n], _t(post, t[1])) + kinetic_energy(
        masses[1], post[nm.B2n], _t(post, t[3])
    )
    res["T_1"] = _quantity(T1, known)
    res["T_2"] = _quantity(T2, known)
    res["T_lost"] = _quantity(T1 - T2, known)
    res["J_n"] = _quantity(impulse_n(masses[0], pre[nm.A1n], post[nm.A2n]), known)
    return res


def _quantity(expr: sympy.Expr, known: dict[sympy.Symbol, sympy.Expr]) -> Quantity:
    expr = sympy.sympify(expr).xreplace(known)
    return Quantity(expr, None if expr.free_symbols else expr)


def _t(values: dict[sympy.Symbol, sympy.Expr], c: sympy.Symbol | None) -> sympy.Expr:
    return values[c] if c is not None else sympy.Integer(0)


def _oblique(
    p: Problem,
    nm: Names,
    post: dict[sympy.Symbol, sympy.Expr],
    known: dict[sympy.Symbol, sympy.Expr],
    angles: str,
    num: Callable[[sympy.Expr], sympy.Expr],
) -> dict[str, Quantity]:
    """The components, speeds and directions after an oblique impact (x-y components too)."""
    res: dict[str, Quantity] = {}
    for name, c in (("v_A2t", nm.A2t), ("v_A2n", nm.A2n), ("v_B2t", nm.B2t), ("v_B2n", nm.B2n)):
        res[name] = _quantity(post[c], known)
    for b in "AB":
        if b == "B" and p.fixed_B:
            continue
        n, t = post[getattr(nm, f"{b}2n")].xreplace(known), post[getattr(nm, f"{b}2t")].xreplace(known)
        res[f"v_{b}2"] = _quantity(sympy.sqrt(n**2 + t**2), known)
        if not (n == 0 and t == 0):
            res[f"theta_{b}2"], res[f"beta_{b}2"] = directions(n, t, angles)
        if p.phi is not None:
            phi = num(p.phi)
            res[f"v_{b}2x"] = _quantity(n * sympy.cos(phi) - t * sympy.sin(phi), known)
            res[f"v_{b}2y"] = _quantity(n * sympy.sin(phi) + t * sympy.cos(phi), known)
    return res


def _acute(
    p: Problem,
    nm: Names,
    pre: dict[sympy.Symbol, sympy.Expr],
    post: dict[sympy.Symbol, sympy.Expr],
    known: dict[sympy.Symbol, sympy.Expr],
    angles: str = "atan2",
) -> dict[str, Quantity]:
    """The acute angles with n (alpha) and t (gamma) after the impact, and the deflection (delta);
    ``angles`` "other_axis": each measured from the other axis (alpha is then the angle with t)."""
    res: dict[str, Quantity] = {}
    for b in "AB":
        if b == "B" and p.fixed_B:
            continue
        n, t = (post[getattr(nm, f"{b}2{c}")].xreplace(known) for c in "nt")
        if n == 0 and t == 0:
            continue
        n, t = _float(n), _float(t)
        n1 = _float(pre[getattr(nm, f"{b}1n")])
        t1 = _float(pre[getattr(nm, f"{b}1t")]) if getattr(nm, f"{b}1t") is not None else sympy.Integer(0)
        pairs = {f"alpha_{b}2": (sympy.Abs(t), sympy.Abs(n)), f"gamma_{b}2": (sympy.Abs(n), sympy.Abs(t))}
        if angles == "other_axis":
            pairs = {f"alpha_{b}2": pairs[f"gamma_{b}2"], f"gamma_{b}2": pairs[f"alpha_{b}2"]}
        if not (n1 == 0 and t1 == 0):
            pairs[f"delta_{b}"] = (sympy.Abs(t1 * n - n1 * t), t1 * t + n1 * n)
        for name, (y, x) in pairs.items():
            rad = sympy.atan2(_float(y), _float(x))
            res[name] = Quantity(rad, None if rad.free_symbols else _float(rad * 180 / sympy.pi))
    return res


def _float(x: sympy.Expr) -> sympy.Expr:
    """``x`` to 30 digits where it is a number: SymPy's exact ``Abs`` and ``atan2`` of a
    radical with cos 20° in it ask for its sign by evaluating it again and again (a second a
    mistake, 55 mistakes and pairs), where a 30-digit number is all a check compares."""
    return x if x.free_symbols else sympy.N(x, 30)


def directions(n: sympy.Expr, t: sympy.Expr, rule: str) -> tuple[Quantity, Quantity]:
    """theta (from +t toward +n) and beta (from +n toward +t) of the direction (n, t)."""
    if rule == "atan2":
        return _direction(n, t, True), _direction(t, n, True)
    if rule == "other_axis":
        return _direction(t, n, False), _direction(n, t, False)
    return _direction(n, t, False), _direction(t, n, False)


@functools.lru_cache(maxsize=1024)
def _direction(y: sympy.Expr, x: sympy.Expr, quadrant: bool) -> Quantity:
    """atan2(y, x) (or, without ``quadrant``, tan⁻¹(y/x)) in radians and degrees (kept for the
    process: the mistakes and their pairs ask for the same direction again and again, and with a
    letter in it each is a simplification)."""
    if x == 0 and not quadrant:
        return Quantity(None, None)
    if x == 0 and (y.is_positive or y.is_negative):
        rad = sympy.pi / 2 if y.is_positive else -sympy.pi / 2
        return Quantity(rad, rad * 180 / sympy.pi)
    if not (y.free_symbols or x.free_symbols):
        y, x = _float(y), _float(x)
        rad = sympy.atan2(y, x) if quadrant else sympy.atan(y / x)
        return Quantity(rad, _float(rad * 180 / sympy.pi))
    ratio = sympy.simplify(y / x) if x != 0 else None
    if ratio is not None and ratio.is_number:
        rad = sympy.atan(ratio)
        if quadrant:
            if x.is_negative:
                rad += sympy.pi if y.is_nonnegative else -sympy.pi
            elif not x.is_positive:
                return Quantity(sympy.atan2(y, x), None)
        return Quantity(rad, rad * 180 / sympy.pi)
    return Quantity(sympy.atan2(y, x) if quadrant else sympy.atan(y / x), None)
