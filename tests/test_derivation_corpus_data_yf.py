"""The yf batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the yf cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, components at a wall or a cushion, an elastic impact
through kinetic energy, a zero dot product for a right angle), with the student's slip made on
purpose for the slip values. Answers in letters (u, v, e, alpha) are checked at a few points.
Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, letters_agree, numbers_agree

YF_CASES = [c for c in CASES if c.name.startswith("yf")]
# (u, v, e, alpha in radians) for the letters
POINTS = ((1.0, 1.0, 0.5, 0.4), (2.0, 0.7, 0.3, 0.9), (1.5, 2.5, 0.9, 1.2))


def _case(prefix: str):
    return next(c for c in YF_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _yf01(g: dict) -> tuple[dict, None]:
    # cos² + e² sin² = 3/5  ->  sin² = (1 - 3/5)/(1 - e²)
    s2 = (1 - 0.6) / (1 - g["e"] ** 2)
    return {"alpha": math.degrees(math.asin(math.sqrt(s2)))}, None


def _yf02(g: dict) -> tuple[dict, None]:
    cm = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]) / (g["m_A"] + g["m_B"])
    return {"v_A2": 2 * cm - g["v_A1"], "v_B2": 2 * cm - g["v_B1"]}, None


def _yf08(g: dict) -> tuple[dict, dict]:
    def worked(square_of_after: float) -> dict:
        p = g["m_A"] * (g["v_A1"] - g["v_A2"])  # m_2 v_2f
        k = g["m_A"] * (g["v_A1"] ** 2 - square_of_after)  # m_2 v_2f^2
        v = k / p
        return {"v_B2": v, "m_B": p / v}

    return worked(g["v_A2"] ** 2), worked(0.0250)  # 0.050² taken as 0.0250


def _yf09(g: dict) -> tuple[dict, dict]:
    v = -g["e"] * g["v_A1"]
    true = {"v_A2": v, "J_n": g["m_A"] * (g["v_A1"] - v), "T_lost": 0.5 * g["m_A"] * (g["v_A1"] ** 2 - v * v)}
    return true, {"T_lost": 0.5 * g["m_A"] * (g["v_A1"] - abs(v)) ** 2}  # ½m(v1 - v2)² from the speeds


def _yf10(g: dict) -> tuple[dict, dict]:
    speed = g["e"] * g["v_A1"]
    before = 0.5 * g["m_A"] * g["v_A1"] ** 2
    true = {"v_A2": -speed, "T_lost": before - 0.5 * g["m_A"] * speed**2}
    return true, {"T_lost": before - g["m_A"] * speed**2}  # ½ × 2 × 2.56 worked as 5.12


def _yf11(g: dict) -> tuple[dict, dict]:
    a_rad = math.radians(g["alpha"])
    b_n, b_t = -g["u_B"] * math.cos(a_rad), g["u_B"] * math.sin(a_rad)
    x = -b_t * b_t / b_n  # x b_n + b_t b_t = 0: B turned through a right angle

    def worked(a_before: float) -> dict:
        a = a_before + b_n - x  # equal masses: a_before + b_n = a + x
        return {"v_A2n": a, "e": (x - a) / (g["v_A1n"] - b_n)}

    true = worked(g["v_A1n"]) | {"v_B2": math.hypot(x, b_t)}
    return true, worked(0.2)  # 0.3 copied as 0.2 in CLM only


def _yf12(g: dict) -> tuple[dict, dict]:
    rhs = g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B2"]  # 20 v_A = 10 - 10.5
    v_a = rhs / g["m_A"]
    true = {"v_A2": v_a, "e": (g["v_B2"] - v_a) / (g["v_A1"] - g["v_B1"])}
    slipped_v = -rhs / g["m_A"]  # the sign lost
    correct_given_slip = (g["v_B2"] - slipped_v) / g["v_A1"]
    assert correct_given_slip == pytest.approx(0.55)
    return true, {"v_A2": slipped_v, "e": correct_given_slip - 0.1}  # 0.275/0.5 worked as 0.45


def _yf13(g: dict) -> tuple[dict, dict]:
    def worked(b_before: float, across: float) -> dict:
        p = g["m_A"] * g["v_A1n"] + g["m_B"] * b_before
        a, b = _solve(g["m_A"], g["m_B"], p, g["e"] * (g["v_A1n"] - g["v_B1n"]))
        return {"v_A2n": a, "v_B2n": b, "v_A2t": across, "v_A2": math.hypot(a, across), "v_B2": abs(b)}

    true = worked(g["v_B1n"], g["v_A1t"])
    return true, worked(-g["v_B1n"], g["e"] * g["v_A1t"])  # B's +4; e on A's perpendicular component


def _yf14(g: dict) -> tuple[dict, None]:
    # 2b = v0 (1 + e), b (1 + e) = 2 v_C  ->  b² = v0 v_C
    b = math.sqrt(g["v_0"] * g["v_C"])
    e = 2 * b / g["v_0"] - 1
    _first, second = _solve(1.0, 1.0, g["v_0"], e * g["v_0"])
    assert second == pytest.approx(b)
    assert _solve(1.0, 1.0, b, e * b)[1] == pytest.approx(g["v_C"])
    return {"u_B": b, "e": e}, None


def _yf15(g: dict) -> tuple[dict, dict]:
    def worked(b_before: float) -> dict:
        p = g["m_A"] * g["v_A"] + g["m_B"] * b_before
        a, b = _solve(g["m_A"], g["m_B"], p, g["e"] * (g["v_A"] + g["v_B"]))
        w = -g["e_wall"] * b
        return {"u_A": a, "u_B": b, "w_B": w, "again": "yes" if w < a else "no"}

    return worked(-g["v_B"]), worked(g["v_B"])  # B's momentum taken positive


NUMERIC_YF: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yf01": _yf01,
    "yf02": _yf02,
    "yf08": _yf08,
    "yf09": _yf09,
    "yf10": _yf10,
    "yf11": _yf11,
    "yf12": _yf12,
    "yf13": _yf13,
    "yf14": _yf14,
    "yf15": _yf15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _yf03(p: dict) -> tuple[dict, None]:
    u, al = p["u"], p["alpha"]
    c = u * math.cos(al)
    a, b = _solve(2.0, 1.0, 2 * c - c, 0.5 * (c + c))
    return {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, u * math.sin(al))}, None


def _yf04(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    along, across = u * math.cos(math.radians(30)), u * math.sin(math.radians(30))
    v_1, _ = _solve(1.0, 1.0, along, e * along)
    # the deflection from the cross and dot products of the velocities before and after
    cross = along * across - across * v_1
    dot = along * v_1 + across * across
    turned = math.atan2(cross, dot)
    assert turned == pytest.approx(math.atan2(across, v_1) - math.radians(30))
    return {"v_A2n": v_1, "deflection": turned}, None


def _yf05(p: dict) -> tuple[dict, None]:
    u, e, al = p["u"], p["e"], p["alpha"]
    return {"beta": math.atan2(e * u * math.sin(al), u * math.cos(al))}, None


def _yf06(p: dict) -> tuple[dict, dict]:
    v, e = p["v"], 0.2  # e = 1/5 in the problem
    after_a, after_b = -v, 1.5 * v
    gap = (after_b - after_a) / e  # p + q, the speeds before

    def worked(momentum: float) -> dict:
        # 2p - 3q = momentum, p + q = gap
        q = (2 * gap - momentum) / 5
        return {"v_A1": gap - q, "v_B1": -q}

    true = worked(2 * after_a + 3 * after_b)
    return true, worked(6.5 * v)  # -2v + 4.5v worked as 6.5v


def _yf07(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 2.0, 3 * u, 3 * e * u)
    sa, sb = _solve(2.0, 1.0, 3 * u, 3 * e * u)  # the masses exchanged after the impact
    return {"v_B2": b, "v_A2": a}, {"v_B2": sb, "v_A2": sa}


SYMBOLIC_YF: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "yf03": _yf03,
    "yf04": _yf04,
    "yf05": _yf05,
    "yf06": _yf06,
    "yf07": _yf07,
}


def test_every_yf_case_is_worked_here() -> None:
    batch_shape(YF_CASES, set(NUMERIC_YF) | set(SYMBOLIC_YF))


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YF))
def test_the_yf_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YF[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YF))
def test_the_yf_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, v, e, alpha in POINTS:
        names = {"u": u, "v": v, "e": e, "alpha": alpha}
        true, slipped = SYMBOLIC_YF[prefix](names)
        letters_agree(case, names, true, slipped)


def test_the_yf04_deflection_the_student_shows() -> None:
    """yf04 records only v_A2n; the show-that its last line reaches is worked here too."""
    for u, _v, e, _alpha in POINTS:
        true, _ = _yf04({"u": u, "e": e})
        assert math.atan(math.sqrt(3) * (1 + e) / (5 - 3 * e)) == pytest.approx(true["deflection"], rel=1e-9)
