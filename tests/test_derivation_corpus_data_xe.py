"""The xe batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xe cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (components along and
across the line of centres as dot products with unit vectors, momentum along the line of centres,
Newton's law of restitution, a fall and a rise, an impulse), with the student's slip made on
purpose for the slip values. Answers in letters (u, e, alpha) are checked at a few points.
Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, letters_agree, numbers_agree

XE_CASES = [c for c in CASES if c.name.startswith("xe")]
# (u, e, alpha in radians) for the letters
POINTS = ((1.0, 0.5, 0.4), (2.0, 0.3, 0.9), (1.5, 0.9, 1.2))


def _case(prefix: str):
    return next(c for c in XE_CASES if c.name.startswith(prefix))


def _dot(a: tuple[float, float], b: tuple[float, float]) -> float:
    return a[0] * b[0] + a[1] * b[1]


def _unit(degrees: float) -> tuple[float, float]:
    return math.cos(math.radians(degrees)), math.sin(math.radians(degrees))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _xe01(g: dict) -> tuple[dict, None]:
    n, t = _unit(g["phi_n"]), _unit(g["phi_n"] + 90)
    u_a = tuple(g["v_A1"] * c for c in _unit(45))
    u_b = tuple(g["v_B1"] * c for c in _unit(120))
    a_n, a_t, b_n, b_t = _dot(u_a, n), _dot(u_a, t), _dot(u_b, n), _dot(u_b, t)
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, g["e"] * (a_n - b_n))
    return {
        "v_A2n": a,
        "v_B2n": b,
        "v_A2": math.hypot(a, a_t),
        "v_B2": math.hypot(b, b_t),
        "psi_A2": g["phi_n"] + math.degrees(math.atan2(a_t, a)),
        "psi_B2": g["phi_n"] + math.degrees(math.atan2(b_t, b)),
    }, None


def _xe02(g: dict) -> tuple[dict, None]:
    b = g["v_B1t"] / math.tan(math.radians(45))  # equal components at 45 deg
    a = (g["m_A"] * g["v_A1n"] + g["m_B"] * g["v_B1n"] - g["m_B"] * b) / g["m_A"]
    return {"e": (b - a) / (g["v_A1n"] - g["v_B1n"]), "v_B2n": b, "v_A2": math.hypot(a, g["v_A1t"])}, None


def _xe03(g: dict) -> tuple[dict, None]:
    v_1 = (g["m_A"] * g["v_A1"] - g["m_B"] * g["v_A1"]) / (g["m_A"] + g["m_B"])  # v2 = v1 + 3.5
    return {"v_A2": v_1, "v_B2": v_1 + g["v_A1"]}, None


def _xe05(g: dict) -> tuple[dict, None]:
    theta = math.atan(3.0)  # u.v = u^2 cos^2 - e u^2 sin^2 = 0
    return {"e": math.cos(theta) ** 2 / math.sin(theta) ** 2}, None


def _xe08(g: dict) -> tuple[dict, dict]:
    p, gap = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"], g["e"] * (g["v_A1"] - g["v_B1"])
    v_a, v_b = _solve(g["m_A"], g["m_B"], p, gap)
    s_a, s_b = _solve(g["m_B"], g["m_A"], p, gap)  # 80 = 8 v_A + 4 v_B
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_b}


def _xe09(g: dict) -> tuple[dict, dict]:
    v_a = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_B"] * g["v_B2"]) / g["m_A"]

    def e_of(v: float) -> float:
        return (g["v_B2"] - v) / (g["v_A1"] - g["v_B1"])

    return {"v_A2": v_a, "e": e_of(v_a)}, {"v_A2": -v_a, "e": e_of(-v_a)}  # the sign dropped in -0.5/20


def _xe10(g: dict) -> tuple[dict, dict]:
    a_n, a_t = g["v_A1"] * math.cos(math.radians(60)), g["v_A1"] * math.sin(math.radians(60))

    def worked(b_in_momentum: float) -> dict:
        p = g["m_A"] * a_n + g["m_B"] * b_in_momentum
        a, b = _solve(g["m_A"], g["m_B"], p, g["e"] * (a_n - g["v_B1n"]))
        return {"v_A2n": a, "v_B2n": b, "v_A2": math.hypot(a, a_t), "angle_loc": math.degrees(math.atan(a_t / abs(a)))}

    return worked(g["v_B1n"]), worked(-g["v_B1n"])  # B's +6 in CLM only


def _xe12(g: dict) -> tuple[dict, dict]:
    v_b = g["v_A2"] + g["e"] * (g["v_A1"] - g["v_B1"])
    m = (g["m_A"] * g["v_A1"] - g["m_A"] * g["v_A2"]) / v_b
    s_v = g["v_A1"] - g["v_A2"]  # slip 1: v_B = 0.200 - 0.050
    s_m = (g["m_A"] * g["v_A1"] - g["m_A"] * g["v_A2"] / 10) / s_v  # slip 2: 0.0400 x 0.050 as 0.00020
    return {"v_B2": v_b, "m_B": m}, {"v_B2": s_v, "m_B": s_m}


def _xe14(g: dict) -> tuple[dict, None]:
    one_plus_e = math.sqrt(g["v_C"] / (g["v_0"] / 4))  # u_C = v_0 (1 + e)^2 / 4
    return {"u_B": g["v_0"] * one_plus_e / 2, "e": one_plus_e - 1}, None


def _xe15(g: dict) -> tuple[dict, dict]:
    v_1 = math.sqrt(2 * g["g"] * g["h_0"])

    def worked(v_2: float) -> dict:
        return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_2 - (-v_1))}

    assert round(2 * g["g"] * g["h_r"], 2) == 27.44
    return worked(math.sqrt(2 * g["g"] * g["h_r"])), worked(math.sqrt(24.74))  # 27.44 written 24.74


NUMERIC_XE: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xe01": _xe01,
    "xe02": _xe02,
    "xe03": _xe03,
    "xe05": _xe05,
    "xe08": _xe08,
    "xe09": _xe09,
    "xe10": _xe10,
    "xe12": _xe12,
    "xe14": _xe14,
    "xe15": _xe15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses equal unless said ----


def _xe04(p: dict) -> tuple[dict, None]:
    u, e, al = p["u"], p["e"], p["alpha"]
    x, y = _solve(1.0, 1.0, u * math.cos(al), e * u * math.cos(al))
    t = u * math.sin(al)
    return {"v_A2t": t, "v_A2n": x, "v_B2": y, "beta_A2": math.atan2(t, x)}, None


def _xe06(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]

    def worked(along: float) -> dict:
        x, y = _solve(1.0, 1.0, along, e * along)
        return {"v_B2": y, "v_A2n": x}

    return worked(u * math.cos(math.radians(30))), worked(u * math.sin(math.radians(30)))


def _xe07(p: dict) -> tuple[dict, dict]:
    u = p["u"]

    def worked(b_mass_in_ke: float) -> dict:
        # (1 - 9e)^2 + k (1 + e)^2 = 50: (81 + k) e^2 + (2k - 18) e + (1 + k - 50) = 0, the positive root
        qa, qb, qc = 81 + b_mass_in_ke, 2 * b_mass_in_ke - 18, 1 + b_mass_in_ke - 50
        e = (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)
        v_a, v_b = _solve(1.0, 9.0, u, e * u)
        return {"e": e, "v_A2": v_a, "v_B2": v_b}

    return worked(9.0), worked(1.0)


def _xe11(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], 0.5
    theta = math.asin(1 / 2)

    def worked(along: float, across: float) -> dict:
        a, b = _solve(1.0, 1.0, along, e * along)
        return {"v_B2": b, "v_A2n": a, "v_A2": math.hypot(a, across)}

    return worked(u * math.cos(theta), u * math.sin(theta)), worked(u * math.sin(theta), u * math.cos(theta))


def _xe13(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    along, across = u * math.cos(math.radians(30)), u * math.sin(math.radians(30))
    a, _ = _solve(1.0, 1.0, along, e * along)
    s_a, _ = _solve(1.0, 1.0, along, -e * along)  # a - b = e (sqrt3/2) u
    tan_beta, t30 = across / s_a, math.tan(math.radians(30))
    numerator = tan_beta - t30
    assert 1 + tan_beta * t30 == pytest.approx((5 + 3 * e) / (3 * (1 + e)))
    slipped_denominator = (5 + e) / (3 * (1 + e))  # 3(1 + e) + 2 taken as 5 + e
    return (
        {"v_A2n": a, "deflection": math.atan2(across, a) - math.radians(30)},
        {"v_A2n": s_a, "deflection": math.atan(numerator / slipped_denominator)},
    )


SYMBOLIC_XE: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xe04": _xe04,
    "xe06": _xe06,
    "xe07": _xe07,
    "xe11": _xe11,
    "xe13": _xe13,
}


def test_every_xe_case_is_worked_here() -> None:
    batch_shape(XE_CASES, set(NUMERIC_XE) | set(SYMBOLIC_XE))


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XE))
def test_the_xe_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XE[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XE))
def test_the_xe_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha in POINTS:
        names = {"u": u, "e": e, "alpha": alpha}
        true, slipped = SYMBOLIC_XE[prefix](names)
        letters_agree(case, names, true, slipped)
