"""The xc batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xc cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, an impulse as a change of momentum, kinetic energy, a
fall and a rise under gravity), with the student's slip made on purpose for the slip values.
Answers in letters (u, e, alpha, k, lambda) are checked at a few points by solving the two linear
equations numerically there (energies in units of m). Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import _ALPHA, _K, _LAM, CASES, _bounce, _formula, _given, _solve

XC_CASES = [c for c in CASES if c.name.startswith("xc")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters
LETTERS = {"alpha": _ALPHA, "k": _K, "lam": _LAM}


def _case(prefix: str):
    return next(c for c in XC_CASES if c.name.startswith(prefix))


def _parts(speed: float, degrees: float) -> tuple[float, float]:
    """(along, across) for a speed at `degrees` to the line of centres."""
    return speed * math.cos(math.radians(degrees)), speed * math.sin(math.radians(degrees))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _xc01(g: dict) -> tuple[dict, None]:
    along, across = _parts(g["v_A1"], 30)
    # equal masses, e = 1: the sum of the x parts kept, their difference reversed
    a, b = _solve(1.0, 1.0, along + g["v_B1n"], g["e"] * (along - g["v_B1n"]))
    return {"v_A2n": a, "v_B2n": b, "v_A2t": across, "v_A2": math.hypot(a, across), "v_B2": abs(b)}, None


def _xc06(g: dict) -> tuple[dict, dict]:
    normal, tangent = _parts(1.0, 90 - g["theta_1"])  # theta_1 from the plane of contact, per unit v
    a, b = _solve(1.0, 1.0, normal, g["e"] * normal)
    sa, sb = _solve(1.0, 1.0, normal, -g["e"] * normal)  # v_An' - v_Bn' = e(approach)

    def worked(v_an: float, v_bn: float) -> dict:
        angle = math.degrees(math.atan2(v_an, tangent))
        return {"theta_A2": angle, "v_A2n_per_v_A1": v_an, "v_B2_per_v_A1": v_bn}

    return worked(a, b), worked(sa, sb)


def _xc11(g: dict) -> tuple[dict, dict]:
    along, across = _parts(g["v_A1"], 60)
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * along + g["m_B"] * g["v_B1n"], g["e"] * (along - g["v_B1n"]))

    def worked(a_t: float) -> dict:
        angle = math.degrees(math.atan2(a_t, abs(a)))
        return {"v_A2n": a, "v_B2n": b, "v_A2t": a_t, "v_A2": math.hypot(a, a_t), "angle_loc": angle}

    slipped = worked(g["e"] * across)  # e applied to A's y component too
    return worked(across), {k: slipped[k] for k in ("v_A2t", "v_A2", "angle_loc")}


def _xc12(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    approach = g["v_A1"] - g["v_B1"]
    v = (p - g["m_A"] * g["v_A2"]) / g["m_B"]
    slipped = (p + g["m_A"] * g["v_A2"]) / g["m_B"]  # A's -1.2 taken +1.2
    true = {"v_B2": v, "e": (v - g["v_A2"]) / approach}
    return true, {"v_B2": slipped, "e": approach / (slipped - g["v_A2"])}  # approach over separation


def _xc13(g: dict) -> tuple[dict, dict]:
    def worked(along: float, across: float, mass_b: float) -> dict:
        a, b = _solve(g["W_A"], g["W_B"], g["W_A"] * along, g["e"] * along)  # g cancels
        return {"v_A2n": a, "v_B2n": b, "v_A2t": across, "v_A2": math.hypot(a, across), "v_B2": b, "J_n": mass_b * b}

    along, across = _parts(g["v_A1"], 30)
    # slips: sin and cos swapped; the weight 47 lb used as the mass in the impulse
    return worked(along, across, g["W_B"] / 32.2), worked(across, along, g["W_B"])


def _xc14(g: dict) -> tuple[dict, None]:
    total = g["m_bullet"] + g["m_block"]
    big_v = g["m_bullet"] * g["v_0"] / total
    return {"V": big_v, "T_after": 0.5 * total * big_v**2, "h_2": big_v**2 / (2 * g["g"])}, None


def _xc15(g: dict) -> tuple[dict, dict]:
    true = _bounce(g, math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"]))
    return true, _bounce(g, math.sqrt(g["v_0"] ** 2 + g["g"] * g["h_0"]))  # the 2 of 2gh lost


NUMERIC_XC: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xc01": _xc01,
    "xc06": _xc06,
    "xc11": _xc11,
    "xc12": _xc12,
    "xc13": _xc13,
    "xc14": _xc14,
    "xc15": _xc15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None), masses in units of m ----


def _xc02(u: float, _e: float) -> tuple[dict, None]:
    # the impulse 4mu: 3m(v_1 - 2u) = -4mu, m(v_2 - (-u)) = 4mu
    return {"v_A2": 2 * u - 4 * u / 3, "v_B2": -u + 4 * u}, None


def _xc03(u: float, _e: float) -> tuple[dict, None]:
    # 1/2 (2/3)(1 - e^2) u^2 = 1/4 u^2 (the quarter lost), then momentum and restitution
    e = math.sqrt(1 - 0.25 * u * u / (0.5 * (2 / 3) * u * u))
    a, b = _solve(2.0, 1.0, 2 * u, e * u)
    assert 0.5 * 2 * a * a + 0.5 * b * b == pytest.approx(0.75 * u * u)
    return {"v_A2": a, "v_B2": b, "e": e}, None


def _xc04(u: float, e: float) -> tuple[dict, None]:
    along = u * math.cos(math.radians(60))
    a, b = _solve(1.0, 1.0, along, e * along)
    return {"v_B2": b, "v_A2n": a}, None


def _xc05(u: float, e: float) -> tuple[dict, None]:
    along, normal = u * math.cos(LETTERS["alpha"]), u * math.sin(LETTERS["alpha"])
    after = e * normal
    return {"beta": math.atan2(after, along), "T_lost": 0.5 * (normal**2 - after**2)}, None


def _xc07(u: float, _e: float) -> tuple[dict, dict]:
    e = 0.5
    c, s = math.cos(LETTERS["alpha"]), math.sin(LETTERS["alpha"])
    a, b = _solve(2.0, 1.0, 2 * u * c - u * c, e * 2 * u * c)
    sa, sb = _solve(2.0, 1.0, 2 * u * c + u * c, e * 2 * u * c)  # B's momentum +m u cos a
    true = {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, u * s)}
    return true, {"v_A2n": sa, "v_B2n": sb, "v_B2": math.hypot(sb, u * s)}


def _xc08(u: float, _e: float) -> tuple[dict, dict]:
    k, lam = LETTERS["k"], LETTERS["lam"]
    w = (u + k * lam * u) / k  # S stopped: m u + k m lam u = k m w
    return {"v_B2": w, "e": w / (u - lam * u)}, {"e": (u - lam * u) / w}


def _xc09(u: float, e: float) -> tuple[dict, dict]:
    along, across = u * math.cos(math.radians(30)), u * math.sin(math.radians(30))
    a, _ = _solve(1.0, 1.0, along, e * along)
    t_phi, t_30 = across / a, math.tan(math.radians(30))
    true = {"v_A2n": a, "deflection": math.atan2(across, a) - math.radians(30)}
    return true, {"deflection": math.atan((t_phi - t_30) / (1 - t_phi * t_30))}  # 1 - tan tan below


def _xc10(u: float, e: float) -> tuple[dict, dict]:
    a, b = _solve(2.0, 3.0, 10 * u, 5 * e * u)
    sa, sb = _solve(3.0, 2.0, 10 * u, 5 * e * u)  # 10u = 3x + 2y
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


SYMBOLIC_XC: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "xc02": _xc02,
    "xc03": _xc03,
    "xc04": _xc04,
    "xc05": _xc05,
    "xc07": _xc07,
    "xc08": _xc08,
    "xc09": _xc09,
    "xc10": _xc10,
}


def test_every_xc_case_is_worked_here() -> None:
    assert len(XC_CASES) == 15
    assert {c.name[:4] for c in XC_CASES} == set(NUMERIC_XC) | set(SYMBOLIC_XC)
    by_category = sorted(c.verdict.category for c in XC_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in XC_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    for case in XC_CASES:
        slipped = case.verdict.category in ("one_slip", "two_slips") or case.verdict.summary != "0 wrong"
        assert bool(case.verdict.slip_values) == slipped, case.name


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XC))
def test_the_xc_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XC[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XC))
def test_the_xc_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        true, slipped = SYMBOLIC_XC[prefix](u, e)
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, LETTERS) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, LETTERS) == pytest.approx(slipped[name], rel=1e-9), name
