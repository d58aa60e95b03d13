"""The f batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the f cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum,
Newton's law of restitution, a wall's rebound, a fall and a slide under friction), with the
student's slip made on purpose for the slip values. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve

F_CASES = [c for c in CASES if c.name.startswith("f")]
G_FT = 32.2  # ft/s^2, the engineering students' g


def _case(prefix: str):
    return next(c for c in F_CASES if c.name.startswith(prefix))


def _plastic(m_a: float, m_b: float, u_a: float, u_b: float) -> dict:
    """A perfectly plastic impact: the common velocity and the kinetic energies."""
    v = (m_a * u_a + m_b * u_b) / (m_a + m_b)
    t_1 = 0.5 * m_a * u_a**2 + 0.5 * m_b * u_b**2
    t_2 = 0.5 * (m_a + m_b) * v**2
    return {"v_A2": v, "v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _f01(g: dict) -> tuple[dict, None]:
    return _plastic(g["W_A"] / G_FT, g["W_B"] / G_FT, g["v_A1"], g["v_B1"]), None


def _f02(g: dict) -> tuple[dict, None]:
    impulse = g["m_B"] * g["v_B2"]  # on B; the opposite on A
    v_a = g["v_A1"] - impulse / g["m_A"]
    return {"v_A2": v_a, "e": (g["v_B2"] - v_a) / g["v_A1"]}, None


def _f03(g: dict) -> tuple[dict, None]:
    v_b = g["v_A1"] - g["v_B1"] + g["v_A2"]  # e = 1: the relative velocity reverses
    return {"v_B2": v_b, "m_B": g["m_A"] * (g["v_A1"] - g["v_A2"]) / v_b}, None


def _f04(g: dict) -> tuple[dict, None]:
    true = _plastic(g["m_A"], g["m_B"], g["v_A1"], 0.0)
    mu = g["m_A"] * g["m_B"] / (g["m_A"] + g["m_B"])
    assert 0.5 * mu * g["v_A1"] ** 2 == pytest.approx(true["T_lost"])  # the reduced-mass loss
    return true, None


def _f05(g: dict) -> tuple[dict, None]:
    u_n = g["v_A1"] * math.cos(math.radians(g["theta"]))
    return {"v_A1n": u_n, "J_n": g["m_A"] * (1 + g["e"]) * u_n}, None


def _suitcases(m_a: float, m_b: float, u: float, e: float) -> tuple[float, float]:
    return _solve(m_a, m_b, m_a * u, e * u)


def _f06(g: dict) -> tuple[dict, dict]:
    m_a, m_b = g["W_A"] / G_FT, g["W_B"] / G_FT
    v_a, v_b = _suitcases(m_a, m_b, g["v_A1"], g["e"])
    s_b, s_a = _solve(m_b, m_a, m_a * g["v_A1"], g["e"] * g["v_A1"])  # v_A - v_B = e u
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_b}


def _f07(g: dict) -> tuple[dict, dict]:
    m, u, v = g["m_A"], g["v_A1"], g["v_A2"]
    lost = 0.5 * m * (u**2 - v**2)
    return {"e": -v / u, "T_lost": lost}, {"T_lost": 0.5 * m * (u - v) ** 2}


def _disks(u_n: float, u_t: float, e: float) -> dict:
    v_an, v_bn = _solve(1.0, 1.0, u_n, e * u_n)  # equal masses
    return {"v_A2n": v_an, "v_B2n": v_bn, "v_A2t": u_t, "v_A2": math.hypot(v_an, u_t), "v_B2": v_bn}


def _f08(g: dict) -> tuple[dict, dict]:
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    true = _disks(g["v_A1"] * c, g["v_A1"] * s, g["e"])
    return true, _disks(g["v_A1"] * s, g["v_A1"] * c, g["e"])  # sin for n, cos for t


def _f09(g: dict) -> tuple[dict, dict]:
    true = _plastic(g["m_A"], g["m_B"], g["v_A1"], g["v_B1"])
    slipped = _plastic(g["m_A"], g["m_B"], g["v_A1"], -g["v_B1"])  # B's velocity taken +0.120
    slipped["T_1"] = true["T_1"]
    slipped["T_lost"] = true["T_1"] - slipped["T_2"]
    return true, slipped


def _f10(g: dict) -> tuple[dict, dict]:
    p, v = g["m_A"] * g["v_A1"], g["v_A2"]
    return {"m_B": p / v - g["m_A"], "e": 0.0}, {"m_B": p - v * g["m_A"]}  # 12000 = 7200 + m_B


def _f11(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u = g["m_A"] / 1000, g["m_B"] / 1000, g["v_A1"]
    v_a, v_b = _solve(m_a, m_b, m_a * u, u)
    assert m_b * u == pytest.approx(0.0945)
    s_a = (m_a * u - 0.0954) / (m_a + m_b)  # 0.027 x 3.5 worked as 0.0954
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_a + u}


def _f12(g: dict) -> tuple[dict, dict]:
    m, u, e = g["m_A"], g["v_A1"], g["e"]
    v = -e * u
    t_1, t_2 = 0.5 * m * u**2, 0.5 * m * v**2
    true = {"v_A2": v, "J_n": abs(m * (v - u)), "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}
    slipped = {"J_n": abs(m * (-v - u)), "T_2": e * t_1, "T_lost": t_1 - e * t_1}
    return true, slipped


def _f13(g: dict) -> tuple[dict, dict]:
    true = _plastic(g["W_A"] / G_FT, g["W_B"] / G_FT, g["v_A1"], g["v_B1"])
    v = (g["W_A"] * g["v_A1"] - g["W_B"] * g["v_B1"]) / (g["W_A"] + g["W_B"])  # B taken +6
    t_1 = 0.5 * g["W_A"] * g["v_A1"] ** 2 + 0.5 * g["W_B"] * g["v_B1"] ** 2  # weights as masses
    t_2 = 0.5 * (g["W_A"] + g["W_B"]) * v**2
    return true, {"v_A2": v, "v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _f14(g: dict) -> tuple[dict, None]:
    big_v = math.sqrt(2 * g["mu_k"] * g["g"] * g["d_skid"])
    return {"V": big_v, "v_car": (g["m_car"] + g["m_suv"]) * big_v / g["m_car"]}, None


def _suitcase_chain(g: dict, v_1: float) -> dict:
    u_a, u_b = _suitcases(g["W_A"] / G_FT, g["W_B"] / G_FT, v_1, g["e"])
    return {"v_1": v_1, "u_A": u_a, "u_B": u_b, "d_B": u_b**2 / (2 * g["mu_k"] * g["g"])}


def _f15(g: dict) -> tuple[dict, dict]:
    true = _suitcase_chain(g, math.sqrt(2 * g["g"] * g["h"]))
    return true, _suitcase_chain(g, math.sqrt(g["g"] * g["h"]))  # W h = (W/g) v^2: the 1/2 dropped


NUMERIC_F: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "f01": _f01,
    "f02": _f02,
    "f03": _f03,
    "f04": _f04,
    "f05": _f05,
    "f06": _f06,
    "f07": _f07,
    "f08": _f08,
    "f09": _f09,
    "f10": _f10,
    "f11": _f11,
    "f12": _f12,
    "f13": _f13,
    "f14": _f14,
    "f15": _f15,
}


def test_every_f_case_is_worked_here() -> None:
    assert len(F_CASES) == 15
    assert {c.name[:3] for c in F_CASES} == set(NUMERIC_F)
    by_category = sorted(c.verdict.category for c in F_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in F_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_F))
def test_the_f_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_F[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"
