"""Mistakes in the t direction: e applied to it, or the system's momentum for each body's."""

from __future__ import annotations

import sympy

from derive.checking.mistakes.equations import Model
from derive.checking.mistakes.records import Variant, mistake


@mistake(
    "e_on_t",
    "e applied to the t components",
    "The t components were reduced by e as well (v_A2t = e v_A1t, v_B2t = e v_B1t), as if restitution "
    "acted in the plane of contact: with smooth bodies each t component is unchanged.",
    (1, 2),
    "the t-momentum of each body",
    "applies e to the t components",
)
def e_on_t(model: Model) -> Variant | None:
    """(1), (2) with e times the t components before the impact."""
    if not model.problem.oblique:
        return None
    return Variant(t_factor=model.e)


def moved(model: Model, v: Variant) -> list[dict[int, sympy.Expr]]:
    """e moved from the n components to the t ones: (1), (2) with e times the t components before,
    and the impact rule (4) without it, separation = approach (``v_par = (3/4) U cos(alpha),
    v_perp = U sin(alpha)`` at a wall); numbers in. A teacher names it e on the t components."""
    if v.t_factor is None or model.e in model.unknowns:
        return []
    eqs = model.equations(v)
    if 4 not in eqs:
        return []
    return [model.numbered(v, {**eqs, 4: eqs[4].xreplace({model.e: sympy.Integer(1)})})]


@mistake(
    "system_t",
    "the system's t momentum used instead of each body's",
    "The t-momentum of A + B together was conserved in place of each body's, with one t velocity for "
    "both, (m_A + m_B) v_2t = m_A v_A1t + m_B v_B1t: no t force acts on either body, so each keeps its own.",
    (1, 2),
    "the t-momentum of each body",
    "uses the t momentum of the system instead of each body's",
)
def system_t(model: Model) -> Variant | None:
    """One t velocity for both bodies, from the t-momentum of the system."""
    p = model.problem
    if not p.oblique or p.fixed_B:
        return None
    return Variant(t_rule="system")
