"""A root search that does not converge (mpmath's NoConvergence, raised inside SymPy's solve)
finds no root; it is no internal error. ``mpmath.NoConvergence`` is not an attribute of mpmath
(it is ``mpmath.libmp.NoConvergence``): naming it so in an ``except`` turned any exception that
passed through there (the time budget's interrupt among them) into an AttributeError, and the
report into "internal error" (corpus u09 and l10 on a loaded machine)."""

from __future__ import annotations

import mpmath
import pytest
import sympy

from derive.checking import relations


def test_no_convergence_in_the_solve_finds_no_root(monkeypatch: pytest.MonkeyPatch) -> None:
    def fails(*_args: object, **_kwargs: object) -> None:
        raise mpmath.libmp.NoConvergence("no root")

    monkeypatch.setattr(relations, "polynomial_roots", lambda eqs, U: None)
    monkeypatch.setattr(sympy, "solve", fails)
    x, y = sympy.symbols("x y")
    assert relations.nonlinear_roots([x**2 + y**2 - 1, x * y - sympy.Rational(1, 3)], (x, y)) == []


def test_another_exception_through_the_solve_is_not_turned_into_an_attribute_error(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    def interrupted(*_args: object, **_kwargs: object) -> None:
        raise KeyboardInterrupt  # a BaseException, as the time budget's interrupt is

    monkeypatch.setattr(relations, "polynomial_roots", lambda eqs, U: None)
    monkeypatch.setattr(sympy, "solve", interrupted)
    x, y = sympy.symbols("x y")
    with pytest.raises(KeyboardInterrupt):
        relations.nonlinear_roots([x**2 + y**2 - 1, x * y], (x, y))
