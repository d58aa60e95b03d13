"""The yj batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the yj cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's rebound, kinetic energy, a fall and a rise),
with the student's slip made on purpose for the slip values. Answers in letters (u, e, alpha) are
checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, closed_form, numbers_agree

YJ_CASES = [c for c in CASES if c.name.startswith("yj")]
# (u, e, alpha in radians) for the letters
POINTS = ((1.0, 0.5, 0.3), (2.0, 0.3, 0.7), (1.5, 0.9, 1.2))


def _case(prefix: str):
    return next(c for c in YJ_CASES if c.name.startswith(prefix))


def _ke(m: float, *speeds: float) -> float:
    return sum(0.5 * m * s * s for s in speeds)


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _yj01(g: dict) -> tuple[dict, None]:
    m1, m2 = g["W_A"] / 32.2, g["W_B"] / 32.2
    v = (m1 * g["v_A1"] + m2 * g["v_B1"]) / (m1 + m2)
    return {"v_A2": v, "v_B2": v}, None


def _yj03(g: dict) -> tuple[dict, dict]:
    th = math.radians(g["theta"])

    def worked(along: Callable[[float], float], across: Callable[[float], float]) -> dict:
        a_n, b_n = g["v_A1"] * along(th), -g["v_B1"] * along(th)
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, g["e"] * (a_n - b_n))
        return {"v_A2n": a, "v_B2n": b, "v_A2t": g["v_A1"] * across(th), "v_B2t": -g["v_B1"] * across(th)}

    return worked(math.cos, math.sin), worked(math.sin, math.cos)  # sin and cos swapped for both


def _yj04(g: dict) -> tuple[dict, None]:
    v = -g["e"] * g["v_A1"]
    t_1, t_2 = 0.5 * g["m_A"] * g["v_A1"] ** 2, 0.5 * g["m_A"] * v * v
    return {"v_A2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _yj05(g: dict) -> tuple[dict, dict]:
    def worked(u_b: float) -> dict:
        v = (g["m_A"] * g["v_A1"] + g["m_B"] * u_b) / (g["m_A"] + g["m_B"])
        return {"v_A2": v, "v_B2": v}

    return worked(g["v_B1"]), worked(-0.210)  # 0.120 copied as 0.210


def _yj06(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    v = (p - g["m_A"] * g["v_A2"]) / g["m_B"]
    slipped_v = (6.8) / g["m_B"]  # 7 - 0.1 worked as 6.8
    assert p - g["m_A"] * g["v_A2"] == pytest.approx(6.9)
    approach = g["v_A1"] - g["v_B1"]
    return (
        {"v_B2": v, "e": (v - g["v_A2"]) / approach},
        {"v_B2": slipped_v, "e": approach / (slipped_v - g["v_A2"])},  # upside down
    )


def _yj07(g: dict) -> tuple[dict, dict]:
    al = math.radians(g["alpha"])
    b_n, b_t = -g["u_B"] * math.cos(al), g["u_B"] * math.sin(al)
    v_bn = b_t / math.tan(math.radians(90) - al)  # 60 deg from +n
    v_an = g["v_A1n"] + b_n - v_bn
    true = {"v_B2": math.hypot(v_bn, b_t), "v_A2n": v_an, "e": (v_bn - v_an) / (g["v_A1n"] - b_n)}
    return true, {"e": (v_bn - v_an) / 0.72}  # 0.3 + 0.520 worked as 0.720


def _yj08(_g: dict) -> tuple[dict, dict]:
    e = 0.75
    k = 1 - e * e  # cos^2 + e^2 sin^2 = 1 - k sin^2 = 3/5
    sin2 = (1 - 0.6) / k
    slipped = (1 - 0.6) * k  # multiplied by 7/16 instead of divided
    assert slipped == pytest.approx(7 / 40)
    return {"alpha": math.degrees(math.asin(math.sqrt(sin2)))}, {"alpha": math.degrees(math.asin(math.sqrt(slipped)))}


def _yj13(g: dict) -> tuple[dict, None]:
    t_1, t_2 = 0.5 * g["m_A"] * g["v_A1"] ** 2, 0.5 * g["m_A"] * g["v_A2"] ** 2
    return {"e": -g["v_A2"] / g["v_A1"], "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _yj14(g: dict) -> tuple[dict, None]:
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A"] - g["m_B"] * g["v_B"], g["e"] * (g["v_A"] + g["v_B"]))
    w = -g["e_wall"] * b
    return {"u_A": a, "u_B": b, "w_B": w, "again": "yes" if w < a else "no"}, None


def _yj15(g: dict) -> tuple[dict, dict]:
    v_2 = math.sqrt(2 * g["g"] * g["h_r"])

    def worked(v_1: float) -> dict:
        return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}

    slipped = worked(round(math.sqrt(2 * g["g"] * g["h_0"]), 1))  # 6.26 rounded to 6.3
    del slipped["v_2"]
    return worked(math.sqrt(2 * g["g"] * g["h_0"])), slipped


NUMERIC_YJ: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yj01": _yj01,
    "yj03": _yj03,
    "yj04": _yj04,
    "yj05": _yj05,
    "yj06": _yj06,
    "yj07": _yj07,
    "yj08": _yj08,
    "yj13": _yj13,
    "yj14": _yj14,
    "yj15": _yj15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _yj02(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 2.0, u, e * u)
    sa, sb = _solve(1.0, 2.0, u, -e * u)  # v - w = eu: the separation reversed
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _yj09(p: dict) -> tuple[dict, None]:
    u, e, al = p["u"], p["e"], p["alpha"]
    a_n, a_t = u * math.cos(al), u * math.sin(al)
    x, _y = _solve(1.0, 1.0, a_n, e * a_n)
    beta = math.atan2(a_t, x)
    assert (1 - e) * math.tan(beta) == pytest.approx(2 * math.tan(al))
    return {"v_A2n": x, "beta_A2": beta}, None


def _yj10(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(3.0, 6.0, 3 * u, e * u)
    lost = _ke(3.0, u) - _ke(3.0, a) - _ke(6.0, b)
    no_half = 3 * u * u - (3 * a * a + 6 * b * b)  # m v^2 for the kinetic energy
    return {"v_A2": a, "v_B2": b, "T_lost": lost}, {"T_lost": no_half}


def _yj11(p: dict) -> tuple[dict, None]:
    u = p["u"]
    a, b = _solve(4.0, 5.0, 4 * u, 0.5 * u)
    assert b == pytest.approx(4 * a)
    return {"v_A2": a, "v_B2": b}, None


def _yj12(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    a, b = _solve(2.0, 1.0, 2 * u, u / 3)
    sa, sb = _solve(1.0, 2.0, 2 * u, u / 3)  # the masses exchanged: 2u = x + 2y
    assert sb == pytest.approx(7 * u / 9)
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": (4 + 1) * u / (9 + 3)}  # 4u/9 + u/3 as 5u/12


SYMBOLIC_YJ: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yj02": _yj02,
    "yj09": _yj09,
    "yj10": _yj10,
    "yj11": _yj11,
    "yj12": _yj12,
}


def test_every_yj_case_is_worked_here() -> None:
    batch_shape(YJ_CASES, set(NUMERIC_YJ) | set(SYMBOLIC_YJ))
    one_slips = [s.name for c in YJ_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YJ))
def test_the_yj_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YJ[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YJ))
def test_the_yj_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha in POINTS:
        names = {"u": u, "e": e, "alpha": alpha}
        true, slipped = SYMBOLIC_YJ[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9), f"slip {name}"
