"""Two mistakes made together: the second built on the equations the first has spoiled.

Only pairs are tried (never three), and at most :data:`MAX_PAIRS` of them, so the
search stays bounded: twelve kinds make 66 pairs, fewer apply to any one problem.
"""

from __future__ import annotations

from derive.checking.mistakes.equations import Model
from derive.checking.mistakes.records import Mistake, Variant

#: The most pairs of mistakes tried for one problem.
MAX_PAIRS = 80

_DEFAULTS = {"restitution": "normal", "t_rule": "each", "angles": "atan2"}
_OPTIONAL = ("approach", "masses", "e", "t_factor")


def combine(first: Mistake, second: Mistake) -> Mistake:
    """The mistake of making ``first`` and ``second`` together (named ``first+second``)."""
    where = first.where if first.where == second.where else f"{first.where}; {second.where}"
    return Mistake(
        f"{first.name}+{second.name}",
        f"{first.title}, together with {second.title}",
        f"Two mistakes together. {first.description} {second.description}",
        tuple(sorted(set(first.enters) | set(second.enters))),
        where,
        f"{first.phrase} and {second.phrase}",
        lambda model: compose(model, first, second),
    )


def compose(model: Model, first: Mistake, second: Mistake) -> Variant | None:
    """The equations with ``first`` made, then ``second`` made on them; None where either
    cannot happen or the two change the same thing in different ways."""
    a = first.build(model)
    if a is None:
        return None
    b = second.build(model.under(a))
    if b is None:
        return None
    return merge(a, b)


def merge(a: Variant, b: Variant) -> Variant | None:
    """One variant with both changes (``b`` built on ``a``'s components before the impact);
    None where they change the same thing differently, or one replaces the impact rule
    (energy conserved) that the other writes wrongly."""
    for x, y in ((a, b), (b, a)):
        if x.energy and (y.restitution != "normal" or y.approach is not None):
            return None
    fields: dict = {"pre": b.pre if b.pre is not None else a.pre, "energy": a.energy or b.energy}
    for name in _OPTIONAL:
        x, y = getattr(a, name), getattr(b, name)
        if x is not None and y is not None and x != y:
            return None
        fields[name] = x if x is not None else y
    for name, default in _DEFAULTS.items():
        x, y = getattr(a, name), getattr(b, name)
        if x != default and y != default and x != y:
            return None
        fields[name] = x if x != default else y
    if any(k in a.values and a.values[k] != v for k, v in b.values.items()):
        return None
    fields["values"] = {**a.values, **b.values}
    return Variant(**fields)
