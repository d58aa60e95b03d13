"""The yc batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the yc cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, Newton's
law of restitution, impulse, the reduced-mass energy loss, a wall's rebound), with the student's
slip made on purpose for the slip values. Letters (u, e, k, lambda, alpha) are checked at a few
points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve, numbers_agree

YC_CASES = [c for c in CASES if c.name.startswith("yc")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters
LETTERS = {"k": 2.5, "lam": 0.3, "alpha": 0.7}  # k, lambda pure numbers; alpha in radians


def _case(prefix: str):
    return next(c for c in YC_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> givens -> (true values, slip values or None) ----


def _yc02(g: dict) -> tuple[dict, None]:
    impulse = g["m_A"] * (g["v_A2"] - g["v_A1"])  # on A; minus that on B (N3L)
    v_b = g["v_B1"] - impulse / g["m_B"]
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _yc06(g: dict) -> tuple[dict, dict]:
    def with_a_after(a_after: float) -> dict:
        v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_A"] * a_after) / g["m_B"]
        return {"v_B2": v_b, "e": (v_b - a_after) / (g["v_A1"] - g["v_B1"])}

    return with_a_after(g["v_A2"]), with_a_after(2.0)  # slip: 0.2 copied as 2


def _yc12(g: dict) -> tuple[dict, dict]:
    def after(a_n: float, a_t: float, p: float) -> dict:
        gap = g["e"] * (a_n - g["v_B1n"])
        x, y = _solve(1.0, 1.0, p, gap)
        return {"v_A2n": x, "v_B2": abs(y), "v_A2": math.hypot(x, a_t)}

    c, s = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    true = after(c, s, c + g["v_B1n"])
    slipped = after(s, c, s - g["v_B1n"])  # sin/cos swapped; B's momentum +3 in CLM
    return true, slipped


def _yc13(g: dict) -> tuple[dict, dict]:
    def v_b(b_before: float) -> float:
        return (g["m_A"] * g["v_A1"] + g["m_B"] * b_before - g["m_A"] * g["v_A2"]) / g["m_B"]

    approach = g["v_A1"] - g["v_B1"]
    true_b, slip_b = v_b(g["v_B1"]), v_b(-g["v_B1"])  # slip 1: B's momentum +0.4(6)
    true = {"v_B2": true_b, "e": (true_b - g["v_A2"]) / approach}
    return true, {"v_B2": slip_b, "e": approach / (slip_b - g["v_A2"])}  # slip 2: e upside down


def _yc14(g: dict) -> tuple[dict, None]:
    u_a, u_b, v_a, v_b = g["v_A"], -g["v_B"], g["s_A"], g["s_B"]
    m_a = g["m_B"] * (v_b - u_b) / (u_a - v_a)
    w = g["I_w"] / g["m_B"] - v_b  # away from the wall
    return {"e": (v_b - v_a) / (u_a - u_b), "m_A": m_a, "u_B": v_b, "w_B": -w, "e_wall": w / v_b}, None


def _yc15(g: dict) -> tuple[dict, dict]:
    def chain(b_in_clm: float) -> dict:
        gap = g["e"] * (g["v_A"] + g["v_B"])
        u_a, u_b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A"] + g["m_B"] * b_in_clm, gap)
        w_b = -g["e_wall"] * u_b
        return {"u_A": u_a, "u_B": u_b, "w_B": w_b, "again": "yes" if w_b < u_a else "no"}

    return chain(-g["v_B"]), chain(g["v_B"])  # slip: B's momentum +0.2(2)


NUMERIC_YC: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yc02": _yc02,
    "yc06": _yc06,
    "yc12": _yc12,
    "yc13": _yc13,
    "yc14": _yc14,
    "yc15": _yc15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None) ----


def _yc01(u: float, e: float) -> tuple[dict, None]:
    x, y = _solve(2.0, 3.0, 10 * u, 5 * e * u)
    return {"v_A2": x, "v_B2": y}, None


def _yc03(u: float, e: float) -> tuple[dict, None]:
    x, y = _solve(3.0, 6.0, 3 * u, e * u)
    lost = 0.5 * 3 * u * u - (0.5 * 3 * x * x + 0.5 * 6 * y * y)  # in units of m
    return {"v_A2": x, "v_B2": y, "T_lost": lost}, None


def _yc04(u: float, _e: float) -> tuple[dict, None]:
    lost = 0.5 * 2 * u * u - 0.75 * u * u
    mu = 2 * 1 / 3
    e = math.sqrt(1 - lost / (0.5 * mu * u * u))
    x, y = _solve(2.0, 1.0, 2 * u, e * u)
    assert 0.5 * 2 * x * x + 0.5 * y * y == pytest.approx(0.75 * u * u)
    return {"v_A2": x, "v_B2": y, "e": e}, None


def _yc05(u: float, _e: float) -> tuple[dict, None]:
    k, lam = LETTERS["k"], LETTERS["lam"]
    w = (u + k * lam * u) / k  # m u + k m lam u = k m w, S at rest
    return {"v_B2": w, "e": w / (u - lam * u)}, None


def _yc07(u: float, e: float) -> tuple[dict, dict]:
    def b_after(along: float) -> float:
        return _solve(1.0, 1.0, along, e * along)[1]

    return {"v_B2": b_after(u * math.cos(math.radians(30)))}, {"v_B2": b_after(u * math.sin(math.radians(30)))}


def _yc08(u: float, _e: float) -> tuple[dict, dict]:
    impulse = 4 * u  # in units of m
    true = {"v_A2": 2 * u - impulse / 3, "v_B2": -u + impulse}
    slipped_b = u + impulse  # the particle of mass m taken at +u
    lost = lambda b: 0.5 * 3 * 4 * u * u + 0.5 * u * u - 0.5 * 3 * true["v_A2"] ** 2 - 0.5 * b * b  # noqa: E731
    assert lost(true["v_B2"]) == pytest.approx(4 / 3 * u * u)
    assert lost(slipped_b) == pytest.approx(-20 / 3 * u * u)
    return true, {"v_B2": slipped_b}


def _yc09(u: float, e: float) -> tuple[dict, dict]:
    along = u * math.cos(math.radians(60))
    return {"v_B2": _solve(1.0, 1.0, along, e * along)[1]}, {"v_B2": _solve(1.0, 1.0, along, -e * along)[1]}


def _yc10(u: float, e: float) -> tuple[dict, dict]:
    alpha = LETTERS["alpha"]
    true = math.atan2(e * u * math.sin(alpha), u * math.cos(alpha))
    slipped = math.atan2(e * u * math.sin(alpha), e * u * math.cos(alpha))
    return {"beta": true}, {"beta": slipped}


def _yc11(u: float, e: float) -> tuple[dict, dict]:
    along = u * math.cos(math.radians(30))
    x = _solve(1.0, 1.0, along, e * along)[0]
    return {"v_A2n": x}, {"v_A2n": (along + e * along) / 2}  # (1) - (2) with e's sign lost


SYMBOLIC_YC: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "yc01": _yc01,
    "yc03": _yc03,
    "yc04": _yc04,
    "yc05": _yc05,
    "yc07": _yc07,
    "yc08": _yc08,
    "yc09": _yc09,
    "yc10": _yc10,
    "yc11": _yc11,
}


def test_every_yc_case_is_worked_here() -> None:
    assert len(YC_CASES) == 15
    assert {c.name[:4] for c in YC_CASES} == set(NUMERIC_YC) | set(SYMBOLIC_YC)
    by_category = sorted(c.verdict.category for c in YC_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in YC_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YC))
def test_the_yc_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YC[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YC))
def test_the_yc_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_YC[prefix](u, e)
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, LETTERS) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, LETTERS) == pytest.approx(slipped[name], rel=1e-9), name
