"""Kinetic energy and the impulse of an impact, written once for every caller.

The notes use energy only before and after an impact (never across one) and report
the kinetic energy an impact loses.
"""

from __future__ import annotations

import sympy

HALF = sympy.Rational(1, 2)


def kinetic_energy(m: sympy.Expr, v_n: sympy.Expr, v_t: sympy.Expr = 0) -> sympy.Expr:
    """``T = 1/2 m (v_n^2 + v_t^2)`` of a particle.

    >>> from sympy import symbols
    >>> m, v = symbols("m v")
    >>> kinetic_energy(m, v)
    m*v**2/2
    """
    return HALF * m * (v_n**2 + v_t**2)


def impulse_n(m_A: sympy.Expr, v_A1n: sympy.Expr, v_A2n: sympy.Expr) -> sympy.Expr:
    """``J_n = m_A (v_A1n - v_A2n)``: the impulse along +n on B from A (on A it is -J_n).

    >>> from sympy import symbols
    >>> impulse_n(2, 5, 1)
    8
    """
    return m_A * (v_A1n - v_A2n)
