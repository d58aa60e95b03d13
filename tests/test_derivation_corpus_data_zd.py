"""The zd batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zd cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, Newton's
law of restitution, impulse, kinetic energy, a fall and a rise under gravity), with the student's
slip made on purpose for the slip values. Answers in letters (u, e, v) are checked at a few points.
Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

ZD_CASES = [c for c in CASES if c.name.startswith("zd")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters


def _case(prefix: str):
    return next(c for c in ZD_CASES if c.name.startswith(prefix))


def _pair(values: tuple[float, float]) -> dict:
    return dict(zip(("v_A2", "v_B2"), values, strict=True))


# ---- numeric problems: prefix -> givens -> (true values, slip values or None) ----


def _zd04(g: dict) -> tuple[dict, None]:
    w = g["v_B1t"] / math.tan(math.radians(45))
    impulse = g["m_B"] * w  # B was at rest along the line
    v = (g["m_A"] * g["v_A1n"] - impulse) / g["m_A"]
    return {"e": (w - v) / g["v_A1n"], "v_B2n": w, "v_A2": abs(v)}, None


def _zd13(g: dict) -> tuple[dict, dict]:
    def worked(v_a: float, half: float) -> dict:
        v_b = (g["m_A"] * g["v_A1"] - g["m_A"] * v_a) / g["m_B"]
        t_1 = half * g["m_A"] * g["v_A1"] ** 2
        t_2 = 0.5 * g["m_A"] * v_a**2 + 0.5 * g["m_B"] * v_b**2
        return {"v_B2": v_b, "e": (v_b - v_a) / g["v_A1"], "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    return worked(g["v_A2"], 0.5), worked(3.0, 1.0)  # A's 2 copied as 3; KE before without the 1/2


def _zd14(g: dict) -> tuple[dict, None]:
    impulse = g["m_B"] * (g["s_B"] + g["v_B"])  # on B, in B's direction after
    w = g["I_w"] / g["m_B"] - g["s_B"]
    true = {
        "m_A": impulse / (g["v_A"] - g["s_A"]),
        "e": (g["s_B"] - g["s_A"]) / (g["v_A"] + g["v_B"]),
        "e_wall": w / g["s_B"],
    }
    return true, None


def _zd15(g: dict) -> tuple[dict, dict]:
    v_2 = math.sqrt(2 * g["g"] * g["h_0"])

    def after(v_1: float) -> dict:
        return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}

    fall = 2 * g["g"] * g["h_0"]
    return after(math.sqrt(g["v_0"] ** 2 + fall)), after(math.sqrt(g["v_0"] + fall))  # 21 for 21^2


NUMERIC_ZD: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zd04": _zd04,
    "zd13": _zd13,
    "zd14": _zd14,
    "zd15": _zd15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None) ----


def _zd01(u: float, _e: float) -> tuple[dict, None]:
    # 2mu = 2mx + my and m x^2 + m y^2 / 2 = 3 m u^2 / 4: 12x^2 - 16ux + 5u^2 = 0
    roots = [(16 * u + s * math.sqrt(256 * u * u - 240 * u * u)) / 24 for s in (1, -1)]
    x = next(r for r in roots if 2 * u - 2 * r >= r)  # Q not behind P
    y = 2 * u - 2 * x
    assert x * x + y * y / 2 == pytest.approx(0.75 * u * u)
    return {"v_A2": x, "v_B2": y, "e": (y - x) / u}, None


def _zd02(u: float, e: float) -> tuple[dict, None]:
    return _pair(_solve(1.0, 3.0, 4 * u, 4 * e * u)), None


def _zd03(u: float, e: float) -> tuple[dict, None]:
    return _pair(_solve(2.0, 1.0, 8 * u - 3 * u, e * 7 * u)), None


def _zd05(v: float, _e: float) -> tuple[dict, None]:
    e = 0.2
    approach = (1.5 * v + v) / e  # p + q
    p = (2 * -v + 3 * 1.5 * v + 3 * approach) / 5  # 2p - 3q = momentum after, q = approach - p
    return {"v_A1": p, "v_B1": -(approach - p)}, None  # B's velocity before is toward P


def _zd06(u: float, e: float) -> tuple[dict, dict]:
    true = _pair(_solve(1.0, 2.0, 3 * u, 3 * e * u))
    assert true["v_B2"] == pytest.approx(u + u * e)
    return true, {"v_A2": u - u * e - 3 * u * e}  # x = y - 3ue with y's +ue taken as -ue


def _zd07(u: float, e: float) -> tuple[dict, dict]:
    return _pair(_solve(5.0, 2.0, 5 * u - 4 * u, 3 * e * u)), _pair(_solve(5.0, 2.0, 5 * u + 4 * u, 3 * e * u))


def _zd08(u: float, e: float) -> tuple[dict, dict]:
    true = _pair(_solve(2.0, 1.0, 4 * u - u, 3 * e * u))
    return true, _pair(_solve(1.0, 2.0, 4 * u - u, 3 * e * u))  # the masses exchanged after


def _zd09(u: float, e: float) -> tuple[dict, dict]:
    v_a, v_b = _solve(3.0, 6.0, 3 * u, e * u)
    t_1 = 0.5 * 3 * u * u
    true = {"v_A2": v_a, "v_B2": v_b, "T_lost": t_1 - 0.5 * 3 * v_a**2 - 0.5 * 6 * v_b**2}
    # mu^2/6 [(1 - 2e)^2 + 2(1 + e)^2] with 2(1 + e)^2 expanded as 2 + 2e + 2e^2
    t_2 = u * u / 6 * ((1 - 2 * e) ** 2 + 2 + 2 * e + 2 * e * e)
    return true, {"T_2": t_2, "T_lost": t_1 - t_2}


def _zd10(u: float, _e: float) -> tuple[dict, dict]:
    e = 2 / 3
    return _pair(_solve(2.0, 1.0, 4 * u, e * 2 * u)), _pair(_solve(2.0, 1.0, 4 * u, -e * 2 * u))


def _zd11(u: float, _e: float) -> tuple[dict, dict]:
    def worked(e: float) -> dict:
        return {"e": e} | _pair(_solve(1.0, 9.0, u, e * u))

    true = worked(math.sqrt(40 / 90))  # (1 - 9e)^2 + 9(1 + e)^2 = 50
    assert 0.5 * true["v_A2"] ** 2 + 4.5 * true["v_B2"] ** 2 == pytest.approx(0.25 * u * u)
    return true, worked(math.sqrt(40 / 80))  # 81e^2 + 9e^2 added as 80e^2


def _zd12(u: float, e: float) -> tuple[dict, dict]:
    true = _pair(_solve(1.0, 2.0, u, e * u))
    _, b = _solve(2.0, 1.0, u, e * u)  # slip 1: the masses exchanged after
    assert b == pytest.approx((u + 2 * e * u) / 3)
    return true, {"v_B2": b, "v_A2": (u - 2 * e * u - 3 * e * u) / 3}  # slip 2: (u + 2eu - 3eu) with +2eu as -2eu


SYMBOLIC_ZD: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "zd01": _zd01,
    "zd02": _zd02,
    "zd03": _zd03,
    "zd05": _zd05,
    "zd06": _zd06,
    "zd07": _zd07,
    "zd08": _zd08,
    "zd09": _zd09,
    "zd10": _zd10,
    "zd11": _zd11,
    "zd12": _zd12,
}


def test_every_zd_case_is_worked_here() -> None:
    assert len(ZD_CASES) == 15
    assert {c.name[:4] for c in ZD_CASES} == set(NUMERIC_ZD) | set(SYMBOLIC_ZD)
    by_category = sorted(c.verdict.category for c in ZD_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZD_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZD))
def test_the_zd_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZD[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZD))
def test_the_zd_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_ZD[prefix](u, e)
        letters = {"v": u}  # zd05's letter v (P's speed after) takes the place of u
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(slipped[name], rel=1e-9), name
