"""Closed forms factored once per structure (derive.physics.forms): the same as ``sympy.factor``."""

from __future__ import annotations

import sympy

from derive.physics import forms


def test_factored_is_what_factor_gives() -> None:
    x, y = sympy.symbols("x y")
    assert forms.factored(x**2 - y**2) == (x - y) * (x + y)


def test_a_structure_is_factored_once_in_a_process(monkeypatch) -> None:
    calls: list[sympy.Expr] = []
    real = sympy.factor
    monkeypatch.setattr(sympy, "factor", lambda expr, *a, **k: calls.append(expr) or real(expr, *a, **k))
    forms.factored.cache_clear()
    a, b = sympy.symbols("a b")
    expr = a**2 + 2 * a * b + b**2
    assert forms.factored(expr) == (a + b) ** 2
    assert forms.factored(expr) == (a + b) ** 2
    assert calls == [expr]
