"""The ze batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the ze cases (ze01-ze15) in
tests/data/derivations/verdicts.toml is worked again here from the problem file's givens with
plain Python arithmetic (n-t components, momentum and restitution along the line of impact, a
wall's rebound, an energy ratio, a rise), each slip made on purpose for the slip values. Letters
(u, e, alpha) are checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given

ZE_CASES = {c.name[:4]: c for c in CASES if c.name.startswith("ze")}
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) where they are letters
ALPHA = 0.7  # alpha in radians where a problem keeps it as a letter
G = 9.81


def _deg(x: float) -> float:
    return math.radians(x)


def _line(m_a: float, m_b: float, e: float, a_n: float, b_n: float) -> tuple[float, float]:
    """n-velocities after: m_A a + m_B b = m_A a_n + m_B b_n and b - a = e (a_n - b_n)."""
    gap = e * (a_n - b_n)
    a = (m_a * a_n + m_b * b_n - m_b * gap) / (m_a + m_b)
    return a, a + gap


# ---- numeric cases: givens -> (true values, slipped values or None) ----


def _ze01(g: dict) -> tuple[dict, None]:
    a_n, a_t = g["v_A1"] * math.cos(_deg(45 - 20)), g["v_A1"] * math.sin(_deg(45 - 20))
    b_n, b_t = g["v_B1"] * math.cos(_deg(120 - 20)), g["v_B1"] * math.sin(_deg(120 - 20))
    mu = g["m_A"] * g["m_B"] / (g["m_A"] + g["m_B"])
    impulse = (1 + g["e"]) * mu * (a_n - b_n)  # the impulse B gets along n
    v_an, v_bn = a_n - impulse / g["m_A"], b_n + impulse / g["m_B"]
    assert (v_an, v_bn) == pytest.approx(_line(g["m_A"], g["m_B"], g["e"], a_n, b_n))
    return {
        "v_A2n": v_an,
        "v_B2n": v_bn,
        "v_A2": math.hypot(v_an, a_t),
        "v_B2": math.hypot(v_bn, b_t),
        "psi_A2": math.degrees(math.atan2(a_t, v_an)) + g["phi_n"],
        "psi_B2": math.degrees(math.atan2(b_t, v_bn)) + g["phi_n"],
    }, None


def _ze02(g: dict) -> tuple[dict, None]:
    a_n, a_t = g["v_A1"] * math.cos(_deg(30)), g["v_A1"] * math.sin(_deg(30))
    v_g = a_n / 2  # equal weights, B at rest
    v_an, v_bn = v_g - g["e"] * (a_n - v_g), v_g + g["e"] * v_g
    return {"v_A2n": v_an, "v_B2n": v_bn, "v_A2t": a_t, "v_A2": math.hypot(v_an, a_t), "v_B2": v_bn}, None


def _ze03(_g: dict) -> tuple[dict, None]:
    theta = math.atan(3.0)
    phi = math.pi / 2 - theta  # the path turns through a right angle
    return {"e": math.tan(phi) / math.tan(theta)}, None


def _ze04(g: dict) -> tuple[dict, None]:
    v_bn = g["v_B1t"] / math.tan(_deg(45))
    impulse = g["m_B"] * (v_bn - g["v_B1n"])
    v_an = g["v_A1n"] - impulse / g["m_A"]
    e = (v_bn - v_an) / (g["v_A1n"] - g["v_B1n"])
    return {"v_B2n": v_bn, "v_A2": math.hypot(v_an, g["v_A1t"]), "e": e}, None


def _ze05(g: dict) -> tuple[dict, None]:
    e2 = g["e"] ** 2
    tan2 = (1 - 0.6) / (0.6 - e2)  # 1 + e^2 t^2 = 0.6 (1 + t^2)
    return {"alpha": math.degrees(math.atan(math.sqrt(tan2)))}, None


def _ocr_fm(g: dict, approach: float) -> dict:
    a_n, a_t = g["v_A1"] * math.cos(_deg(60)), g["v_A1"] * math.sin(_deg(60))
    p = g["m_A"] * a_n + g["m_B"] * g["v_B1n"]
    gap = g["e"] * approach
    v_an = (p - g["m_B"] * gap) / (g["m_A"] + g["m_B"])
    v_bn = v_an + gap
    return {
        "v_A2n": v_an,
        "v_B2n": v_bn,
        "v_A2t": a_t,
        "v_A2": math.hypot(v_an, a_t),
        "angle_loc": math.degrees(math.atan2(a_t, abs(v_an))),
    }


def _ze06(g: dict) -> tuple[dict, dict]:
    a_n = g["v_A1"] * math.cos(_deg(60))
    return _ocr_fm(g, a_n - g["v_B1n"]), _ocr_fm(g, a_n + g["v_B1n"])  # 2 - 6: B's sign lost


def _cue(g: dict, nel_sign: float) -> dict:
    a_n, a_t = math.sin(_deg(g["theta_1"])), math.cos(_deg(g["theta_1"]))  # per unit v_A1
    gap = nel_sign * g["e"] * a_n  # v_Bn - v_An
    v_an = (a_n - gap) / 2
    return {"theta_A2": math.degrees(math.atan2(v_an, a_t)), "v_A2n_per_v_A1": v_an, "v_B2_per_v_A1": v_an + gap}


def _ze07(g: dict) -> tuple[dict, dict]:
    return _cue(g, 1.0), _cue(g, -1.0)  # v_An - v_Bn = e (approach): the sign of the gap reversed


def _ze11(g: dict) -> tuple[dict, dict]:
    a_n, a_t = g["v_A1"] * math.cos(_deg(30)), g["v_A1"] * math.sin(_deg(30))
    b_n = g["v_B1n"]
    v_an, v_bn = _line(1.0, 1.0, g["e"], a_n, b_n)
    true = {"v_A2n": v_an, "v_B2n": v_bn, "v_A2t": a_t, "v_A2": math.hypot(v_an, a_t), "v_B2": abs(v_bn)}
    gap = g["e"] * (a_n - b_n)  # restitution right
    s_an = (a_n - b_n - gap) / 2  # momentum with +3 for B
    s_bn = s_an + gap
    return true, {"v_A2n": s_an, "v_B2n": s_bn, "v_A2": math.hypot(s_an, a_t), "v_B2": abs(s_bn)}


def _ze12(g: dict) -> tuple[dict, dict]:
    m, u, v = g["m_A"], g["v_A1"], g["v_A2"]
    t_1, t_2 = 0.5 * m * u**2, 0.5 * m * v**2
    true = {"e": -v / u, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}
    s_t1 = 0.5 * m * u  # the speed not squared
    return true, {"e": -u / v, "T_1": s_t1, "T_lost": s_t1 - t_2}


def _ocr_m3_2007(g: dict, along: float, across: float, e_across: float) -> dict:
    v_an, v_bn = _line(g["m_A"], g["m_B"], g["e"], along, g["v_B1n"])
    v_at = e_across * across
    return {
        "v_A2n": v_an,
        "v_B2n": v_bn,
        "v_A2t": v_at,
        "v_A2": math.hypot(v_an, v_at),
        "dir_A_from_i": math.degrees(math.atan2(v_at, v_an)),
    }


def _ze13(g: dict) -> tuple[dict, dict]:
    sin_a = 0.8
    cos_a = math.sqrt(1 - sin_a**2)
    true = _ocr_m3_2007(g, g["v_A1"] * cos_a, g["v_A1"] * sin_a, 1.0)
    slipped = _ocr_m3_2007(g, g["v_A1"] * sin_a, g["v_A1"] * cos_a, g["e"])  # swapped, then e on t
    return true, slipped


def _ze14(g: dict) -> tuple[dict, None]:
    u_a, u_b, v_a, v_b = g["v_A"], -g["v_B"], g["s_A"], g["s_B"]  # B moves back: the way A went
    impulse = g["m_B"] * (v_b - u_b)  # on B; the opposite on A
    m_a = impulse / (u_a - v_a)
    w = g["I_w"] / g["m_B"] - g["s_B"]  # away from the wall
    return {"e": (v_b - v_a) / (u_a - u_b), "m_A": m_a, "u_B": v_b, "w_B": -w, "e_wall": w / v_b}, None


def _bullet(m: float, big_m: float, v_0: float) -> dict:
    v = m * v_0 / (m + big_m)
    return {"V": v, "T_after": 0.5 * (m + big_m) * v**2, "h_2": v**2 / (2 * G)}


def _ze15(g: dict) -> tuple[dict, dict]:
    assert g["g"] == G
    true = _bullet(g["m_bullet"], g["m_block"], g["v_0"])
    return true, _bullet(10 * g["m_bullet"], g["m_block"], g["v_0"])  # 0.020 copied as 0.20


NUMERIC_ZE: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "ze01": _ze01,
    "ze02": _ze02,
    "ze03": _ze03,
    "ze04": _ze04,
    "ze05": _ze05,
    "ze06": _ze06,
    "ze07": _ze07,
    "ze11": _ze11,
    "ze12": _ze12,
    "ze13": _ze13,
    "ze14": _ze14,
    "ze15": _ze15,
}


# ---- symbolic cases: (u, e) -> (true values, slipped values) ----


def _ze08(u: float, e: float) -> tuple[dict, dict]:
    def at(along: float) -> dict:
        v_an, v_bn = _line(1.0, 1.0, e, along, 0.0)
        return {"v_A2n": v_an, "v_B2": v_bn}

    return at(u * math.cos(_deg(60))), at(u * math.sin(_deg(60)))  # sin 60 along n


def _ze09(u: float, e: float) -> tuple[dict, dict]:
    along, normal = u * math.cos(ALPHA), u * math.sin(ALPHA)
    true = math.atan2(e * normal, along)
    slipped = math.atan2(normal, e * along)  # e on the component along the cushion
    return {"beta": true}, {"beta": slipped}


def _ze10(u: float, _e: float) -> tuple[dict, dict]:
    e = _given("ocr-m3-2012-january-q2-opposite-directions-each-at-alpha")["e"]
    c, s = math.cos(ALPHA), math.sin(ALPHA)

    def with_masses(m_a: float, m_b: float) -> dict:
        v_an, v_bn = _line(m_a, m_b, e, u * c, -u * c)
        return {"v_A2n": v_an, "v_B2n": v_bn, "v_B2": math.hypot(v_bn, -u * s)}

    return with_masses(2.0, 1.0), with_masses(1.0, 2.0)


SYMBOLIC_ZE: dict[str, Callable[[float, float], tuple[dict, dict]]] = {
    "ze08": _ze08,
    "ze09": _ze09,
    "ze10": _ze10,
}


def test_every_ze_case_is_worked_here() -> None:
    assert len(ZE_CASES) == 15
    assert set(ZE_CASES) == set(NUMERIC_ZE) | set(SYMBOLIC_ZE)
    by_category = sorted(c.verdict.category for c in ZE_CASES.values())
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZE_CASES.values()) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZE))
def test_the_ze_values(prefix: str) -> None:
    case = ZE_CASES[prefix]
    true, slipped = NUMERIC_ZE[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZE))
def test_the_ze_closed_forms(prefix: str) -> None:
    case = ZE_CASES[prefix]
    assert case.verdict.slip_values, case.name
    for u, e in POINTS:
        true, slipped = SYMBOLIC_ZE[prefix](u, e)
        for name, formula in case.verdict.values.items():
            got = _formula(str(formula), u, e, {"alpha": ALPHA})
            assert got == pytest.approx(true[name], rel=1e-9, abs=1e-12), f"{case.name}: {name}"
        for name, formula in case.verdict.slip_values.items():
            got = _formula(str(formula), u, e, {"alpha": ALPHA})
            assert got == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), f"{case.name}: slip {name}"
