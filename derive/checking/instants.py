"""One body against a fixed one (a ball and a wall): its velocities named by the instant.

With one body moving, a digit after a velocity's letter is no body (the wall never moves): ``v_2``
(``v2``) is the body's velocity after the impact, and ``v_1`` (``v1``) its velocity before where
no ``u`` names the velocity before (``v_1 = 4``, ``v_2 = -1.6``, the instants 1 and 2 as the
engineering texts number them); beside ``u_1`` (``u1 = 4, v1 = -1.6``) ``v_1`` stays the first
body's velocity after (the A-level habit)."""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context


def one_body_instants(ctx: Context, used: set[str] | None) -> dict[str, sympy.Expr]:
    """The names ``v_1``, ``v1``, ``v_2``, ``v2`` -> the one moving body's velocity before and
    after the impact, in a direct impact with a fixed body; {} otherwise."""
    p = ctx.problem
    if not p.fixed_B or p.oblique:
        return {}
    nm = ctx.model.nm
    out: dict[str, sympy.Expr] = {"v_2": nm.A2n, "v2": nm.A2n}
    if used is None or not any(re.fullmatch(r"u(?:_?[A1a])?", n) for n in used):
        out["v_1"] = out["v1"] = nm.A1n
    return out
