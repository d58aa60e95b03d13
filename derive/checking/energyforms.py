"""More wrong formulas of a kinetic energy, as students write them (``ke_formula``).

:func:`~.slipnames.wrong_energies` has the formula's own slips (no square, no half, the
energy lost as ½m(u − v)²); these are the slips in what the formula is applied to: one
body's energy for the two bodies' (``T_2 = ½(4.0)(1.4925)²`` for a bullet lodged in a
block, the bullet left out), and the energy after as e (or, for two bodies, e²) times the energy
before (e scales a rebound speed, so a wall's energy scales by e²; two bodies' does not).
"""

from __future__ import annotations

from dataclasses import replace

import sympy

from derive.checking.context import Context


def more_energies(ctx: Context) -> list[dict[str, sympy.Expr]]:
    """The kinetic energies (by result name) with one body's left out, and the energy after
    as e times the energy before, in the components (as :func:`~.slipnames.wrong_energies`)."""
    model, p = ctx.model, ctx.problem
    nm = model.nm
    half, zero = sympy.Rational(1, 2), sympy.Integer(0)
    bodies = [("A", model.m_A)] + ([] if p.fixed_B else [("B", model.m_B)])

    def energy(b: str, m: sympy.Expr, k: str) -> sympy.Expr:
        n = getattr(nm, f"{b}{k}n")
        t = getattr(nm, f"{b}{k}t") if p.oblique else None
        return half * m * (n**2 + (t**2 if t is not None else zero))

    before = sum((energy(b, m, "1") for b, m in bodies), zero)
    after = sum((energy(b, m, "2") for b, m in bodies), zero)
    forms: list[dict[str, sympy.Expr]] = [{"T_2": model.e * before, "T_lost": before - model.e * before}]
    if len(bodies) > 1:  # e² scales a wall's energy only: two bodies' is not e² times it
        forms += [{"T_2": model.e**2 * before, "T_lost": before - model.e**2 * before}]
    for b, m in bodies if len(bodies) > 1 else ():  # one body's energy only, the other's left out
        forms += [{"T_1": energy(b, m, "1"), "T_lost": energy(b, m, "1") - after}]
        forms += [{"T_2": energy(b, m, "2"), "T_lost": before - energy(b, m, "2")}]
        forms += [{"T_lost": energy(b, m, "1") - energy(b, m, "2")}]
    return forms


def masses_put_right(ctx: Context, bad, holds) -> sympy.Expr | None:
    """The relation ``bad`` stands for where it writes a kinetic energy out term by term, ½ M v²
    for each body's velocity v, with a term's mass or half wrong (``½ m v_A² + ½ m v_B² = ¼ m u²``
    where B's mass is 9m), and holds once each such term is ½ m v² with its own body's mass: a
    wrong formula of the energy, as teachers name it (``ke_formula``); None otherwise."""
    if bad.raw is None:
        return None
    model, p = ctx.model, ctx.problem
    nm, half = model.nm, sympy.Rational(1, 2)
    bodies = [("A", model.m_A)] + ([] if p.fixed_B else [("B", model.m_B)])
    mass = {s: m for b, m in bodies for k in "12" for a in "nt" if (s := getattr(nm, f"{b}{k}{a}", None)) is not None}
    raw, changed = [], False
    for side in bad.raw:
        terms = []
        for t in sympy.Add.make_args(sympy.expand(side)):
            squared = [s for s in mass if t.has(s**2) and not (t / s**2).free_symbols & set(mass)]
            if len(squared) == 1:
                right = half * mass[squared[0]] * squared[0] ** 2
                changed |= sympy.simplify(ctx.in_unknowns(t - right)) != 0
                t = right
            terms.append(t)
        raw.append(sympy.Add(*terms))
    if not changed:
        return None
    left, right = (ctx.in_unknowns(x) for x in raw)
    return left - right if holds(replace(bad, left=left, right=right, raw=(raw[0], raw[1]))) else None
