"""The table of factored closed forms (derive.physics.forms, issue #19): every entry is what
``sympy.factor`` gives, built back as the very same tree, and a bundled problem uses it."""

from __future__ import annotations

import pytest
import sympy

from derive.physics import forms
from derive.physics.forms_table import FACTORED


@pytest.mark.parametrize("key", sorted(FACTORED)[::4])  # a quarter of them: factor is slow on the big ones
def test_each_entry_is_what_factor_gives(key: str) -> None:
    assert forms.dump(sympy.factor(forms.rebuild(key))) == FACTORED[key]


def test_entries_are_built_back_unchanged() -> None:
    for key, text in FACTORED.items():
        assert forms.dump(forms.rebuild(key)) == key
        assert forms.dump(forms.rebuild(text)) == text


def test_a_factor_term_is_not_redistributed() -> None:
    """With evaluation on, Mul(1/3, Add) would become a sum of thirds: the trap of a cache."""
    x, y = sympy.symbols("x y")
    text = forms.dump(sympy.Mul(sympy.Rational(1, 3), x + 4 * y, evaluate=False))
    assert forms.rebuild(text).args[0] == sympy.Rational(1, 3)
    minus = -4 * x * y**2 + 3 * x  # srepr would write Mul(Integer(-1), Integer(4), ...)
    assert forms.rebuild(forms.dump(minus)).args == minus.args


def test_a_structure_outside_the_table_is_factored(monkeypatch: pytest.MonkeyPatch) -> None:
    import derive.physics.forms_table as table

    monkeypatch.setattr(table, "FACTORED", {})
    x, y = sympy.symbols("x y")
    assert forms.factored(x**2 - y**2) == (x - y) * (x + y)


def test_the_benchmark_problem_reads_the_table(monkeypatch: pytest.MonkeyPatch) -> None:
    import derive

    calls = []
    real = sympy.factor
    monkeypatch.setattr(sympy, "factor", lambda *a, **k: calls.append(a) or real(*a, **k))
    derive.solve(derive.load("notes-4c11-two-spheres"))
    assert calls == []
