"""The zk batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zk cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's rebound, kinetic energy, a fall, a rise and
a spring), with the student's slip made on purpose for the slip values. Answers in letters (u, e,
v) are checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, closed_form

ZK_CASES = [c for c in CASES if c.name.startswith("zk")]
# (u, e, v) for the letters
POINTS = ((1.0, 0.5, 2.0), (2.0, 0.3, 3.0), (1.5, 0.9, 1.5))


def _case(prefix: str):
    return next(c for c in ZK_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _zk01(g: dict) -> tuple[dict, None]:
    a_n, a_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    v_an, v_bn = _solve(1.0, 1.0, a_n + g["v_B1n"], g["e"] * (a_n - g["v_B1n"]))
    assert v_an == pytest.approx(g["v_B1n"]) and v_bn == pytest.approx(a_n)  # the swap
    return {"v_B2": math.hypot(v_bn, g["v_B1t"]), "v_A2": math.hypot(v_an, a_t)}, None


def _zk02(g: dict) -> tuple[dict, dict]:
    gap = g["e"] * (g["v_A1n"] - g["v_B1n"])

    def worked(b_n: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1n"] + g["m_B"] * b_n, gap)
        return {"v_A2n": a, "v_B2": abs(b), "v_A2": math.hypot(a, g["v_A1t"])}

    return worked(g["v_B1n"]), worked(-g["v_B1n"])  # B's -4 put in the momentum as +4


def _zk03(g: dict) -> tuple[dict, None]:
    mu = g["m_A"] * g["m_B"] / (g["m_A"] + g["m_B"])
    j = (1 + g["e"]) * mu * (g["v_A1"] - g["v_B1"])
    return {"J_n": j, "v_A2": g["v_A1"] - j / g["m_A"], "v_B2": g["v_B1"] + j / g["m_B"]}, None


def _zk04(g: dict) -> tuple[dict, dict]:
    e = g["e"]
    sin2 = (1 - 0.6) / (1 - e * e)  # cos^2 + e^2 sin^2 = 3/5
    slipped = (2 / 5) * 16 / 7 * 35 / 45  # 32/35 written 32/45
    assert sin2 == pytest.approx(32 / 35)
    return (
        {"alpha": math.degrees(math.asin(math.sqrt(sin2)))},
        {"alpha": math.degrees(math.asin(math.sqrt(slipped)))},
    )


def _zk06(g: dict) -> tuple[dict, dict]:
    approach, separation = g["v_A1"] - g["v_B1"], g["v_B2"] - g["v_A2"]
    m_a = g["m_B"] * (g["v_B2"] - g["v_B1"]) / (g["v_A1"] - g["v_A2"])
    return {"e": separation / approach, "m_A": m_a}, {"e": approach / separation}  # upside down


def _zk09(g: dict) -> tuple[dict, dict]:
    u_a, u_b, e = g["v_A1"], g["v_B1"], g["e"]

    def worked(m_a: float, m_b: float) -> dict:  # momentum with (m_a, m_b); energies with 2m, 3m
        a, b = _solve(m_a, m_b, m_a * u_a + m_b * u_b, e * (u_a - u_b))
        t_1 = 0.5 * 2 * u_a**2 + 0.5 * 3 * u_b**2
        t_2 = 0.5 * 2 * a**2 + 0.5 * 3 * b**2
        return {"v_A2": a, "v_B2": b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    return worked(2.0, 3.0), worked(3.0, 2.0)


def _zk11(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b, e = g["m_A"], g["m_B"], g["v_A1"], g["v_B1"], g["e"]
    t_1 = 0.5 * m_a * u_a**2 + 0.5 * m_b * u_b**2
    a, b = _solve(m_a, m_b, m_a * u_a + m_b * u_b, e * (u_a - u_b))
    t_2 = 0.5 * m_a * a**2 + 0.5 * m_b * b**2
    sa, sb = _solve(m_a, m_b, m_a * u_a + m_b * u_b, e * (abs(u_a) - abs(u_b)))  # the speeds
    st_2 = m_a * sa**2 + m_b * sb**2  # the 1/2 left out
    return (
        {"v_A2": a, "v_B2": b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2},
        {"v_A2": sa, "v_B2": sb, "T_2": st_2, "T_lost": t_1 - st_2},
    )


def _zk13(g: dict) -> tuple[dict, dict]:
    m, u, e = g["m_A"], g["v_A1"], g["e"]
    v = -e * u
    return (
        {"v_A2": v, "J_n": m * (u - v), "T_lost": 0.5 * m * (u * u - v * v)},
        {"T_lost": 0.5 * m * (u - abs(v)) ** 2},
    )


def _zk14(g: dict) -> tuple[dict, None]:
    mass = g["m_bullet"] + g["m_block"]
    v = g["m_bullet"] * g["v_0"] / mass
    return {"V": v, "T_after": 0.5 * mass * v * v, "h_2": v * v / (2 * g["g"])}, None


def _zk15(g: dict) -> tuple[dict, dict]:
    mass, k = g["m_block"] + g["m_pan"], g["k"] * 1000  # kN/m to N/m
    delta = g["m_pan"] * g["g"] / k

    def worked(v_1: float) -> dict:
        v = g["m_block"] * v_1 / mass
        # (1/2) M V^2 + M g x = (k/2)(2 delta x + x^2)
        a, b, c = k / 2, k * delta - mass * g["g"], -0.5 * mass * v * v
        return {"v_1": v_1, "V": v, "x": (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)}

    return worked(math.sqrt(2 * g["g"] * g["h"])), worked(math.sqrt(g["g"] * g["h"]))  # 2(9.81)(2) as 19.62


NUMERIC_ZK: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zk01": _zk01,
    "zk02": _zk02,
    "zk03": _zk03,
    "zk04": _zk04,
    "zk06": _zk06,
    "zk09": _zk09,
    "zk11": _zk11,
    "zk13": _zk13,
    "zk14": _zk14,
    "zk15": _zk15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _zk05(p: dict) -> tuple[dict, None]:
    u = p["u"]
    a, b = _solve(2.0, 1.0, 2 * u, u / 3)
    return {"v_A2": a, "v_B2": b}, None


def _zk07(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    e = math.sqrt(1 - 0.5 / 0.9)  # reduced mass 9m/10: (9/10)(1 - e^2) = 1/2
    a, b = _solve(1.0, 9.0, u, e * u)
    assert 0.5 * a * a + 4.5 * b * b == pytest.approx(0.25 * u * u)
    slipped = (9 + math.sqrt(81 + 4 * 90 * 40)) / 180  # 90e^2 - 9e - 40 = 0
    return {"e": e, "v_A2": a, "v_B2": b}, {"e": slipped}


def _zk08(p: dict) -> tuple[dict, dict]:
    v = p["v"]
    approach = (1.5 * v + v) * 5  # a + b from restitution, e = 1/5

    def worked(m_p: float, m_q: float, total: float) -> dict:
        # m_p a - m_q b = m_p(-v) + m_q(1.5v); a + b = total
        b = (m_p * total - (-m_p * v + m_q * 1.5 * v)) / (m_p + m_q)
        return {"v_A1": total - b, "v_B1": -b}

    return worked(2.0, 3.0, approach), worked(3.0, 2.0, (1.5 * v + v) / 5)  # masses swapped; x 1/5


def _zk10(p: dict) -> tuple[dict, None]:
    u = p["u"]
    for alpha in (0.3, 0.7, 1.2):
        c, s = math.cos(alpha), math.sin(alpha)
        a, b = _solve(2.0, 1.0, 2 * u * c - u * c, 0.5 * (u * c + u * c))
        assert a == pytest.approx(0, abs=1e-12) and math.hypot(b, u * s) == pytest.approx(u)
    return {"v_A2n": 0.0, "v_B2": u}, None


def _zk12(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 1.0, 8 * u - 3 * u, e * 7 * u)
    return {"v_A2": a, "v_B2": b}, None


SYMBOLIC_ZK: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zk05": _zk05,
    "zk07": _zk07,
    "zk08": _zk08,
    "zk10": _zk10,
    "zk12": _zk12,
}


def test_every_zk_case_is_worked_here() -> None:
    assert len(ZK_CASES) == 15
    assert {c.name[:4] for c in ZK_CASES} == set(NUMERIC_ZK) | set(SYMBOLIC_ZK)
    by_category = sorted(c.verdict.category for c in ZK_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZK_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in ZK_CASES}) == 15
    for case in ZK_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in ZK_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZK))
def test_the_zk_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZK[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


def _agree(value: object, worked: float, names: dict, what: str) -> None:
    if isinstance(value, str):
        assert closed_form(value, names) == pytest.approx(worked, rel=1e-9, abs=1e-12), what
    else:  # a number the student reached (the slipped quadratic's root)
        assert value == pytest.approx(worked, rel=2e-4, abs=2e-4), what


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZK))
def test_the_zk_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, v in POINTS:
        names = {"u": u, "e": e, "v": v}
        true, slipped = SYMBOLIC_ZK[prefix](names)
        for name, formula in case.verdict.values.items():
            _agree(formula, true[name], names, name)
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            _agree(formula, slipped[name], names, f"slip {name}")
