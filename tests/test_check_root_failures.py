"""SymPy's ``solve`` failing inside :func:`derive.checking.relations.nonlinear_roots` gives no roots,
and an exception it does not expect (the checker's own time budget) passes through as itself:
mpmath names its ``NoConvergence`` in ``mpmath.libmp`` only, so naming it ``mpmath.NoConvergence``
in the ``except`` raised AttributeError whenever anything at all was raised inside ``solve``."""

from __future__ import annotations

import pytest
import sympy

from derive.checking import relations


@pytest.fixture(autouse=True)
def _solved_afresh():
    """The roots are kept for the process: each test here solves its system afresh and leaves
    no given-up answer behind for later tests."""
    relations._nonlinear_roots.cache_clear()
    yield
    relations._nonlinear_roots.cache_clear()


class _Budget(Exception):
    """Stands for the checker's time budget running out (raised from deep inside SymPy)."""


@pytest.mark.parametrize("error", [NotImplementedError, ValueError, TypeError])
def test_a_solve_that_fails_gives_no_roots(monkeypatch: pytest.MonkeyPatch, error: type) -> None:
    def fails(*_args: object, **_kw: object) -> list:
        raise error("no solution found")

    monkeypatch.setattr(relations, "polynomial_roots", lambda eqs, U: None)
    monkeypatch.setattr(relations.sympy, "solve", fails)
    x, y = sympy.symbols("x y")
    assert relations.nonlinear_roots([x**5 + x * y - 1, y - x], (x, y)) == []


def test_an_exception_solve_does_not_expect_passes_through(monkeypatch: pytest.MonkeyPatch) -> None:
    def runs_out(*_args: object, **_kw: object) -> list:
        raise _Budget

    monkeypatch.setattr(relations, "polynomial_roots", lambda eqs, U: None)
    monkeypatch.setattr(relations.sympy, "solve", runs_out)
    x, y = sympy.symbols("x y")
    with pytest.raises(_Budget):
        relations.nonlinear_roots([x**5 + x * y - 1, y - x], (x, y))
