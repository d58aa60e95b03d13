"""The xf batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xf cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, components of a velocity, an impulse, kinetic
energies), with the student's slip made on purpose for the slip values. Answers in letters (u, e,
alpha) are checked at a few points by solving the two linear equations numerically there. Nothing
here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, letters_agree, numbers_agree

XF_CASES = [c for c in CASES if c.name.startswith("xf")]
POINTS = ((1.0, 0.5, 0.4), (2.0, 0.3, 0.9), (1.5, 0.9, 1.2))  # (u, e, alpha in radians)


def _case(prefix: str):
    return next(c for c in XF_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _xf01(g: dict) -> tuple[dict, None]:
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1n"] + g["m_B"] * g["v_B1n"], g["e"] * (g["v_A1n"] - g["v_B1n"]))
    return {"v_A2n": a, "v_B2n": b, "v_A2t": g["v_A1t"], "v_A2": math.hypot(a, g["v_A1t"]), "v_B2": abs(b)}, None


def _xf02(g: dict) -> tuple[dict, None]:
    j = g["m_A"] * (g["v_A2"] - g["v_A1"])  # impulse on A
    v_b = g["v_B1"] - j / g["m_B"]
    return {"v_A2": g["v_A2"], "v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _xf06(g: dict) -> tuple[dict, None]:
    e = (g["s_B"] - g["s_A"]) / (g["v_A"] + g["v_B"])
    m_a = g["m_B"] * (g["s_B"] + g["v_B"]) / (g["v_A"] - g["s_A"])
    w = g["I_w"] / g["m_B"] - g["s_B"]
    return {"e": e, "m_A": m_a, "u_B": g["s_B"], "w_B": -w, "e_wall": w / g["s_B"]}, None


def _xf07(g: dict) -> tuple[dict, dict]:
    t = 3.0  # tan theta
    c2, s2 = 1 / (1 + t * t), t * t / (1 + t * t)
    # after (u cos, e u sin): c2 - e s2 = 0; the slip (u cos, u sin / e): c2 - s2/e = 0
    return {"e": c2 / s2}, {"e": s2 / c2}


def _xf08(g: dict) -> tuple[dict, dict]:
    m = g["m_A"]
    t1, t2 = 0.5 * m * g["v_A1"] ** 2, 0.5 * m * g["v_A2"] ** 2
    slipped = 0.5 * m * (2 * abs(g["v_A2"]))  # 2.40^2 worked as 2 x 2.40
    return {"e": -g["v_A2"] / g["v_A1"], "T_1": t1, "T_2": t2, "T_lost": t1 - t2}, {
        "T_2": slipped,
        "T_lost": t1 - slipped,
    }


def _xf09(g: dict) -> tuple[dict, dict]:
    c, s = math.cos(math.radians(g["theta"])), math.sin(math.radians(g["theta"]))
    a_n, a_t, b_n, b_t = g["v_A1"] * c, g["v_A1"] * s, -g["v_B1"] * c, -g["v_B1"] * s
    gap = g["e"] * (a_n - b_n)
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, gap)
    sa, sb = _solve(g["m_B"], g["m_A"], g["m_B"] * a_n + g["m_A"] * b_n, gap)  # masses exchanged
    return {"v_A2t": a_t, "v_B2t": b_t, "v_A2n": a, "v_B2n": b}, {"v_A2n": sa, "v_B2n": sb}


def _xf10(g: dict) -> tuple[dict, dict]:
    v0, vc = g["v_0"], g["v_C"]
    e = math.sqrt(4 * vc / v0) - 1  # 7(1 + e)^2/4 = 4
    # slip: y = (7 + e)/2, (7 + e)(1 + e) = 4 vc: e^2 + 8e + 7 - 16 = 0
    bq, cq = v0 + 1, v0 - 4 * vc
    se = (-bq + math.sqrt(bq * bq - 4 * cq)) / 2
    return {"u_B": v0 * (1 + e) / 2, "e": e}, {"u_B": (v0 + se) / 2, "e": se}


def _xf11(g: dict) -> tuple[dict, dict]:
    rhs = g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B2"]
    v_a, slipped = rhs / g["m_A"], -rhs / g["m_A"]

    def e(v: float) -> float:
        return (g["v_B2"] - v) / g["v_A1"]

    return {"v_A2": v_a, "e": e(v_a)}, {"v_A2": slipped, "e": e(slipped)}


def _xf13(g: dict) -> tuple[dict, dict]:
    m_a, m_b = g["W_A"] / 32.2, g["W_B"] / 32.2
    p, gap = m_a * g["v_A1"], g["e"] * g["v_A1"]
    a, b = _solve(m_a, m_b, p, gap)
    sb, sa = _solve(m_b, m_a, p, gap)  # (v_A)2 = (v_B)2 + e u: B's velocity first
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


NUMERIC_XF: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xf01": _xf01,
    "xf02": _xf02,
    "xf06": _xf06,
    "xf07": _xf07,
    "xf08": _xf08,
    "xf09": _xf09,
    "xf10": _xf10,
    "xf11": _xf11,
    "xf13": _xf13,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _xf03(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    a, b = _solve(3.0, 6.0, 3 * u, e * u)
    lost = 0.5 * 3 * u * u - 0.5 * 3 * a * a - 0.5 * 6 * b * b
    return {"v_A2": a, "v_B2": b, "T_lost": lost}, None


def _xf04(p: dict) -> tuple[dict, None]:
    a, b = _solve(1.0, 2.0, p["u"], p["e"] * p["u"])
    return {"v_A2": a, "v_B2": b}, None


def _xf05(p: dict) -> tuple[dict, None]:
    a, b = _solve(1.0, 1.0, p["u"], p["e"] * p["u"])
    return {"v_A2": a, "v_B2": b}, None


def _xf12(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 3.0, 10 * u, 5 * e * u)
    sa, sb = _solve(3.0, 2.0, 10 * u, 5 * e * u)  # P's 3m and Q's 2m after
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _xf14(p: dict) -> tuple[dict, dict]:
    u, e, al = p["u"], p["e"], p["alpha"]

    def worked(along: float, across: float, halve: bool) -> dict:
        x, _ = _solve(1.0, 1.0, along, e * along)
        x = x if halve else 2 * x  # slip 2: the 2 not divided out
        return {"v_A2n": x, "v_A2t": across, "beta_A2": math.atan2(across, x)}

    return worked(u * math.cos(al), u * math.sin(al), True), worked(u * math.sin(al), u * math.cos(al), False)


def _xf15(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 1.0, 4 * u - u, 3 * e * u)
    # slip 1: Q's momentum +mu, so 3x = 5u - 3eu; slip 2: only 5u divided by 3
    sa = (4 * u + u) / 3 - 3 * e * u
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sa + 3 * e * u}


SYMBOLIC_XF: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xf03": _xf03,
    "xf04": _xf04,
    "xf05": _xf05,
    "xf12": _xf12,
    "xf14": _xf14,
    "xf15": _xf15,
}


def test_every_xf_case_is_worked_here() -> None:
    batch_shape(XF_CASES, set(NUMERIC_XF) | set(SYMBOLIC_XF))


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XF))
def test_the_xf_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XF[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XF))
def test_the_xf_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha in POINTS:
        names = {"u": u, "e": e, "alpha": alpha}
        true, slipped = SYMBOLIC_XF[prefix](names)
        letters_agree(case, names, true, slipped)
