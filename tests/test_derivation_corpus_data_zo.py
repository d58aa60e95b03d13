"""The zo batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zo cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, impulse, a wall's impulse, kinetic energy, a fall and
a rise), with the student's slip made on purpose for the slip values. Answers in letters (u, e) are
checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _bounce, _given, _solve, closed_form

ZO_CASES = [c for c in CASES if c.name.startswith("zo")]
POINTS = ({"u": 1.0, "e": 0.5}, {"u": 2.0, "e": 0.3}, {"u": 1.5, "e": 0.9})


def _case(prefix: str):
    return next(c for c in ZO_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _zo01(g: dict) -> tuple[dict, dict]:
    n = g["phi_n"]
    c, s = (lambda d: math.cos(math.radians(d))), (lambda d: math.sin(math.radians(d)))
    a_n, a_t = g["v_A1"] * c(45 - n), g["v_A1"] * s(45 - n)
    b_n, b_t = g["v_B1"] * c(120 - n), g["v_B1"] * s(120 - n)
    assert b_n < 0  # B at 100 deg from n moves back toward A

    def worked(bn: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * bn, g["e"] * (a_n - bn))
        return {
            "v_A2n": a,
            "v_B2n": b,
            "v_A2": math.hypot(a, a_t),
            "v_B2": math.hypot(b, b_t),
            "psi_A2": n + math.degrees(math.atan2(a_t, a)),
            "psi_B2": n + math.degrees(math.atan2(b_t, b)),
        }

    return worked(b_n), worked(-b_n)  # B's n component taken as +110 cos 80


def _zo03(g: dict) -> tuple[dict, dict]:
    u_a, u_b = g["v_A1"], g["v_B1"]
    t_1 = 0.5 * g["m_A"] * u_a**2 + 0.5 * g["m_B"] * u_b**2

    def worked(e: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * u_a + g["m_B"] * u_b, e * (u_a - u_b))
        t_2 = 0.5 * g["m_A"] * a * a + 0.5 * g["m_B"] * b * b
        return {"v_A2": a, "v_B2": b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    return worked(g["e"]), worked(0.6)  # e = 0.8 copied as 0.6


def _zo04(g: dict) -> tuple[dict, None]:
    m_a, m_b = g["W_A"] / 32.2, g["W_B"] / 32.2
    a, b = _solve(m_a, m_b, m_a * g["v_A1"], g["e"] * g["v_A1"])
    # the student's slugs to 4 s.f. carried: 9.433 and 15.33, within a unit or two of the 4th figure
    sa, sb = _solve(0.4658, 0.3106, 0.4658 * g["v_A1"], g["e"] * g["v_A1"])
    assert sa == pytest.approx(a, rel=5e-4) and sb == pytest.approx(b, rel=5e-4)
    return {"v_A2": a, "v_B2": b}, None


def _zo06(g: dict) -> tuple[dict, None]:
    b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_A"] * g["v_A2"]) / g["m_B"]
    e = -(b - g["v_A2"]) / (g["v_B1"] - g["v_A1"])
    k_i = 0.5 * g["m_A"] * g["v_A1"] ** 2 + 0.5 * g["m_B"] * g["v_B1"] ** 2
    k_f = 0.5 * g["m_A"] * g["v_A2"] ** 2 + 0.5 * g["m_B"] * b * b
    assert k_i == pytest.approx(13.0) and k_f == pytest.approx(12.6125)
    return {"v_A2": g["v_A2"], "v_B2": b, "e": e, "T_lost": k_i - k_f}, None


def _zo08(g: dict) -> tuple[dict, None]:
    v = (g["m_A"] * g["v_A1"] - g["m_A"] * g["v_A2"]) / g["m_B"]
    return {"v_B2": v, "e": (v - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _zo09(g: dict) -> tuple[dict, dict]:
    total = g["m_A"] + g["m_B"]
    v = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]) / total
    sv = (g["m_B"] * g["v_A1"] + g["m_A"] * g["v_B1"]) / total  # the masses exchanged
    return {"v_A2": v, "v_B2": v}, {"v_A2": sv, "v_B2": sv}


def _zo10(g: dict) -> tuple[dict, dict]:
    a_n, a_t = g["v_A1"] * math.cos(math.radians(60)), g["v_A1"] * math.sin(math.radians(60))
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * g["v_B1n"], g["e"] * (a_n - g["v_B1n"]))

    def worked(across: float) -> dict:
        return {
            "v_A2n": a,
            "v_B2n": b,
            "v_A2t": across,
            "v_A2": math.hypot(a, across),
            "angle_loc": math.degrees(math.atan2(across, abs(a))),
        }

    return worked(a_t), worked(g["e"] * a_t)  # e applied across the line of centres


def _zo11(g: dict) -> tuple[dict, None]:
    impulse_on_a = g["m_A"] * (g["v_A2"] - g["v_A1"])
    v = g["v_B1"] - impulse_on_a / g["m_B"]  # equal and opposite impulse on B
    return {"v_B2": v, "e": (v - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _zo13(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    v = (p - g["m_A"] * g["v_A2"]) / g["m_B"]
    sv = (p - 10 * g["m_A"] * g["v_A2"]) / g["m_B"]  # 0.5(0.2) worked as 1
    se = (sv - g["v_A2"]) / (g["v_A1"] + g["v_B1"])  # approach 6 + 2
    return {"v_B2": v, "e": (v - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, {"v_B2": sv, "e": se}


def _zo14(g: dict) -> tuple[dict, dict]:
    u_a, u_b, v_a, v_b = g["v_A"], -g["v_B"], g["s_A"], g["s_B"]
    m_a = g["m_B"] * (v_b - u_b) / (u_a - v_a)
    e = (v_b - v_a) / (u_a - u_b)

    def wall(impulse: float) -> dict:
        w = (g["m_B"] * v_b - impulse) / g["m_B"]  # toward the wall positive, the wall pushes back
        return {"w_B": w, "e_wall": -w / v_b}

    return {"e": e, "m_A": m_a} | wall(g["I_w"]), wall(0.86)  # 0.68 copied as 0.86


def _zo15(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h_0"])
    v_2 = math.sqrt(2 * g["g"] * g["h_r"])
    e = math.sqrt(g["h_r"] / g["h_0"])
    assert e == pytest.approx(v_2 / v_1)
    j = g["m"] * v_2 - g["m"] * (-v_1)  # +y up
    assert _bounce(g | {"e_floor": e}, v_1)["J"] == pytest.approx(j)
    return {"v_1": v_1, "v_2": v_2, "e_floor": e, "J": j}, None


NUMERIC_ZO: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zo01": _zo01,
    "zo03": _zo03,
    "zo04": _zo04,
    "zo06": _zo06,
    "zo08": _zo08,
    "zo09": _zo09,
    "zo10": _zo10,
    "zo11": _zo11,
    "zo13": _zo13,
    "zo14": _zo14,
    "zo15": _zo15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _zo02(p: dict) -> tuple[dict, None]:
    u, e = p["u"], 2 / 3  # e = 2/3 is given
    m1, m2, v1 = 2.0, 1.0, 2 * u
    a, b = (m1 - e * m2) * v1 / (m1 + m2), (1 + e) * m1 * v1 / (m1 + m2)
    s, t = _solve(m1, m2, m1 * v1, e * v1)
    assert (a, b) == pytest.approx((s, t))
    return {"v_A2": a, "v_B2": b}, None


def _zo05(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], 1 / 3  # e = 1/3 is given
    a, b = _solve(2.0, 1.0, 2 * u, e * u)
    sa, sb = _solve(2.0, 1.0, 2 * u, -e * u)  # x - y = u/3
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _zo07(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 3.0, 10 * u, 5 * e * u)
    sb = (10 * u + 5 * e * u) / 5  # 2(y - 5eu) taken as 2y - 5eu
    assert sb - 5 * e * u == pytest.approx(2 * u - 4 * e * u)
    return {"v_A2": a, "v_B2": b}, {"v_B2": sb, "v_A2": sb - 5 * e * u - 2 * e * u}  # -4eu written -6eu


def _zo12(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 2.0, u, e * u)
    speed = (2 * e * u - u) / 2  # u = -v + 2eu - v
    return {"v_A2": a, "v_B2": b}, {"v_A2": -speed, "v_B2": e * u - speed}


SYMBOLIC_ZO: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zo02": _zo02,
    "zo05": _zo05,
    "zo07": _zo07,
    "zo12": _zo12,
}


def test_every_zo_case_is_worked_here() -> None:
    assert len(ZO_CASES) == 15
    assert {c.name[:4] for c in ZO_CASES} == set(NUMERIC_ZO) | set(SYMBOLIC_ZO)
    by_category = sorted(c.verdict.category for c in ZO_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZO_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in ZO_CASES}) == 15
    for case in ZO_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in ZO_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZO))
def test_the_zo_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZO[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZO))
def test_the_zo_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for names in POINTS:
        true, slipped = SYMBOLIC_ZO[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
