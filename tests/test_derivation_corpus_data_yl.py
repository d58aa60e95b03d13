"""The yl batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the yl cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a cushion's rebound, kinetic energy, a fall, a plastic
impact and a spring), with the student's slip made on purpose for the slip values. Answers in
letters (u, e, alpha) are checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, closed_form

YL_CASES = [c for c in CASES if c.name.startswith("yl")]
# (u, e, alpha) for the letters
POINTS = (
    {"u": 1.0, "e": 0.5, "alpha": 0.3},
    {"u": 2.0, "e": 0.3, "alpha": 0.7},
    {"u": 1.5, "e": 0.9, "alpha": 1.2},
)


def _case(prefix: str):
    return next(c for c in YL_CASES if c.name.startswith(prefix))


def _ke(*pairs: tuple[float, float]) -> float:
    return sum(0.5 * m * v * v for m, v in pairs)


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _yl02(g: dict) -> tuple[dict, dict]:
    u_a, u_b, e = g["v_A1"], g["v_B1"], g["e"]  # masses in units of m: 2, 3
    a, b = _solve(2.0, 3.0, 2 * u_a + 3 * u_b, e * (u_a - u_b))
    t_1, t_2 = _ke((2.0, u_a), (3.0, u_b)), _ke((2.0, a), (3.0, b))
    slipped_t_2 = 0.5 * 2.0 * abs(a) + 0.5 * 3.0 * b * b  # A's speed not squared
    true = {"v_A2": a, "v_B2": b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}
    return true, {"T_2": slipped_t_2, "T_lost": t_1 - slipped_t_2}


def _yl03(g: dict) -> tuple[dict, None]:
    m_1, m_2, v_1 = g["m_A"], g["m_B"], g["v_A1"]
    a, b = (m_1 - m_2) / (m_1 + m_2) * v_1, 2 * m_1 / (m_1 + m_2) * v_1
    assert (a, b) == pytest.approx(_solve(m_1, m_2, m_1 * v_1, v_1))  # e = 1, the goalie at rest
    return {"v_A2": a, "v_B2": b}, None


def _yl06(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    v = p / (g["m_A"] + g["m_B"])
    assert p == pytest.approx(31800)
    sv = (p + 1000) / (g["m_A"] + g["m_B"])  # 45000 - 13200 worked as 32800
    return {"v_A2": v, "v_B2": v}, {"v_A2": sv, "v_B2": sv}


def _yl08(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u = g["W_A"] / 32.2, g["W_B"] / 32.2, g["v_A1"]

    def worked(gap: float, t_1: float) -> dict:
        a, b = _solve(m_a, m_b, m_a * u, gap)
        t_2 = _ke((m_a, a), (m_b, b))
        return {"v_A2": a, "v_B2": b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    true = worked(g["e"] * u, _ke((m_a, u)))
    slipped = worked(g["e"] * 19.567, _ke((g["W_A"], u)))  # 19.657 copied as 19.567; then the weight as mass
    return true, slipped


def _yl10(g: dict) -> tuple[dict, dict]:
    c, s = math.cos(math.radians(g["theta"])), math.sin(math.radians(g["theta"]))
    a_n, a_t, b_n, b_t = g["v_A1"] * c, g["v_A1"] * s, -g["v_B1"] * c, -g["v_B1"] * s

    def worked(e: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, e * (a_n - b_n))
        return {"v_A2n": a, "v_B2n": b, "v_A2": math.hypot(a, a_t), "v_B2": math.hypot(b, b_t)}

    true = worked(g["e"]) | {"v_A2t": a_t, "v_B2t": b_t}
    return true, worked(0.8)  # e copied as 0.8


def _yl11(g: dict) -> tuple[dict, dict]:
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))

    def worked(along: float, across: float) -> dict:
        a, b = _solve(1.0, 1.0, along + g["v_B1n"], g["e"] * (along - g["v_B1n"]))
        return {"v_A2n": a, "v_B2n": b, "v_A2t": across, "v_A2": math.hypot(a, across), "v_B2": abs(b)}

    true, slipped = worked(g["v_A1"] * c, g["v_A1"] * s), worked(g["v_A1"] * s, g["v_A1"] * c)
    assert slipped["v_A2n"] == pytest.approx(true["v_A2n"])  # line 20 holds for the problem
    return true, slipped


def _yl12(g: dict) -> tuple[dict, dict]:
    v_bn = g["v_B1t"] / math.tan(math.radians(45))
    v_an = (g["m_A"] * g["v_A1n"] + g["m_B"] * g["v_B1n"] - g["m_B"] * v_bn) / g["m_A"]
    e = (v_bn - v_an) / (g["v_A1n"] - g["v_B1n"])
    s_an = (g["m_A"] * g["v_A1n"] - g["m_B"] * v_bn + 2.0) / g["m_A"]  # 12 - 10 worked as 4
    s_e = (g["v_A1n"] - g["v_B1n"]) / (v_bn - s_an)  # approach over separation
    return {"e": e, "v_B2n": v_bn, "v_A2": math.hypot(v_an, g["v_A1t"])}, {"v_A2": s_an, "e": s_e}


def _yl13(g: dict) -> tuple[dict, None]:
    m_a, m_b, u = g["m_A"], g["m_B"], g["v_A1"]
    v = m_a * u / (m_a + m_b)
    mu = m_a * m_b / (m_a + m_b)
    lost = 0.5 * mu * u * u
    t_1 = _ke((m_a, u))
    assert t_1 - lost == pytest.approx(_ke((m_a + m_b, v)))
    return {"v_B2": v, "T_1": t_1, "T_2": t_1 - lost, "T_lost": lost}, None


def _yl14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    big, k = g["m_block"] + g["m_pan"], 1000 * g["k"]
    v = g["m_block"] * v_1 / big
    d_0 = g["m_pan"] * g["g"] / k
    a, b, c = k / 2, k * d_0 - big * g["g"], -0.5 * big * v * v
    x = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)
    assert 0.5 * big * v * v + big * g["g"] * x == pytest.approx(0.5 * k * ((d_0 + x) ** 2 - d_0**2))
    return {"v_1": v_1, "V": v, "x": x}, None


def _yl15(g: dict) -> tuple[dict, dict]:
    v_0, v_c = g["v_0"], g["v_C"]
    e = math.sqrt(4 * v_c / v_0) - 1  # v_0 (1 + e)^2 / 4 = v_C
    se = math.sqrt(2 * v_c / v_0) - 1  # the 2 not divided out: v_0 (1 + e)^2 / 2 = v_C
    return {"u_B": v_0 * (1 + e) / 2, "e": e}, {"u_B": v_0 * (1 + se), "e": se}


NUMERIC_YL: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yl02": _yl02,
    "yl03": _yl03,
    "yl06": _yl06,
    "yl08": _yl08,
    "yl10": _yl10,
    "yl11": _yl11,
    "yl12": _yl12,
    "yl13": _yl13,
    "yl14": _yl14,
    "yl15": _yl15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _yl01(p: dict) -> tuple[dict, None]:
    u, e, al = p["u"], p["e"], p["alpha"]
    along, away = u * math.cos(al), e * u * math.sin(al)  # V cos(beta), V sin(beta)
    return {"beta": math.atan2(away, along)}, None


def _yl04(p: dict) -> tuple[dict, dict]:
    u, e, al = p["u"], p["e"], p["alpha"]
    along, across = u * math.cos(al), u * math.sin(al)
    x, y = _solve(1.0, 1.0, along, e * along)
    sx = along * (1 + e) / 2  # along - y with the sign of e kept
    true = {"v_A2n": x, "v_B2": y, "beta_A2": math.atan2(across, x)}
    return true, {"v_A2n": sx, "beta_A2": math.atan2(across, sx)}


def _yl05(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    x, y = _solve(5.0, 2.0, 5 * u - 4 * u, e * (u + 2 * u))
    return {"v_A2": x, "v_B2": y}, None


def _yl07(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    v_1 = (u * math.sqrt(3) / 2, u / 2)
    x, _ = _solve(1.0, 1.0, v_1[0], e * v_1[0])
    v_1_after = (x, u / 2)
    cross = v_1[0] * v_1_after[1] - v_1[1] * v_1_after[0]
    dot = v_1[0] * v_1_after[0] + v_1[1] * v_1_after[1]
    return {"v_A2n": x, "deflection": math.atan2(cross, dot)}, None


def _yl09(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 3.0, 4 * u, 4 * e * u)
    # 4mu = 3mx + mv (P's velocity -v taken +v), x + v = 4eu: 4u = 12eu - 2v
    sv = (12 * e * u - 4 * u) / 2
    return {"v_A2": a, "v_B2": b}, {"v_A2": -sv, "v_B2": 4 * e * u - sv}


SYMBOLIC_YL: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yl01": _yl01,
    "yl04": _yl04,
    "yl05": _yl05,
    "yl07": _yl07,
    "yl09": _yl09,
}


def test_every_yl_case_is_worked_here() -> None:
    batch_shape(YL_CASES, set(NUMERIC_YL) | set(SYMBOLIC_YL))
    one_slips = [s.name for c in YL_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YL))
def test_the_yl_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YL[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YL))
def test_the_yl_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for names in POINTS:
        true, slipped = SYMBOLIC_YL[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
