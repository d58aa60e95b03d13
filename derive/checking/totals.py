"""A student's names of the total momentum before and after the impact: ``p_i = p_f``,
``P_before = P_after``. A teacher reads them as what they are, the momentum of A and B together
along the line of impact, so ``p_i = 150000(0.300) + 110000(0.120)`` for cars moving toward
each other is the slip of B's sign (not a definition of p_i), and ``p_i = p_f`` is the
conservation of momentum. The names with a body's number (``p_1``, ``p_A``) are one body's
momentum, not a total, and are left to be inferred.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context

#: How students name the total momentum before (i, initial, before) and after (f, final, after).
BEFORE = ("p_i", "P_i", "p_initial", "P_initial", "p_before", "P_before", "p_0", "P_0")
AFTER = ("p_f", "P_f", "p_final", "P_final", "p_after", "P_after")


def totals(ctx: Context, used: set[str] | None) -> dict[str, sympy.Expr]:
    """The names of the total momentum the text uses (all where ``used`` is None), -> the momentum
    of A and B along the line of impact before and after (A's alone where B is a wall)."""
    if used is not None and not (set(used) & set(BEFORE + AFTER)):
        return {}
    model, nm = ctx.model, ctx.model.nm
    bodies = ("A",) if ctx.problem.fixed_B else ("A", "B")
    masses = {"A": model.m_A, "B": model.m_B}
    before = [(masses[b], getattr(nm, f"{b}1n", None)) for b in bodies]
    after = [(masses[b], getattr(nm, f"{b}2n", None)) for b in bodies]
    out: dict[str, sympy.Expr] = {}
    for names, terms in ((BEFORE, before), (AFTER, after)):
        if all(m is not None and v is not None for m, v in terms):
            out.update(dict.fromkeys(names, sympy.Add(*(m * v for m, v in terms))))
    return out


def signed_change(written: tuple[str, ...], sides: tuple[str, ...]) -> tuple[str, ...]:
    """``ΔKE = 6523 - 7542 = -1019``: a change in kinetic energy worked out negative is the
    final less the initial, minus the energy lost (read as ``-T_lost``); written positive
    (``ΔKE = 7542 - 6523 = 1019``) it is the loss, as students write it. ``written``: the sides
    as typed, ``sides``: as rewritten in names."""
    change = len(sides) >= 2 and sides[0].strip() == "T_lost" and re.match(r"\s*(?:Δ|\\?Delta)", written[0])
    if change and re.match(r"\s*[-−]\s*\d", sides[-1]):
        return ("-T_lost", *sides[1:])
    return sides
