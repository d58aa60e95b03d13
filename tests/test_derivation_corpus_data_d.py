"""The d batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the d cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum,
Newton's law of restitution, a wall's rebound, the work done by friction), with the student's
slip made on purpose for the slip values. Letters (u, e, k, lambda) are checked at a few
points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

D_CASES = [c for c in CASES if c.name.startswith("d")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters
LETTERS = ({"k": 2.0, "lam": 0.25}, {"k": 3.0, "lam": 0.1}, {"k": 1.5, "lam": 0.4})


def _case(prefix: str):
    return next(c for c in D_CASES if c.name.startswith(prefix))


def _energy(m_a: float, m_b: float, v_a: float, v_b: float) -> float:
    return 0.5 * m_a * v_a**2 + 0.5 * m_b * v_b**2


# ---- numeric problems: name -> (true values, slip values or None) from the givens ----


def _d02(g: dict) -> tuple[dict, None]:
    # CLM with A's after-velocity given: m_A u_A + m_B u_B = m_A v_A + m_B v_B
    v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_A"] * g["v_A2"]) / g["m_B"]
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _d03(g: dict) -> tuple[dict, None]:
    m_a = g["m_B"] * (g["v_B2"] - g["v_B1"]) / (g["v_A1"] - g["v_A2"])
    return {"m_A": m_a, "e": (g["v_B2"] - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _d05(g: dict) -> tuple[dict, None]:
    m, big_m, u = g["m_A"], g["m_B"], g["v_A1"]
    mu = m * big_m / (m + big_m)
    v = m * u / (m + big_m)
    t_2 = 0.5 * (m + big_m) * v**2
    return {"v_B2": v, "T_1": 0.5 * m * u**2, "T_2": t_2, "T_lost": 0.5 * mu * u**2}, None


def _d06(g: dict) -> tuple[dict, dict]:
    def mass(u: float) -> float:
        return g["m_A"] * (u - g["v_A2"]) / g["v_B2"]  # m_A u = (m_A + M) V

    e = (g["v_B2"] - g["v_A2"]) / g["v_A1"]
    return {"m_B": mass(g["v_A1"]), "e": e}, {"m_B": mass(12.0)}  # 10 m/s copied as 12


def _d08(g: dict) -> tuple[dict, dict]:
    m, u, e = g["m_A"], g["v_A1"], g["e"]
    v = -e * u
    true = {"v_A2": v, "J_n": m * (u - v), "T_lost": 0.5 * m * (u**2 - v**2)}
    return true, {"T_lost": 0.5 * m * (u - e * u) ** 2}  # 1/2 m (u - v)^2 with speeds


def _weights(g: dict, u_b: float) -> dict:
    m_a, m_b = g["W_A"] / 32.2, g["W_B"] / 32.2
    v = (m_a * g["v_A1"] + m_b * u_b) / (m_a + m_b)
    return {"v_A2": v, "v_B2": v}


def _d09(g: dict) -> tuple[dict, dict]:
    return _weights(g, g["v_B1"]), _weights(g, -g["v_B1"])  # B's -6 ft/s taken +6


def _d10(g: dict) -> tuple[dict, dict]:
    def impulse(cos_theta: float) -> dict:
        u_n = g["v_A1"] * cos_theta
        return {"v_A1n": u_n, "J_n": g["m_A"] * (1 + g["e"]) * u_n}

    return impulse(math.cos(math.radians(g["theta"]))), impulse(math.cos(g["theta"]))  # 45 rad


def _d12(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b, e = 2.0, 3.0, g["v_A1"], g["v_B1"], g["e"]  # 2m and 3m, in units of m
    gap = e * (u_a - u_b)
    v_a, v_b = _solve(m_a, m_b, m_a * u_a + m_b * u_b, gap)
    t_1, t_2 = _energy(m_a, m_b, u_a, u_b), _energy(m_a, m_b, v_a, v_b)
    true = {"v_A2": v_a, "v_B2": v_b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}
    s_a, s_b = _solve(m_b, m_a, m_b * u_a + m_a * u_b, gap)  # slip 1: the masses swapped in CLM
    s_2 = _energy(m_a, m_b, s_a, s_b)
    assert t_1 - s_2 == pytest.approx(7.728)
    return true, {"v_A2": s_a, "v_B2": s_b, "T_2": s_2, "T_lost": t_1 - s_2 + 1.0}  # slip 2: 8.728


def _d13(g: dict) -> tuple[dict, dict]:
    m, u, e = g["m_A"], g["v_A1"], g["e"]
    true = {"v_A2": -e * u, "T_lost": 0.5 * m * (u**2 - (e * u) ** 2)}
    s_u = 5.0  # slip 1: 4 m/s copied as 5
    return true, {"v_A2": -e * s_u, "T_lost": 0.5 * m * (s_u - e * s_u) ** 2}  # slip 2: (u - v)^2


def _d14(g: dict) -> tuple[dict, None]:
    u_a, u_b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A"] - g["m_B"] * g["v_B"], g["e"] * (g["v_A"] + g["v_B"]))
    w_b = -g["e_wall"] * u_b
    return {"u_A": u_a, "u_B": u_b, "w_B": w_b, "again": "yes" if u_a > w_b else "no"}, None


def _d15(g: dict) -> tuple[dict, dict]:
    total = g["m_car"] + g["m_suv"]

    def speeds(v_squared: float) -> dict:
        big_v = math.sqrt(v_squared)
        return {"V": big_v, "v_car": total * big_v / g["m_car"]}

    work = g["mu_k"] * g["g"] * g["d_skid"]  # per unit mass
    return speeds(2 * work), speeds(work)  # 1/2 M V^2 = mu M g d; the slip: M V^2


NUMERIC_D: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "d02": _d02,
    "d03": _d03,
    "d05": _d05,
    "d06": _d06,
    "d08": _d08,
    "d09": _d09,
    "d10": _d10,
    "d12": _d12,
    "d13": _d13,
    "d14": _d14,
    "d15": _d15,
}


# ---- letters: name -> (u, e, letters) -> (true values, slip values or None) ----


def _d01(u: float, e: float, _l: dict) -> tuple[dict, None]:
    v_a, v_b = _solve(2.0, 1.0, 2.0 * 2 * u - u, e * 3 * u)
    return {"v_A2": v_a, "v_B2": v_b}, None


def _d04(u: float, e: float, _l: dict) -> tuple[dict, None]:
    v_a, v_b = _solve(1.0, 1.0, u, e * u)
    return {"v_A2": v_a, "v_B2": v_b}, None


def _d07(u: float, e: float, _l: dict) -> tuple[dict, dict]:
    v_a, v_b = _solve(1.0, 2.0, 3 * u, e * 3 * u)
    s_a, s_b = _solve(1.0, 2.0, 3 * u, 3 * u / e)  # e(w - v) = 3u
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_b}


def _d11(u: float, _e: float, letters: dict) -> tuple[dict, dict]:
    k, lam = letters["k"], letters["lam"]
    w = (u + k * lam * u) / k  # m u + k m (lam u) = k m w, S at rest after
    s_w = u * (1 + lam) / k  # the k lost from k lam
    approach = u - lam * u
    return {"v_B2": w, "e": w / approach}, {"v_B2": s_w, "e": s_w / approach}


SYMBOLIC_D: dict[str, Callable[[float, float, dict], tuple[dict, dict | None]]] = {
    "d01": _d01,
    "d04": _d04,
    "d07": _d07,
    "d11": _d11,
}


def test_every_d_case_is_worked_here() -> None:
    assert len(D_CASES) == 15
    assert {c.name[:3] for c in D_CASES} == set(NUMERIC_D) | set(SYMBOLIC_D)
    by_category = sorted(c.verdict.category for c in D_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in D_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_D))
def test_the_d_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_D[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        if isinstance(value, str):
            assert value == true[name], f"{case.name}: {name}"
            continue
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_D))
def test_the_d_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for (u, e), letters in zip(POINTS, LETTERS, strict=True):
        true, slipped = SYMBOLIC_D[prefix](u, e, letters)
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(slipped[name], rel=1e-9), name
