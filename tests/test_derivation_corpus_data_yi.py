"""The yi batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the yi cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's rebound, kinetic energy, a fall, a bounce
and a rise), with the student's slip made on purpose for the slip values. Answers in letters (u, e)
are checked at a few points, with m = 1. Nothing here runs derive's checker.
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

YI_CASES = [c for c in CASES if c.name.startswith("yi")]
POINTS = ((1.0, 0.5, 2.0), (2.0, 0.3, 3.0), (1.5, 0.9, 1.5))  # (u, e, v)


def _case(prefix: str):
    return next(c for c in YI_CASES if c.name.startswith(prefix))


def _direct(m_a: float, m_b: float, e: float, u_a: float, u_b: float) -> tuple[float, float]:
    return _solve(m_a, m_b, m_a * u_a + m_b * u_b, e * (u_a - u_b))


# ---- numeric problems ----


def _yi01(g: dict) -> tuple[dict, None]:
    mass = g["m_A"] + g["m_B"]
    p = g["m_A"] * g["v_A1"]
    t_1 = 0.5 * g["m_A"] * g["v_A1"] ** 2
    t_2 = p * p / (2 * mass)
    return {"v_B2": p / mass, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _yi02(g: dict) -> tuple[dict, dict]:
    v_a2 = (g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B2"]) / g["m_A"]
    approach, separation = g["v_A1"] - g["v_B1"], g["v_B2"] - v_a2
    return {"v_A2": v_a2, "e": separation / approach}, {"e": approach / separation}  # upside down


def _yi04(g: dict) -> tuple[dict, dict]:
    c, s = math.cos(math.radians(g["theta"])), math.sin(math.radians(g["theta"]))

    def worked(along: float, across: float) -> dict:  # the n part with `along`, the t part with `across`
        a_n, b_n = g["v_A1"] * along, -g["v_B1"] * along
        v_an, v_bn = _direct(g["m_A"], g["m_B"], g["e"], a_n, b_n)
        return {"v_A2t": g["v_A1"] * across, "v_B2t": -g["v_B1"] * across, "v_A2n": v_an, "v_B2n": v_bn}

    return worked(c, s), worked(s, c)  # sin and cos swapped


def _yi10(g: dict) -> tuple[dict, None]:
    a, b = _direct(g["m_A"], g["m_B"], g["e"], g["v_A1"], g["v_B1"])
    t_1 = 0.5 * g["m_A"] * g["v_A1"] ** 2
    t_2 = 0.5 * g["m_A"] * a * a + 0.5 * g["m_B"] * b * b
    assert t_2 == pytest.approx(t_1)
    return {"v_A2": a, "v_B2": b, "T_1": t_1, "T_2": t_2}, None


def _yi11(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b, e = g["m_A"], g["m_B"], g["v_A1"], g["v_B1"], g["e"]
    a, b = _direct(m_a, m_b, e, u_a, u_b)
    sa, sb = _solve(m_a, m_b, m_a * u_a + m_b * u_b, e * (u_a + u_b))  # the approach as the sum
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _yi13(g: dict) -> tuple[dict, None]:
    tan_theta = 3.0  # the problem's theta = atan(3)
    e = (1 / tan_theta) / tan_theta  # tan(phi) = e tan(theta) = tan(90 - theta)
    u = 1.0
    along, normal = u / math.hypot(1, tan_theta), u * tan_theta / math.hypot(1, tan_theta)
    incoming, outgoing = (along, -normal), (along, e * normal)  # the rebound path is at 90° to AP
    assert incoming[0] * outgoing[0] + incoming[1] * outgoing[1] == pytest.approx(0, abs=1e-12)
    return {"e": e}, None


def _yi14(g: dict) -> tuple[dict, None]:
    u_a, u_b = _direct(g["m_A"], g["m_B"], g["e"], g["v_A"], -g["v_B"])
    w_b = -g["e_wall"] * u_b
    return {"u_A": u_a, "u_B": u_b, "w_B": w_b, "again": "yes" if w_b < u_a else "no"}, None


def _yi15(g: dict) -> tuple[dict, dict]:
    true = _bounce(g, math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"]))
    slipped = _bounce(g, math.sqrt(g["v_0"] ** 2 + g["g"] * g["h_0"]))  # 2(9.8)(1.6) worked as 15.68
    return true, slipped


NUMERIC_YI: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yi01": _yi01,
    "yi02": _yi02,
    "yi04": _yi04,
    "yi10": _yi10,
    "yi11": _yi11,
    "yi13": _yi13,
    "yi14": _yi14,
    "yi15": _yi15,
}


# ---- letters: masses in units of m (m = 1) ----


def _yi03(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    a, b = _direct(2.0, 3.0, e, 5 * u, 0.0)
    return {"v_A2": a, "v_B2": b}, None


def _yi05(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    a, b = _direct(4.0, 5.0, 0.5, u, 0.0)
    # slipped: 4u = 5a + 4b with b - a = u/2
    sa, sb = _solve(5.0, 4.0, 4 * u, 0.5 * u)
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _yi06(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    # 3y^2 - 4uy + u^2 = 0: the larger root y, x = u - y/2 (the other root gives x > y)
    y = (4 * u + math.sqrt(16 * u * u - 12 * u * u)) / 6
    x = u - y / 2
    assert 0.5 * 2 * x * x + 0.5 * y * y == pytest.approx(0.75 * u * u)
    sy = (4 * u + 4 * u) / 6  # sqrt(4u^2) taken as 4u
    sx = u - sy / 2
    return {"v_A2": x, "v_B2": y, "e": (y - x) / u}, {"v_A2": sx, "v_B2": sy, "e": (sy - sx) / u}


def _yi07(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _direct(3.0, 6.0, e, u, 0.0)
    t_1 = 0.5 * 3 * u * u
    sa, sb = _solve(1.0, 3.0, u, e * u)  # u = x + 3y
    return (
        {"v_A2": a, "v_B2": b, "T_lost": t_1 - (0.5 * 3 * a * a + 0.5 * 6 * b * b)},
        {"v_A2": sa, "v_B2": sb, "T_lost": t_1 - (0.5 * 3 * sa * sa + 6 * sb * sb)},  # B's half left out
    )


def _yi08(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    psi = math.radians(30)
    a_n, a_t = u * math.cos(psi), u * math.sin(psi)
    v_an, _ = _direct(1.0, 1.0, e, a_n, 0.0)
    deflection = math.atan2(a_t, v_an) - psi  # the student's tan(theta) line, worked from the components
    assert math.tan(deflection) == pytest.approx(math.sqrt(3) * (1 + e) / (5 - 3 * e))
    return {"v_A2n": v_an}, None


def _yi09(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a_n = u * math.cos(math.radians(30))
    _, v_bn = _direct(1.0, 1.0, e, a_n, 0.0)
    return {"v_B2": abs(v_bn)}, {"v_B2": a_n * (1 + e)}  # 2 v' not halved


def _yi12(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    theta = math.asin(1 / 2)  # offset r, centres 2r apart
    assert math.degrees(theta) == pytest.approx(30)

    def worked(along: float, across: float, gap: float) -> dict:
        a, b = _solve(1.0, 1.0, along, gap)
        return {"v_B2": abs(b), "v_A2n": a, "v_A2": math.hypot(a, across)}

    c, s = u * math.cos(theta), u * math.sin(theta)
    return worked(c, s, 0.5 * c), worked(s, c, s / 0.5)  # swapped; then approach / e


SYMBOLIC_YI: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yi03": _yi03,
    "yi05": _yi05,
    "yi06": _yi06,
    "yi07": _yi07,
    "yi08": _yi08,
    "yi09": _yi09,
    "yi12": _yi12,
}


def test_the_yi_batch_has_its_shape() -> None:
    batch_shape(YI_CASES, set(NUMERIC_YI) | set(SYMBOLIC_YI))
    one_slips = [s.name for c in YI_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YI))
def test_the_yi_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YI[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YI))
def test_the_yi_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, v in POINTS:
        names = {"u": u, "e": e, "v": v}
        true, slipped = SYMBOLIC_YI[prefix](names)
        letters_agree(case, names, true, slipped)
