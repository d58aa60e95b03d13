"""The l batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the l cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, Newton's
law of restitution, a wall's rebound, the work of friction in a skid), with the student's slip made
on purpose for the slip values. Letters (u, e) are checked at a few points. Nothing here runs
derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

L_CASES = [c for c in CASES if c.name.startswith("l")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters


def _case(prefix: str):
    return next(c for c in L_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> givens -> (true values, slip values or None) ----


def _l01(g: dict) -> tuple[dict, None]:
    m, big_m, u = g["m_A"], g["m_B"], g["v_A1"]
    v = m * u / (m + big_m)
    t_2 = 0.5 * (m + big_m) * v**2
    mu = m * big_m / (m + big_m)
    assert 0.5 * mu * u**2 == pytest.approx(0.5 * m * u**2 - t_2)  # the reduced-mass loss
    return {"v_B2": v, "T_2": t_2, "T_lost": 0.5 * mu * u**2}, None


def _l03(g: dict) -> tuple[dict, None]:
    m_b = g["m_A"] * g["v_A1"] / g["v_A2"] - g["m_A"]  # 1200 x 10 = (1200 + M) 6
    return {"m_B": m_b, "e": (g["v_B2"] - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _l04(g: dict) -> tuple[dict, None]:
    m_a, m_b = g["W_A"] / 32.2, g["W_B"] / 32.2
    v = (m_a * g["v_A1"] + m_b * g["v_B1"]) / (m_a + m_b)
    t_1 = 0.5 * m_a * g["v_A1"] ** 2 + 0.5 * m_b * g["v_B1"] ** 2
    t_2 = 0.5 * (m_a + m_b) * v**2
    return {"v_A2": v, "v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _l06(g: dict) -> tuple[dict, dict]:
    m, u = g["m_A"], g["v_A1"]
    v = -g["e"] * u  # the rebound, toward the wall positive
    true = {"v_A2": v, "J_n": m * (u - v), "T_lost": 0.5 * m * (u**2 - v**2)}
    return true, {"T_lost": 0.5 * m * (u - abs(v)) ** 2}  # 1/2 m (u - v)^2 with the speeds


def _l07(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B2"]  # = m_A (v_A)_2
    v_a = p / g["m_A"]
    e = (g["v_B2"] - v_a) / (g["v_A1"] - g["v_B1"])
    s_a = -v_a  # (10.5 - 10)/20: the sign lost in rearranging
    return {"v_A2": v_a, "e": e}, {"v_A2": s_a, "e": (g["v_B2"] - s_a) / g["v_A1"]}


def _l09(g: dict) -> tuple[dict, dict]:
    v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_A"] * g["v_A2"]) / g["m_B"]
    sep = v_b - g["v_A2"]
    return {"v_B2": v_b, "e": sep / (g["v_A1"] - g["v_B1"])}, {"e": sep / (g["v_A1"] + g["v_B1"])}


def _l10(g: dict) -> tuple[dict, dict]:
    e = 0.75  # the problem's "3/4"
    assert g["e"] == pytest.approx(e)
    # alpha from the wall: U cos kept, e U sin: cos^2 + e^2 sin^2 = 3/5
    sin2 = (1 - 0.6) / (1 - e**2)
    true = math.degrees(math.asin(math.sqrt(sin2)))
    slipped = math.degrees(math.acos(math.sqrt(sin2)))  # the components swapped: cos^2 = 32/35
    return {"alpha": true}, {"alpha": slipped}


def _l11(g: dict) -> tuple[dict, None]:
    u_a, u_b, v_a, v_b = g["v_A"], -g["v_B"], g["s_A"], g["s_B"]
    m_a = g["m_B"] * (v_b - u_b) / (u_a - v_a)
    w = g["I_w"] / g["m_B"] - g["s_B"]  # 0.68 = 0.2 (w + 2.9)
    return {"e": (v_b - v_a) / (u_a - u_b), "m_A": m_a, "e_wall": w / g["s_B"]}, None


def _l12(g: dict) -> tuple[dict, dict]:
    def car(v_common: float) -> float:
        return v_common * (g["m_car"] + g["m_suv"]) / g["m_car"]

    v = math.sqrt(2 * g["mu_k"] * g["g"] * g["d_skid"])
    s_v = math.sqrt(g["mu_k"] * g["g"] * g["d_skid"])  # the 2 lost: V^2 = mu g d
    return {"V": v, "v_car": car(v)}, {"V": s_v, "v_car": car(s_v)}


def _l13(g: dict) -> tuple[dict, dict]:
    u_a, u_b, v_a, v_b, m_b = g["v_A1"], g["v_B1"], g["v_A2"], g["v_B2"], g["m_B"]
    true = {"m_A": m_b * (v_b - u_b) / (u_a - v_a), "e": (v_b - v_a) / (u_a - u_b)}
    s_m = m_b * (v_b + u_b) / (u_a - v_a)  # B's momentum before taken +0.2 x 1.5
    return true, {"m_A": s_m, "e": 0.7 / (u_a - u_b)}  # 2.9 - 2 worked as 0.7


def _l14(g: dict) -> tuple[dict, dict]:
    m1, m2, u = g["m_A"], g["m_B"], g["v_A1"]
    v1, v2 = (m1 - m2) / (m1 + m2) * u, 2 * m1 / (m1 + m2) * u
    t_1 = 0.5 * m1 * u**2
    true = {"v_A2": v1, "v_B2": v2, "T_1": t_1, "T_2": 0.5 * m1 * v1**2 + 0.5 * m2 * v2**2}
    s1 = (m2 - m1) / (m1 + m2) * u  # slip 1: m2 - m1
    s2 = 2 * m1 / (m1 + 7.05e3) * u  # slip 2: 7.50e3 copied as 7.05e3
    return true, {"v_A2": s1, "v_B2": s2, "T_2": 0.5 * m1 * s1**2 + 0.5 * m2 * s2**2}


NUMERIC_L: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "l01": _l01,
    "l03": _l03,
    "l04": _l04,
    "l06": _l06,
    "l07": _l07,
    "l09": _l09,
    "l10": _l10,
    "l11": _l11,
    "l12": _l12,
    "l13": _l13,
    "l14": _l14,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None) ----


def _l02(u: float, e: float) -> tuple[dict, None]:
    # left positive: P at -2u, Q at +u; -3u = 2x + y, x - y = 3eu; back to the right: -x, -y
    x = (-3 * u + 3 * e * u) / 3
    y = x - 3 * e * u
    assert (-x, -y) == pytest.approx(_solve(2.0, 1.0, 4 * u - u, e * 3 * u))
    return {"v_A2": -x, "v_B2": -y}, None


def _l05(u: float, e: float) -> tuple[dict, None]:
    v_a, v_b = _solve(2.0, 1.0, 2 * 4 * u - 3 * u, e * 7 * u)
    return {"v_A2": v_a, "v_B2": v_b}, None


def _l08(u: float, e: float) -> tuple[dict, dict]:
    true = _solve(1.0, 2.0, u, e * u)
    slipped = _solve(1.0, 2.0, u, -e * u)  # v_P - v_Q = eu
    return dict(zip(("v_A2", "v_B2"), true, strict=True)), dict(zip(("v_A2", "v_B2"), slipped, strict=True))


def _l15(u: float, e: float) -> tuple[dict, dict]:
    true = _solve(1.0, 1.0, u, e * u)
    s_1 = (u + e * u) / 2  # (1) - (2) with the sign lost: 2 v_1 = u + eu
    return {"v_A2": true[0], "v_B2": true[1]}, {"v_A2": s_1, "v_B2": s_1 + e * u}


SYMBOLIC_L: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "l02": _l02,
    "l05": _l05,
    "l08": _l08,
    "l15": _l15,
}


def test_every_l_case_is_worked_here() -> None:
    assert len(L_CASES) == 15
    assert {c.name[:3] for c in L_CASES} == set(NUMERIC_L) | set(SYMBOLIC_L)
    by_category = sorted(c.verdict.category for c in L_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in L_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_L))
def test_the_l_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_L[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_L))
def test_the_l_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_L[prefix](u, e)
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e) == pytest.approx(slipped[name], rel=1e-9), name
