"""The zl batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zl cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's rebound, impulses, kinetic energy, a fall and
a spring), with the student's slip made on purpose for the slip values. Answers in letters (u, e,
v, k, lam) are checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, closed_form

ZL_CASES = [c for c in CASES if c.name.startswith("zl")]
# (u, e, v, k, lam) for the letters
POINTS = ((1.0, 0.5, 2.0, 2.5, 0.3), (2.0, 0.3, 3.0, 1.5, 0.2), (1.5, 0.9, 1.5, 4.0, 0.45))


def _case(prefix: str):
    return next(c for c in ZL_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _zl02(g: dict) -> tuple[dict, None]:
    m, u, e = g["m_A"], g["v_A1"], g["e"]
    v = -e * u
    t_1, t_2 = 0.5 * m * u * u, 0.5 * m * v * v
    return {"v_A2": v, "J_n": m * (u - v), "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _zl03(g: dict) -> tuple[dict, dict]:
    w_a, w_b, u, e = g["W_A"], g["W_B"], g["v_A1"], g["e"]
    a, b = _solve(w_a, w_b, w_a * u, e * u)  # g cancels
    sa, sb = _solve(w_b, w_a, w_a * u, e * u)  # the masses exchanged after the impact
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _zl04(g: dict) -> tuple[dict, None]:
    m_1, m_2, v_1, v_2, e = g["m_A"], g["m_B"], g["v_A1"], g["v_B1"], g["e"]
    cm = (m_1 * v_1 + m_2 * v_2) / (m_1 + m_2)
    return {"v_A2": cm - e * (v_1 - cm), "v_B2": cm - e * (v_2 - cm)}, None


def _zl06(g: dict) -> tuple[dict, dict]:
    m_a, m_b, e, s = g["m_A"], g["m_B"], g["e"], g["v_B1"]

    def worked(along: float, across: float) -> dict:
        # m_a a + m_b along = m_b b; b = e (a - along)
        a = (m_b * along + m_b * e * along) / (m_b * e - m_a)
        b = e * (a - along)
        beta = math.degrees(math.atan(across / b))
        return {"v_A1n": a, "v_B2": math.hypot(b, across), "beta_B2": beta, "delta_B": 60 - beta}

    c60, s60 = s * math.cos(math.radians(60)), s * math.sin(math.radians(60))
    return worked(c60, s60), worked(s60, c60)  # sin and cos swapped


def _zl07(g: dict) -> tuple[dict, None]:
    a_n, a_t, b_n = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30)), g["v_B1n"]
    j = (1 + g["e"]) * 0.5 * (a_n - b_n)  # per unit m
    return {"v_A2n": a_n - j, "v_B2n": b_n + j, "v_A2": math.hypot(a_n - j, a_t), "v_B2": abs(b_n + j)}, None


def _zl08(g: dict) -> tuple[dict, dict]:
    e, mass = g["e"], g["W_A"] / 32.2

    def worked(cos30: float, m: float) -> dict:
        n, t = g["v_A1"] * cos30, g["v_A1"] * 0.5
        a, b = _solve(1.0, 1.0, n, e * n)
        return {"v_A2n": a, "v_B2": b, "v_A2": math.hypot(a, t), "J_n": m * b}

    return worked(math.cos(math.radians(30)), mass), worked(0.87, g["W_A"])  # .87; 47 lb as the mass


def _zl09(g: dict) -> tuple[dict, None]:
    m, u, e = g["m_A"], g["v_A1"], g["e"]
    return {"v_A2": -e * u, "J_n": m * (u + e * u), "T_lost": 0.5 * m * u * u * (1 - e * e)}, None


def _zl11(g: dict) -> tuple[dict, dict]:
    m, u = g["m_A"], g["v_A1"]

    def worked(perp: float) -> dict:
        return {"v_A1n": perp, "J_n": m * (perp + g["e"] * perp)}

    return worked(u * math.cos(math.radians(45))), worked(u * math.cos(45))  # radians


def _zl12(g: dict) -> tuple[dict, None]:
    m_1, m_2, v_1, v_2 = g["m_A"], g["m_B"], g["v_A1"], g["v_B2"]
    j = m_2 * v_2
    common = m_1 * v_1 / (m_1 + m_2)
    j_d = m_2 * common
    return {"v_A2": v_1 - j / m_1, "e": (j - j_d) / j_d}, None


def _zl13(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b, v_a = g["m_A"], g["m_B"], g["v_A1"], g["v_B1"], g["v_A2"]
    v_b = (m_a * u_a + m_b * u_b - m_a * v_a) / m_b
    s_b = 3.44 / m_b  # 2.4 + 0.96 added as 3.44
    t_1 = 0.5 * m_a * u_a**2 + 0.5 * m_b * u_b**2
    s_t2 = 0.5 * m_a * abs(v_a) + 0.5 * m_b * s_b**2  # A's speed not squared
    return (
        {"v_B2": v_b, "e": (v_b - v_a) / (u_a - u_b)},
        {"v_B2": s_b, "e": (s_b - v_a) / (u_a - u_b), "T_2": s_t2, "T_lost": t_1 - s_t2},
    )


def _zl14(g: dict) -> tuple[dict, dict]:
    u_a, u_b, v_a, v_b, m_b = g["v_A"], -g["v_B"], g["s_A"], g["s_B"], g["m_B"]
    m_a = m_b * (v_b - u_b) / (u_a - v_a)
    w = (m_b * v_b - g["I_w"]) / m_b
    s_w = (round(m_b * v_b - g["I_w"], 2) - 0.04) / m_b  # -0.10 written -0.14
    return (
        {"e": (v_b - v_a) / (u_a - u_b), "m_A": m_a, "u_B": v_b, "w_B": w, "e_wall": -w / v_b},
        {"w_B": s_w, "e_wall": -s_w / v_b},
    )


def _zl15(g: dict) -> tuple[dict, None]:
    k, mass = g["k"] * 1000, g["m_block"] + g["m_pan"]
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    v = g["m_block"] * v_1 / mass
    d = g["m_block"] * g["g"] / k
    amplitude = math.sqrt(d * d + v * v * mass / k)
    x = d + amplitude
    # the same x from energy: (1/2) M V^2 + M g x = (k/2)((delta + x)^2 - delta^2), delta = m_pan g/k
    delta = g["m_pan"] * g["g"] / k
    assert 0.5 * mass * v * v + mass * g["g"] * x == pytest.approx(0.5 * k * ((delta + x) ** 2 - delta**2))
    return {"v_1": v_1, "V": v, "x": x}, None


NUMERIC_ZL: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zl02": _zl02,
    "zl03": _zl03,
    "zl04": _zl04,
    "zl06": _zl06,
    "zl07": _zl07,
    "zl08": _zl08,
    "zl09": _zl09,
    "zl11": _zl11,
    "zl12": _zl12,
    "zl13": _zl13,
    "zl14": _zl14,
    "zl15": _zl15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _zl01(p: dict) -> tuple[dict, dict]:
    u, k, lam = p["u"], p["k"], p["lam"]
    v = (u + k * lam * u) / k  # m u + k m lam u = k m v
    return {"e": v / (u - lam * u), "v_B2": v}, {"e": (u - lam * u) / v}  # upside down


def _zl05(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 1.0, u, e * u)
    return {"v_A2": a, "v_B2": b}, {"v_A2": (2 * u - u + e * u) / 2}  # the sign lost in the bracket


def _zl10(p: dict) -> tuple[dict, dict]:
    v, e = p["v"], 0.2
    after = 2 * (-v) + 3 * 1.5 * v  # 2a + 3b
    gap = (1.5 * v + v) / e

    def worked(sign: float) -> dict:  # a + sign*b = gap
        # 2a + 3b = after, a = gap - sign b -> 2 gap + (3 - 2 sign) b = after
        b = (after - 2 * gap) / (3 - 2 * sign)
        return {"v_A1": gap - sign * b, "v_B1": b}

    return worked(-1.0), worked(1.0)  # a - b = gap; slip: a + b = gap


SYMBOLIC_ZL: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zl01": _zl01,
    "zl05": _zl05,
    "zl10": _zl10,
}


def test_every_zl_case_is_worked_here() -> None:
    assert len(ZL_CASES) == 15
    assert {c.name[:4] for c in ZL_CASES} == set(NUMERIC_ZL) | set(SYMBOLIC_ZL)
    by_category = sorted(c.verdict.category for c in ZL_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZL_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in ZL_CASES}) == 15
    for case in ZL_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in ZL_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZL))
def test_the_zl_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZL[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZL))
def test_the_zl_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, v, k, lam in POINTS:
        names = {"u": u, "e": e, "v": v, "k": k, "lam": lam}
        true, slipped = SYMBOLIC_ZL[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            worked = slipped[name]
            assert closed_form(str(formula), names) == pytest.approx(worked, rel=1e-9, abs=1e-12), name
