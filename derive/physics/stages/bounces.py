"""The ``bounces`` stage: a ball dropped from a height bouncing on a floor ``count`` times.

Each bounce is an impact with a fixed body, so the rebound speed is e times the
impact speed; between bounces energy is conserved, so h_k = e^(2k) h_0, and the
distance travelled before the ball comes to rest is a geometric series.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from derive.physics.state import ChainState, StageOutcome
from derive.problem import Given, units


@dataclass(frozen=True)
class Bounces:
    """The drop height ``h0``, ``e``, the impact speed ``v0``, each bounce's speed and
    height, and the total distance."""

    h0: sympy.Expr
    e: sympy.Expr
    g: sympy.Symbol
    v0: sympy.Expr
    speeds: tuple[Given, ...]
    heights: tuple[Given, ...]
    total: Given


def bounces(state: ChainState, i: int, st: dict) -> StageOutcome:
    """Speeds and heights after each of ``count`` bounces (default 3), and the total distance."""
    h0 = state.quantity(i, st, "height", units.LENGTH)
    e = state.quantity(i, st, "e", units.DIMENSIONLESS)
    n = st.get("count", 3)
    if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= 50:
        raise state.err(i, "count", "expected a whole number of bounces from 1 to 50", n)
    if state.value(e) == 1:  # the series of distances has no sum: refused before it is formed
        raise state.err(
            i,
            "e",
            "with e = 1 the ball never comes to rest (no energy is lost at a bounce): give e below 1",
            st.get("e"),
        )
    g = state.g_symbol()
    v0 = sympy.sqrt(2 * g * h0)
    speeds, heights, outputs = [], [], []
    for k in range(1, n + 1):
        vk = state.define(i, f"v_b{k}", e**k * v0, units.VELOCITY)
        hk = state.define(i, f"h_b{k}", e ** (2 * k) * h0, units.LENGTH)
        speeds.append(vk)
        heights.append(hk)
        outputs += [vk.name, hk.name]
    total = state.define(i, "s_total", h0 * (1 + e**2) / (1 - e**2), units.LENGTH)
    data = Bounces(h0, e, g, v0, tuple(speeds), tuple(heights), total)
    return StageOutcome(i, "bounces", f"{n} bounces on the floor", data, (*outputs, total.name))
