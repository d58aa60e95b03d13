"""The yh batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the yh cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a cushion, kinetic energy, a swing up), with the
student's slip made on purpose for the slip values. Answers in letters (u, e, e_1, alpha) are
checked at a few points against the numbers worked there. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, closed_form

YH_CASES = [c for c in CASES if c.name.startswith("yh")]
# (u, e, alpha in radians): acute alpha, 0 <= e < 1
POINTS = ((1.0, 0.5, 0.4), (2.0, 0.3, 1.0), (1.5, 0.9, 0.7))


def _case(prefix: str):
    return next(c for c in YH_CASES if c.name.startswith(prefix))


# ---- numeric problems ----


def _yh01(g: dict) -> tuple[dict, None]:
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1"], g["e"] * g["v_A1"])
    return {"v_A2": a, "v_B2": b}, None


def _yh03(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    v = (p - g["m_A"] * g["v_A2"]) / g["m_B"]
    approach = g["v_A1"] - g["v_B1"]
    return {"v_B2": v, "e": (v - g["v_A2"]) / approach}, {"e": (v - abs(g["v_A2"])) / approach}


def _yh05(g: dict) -> tuple[dict, None]:
    mass = g["m_A"] + g["m_B"]
    v = g["m_A"] * g["v_A1"] / mass
    t_1, t_2 = 0.5 * g["m_A"] * g["v_A1"] ** 2, 0.5 * mass * v * v
    return {"v_B2": v, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _yh06(g: dict) -> tuple[dict, dict]:
    m_a, m_b = g["m_A"] * 1000, g["m_B"] * 1000  # Mg to kg: the ratio is what counts

    def worked(sign: float) -> dict:
        v_a = sign * (m_a * g["v_A1"] - m_b * g["v_B2"]) / m_a  # the slip drops the minus
        return {"v_A2": v_a, "e": (g["v_B2"] - v_a) / g["v_A1"]}

    return worked(1.0), worked(-1.0)


def _yh09(g: dict) -> tuple[dict, dict]:
    true = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"], g["e"] * (g["v_A1"] - g["v_B1"]))
    # B's momentum taken positive; separation = approach / e
    slip = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B1"], (g["v_A1"] - g["v_B1"]) / g["e"])
    return {"v_A2": true[0], "v_B2": true[1]}, {"v_A2": slip[0], "v_B2": slip[1]}


def _yh11(g: dict) -> tuple[dict, dict]:
    v = (g["m_A"] * g["v_A1"] - g["m_A"] * g["v_A2"]) / g["m_B"]
    sv = (g["m_B"] * g["v_A1"] - g["m_B"] * g["v_A2"]) / g["m_A"]  # masses swapped
    return {"v_B2": v, "e": (v - g["v_A2"]) / g["v_A1"]}, {"v_B2": sv, "e": (g["v_A2"] - sv) / g["v_A1"]}


def _yh14(g: dict) -> tuple[dict, dict]:
    p, mass = g["m_bullet"] * g["v_0"], g["m_bullet"] + g["m_block"]

    def worked(v: float) -> dict:
        return {"V": v, "T_after": 0.5 * mass * v * v, "h_2": v * v / (2 * g["g"])}

    return worked(p / mass), worked(p / g["m_block"])  # the bullet's mass left out after


def _yh15(g: dict) -> tuple[dict, None]:
    u_a, u_b, s_a, s_b = g["v_A"], -g["v_B"], g["s_A"], g["s_B"]
    e = (s_b - s_a) / (u_a - u_b)
    m_a = g["m_B"] * (s_b - u_b) / (u_a - s_a)
    e_w = g["I_w"] / (g["m_B"] * s_b) - 1
    return {"e": e, "m_A": m_a, "u_B": s_b, "w_B": -e_w * s_b, "e_wall": e_w}, None


NUMERIC_YH: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yh01": _yh01,
    "yh03": _yh03,
    "yh05": _yh05,
    "yh06": _yh06,
    "yh09": _yh09,
    "yh11": _yh11,
    "yh14": _yh14,
    "yh15": _yh15,
}


# ---- letters: masses in units of m ----


def _yh02(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 7.0, 12 * u, e * 4 * u)
    sa, sb = _solve(1.0, 7.0, 12 * u, -e * 4 * u)  # v_1' - v_2' = 4eu
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _yh04(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    a, b = _solve(4.0, 5.0, 4 * u, 0.5 * u)
    sa, sb = _solve(4.0, 5.0, 4 * u, -0.5 * u)  # v1' = v2' + u/2
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _yh07(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    along = u * math.cos(math.radians(60))
    return {"v_B2": _solve(1.0, 1.0, along, e * along)[1]}, None


def _yh08(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    true = _solve(1.0, 1.0, u * math.cos(math.radians(30)), e * u * math.cos(math.radians(30)))[0]
    slip = _solve(1.0, 1.0, u * math.sin(math.radians(30)), e * u * math.sin(math.radians(30)))[0]
    return {"v_A2n": true}, {"v_A2n": slip}


def _yh10(p: dict) -> tuple[dict, None]:
    e, alpha = p["e"], p["alpha"]
    along, normal = math.cos(alpha), e * math.sin(alpha)  # U = 1
    return {"beta": math.atan2(normal, along)}, None


def _yh12(p: dict) -> tuple[dict, dict]:
    u, e, alpha = p["u"], p["e"], p["alpha"]
    a, b = _solve(1.0, 1.0, u * math.cos(alpha), e * u * math.cos(alpha))
    t = u * math.sin(alpha)
    return {"beta_A2": math.atan2(t, a)}, {"beta_A2": math.atan2(t, b)}  # P's component used


def _yh13(p: dict) -> tuple[dict, None]:
    u = p["u"]
    a, b = _solve(2.0, 1.0, 4 * u, (2 / 3) * 2 * u)
    return {"v_A2": a, "v_B2": b}, None


SYMBOLIC_YH: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yh02": _yh02,
    "yh04": _yh04,
    "yh07": _yh07,
    "yh08": _yh08,
    "yh10": _yh10,
    "yh12": _yh12,
    "yh13": _yh13,
}


def test_every_yh_case_is_worked_here() -> None:
    assert len(YH_CASES) == 15
    assert {c.name[:4] for c in YH_CASES} == set(NUMERIC_YH) | set(SYMBOLIC_YH)
    by_category = sorted(c.verdict.category for c in YH_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in YH_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in YH_CASES}) == 15
    for case in YH_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in YH_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YH))
def test_the_yh_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YH[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YH))
def test_the_yh_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha in POINTS:
        names = {"u": u, "U": u, "e": e, "e_1": e, "alpha": alpha}
        true, slipped = SYMBOLIC_YH[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
