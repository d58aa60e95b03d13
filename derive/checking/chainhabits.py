"""A chain's velocities named by the habit, and the givens restated in those names.

``vA``, ``v_B2``, ``(v_A)_1`` name the velocities of the impact of A and B
(:func:`.chainnames.velocities`); once so known, a line of givens before the working that writes a
given in them (``(v_B)_1 = 2 m/s ←`` for B's speed toward A) restates it and is not judged
(:func:`.chainnames.restated`).
"""

from __future__ import annotations

from collections.abc import Callable

from derive.checking import chainnames
from derive.checking.context import Context


def habit_names(ctx: Context, read: list, said: chainnames.Declared, holds: Callable) -> tuple[dict, list]:
    """``said`` with the impact's velocities the habit names, and ``read`` without the givens
    restated in them."""
    said = {**said, **chainnames.velocities(ctx, read, said, holds)}
    return said, [x for x in read if not chainnames.restated(ctx, x, read, said)]
