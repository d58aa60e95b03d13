"""Mistakes in the impact rule (4): reversed differences, speeds for components, energy."""

from __future__ import annotations

import sympy

from derive.checking.mistakes.equations import APPROACH_A, APPROACH_B, Model, point
from derive.checking.mistakes.records import Variant, mistake


@mistake(
    "restitution_reversed",
    "restitution the wrong way round",
    "The impact rule was written the wrong way round: its differences reversed, "
    "e (v_A1n − v_B1n) = v_A2n − v_B2n, or its ratio upside down, e = approach ÷ separation. "
    "The rule is separation = e × approach: v_B2n − v_A2n = e (v_A1n − v_B1n).",
    (4,),
    "the impact rule",
    "has the impact rule the wrong way round",
)
def restitution_reversed(model: Model) -> Variant | None:
    """Separation written v_A2n − v_B2n."""
    return Variant(restitution="reversed")


def upside_down(model: Model, v: Variant) -> list[dict[int, sympy.Expr]]:
    """The impact rule with e on the separation's side, e (v_B2n − v_A2n) = v_A1n − v_B1n
    (the ratio turned upside down: e = approach / separation), its differences in either
    order; numbers in. A teacher names it as the rule's differences the wrong way round."""
    base = model.base()
    eqs = model.equations(base)
    if 4 not in eqs:
        return []
    nm, e = model.nm, model.e
    approach = APPROACH_A - APPROACH_B
    return [model.numbered(base, {**eqs, 4: e * sep - approach}) for sep in (nm.B2n - nm.A2n, nm.A2n - nm.B2n)]


@mistake(
    "e_speeds",
    "e applied to speeds instead of n components",
    "The impact rule used the speeds before the impact, e (v_A1 − v_B1) = v_B2n − v_A2n, "
    "instead of their n components: restitution relates the normal components only.",
    (4,),
    "the impact rule",
    "applies e to the speeds, not to the n components",
)
def e_speeds(model: Model) -> Variant | None:
    """The approach in (4) from the speeds, each with the sign of its n component."""
    p = model.problem
    if not p.oblique:
        return None
    nm = model.nm
    signed = []
    for motion, n, t, sense in ((p.motion_A, nm.A1n, nm.A1t, 1), (p.motion_B, nm.B1n, nm.B1t, -1)):
        if motion.body == "B" and p.fixed_B:
            signed.append(sympy.Integer(0))
            continue
        speed = motion.speed if motion.speed is not None else sympy.sqrt(model.pre[n] ** 2 + model.pre[t] ** 2)
        sign = sympy.sign(model.num(model.pre[n]).xreplace(point(model.num(model.pre[n]).free_symbols)))
        signed.append((sign if sign != 0 else sense) * speed)
    if model.is_zero(signed[0] - model.pre[nm.A1n]) and model.is_zero(signed[1] - model.pre[nm.B1n]):
        return None
    return Variant(approach=(signed[0], signed[1]))


@mistake(
    "energy_conserved",
    "kinetic energy conserved across the impact",
    "Kinetic energy was taken as conserved across the impact, in place of the impact rule: that holds "
    "only when e = 1, so the velocities are those of a perfectly elastic impact.",
    (4,),
    "the impact rule, replaced by conservation of kinetic energy",
    "conserves kinetic energy instead of applying the impact rule",
)
def energy_conserved(model: Model) -> Variant | None:
    """(4) replaced by T_1 = T_2, whose nontrivial root is that of e = 1. Where e is an unknown
    (a mass or e to find) there is no e to put in: only its forms, the energy in place of the
    momentum (:func:`energy_for_momentum`), are written."""
    if model.e in model.unknowns:
        return Variant(energy=True)
    return Variant(e=sympy.Integer(1), energy=True)


def energy_for_momentum(model: Model, v: Variant) -> list[dict[int, sympy.Expr]]:
    """Kinetic energy conserved in place of the momentum (3), the impact rule kept (a bullet
    that lodges: ½ m u² = ½ (m + M) V²); numbers in."""
    eqs = model.equations(model.base())
    if 3 not in eqs:
        return []
    return [model.numbered(model.base(), {**eqs, 3: model.energy_equation()})]
