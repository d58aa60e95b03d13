"""The mb batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the mb cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum,
Newton's law of restitution, a wall's rebound, the energy of a fall or a rise, a slide against
friction), with the student's slip made on purpose for the slip values. The one answer in
letters (u, e) is checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

MB_CASES = [c for c in CASES if c.name.startswith("mb")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters


def _case(prefix: str):
    return next(c for c in MB_CASES if c.name.startswith(prefix))


def _ke(m: float, *speeds: float) -> float:
    return sum(0.5 * m * s * s for s in speeds)


def _direct(g: dict) -> tuple[float, float]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    return _solve(g["m_A"], g["m_B"], p, g["e"] * (g["v_A1"] - g["v_B1"]))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _mb01(g: dict) -> tuple[dict, None]:
    m_1, m_2, u = g["m_A"], g["m_B"], g["v_A1"]  # grams: only ratios are used
    return {"v_A2": (m_1 - m_2) / (m_1 + m_2) * u, "v_B2": 2 * m_1 / (m_1 + m_2) * u}, None


def _mb02(g: dict) -> tuple[dict, None]:
    m = g["m_A"] + g["m_B"]
    v = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]) / m
    t_1 = _ke(g["m_A"], g["v_A1"]) + _ke(g["m_B"], g["v_B1"])
    mu = g["m_A"] * g["m_B"] / m
    assert t_1 - _ke(m, v) == pytest.approx(0.5 * mu * (g["v_A1"] - g["v_B1"]) ** 2)  # the reduced mass
    return {"v_A2": v, "v_B2": v, "T_1": t_1, "T_2": _ke(m, v), "T_lost": t_1 - _ke(m, v)}, None


def _wall(g: dict) -> dict:
    m, u = g["m_A"], g["v_A1"]
    v = -g["e"] * u
    return {"v_A2": v, "J_n": m * (u - v), "T_1": _ke(m, u), "T_2": _ke(m, v), "T_lost": _ke(m, u) - _ke(m, v)}


def _mb03(g: dict) -> tuple[dict, None]:
    return _wall(g), None


def _mb04(g: dict) -> tuple[dict, None]:
    cos_a, sin_a = math.sqrt(1 - 0.8**2), 0.8
    u_n, u_t = g["v_A1"] * cos_a, g["v_A1"] * sin_a
    p = g["m_A"] * u_n + g["m_B"] * g["v_B1n"]
    a, b = _solve(g["m_A"], g["m_B"], p, g["e"] * (u_n - g["v_B1n"]))
    angle = math.degrees(math.atan2(u_t, a))  # anticlockwise from i
    return {"v_A2n": a, "v_A2t": u_t, "v_B2n": b, "v_A2": math.hypot(a, u_t), "dir_A_from_i": angle}, None


def _mb06(g: dict) -> tuple[dict, dict]:
    v_a, v_b = _direct(g)
    p = g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B1"]  # B's momentum taken +0.4
    s_a, s_b = _solve(g["m_A"], g["m_B"], p, g["e"] * (g["v_A1"] - g["v_B1"]))
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_b}


def _mb07(g: dict) -> tuple[dict, dict]:
    m_a, m_b = g["W_A"] / 32.2, g["W_B"] / 32.2
    p = m_a * g["v_A1"] + m_b * g["v_B1"]
    v = p / (m_a + m_b)
    return {"v_A2": v, "v_B2": v}, {"v_A2": -v, "v_B2": -v}  # the momentum's sign dropped


def _mb08(g: dict) -> tuple[dict, dict]:
    m_a = g["m_B"] * (g["v_B2"] - g["v_B1"]) / (g["v_A1"] - g["v_A2"])
    sep, app = g["v_B2"] - g["v_A2"], g["v_A1"] - g["v_B1"]
    return {"e": sep / app, "m_A": m_a}, {"e": app / sep}  # e upside down


def _mb09(g: dict) -> tuple[dict, dict]:
    v_a, v_b = _direct(g)
    assert 2 * g["m_A"] * g["v_A1"] / (g["m_A"] + g["m_B"]) == pytest.approx(v_b)  # 10.5/70.15
    written = 0.160  # 10.5/70.15 worked as 0.160
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": written - g["v_A1"], "v_B2": written}


def _energies(g: dict, v_a: float, v_b: float) -> dict:
    t_1 = _ke(g["m_A"], g["v_A1"]) + _ke(g["m_B"], g["v_B1"])
    t_2 = _ke(g["m_A"], v_a) + _ke(g["m_B"], v_b)
    return {"v_A2": v_a, "v_B2": v_b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _mb10(g: dict) -> tuple[dict, dict]:
    gap = g["e"] * (g["v_A1"] - g["v_B1"])
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    x = (p + g["m_B"] * gap) / (g["m_A"] + g["m_B"])  # 3x = 5 + 8: the 8 kept on the wrong side
    slipped = _energies(g, x, x + gap)
    del slipped["T_1"]
    return _energies(g, *_direct(g)), slipped


def _mb11(g: dict) -> tuple[dict, dict]:
    v_a, v_b = _direct(g)
    slipped = 2 * g["m_B"] / (g["m_A"] + g["m_B"]) * g["v_A1"]  # 2 m_2 on top
    return {"v_A2": v_a, "v_B2": v_b}, {"v_B2": slipped}


def _mb12(g: dict) -> tuple[dict, dict]:
    true = _energies(g, *_direct(g))
    p, gap = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"], g["e"] * (g["v_A1"] - g["v_B1"])
    s_a, s_b = _solve(g["m_A"], g["m_B"], p, -gap)  # slip 1: v_A - v_B = e(u_A - u_B)
    lost = _ke(g["m_A"], g["v_A1"] - s_a) + _ke(g["m_B"], g["v_B1"] - s_b)  # slip 2: 1/2 m (u - v)^2
    keep = ("v_A2", "v_B2", "T_lost")
    return {k: true[k] for k in keep}, {"v_A2": s_a, "v_B2": s_b, "T_lost": lost}


def _mb13(g: dict) -> tuple[dict, dict]:
    true = _wall(g)
    speed = g["e"] * g["v_A1"]
    j = abs(g["m_A"] * (speed - g["v_A1"]))  # slip 1: the rebound velocity kept positive
    return true, {"J_n": j, "T_lost": true["T_lost"] + 1.0}  # slip 2: 16 - 2.56 written 14.44


def _mb14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    u_a, u_b = _solve(g["W_A"], g["W_B"], g["W_A"] * v_1, g["e"] * v_1)  # 1/g cancels
    return {"v_1": v_1, "u_A": u_a, "u_B": u_b, "d_B": u_b**2 / (2 * g["mu_k"] * g["g"])}, None


def _mb15(g: dict) -> tuple[dict, dict]:
    def worked(two_g_h: float) -> dict:
        v_1 = math.sqrt(g["v_0"] ** 2 + two_g_h)
        v_2 = math.sqrt(2 * g["g"] * g["h_0"])  # rises back to the start
        return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}

    assert 2 * g["g"] * g["h_0"] == pytest.approx(784.0)
    slipped = worked(748.0)  # 784 written 748
    del slipped["v_2"]
    return worked(2 * g["g"] * g["h_0"]), slipped


NUMERIC_MB: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "mb01": _mb01,
    "mb02": _mb02,
    "mb03": _mb03,
    "mb04": _mb04,
    "mb06": _mb06,
    "mb07": _mb07,
    "mb08": _mb08,
    "mb09": _mb09,
    "mb10": _mb10,
    "mb11": _mb11,
    "mb12": _mb12,
    "mb13": _mb13,
    "mb14": _mb14,
    "mb15": _mb15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None) ----


def _mb05(u: float, e: float) -> tuple[dict, None]:
    v_p, v_q = _solve(2.0, 1.0, 2.0 * 2 * u - u, e * 3 * u)  # P 2m at 2u, Q m at u towards P
    cm = (2.0 * 2 * u - u) / 3.0
    assert v_p == pytest.approx(cm - e * (2 * u - cm)) and v_q == pytest.approx(cm - e * (-u - cm))
    return {"v_A2": v_p, "v_B2": v_q}, None


SYMBOLIC_MB: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {"mb05": _mb05}


def test_every_mb_case_is_worked_here() -> None:
    assert len(MB_CASES) == 15
    assert {c.name[:4] for c in MB_CASES} == set(NUMERIC_MB) | set(SYMBOLIC_MB)
    by_category = sorted(c.verdict.category for c in MB_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in MB_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    for case in MB_CASES:
        slipped = case.verdict.category in ("one_slip", "two_slips") or case.verdict.summary != "0 wrong"
        assert bool(case.verdict.slip_values) == slipped, case.name


@pytest.mark.parametrize("prefix", sorted(NUMERIC_MB))
def test_the_mb_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_MB[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"
    assert set(case.verdict.slip_values or {}) == set(slipped or {}), case.name


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_MB))
def test_the_mb_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_MB[prefix](u, e)
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e) == pytest.approx(true[name], rel=1e-9), name
        assert slipped is None and not case.verdict.slip_values
