"""The records the mistakes are made of: a mistaken set of equations, a mistake, what it gives."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import sympy


@dataclass(frozen=True)
class Variant:
    """A mistaken set of equations: only what differs from the correct one.

    ``pre`` maps the components before the impact (``v_A1n`` ...) to their
    expressions in the givens; ``approach`` is what (4) uses for v_A1n and v_B1n;
    ``masses`` are (m_A, m_B) as the equations use them; ``restitution`` is
    "normal" or "reversed"; ``t_rule`` is "each" (equations (1), (2)) or "system"
    (one t velocity for both) ("scaled", as before, is "each" with e as ``t_factor``); ``t_factor`` multiplies the t components before the
    impact in (1) and (2) (e where e is applied to them; None for 1); ``energy``
    replaces (4) with conservation of kinetic energy (its nontrivial root is e = 1);
    ``values`` overrides the numbers of some givens; ``angles`` is how the
    directions after the impact are computed: "atan2", "other_axis"
    (tan⁻¹(v_t/v_n)) or "principal" (tan⁻¹(v_n/v_t) without the quadrant).
    """

    pre: Mapping[sympy.Symbol, sympy.Expr] | None = None
    approach: tuple[sympy.Expr, sympy.Expr] | None = None
    masses: tuple[sympy.Expr, sympy.Expr] | None = None
    e: sympy.Expr | None = None
    restitution: str = "normal"
    t_rule: str = "each"
    t_factor: sympy.Expr | None = None
    energy: bool = False
    values: Mapping[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    angles: str = "atan2"


@dataclass(frozen=True)
class Mistake:
    """One common mistake: its name, what it is, and where it enters the solution.

    ``enters`` are the equations it changes (none for a direction computed
    wrongly at the end); ``where`` says the same in words; ``phrase`` completes
    "your (4) ..."; ``build(model)`` returns its :class:`Variant`, or None where
    the mistake cannot happen in that problem.
    """

    name: str
    title: str
    description: str
    enters: tuple[int, ...]
    where: str
    phrase: str
    build: Callable[[Any], Variant | None]

    def __call__(self, model: Any) -> Variant | None:
        """``build(model)``: the mistake's variant of the equations, or None."""
        return self.build(model)

    def where_in(self, numbers: tuple[int, ...] | Any) -> str:
        """``where`` for a problem with equations ``numbers`` (or a model, which has them):
        only the equations it has."""
        numbers = getattr(numbers, "numbers", numbers)
        nums = [k for k in self.enters if k in numbers]
        if not self.enters:
            return self.where
        listed = ", ".join(f"({k})" for k in nums)
        return f"{listed}: {self.where}" if listed else self.where


@dataclass(frozen=True)
class Quantity:
    """A result under a set of equations: ``partial`` with the numbers in (symbolic
    givens kept; angles in radians), ``value`` the number in the working unit
    (degrees for angles), or None when a symbolic given remains."""

    partial: sympy.Expr | None
    value: sympy.Expr | None


@dataclass(frozen=True)
class Outcome:
    """The correct equations (``mistake`` None) or a mistaken set, solved.

    ``results`` by result name; ``post`` the velocity components after the impact
    and the unknown givens, numbers in; ``equations`` each equation as
    ``lhs - rhs`` with the numbers in and the unknowns as symbols.
    """

    mistake: Mistake | None
    results: dict[str, Quantity]
    post: dict[sympy.Symbol, sympy.Expr]
    equations: dict[int, sympy.Expr]
    unknowns: tuple[sympy.Symbol, ...]


#: Every mistake by name (:mod:`.registry` puts the built-in kinds in report order).
REGISTRY: dict[str, Mistake] = {}


def mistake(
    name: str, title: str, description: str, enters: tuple[int, ...], where: str, phrase: str
) -> Callable[[Callable[[Any], Variant | None]], Mistake]:
    """Make a :class:`Mistake` of a function ``build(model) -> Variant | None`` and register it."""

    def make(build: Callable[[Any], Variant | None]) -> Mistake:
        m = Mistake(name, title, description, enters, where, phrase, build)
        REGISTRY[name] = m
        return m

    return make
