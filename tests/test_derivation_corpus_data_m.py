"""The m batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the m cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum,
Newton's law of restitution, a wall's rebound, the energy of a fall or a rise), with the
student's slip made on purpose for the slip values. The one answer in letters (u, e) is checked
at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

M_CASES = [c for c in CASES if c.name.startswith("m") and c.name[1:3].isdigit()]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters


def _case(prefix: str):
    return next(c for c in M_CASES if c.name.startswith(prefix))


def _ke(m: float, *speeds: float) -> float:
    return sum(0.5 * m * s * s for s in speeds)


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _m01(g: dict) -> tuple[dict, None]:
    v_a, v_b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1"], g["e"] * g["v_A1"])
    return {"v_A2": v_a, "v_B2": v_b}, None


def _m02(g: dict) -> tuple[dict, None]:
    v_a = (g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B2"]) / g["m_A"]
    return {"v_A2": v_a, "e": (g["v_B2"] - v_a) / (g["v_A1"] - g["v_B1"])}, None


def _m03(g: dict) -> tuple[dict, None]:
    v = (g["W_A"] / 32.2 * g["v_A1"] + g["W_B"] / 32.2 * g["v_B1"]) / ((g["W_A"] + g["W_B"]) / 32.2)
    return {"v_A2": v, "v_B2": v}, None


def _m04(g: dict) -> tuple[dict, None]:
    t_1, t_2 = _ke(g["m_A"], g["v_A1"]), _ke(g["m_A"], g["v_A2"])
    return {"e": -g["v_A2"] / g["v_A1"], "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _m05(g: dict) -> tuple[dict, None]:
    u_n, u_t = g["v_A1"] * 0.6, g["v_A1"] * 0.8  # sin alpha = 0.8, cos alpha = 0.6
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * u_n + g["m_B"] * g["v_B1n"], g["e"] * (u_n - g["v_B1n"]))
    angle = math.degrees(math.atan2(u_t, a))  # anticlockwise from i
    return {"v_A2n": a, "v_A2t": u_t, "v_B2n": b, "v_A2": math.hypot(a, u_t), "dir_A_from_i": angle}, None


def _m06(g: dict) -> tuple[dict, dict]:
    m, u, v = g["m_A"], g["v_A1"], -g["e"] * g["v_A1"]
    true = {"v_A2": v, "J_n": m * (u - v), "T_lost": _ke(m, u) - _ke(m, v)}
    return true, {"T_lost": 0.5 * m * (u - abs(v)) ** 2}  # 1/2 m (u - v)^2 with the speeds


def _m07(g: dict) -> tuple[dict, dict]:
    v_b = g["v_A2"] + g["v_A1"] - g["v_B1"]  # e = 1: v_B - v_A = u_A - u_B
    true = {"v_B2": v_b, "m_B": g["m_A"] * (g["v_A1"] - g["v_A2"]) / v_b}
    slipped = (10 * g["m_A"] * g["v_A1"] - g["m_A"] * g["v_A2"]) / v_b  # 0.008 written 0.08
    return true, {"m_B": slipped}


def _m09(g: dict) -> tuple[dict, dict]:
    def worked(cos_45: float) -> dict:
        u_n = g["v_A1"] * cos_45
        return {"v_A1n": u_n, "J_n": g["m_A"] * (1 + g["e"]) * u_n}

    return worked(math.cos(math.radians(g["theta"]))), worked(math.cos(g["theta"]))  # radian mode


def _m10(g: dict) -> tuple[dict, dict]:
    v_b = (g["m_A"] * (g["v_A1"] - g["v_A2"]) + g["m_B"] * g["v_B1"]) / g["m_B"]
    sep, app = v_b - g["v_A2"], g["v_A1"] - g["v_B1"]
    return {"v_B2": v_b, "e": sep / app}, {"e": app / sep}  # e upside down


def _m11(g: dict) -> tuple[dict, dict]:
    p, gap = g["W_A"] * g["v_A1"], g["e"] * g["v_A1"]  # 1/32.2 cancelled
    true = _solve(g["W_A"], g["W_B"], p, gap)
    slipped = _solve(g["W_B"], g["W_A"], p, gap)  # 10 with v_A, 15 with v_B after
    return {"v_A2": true[0], "v_B2": true[1]}, {"v_A2": slipped[0], "v_B2": slipped[1]}


def _m12(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b = 2.0, 3.0, g["v_A1"], g["v_B1"]  # 2m and 3m, in units of m
    p = m_a * u_a + m_b * u_b

    def energies(gap: float) -> dict:
        a, b = _solve(m_a, m_b, p, gap)
        t_1, t_2 = _ke(m_a, u_a) + _ke(m_b, u_b), _ke(m_a, a) + _ke(m_b, b)
        return {"v_A2": a, "v_B2": b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    true = energies(g["e"] * (u_a - u_b))
    slipped = energies(g["e"] * (u_a + u_b))  # slip 1: B's sign lost in the approach
    t_1 = _ke(m_a, u_a) + m_b * u_b**2  # slip 2: 1/2 (3m)(2^2) worked as 12m
    return true, slipped | {"T_1": t_1, "T_lost": t_1 - slipped["T_2"]}


def _m13(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    gap = g["e"] * (g["v_A1"] - g["v_B1"])
    v_a, v_b = _solve(g["m_A"], g["m_B"], p, gap)
    assert p == pytest.approx(0.5)
    s_a, s_b = _solve(g["m_A"], g["m_B"], 0.6, -gap)  # slip 1: 0.5 written 0.6; slip 2: v_A - v_B = 4
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_b}


def _m14(g: dict) -> tuple[dict, None]:
    mass = g["m_bullet"] + g["m_block"]
    v = g["m_bullet"] * g["v_0"] / mass
    return {"V": v, "T_after": 0.5 * mass * v * v, "h_2": v * v / (2 * g["g"])}, None


def _m15(g: dict) -> tuple[dict, dict]:
    def worked(height: float) -> dict:
        v_1 = math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * height)
        v_2 = math.sqrt(2 * g["g"] * height)  # rises back to the start
        return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}

    return worked(g["h_0"]), worked(30.0)  # 40 m copied as 30 m


NUMERIC_M: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "m01": _m01,
    "m02": _m02,
    "m03": _m03,
    "m04": _m04,
    "m05": _m05,
    "m06": _m06,
    "m07": _m07,
    "m09": _m09,
    "m10": _m10,
    "m11": _m11,
    "m12": _m12,
    "m13": _m13,
    "m14": _m14,
    "m15": _m15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None) ----


def _m08(u: float, e: float) -> tuple[dict, dict]:
    true = _solve(2.0, 3.0, 2.0 * 5 * u, 5 * e * u)  # P 2m at 5u, Q 3m at rest
    slipped = _solve(3.0, 2.0, 2.0 * 5 * u, 5 * e * u)  # 10u = 3x + 2y
    return {"v_A2": true[0], "v_B2": true[1]}, {"v_A2": slipped[0], "v_B2": slipped[1]}


SYMBOLIC_M: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {"m08": _m08}


def test_every_m_case_is_worked_here() -> None:
    assert len(M_CASES) == 15
    assert {c.name[:3] for c in M_CASES} == set(NUMERIC_M) | set(SYMBOLIC_M)
    by_category = sorted(c.verdict.category for c in M_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in M_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    for case in M_CASES:
        slipped = case.verdict.category in ("one_slip", "two_slips") or case.verdict.summary != "0 wrong"
        assert bool(case.verdict.slip_values) == slipped, case.name


@pytest.mark.parametrize("prefix", sorted(NUMERIC_M))
def test_the_m_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_M[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_M))
def test_the_m_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_M[prefix](u, e)
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e) == pytest.approx(true[name], rel=1e-9), name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e) == pytest.approx(slipped[name], rel=1e-9), name
