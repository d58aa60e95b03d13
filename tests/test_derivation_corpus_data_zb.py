"""The zb batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zb cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, Newton's
law of restitution, impulse, a fall and a rise under gravity), with the student's slip made on
purpose for the slip values. Letters (u, e, m, alpha) are checked at a few points. Nothing here
runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

ZB_CASES = [c for c in CASES if c.name.startswith("zb")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters
LETTERS = {"m": 1.7, "alpha": 0.6}  # the other letters, at one point


def _case(prefix: str):
    return next(c for c in ZB_CASES if c.name.startswith(prefix))


def _pair(values: tuple[float, float]) -> dict:
    return dict(zip(("v_A2", "v_B2"), values, strict=True))


# ---- numeric problems: prefix -> givens -> (true values, slip values or None) ----


def _zb03(g: dict) -> tuple[dict, None]:
    m_a, m_b = g["W_A"] / 32.2, g["W_B"] / 32.2
    u = g["v_A1"]
    return _pair(_solve(m_a, m_b, m_a * u, g["e"] * u)), None


def _zb04(g: dict) -> tuple[dict, None]:
    w_b = g["v_B1t"] / math.tan(math.radians(45))
    w_a = (g["m_A"] * g["v_A1n"] - g["m_B"] * w_b) / g["m_A"]
    return {"e": (w_b - w_a) / g["v_A1n"], "v_B2n": w_b, "v_A2": abs(w_a)}, None


def _zb08(g: dict) -> tuple[dict, dict]:
    gap = g["e"] * (g["v_A1n"] - g["v_B1n"])
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1n"] + g["m_B"] * g["v_B1n"], gap)
    t = g["v_A1t"]
    true = {"v_A2n": a, "v_B2n": b, "v_A2t": t, "v_A2": math.hypot(a, t), "v_B2": abs(b)}
    s_a, s_b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_B1n"], gap)  # B's momentum with A's mass
    return true, {"v_A2n": s_a, "v_B2n": s_b, "v_A2": math.hypot(s_a, t), "v_B2": abs(s_b)}


def _zb10(g: dict) -> tuple[dict, dict]:
    alpha = math.radians(g["alpha"])
    b_n, b_t = -g["u_B"] * math.cos(alpha), g["u_B"] * math.sin(alpha)
    w_b = b_t / math.tan(math.pi / 2 - alpha)  # B's path turned through 90 deg: 60 deg to the line
    v_a = g["v_A1n"] + b_n - w_b  # equal masses
    true = {"v_B2": math.hypot(b_t, w_b), "v_A2n": v_a, "e": (w_b - v_a) / (g["v_A1n"] - b_n)}
    return true, {"e": (w_b - v_a) / (g["v_A1n"] + g["u_B"])}  # B's speed in the approach


def _zb13(g: dict) -> tuple[dict, dict]:
    u, e = g["v_A1"], g["e"]

    def energies(m_a: float, m_b: float, v_a: float, v_b: float) -> dict:
        t_1, t_2 = 0.5 * m_a * u**2, 0.5 * m_a * v_a**2 + 0.5 * m_b * v_b**2
        return {"v_A2": v_a, "v_B2": v_b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    true = energies(g["W_A"] / 32.2, g["W_B"] / 32.2, *_solve(g["W_A"], g["W_B"], g["W_A"] * u, e * u))
    slip_gap = e * u - 0.1  # slip 1: 0.3 x 19.657 worked as 5.797
    slipped = _solve(g["W_A"], g["W_B"], g["W_A"] * u, slip_gap)
    return true, energies(g["W_A"], g["W_B"], *slipped)  # slip 2: the weights as masses


def _zb14(g: dict) -> tuple[dict, None]:
    one_plus_e = math.sqrt(4 * g["v_C"] / g["v_0"])  # v_C = v_0 (1 + e)^2 / 4
    u_b = _solve(1.0, 1.0, g["v_0"], (one_plus_e - 1) * g["v_0"])[1]
    assert _solve(1.0, 1.0, u_b, (one_plus_e - 1) * u_b)[1] == pytest.approx(g["v_C"])
    return {"u_B": u_b, "e": one_plus_e - 1}, None


def _zb15(g: dict) -> tuple[dict, dict]:
    v_2 = math.sqrt(2 * g["g"] * g["h_r"])

    def after(v_1: float) -> dict:
        return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}

    return after(math.sqrt(2 * g["g"] * g["h_0"])), after(math.sqrt(g["g"] * g["h_0"]))  # 2gh = 19.6


NUMERIC_ZB: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zb03": _zb03,
    "zb04": _zb04,
    "zb08": _zb08,
    "zb10": _zb10,
    "zb13": _zb13,
    "zb14": _zb14,
    "zb15": _zb15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None) ----


def _zb01(u: float, e: float) -> tuple[dict, None]:
    assert 2 * 2 * u + 4 * (-u) == 0  # the centre of mass is at rest
    return _pair(_solve(2.0, 4.0, 0.0, e * 3 * u)), None


def _zb02(u: float, _e: float) -> tuple[dict, None]:
    return _pair(_solve(2.0, 1.0, 2 * u, u / 3)), None


def _zb05(u: float, e: float) -> tuple[dict, None]:
    a_n = u * math.cos(math.radians(30))
    v_1 = _solve(1.0, 1.0, a_n, e * a_n)[0]
    deflection = math.atan2(u / 2, v_1) - math.radians(30)
    assert math.tan(deflection) == pytest.approx(math.sqrt(3) * (1 + e) / (5 - 3 * e))
    return {"v_A2n": v_1}, None


def _zb06(u: float, e: float) -> tuple[dict, dict]:
    p = 5 * u + 7 * u
    return _pair(_solve(1.0, 7.0, p, e * 4 * u)), _pair(_solve(1.0, 7.0, p, -e * 4 * u))  # v1 - v2 = 4eu


def _zb07(u: float, _e: float) -> tuple[dict, dict]:
    s_a = (4 * u + 5 * u / 2) / 9  # 5u/2 moved across without its sign changing
    return _pair(_solve(4.0, 5.0, 4 * u, u / 2)), {"v_A2": s_a, "v_B2": s_a + u / 2}


def _zb09(u: float, _e: float) -> tuple[dict, dict]:
    m = LETTERS["m"]
    v_a, v_b = 2 * u - 4 * m * u / (3 * m), -u + 4 * m * u / m
    t_1 = 0.5 * 3 * m * (2 * u) ** 2 + 0.5 * m * u**2
    s_b = u + 4 * m * u / m  # B's velocity before taken as +u
    s_t2 = 0.5 * 3 * m * v_a**2 + 0.5 * m * s_b**2
    true_t2 = 0.5 * 3 * m * v_a**2 + 0.5 * m * v_b**2
    assert t_1 - true_t2 == pytest.approx(4 / 3 * m * u**2)  # the printed answer
    return {"v_A2": v_a, "v_B2": v_b}, {"v_B2": s_b, "T_2": s_t2, "T_lost": t_1 - s_t2}


def _zb11(u: float, e: float) -> tuple[dict, dict]:
    alpha = LETTERS["alpha"]
    along, normal = u * math.cos(alpha), u * math.sin(alpha)
    true = math.atan2(e * normal, along)
    slipped = math.atan2(normal, e * along)  # e on the component along the cushion
    return {"beta": true}, {"beta": slipped}


def _zb12(u: float, _e: float) -> tuple[dict, dict]:
    # slip 1: x - y = u/3; slip 2: 3y = 2u - 2u/3 worked as 5u/3
    y = (5 * u / 3) / 3
    return _pair(_solve(2.0, 1.0, 2 * u, u / 3)), {"v_A2": y + u / 3, "v_B2": y}


SYMBOLIC_ZB: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "zb01": _zb01,
    "zb02": _zb02,
    "zb05": _zb05,
    "zb06": _zb06,
    "zb07": _zb07,
    "zb09": _zb09,
    "zb11": _zb11,
    "zb12": _zb12,
}


def test_every_zb_case_is_worked_here() -> None:
    assert len(ZB_CASES) == 15
    assert {c.name[:4] for c in ZB_CASES} == set(NUMERIC_ZB) | set(SYMBOLIC_ZB)
    by_category = sorted(c.verdict.category for c in ZB_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZB_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZB))
def test_the_zb_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZB[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZB))
def test_the_zb_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_ZB[prefix](u, e)
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, LETTERS) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, LETTERS) == pytest.approx(slipped[name], rel=1e-9), name
