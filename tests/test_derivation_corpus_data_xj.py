"""The xj batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xj cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's or the ground's rebound, kinetic energy, a
fall and a rise), with the student's slip made on purpose for the slip values. Answers in letters
(u, e) are checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, closed_form

XJ_CASES = [c for c in CASES if c.name.startswith("xj")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))
G_FT = 32.2


def _case(prefix: str):
    return next(c for c in XJ_CASES if c.name.startswith(prefix))


def _xj01(g: dict) -> tuple[dict, None]:
    m_a, m_b = g["W_A"] / G_FT, g["W_B"] / G_FT
    v = (m_a * g["v_A1"] + m_b * g["v_B1"]) / (m_a + m_b)  # e = 0: one common velocity
    return {"v_A2": v, "v_B2": v}, None


def _xj02(g: dict) -> tuple[dict, dict]:
    u_b, a = g["u_B"], math.radians(g["alpha"])
    b_n, b_t = -u_b * math.cos(a), u_b * math.sin(a)
    b2_n = b_t * math.tan(a)  # turned through a right angle
    a2_n = g["v_A1n"] + b_n - b2_n  # equal masses
    v_b2 = math.hypot(b2_n, b_t)
    e = (b2_n - a2_n) / (g["v_A1n"] - b_n)
    slipped = (v_b2 + abs(a2_n)) / (g["v_A1n"] + u_b)  # the speeds, not the components
    return {"v_B2": v_b2, "v_A2n": a2_n, "e": e}, {"e": slipped}


def _xj04(g: dict) -> tuple[dict, dict]:
    def worked(along: float, across: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * along + g["m_B"] * g["v_B1n"], g["e"] * (along - g["v_B1n"]))
        return {
            "v_A2n": a,
            "v_B2n": b,
            "v_A2t": across,
            "v_A2": math.hypot(a, across),
            "angle_loc": math.degrees(math.atan2(across, abs(a))),
        }

    s, c = math.sin(math.radians(60)), math.cos(math.radians(60))
    return worked(g["v_A1"] * c, g["v_A1"] * s), worked(g["v_A1"] * s, g["v_A1"] * c)  # sin/cos swapped


def _xj05(g: dict) -> tuple[dict, dict]:
    c, s = math.cos(math.radians(37.6)), math.sin(math.radians(37.6))
    a_n, a_t, b_n, b_t = g["v_A1"] * c, g["v_A1"] * s, -g["v_B1"] * c, -g["v_B1"] * s
    gap = g["e"] * (a_n - b_n)
    p = g["m_A"] * a_n + g["m_B"] * b_n
    a, b = _solve(g["m_A"], g["m_B"], p, gap)
    sa, sb = _solve(g["m_A"], g["m_B"], p + 10, gap)  # 19.80 written 29.80
    return {"v_A2t": a_t, "v_B2t": b_t, "v_A2n": a, "v_B2n": b}, {"v_A2n": sa, "v_B2n": sb}


def _xj06(g: dict) -> tuple[dict, None]:
    m, u, v = g["m_A"], g["v_A1"], g["v_A2"]
    t_1, t_2 = 0.5 * m * u * u, 0.5 * m * v * v
    e = -v / u
    assert (1 - e * e) * t_1 == pytest.approx(t_1 - t_2)
    return {"e": e, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _xj08(g: dict) -> tuple[dict, dict]:
    b_n, b_t = g["v_B1"] * math.cos(math.radians(60)), g["v_B1"] * math.sin(math.radians(60))
    m_a, m_b, e = g["m_A"], g["m_B"], g["e"]

    def worked(sign: float) -> dict:
        # m_a a + m_b b_n = m_b b; b = e (a - sign * b_n)  ->  m_a a + m_b b_n = m_b e a - m_b e sign b_n
        a = (m_b * b_n + m_b * e * sign * b_n) / (m_b * e - m_a)
        b = e * (a - sign * b_n)
        beta = math.degrees(math.atan2(b_t, b))
        return {"v_A1n": a, "v_B2": math.hypot(b, b_t), "beta_B2": beta, "delta_B": 60 - beta}

    return worked(1.0), worked(-1.0)  # approach a + 1 for a - 1


def _xj09(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b, v_a = g["m_A"], g["m_B"], g["v_A1"], g["v_B1"], g["v_A2"]
    v = (m_a * u_a + m_b * u_b - m_a * v_a) / m_b
    sv = (m_a * u_a + m_b * u_b - 0.01) / m_b  # 0.5(0.2) worked as 0.01
    return {"v_B2": v, "e": (v - v_a) / (u_a - u_b)}, {"v_B2": sv, "e": (sv - v_a) / (u_a + u_b)}


def _xj10(g: dict) -> tuple[dict, None]:
    w = g["v_B1t"] / math.tan(math.radians(45))
    v_a = (g["m_A"] * g["v_A1n"] - g["m_B"] * w) / g["m_A"]
    return {"e": (w - v_a) / g["v_A1n"], "v_B2n": w, "v_A2": abs(v_a)}, None


def _xj11(g: dict) -> tuple[dict, dict]:
    a_n, a_t = g["v_A1"] * 0.6, g["v_A1"] * 0.8
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * g["v_B1n"], g["e"] * (a_n - g["v_B1n"]))
    true = {"v_A2n": a, "v_A2t": a_t, "v_B2n": b, "v_A2": math.hypot(a, a_t)}
    true["dir_A_from_i"] = math.degrees(math.atan2(a_t, a))
    st = g["e"] * a_t  # e on the t component
    slipped = {"v_A2t": st, "v_A2": math.hypot(a, st), "dir_A_from_i": math.degrees(math.atan(st / abs(a)))}
    return true, slipped


def _xj13(g: dict) -> tuple[dict, dict]:
    p, gap = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"], g["e"] * (g["v_A1"] - g["v_B1"])
    a, b = _solve(g["m_A"], g["m_B"], p, gap)
    sa, sb = _solve(g["m_B"], g["m_A"], p, gap)  # masses exchanged after the impact
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _xj14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"])
    v_2 = math.sqrt(2 * g["g"] * g["h_0"])
    return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}, None


def _xj15(g: dict) -> tuple[dict, dict]:
    def worked(s_b: float) -> dict:
        u_a, u_b, v_a = g["v_A"], -g["v_B"], g["s_A"]
        m_a = g["m_B"] * (s_b - u_b) / (u_a - v_a)
        w = g["I_w"] / g["m_B"] - s_b  # m_B (s_b + w) = I_w
        return {"e": (s_b - v_a) / (u_a - u_b), "m_A": m_a, "u_B": s_b, "w_B": -w, "e_wall": w / s_b}

    return worked(g["s_B"]), worked(2.6)  # 2.9 copied as 2.6


NUMERIC_XJ: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xj01": _xj01,
    "xj02": _xj02,
    "xj04": _xj04,
    "xj05": _xj05,
    "xj06": _xj06,
    "xj08": _xj08,
    "xj09": _xj09,
    "xj10": _xj10,
    "xj11": _xj11,
    "xj13": _xj13,
    "xj14": _xj14,
    "xj15": _xj15,
}


# ---- letters: masses in units of m ----


def _xj03(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 3.0, 10 * u, e * 5 * u)
    return {"v_A2": a, "v_B2": b}, None


def _xj07(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    a, b = _solve(2.0, 1.0, 4 * u, (2 / 3) * 2 * u)
    sa, sb = _solve(2.0, 1.0, 4 * u, -(2 / 3) * 2 * u)  # v_A - v_B = 4u/3
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _xj12(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 2.0, 3 * u, e * 3 * u)
    mu = 2.0 / 3.0
    j = (1 + e) * mu * 3 * u
    assert b == pytest.approx(j / 2) and a == pytest.approx(3 * u - j)
    return {"v_A2": a, "v_B2": b}, None


SYMBOLIC_XJ: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xj03": _xj03,
    "xj07": _xj07,
    "xj12": _xj12,
}


def test_every_xj_case_is_worked_here() -> None:
    assert len(XJ_CASES) == 15
    assert {c.name[:4] for c in XJ_CASES} == set(NUMERIC_XJ) | set(SYMBOLIC_XJ)
    by_category = sorted(c.verdict.category for c in XJ_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in XJ_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in XJ_CASES}) == 15
    for case in XJ_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in XJ_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XJ))
def test_the_xj_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XJ[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XJ))
def test_the_xj_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        names = {"u": u, "e": e}
        true, slipped = SYMBOLIC_XJ[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
