"""The velocity of the centre of mass in the problem's symbols: before the impact (the common
velocity a name such as ``v_cm`` stands for) and after it (two bodies that move off together)."""

from __future__ import annotations

import sympy

from derive.checking.context import Context


def common_velocity(ctx: Context) -> sympy.Expr:
    """(m_A v_A1 + m_B v_B1)/(m_A + m_B) in the problem's symbols (the velocity of the centre of mass)."""
    nm = ctx.model.nm
    return _centre(ctx, nm.A1n, nm.B1n if nm.B1n is not None else 0)


def moving_together(ctx: Context, a: sympy.Expr | None, b: sympy.Expr | None) -> sympy.Expr | None:
    """The one velocity of two bodies that move off together (e = 0): the velocity of their
    centre of mass after the impact, (m_A v_A2 + m_B v_B2)/(m_A + m_B), which is each one's
    when they do; so ``(m_A + m_B) V = m_A u_A + m_B u_B`` is (3) itself, whatever the slip."""
    if ctx.problem.fixed_B or a is None or b is None or a == b:
        return a
    return _centre(ctx, a, b)


def _centre(ctx: Context, a: sympy.Expr, b: sympy.Expr) -> sympy.Expr:
    """The mass-weighted mean of A's velocity ``a`` and B's ``b``."""
    m = ctx.model
    return (m.m_A * a + m.m_B * b) / (m.m_A + m.m_B)
