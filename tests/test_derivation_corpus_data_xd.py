"""The xd batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xd cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, the notes' restitution equation (4), components of a velocity, a fall and a rise,
an impulse, kinetic energies), with the student's slip made on purpose for the slip values. Answers
in letters (u, e, alpha) are checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import (
    CASES,
    _bounce,
    _given,
    _solve,
    batch_shape,
    letters_agree,
    numbers_agree,
)

XD_CASES = [c for c in CASES if c.name.startswith("xd")]
# (u, e, alpha in radians) for the letters
POINTS = ((1.0, 0.5, 0.4), (2.0, 0.3, 0.9), (1.5, 0.9, 1.2))
DEG = math.radians


def _case(prefix: str):
    return next(c for c in XD_CASES if c.name.startswith(prefix))


def _pair(m_a: float, m_b: float, e: float, u_a: float, u_b: float, nel: float = 1.0) -> tuple[float, float]:
    """(3) and (4); nel = -1 writes (4) the wrong way round (v_A - v_B = e(u_A - u_B))."""
    return _solve(m_a, m_b, m_a * u_a + m_b * u_b, nel * e * (u_a - u_b))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _xd02(g: dict) -> tuple[dict, dict]:
    a, b = _pair(g["m_A"], g["m_B"], g["e"], g["v_A1"], g["v_B1"])
    sa, sb = _pair(g["m_A"], g["m_B"], g["e"], g["v_A1"], g["v_B1"], nel=-1.0)
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _xd03(g: dict) -> tuple[dict, dict]:
    mass = g["m_A"] + g["m_B"]
    v = g["m_A"] * g["v_A1"] / mass
    t1, t2 = 0.5 * g["m_A"] * g["v_A1"] ** 2, 0.5 * mass * v * v
    puck = 0.5 * g["m_A"] * (g["v_A1"] - v) ** 2  # the slip: 1/2 m (u - v)^2
    goalie = 0.5 * g["m_B"] * v * v
    return {"v_B2": v, "T_1": t1, "T_2": t2, "T_lost": t1 - t2}, {"T_lost": puck - goalie}


def _xd05(g: dict) -> tuple[dict, dict]:
    gh = 2 * g["g"] * g["h_0"]
    v_2 = math.sqrt(gh)  # back up to the start

    def worked(v_1: float) -> dict:
        return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}

    true = worked(math.sqrt(g["v_0"] ** 2 + gh))
    # the bounce helper agrees: e_floor from the true landing speed gives the rise back to h_0
    assert _bounce(g | {"e_floor": true["e_floor"]}, true["v_1"])["h_2"] == pytest.approx(g["h_0"])
    return true, worked(math.sqrt(g["v_0"] ** 2 + gh - 100.0))  # 441 + 784 added as 1125


def _xd09(g: dict) -> tuple[dict, None]:
    rel_a, rel_b = 45.0 - g["phi_n"], 120.0 - g["phi_n"]
    a_n, a_t = g["v_A1"] * math.cos(DEG(rel_a)), g["v_A1"] * math.sin(DEG(rel_a))
    b_n, b_t = g["v_B1"] * math.cos(DEG(rel_b)), g["v_B1"] * math.sin(DEG(rel_b))
    a, b = _pair(g["m_A"], g["m_B"], g["e"], a_n, b_n)
    return {
        "v_A2n": a,
        "v_B2n": b,
        "v_A2": math.hypot(a, a_t),
        "v_B2": math.hypot(b, b_t),
        "psi_A2": g["phi_n"] + math.degrees(math.atan2(a_t, a)),
        "psi_B2": g["phi_n"] + math.degrees(math.atan2(b_t, b)),
    }, None


def _xd11(g: dict) -> tuple[dict, dict]:
    sep = g["v_B2"] - g["v_A2"]
    m_a = g["m_B"] * (g["v_B2"] - g["v_B1"]) / (g["v_A1"] - g["v_A2"])
    return {"e": -sep / (g["v_B1"] - g["v_A1"]), "m_A": m_a}, {"e": -sep / (-g["v_B1"] - g["v_A1"])}


def _xd12(g: dict) -> tuple[dict, None]:
    v = -g["e"] * g["v_A1"]
    t1, t2 = 0.5 * g["m_A"] * g["v_A1"] ** 2, 0.5 * g["m_A"] * v * v
    return {"v_A2": v, "J_n": -g["m_A"] * (v - g["v_A1"]), "T_1": t1, "T_2": t2, "T_lost": t1 - t2}, None


def _xd14(g: dict) -> tuple[dict, None]:
    u_a, u_b = g["v_A"], -g["v_B"]
    big_v = (g["m_A"] * u_a + g["m_B"] * u_b) / (g["m_A"] + g["m_B"])
    a, b = big_v - g["e"] * (u_a - big_v), big_v - g["e"] * (u_b - big_v)
    w = -g["e_wall"] * b
    return {"u_A": a, "u_B": b, "w_B": w, "again": "yes" if w < a else "no"}, None


NUMERIC_XD: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xd02": _xd02,
    "xd03": _xd03,
    "xd05": _xd05,
    "xd09": _xd09,
    "xd11": _xd11,
    "xd12": _xd12,
    "xd14": _xd14,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _xd01(p: dict) -> tuple[dict, None]:
    u, theta = p["u"], math.asin(1 / 2)  # sin(theta) = r/2r
    a, b = _pair(1.0, 1.0, 0.5, u * math.cos(theta), 0.0)
    return {"v_A2n": a, "v_B2": abs(b), "v_A2": math.hypot(a, u * math.sin(theta))}, None


def _xd04(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    a, b = _pair(4.0, 5.0, 0.5, u, 0.0)
    x = (4 * u - u / 2) / 9  # 4u = 4x + 5x + u/2
    return {"v_A2": a, "v_B2": b}, {"v_A2": x, "v_B2": x + u / 2}


def _xd06(p: dict) -> tuple[dict, None]:
    a, b = _pair(2.0, 1.0, 2 / 3, 2 * p["u"], 0.0)
    return {"v_A2": a, "v_B2": b}, None


def _xd07(p: dict) -> tuple[dict, dict]:
    u, e, al = p["u"], p["e"], p["alpha"]
    a_n, a_t = u * math.cos(al), u * math.sin(al)
    a, _ = _pair(1.0, 1.0, e, a_n, 0.0)
    return (
        {"v_A2t": a_t, "v_A2n": a, "beta_A2": math.atan2(a_t, a)},
        {"v_A2t": e * a_t, "beta_A2": math.atan2(e * a_t, a)},
    )


def _xd08(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _pair(2.0, 1.0, e, 4 * u, -3 * u)
    sa, _ = _solve(2.0, 1.0, 5 * u, e * (4 * u - 3 * u))  # slip 1: B's +3u in (4) only
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sa + e * u + 2 * e * u / 3}  # slip 2: 2e/3 too much


def _xd10(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    impulse = 4 * u * (1 + e) / (4 / 3)  # per unit m, from I/3 + I = 4u(1 + e)
    return {"v_A2": 4 * u - impulse}, None


def _xd13(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _pair(1.0, 1.0, e, u, 0.0)
    sa, _ = _pair(1.0, 1.0, e, u, 0.0, nel=-1.0)  # slip 1: vA2 - vB2 = eu
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": 2 * (u - sa)}  # slip 2: the /2 lost


def _xd15(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]

    def worked(along: float, across: float) -> dict:
        a, _ = _pair(1.0, 1.0, e, along, 0.0)
        return {"v_A2n": a, "deflection": math.atan2(across, a) - DEG(30)}

    c, s = u * math.cos(DEG(30)), u * math.sin(DEG(30))
    return worked(c, s), worked(s, c)


SYMBOLIC_XD: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xd01": _xd01,
    "xd04": _xd04,
    "xd06": _xd06,
    "xd07": _xd07,
    "xd08": _xd08,
    "xd10": _xd10,
    "xd13": _xd13,
    "xd15": _xd15,
}


def test_every_xd_case_is_worked_here() -> None:
    batch_shape(XD_CASES, set(NUMERIC_XD) | set(SYMBOLIC_XD))


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XD))
def test_the_xd_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XD[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XD))
def test_the_xd_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha in POINTS:
        names = {"u": u, "e": e, "alpha": alpha}
        true, slipped = SYMBOLIC_XD[prefix](names)
        letters_agree(case, names, true, slipped)
