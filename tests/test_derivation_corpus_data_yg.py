"""The yg batch of typed derivations (tenth session): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the yg cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, components of a velocity, weights over g, a fall, a
bounce and a rise, an impulse), with the student's slip made on purpose for the slip values.
Answers in letters (u, e) are checked at a few points with closed_form. Nothing here runs derive's
checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _bounce, _given, _solve, batch_shape, closed_form

YG_CASES = [c for c in CASES if c.name.startswith("yg")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))


def _case(prefix: str):
    return next(c for c in YG_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _yg01(g: dict) -> tuple[dict, None]:
    b_n, b_t = g["v_B1"] * math.cos(math.radians(60)), g["v_B1"] * math.sin(math.radians(60))
    # m_A v1 + m_B b_n = m_B w with w = e (v1 - b_n): (m_A - e m_B) v1 = -m_B b_n (1 + e)
    v1 = -g["m_B"] * b_n * (1 + g["e"]) / (g["m_A"] - g["e"] * g["m_B"])
    w = g["e"] * (v1 - b_n)
    beta = math.degrees(math.atan(b_t / w))
    return {"v_A1n": v1, "v_B2": math.sqrt(w * w + b_t * b_t), "beta_B2": beta, "delta_B": 60 - beta}, None


def _yg02(g: dict) -> tuple[dict, None]:
    v_a = (g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B2"]) / g["m_A"]
    return {"v_A2": v_a, "e": (g["v_B2"] - v_a) / (g["v_A1"] - 0.0)}, None


def _yg04(g: dict) -> tuple[dict, None]:
    v = (g["W_A"] * g["v_A1"] + g["W_B"] * g["v_B1"]) / (g["W_A"] + g["W_B"])  # g cancels
    return {"v_A2": v, "v_B2": v}, None


def _yg05(g: dict) -> tuple[dict, None]:
    v_a, v_b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1"], g["e"] * g["v_A1"])
    return {"v_A2": v_a, "v_B2": v_b}, None


def _yg06(g: dict) -> tuple[dict, dict]:
    m1, m2, v1 = g["m_A"], g["m_B"], g["v_A1"]
    true = {"v_A2": (m1 - m2) / (m1 + m2) * v1, "v_B2": 2 * m1 / (m1 + m2) * v1}
    return true, {"v_A2": -68.85 / (m1 + m2) * v1}  # 0.150 - 70.0 written -68.85


def _yg07(g: dict) -> tuple[dict, dict]:
    v_bx = g["v_B1t"] / math.tan(math.radians(45))
    v_ax = (g["m_A"] * g["v_A1n"] - g["m_B"] * v_bx) / g["m_A"]
    approach = g["v_A1n"] - g["v_B1n"]
    speed_b = g["v_B1t"] / math.cos(math.radians(45))  # B's whole speed put in NEL
    return {"v_B2n": v_bx, "v_A2": abs(v_ax), "e": (v_bx - v_ax) / approach}, {"e": (speed_b - v_ax) / approach}


def _yg09(g: dict) -> tuple[dict, dict]:
    def worked(c: float, s: float) -> dict:
        a_n, a_t, b_n, b_t = g["v_A1"] * c, g["v_A1"] * s, -g["v_B1"] * c, -g["v_B1"] * s
        gap = g["e"] * (a_n - b_n)
        v_an = (g["m_A"] * a_n + g["m_B"] * b_n - g["m_B"] * gap) / (g["m_A"] + g["m_B"])
        return {"v_A2t": a_t, "v_B2t": b_t, "v_A2n": v_an, "v_B2n": v_an + gap}

    degrees, radians = math.radians(g["theta"]), g["theta"]  # the slip: 37.6 read as radians
    return worked(math.cos(degrees), math.sin(degrees)), worked(math.cos(radians), math.sin(radians))


def _yg10(g: dict) -> tuple[dict, dict]:
    n, t = math.sin(math.radians(g["theta_1"])), math.cos(math.radians(g["theta_1"]))  # per unit v
    diff = n - g["e"] * n  # (vAn' + vB') - (vB' - vAn') = 2 vAn'
    true, slipped = diff / 2, diff  # the 2 dropped
    return (
        {"theta_A2": math.degrees(math.atan(true / t)), "v_A2n_per_v_A1": true},
        {"theta_A2": math.degrees(math.atan(slipped / t)), "v_A2n_per_v_A1": slipped},
    )


def _yg12(g: dict) -> tuple[dict, dict]:
    u_a, u_b, v_a, v_b, m_b = g["v_A1"], g["v_B1"], g["v_A2"], g["v_B2"], g["m_B"]
    true = {"e": (v_b - v_a) / (u_a - u_b), "m_A": m_b * (v_b - u_b) / (u_a - v_a)}
    # slip 1: 2.9 copied as 2.5 in NEL; slip 2: m(3 - 2) = 0.58 - 0.3 (B's -0.3 moved across unchanged)
    # 3m + m_B u_B = 2m + m_B v_B with m_B u_B left on its side's sign when moved: m = m_B v_B + m_B u_B
    slipped = {"e": (2.5 - v_a) / (u_a - u_b), "m_A": (m_b * v_b + m_b * u_b) / (u_a - v_a)}
    return true, slipped


def _yg13(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u = g["m_A"], g["m_B"], g["v_A1"]

    def worked(total: float, t_1: float) -> dict:
        v = m_a * u / total
        t_2 = 0.5 * total * v * v
        return {"v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    return worked(m_a + m_b, 0.5 * m_a * u * u), worked(71.5, 0.5 * m_a * u)  # 71.5 for 70.15; u not squared


def _yg14(g: dict) -> tuple[dict, None]:
    m_a = g["m_B"] * (g["s_B"] + g["v_B"]) / (g["v_A"] - g["s_A"])
    w = g["I_w"] / g["m_B"] - g["s_B"]  # 0.68 = 0.2 (w + 2.9)
    e = (g["s_B"] - g["s_A"]) / (g["v_A"] + g["v_B"])
    return {"e": e, "m_A": m_a, "u_B": g["s_B"], "w_B": -w, "e_wall": w / g["s_B"]}, None


def _yg15(g: dict) -> tuple[dict, dict]:
    true = _bounce(g, math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"]))
    slipped = _bounce(g, math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"] / 10))  # 31.36 written 3.136
    return true, slipped


NUMERIC_YG: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yg01": _yg01,
    "yg02": _yg02,
    "yg04": _yg04,
    "yg05": _yg05,
    "yg06": _yg06,
    "yg07": _yg07,
    "yg09": _yg09,
    "yg10": _yg10,
    "yg12": _yg12,
    "yg13": _yg13,
    "yg14": _yg14,
    "yg15": _yg15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None), masses in units of m ----


def _yg03(u: float, e: float) -> tuple[dict, None]:
    along = u * math.cos(math.radians(60))
    _, w = _solve(1.0, 1.0, along, e * along)
    return {"v_B2": w}, None


def _yg08(u: float, _e: float) -> tuple[dict, dict]:
    e = 2 / 3
    true = _solve(2.0, 1.0, 4 * u, e * 2 * u)
    slipped = _solve(1.0, 2.0, 4 * u, e * 2 * u)  # 2m and m exchanged after the impact
    return {"v_A2": true[0], "v_B2": true[1]}, {"v_A2": slipped[0], "v_B2": slipped[1]}


def _yg11(u: float, e: float) -> tuple[dict, dict]:
    v_a, v_b = _solve(3.0, 6.0, 3 * u, e * u)
    before = 0.5 * 3 * u * u
    after = 0.5 * 3 * v_a**2 + 0.5 * 6 * v_b**2
    after_slipped = 3 * v_a**2 + 6 * v_b**2  # the 1/2 left out after
    return (
        {"v_A2": v_a, "v_B2": v_b, "T_lost": before - after},
        {"T_2": after_slipped, "T_lost": before - after_slipped},
    )


SYMBOLIC_YG: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "yg03": _yg03,
    "yg08": _yg08,
    "yg11": _yg11,
}


def test_every_yg_case_is_worked_here() -> None:
    batch_shape(YG_CASES, set(NUMERIC_YG) | set(SYMBOLIC_YG))
    one_slip_names = [s.name for c in YG_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slip_names) == len(set(one_slip_names)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YG))
def test_the_yg_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YG[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YG))
def test_the_yg_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_YG[prefix](u, e)
        names = {"u": u, "e": e}
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9), name
