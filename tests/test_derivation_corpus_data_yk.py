"""The yk batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the yk cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a cushion, kinetic energy, a fall and a slide), with
the student's slip made on purpose for the slip values. Answers in letters (u, e, alpha) are
checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, closed_form

YK_CASES = [c for c in CASES if c.name.startswith("yk")]
POINTS = (
    {"u": 1.0, "e": 0.5, "alpha": 0.3},
    {"u": 2.0, "e": 0.3, "alpha": 0.7},
    {"u": 1.5, "e": 0.9, "alpha": 1.2},
)


def _case(prefix: str):
    return next(c for c in YK_CASES if c.name.startswith(prefix))


def _ke(m: float, v: float) -> float:
    return 0.5 * m * v * v


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _yk01(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u = g["m_A"], g["m_B"], g["v_A1"]
    a, b = _solve(m_a, m_b, m_a * u, g["e"] * u)
    # sub v_B = v_A + u: (m_a + m_b) v_A = m_a u - m_b u, with m_a u - m_b u worked as -(m_a u + m_b u)
    sa = -(m_a * u + m_b * u) / (m_a + m_b)
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sa + u}


def _yk02(g: dict) -> tuple[dict, None]:
    v = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]) / (g["m_A"] + g["m_B"])
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1"], g["e"] * g["v_A1"])
    assert a == pytest.approx(2 * v - g["v_A1"]) and b == pytest.approx(2 * v)
    return {"v_A2": a, "v_B2": b}, None


def _yk03(g: dict) -> tuple[dict, dict]:
    al = math.radians(g["alpha"])
    b_n, b_t = -g["u_B"] * math.cos(al), g["u_B"] * math.sin(al)
    v_bn = b_t * math.tan(al)
    v_an = g["v_A1n"] + b_n - v_bn  # equal masses
    sep = v_bn - v_an
    return (
        {"v_B2": math.hypot(v_bn, b_t), "v_A2n": v_an, "e": sep / (g["v_A1n"] - b_n)},
        {"e": sep / (g["v_A1n"] + g["u_B"])},  # B's speed for its component
    )


def _yk04(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    v_a = g["v_A2"]
    v_b = (p - g["m_A"] * v_a) / g["m_B"]
    before = _ke(g["m_A"], g["v_A1"]) + _ke(g["m_B"], g["v_B1"])
    after = _ke(g["m_A"], v_a) + _ke(g["m_B"], v_b)
    app, sep = g["v_A1"] - g["v_B1"], v_b - v_a
    return {"v_B2": v_b, "e": sep / app, "T_lost": before - after}, {"e": app / sep}


def _yk06(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b, e = 2.0, 3.0, g["v_A1"], g["v_B1"], g["e"]  # in units of m
    p, gap = m_a * u_a + m_b * u_b, e * (u_a - u_b)
    a, b = _solve(m_a, m_b, p, gap)
    t_1 = _ke(m_a, u_a) + _ke(m_b, u_b)
    t_2 = _ke(m_a, a) + _ke(m_b, b)
    sa, sb = _solve(m_b, m_a, p, gap)  # 3x + 2y: the masses on the wrong velocities
    st_2 = _ke(m_a, sa) + _ke(m_b, sb) - 1.0  # 1/2(3m)(1.84^2) = 5.0784m written 4.0784m
    assert _ke(m_b, sb) == pytest.approx(5.0784)
    return (
        {"v_A2": a, "v_B2": b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2},
        {"v_A2": sa, "v_B2": sb, "T_2": st_2, "T_lost": t_1 - st_2},
    )


def _yk07(g: dict) -> tuple[dict, None]:
    impulse = g["m_B"] * (g["v_B2"] - g["v_B1"])  # Mg m/s
    v_a = g["v_A1"] - impulse / g["m_A"]
    return {"v_A2": v_a, "v_B2": g["v_B2"], "e": (g["v_B2"] - v_a) / (g["v_A1"] - g["v_B1"])}, None


def _yk08(g: dict) -> tuple[dict, dict]:
    def worked(along: float, across: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * along + g["m_B"] * g["v_B1n"], g["e"] * (along - g["v_B1n"]))
        return {
            "v_A2n": a,
            "v_B2n": b,
            "v_A2t": across,
            "v_A2": math.hypot(a, across),
            "angle_loc": math.degrees(math.atan2(across, abs(a))),
        }

    c, s = math.cos(math.radians(60)), math.sin(math.radians(60))
    return worked(g["v_A1"] * c, g["v_A1"] * s), worked(g["v_A1"] * s, g["v_A1"] * c)  # sin for along


def _yk09(g: dict) -> tuple[dict, None]:
    n = g["phi_n"]
    a_n, a_t = g["v_A1"] * math.cos(math.radians(45 - n)), g["v_A1"] * math.sin(math.radians(45 - n))
    b_n, b_t = g["v_B1"] * math.cos(math.radians(120 - n)), g["v_B1"] * math.sin(math.radians(120 - n))
    mu = g["m_A"] * g["m_B"] / (g["m_A"] + g["m_B"])
    j = (1 + g["e"]) * mu * (a_n - b_n)
    a, b = a_n - j / g["m_A"], b_n + j / g["m_B"]
    beta_a, beta_b = math.degrees(math.atan2(a_t, a)), math.degrees(math.atan2(b_t, b))
    return {
        "v_A2n": a,
        "v_B2n": b,
        "v_A2": math.hypot(a, a_t),
        "v_B2": math.hypot(b, b_t),
        "beta_A2": beta_a,
        "beta_B2": beta_b,
        "psi_A2": beta_a + n,
        "psi_B2": beta_b + n,
    }, None


def _yk11(g: dict) -> tuple[dict, dict]:
    t_1, t_2 = _ke(g["m_A"], g["v_A1"]), _ke(g["m_A"], g["v_A2"])
    assert g["m_A"] * (g["v_A1"] - g["v_A2"]) / 0.0150 == pytest.approx(86.4)
    return (
        {"e": -g["v_A2"] / g["v_A1"], "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2},
        {"T_1": 2 * t_1, "T_2": 2 * t_2, "T_lost": 2 * (t_1 - t_2)},  # the 1/2 left out
    )


def _yk13(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    v_b = (p - g["m_A"] * g["v_A2"]) / g["m_B"]
    sv_b = (p - g["v_A2"]) / g["m_B"]  # 0.5(0.2) taken as 0.2
    return (
        {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])},
        {"v_B2": sv_b, "e": (sv_b - g["v_A2"]) / (8 - g["v_B1"])},  # 6 copied as 8
    )


def _yk14(g: dict) -> tuple[dict, None]:
    e = math.sqrt(4 * g["v_C"] / g["v_0"]) - 1  # v_0 (1 + e)^2 / 4 = v_C
    u_b = g["v_0"] * (1 + e) / 2
    assert u_b * (1 + e) / 2 == pytest.approx(g["v_C"])
    return {"e": e, "u_B": u_b}, None


def _yk15(g: dict) -> tuple[dict, dict]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    gap = g["e"] * v_1

    def worked(a: float) -> dict:
        b = a + gap
        return {"v_1": v_1, "u_A": a, "u_B": b, "d_B": b * b / (2 * g["mu_k"] * g["g"])}

    true = worked((g["W_A"] * v_1 - g["W_B"] * gap) / (g["W_A"] + g["W_B"]))
    slipped = worked((g["W_A"] * v_1 - gap) / (g["W_A"] + g["W_B"]))  # 10(u_A + gap) as 10u_A + gap
    return true, {k: slipped[k] for k in ("u_A", "u_B", "d_B")}


NUMERIC_YK: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yk01": _yk01,
    "yk02": _yk02,
    "yk03": _yk03,
    "yk04": _yk04,
    "yk06": _yk06,
    "yk07": _yk07,
    "yk08": _yk08,
    "yk09": _yk09,
    "yk11": _yk11,
    "yk13": _yk13,
    "yk14": _yk14,
    "yk15": _yk15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _yk05(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    v = u / 2  # the common velocity of equal masses
    a, b = v - e * (u - v), v - e * (0 - v)
    assert (a, b) == pytest.approx(_solve(1.0, 1.0, u, e * u))
    return {"v_A2": a, "v_B2": b}, None


def _yk10(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 4.0, 2 * 2 * u - 4 * u, e * (2 * u + u))
    sa, sb = _solve(2.0, 4.0, 0.0, e * (2 * u - u))  # B's sign lost in the approach
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _yk12(p: dict) -> tuple[dict, None]:
    u, al = p["u"], p["alpha"]
    c, s = u * math.cos(al), u * math.sin(al)
    v_cm = (2 * c - c) / 3
    a = v_cm - 0.5 * (c - v_cm)
    b = v_cm - 0.5 * (-c - v_cm)
    assert (a, b) == pytest.approx(_solve(2.0, 1.0, 2 * c - c, 0.5 * (c + c)))
    return {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, -s)}, None


SYMBOLIC_YK: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yk05": _yk05,
    "yk10": _yk10,
    "yk12": _yk12,
}


def test_every_yk_case_is_worked_here() -> None:
    assert len(YK_CASES) == 15
    assert {c.name[:4] for c in YK_CASES} == set(NUMERIC_YK) | set(SYMBOLIC_YK)
    by_category = sorted(c.verdict.category for c in YK_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in YK_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in YK_CASES}) == 15
    for case in YK_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in YK_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YK))
def test_the_yk_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YK[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YK))
def test_the_yk_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for names in POINTS:
        true, slipped = SYMBOLIC_YK[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
