"""The e batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the e cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, Newton's
law of restitution, the reduced-mass energy loss, a wall's rebound, suvat for a drop), with the
student's slip made on purpose for the slip values. Letters (u, e, v) are checked at a few
points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

E_CASES = [c for c in CASES if c.name.startswith("e")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters


def _case(prefix: str):
    return next(c for c in E_CASES if c.name.startswith(prefix))


def _pair(v_a: float, v_b: float) -> dict:
    return {"v_A2": v_a, "v_B2": v_b}


# ---- numeric problems: prefix -> givens -> (true values, slip values or None) ----


def _e03(g: dict) -> tuple[dict, None]:
    # i along the line of centres: A has 0, B has -4; j components kept (A's 4)
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1n"] + g["m_B"] * g["v_B1n"], g["e"] * (g["v_A1n"] - g["v_B1n"]))
    t = g["v_A1t"]
    return {"v_A2n": a, "v_B2n": b, "v_A2t": t, "v_A2": math.sqrt(a * a + t * t), "v_B2": abs(b)}, None


def _e05(_g: dict) -> tuple[dict, None]:
    # before (1, -3), after (1, 3e) up to u/sqrt10; PA = -(1, -3); PA . PB = -1 + 9e = 0
    return {"e": 1 / 9}, None


def _e08(g: dict) -> tuple[dict, dict]:
    alpha = math.radians(g["alpha"])
    b_n, b_t = -g["u_B"] * math.cos(alpha), g["u_B"] * math.sin(alpha)
    w = b_t / math.tan(math.radians(90.0) - alpha)  # B's new direction at 60 deg to the line
    a = g["v_A1n"] + b_n - w  # equal masses
    approach = g["v_A1n"] - b_n
    true = {"v_B2": math.hypot(w, b_t), "v_A2n": a, "e": (w - a) / approach}
    s_a = g["v_A1n"] + b_n + w  # -0.220 - 0.173 worked as -0.047
    return true, {"v_A2n": s_a, "e": (w - s_a) / approach}


def _e09(g: dict) -> tuple[dict, dict]:
    def solve(along: float, across: float) -> dict:
        # m_A U + m_B along = m_B w (A stops); w = e (U - along)
        u = (g["m_B"] * along + g["m_B"] * g["e"] * along) / (g["m_B"] * g["e"] - g["m_A"])
        w = g["e"] * (u - along)
        return {"v_A1n": u, "v_B2": math.hypot(w, across), "beta_B2": math.degrees(math.atan2(across, w))}

    c, s = g["v_B1"] * math.cos(math.radians(60)), g["v_B1"] * math.sin(math.radians(60))
    return solve(c, s), solve(s, c)  # slip: sin and cos swapped


def _e14(g: dict) -> tuple[dict, None]:
    v_1, v_2 = math.sqrt(2 * g["g"] * g["h_0"]), math.sqrt(2 * g["g"] * g["h_r"])
    up, down = v_2, -v_1  # upwards positive
    return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (up - down)}, None


def _e15(g: dict) -> tuple[dict, dict]:
    v_0, v_c = g["v_0"], g["v_C"]
    # v2 = v_0 (1 + e)/2; v_C = v2 (1 + e)/2
    e = math.sqrt(4 * v_c / v_0) - 1
    # slip: v2 = v_0/2 + v_0 e; (v_0/2 + v_0 e)(1 + e) = 2 v_C -> v_0 e^2 + 1.5 v_0 e + v_0/2 - 2 v_C = 0
    qa, qb, qc = v_0, 1.5 * v_0, v_0 / 2 - 2 * v_c
    s_e = (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)
    return {"u_B": v_0 * (1 + e) / 2, "e": e}, {"u_B": v_0 / 2 + v_0 * s_e, "e": s_e}


NUMERIC_E: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "e03": _e03,
    "e05": _e05,
    "e08": _e08,
    "e09": _e09,
    "e14": _e14,
    "e15": _e15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None) ----


def _e01(u: float, e: float) -> tuple[dict, None]:
    v = (5 * u + 7 * u) / 8  # the common velocity
    assert _pair(v - e * (5 * u - v), v - e * (u - v)) == pytest.approx(_pair(*_solve(1.0, 7.0, 12 * u, 4 * e * u)))
    return _pair(v - e * (5 * u - v), v - e * (u - v)), None


def _e02(u: float, e: float) -> tuple[dict, None]:
    # left positive: A at -2u, B at u; 0 = 2x + 4y, x - y = 3eu; back to A's direction: -x, -y
    y = -3 * e * u / 3
    x = -2 * y
    assert (-x, -y) == pytest.approx(_solve(2.0, 4.0, 4 * u - 4 * u, 3 * e * u))
    return _pair(-x, -y), None


def _e04(u: float, _e: float) -> tuple[dict, None]:
    lost = 1.0 * u**2 - 0.75 * u**2  # m u^2 before, 3/4 m u^2 after (m = 1)
    mu = 2 * 1 / 3
    e = math.sqrt(1 - lost / (0.5 * mu * u**2))
    return {**_pair(*_solve(2.0, 1.0, 2 * u, e * u)), "e": e}, None


def _e06(u: float, e: float) -> tuple[dict, dict]:
    true = _solve(5.0, 2.0, 5 * u - 4 * u, 3 * e * u)
    slipped = _solve(5.0, 2.0, 5 * u + 4 * u, 3 * e * u)  # B's momentum taken +4mu
    return _pair(*true), _pair(*slipped)


def _e07(u: float, e: float) -> tuple[dict, dict]:
    true = _solve(1.0, 3.0, 4 * u, 4 * e * u)
    slipped = _solve(3.0, 1.0, 4 * u, 4 * e * u)  # 4u = 3 v_1 + v_2
    return _pair(*true), _pair(*slipped)


def _e10(u: float, _e: float) -> tuple[dict, dict]:
    true = _solve(2.0, 1.0, 2 * u, u / 3)
    s_p = (2 * u + u / 3) / 3  # the sign of u/3 kept when it crosses
    return _pair(*true), _pair(s_p, s_p + u / 3)


def _e11(v: float, _e: float) -> tuple[dict, dict]:
    e = 1 / 5
    approach = (1.5 * v + v) / e  # u_P + u_Q

    def before(p_after: float) -> dict:
        # 2 u_P - 3 u_Q = p_after; u_P + u_Q = approach
        u_q = (2 * approach - p_after) / 5
        return {"v_A1": approach - u_q, "v_B1": -u_q}

    return before(2 * (-v) + 3 * 1.5 * v), before(3 * (-v) + 2 * 1.5 * v)  # slip: masses exchanged after


def _e12(u: float, _e: float) -> tuple[dict, dict]:
    def energy_after(x: float, y: float) -> float:
        return 0.5 * x * x + 0.5 * 9 * y * y

    e = math.sqrt(40 / 90)  # (1 - 9e)^2 + 9(1 + e)^2 = 50
    x, y = _solve(1.0, 9.0, u, e * u)
    assert energy_after(x, y) == pytest.approx(0.25 * u * u)
    s_e = math.sqrt(40 / 80)  # slip 2: 81 + 9 = 80
    s_x, s_y = u * (1 + 9 * s_e) / 10, u * (1 - s_e) / 10  # slip 1: x - y = eu
    assert (s_x, s_y) == pytest.approx(_solve(1.0, 9.0, u, -s_e * u))
    return {"e": e, **_pair(x, y)}, {"e": s_e, **_pair(s_x, s_y)}


def _e13(u: float, _e: float) -> tuple[dict, dict]:
    true = _solve(4.0, 5.0, 4 * u, u / 2)
    s_a = _solve(5.0, 4.0, 4 * u, u / 2)[0]  # slip 1: masses exchanged after
    s_b = (2 + 1) * u / (9 + 2)  # slip 2: 2u/9 + u/2 added tops and bottoms
    return _pair(*true), _pair(s_a, s_b)


SYMBOLIC_E: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "e01": _e01,
    "e02": _e02,
    "e04": _e04,
    "e06": _e06,
    "e07": _e07,
    "e10": _e10,
    "e11": _e11,
    "e12": _e12,
    "e13": _e13,
}


def test_every_e_case_is_worked_here() -> None:
    assert len(E_CASES) == 15
    assert {c.name[:3] for c in E_CASES} == set(NUMERIC_E) | set(SYMBOLIC_E)
    by_category = sorted(c.verdict.category for c in E_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in E_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_E))
def test_the_e_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_E[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_E))
def test_the_e_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        letters = {"v": u}  # e11's letter v, at the point u
        true, slipped = SYMBOLIC_E[prefix](u, e)
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(slipped[name], rel=1e-9), name
