"""Mistakes in the t direction: e applied to it, or the system's momentum for each body's."""

from __future__ import annotations

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
