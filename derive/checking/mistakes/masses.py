"""Mistakes in the masses: swapped, or a weight used as a mass."""

from __future__ import annotations

import sympy

from derive.checking.mistakes.equations import Model
from derive.checking.mistakes.records import Variant, mistake


@mistake(
    "masses_swapped",
    "masses swapped",
    "m_A and m_B were exchanged (in the momentum of the system and the kinetic energies).",
    (3,),
    "the masses in the n-momentum of the system",
    "has the masses swapped",
)
def masses_swapped(model: Model) -> Variant | None:
    """m_A and m_B exchanged."""
    if model.problem.fixed_B or model.is_zero(model.m_A - model.m_B):
        return None
    return Variant(masses=(model.m_B, model.m_A))


def one_side(model: Model, v: Variant) -> list[dict[int, sympy.Expr]]:
    """The n-momentum (3) with the masses swapped on one side only (before the impact, or
    after it: ``2m(4) - 3m(2) = 3m x + 2m y``), the other side right; numbers in."""
    eqs = model.equations(model.base())
    if 3 not in eqs or v.masses is None:
        return []
    nm = model.nm
    after = sympy.expand(eqs[3]) - sympy.expand(eqs[3]).xreplace({nm.A1n: 0, nm.B1n: 0})
    before = sympy.expand(eqs[3]) - after
    swap = {model.m_A: v.masses[0], model.m_B: v.masses[1]}
    base = model.base()
    return [
        model.numbered(base, {**eqs, 3: before.xreplace(swap) + after}),
        model.numbered(base, {**eqs, 3: before + after.xreplace(swap)}),
    ]


@mistake(
    "weight_as_mass",
    "weight used as mass",
    "A weight was used as the mass, without dividing by g (m = W/g). With both masses off by the same "
    "factor the velocities can come out right; the kinetic energies and the impulse do not.",
    (3,),
    "the masses, m = W/g (in the momentum and the kinetic energies)",
    "uses the weights as masses",
)
def weight_as_mass(model: Model) -> Variant | None:
    """Each mass given as W/g put in as W."""
    p = model.problem
    values = {}
    for b in "AB":
        try:
            m, w = p.given(f"m_{b}"), p.given(f"W_{b}")
        except KeyError:
            continue
        if w.value is not None and m.value is not None and not m.unknown:
            values[m.symbol] = w.value
    if not values:
        return None
    return Variant(values=values)


def one_body(model: Model, v: Variant) -> list[dict[int, sympy.Expr]]:
    """The n-momentum (3) with one body's weight put in as its mass, the other's mass right
    (``0.466(19.657) = 0.466 v_A + 10 v_B``: A's 15 lb turned to slugs, B's 10 lb not)."""
    eqs = model.equations(model.base())
    masses = [m for m in (model.m_A, model.m_B) if m in v.values]
    if 3 not in eqs or len(masses) != 2:
        return []
    base = model.base()
    return [model.numbered(base, {**eqs, 3: eqs[3].xreplace({m: v.values[m]})}) for m in masses]
