"""The common mistakes, in the order a report lists them: one entry per kind.

A new kind is a function decorated with :func:`~.records.mistake` (which registers
it, after these); a built-in one is also one line of :data:`KINDS`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import sympy

from derive.checking.mistakes import directions, masses, restitution, tangential, velocities
from derive.checking.mistakes.records import REGISTRY, Mistake, Variant

#: What each of the equations is, in words (the notes' three systems and the impact rule).
EQUATION_TITLES = {
    1: "the t-momentum of A",
    2: "the t-momentum of B",
    3: "the n-momentum of the system A + B",
    4: "the impact rule (restitution)",
}

KINDS: tuple[Mistake, ...] = (
    velocities.b_sign,
    restitution.restitution_reversed,
    restitution.e_speeds,
    tangential.e_on_t,
    restitution.energy_conserved,
    tangential.system_t,
    velocities.sin_cos_swapped,
    directions.angle_other_axis,
    directions.angle_quadrant,
    velocities.degrees_as_radians,
    masses.masses_swapped,
    masses.weight_as_mass,
)

#: Further ways a kind shows in the equations a student writes (its equations, numbers in).
FORMS: dict[str, Callable[[Any, Variant], list[dict[int, sympy.Expr]]]] = {
    "masses_swapped": masses.one_side,
    "restitution_reversed": restitution.upside_down,
    "weight_as_mass": masses.one_body,
    "energy_conserved": restitution.energy_for_momentum,
    "e_on_t": tangential.moved,
}

# every kind registered itself when its module was imported; here they are put in report order
_OTHERS = {k: m for k, m in REGISTRY.items() if m not in KINDS}
REGISTRY.clear()
REGISTRY.update({m.name: m for m in KINDS}, **_OTHERS)


def register(m: Mistake) -> Mistake:
    """Add a kind of mistake after those of :data:`KINDS` (what :func:`~.records.mistake` does); returns it."""
    REGISTRY[m.name] = m
    return m


def phrase(name: str) -> str | None:
    """What completes "your (4) ..." for a mistake, or two together (``e_on_t+system_t``)."""
    parts = [REGISTRY.get(n) for n in name.split("+")]
    if any(m is None for m in parts):
        return None
    return " and ".join(m.phrase for m in parts if m is not None)
