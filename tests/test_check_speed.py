"""The work of checking a derivation is bounded (issue #31, item 8: every report in under 10 s).

Not timed tests: each asserts what bounds the work. A polynomial system is taken apart by
elimination (no Gröbner basis over floats, which took minutes for three equations of an
inverse problem); an equation in some of the symbolic givens is solved with the others at
numbers for every given; the mistakes' directions are numbers; and a budget that runs out
leaves lines "not checked" while the report of the others comes back.

The numbers are worked by hand: CAIE 9231/2 June 2014 Q3 (A of mass m at u hits B of mass 9m
at rest, half the kinetic energy lost): x + 9y = u, y - x = e u, x^2 + 9y^2 = u^2/2, so
(1 - 9e)^2 + 9(1 + e)^2 = 50, 90e^2 = 40, e = 2/3, x = -u/2, y = u/6; the other root e = -2/3
(x = 7u/10, y = u/30: the mark scheme's other pair; y - x = -2u/3).
"""

from __future__ import annotations

import time
from pathlib import Path

import pytest
import sympy

import derive
from derive.checking import budget
from derive.checking.context import Context
from derive.checking.equation import relation
from derive.checking.polyroots import polynomial_roots

HALF_KE = "cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost"
CORPUS = Path(__file__).resolve().parent / "data" / "derivations"
x, y, e = sympy.symbols("v_A2 v_B2 e")


@pytest.fixture(scope="module")
def half_ke() -> derive.Solution:
    return derive.solve(derive.load(HALF_KE))


@pytest.fixture
def no_float_solve(monkeypatch: pytest.MonkeyPatch) -> list:
    """SymPy's solve, refusing a system with floats in it (a Gröbner basis over floats)."""
    calls: list = []
    real = sympy.solve

    def solve(eqs, *args, **kwargs):  # type: ignore[no-untyped-def]
        eqs_list = eqs if isinstance(eqs, list | tuple) else [eqs]
        floats = any(sympy.sympify(q).atoms(sympy.Float) for q in eqs_list)
        calls.append(floats)
        assert not floats, f"SymPy asked to solve a system of floats: {eqs}"
        return real(eqs, *args, **kwargs)

    monkeypatch.setattr(sympy, "solve", solve)
    return calls


def _roots(found: list[dict]) -> set[tuple[float, ...]]:
    return {tuple(round(r[s].real, 9) for s in (x, y, e)) for r in found}


def test_the_find_e_system_is_taken_apart_by_elimination() -> None:
    u = sympy.Float(1, 30)
    eqs = [u - x - 9 * y, e * u + x - y, u**2 / 4 - x**2 / 2 - 9 * y**2 / 2]  # m = 1
    found = polynomial_roots(eqs, (x, y, e))
    assert found is not None
    assert _roots(found) == {(-0.5, round(1 / 6, 9), round(2 / 3, 9)), (0.7, round(1 / 30, 9), round(-2 / 3, 9))}


def test_an_equation_in_e_alone_takes_the_place_of_one() -> None:
    # the student's (1 - 9e)^2 + 9(1 + e)^2 = 50 with momentum and restitution (u = 1)
    eqs = [1 - x - 9 * y, e + x - y, sympy.Float(1) * ((1 - 9 * e) ** 2 + 9 * (1 + e) ** 2 - 50)]
    assert _roots(polynomial_roots(eqs, (x, y, e)) or []) == {
        (-0.5, round(1 / 6, 9), round(2 / 3, 9)),
        (0.7, round(1 / 30, 9), round(-2 / 3, 9)),
    }


def test_no_single_root_none_at_all_and_what_it_cannot_take_apart() -> None:
    # two equations in e alone, nothing fixes x and y apart: no single root
    assert polynomial_roots([90 * e**2 - 40, x - y + e, 9 * e**2 - 4], (x, y, e)) == []
    assert polynomial_roots([x + y - 1, x + y - 2, e - 1], (x, y, e)) == []  # inconsistent
    assert polynomial_roots([sympy.sin(e) - x, x - y, y - 1], (x, y, e)) is None  # not polynomial


def test_a_cubic_in_one_unknown() -> None:
    found = polynomial_roots([x**3 - 2 * x + 1, y - x, e - 2], (x, y, e))  # (x - 1)(x^2 + x - 1)
    golden = (5**0.5 - 1) / 2
    assert sorted(round(r[x].real, 9) for r in found or []) == sorted(round(v, 9) for v in (1, golden, -1 - golden))


def test_an_equation_is_solved_with_numbers_for_every_symbolic_given(half_ke: derive.Solution) -> None:
    ctx = Context(half_ke, None)
    eq = relation(ctx, "(1 - 9e)^2 + 9(1 + e)^2 = 50", "", (1 - 9 * e) ** 2 + 9 * (1 + e) ** 2 - 50)
    names = {s.name for pt in eq.pts for s in pt}
    assert {"m", "u"} <= names, "the system it is solved with has m and u: they need numbers"


def test_the_mark_schemes_equation_is_right_without_a_float_groebner(half_ke, no_float_solve) -> None:
    report = derive.check(half_ke, {}, equations={"": "(1 - 9*e)^2 + 9*(1 + e)^2 = 50"})
    assert report.items[0].status == "correct"
    wrong = derive.check(half_ke, {}, equations={"": "(1 - 9*e)^2 + 9*(1 + e)^2 = 25"})
    assert wrong.items[0].status == "wrong"


def test_the_find_e_derivation_reports_its_slip_and_carries_it(half_ke, no_float_solve) -> None:
    text = (CORPUS / "n18-cie-2014-half-ke-arithmetic.tex").read_text(encoding="utf-8")
    report = derive.check(half_ke, {}, derivation=text)
    status = {i.name: i.status for i in report.items}
    # 25 for 50: 90e^2 = 15, e = 1/sqrt(6) = 0.408, x = -0.267u, y = 0.141u, carried
    assert status["13"] == "wrong"
    assert [status[n] for n in ("14", "15", "16", "18")] == ["carried"] * 4


def test_the_mistakes_directions_are_numbers() -> None:
    """FisicaLab Example 7 (d): A leaves at 100.326° from x, B at 77.172°; the common normal is at
    20° from x, so beta (from +n toward +t) is 80.326° and 57.172°."""
    import importlib

    outcomes = importlib.import_module("derive.checking.mistakes.outcomes")
    solution = derive.solve(derive.load("fisicalab-example-7-normal-at-20deg"))
    base = outcomes.correct(solution)
    assert base is not None
    assert float(base.results["beta_A2"].value) == pytest.approx(80.326, abs=1e-3)
    assert float(base.results["beta_B2"].value) == pytest.approx(57.172, abs=1e-3)
    for out in [base, *outcomes.pair_outcomes(solution)]:
        for name, q in out.results.items():
            if name.startswith(("alpha", "gamma", "delta", "beta", "theta")) and q.value is not None:
                assert isinstance(q.value, sympy.Float), (name, q.value)


def test_a_line_still_being_judged_when_the_budget_runs_out_is_not_checked(monkeypatch) -> None:
    monkeypatch.setattr(budget, "CPU_SECONDS", 0.2)

    def judge(n: int) -> str:
        if n == 2:
            while True:  # a line that would never finish
                sum(range(1000))
        return f"judged {n}"

    out = budget.judged(judge, [1, 2, 3], lambda n, why: f"not checked {n}: {why[:12]}")
    assert out == ["judged 1", "not checked 2: Not checked:", "not checked 3: Not checked:"]


def test_out_of_time_the_report_still_comes_back(monkeypatch) -> None:
    solution = derive.solve(derive.load("notes-4c11-two-spheres"))
    text = "v_A2t = 5 sin 37.6° = 3.05\nv_B2t = -15 sin 37.6° = -9.15\n"
    monkeypatch.setattr(budget, "CPU_SECONDS", 0.0)
    report = derive.check(solution, {}, derivation=text)
    assert [i.status for i in report.items] == ["not checked", "not checked"]
    assert "2 not checked (out of time)" in report.summary()
    assert report.exit_code == 0 and report.as_dict()["counts"]["not checked"] == 2


def test_the_budget_is_of_cpu_time_not_of_a_busy_machine(monkeypatch) -> None:
    """Waiting (another process has the core) does not use up the budget."""
    monkeypatch.setattr(budget, "CPU_SECONDS", 0.3)
    out = budget.judged(lambda n: time.sleep(0.2) or n, [1, 2, 3], lambda n, why: None)
    assert out == [1, 2, 3]


def test_an_unknown_given_angle_is_judged_once(monkeypatch) -> None:
    """Edexcel M4 2018 (find alpha): `alpha = tan^-1(3.266) = 1.27°` (radian mode) is judged as
    an answer once, not first as a direction of the impact and then again."""
    from derive.checking import lines

    solution = derive.solve(derive.load("edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke"))
    calls: list[str] = []
    real = lines.Trace._answer

    def answer(self, line):  # type: ignore[no-untyped-def]
        calls.append(line.written)
        return real(self, line)

    monkeypatch.setattr(lines.Trace, "_answer", answer)
    report = derive.check(solution, {}, derivation="tan(alpha) = sqrt(32/3) = 3.266\nalpha = tan^-1(3.266) = 1.27°\n")
    assert report.items[1].slip == "degrees_as_radians"
    assert calls.count("alpha = tan^-1(3.266) = 1.27°") <= 1


def test_a_slips_system_is_solved_once_for_all_the_rules(monkeypatch: pytest.MonkeyPatch) -> None:
    """The rules that explain a slip (solves correctly? as a common mistake? with a pair?) each
    solve the equations with the slip in place of (k): each system is solved once."""
    from derive.checking import relations

    real, calls = relations._solve_with, []
    monkeypatch.setattr(
        relations, "_solve_with", lambda F, eqs, k, U, pts: calls.append((F, k)) or real(F, eqs, k, U, pts)
    )
    relations._SOLVED.clear()
    # OCR M2 2014 (2m at 4, 3m at 2 toward it): 2vA + 3vB = 8 - 6 = 2; 5 is no common mistake's
    work = "2vA + 3vB = 5\nvB - vA = 2.4\n"
    report = derive.check(derive.solve(derive.load("ocr-m2-2014-particles-2m-3m-ke-lost")), derivation=work)
    assert report.items[0].status == "wrong", report.text()
    assert calls and len(calls) == len(set(calls)), calls
