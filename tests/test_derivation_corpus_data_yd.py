"""The yd batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the yd cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, components of a velocity, energy for a ramp, suvat for
a slide, an impulse), with the student's slip made on purpose for the slip values. Answers in letters
(u, e, alpha) are checked at a few points by solving the two linear equations numerically there.
Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, letters_agree, numbers_agree

YD_CASES = [c for c in CASES if c.name.startswith("yd")]
# (u, e, alpha in radians) for the letters
POINTS = ((1.0, 0.5, 0.4), (2.0, 0.3, 0.9), (1.5, 0.9, 1.2))


def _case(prefix: str):
    return next(c for c in YD_CASES if c.name.startswith(prefix))


def _after(m_a: float, m_b: float, u_a: float, u_b: float, e: float) -> tuple[float, float]:
    """Momentum and v_B - v_A = e (u_A - u_B)."""
    return _solve(m_a, m_b, m_a * u_a + m_b * u_b, e * (u_a - u_b))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _yd01(g: dict) -> tuple[dict, None]:
    v = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]) / (g["m_A"] + g["m_B"])  # centre of mass
    return {"v_A2": v - g["e"] * (g["v_A1"] - v), "v_B2": v - g["e"] * (g["v_B1"] - v)}, None


def _yd02(g: dict) -> tuple[dict, None]:
    m1, m2, v = g["m_A"], g["m_B"], g["v_A1"]
    return {"v_A2": (m1 - m2) / (m1 + m2) * v, "v_B2": 2 * m1 / (m1 + m2) * v, "T_1": 0.5 * m1 * v * v}, None


def _yd03(g: dict) -> tuple[dict, dict]:
    m, big, v = g["m_A"], g["m_B"], g["v_A1"]
    common = m * v / (m + big)
    before = 0.5 * m * v * v
    after = 0.5 * (m + big) * common**2
    slipped = 0.5 * m * (v - round(common, 4)) ** 2  # 1/2 m (v - v')^2 with v' = 0.0748
    true = {"v_B2": common, "T_1": before, "T_2": after, "T_lost": before - after}
    return true, {"T_lost": slipped, "T_2": before - slipped}


def _energies(v_a: float, v_b: float, u_a: float, u_b: float, b_squared: bool = True) -> dict:
    before = 0.5 * 2 * u_a**2 + 0.5 * 3 * (u_b**2 if b_squared else abs(u_b))  # in units of m
    after = 0.5 * 2 * v_a**2 + 0.5 * 3 * v_b**2
    return {"v_A2": v_a, "v_B2": v_b, "T_1": before, "T_2": after, "T_lost": before - after}


def _yd06(g: dict) -> tuple[dict, dict]:
    u_a, u_b, e = g["v_A1"], g["v_B1"], g["e"]
    true = _energies(*_after(2.0, 3.0, u_a, u_b, e), u_a, u_b)
    v_a, v_b = _solve(2.0, 3.0, 2 * u_a - 3 * u_b, e * (u_a - u_b))  # B's momentum taken positive
    return true, _energies(v_a, v_b, u_a, u_b, b_squared=False)


def _yd07(g: dict) -> tuple[dict, dict]:
    sin_a = 0.8
    cos_a = math.sqrt(1 - sin_a**2)

    def worked(along: float, across: float) -> dict:
        a, b = _after(g["m_A"], g["m_B"], along, g["v_B1n"], g["e"])
        return {"v_A2n": a, "v_B2n": b, "v_A2t": across, "v_A2": math.hypot(a, across)}

    v = g["v_A1"]
    return worked(v * cos_a, v * sin_a), worked(v * sin_a, v * cos_a)


def _yd08(g: dict) -> tuple[dict, None]:
    al = math.radians(g["alpha"])
    b_n, b_t = -g["u_B"] * math.cos(al), g["u_B"] * math.sin(al)
    x = -b_t * b_t / b_n  # u_B . v_B = 0 with v_B = (x, b_t)
    a = g["v_A1n"] + b_n - x  # equal masses
    return {"v_B2": math.hypot(x, b_t), "v_A2n": a, "e": (x - a) / (g["v_A1n"] - b_n)}, None


def _yd09(g: dict) -> tuple[dict, dict]:
    b_n = g["v_B1"] * math.cos(math.radians(60))
    b_t = g["v_B1"] * math.sin(math.radians(60))
    # m_A u + m_B b_n = m_B w and w = e (u - b_n): u (m_B e - m_A) = m_B b_n (1 + e)
    u = g["m_B"] * b_n * (1 + g["e"]) / (g["m_B"] * g["e"] - g["m_A"])

    def worked(w: float) -> dict:
        beta = math.degrees(math.atan2(b_t, w))
        return {"v_B2": math.hypot(w, b_t), "beta_B2": beta, "delta_B": 60 - beta}

    return {"v_A1n": u} | worked(g["e"] * (u - b_n)), worked(g["e"] * u)  # slip: 0.8 x 9


def _yd14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    u_a, u_b = _after(g["W_A"], g["W_B"], v_1, 0.0, g["e"])  # weights: g cancels
    return {"v_1": v_1, "u_A": u_a, "u_B": u_b, "d_B": u_b**2 / (2 * g["mu_k"] * g["g"])}, None


def _yd15(g: dict) -> tuple[dict, dict]:
    u_a, u_b, v_a, v_b = g["v_A"], -g["v_B"], g["s_A"], g["s_B"]
    e = (v_b - v_a) / (u_a - u_b)
    m_a = g["m_B"] * (v_b - u_b) / (u_a - v_a)
    w = g["I_w"] / g["m_B"] - g["s_B"]  # m_B (w + s_B) = I_w
    w_slip = 3.2 - g["s_B"]  # 0.68/0.2 worked as 3.2
    return {"e": e, "m_A": m_a, "e_wall": w / g["s_B"]}, {"e_wall": w_slip / g["s_B"]}


NUMERIC_YD: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yd01": _yd01,
    "yd02": _yd02,
    "yd03": _yd03,
    "yd06": _yd06,
    "yd07": _yd07,
    "yd08": _yd08,
    "yd09": _yd09,
    "yd14": _yd14,
    "yd15": _yd15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _yd04(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    v_a, v_b = _after(2.0, 1.0, 2 * u, 0.0, 2 / 3)
    # slips: the masses exchanged after (4u = v_A + 2v_B) and e upside down (v_B - v_A = 3u)
    s_b, s_a = _solve(2.0, 1.0, 4 * u, -(3 / 2) * 2 * u)  # as (v_B, v_A): 2v_B + v_A = 4u, v_A - v_B = -3u
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_b}


def _yd05(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    v_p, v_q = _after(1.0, 2.0, 3 * u, 0.0, e)
    return {"v_A2": v_p, "v_B2": v_q}, None


def _yd10(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    theta = math.asin(1 / 2)  # r / 2r

    def worked(along: float) -> dict:
        a, b = _after(1.0, 1.0, along, 0.0, 0.5)
        return {"v_A2n": a, "v_B2": abs(b)}

    return worked(u * math.cos(theta)), worked(u * math.sin(theta))


def _yd11(p: dict) -> tuple[dict, dict]:
    u, al = p["u"], p["alpha"]
    c, s = u * math.cos(al), u * math.sin(al)

    def worked(p_along: float) -> dict:
        a, b = _solve(2.0, 1.0, p_along, 0.5 * (c + c))
        return {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, s)}

    return worked(2 * c - c), worked(2 * c + c)  # slip: B's momentum taken positive


def _yd12(p: dict) -> tuple[dict, dict]:
    u, e, al = p["u"], p["e"], p["alpha"]
    true = math.atan2(e * u * math.sin(al), u * math.cos(al))
    slipped = math.atan2(u * math.sin(al), e * u * math.cos(al))  # e on the component along DC
    return {"beta": true}, {"beta": slipped}


def _yd13(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    along, across = u * math.cos(math.radians(30)), u * math.sin(math.radians(30))
    a, _ = _after(1.0, 1.0, along, 0.0, e)
    return {"v_A2n": a, "deflection": math.atan2(across, a) - math.radians(30)}, None


SYMBOLIC_YD: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yd04": _yd04,
    "yd05": _yd05,
    "yd10": _yd10,
    "yd11": _yd11,
    "yd12": _yd12,
    "yd13": _yd13,
}


def test_every_yd_case_is_worked_here() -> None:
    batch_shape(YD_CASES, set(NUMERIC_YD) | set(SYMBOLIC_YD))


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YD))
def test_the_yd_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YD[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YD))
def test_the_yd_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha in POINTS:
        names = {"u": u, "e": e, "alpha": alpha}
        true, slipped = SYMBOLIC_YD[prefix](names)
        letters_agree(case, names, true, slipped)
