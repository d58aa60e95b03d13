"""Mistakes in the velocities before the impact: a sign, sin and cos, degrees and radians."""

from __future__ import annotations

from dataclasses import replace

import sympy

from derive.checking.mistakes.equations import Model
from derive.checking.mistakes.records import Variant, mistake
from derive.problem.units import ANGLE


@mistake(
    "b_sign",
    "B's velocity with the wrong sign",
    "B's velocity before the impact was taken with the wrong sign, as if B moved the other way: "
    "n points from A toward B, so a B moving toward A has v_B1n < 0.",
    (2, 3, 4),
    "B's velocity before the impact, v_B1n (and v_B1t)",
    "has B's velocity with the wrong sign",
)
def b_sign(model: Model) -> Variant | None:
    """B's components before the impact negated."""
    if model.problem.fixed_B:
        return None
    pre = {k: (-x if k in (model.nm.B1n, model.nm.B1t) else x) for k, x in model.pre.items()}
    if all(model.is_zero(model.pre[k]) for k in model.pre if k in (model.nm.B1n, model.nm.B1t)):
        return None
    return Variant(pre=pre)


@mistake(
    "sin_cos_swapped",
    "sin and cos swapped (angle from the other axis)",
    "The velocities before the impact were resolved with sin and cos swapped, as if the angle were "
    "measured from the other axis (from t instead of n, or from n instead of t).",
    (1, 2, 3, 4),
    "the n and t components before the impact (stage 1), and through them every equation",
    "has sin and cos swapped",
)
def sin_cos_swapped(model: Model) -> Variant | None:
    """Each velocity given by a speed and an angle resolved with the complement of its angle
    to the line of impact (80 sin 25° along n for a velocity at 25° to it; where n is at φ to
    x, the angle θ from x becomes π/2 + 2φ − θ, so that θ − φ becomes π/2 − (θ − φ))."""
    return _resolved_swapped(model, keep_way=True)


def sin_cos_swapped_as_written(model: Model) -> Variant | None:
    """:func:`sin_cos_swapped` where the line of impact is the geometry's, each part not keeping
    its way but as the swap writes it: B at 100° from n resolved ``110 sin 100° = 108.3`` along n
    and ``110 cos 100° = -19.10`` across (the student's own angle from n, obtuse); None where
    that is the same as :func:`sin_cos_swapped`."""
    if model.problem.phi is None:
        return None
    return _resolved_swapped(model, keep_way=False)


def _resolved_swapped(model: Model, keep_way: bool) -> Variant | None:
    p = model.problem
    motions = [m for m in (p.motion_A, p.motion_B) if m.angle is not None and m.speed is not None]
    if not p.oblique or not motions:
        return None
    nm = model.nm
    pre = dict(model.pre)
    phi = p.phi if p.phi is not None else sympy.Integer(0)
    for motion, (n, t) in ((p.motion_A, (nm.A1n, nm.A1t)), (p.motion_B, (nm.B1n, nm.B1t))):
        if motion in motions:
            swap = {motion.angle: sympy.pi / 2 + 2 * phi - motion.angle}
            pre[n] = model.pre[n].xreplace(swap)
            pre[t] = model.pre[t].xreplace(swap)
            if p.phi is not None and keep_way:  # the line of impact from the geometry: each part keeps its way
                pre[n] = sympy.sign(model.pre[n]) * sympy.Abs(model.pre[t])
                pre[t] = sympy.sign(model.pre[t]) * sympy.Abs(model.pre[n])
    return Variant(pre=pre)


@mistake(
    "degrees_as_radians",
    "degrees read as radians",
    "An angle given in degrees was used as if it were in radians (a calculator in radian mode): "
    "sin 37.6 instead of sin 37.6°.",
    (1, 2, 3, 4),
    "the n and t components before the impact (stage 1), and through them every equation",
    "reads the angle in degrees as radians",
)
def degrees_as_radians(model: Model) -> Variant | None:
    """Each angle given as a number of degrees put in as that many radians."""
    values = {}
    for g in model.problem.givens:
        if g.dim == ANGLE and g.value is not None and g.definition is None and g.written is None and not g.unknown:
            values[g.symbol] = g.value * 180 / sympy.pi
    if not values:
        return None
    return Variant(values=values)


def of_one_body(model: Model, v: Variant | None, named: set[sympy.Symbol]) -> Variant | None:
    """``v`` made on one body's velocity before the impact only, where the line it is found on
    names that body's components and not the other's (A's resolved with sin and cos swapped,
    B's not, or not yet); None where ``v`` changes one body only already, or the line names both."""
    if v is None or v.pre is None:
        return None
    nm = model.nm
    bodies = [{c for c in (nm.A1n, nm.A1t) if c is not None}, {c for c in (nm.B1n, nm.B1t) if c is not None}]
    touched = [b for b in bodies if b & named]
    changed = [b for b in bodies if any(v.pre.get(c, model.pre.get(c)) != model.pre.get(c) for c in b)]
    if len(touched) != 1 or len(changed) < 2:
        return None
    pre = {c: (x if c in touched[0] else model.pre[c]) for c, x in v.pre.items()}
    return replace(v, pre=pre)
