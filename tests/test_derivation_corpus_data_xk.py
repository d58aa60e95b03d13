"""The xk batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xk cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, components at an angle, kinetic energy, a fall, a rise
and a slide), with the student's slip made on purpose for the slip values. Answers in letters
(u, e, v) are checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _bounce, _given, _solve, closed_form

XK_CASES = [c for c in CASES if c.name.startswith("xk")]
POINTS = ({"u": 1.0, "e": 0.5, "v": 1.0}, {"u": 2.0, "e": 0.3, "v": 0.7}, {"u": 1.5, "e": 0.9, "v": 2.5})


def _case(prefix: str):
    return next(c for c in XK_CASES if c.name.startswith(prefix))


def _deg(x: float) -> float:
    return math.radians(x)


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _xk02(g: dict) -> tuple[dict, dict]:
    def worked(along: float, across: float) -> dict:
        # m_A a + m_B along = m_B b (A stops), b = e (a - along)
        a = (g["m_B"] * along + g["e"] * g["m_B"] * along) / (g["e"] * g["m_B"] - g["m_A"])
        b = g["e"] * (a - along)
        assert g["m_A"] * a + g["m_B"] * along == pytest.approx(g["m_B"] * b)
        beta = math.degrees(math.atan2(across, b))
        return {
            "v_A1n": a,
            "v_B2n": b,
            "v_B2t": across,
            "v_B2": math.hypot(b, across),
            "beta_B2": beta,
            "delta_B": 60 - beta,
        }

    v = g["v_B1"]
    return worked(v * math.cos(_deg(60)), v * math.sin(_deg(60))), worked(
        v * math.sin(_deg(60)), v * math.cos(_deg(60))
    )


def _xk03(g: dict) -> tuple[dict, None]:
    n = g["phi_n"]
    a_n, a_t = g["v_A1"] * math.cos(_deg(45 - n)), g["v_A1"] * math.sin(_deg(45 - n))
    b_n, b_t = g["v_B1"] * math.cos(_deg(120 - n)), g["v_B1"] * math.sin(_deg(120 - n))
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, g["e"] * (a_n - b_n))
    return {
        "v_A2n": a,
        "v_B2n": b,
        "v_A2": math.hypot(a, a_t),
        "v_B2": math.hypot(b, b_t),
        "psi_A2": n + math.degrees(math.atan2(a_t, a)),
        "psi_B2": n + math.degrees(math.atan2(b_t, b)),
    }, None


def _xk07(g: dict) -> tuple[dict, None]:
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"], g["e"] * (g["v_A1"] - g["v_B1"]))
    return {"v_A2": a, "v_B2": b}, None


def _xk12(g: dict) -> tuple[dict, None]:
    v = g["m_A"] * g["v_A1"] / (g["m_A"] + g["m_B"])
    t_1 = 0.5 * g["m_A"] * g["v_A1"] ** 2
    t_2 = 0.5 * (g["m_A"] + g["m_B"]) * v * v
    return {"v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _xk14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    a, b = _solve(g["W_A"], g["W_B"], g["W_A"] * v_1, g["e"] * v_1)  # g cancels
    return {"v_1": v_1, "u_A": a, "u_B": b, "d_B": b * b / (2 * g["mu_k"] * g["g"])}, None


def _xk15(g: dict) -> tuple[dict, dict]:
    v_1 = math.sqrt(2 * g["g"] * g["h_0"])

    def worked(h_r: float) -> dict:
        v_2 = math.sqrt(2 * g["g"] * h_r)
        return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}

    true = worked(g["h_r"])
    assert _bounce(g | {"e_floor": true["e_floor"]}, v_1)["J"] == pytest.approx(true["J"])
    return true, worked(1.6)  # h_r = 1.4 copied as 1.6


NUMERIC_XK: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xk02": _xk02,
    "xk03": _xk03,
    "xk07": _xk07,
    "xk12": _xk12,
    "xk14": _xk14,
    "xk15": _xk15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _tan_diff(t: float, psi: float) -> float:
    return (t - math.tan(psi)) / (1 + t * math.tan(psi))


def _xk01(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 1.0, u * math.cos(_deg(60)), e * u * math.cos(_deg(60)))
    return {"v_B2": b, "v_A2n": a}, None


def _equal_30(p: dict, halve: float, across_e: bool) -> dict:
    u, e = p["u"], p["e"]
    along = u * math.cos(_deg(30))
    a, _b = _solve(1.0, 1.0, along, e * along)
    true_a = a
    a = a * halve  # the student's 2 not divided out: halve = 2
    t = u * math.sin(_deg(30)) * (e if across_e else 1.0)
    return {"v_A2n": a, "v_B2n": true_a + e * along, "v_A2t": t, "deflection": math.atan(_tan_diff(t / a, _deg(30)))}


def _xk05(p: dict) -> tuple[dict, dict]:
    return _equal_30(p, 1.0, False), _equal_30(p, 1.0, True)  # e on A's perpendicular component


def _xk06(p: dict) -> tuple[dict, dict]:
    return _equal_30(p, 1.0, False), _equal_30(p, 2.0, False)


def _xk04(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 2.0, u, e * u)
    sa, sb = _solve(1.0, 2.0, u, u / e)  # u = e(w - v)
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _xk08(p: dict) -> tuple[dict, None]:
    u = p["u"]
    # 2u = 2x + y and x^2 + y^2/2 = 3u^2/4: 12x^2 - 16ux + 5u^2 = 0
    roots = [(16 * u + s * math.sqrt(256 * u * u - 240 * u * u)) / 24 for s in (1, -1)]
    kept = [(x, 2 * u - 2 * x) for x in roots if 2 * u - 2 * x >= x]
    assert len(kept) == 1
    x, y = kept[0]
    return {"v_A2": x, "v_B2": y, "e": (y - x) / u}, None


def _xk09(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 1.0, u, e * u)
    sa = (u + e * u) / 2  # the sum taken as 2vA
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sa + e * u}


def _xk10(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    a, b = _solve(2.0, 1.0, 2 * 2 * u, 2 / 3 * 2 * u)
    sa, sb = _solve(1.0, 2.0, 2 * 2 * u, 2 / 3 * 2 * u)  # masses exchanged after
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _xk11(p: dict) -> tuple[dict, dict]:
    v = p["v"]

    def worked(momentum: float, e: float) -> dict:
        # 2a - 3b = momentum, a + b = (5v/2)/e; velocities before: a, -b
        s = 2.5 * v / e
        b = (2 * s - momentum) / 5
        return {"v_A1": s - b, "v_B1": -b}

    true = worked(-2 * v + 3 * 1.5 * v, 1 / 5)
    assert 2 * true["v_A1"] + 3 * true["v_B1"] == pytest.approx(2 * -v + 3 * 1.5 * v)
    return true, worked(3.5 * v, 1 / 4)


def _xk13(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 1.0, 2 * 4 * u - 3 * u, e * 7 * u)
    sa, sb = _solve(2.0, 1.0, 2 * 4 * u + 3 * u, e * 7 * u)  # B's momentum +3mu
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb + 14 * e * u / 3}  # -7e + 21e added as 28e


SYMBOLIC_XK: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xk01": _xk01,
    "xk04": _xk04,
    "xk05": _xk05,
    "xk06": _xk06,
    "xk08": _xk08,
    "xk09": _xk09,
    "xk10": _xk10,
    "xk11": _xk11,
    "xk13": _xk13,
}


def test_every_xk_case_is_worked_here() -> None:
    assert len(XK_CASES) == 15
    assert {c.name[:4] for c in XK_CASES} == set(NUMERIC_XK) | set(SYMBOLIC_XK)
    by_category = sorted(c.verdict.category for c in XK_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in XK_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in XK_CASES}) == 15
    for case in XK_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in XK_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XK))
def test_the_xk_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XK[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XK))
def test_the_xk_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for names in POINTS:
        true, slipped = SYMBOLIC_XK[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
