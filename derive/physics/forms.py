"""Closed forms factored once per problem *structure* in a process, not once per problem.

``sympy.factor`` of the general solution of (1)-(4), and of the kinetic energy lost, works in
the component symbols (v_A1n, m_A, e, ...): its input depends only on the structure of the
problem (direct or oblique, a fixed B, which pre-impact components are 0, which masses are
letters), never on its numbers. So a process that solves many problems of one structure (a
handout, a batch of variants, the tests) factors each structure once; nothing is kept on disk.
"""

from __future__ import annotations

from functools import lru_cache

import sympy


@lru_cache(maxsize=256)
def factored(expr: sympy.Expr) -> sympy.Expr:
    """``sympy.factor(expr)``, remembered for the process (its input is a structure, not numbers)."""
    return sympy.factor(expr)
