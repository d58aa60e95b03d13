"""The xg batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xg cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, components of a velocity, kinetic energy, a fall and
a rise, an impulse), with the student's slip made on purpose for the slip values. Answers in
letters (u, e, alpha) are checked at a few points by evaluating the closed forms there against
the two linear equations solved numerically. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, closed_form, letters_agree, numbers_agree

XG_CASES = [c for c in CASES if c.name.startswith("xg")]
# (u, e, alpha in radians) for the letters
POINTS = ((1.0, 0.5, 0.4), (2.0, 0.3, 0.9), (1.5, 0.9, 1.2))


def _case(prefix: str):
    return next(c for c in XG_CASES if c.name.startswith(prefix))


def _energy(m: float, v: float) -> float:
    return 0.5 * m * v * v


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _xg01(g: dict) -> tuple[dict, None]:
    m_b = (g["m_A"] * g["v_A1"] - g["m_A"] * g["v_A2"]) / g["v_B2"]
    return {"m_B": m_b, "e": (g["v_B2"] - g["v_A2"]) / (g["v_A1"] - 0.0)}, None


def _xg02(g: dict) -> tuple[dict, None]:
    e = g["e"]
    sin2 = (1 - 3 / 5) / (1 - e * e)  # cos^2 + e^2 sin^2 = 3/5 with cos^2 = 1 - sin^2
    return {"alpha": math.degrees(math.asin(math.sqrt(sin2)))}, None


def _xg05(g: dict) -> tuple[dict, None]:
    normal = g["v_A1"] * math.cos(math.radians(g["theta"]))
    before, after = -normal, g["e"] * normal  # x out of the wall
    return {"v_A1n": normal, "J_n": g["m_A"] * after - g["m_A"] * before}, None


def _xg07(g: dict) -> tuple[dict, dict]:
    mass = g["m_A"] + g["m_B"]
    v = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]) / mass
    t_1 = _energy(g["m_A"], g["v_A1"])
    t_2 = _energy(mass, v)
    slipped = mass * v * v  # no half
    return {"v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, {"T_2": slipped, "T_lost": t_1 - slipped}


def _xg08(g: dict) -> tuple[dict, dict]:
    v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_A"] * g["v_A2"]) / g["m_B"]
    approach = g["v_A1"] - g["v_B1"]
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / approach}, {"e": (3.54 - g["v_A2"]) / approach}  # 3.45 as 3.54


def _xg09(g: dict) -> tuple[dict, dict]:
    a_n = g["v_A1"] * math.cos(math.radians(60))
    a_t = g["v_A1"] * math.sin(math.radians(60))
    gap = g["e"] * (a_n - g["v_B1n"])

    def worked(b_n: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, gap)
        return {
            "v_A2n": a,
            "v_B2n": b,
            "v_A2t": a_t,
            "v_A2": math.hypot(a, a_t),
            "angle_loc": math.degrees(math.atan2(a_t, abs(a))),
        }

    slipped = worked(-g["v_B1n"])  # B's +6 in the momentum only
    del slipped["v_A2t"]
    return worked(g["v_B1n"]), slipped


def _xg10(g: dict) -> tuple[dict, dict]:
    n = math.sin(math.radians(g["theta_1"]))
    t = math.cos(math.radians(g["theta_1"]))

    def worked(sign: float) -> dict:
        a, b = _solve(1.0, 1.0, n, sign * g["e"] * n)  # b - a = sign * e n
        return {"v_A2n_per_v_A1": a, "v_B2_per_v_A1": b, "theta_A2": math.degrees(math.atan2(a, t))}

    return worked(1.0), worked(-1.0)  # a - b = e n


def _xg11(g: dict) -> tuple[dict, dict]:
    def worked(along: float, across: float) -> dict:
        # m_A a + m_B along = m_B b, b = e (a - along)
        a = (g["m_B"] * along + g["m_B"] * g["e"] * along) / (g["m_B"] * g["e"] - g["m_A"])
        b = g["e"] * (a - along)
        return {"v_A1n": a, "v_B2": math.hypot(b, across), "delta_B": 60.0 - math.degrees(math.atan2(across, b))}

    c, s = g["v_B1"] * math.cos(math.radians(60)), g["v_B1"] * math.sin(math.radians(60))
    return worked(c, s), worked(s, c)


def _xg12(g: dict) -> tuple[dict, dict]:
    mass = g["m_A"] + g["m_B"]
    v = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]) / mass
    t_1 = _energy(g["m_A"], g["v_A1"]) + _energy(g["m_B"], g["v_B1"])
    true = {"v_A2": v, "T_1": t_1, "T_2": _energy(mass, v), "T_lost": t_1 - _energy(mass, v)}
    v_s = (g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B1"]) / mass  # slip 1: v2 entered as +0.120
    t_1s = 7452.0  # slip 2: 6750 + 792 written 7452
    assert round(_energy(g["m_A"], g["v_A1"]) + _energy(g["m_B"], g["v_B1"])) == 7542
    return true, {"v_A2": v_s, "T_1": t_1s, "T_2": _energy(mass, v_s), "T_lost": t_1s - _energy(mass, v_s)}


def _xg14(g: dict) -> tuple[dict, None]:
    mass = g["m_bullet"] + g["m_block"]
    v = g["m_bullet"] * g["v_0"] / mass
    return {"V": v, "T_after": _energy(mass, v), "h_2": v * v / (2 * g["g"])}, None


def _xg15(g: dict) -> tuple[dict, dict]:
    def worked(v_1_squared: float) -> dict:
        v_1 = math.sqrt(v_1_squared)
        v_2 = math.sqrt(2 * g["g"] * g["h_0"])  # back up to the start
        return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}

    true = worked(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"])
    slipped = worked(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"] - 100.0)  # 441 + 784 added as 1125
    del slipped["v_2"]
    return true, slipped


NUMERIC_XG: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xg01": _xg01,
    "xg02": _xg02,
    "xg05": _xg05,
    "xg07": _xg07,
    "xg08": _xg08,
    "xg09": _xg09,
    "xg10": _xg10,
    "xg11": _xg11,
    "xg12": _xg12,
    "xg14": _xg14,
    "xg15": _xg15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _xg03(p: dict) -> tuple[dict, None]:
    along = p["u"] * math.cos(math.radians(60))
    a, b = _solve(1.0, 1.0, along, p["e"] * along)
    return {"v_B2": b, "v_A2n": a}, None


def _xg04(p: dict) -> tuple[dict, None]:
    a, b = _solve(1.0, 1.0, p["u"], p["e"] * p["u"])
    return {"v_A2": a, "v_B2": b}, None


def _xg06(p: dict) -> tuple[dict, dict]:
    u, e, al = p["u"], p["e"], p["alpha"]
    along, across = u * math.cos(al), u * math.sin(al)
    x, _ = _solve(1.0, 1.0, along, e * along)
    true = {"v_A2t": across, "v_A2n": x, "beta_A2": math.atan2(across, x)}
    slipped_x = (along + e * along) / 2  # the sum x + y + (y - x) = 2y taken for 2x
    return true, {"v_A2n": slipped_x, "beta_A2": math.atan2(across, slipped_x)}


def _xg13(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    _, b = _solve(1.0, 1.0, u * math.cos(math.radians(30)), e * u * math.cos(math.radians(30)))
    along = u * math.sin(math.radians(30))  # slip 1: sin 30
    two_b = along + e * along
    return {"v_B2": b}, {"v_B2": two_b}  # slip 2: 2 v_B taken for v_B


SYMBOLIC_XG: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xg03": _xg03,
    "xg04": _xg04,
    "xg06": _xg06,
    "xg13": _xg13,
}


def test_every_xg_case_is_worked_here() -> None:
    batch_shape(XG_CASES, set(NUMERIC_XG) | set(SYMBOLIC_XG))


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XG))
def test_the_xg_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XG[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XG))
def test_the_xg_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha in POINTS:
        names = {"u": u, "e": e, "alpha": alpha}
        true, slipped = SYMBOLIC_XG[prefix](names)
        letters_agree(case, names, true, slipped)


def test_the_xg06_show_that_fails_only_by_the_sign_of_e() -> None:
    values = _case("xg06").verdict.slip_values
    for u, e, alpha in POINTS:
        beta = closed_form(str(values["beta_A2"]), {"u": u, "e": e, "alpha": alpha})
        assert (1 + e) * math.tan(beta) == pytest.approx(2 * math.tan(alpha))
