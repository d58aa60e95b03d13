"""The zh batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zh cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, an impulse, a wall's rebound, a fall and a rise), with
the student's slip made on purpose for the slip values. The one answer in letters (u, e) is checked
at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _bounce, _given, _solve, batch_shape, closed_form, numbers_agree

ZH_CASES = [c for c in CASES if c.name.startswith("zh")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters


def _case(prefix: str):
    return next(c for c in ZH_CASES if c.name.startswith(prefix))


def _ke(m: float, *speeds: float) -> float:
    return sum(0.5 * m * s * s for s in speeds)


# ---- numeric problems: prefix -> givens -> (true values, slip values or None) ----


def _zh01(g: dict) -> tuple[dict, None]:
    m_a, m_b, e, u_a, u_b = g["m_A"], g["m_B"], g["e"], g["v_A1"], g["v_B1"]
    v_a, v_b = _solve(m_a, m_b, m_a * u_a + m_b * u_b, e * (u_a - u_b))
    mu = m_a * m_b / (m_a + m_b)
    lost = 0.5 * mu * (1 - e * e) * (u_a - u_b) ** 2  # the student's reduced-mass route
    t_1, t_2 = _ke(m_a, u_a) + _ke(m_b, u_b), _ke(m_a, v_a) + _ke(m_b, v_b)
    assert lost == pytest.approx(t_1 - t_2)
    return {"v_A2": v_a, "v_B2": v_b, "T_1": t_1, "T_2": t_2, "T_lost": lost}, None


def _zh02(g: dict) -> tuple[dict, None]:
    # impulse I on B along +n, -I on A: a = u_An - I/m_A, b = u_Bn + I/m_B, b - a = e (u_An - u_Bn)
    u_a, u_b = g["v_A1n"], g["v_B1n"]
    impulse = (g["e"] * (u_a - u_b) - (u_b - u_a)) / (1 / g["m_A"] + 1 / g["m_B"])
    a, b = u_a - impulse / g["m_A"], u_b + impulse / g["m_B"]
    t = g["v_A1t"]
    return {"v_A2n": a, "v_B2n": b, "v_A2t": t, "v_A2": math.hypot(a, t), "v_B2": abs(b)}, None


def _zh03(_g: dict) -> tuple[dict, None]:
    tan_theta = 3.0  # theta = atan(3) in the problem file
    # tan(phi) = e tan(theta) and theta + phi = 90 deg: tan(phi) = 1/tan(theta)
    return {"e": 1 / tan_theta**2}, None


def _zh04(g: dict) -> tuple[dict, None]:
    w = g["v_B1t"] / math.tan(math.radians(g["alpha"]))
    v = (g["m_A"] * g["v_A1n"] + g["m_B"] * g["v_B1n"] - g["m_B"] * w) / g["m_A"]
    return {"v_B2n": w, "v_A2": abs(v), "e": (w - v) / (g["v_A1n"] - g["v_B1n"])}, None


def _zh06(g: dict) -> tuple[dict, dict]:
    p, gap = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"], g["e"] * (g["v_A1"] - g["v_B1"])
    v_a, v_b = _solve(g["m_A"], g["m_B"], p, gap)
    s_a, s_b = _solve(g["m_A"], g["m_B"], p, -gap)  # x - y = e(u_A - u_B)
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_b}


def _zh07(g: dict) -> tuple[dict, dict]:
    def worked(n: float, t: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * n + g["m_B"] * g["v_B1n"], g["e"] * (n - g["v_B1n"]))
        return {
            "v_A2n": a,
            "v_B2n": b,
            "v_A2t": t,
            "v_A2": math.hypot(a, t),
            "angle_loc": math.degrees(math.atan2(t, abs(a))),
        }

    c, s = g["v_A1"] * math.cos(math.radians(60)), g["v_A1"] * math.sin(math.radians(60))  # [A] angle 60 deg
    return worked(c, s), worked(s, c)  # sin for the component along the line of centres


def _zh08(g: dict) -> tuple[dict, dict]:
    v_r = g["v_A2"] + (g["v_A1"] - g["v_B1"])  # elastic: the relative velocity reverses
    gained = g["m_A"] * (g["v_A1"] - g["v_A2"])
    return {"v_B2": v_r, "m_B": gained / v_r}, {"m_B": gained / v_r / 10}  # 0.006/0.25 worked as 0.0024


def _zh09(g: dict) -> tuple[dict, dict]:
    kept, e = 0.6, g["e"]  # cos^2 + e^2 sin^2 = 0.6 -> (1 - e^2) sin^2 = 0.4
    true = math.degrees(math.asin(math.sqrt((1 - kept) / (1 - e * e))))
    slipped = math.degrees(math.asin(math.sqrt((1 - kept) * (1 - e * e))))  # multiplied by 7/16
    return {"alpha": true}, {"alpha": slipped}


def _zh10(g: dict) -> tuple[dict, dict]:
    m_a, m_b = 2.0, 3.0  # in units of m
    u_a, u_b = g["v_A1"], g["v_B1"]
    v_a, v_b = _solve(m_a, m_b, m_a * u_a + m_b * u_b, g["e"] * (u_a - u_b))
    lost = _ke(m_a, u_a) + _ke(m_b, u_b) - _ke(m_a, v_a) - _ke(m_b, v_b)
    slipped = _ke(m_a, u_a - v_a) + _ke(m_b, u_b - v_b)  # 1/2 m (u - v)^2
    return {"v_A2": v_a, "v_B2": v_b, "T_lost": lost}, {"T_lost": slipped}


def _zh11(g: dict) -> tuple[dict, dict]:
    def worked(normal: float) -> dict:
        return {"v_A1n": normal, "J_n": g["m_A"] * (1 + g["e"]) * normal}

    return worked(g["v_A1"] * math.cos(math.radians(g["theta"]))), worked(g["v_A1"] * math.cos(g["theta"]))


def _zh12(g: dict) -> tuple[dict, dict]:
    def worked(v_a: float, half_b: float) -> dict:
        v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_A"] * v_a) / g["m_B"]
        after = _ke(g["m_A"], v_a) + half_b * _ke(g["m_B"], v_b)
        return {"v_B2": v_b, "e": (v_b - v_a) / (g["v_A1"] - g["v_B1"]), "T_lost": _ke(g["m_A"], g["v_A1"]) - after}

    return worked(g["v_A2"], 1.0), worked(3.0, 2.0)  # A after copied as 3; B's 1/2 dropped


def _zh13(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    v = (p - g["m_A"] * g["v_A2"]) / g["m_B"]
    slipped = (p + g["m_A"] * g["v_A2"]) / g["m_B"]  # 7 = -0.1 + 2v taken as 2v = 7 - 0.1
    return (
        {"v_B2": v, "e": (v - g["v_A2"]) / (g["v_A1"] - g["v_B1"])},
        {"v_B2": slipped, "e": (slipped - g["v_A2"]) / (g["v_A1"] + g["v_B1"])},  # approach 6 + 2
    )


def _zh14(g: dict) -> tuple[dict, None]:
    # equal masses, one at rest: b = v_0 (1 + e)/2, c = b (1 + e)/2 = v_C
    e = 2 * math.sqrt(g["v_C"] / g["v_0"]) - 1
    b = g["v_0"] * (1 + e) / 2
    assert b * (1 + e) / 2 == pytest.approx(g["v_C"])
    return {"e": e, "u_B": b}, None


def _zh15(g: dict) -> tuple[dict, dict]:
    v_1, v_2 = math.sqrt(2 * g["g"] * g["h_0"]), math.sqrt(2 * g["g"] * g["h_r"])
    true = _bounce(g | {"e_floor": v_2 / v_1}, v_1) | {"e_floor": v_2 / v_1}
    assert true["v_2"] == pytest.approx(v_2)
    rounded = round(v_1, 1)  # 6.3, carried
    return true, {"J": g["m"] * (rounded + v_2), "e_floor": v_2 / rounded}


NUMERIC_ZH: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zh01": _zh01,
    "zh02": _zh02,
    "zh03": _zh03,
    "zh04": _zh04,
    "zh06": _zh06,
    "zh07": _zh07,
    "zh08": _zh08,
    "zh09": _zh09,
    "zh10": _zh10,
    "zh11": _zh11,
    "zh12": _zh12,
    "zh13": _zh13,
    "zh14": _zh14,
    "zh15": _zh15,
}


# ---- letters: prefix -> (u, e) -> true values, masses in units of m ----


def _zh05(u: float, e: float) -> dict:
    # zero total momentum: v_A = -2 v_B; NEL v_B - v_A = e (2u + u)
    assert 2 * (2 * u) + 4 * (-u) == 0
    v_b = e * 3 * u / 3
    return {"v_A2": -2 * v_b, "v_B2": v_b}


SYMBOLIC_ZH: dict[str, Callable[[float, float], dict]] = {"zh05": _zh05}


def test_every_zh_case_is_worked_here() -> None:
    batch_shape(ZH_CASES, set(NUMERIC_ZH) | set(SYMBOLIC_ZH))


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZH))
def test_the_zh_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZH[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZH))
def test_the_zh_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    assert not case.verdict.slip_values
    for u, e in POINTS:
        true = SYMBOLIC_ZH[prefix](u, e)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), {"u": u, "e": e}) == pytest.approx(true[name], rel=1e-9), name
