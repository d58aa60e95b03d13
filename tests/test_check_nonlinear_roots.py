"""The student's nonlinear system solved by SymPy where elimination cannot take it apart: a
system SymPy gives up on means "no root found", never an internal error (an ``except`` clause
that named an mpmath error mpmath does not have turned every such give-up into a traceback)."""

from __future__ import annotations

import sympy

from derive.checking import relations


def test_a_system_sympy_cannot_solve_has_no_roots(monkeypatch) -> None:
    x, y = sympy.symbols("x y")

    def gives_up(*args, **kwargs):
        raise NotImplementedError("no algorithm")

    relations._nonlinear_roots.cache_clear()  # kept for the process: solve these afresh
    monkeypatch.setattr(relations, "polynomial_roots", lambda eqs, U: None)
    monkeypatch.setattr(relations.sympy, "solve", gives_up)
    try:
        assert relations.nonlinear_roots([x**2 + y**2 - 1, x - y], (x, y)) == []
    finally:
        relations._nonlinear_roots.cache_clear()  # no given-up answer left for later tests


def test_a_system_elimination_cannot_take_apart_is_still_solved(monkeypatch) -> None:
    # x^2 + y^2 = 1 and x = y: x = y = ±1/√2 (worked by hand), through SymPy's solve.
    x, y = sympy.symbols("x y")
    relations._nonlinear_roots.cache_clear()
    monkeypatch.setattr(relations, "polynomial_roots", lambda eqs, U: None)
    roots = relations.nonlinear_roots([x**2 + y**2 - 1, x - y], (x, y))
    assert sorted(round(float(r[x]), 6) for r in roots) == [-0.707107, 0.707107]
    assert all(abs(float(r[x] - r[y])) < 1e-12 for r in roots)
