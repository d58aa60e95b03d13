"""The yb batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the yb cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, Newton's
law of restitution, the reduced-mass energy loss, a wall's rebound, suvat for a fall and a rise),
with the student's slip made on purpose for the slip values. Letters (u, e) are checked at a few
points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve, _thrown_down

YB_CASES = [c for c in CASES if c.name.startswith("yb")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters


def _case(prefix: str):
    return next(c for c in YB_CASES if c.name.startswith(prefix))


def _pair(v_a: float, v_b: float) -> dict:
    return {"v_A2": v_a, "v_B2": v_b}


# ---- numeric problems: prefix -> givens -> (true values, slip values or None) ----


def _yb02(g: dict) -> tuple[dict, None]:
    impulse = g["m_A"] * (g["v_A1"] - g["v_A2"])  # on A; the same on B (N3L)
    v_b = g["v_B1"] + impulse / g["m_B"]
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _wall_angle(e: float, kept: float, from_wall: bool) -> float:
    """cos^2 a + e^2 sin^2 a = kept (a from the wall); the slip takes a from the normal."""
    sin2 = (1 - kept) / (1 - e * e)
    return math.degrees(math.asin(math.sqrt(sin2)) if from_wall else math.acos(math.sqrt(sin2)))


def _yb04(g: dict) -> tuple[dict, None]:
    alpha = _wall_angle(g["e"], 0.6, True)
    assert math.tan(math.radians(alpha)) ** 2 == pytest.approx(32 / 3)  # the student's tan^2
    return {"alpha": alpha}, None


def _yb10(g: dict) -> tuple[dict, dict]:
    return {"alpha": _wall_angle(g["e"], 0.6, True)}, {"alpha": _wall_angle(g["e"], 0.6, False)}


def _disc_stops(g: dict, along: float, across: float, w_written: float | None = None) -> dict:
    """A stopped: m_A u + m_B along = m_B w and w = e (u - along)."""
    u = g["m_B"] * along * (1 + g["e"]) / (g["m_B"] * g["e"] - g["m_A"])
    w = g["e"] * (u - along) if w_written is None else w_written
    beta = math.degrees(math.atan2(across, w))
    return {"v_A1n": u, "v_B2": math.hypot(w, across), "delta_B": 60.0 - beta}


def _yb05(g: dict) -> tuple[dict, None]:
    c, s = g["v_B1"] * math.cos(math.radians(60)), g["v_B1"] * math.sin(math.radians(60))
    return _disc_stops(g, c, s), None


def _yb13(g: dict) -> tuple[dict, dict]:
    c, s = g["v_B1"] * math.cos(math.radians(60)), g["v_B1"] * math.sin(math.radians(60))
    # slip 1: sin and cos swapped; slip 2: 0.8 x 13.86 written 11.9
    return _disc_stops(g, c, s), _disc_stops(g, s, c, w_written=11.9)


def _yb06(g: dict) -> tuple[dict, dict]:
    def with_product(a_after: float) -> dict:
        v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - a_after) / g["m_B"]
        return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}

    return with_product(g["m_A"] * g["v_A2"]), with_product(0.01)  # slip: 0.5 x 0.2 = 0.01


def _yb08(g: dict) -> tuple[dict, dict]:
    def after(along: float, across: float) -> dict:
        x, y = _solve(g["m_A"], g["m_B"], g["m_A"] * along + g["m_B"] * g["v_B1n"], g["e"] * (along - g["v_B1n"]))
        return {
            "v_A2n": x,
            "v_B2n": y,
            "v_A2": math.hypot(x, across),
            "angle_loc": math.degrees(math.atan2(across, -x)),
        }

    c, s = g["v_A1"] * math.cos(math.radians(60)), g["v_A1"] * math.sin(math.radians(60))
    return after(c, s), after(s, c)  # slip: sin and cos swapped


def _yb11(g: dict) -> tuple[dict, dict]:
    def wall(v_after: float) -> dict:
        before = 0.5 * g["m_A"] * g["v_A1"] ** 2
        return {
            "v_A2": v_after,
            "J_n": g["m_A"] * (g["v_A1"] - v_after),
            "T_1": before,
            "T_lost": before - 0.5 * g["m_A"] * v_after**2,
        }

    true, slipped = wall(-g["e"] * g["v_A1"]), wall(-g["v_A1"] / g["e"])  # slip: e = approach/separation
    del slipped["T_1"]
    return true, slipped


def _yb12(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    gap = g["e"] * (g["v_A1"] - g["v_B1"])
    x, y = _solve(g["m_A"], g["m_B"], p, gap)
    before = 0.5 * g["m_A"] * g["v_A1"] ** 2 + 0.5 * g["m_B"] * g["v_B1"] ** 2
    after = 0.5 * g["m_A"] * x**2 + 0.5 * g["m_B"] * y**2
    s_x, s_y = _solve(g["m_A"], g["m_B"], p, -gap)  # slip 1: x - y = 8
    # slip 2: 1/2 m (u - v)^2 for each sphere
    s_lost = 0.5 * g["m_A"] * (g["v_A1"] - s_x) ** 2 + 0.5 * g["m_B"] * (g["v_B1"] - s_y) ** 2
    return {"v_A2": x, "v_B2": y, "T_1": before, "T_lost": before - after}, {"v_A2": s_x, "v_B2": s_y, "T_lost": s_lost}


def _yb14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"])
    v_2 = math.sqrt(2 * g["g"] * g["h_0"])  # rises back to the start
    return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_2 + v_1)}, None


def _yb15(g: dict) -> tuple[dict, dict]:
    # the slip: 2as = 31.36 written 3.136, as if the drop were a tenth of its height
    return _thrown_down(g), _thrown_down({**g, "h_0": g["h_0"] / 10})


NUMERIC_YB: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yb02": _yb02,
    "yb04": _yb04,
    "yb05": _yb05,
    "yb06": _yb06,
    "yb08": _yb08,
    "yb10": _yb10,
    "yb11": _yb11,
    "yb12": _yb12,
    "yb13": _yb13,
    "yb14": _yb14,
    "yb15": _yb15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None) ----


def _yb01(u: float, e: float) -> tuple[dict, None]:
    v = (2 * 5 * u + 3 * 0) / 5  # the common velocity
    true = _pair(v - e * (5 * u - v), v + e * v)
    assert true == pytest.approx(_pair(*_solve(2.0, 3.0, 10 * u, 5 * e * u)))
    return true, None


def _yb03(u: float, _e: float) -> tuple[dict, None]:
    mu = 1 * 9 / 10  # reduced mass, in units of m
    e = math.sqrt(1 - (0.5 * 0.5 * u * u) / (0.5 * mu * u * u))  # half of 1/2 m u^2 lost
    return {"e": e, **_pair(*_solve(1.0, 9.0, u, e * u))}, None


def _yb07(u: float, _e: float) -> tuple[dict, dict]:
    e = 2 / 3
    true = _solve(2.0, 1.0, 4 * u, e * 2 * u)
    slipped = _solve(1.0, 2.0, 4 * u, e * 2 * u)  # 4u = v_A + 2 v_B
    return _pair(*true), _pair(*slipped)


def _yb09(u: float, e: float) -> tuple[dict, dict]:
    true = _solve(1.0, 2.0, 3 * u, 3 * e * u)
    s_x = (3 * u + 6 * e * u) / 3  # 3x = 3u + 6eu: the sign of 6eu kept
    return _pair(*true), _pair(s_x, s_x + 3 * e * u)


SYMBOLIC_YB: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "yb01": _yb01,
    "yb03": _yb03,
    "yb07": _yb07,
    "yb09": _yb09,
}


def test_every_yb_case_is_worked_here() -> None:
    assert len(YB_CASES) == 15
    assert {c.name[:4] for c in YB_CASES} == set(NUMERIC_YB) | set(SYMBOLIC_YB)
    by_category = sorted(c.verdict.category for c in YB_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in YB_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YB))
def test_the_yb_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YB[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YB))
def test_the_yb_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_YB[prefix](u, e)
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e) == pytest.approx(slipped[name], rel=1e-9), name
