"""The xl batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xl cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's rebound, kinetic energy, a fall, a plastic
impact and a spring, a bounce and a rise), with the student's slip made on purpose for the slip
values. Answers in letters (u, e, alpha) are checked at a few points. Nothing here runs derive's
checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _bounce, _given, _solve, closed_form

XL_CASES = [c for c in CASES if c.name.startswith("xl")]
# (u, e, alpha) for the letters
POINTS = (
    {"u": 1.0, "e": 0.5, "alpha": 0.3},
    {"u": 2.0, "e": 0.3, "alpha": 0.7},
    {"u": 1.5, "e": 0.9, "alpha": 1.2},
)


def _case(prefix: str):
    return next(c for c in XL_CASES if c.name.startswith(prefix))


def _rad(degrees: float) -> float:
    return math.radians(degrees)


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _xl02(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b, v_a = g["m_A"], g["m_B"], g["v_A1"], g["v_B1"], g["v_A2"]
    rhs = m_a * u_a + m_b * u_b - m_a * v_a  # 0.4 v_B = 3.36
    v_b = rhs / m_b
    slipped = 8.6  # 3.36/0.4 worked as 8.6
    assert slipped != pytest.approx(v_b)
    return {"v_B2": v_b, "e": (v_b - v_a) / (u_a - u_b)}, {"v_B2": slipped, "e": (slipped - v_a) / (u_a - u_b)}


def _xl03(g: dict) -> tuple[dict, None]:
    v_bn = g["v_B1t"] / math.tan(_rad(45))
    v_an = (g["m_A"] * g["v_A1n"] + g["m_B"] * g["v_B1n"] - g["m_B"] * v_bn) / g["m_A"]
    e = -(v_bn - v_an) / (g["v_B1n"] - g["v_A1n"])
    return {"v_B2n": v_bn, "e": e, "v_A2": math.hypot(v_an, g["v_A1t"])}, None


def _xl05(g: dict) -> tuple[dict, None]:
    n, t = math.sin(_rad(g["theta_1"])), math.cos(_rad(g["theta_1"]))  # per unit v
    a, b = _solve(1.0, 1.0, n, g["e"] * n)
    assert b == pytest.approx(0.672, abs=5e-4)
    return {"theta_A2": math.degrees(math.atan2(a, t))}, None


def _xl06(g: dict) -> tuple[dict, dict]:
    m, u, e = g["m_A"], g["v_A1"], g["e"]
    v = e * u  # away from the wall; +n toward it
    true = {"v_A2": -v, "T_1": 0.5 * m * u * u, "T_2": 0.5 * m * v * v}
    true["T_lost"] = true["T_1"] - true["T_2"]
    t_1, t_2 = m * u * u, m * v * v  # the 1/2 left out, twice
    return true, {"T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _xl08(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u_a, u_b = g["m_A"], g["m_B"], g["v_A1"], g["v_B1"]

    def worked(v_a: float) -> dict:
        v_b = (m_a * u_a + m_b * u_b - m_a * v_a) / m_b
        return {"v_B2": v_b, "e": (v_b - v_a) / (u_a - u_b)}

    return worked(g["v_A2"]), worked(-g["v_A2"])  # A's velocity after taken as +0.2


def _xl09(g: dict) -> tuple[dict, dict]:
    a_n, a_t = g["v_A1"] * math.cos(_rad(25)), g["v_A1"] * math.sin(_rad(25))
    b_n, b_t = g["v_B1"] * math.cos(_rad(100)), g["v_B1"] * math.sin(_rad(100))
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, g["e"] * (a_n - b_n))
    true = {
        "v_A2n": a,
        "v_B2n": b,
        "v_A2": math.hypot(a, a_t),
        "psi_A2": g["phi_n"] + math.degrees(math.atan2(a_t, a)),
        "v_B2": math.hypot(b, b_t),
        "psi_B2": g["phi_n"] + math.degrees(math.atan2(b_t, b)),
    }
    copied = a_t + 5.0  # 33.81 copied as 38.81
    slipped = {
        "v_A2": math.hypot(a, copied),
        "psi_A2": g["phi_n"] + math.degrees(math.atan2(copied, a)),
        "v_B2": math.sqrt(b * b + b_t * b_t - 1000.0),  # 16618.6 added as 15618.6
    }
    return true, slipped


def _xl10(g: dict) -> tuple[dict, None]:
    b_n, b_t = g["v_B1"] * math.cos(_rad(60)), g["v_B1"] * math.sin(_rad(60))
    # b = e(a - b_n), m_A a + m_B b_n = m_B b
    a = (g["m_B"] * b_n + g["m_B"] * g["e"] * b_n) / (g["m_B"] * g["e"] - g["m_A"])
    b = g["e"] * (a - b_n)
    assert g["m_A"] * a + g["m_B"] * b_n == pytest.approx(g["m_B"] * b)
    return {"v_A1n": a, "v_B2": math.hypot(b, b_t), "delta_B": 60 - math.degrees(math.atan2(b_t, b))}, None


def _xl11(g: dict) -> tuple[dict, dict]:
    al = math.asin(0.8)

    def worked(along: float, across: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * along + g["m_B"] * g["v_B1n"], g["e"] * (along - g["v_B1n"]))
        return {
            "v_A2n": a,
            "v_B2n": b,
            "v_A2t": across,
            "v_A2": math.hypot(a, across),
            "dir_A_from_i": math.degrees(math.atan2(across, a)),
        }

    u = g["v_A1"]
    return worked(u * math.cos(al), u * math.sin(al)), worked(u * math.sin(al), u * math.cos(al))


def _xl12(g: dict) -> tuple[dict, dict]:
    c, s = math.cos(_rad(g["theta"])), math.sin(_rad(g["theta"]))
    a_n, a_t, b_n, b_t = g["v_A1"] * c, g["v_A1"] * s, -g["v_B1"] * c, -g["v_B1"] * s
    p = g["m_A"] * a_n + g["m_B"] * b_n

    def worked(gap: float, ta: float, tb: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], p, gap)
        return {"v_A2n": a, "v_B2n": b, "v_A2t": ta, "v_B2t": tb, "v_A2": math.hypot(a, ta), "v_B2": math.hypot(b, tb)}

    e = g["e"]
    true = worked(e * (a_n - b_n), a_t, b_t)
    assert e * (a_n - b_n) == pytest.approx(9.507, abs=1e-3)
    return true, worked(9.054, e * a_t, e * b_t)  # 9.505 worked as 9.054; e on the t components


def _xl14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    m, k = g["m_block"] + g["m_pan"], 1000 * g["k"]
    v = g["m_block"] * v_1 / m
    d_0 = g["m_pan"] * g["g"] / k
    assert k * d_0 == pytest.approx(g["m_pan"] * g["g"])  # the pan's weight cancels
    # k/2 x^2 - m_block g x - (1/2) m V^2 = 0
    a, b, c = k / 2, -g["m_block"] * g["g"], -0.5 * m * v * v
    x = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)
    assert 0.5 * m * v * v + m * g["g"] * x == pytest.approx(0.5 * k * ((d_0 + x) ** 2 - d_0**2))
    return {"v_1": v_1, "V": v, "x": x}, None


def _xl15(g: dict) -> tuple[dict, dict]:
    def worked(v_1_squared: float) -> dict:
        r = _bounce(g, math.sqrt(v_1_squared))
        assert r["E_lost"] == pytest.approx(0.5 * g["m"] * v_1_squared * (1 - g["e_floor"] ** 2))
        return {k: r[k] for k in ("v_1", "v_2", "h_2", "J", "E_lost")}

    squared = g["v_0"] ** 2 + 2 * g["g"] * g["h_0"]
    return worked(squared), worked(squared - 3.0)  # 25 + 31.36 added as 53.36


NUMERIC_XL: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xl02": _xl02,
    "xl03": _xl03,
    "xl05": _xl05,
    "xl06": _xl06,
    "xl08": _xl08,
    "xl09": _xl09,
    "xl10": _xl10,
    "xl11": _xl11,
    "xl12": _xl12,
    "xl14": _xl14,
    "xl15": _xl15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _xl01(p: dict) -> tuple[dict, None]:
    u = p["u"]
    mu = 2.0 / 3.0  # reduced mass of 2m and m
    e = math.sqrt(1 - 0.25 / (0.5 * mu))  # (1/2) mu (1 - e^2) u^2 = (1/4) u^2
    a, b = _solve(2.0, 1.0, 2 * u, e * u)
    assert 0.5 * 2 * a * a + 0.5 * b * b == pytest.approx(0.75 * u * u)
    return {"e": e, "v_A2": a, "v_B2": b}, None


def _xl04(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 1.0, 4 * u - u, 3 * e * u)
    sa, sb = _solve(2.0, 1.0, 4 * u - u, -3 * e * u)  # v_P - v_Q = 3eu
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _xl07(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 2.0, 3 * u, 3 * e * u)
    sa, sb = _solve(2.0, 1.0, 2 * 3 * u, 3 * e * u)  # the masses exchanged
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _xl13(p: dict) -> tuple[dict, None]:
    u, c, s = p["u"], math.cos(p["alpha"]), math.sin(p["alpha"])
    e = 0.5
    v_x = (2 * u * c - u * c) / 3  # the centre of mass along the line of centres
    a, b = v_x - e * (u * c - v_x), v_x - e * (-u * c - v_x)
    assert (a, b) == pytest.approx(_solve(2.0, 1.0, u * c, e * 2 * u * c), abs=1e-12)
    return {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, -u * s)}, None


SYMBOLIC_XL: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xl01": _xl01,
    "xl04": _xl04,
    "xl07": _xl07,
    "xl13": _xl13,
}


def test_every_xl_case_is_worked_here() -> None:
    assert len(XL_CASES) == 15
    assert {c.name[:4] for c in XL_CASES} == set(NUMERIC_XL) | set(SYMBOLIC_XL)
    by_category = sorted(c.verdict.category for c in XL_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in XL_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in XL_CASES}) == 15
    for case in XL_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in XL_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XL))
def test_the_xl_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XL[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XL))
def test_the_xl_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for names in POINTS:
        true, slipped = SYMBOLIC_XL[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
