"""The u batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the u cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, Newton's
law of restitution, a wall's rebound, the work of friction in a skid), with the student's slip made
on purpose for the slip values. Letters (u, e, k, lambda) are checked at a few points. Nothing here
runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve, numbers_agree

U_CASES = [c for c in CASES if c.name.startswith("u")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters
K, LAM = 3.0, 0.25  # the letters k and lambda of u07, at one point


def _case(prefix: str):
    return next(c for c in U_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _u01(g: dict) -> tuple[dict, None]:
    v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_A"] * g["v_A2"]) / g["m_B"]
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _u03(g: dict) -> tuple[dict, None]:
    m_b = g["m_A"] * (g["v_A1"] - g["v_A2"]) / g["v_A2"]  # 1200 (10) = (1200 + M) 6
    return {"m_B": m_b, "e": (g["v_B2"] - g["v_A2"]) / g["v_A1"]}, None


def _u05(g: dict) -> tuple[dict, None]:
    v_a = (g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B2"]) / g["m_A"]
    return {"v_A2": v_a, "e": (g["v_B2"] - v_a) / g["v_A1"]}, None


def _u08(g: dict) -> tuple[dict, dict]:
    def components(speed: float, degrees: float) -> tuple[float, float]:
        angle = math.radians(degrees - g["phi_n"])  # from the normal at 20 deg
        return speed * math.cos(angle), speed * math.sin(angle)

    a_n, a_t = components(g["v_A1"], 45.0)
    b_n, b_t = components(g["v_B1"], 120.0)
    v_an, v_bn = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, g["e"] * (a_n - b_n))
    true = {"v_A2n": v_an, "v_B2n": v_bn, "v_A2": math.hypot(v_an, a_t), "v_B2": math.hypot(v_bn, b_t)}
    slipped = {"v_A2": math.hypot(v_an, g["e"] * a_t), "v_B2": math.hypot(v_bn, g["e"] * b_t)}  # e on t
    return true, slipped


def _u09(g: dict) -> tuple[dict, dict]:
    e, kept = g["e"], 0.6  # "keeps 60% of its kinetic energy"
    # true: cos^2 a + e^2 sin^2 a = kept; slip (e on the component along the wall): e^2 cos^2 a + sin^2 a = kept
    sin2 = (1 - kept) / (1 - e * e)
    return {"alpha": math.degrees(math.asin(math.sqrt(sin2)))}, {"alpha": math.degrees(math.acos(math.sqrt(sin2)))}


def _u10(g: dict) -> tuple[dict, dict]:
    mass = g["m_A"] + g["m_B"]
    v = g["m_A"] * g["v_A1"] / mass
    t_1, t_2 = 0.5 * g["m_A"] * g["v_A1"] ** 2, 0.5 * mass * v**2
    true = {"v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}
    return true, {"T_lost": 0.5 * g["m_A"] * (g["v_A1"] - v) ** 2}  # 1/2 m (u - V)^2


def _u13(g: dict) -> tuple[dict, dict]:
    u, gap = g["v_A1"], g["e"] * g["v_A1"]
    v_a, v_b = _solve(g["W_A"], g["W_B"], g["W_A"] * u, gap)  # weights: g cancels in momentum
    s_a, s_b = _solve(g["W_B"], g["W_A"], g["W_B"] * u, gap)  # slip 1: the weights swapped
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_b, "J_n": g["W_B"] * s_b}  # slip 2: W as m


def _u14(g: dict) -> tuple[dict, None]:
    big_v = math.sqrt(2 * g["mu_k"] * g["g"] * g["d_skid"])  # 1/2 M V^2 = mu_k M g d
    return {"V": big_v, "v_car": (g["m_car"] + g["m_suv"]) * big_v / g["m_car"]}, None


def _u15(g: dict) -> tuple[dict, dict]:
    def stages(u_b: float) -> dict:
        u_a2, u_b2 = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A"] + g["m_B"] * u_b, g["e"] * (g["v_A"] + g["v_B"]))
        return {"u_A": u_a2, "u_B": u_b2, "w_B": -g["e_wall"] * u_b2}

    true = stages(-g["v_B"])
    assert true["u_A"] < 0 and true["u_A"] > true["w_B"]  # A moves away slower than B comes back: again
    return true | {"again": "yes"}, stages(+g["v_B"])  # slip: B's momentum +0.2(2)


NUMERIC_U: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "u01": _u01,
    "u03": _u03,
    "u05": _u05,
    "u08": _u08,
    "u09": _u09,
    "u10": _u10,
    "u13": _u13,
    "u14": _u14,
    "u15": _u15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None); m = 1 ----


def _u02(u: float, e: float) -> tuple[dict, None]:
    v_a, v_b = _solve(3.0, 6.0, 3.0 * u, e * u)
    return {"T_lost": 0.5 * 3 * u * u - 0.5 * 3 * v_a**2 - 0.5 * 6 * v_b**2}, None


def _u04(u: float, e: float) -> tuple[dict, None]:
    u_n = u * math.cos(math.radians(30))
    v_an, v_bn = _solve(1.0, 1.0, u_n, e * u_n)
    return {"v_B2": v_bn, "v_A2n": v_an}, None


def _u06(u: float, e: float) -> tuple[dict, dict]:
    v_a, v_b = _solve(1.0, 3.0, 4 * u, e * 4 * u)
    s_a, s_b = _solve(1.0, 3.0, 4 * u, -e * 4 * u)  # v1 - v2 = 4eu
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_b}


def _u07(u: float, e: float) -> tuple[dict, dict]:
    del e  # e is the unknown here
    m_a, m_b, u_a, u_b = 1.0, K, u, LAM * u
    v_b = (m_a * u_a + m_b * u_b) / m_b  # S is brought to rest
    s_v = (u_a + u_b) / m_b  # slip: k lost on T's momentum
    return {"v_B2": v_b, "e": v_b / (u_a - u_b)}, {"v_B2": s_v, "e": s_v / (u_a - u_b)}


def _u11(u: float, e: float) -> tuple[dict, dict]:
    v_a, v_b = _solve(5.0, 2.0, 5 * u + 2 * (-2 * u), e * 3 * u)
    s_a, s_b = _solve(5.0, 2.0, 5 * u + 2 * (2 * u), e * 3 * u)  # B's momentum +2m(2u)
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_b}


def _u12(u: float, e: float) -> tuple[dict, dict]:
    v_a, v_b = _solve(1.0, 1.0, u, e * u)
    s_a = (e * u - u) / 2  # slip 1: 2 v_A = eu - u
    # slip 2: (1 + e)^2 taken as 1 + e^2 in the KE after, with the student's v_A (its square is right)
    t_2 = 0.5 * s_a**2 + 0.5 * (u / 2) ** 2 * (1 + e * e)
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "T_2": t_2, "T_lost": 0.5 * u * u - t_2}


SYMBOLIC_U: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "u02": _u02,
    "u04": _u04,
    "u06": _u06,
    "u07": _u07,
    "u11": _u11,
    "u12": _u12,
}


def test_every_u_case_is_worked_here() -> None:
    assert len(U_CASES) == 15
    assert {c.name[:3] for c in U_CASES} == set(NUMERIC_U) | set(SYMBOLIC_U)
    by_category = sorted(c.verdict.category for c in U_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in U_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_U))
def test_the_u_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_U[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_U))
def test_the_u_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_U[prefix](u, e)
        letters = {"k": K, "lam": LAM}
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(slipped[name], rel=1e-9), name
