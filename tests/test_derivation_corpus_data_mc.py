"""The mc batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the mc cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, Newton's
law of restitution, kinetic energy, a fall, a spring's energy, a slide to rest), with the student's
slip made on purpose for the slip values. Answers in letters (u, e, m, v) are checked at a few
points (energies in units of m) by solving the two linear equations numerically there. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

MC_CASES = [c for c in CASES if c.name.startswith("mc")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters


def _case(prefix: str):
    return next(c for c in MC_CASES if c.name.startswith(prefix))


def _ke(m: float, *speeds: float) -> float:
    return sum(0.5 * m * s * s for s in speeds)


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _find_e(g: dict, *, reversed_e: bool = False, no_half: bool = False) -> dict:
    """A hits B at rest and carries on at v_A2: B's velocity, e and the energies."""
    v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_A"] * g["v_A2"]) / g["m_B"]
    sep, app = v_b - g["v_A2"], g["v_A1"] - g["v_B1"]
    t_1 = _ke(g["m_A"], g["v_A1"]) * (2 if no_half else 1) + _ke(g["m_B"], g["v_B1"])
    t_2 = _ke(g["m_A"], g["v_A2"]) + _ke(g["m_B"], v_b)
    return {"v_B2": v_b, "e": app / sep if reversed_e else sep / app, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _mc03(g: dict) -> tuple[dict, None]:
    return _find_e(g), None


def _mc09(g: dict) -> tuple[dict, dict]:
    true = _find_e(g)
    return true, {"e": (true["v_B2"] + g["v_A2"]) / (g["v_A1"] - g["v_B1"])}  # A's -0.2 taken as +0.2


def _mc11(g: dict) -> tuple[dict, dict]:
    b_n = g["v_B1"] * math.cos(math.radians(60))
    b_t = g["v_B1"] * math.sin(math.radians(60))
    # m_A U + m_B b_n = m_B w and w = e (U - b_n), A at rest after
    u = (g["m_B"] * b_n + g["m_B"] * g["e"] * b_n) / (g["m_B"] * g["e"] - g["m_A"])
    w = g["e"] * (u - b_n)
    beta = math.degrees(math.atan2(b_t, w))
    true = {"v_A1n": u, "v_B2": math.hypot(w, b_t), "beta_B2": beta, "delta_B": 60 - beta}
    wrong = math.degrees(math.atan2(w, b_t))  # the angle with the perpendicular to XY
    return true, {"beta_B2": wrong, "delta_B": wrong - 60}


def _mc12(g: dict) -> tuple[dict, dict]:
    slipped = _find_e(g, reversed_e=True, no_half=True)
    return _find_e(g), {"e": slipped["e"], "T_1": slipped["T_1"], "T_lost": slipped["T_lost"]}


def _mc14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    mass = g["m_block"] + g["m_pan"]
    big_v = g["m_block"] * v_1 / mass
    k = 20000.0  # "20 kN/m"
    d_0 = g["m_pan"] * g["g"] / k
    # 1/2 M V^2 + M g x = 1/2 k ((d_0 + x)^2 - d_0^2) -> k/2 x^2 + (k d_0 - M g) x - 1/2 M V^2 = 0
    a, b, c = k / 2, k * d_0 - mass * g["g"], -0.5 * mass * big_v**2
    x = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)
    return {"v_1": v_1, "V": big_v, "x": x}, None


def _mc15(g: dict) -> tuple[dict, dict]:
    def worked(v_1: float) -> dict:
        u_a, u_b = _solve(g["W_A"], g["W_B"], g["W_A"] * v_1, g["e"] * v_1)  # weights: g cancels
        return {"v_1": v_1, "u_A": u_a, "u_B": u_b, "d_B": u_b**2 / (2 * g["mu_k"] * g["g"])}

    true = worked(math.sqrt(2 * g["g"] * g["h"]))
    return true, worked(math.sqrt(g["g"] * g["h"]))  # v1^2 = g h, the 2 lost


NUMERIC_MC: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "mc03": _mc03,
    "mc09": _mc09,
    "mc11": _mc11,
    "mc12": _mc12,
    "mc14": _mc14,
    "mc15": _mc15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None), masses in units of m ----


def _mc01(u: float, e: float) -> tuple[dict, None]:
    a, b = _solve(2.0, 1.0, 2.0 * 2 * u - u, e * 3 * u)  # P 2m at 2u, Q m at -u
    return {"v_A2": a, "v_B2": b}, None


def _mc02(u: float, e: float) -> tuple[dict, None]:
    a, b = _solve(2.0, 1.0, 2.0 * 4 * u - 3 * u, e * 7 * u)  # A 2m at 4u, B m at -3u
    return {"v_A2": a, "v_B2": b}, None


def _mc04(v: float, e: float) -> tuple[dict, None]:
    # 2 u_A + 3 u_B = 2(-v) + 3(3v/2) and (3v/2 + v) = (1/5)(u_A - u_B), along P -> Q
    p, gap = -2 * v + 4.5 * v, -(1.5 * v + v) / 0.2  # u_B - u_A = -(approach)
    a, b = _solve(2.0, 3.0, p, gap)
    return {"v_A1": a, "v_B1": b}, None


def _mc05(u: float, e: float) -> tuple[dict, None]:
    along = u * math.cos(math.radians(30))
    a, b = _solve(1.0, 1.0, along, e * along)
    return {"v_B2": b, "v_A2n": a}, None


def _mc06(u: float, e: float) -> tuple[dict, dict]:
    a, b = _solve(5.0, 2.0, 5 * u - 4 * u, 3 * e * u)
    sa, sb = _solve(5.0, 2.0, 5 * u + 4 * u, 3 * e * u)  # B's momentum +4mu
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _mc07(u: float, e: float) -> tuple[dict, dict]:
    a, b = _solve(3.0, 6.0, 3 * u, e * u)  # energies in units of m
    t_1, t_2 = _ke(3.0, u), _ke(3.0, a) + _ke(6.0, b)
    bracket = (1 - 4 * e + 2 * e * e) + 2 * (1 + e) ** 2  # (1 - 2e)^2 with 2e^2
    return {"v_A2": a, "v_B2": b, "T_lost": t_1 - t_2}, {"T_lost": t_1 - u * u / 6 * bracket}


def _mc08(u: float, e: float) -> tuple[dict, dict]:
    a, b = _solve(1.0, 2.0, 3 * u, 3 * e * u)
    sa, sb = _solve(1.0, 2.0, 3 * u, -3 * e * u)  # v_P - v_Q = 3eu
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _mc10(u: float, e: float) -> tuple[dict, dict]:
    a, b = _solve(1.0, 3.0, 4 * u, 4 * e * u)
    sa, sb = _solve(3.0, 1.0, 4 * u, 4 * e * u)  # 4u = 3v + w
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _mc13(u: float, e: float) -> tuple[dict, dict]:
    a, b = _solve(2.0, 1.0, 4 * u - u, 3 * e * u)
    # slip 1: 5u = 2v1' + v2' -> 3v1' = 5u - 3eu; slip 2: v1' = 5u/3 - 3eu, v2' = v1' + 3eu
    sa = 5 * u / 3 - 3 * e * u
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sa + 3 * e * u}


SYMBOLIC_MC: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "mc01": _mc01,
    "mc02": _mc02,
    "mc04": _mc04,
    "mc05": _mc05,
    "mc06": _mc06,
    "mc07": _mc07,
    "mc08": _mc08,
    "mc10": _mc10,
    "mc13": _mc13,
}


def test_every_mc_case_is_worked_here() -> None:
    assert len(MC_CASES) == 15
    assert {c.name[:4] for c in MC_CASES} == set(NUMERIC_MC) | set(SYMBOLIC_MC)
    by_category = sorted(c.verdict.category for c in MC_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in MC_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    for case in MC_CASES:
        slipped = case.verdict.category in ("one_slip", "two_slips") or case.verdict.summary != "0 wrong"
        assert bool(case.verdict.slip_values) == slipped, case.name


@pytest.mark.parametrize("prefix", sorted(NUMERIC_MC))
def test_the_mc_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_MC[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_MC))
def test_the_mc_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_MC[prefix](u, e)
        letters = {"v": u}
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(slipped[name], rel=1e-9), name
