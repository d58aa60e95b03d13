"""Two slips in the velocities before the impact, one on each body, make one world together.

A's velocity resolved with sin and cos swapped, then B's taken with the wrong sign (``u_An = 4 sin 30°
= 2``, then ``u_Bn = 3`` for B moving toward A): each is a slip of its own, and the lines after
are right given both (``m(2) + m(3) = m v_An + m v_Bn`` is carried, not the first mistake made
again). The world the lines after are judged in has each body's components as the student
resolved them: each component from the variant that changed it.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from derive.checking.mistakes.pairs import merge
from derive.checking.mistakes.records import Mistake, Variant


def with_both(trace: Any, variant: Variant | None, mistake: Mistake) -> bool:
    """Make ``trace``'s world that of its variant of the values before (a first slip there) with
    ``variant`` (a further one) made too, each component as the one that changed it has it;
    False (nothing changed) where the world is not one of the values before, or ``variant``
    changes nothing new."""
    model, first = trace.ctx.model, trace.variant
    if trace.world is None or trace.replaced or first.pre is None or variant is None or variant.pre is None:
        return False
    if mistake.name in set().union(*trace.named.values()):
        return False  # the same mistake again (B's resolved as A's was): the world has it already
    pre = {}
    for c, true in model.pre.items():
        x, y = first.pre.get(c, true), variant.pre.get(c, true)
        pre[c] = y if y != true else x
    if all(pre[c] == first.pre.get(c, t) for c, t in model.pre.items()):
        return False
    both = merge(first, replace(variant, pre=None))
    out = model.outcome(replace(both, pre=pre), mistake) if both is not None else None
    if out is None:
        return False
    trace.world = [{u: out.post[u].xreplace(pt) for u in trace.U} for pt in trace.pts]
    trace.equations = {j: F for j, F in out.equations.items() if j in trace.equations}
    trace.variant = replace(both, pre=pre)
    return True
