"""The zc batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zc cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, Newton's
law of restitution, impulse, components at a wall, a fall, a slide and a spring's energy), with
the student's slip made on purpose for the slip values. Letters (u, e, v) are checked at a few
points, with m = 1. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

ZC_CASES = [c for c in CASES if c.name.startswith("zc")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters


def _case(prefix: str):
    return next(c for c in ZC_CASES if c.name.startswith(prefix))


def _pair(values: tuple[float, float]) -> dict:
    return dict(zip(("v_A2", "v_B2"), values, strict=True))


# ---- numeric problems: prefix -> givens -> (true values, slip values or None) ----


def _zc03(g: dict) -> tuple[dict, None]:
    impulse_on_a = g["m_A"] * (g["v_A2"] - g["v_A1"])
    v_b = g["v_B1"] - impulse_on_a / g["m_B"]
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _zc05(g: dict) -> tuple[dict, None]:
    along = math.sin(math.radians(g["theta_1"]))  # per unit speed: the component on the line of centres
    across = math.cos(math.radians(g["theta_1"]))
    a_n, b_n = _solve(1.0, 1.0, along, g["e"] * along)
    return {
        "theta_A2": math.degrees(math.atan2(a_n, across)),
        "v_A2n_per_v_A1": a_n,
        "v_B2_per_v_A1": b_n,
    }, None


def _zc08(g: dict) -> tuple[dict, dict]:
    e, kept = g["e"], 3 / 5
    sin2 = (1 - kept) / (1 - e**2)  # cos^2 + e^2 sin^2 = 3/5
    true = math.degrees(math.asin(math.sqrt(sin2)))
    slipped = math.degrees(math.acos(math.sqrt(sin2)))  # sin^2 + e^2 cos^2 = 3/5
    return {"alpha": true}, {"alpha": slipped}


def _zc09(g: dict) -> tuple[dict, dict]:
    m, u = g["m_A"], g["v_A1"]
    v = -g["e"] * u
    true = {"v_A2": v, "J_n": m * (u - v), "T_lost": 0.5 * m * (u**2 - v**2)}
    return true, {"T_lost": 0.5 * m * (u - abs(v)) ** 2}  # 1/2 m (u - v)^2 with speeds


def _zc10(g: dict) -> tuple[dict, dict]:
    w_a, w_b = g["W_A"], g["W_B"]  # g cancels
    v = (w_a * g["v_A1"] + w_b * g["v_B1"]) / (w_a + w_b)
    slipped = (w_a * g["v_A1"] - w_b * g["v_B1"]) / (w_a + w_b)  # B's -6 taken as +6
    return {"v_A2": v, "v_B2": v}, {"v_A2": slipped, "v_B2": slipped}


def _zc11(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u = g["m_A"], g["m_B"], g["v_A1"]
    true = _pair(_solve(m_a, m_b, m_a * u, u))
    v_1 = (-m_a * u - m_b * u) / (m_a + m_b)  # 70.15 v_1 = -(5.25 + 2450)
    assert true["v_A2"] == pytest.approx((m_a * u - m_b * u) / (m_a + m_b))
    return true, {"v_A2": v_1, "v_B2": v_1 + u}


def _zc12(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u = g["m_A"], g["m_B"], g["v_A1"]
    true = _pair(_solve(m_a, m_b, m_a * u, u))
    assert true["v_B2"] == pytest.approx(2 * m_a / (m_a + m_b) * u)
    swapped = (m_b - m_a) / (m_a + m_b) * u
    digits = f"{true['v_B2']:.2f}"  # "3.14", its last two digits exchanged
    slipped_b = float(digits[:-2] + digits[-1] + digits[-2])
    return true, {"v_A2": swapped, "v_B2": slipped_b}


def _zc14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    u_a, u_b = _solve(g["W_A"], g["W_B"], g["W_A"] * v_1, g["e"] * v_1)
    d_b = u_b**2 / (2 * g["mu_k"] * g["g"])
    return {"v_1": v_1, "u_A": u_a, "u_B": u_b, "d_B": d_b}, None


def _zc15(g: dict) -> tuple[dict, dict]:
    m_1, m_2, k, grav = g["m_block"], g["m_pan"], g["k"] * 1000, g["g"]
    v_1 = math.sqrt(2 * grav * g["h"])
    d_0 = m_2 * grav / k

    def deflection(speed: float) -> float:
        # 1/2 M V^2 + M g x = 1/2 k ((d0 + x)^2 - d0^2): k/2 x^2 + (k d0 - M g) x - 1/2 M V^2 = 0
        a, b, c = k / 2, k * d_0 - (m_1 + m_2) * grav, -0.5 * (m_1 + m_2) * speed**2
        return (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)

    big_v = m_1 * v_1 / (m_1 + m_2)
    kept = v_1 * math.sqrt(m_1 / (m_1 + m_2))  # 1/2 m_1 v_1^2 = 1/2 (m_1 + m_2) V^2
    return {"v_1": v_1, "V": big_v, "x": deflection(big_v)}, {"V": kept, "x": deflection(kept)}


NUMERIC_ZC: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zc03": _zc03,
    "zc05": _zc05,
    "zc08": _zc08,
    "zc09": _zc09,
    "zc10": _zc10,
    "zc11": _zc11,
    "zc12": _zc12,
    "zc14": _zc14,
    "zc15": _zc15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None); m = 1 ----


def _zc01(u: float, e: float) -> tuple[dict, None]:
    return _pair(_solve(5.0, 2.0, 5 * u - 2 * 2 * u, e * 3 * u)), None


def _zc02(u: float, e: float) -> tuple[dict, None]:
    return _pair(_solve(2.0, 1.0, 2 * 2 * u - u, e * 3 * u)), None


def _zc04(v: float, _e: float) -> tuple[dict, None]:
    # speeds p, q before (toward each other): 2p - 3q = 2(-v) + 3(3v/2); 3v/2 + v = (p + q)/5
    rhs, total = -2 * v + 3 * 1.5 * v, 5 * (1.5 * v + v)
    q = (2 * total - rhs) / 5
    return {"v_A1": total - q, "v_B1": -q}, None


def _zc06(u: float, e: float) -> tuple[dict, dict]:
    true = _pair(_solve(1.0, 2.0, 3 * u, e * 3 * u))
    y = (3 * u - 3 * e * u) / 3  # -3eu kept on crossing
    return true, {"v_A2": y - 3 * e * u, "v_B2": y}


def _zc07(u: float, e: float) -> tuple[dict, dict]:
    a, b = _solve(3.0, 6.0, 3 * u, e * u)
    t_1, t_2 = 1.5 * u**2, 1.5 * a**2 + 3 * b**2
    slipped_t2 = u**2 / 6 * ((1 - 4 * e + 2 * e**2) + 2 * (1 + e) ** 2)  # (1 - 2e)^2 as 1 - 4e + 2e^2
    return {"v_A2": a, "v_B2": b, "T_lost": t_1 - t_2}, {"T_lost": t_1 - slipped_t2}


def _zc13(u: float, e: float) -> tuple[dict, dict]:
    true = _pair(_solve(2.0, 1.0, 2 * 4 * u - 3 * u, e * 7 * u))
    v_a = _solve(2.0, 1.0, 2 * 4 * u + 3 * u, e * 7 * u)[0]  # slip 1: B's momentum +3mu
    return true, {"v_A2": v_a, "v_B2": v_a + e * 7 * u / 3}  # slip 2: 7eu put over 3 as 7eu/3


SYMBOLIC_ZC: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "zc01": _zc01,
    "zc02": _zc02,
    "zc04": _zc04,
    "zc06": _zc06,
    "zc07": _zc07,
    "zc13": _zc13,
}


def test_every_zc_case_is_worked_here() -> None:
    assert len(ZC_CASES) == 15
    assert {c.name[:4] for c in ZC_CASES} == set(NUMERIC_ZC) | set(SYMBOLIC_ZC)
    by_category = sorted(c.verdict.category for c in ZC_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZC_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZC))
def test_the_zc_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZC[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZC))
def test_the_zc_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_ZC[prefix](u, e)
        letters = {"v": u}  # zc04's letter v, at the point u
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(slipped[name], rel=1e-9), name
