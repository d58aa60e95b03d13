"""What a check computes once and passes along (issue #31: every report in under 10 s).

A check sets up its problem's impact twice (for the worked solution and for the mistakes'
model): the second time is the first's Impact. The mistakes' systems (:func:`real_roots`) and
the worlds' nonlinear systems (:func:`nonlinear_roots`) are solved once for the process: the
same problem checked again (the corpus, a class's derivations of one problem) solves none of
them again, and what a caller does with the roots it gets does not change the next caller's.

The roots are worked by hand: x^2 = 4 has x = 2 and x = -2; x + 3 = 0 has x = -3 even where x
is declared positive (a mistaken mass or e may come out negative, and is shown); x y = 6 with
x + y = 5 has (2, 3) and (3, 2).
"""

from __future__ import annotations

import re

import mpmath
import pytest
import sympy

import derive
from derive import resources
from derive.checking import budget, relations
from derive.checking.mistakes import model as mistakes_model
from derive.checking.mistakes.equations import real_roots
from derive.physics import impact
from derive.problem import loads
from derive.steps import solve

x = sympy.Symbol("x_speed_cache", real=True)
y = sympy.Symbol("y_speed_cache", real=True)
m = sympy.Symbol("m_speed_cache", positive=True)


def test_a_problem_is_set_up_once_and_a_problem_read_again_found_by_value() -> None:
    impact.setup(derive.load("notes-4c11-two-spheres"))  # set up before, for an equal problem
    p = derive.load("notes-4c11-two-spheres")
    first = impact.setup(p)
    assert impact.setup(p) is first and first.problem is p  # the same object: the same set-up
    q = derive.load("notes-4c11-two-spheres")  # a new object, equal to p: its set-up is p's
    again = impact.setup(q)
    assert again.problem is q and again.closed is first.closed


def _notes_text() -> str:
    return resources.bundled()["notes-4c11-two-spheres"].read_text(encoding="utf-8")


def test_a_problem_read_again_shares_its_solution_and_its_mistakes() -> None:
    first = solve(derive.load("notes-4c11-two-spheres"), steps=False)
    again = solve(derive.load("notes-4c11-two-spheres"), steps=False)
    assert again.problem is not first.problem and again.results is first.results
    assert mistakes_model(again) is mistakes_model(first)


def test_a_problem_changed_in_its_file_is_set_up_afresh() -> None:
    text = _notes_text()
    p = loads(text, path="spheres.toml")
    first = impact.setup(p)
    # m_A 20 kg -> 25 kg: v_B2n = (m_A v_A1n + m_B v_B1n + e m_A (v_A1n - v_B1n)) / (m_A + m_B) grows
    heavier = loads(re.sub(r"(?m)^m_A = .*$", 'm_A = "25 kg"', text, count=1), path="spheres.toml")
    assert heavier != p and impact.setup(heavier).closed is not first.closed
    assert solve(heavier, steps=False).results["v_B2n"].value > solve(p, steps=False).results["v_B2n"].value
    # a comment added: the same physics, but the lines its messages name may move: set up afresh
    commented = impact.setup(loads("# a comment\n" + text, path="spheres.toml"))
    assert commented is not first and commented.closed is not first.closed and commented.closed == first.closed
    # the same text from another file: that file's own
    assert impact.setup(loads(text, path="other.toml")).closed is not first.closed


def test_the_roots_of_a_mistakes_system_are_real_and_kept() -> None:
    assert {r[0][1] for r in real_roots((x**2 - 4,), (x,))} == {2, -2}
    assert real_roots((x**2 - 4,), (x,)) is real_roots((x**2 - 4,), (x,))
    assert [dict(r) for r in real_roots((m + 3,), (m,))] == [{m: -3}]  # declared positive: still found


def test_a_worlds_roots_given_twice_are_fresh_lists() -> None:
    eqs = [x * y - 6, x + y - 5]
    roots = relations.nonlinear_roots(eqs, (x, y))
    assert sorted((float(r[x]), float(r[y])) for r in roots) == [(2.0, 3.0), (3.0, 2.0)]
    roots.sort(key=lambda r: -float(r[x]))
    roots[0][x] = sympy.Integer(99)
    roots.clear()
    again = relations.nonlinear_roots(eqs, (x, y))
    assert sorted((float(r[x]), float(r[y])) for r in again) == [(2.0, 3.0), (3.0, 2.0)]


def _not_polynomial() -> list[sympy.Expr]:
    """A system elimination cannot take apart (an exponential): SymPy's solve is asked."""
    return [sympy.exp(x) - 3 * y, x + y - sympy.Rational(7, 3)]


def test_sympy_giving_up_without_convergence_is_no_root(monkeypatch: pytest.MonkeyPatch) -> None:
    def gives_up(*args, **kwargs):
        raise mpmath.libmp.NoConvergence("no convergence")

    relations._nonlinear_roots.cache_clear()
    monkeypatch.setattr(relations.sympy, "solve", gives_up)
    assert relations.nonlinear_roots(_not_polynomial(), (x, y)) == []
    relations._nonlinear_roots.cache_clear()


def test_the_budget_running_out_inside_the_solve_stops_the_check(monkeypatch: pytest.MonkeyPatch) -> None:
    def out_of_time(*args, **kwargs):
        raise budget.OutOfBudget

    relations._nonlinear_roots.cache_clear()
    monkeypatch.setattr(relations.sympy, "solve", out_of_time)
    with pytest.raises(budget.OutOfBudget):  # not an AttributeError from the except clause
        relations.nonlinear_roots([*_not_polynomial(), x - y], (x, y))
    relations._nonlinear_roots.cache_clear()
