"""The xi batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xi cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's rebound, kinetic energy, a fall, a slide and
a rise), with the student's slip made on purpose for the slip values. Answers in letters are
checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, letters_agree, numbers_agree

XI_CASES = [c for c in CASES if c.name.startswith("xi")]


def _case(prefix: str):
    return next(c for c in XI_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _xi01(g: dict) -> tuple[dict, None]:
    m_b = g["m_A"] * (g["v_A1"] - g["v_A2"]) / (g["v_B2"] - g["v_B1"])
    e = (g["v_B2"] - g["v_A2"]) / (g["v_A1"] - g["v_B1"])
    return {"m_B": m_b, "e": e}, None


def _xi02(g: dict) -> tuple[dict, None]:
    rad = math.radians
    a_n, a_t = g["v_A1"] * math.cos(rad(45 - 20)), g["v_A1"] * math.sin(rad(45 - 20))
    b_n, b_t = g["v_B1"] * math.cos(rad(120 - 20)), g["v_B1"] * math.sin(rad(120 - 20))
    v_an, v_bn = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, g["e"] * (a_n - b_n))
    return {
        "v_A2n": v_an,
        "v_B2n": v_bn,
        "v_A2": math.hypot(v_an, a_t),
        "v_B2": math.hypot(v_bn, b_t),
        "psi_A2": g["phi_n"] + math.degrees(math.atan2(a_t, v_an)),
        "psi_B2": g["phi_n"] + math.degrees(math.atan2(b_t, v_bn)),
    }, None


def _xi04(g: dict) -> tuple[dict, None]:
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1"], g["e"] * g["v_A1"])
    return {"v_A2": a, "v_B2": b}, None


def _xi05(g: dict) -> tuple[dict, dict]:
    m, u = g["m_A"], g["v_A1"]
    v = -g["e"] * u
    return {"v_A2": v, "T_lost": 0.5 * m * (u * u - v * v)}, {"T_lost": m * (u * u - v * v)}  # no 1/2


def _xi11(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u = g["m_A"], g["m_B"], g["v_A1"]
    a, b = _solve(m_a, m_b, m_a * u, g["e"] * u)
    assert a == pytest.approx((m_a - m_b) / (m_a + m_b) * u)
    return {"v_A2": a, "v_B2": b}, {"v_A2": (m_b - m_a) / (m_a + m_b) * u}  # masses swapped


def _xi12(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]

    def worked(v_b: float) -> dict:
        return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}

    true = worked((p - g["m_A"] * g["v_A2"]) / g["m_B"])
    return true, worked(true["v_B2"] - 1.0)  # 10 - 4 worked as 5


def _xi13(g: dict) -> tuple[dict, dict]:
    sep = g["v_B2"] - g["v_A2"]
    rhs = g["m_B"] * g["v_B2"] - g["m_B"] * g["v_B1"]  # 0.58 + 0.3
    true = {"e": sep / (g["v_A1"] - g["v_B1"]), "m_A": rhs / (g["v_A1"] - g["v_A2"])}
    slipped_rhs = g["m_B"] * g["v_B2"] + g["m_B"] * g["v_B1"]  # 0.58 - 0.3
    return true, {"e": sep / (g["v_A1"] + g["v_B1"]), "m_A": slipped_rhs / (g["v_A1"] - g["v_A2"])}


def _xi14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    u_a, u_b = _solve(g["W_A"], g["W_B"], g["W_A"] * v_1, g["e"] * v_1)  # g cancels
    return {"v_1": v_1, "u_A": u_a, "u_B": u_b, "d_B": u_b**2 / (2 * g["mu_k"] * g["g"])}, None


def _xi15(g: dict) -> tuple[dict, dict]:
    mass = g["m_bullet"] + g["m_block"]
    v = g["m_bullet"] * g["v_0"] / mass
    t_true, t_slip = 0.5 * mass * v * v, mass * v * v  # the 1/2 left out
    return (
        {"V": v, "T_after": t_true, "h_2": t_true / (mass * g["g"])},
        {"T_after": t_slip, "h_2": t_slip / (mass * g["g"])},
    )


NUMERIC_XI: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xi01": _xi01,
    "xi02": _xi02,
    "xi04": _xi04,
    "xi05": _xi05,
    "xi11": _xi11,
    "xi12": _xi12,
    "xi13": _xi13,
    "xi14": _xi14,
    "xi15": _xi15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _xi03(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    a, b = _solve(2.0, 1.0, 2 * u, u / 3)
    sa = (2 * u + u / 3) / 3  # 2x + y = 2u and x - y = u/3 added
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": 2 * u - 2 * sa}


def _xi06(p: dict) -> tuple[dict, dict]:
    u, e, c, s = p["u"], p["e"], math.cos(math.radians(30)), math.sin(math.radians(30))

    def worked(along: float) -> dict:
        a, _ = _solve(1.0, 1.0, along, e * along)
        return {"v_A2n": a}

    return worked(u * c), worked(u * s)  # sin and cos swapped: u sin 30 along the line


def _xi07(p: dict) -> tuple[dict, None]:
    u, k, lam = p["u"], p["k"], p["lam"]
    v_b = (u + k * lam * u) / k  # m u + k m lam u = k m v_B, S at rest
    return {"e": v_b / (u - lam * u), "v_B2": v_b}, None


def _xi08(p: dict) -> tuple[dict, dict]:
    big_u = p["u"]  # U
    theta = math.asin(1 / 2)  # sin(theta) = r/2r
    c, s = big_u * math.cos(theta), big_u * math.sin(theta)
    a, b = _solve(1.0, 1.0, c, 0.5 * c)
    slipped_b = s + 0.5 * s  # along U sin 30; 2 v_B = 3U/4 not halved
    return (
        {"v_B2": b, "v_A2n": a},
        {"v_B2": slipped_b, "v_A2n": slipped_b - 0.5 * s},
    )


def _xi09(p: dict) -> tuple[dict, dict]:
    u, e, alpha = p["u"], p["e"], p["alpha"]  # e is e_1
    along, normal = u * math.cos(alpha), u * math.sin(alpha)
    return (
        {"beta": math.atan2(e * normal, along)},
        {"beta": math.atan2(normal, e * along)},  # e_1 on the component along the cushion
    )


def _xi10(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 1.0, u, e * u)
    return {"v_A2": a, "v_B2": b}, None


SYMBOLIC_XI: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xi03": _xi03,
    "xi06": _xi06,
    "xi07": _xi07,
    "xi08": _xi08,
    "xi09": _xi09,
    "xi10": _xi10,
}
POINTS = (
    {"u": 1.0, "e": 0.5, "k": 2.0, "lam": 0.25, "alpha": 0.7},
    {"u": 2.0, "e": 0.3, "k": 3.0, "lam": 0.1, "alpha": 0.3},
    {"u": 1.5, "e": 0.9, "k": 1.5, "lam": 0.4, "alpha": 1.1},
)


def test_every_xi_case_is_worked_here() -> None:
    batch_shape(XI_CASES, set(NUMERIC_XI) | set(SYMBOLIC_XI))
    one_slips = [s.name for c in XI_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XI))
def test_the_xi_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XI[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XI))
def test_the_xi_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for names in POINTS:
        true, slipped = SYMBOLIC_XI[prefix](names)
        letters_agree(case, names, true, slipped)
