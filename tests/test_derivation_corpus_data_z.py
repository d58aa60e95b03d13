"""The z batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the z cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum,
Newton's law of restitution, a wall's rebound, the energy of a fall, a rise or a spring), with
the student's slip made on purpose for the slip values. Letters (u, v, e) are checked at a few
points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

Z_CASES = [c for c in CASES if c.name.startswith("z") and c.name[1:3].isdigit()]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters; e only where e is a letter


def _case(prefix: str):
    return next(c for c in Z_CASES if c.name.startswith(prefix))


# ---- numeric problems: name -> (true values, slip values or None) from the givens ----


def _z02(g: dict) -> tuple[dict, None]:
    theta = math.atan(3.0)  # tan theta = 3 (the problem's "atan(3)")
    phi = math.pi / 2 - theta  # angle APB = 90 deg: theta + phi = 90 deg
    return {"e": math.tan(phi) / math.tan(theta)}, None


def _z03(g: dict) -> tuple[dict, None]:
    u_n, u_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    v_an, v_bn = _solve(g["W_A"], g["W_B"], g["W_A"] * u_n, g["e"] * u_n)
    true = {"v_A2n": v_an, "v_B2n": v_bn, "v_A2t": u_t, "v_A2": math.hypot(v_an, u_t), "v_B2": v_bn}
    return true | {"J_n": g["W_B"] / 32.2 * v_bn}, None


def _z04(g: dict) -> tuple[dict, None]:
    m1, m2, v1 = g["m_A"], g["m_B"], g["v_A1"]
    return {"v_A2": (m1 - m2) / (m1 + m2) * v1, "v_B2": 2 * m1 / (m1 + m2) * v1}, None


def _z07(g: dict) -> tuple[dict, dict]:
    u_n = g["v_A1"] * math.cos(math.radians(g["theta"]))
    # the student's 0.060 x 39.6 with a decimal place lost (a tenth of the product)
    return {"v_A1n": u_n, "J_n": g["m_A"] * (1 + g["e"]) * u_n}, {"J_n": g["m_A"] * 39.6 / 10}


def _z08(g: dict) -> tuple[dict, dict]:
    w_n = g["v_B1t"] / math.tan(math.radians(45))
    v_a = (g["m_A"] * g["v_A1n"] - g["m_B"] * w_n) / g["m_A"]
    true = {"e": (w_n - v_a) / g["v_A1n"], "v_B2n": w_n, "v_A2": abs(v_a)}
    return true, {"e": (math.hypot(w_n, g["v_B1t"]) - v_a) / g["v_A1n"]}  # B's speed in NEL


def _z10(g: dict) -> tuple[dict, dict]:
    def after(u: float) -> dict:
        v_a, v_b = _solve(g["W_A"] / 32.2, g["W_B"] / 32.2, g["W_A"] / 32.2 * u, g["e"] * u)
        return {"v_A2": v_a, "v_B2": v_b}

    return after(g["v_A1"]), after(19.567)  # 19.657 copied as 19.567


def _train(g: dict, u_b: float) -> dict:
    v = (g["m_A"] * g["v_A1"] + g["m_B"] * u_b) / (g["m_A"] + g["m_B"])
    t1 = 0.5 * g["m_A"] * g["v_A1"] ** 2 + 0.5 * g["m_B"] * g["v_B1"] ** 2
    t2 = 0.5 * (g["m_A"] + g["m_B"]) * v**2
    return {"v_A2": v, "v_B2": v, "T_1": t1, "T_2": t2, "T_lost": t1 - t2}


def _z12(g: dict) -> tuple[dict, dict]:
    true = _train(g, g["v_B1"])
    slipped = _train(g, -g["v_B1"])  # slip 1: B's velocity taken +0.120
    assert round(true["T_1"]) == 7542
    t_1 = 7452.0  # slip 2: 6750 + 792 written 7452 (the digits of 7542 transposed)
    return true, slipped | {"T_1": t_1, "T_lost": t_1 - slipped["T_2"]}


def _z13(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b = 2.0, 3.0, g["v_A1"], g["v_B1"]  # the masses 2m and 3m, in units of m
    p = m_a * u_a + m_b * u_b
    v_a, v_b = _solve(m_a, m_b, p, g["e"] * (u_a - u_b))
    lost = 0.5 * m_a * (u_a**2 - v_a**2) + 0.5 * m_b * (u_b**2 - v_b**2)
    s_a, s_b = _solve(m_a, m_b, p, g["e"] * (u_a + u_b))  # slip 1: B's speed in NEL
    s_lost = 0.5 * m_a * (u_a - s_a) ** 2 + 0.5 * m_b * (u_b - s_b) ** 2  # slip 2: 1/2 m (u - v)^2
    return {"v_A2": v_a, "v_B2": v_b, "T_lost": lost}, {"v_A2": s_a, "v_B2": s_b, "T_lost": s_lost}


def _z14(g: dict) -> tuple[dict, None]:
    """The compression s from the spring's unstretched length; x = s_2 - s_1."""
    k = 20000.0  # "20 kN/m"
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    big_v = g["m_block"] * v_1 / (g["m_block"] + g["m_pan"])
    mass, s_1 = g["m_block"] + g["m_pan"], g["m_pan"] * g["g"] / k
    # 1/2 M V^2 + 1/2 k s_1^2 = -M g (s - s_1) + 1/2 k s^2: a quadratic in s
    a, b, c = k / 2, -mass * g["g"], mass * g["g"] * s_1 - 0.5 * mass * big_v**2 - 0.5 * k * s_1**2
    s_2 = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)
    return {"v_1": v_1, "V": big_v, "x": s_2 - s_1}, None


def _z15(g: dict) -> tuple[dict, dict]:
    m, big_m, v_0 = g["m_bullet"], g["m_block"], g["v_0"]
    v = m * v_0 / (m + big_m)
    true = {"V": v, "T_after": 0.5 * (m + big_m) * v**2, "h_2": v**2 / (2 * g["g"])}
    s_v = math.sqrt(m * v_0**2 / (m + big_m))  # kinetic energy kept in the impact
    slipped = {"V": s_v, "T_after": 0.5 * m * v_0**2, "h_2": s_v**2 / (2 * g["g"])}
    return true, slipped


NUMERIC_Z: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "z02": _z02,
    "z03": _z03,
    "z04": _z04,
    "z07": _z07,
    "z08": _z08,
    "z10": _z10,
    "z12": _z12,
    "z13": _z13,
    "z14": _z14,
    "z15": _z15,
}


# ---- letters: name -> (u, e) -> (true values, slip values or None) ----


def _z01(u: float, _e: float) -> tuple[dict, None]:
    v_a, v_b = _solve(2.0, 1.0, 2.0 * 2 * u, 2 / 3 * 2 * u)
    return {"v_A2": v_a, "v_B2": v_b}, None


def _z05(u: float, _e: float) -> tuple[dict, None]:
    """u stands for the letter v here: after, P at -v and Q at 3v/2; solve CLM and NEL for before."""
    v = u
    sep = 1.5 * v - (-v)  # = e (x - y) with e = 1/5
    approach = sep / (1 / 5)
    p = 2 * (-v) + 3 * (1.5 * v)  # = 2x + 3y
    y = (p - 2 * approach) / 5  # x = y + approach
    return {"v_A1": y + approach, "v_B1": y}, None


def _z06(u: float, _e: float) -> tuple[dict, dict]:
    e = 0.5
    true = _solve(4.0, 5.0, 4 * u, e * u)
    slipped = _solve(4.0, 5.0, 4 * u, -e * u)  # v1 - v2 = e u
    return {"v_A2": true[0], "v_B2": true[1]}, {"v_A2": slipped[0], "v_B2": slipped[1]}


def _z09(u: float, e: float) -> tuple[dict, dict]:
    v_a, v_b = _solve(1.0, 1.0, u, e * u)
    s_a = (u + e * u) / 2  # 2vA = u + eu
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": u - s_a}


def _z11(u: float, _e: float) -> tuple[dict, dict]:
    mu = 9 / 10  # m 9m / 10m, in units of m
    e = math.sqrt(1 - 0.5 / mu)  # (1/2) mu (1 - e^2) u^2 = (1/2)(1/2) u^2
    v_a, v_b = _solve(1.0, 9.0, u, e * u)
    s_a = (u - e * u) / 10  # u = 9 vA + vB with vB = vA + e u
    return {"e": e, "v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_a + e * u}


SYMBOLIC_Z: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "z01": _z01,
    "z05": _z05,
    "z06": _z06,
    "z09": _z09,
    "z11": _z11,
}


def test_every_z_case_is_worked_here() -> None:
    assert len(Z_CASES) == 15
    assert {c.name[:3] for c in Z_CASES} == set(NUMERIC_Z) | set(SYMBOLIC_Z)
    by_category = sorted(c.verdict.category for c in Z_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in Z_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_Z))
def test_the_z_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_Z[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_Z))
def test_the_z_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_Z[prefix](u, e)
        letters = {"v": u}  # z05's letter v
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(slipped[name], rel=1e-9), name
