"""The zg batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zg cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's rebound, kinetic energies, a fall and a slide
with friction), with the student's slip made on purpose for the slip values, at the figures the
student carried where the student rounded. Answers in letters (u, e) are checked at a few points by
solving the two linear equations numerically there. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, letters_agree, numbers_agree

ZG_CASES = [c for c in CASES if c.name.startswith("zg")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))


def _case(prefix: str):
    return next(c for c in ZG_CASES if c.name.startswith(prefix))


def _ke(*pairs: tuple[float, float]) -> float:
    return sum(0.5 * m * v * v for m, v in pairs)


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _zg01(g: dict) -> tuple[dict, None]:
    m1, m2, u = g["m_A"], g["m_B"], g["v_A1"]  # grams: only the ratio matters
    return {"v_A2": (m1 - m2) / (m1 + m2) * u, "v_B2": 2 * m1 / (m1 + m2) * u}, None


def _zg02(g: dict) -> tuple[dict, None]:
    m, big, u = g["m_A"], g["m_B"], g["v_A1"]
    v = m * u / (m + big)
    before, after = _ke((m, u)), _ke((m + big, v))
    return {"v_B2": v, "T_1": before, "T_2": after, "T_lost": before - after}, None


def _zg03(g: dict) -> tuple[dict, None]:
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1n"] + g["m_B"] * g["v_B1n"], g["e"] * (g["v_A1n"] - g["v_B1n"]))
    t = g["v_A1t"]
    return {
        "v_A2n": a,
        "v_B2n": b,
        "v_A2t": t,
        "v_A2": math.hypot(a, t),
        "v_B2": abs(b),
        "dir_A_from_i": math.degrees(math.atan2(t, a)),
    }, None


def _zg05(g: dict) -> tuple[dict, None]:
    v_cm = g["m_A"] * g["v_A1"] / (g["m_A"] + g["m_B"])
    return {"v_A2": 2 * v_cm - g["v_A1"], "v_B2": 2 * v_cm}, None


def _zg06(g: dict) -> tuple[dict, dict]:
    e = (g["v_B2"] - g["v_A2"]) / (g["v_A1"] - g["v_B1"])

    def mass(u_b: float) -> float:  # m u_A + m_B u_b = m v_A + m_B v_B
        return g["m_B"] * (g["v_B2"] - u_b) / (g["v_A1"] - g["v_A2"])

    return {"e": e, "m_A": mass(g["v_B1"])}, {"m_A": mass(-g["v_B1"])}  # B's +1.5


def _zg07(g: dict) -> tuple[dict, dict]:
    m, u = g["m_A"], g["v_A1"]
    v = -g["e"] * u
    return {
        "v_A2": v,
        "J_n": m * (u - v),
        "T_1": _ke((m, u)),
        "T_lost": _ke((m, u)) - _ke((m, v)),
    }, {"T_lost": 0.5 * m * (u - abs(v)) ** 2}  # 1/2 m (u - v)^2 with the speeds


def _zg08(g: dict) -> tuple[dict, dict]:
    def worked(m: float) -> dict:
        total = m + g["m_B"]
        v = m * g["v_A1"] / total
        before, after = _ke((m, g["v_A1"])), _ke((total, v))
        return {"v_B2": v, "T_1": before, "T_2": after, "T_lost": before - after}

    return worked(g["m_A"]), worked(10 * g["m_A"])  # 20 g written 0.2 kg


def _zg09(g: dict) -> tuple[dict, dict]:
    v_b = g["v_A2"] + g["e"] * (g["v_A1"] - g["v_B1"])
    m_a = g["m_A"]
    true = m_a * (g["v_A1"] - g["v_A2"]) / v_b
    slipped = m_a * (g["v_A1"] + g["v_A2"]) / v_b  # 0.0080 + 0.0020
    return {"v_B2": v_b, "m_B": true}, {"m_B": slipped}


def _zg11(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b, v_a = g["m_A"], g["m_B"], g["v_A1"], g["v_B1"], g["v_A2"]

    def worked(v_a_in_clm: float) -> dict:
        v_b = (m_a * u_a + m_b * u_b - m_a * v_a_in_clm) / m_b
        lost = _ke((m_a, u_a), (m_b, u_b)) - _ke((m_a, v_a), (m_b, v_b))
        return {"v_B2": v_b, "e": (v_b - v_a) / (u_a - u_b), "T_lost": lost}

    slipped = worked(-v_a)  # A's velocity after taken +0.2 in CLM only
    assert slipped["T_lost"] == pytest.approx(1.0875)  # written 1.1875: the second slip
    return worked(v_a), {k: slipped[k] for k in ("v_B2", "e")}


def _zg12(g: dict) -> tuple[dict, dict]:
    m_a, m_b, e, u_a, u_b = g["m_A"], g["m_B"], g["e"], g["v_A1"], g["v_B1"]

    def worked(p: float) -> tuple[float, float]:
        return _solve(m_a, m_b, p, e * (u_a - u_b))

    v_a, v_b = worked(m_a * u_a + m_b * u_b)
    before = _ke((m_a, u_a), (m_b, u_b))
    after = _ke((m_a, v_a), (m_b, v_b))
    s_a, s_b = worked(m_a * u_a - m_b * u_b)  # B's momentum +0.4
    s_after = _ke((m_a, s_a), (m_b, s_b))
    written_before = 1.57  # 1.35 + 0.4 written 1.57: the second slip
    assert before == pytest.approx(1.75)
    return (
        {"v_A2": v_a, "v_B2": v_b, "T_1": before, "T_2": after, "T_lost": before - after},
        {"v_A2": s_a, "v_B2": s_b, "T_2": s_after, "T_lost": written_before - s_after},
    )


def _zg14(g: dict) -> tuple[dict, None]:
    u_a, u_b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A"] - g["m_B"] * g["v_B"], g["e"] * (g["v_A"] + g["v_B"]))
    w_b = -g["e_wall"] * u_b
    return {"u_A": u_a, "u_B": u_b, "w_B": w_b, "again": "yes" if w_b < u_a else "no"}, None


def _zg15(g: dict) -> tuple[dict, dict]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    w_a, w_b, e = g["W_A"], g["W_B"], g["e"]  # weights: g cancels from the momentum equation
    u_a, u_b = _solve(w_a, w_b, w_a * v_1, e * v_1)
    friction = 2 * g["mu_k"] * g["g"]
    true = {"v_1": v_1, "u_A": u_a, "u_B": u_b, "d_B": u_b**2 / friction}
    v_1 = round(v_1, 2)  # 19.66 carried
    gap = round(e * v_1, 3)  # 5.898, reversed: vA - vB = 5.898
    s_b = (w_a * v_1 - w_a * gap) / (w_a + w_b)
    return true, {"u_A": s_b + gap, "u_B": s_b, "d_B": round(s_b, 3) ** 2 / friction}


NUMERIC_ZG: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zg01": _zg01,
    "zg02": _zg02,
    "zg03": _zg03,
    "zg05": _zg05,
    "zg06": _zg06,
    "zg07": _zg07,
    "zg08": _zg08,
    "zg09": _zg09,
    "zg11": _zg11,
    "zg12": _zg12,
    "zg14": _zg14,
    "zg15": _zg15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None), masses in units of m ----


def _zg04(u: float, e: float) -> tuple[dict, None]:
    v_p, v_q = _solve(1.0, 2.0, u, e * u)
    return {"v_A2": v_p, "v_B2": v_q}, None


def _zg10(u: float, e: float) -> tuple[dict, dict]:
    p, gap = 2.0 * 4 * u + 1.0 * (-3 * u), e * 7 * u
    true = _solve(2.0, 1.0, p, gap)
    slipped = _solve(1.0, 2.0, p, gap)  # A's mass m and B's 2m after the impact
    return {"v_A2": true[0], "v_B2": true[1]}, {"v_A2": slipped[0], "v_B2": slipped[1]}


def _zg13(u: float, e: float) -> tuple[dict, dict]:
    x, y = _solve(1.0, 3.0, 4 * u, 4 * e * u)
    sx = (4 * u - 4 * e * u) / 4  # 3(x + 4eu) taken as 3x + 4eu
    return {"v_A2": x, "v_B2": y}, {"v_A2": sx, "v_B2": sx + 4 * e * u}


SYMBOLIC_ZG: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "zg04": _zg04,
    "zg10": _zg10,
    "zg13": _zg13,
}


def test_every_zg_case_is_worked_here() -> None:
    batch_shape(ZG_CASES, set(NUMERIC_ZG) | set(SYMBOLIC_ZG))


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZG))
def test_the_zg_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZG[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZG))
def test_the_zg_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        names = {"u": u, "e": e}
        true, slipped = SYMBOLIC_ZG[prefix](u, e)
        letters_agree(case, names, true, slipped)
