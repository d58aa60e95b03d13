"""The g batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the g cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum,
Newton's law of restitution, a wall's rebound, kinetic energy, a skid to rest), with the
student's slip made on purpose for the slip values. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given

G_CASES = [c for c in CASES if c.name.startswith("g")]


def _case(prefix: str):
    return next(c for c in G_CASES if c.name.startswith(prefix))


def _after(m_a: float, m_b: float, e: float, u_a: float, u_b: float) -> tuple[float, float]:
    """v_A, v_B from momentum and v_B - v_A = e (u_A - u_B)."""
    v_a = (m_a * u_a + m_b * u_b - m_b * e * (u_a - u_b)) / (m_a + m_b)
    return v_a, v_a + e * (u_a - u_b)


def _g01(g: dict) -> tuple[dict, None]:
    v_a, v_b = _after(g["m_A"], g["m_B"], g["e"], g["v_A1"], g["v_B1"])
    return {"v_A2": v_a, "v_B2": v_b}, None


def _g02(g: dict) -> tuple[dict, None]:
    v_s = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]) / (g["m_A"] + g["m_B"])
    return {"v_A2": 2 * v_s - g["v_A1"], "v_B2": 2 * v_s - g["v_B1"]}, None


def _g03(g: dict) -> tuple[dict, None]:
    rebound = g["e"] * g["v_A1"]
    lost = 0.5 * g["m_A"] * (g["v_A1"] ** 2 - rebound**2)
    assert lost == pytest.approx(0.5 * g["m_A"] * g["v_A1"] ** 2 * (1 - g["e"] ** 2))
    return {"v_A2": -rebound, "T_lost": lost}, None


def _g04(g: dict) -> tuple[dict, None]:
    v = (g["W_A"] * g["v_A1"] + g["W_B"] * g["v_B1"]) / (g["W_A"] + g["W_B"])  # g cancels
    return {"v_A2": v, "v_B2": v}, None


def _g05(g: dict) -> tuple[dict, None]:
    e = (g["v_B2"] - g["v_A2"]) / (g["v_A1"] - g["v_B1"])
    impulse_b = g["m_B"] * (g["v_B2"] - g["v_B1"])
    return {"e": e, "m_A": -impulse_b / (g["v_A2"] - g["v_A1"])}, None


def _g06(g: dict) -> tuple[dict, dict]:
    def mass(u: float) -> float:
        return g["m_A"] * u / g["v_A2"] - g["m_A"]

    e = (g["v_B2"] - g["v_A2"]) / g["v_A1"]
    return {"m_B": mass(g["v_A1"]), "e": e}, {"m_B": mass(12.0)}  # 10 m/s copied as 12


def _g07(g: dict) -> tuple[dict, dict]:
    def from_momentum(rhs: float) -> dict:
        v_b = rhs / g["m_B"]
        return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}

    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    true = from_momentum(p - g["m_A"] * g["v_A2"])
    assert p - g["m_A"] * g["v_A2"] == pytest.approx(3.36)
    return true, from_momentum(3.26)  # 2.4 + 0.96 written 3.26


def _g08(g: dict) -> tuple[dict, dict]:
    v_a = (g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B2"]) / g["m_A"]
    e = (g["v_B2"] - v_a) / g["v_A1"]
    return {"v_A2": v_a, "e": e}, {"e": (g["v_B2"] - abs(v_a)) / g["v_A1"]}  # A's sign lost


def _bullet(m: float, big_m: float, u: float) -> dict:
    v = m * u / (m + big_m)
    t_1, t_2 = 0.5 * m * u**2, 0.5 * (m + big_m) * v**2
    return {"v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _g09(g: dict) -> tuple[dict, dict]:
    return _bullet(g["m_A"], g["m_B"], g["v_A1"]), _bullet(0.2, g["m_B"], g["v_A1"])  # 20 g as 0.2 kg


def _g10(g: dict) -> tuple[dict, dict]:
    v_b = g["v_A2"] + g["e"] * (g["v_A1"] - g["v_B1"])
    m_b = g["m_A"] * (g["v_A1"] - g["v_A2"]) / v_b
    return {"v_B2": v_b, "m_B": m_b}, {"m_B": m_b / 10}  # a decimal place lost


def _g11(g: dict) -> tuple[dict, dict]:
    def swap(u_an: float, u_at: float) -> dict:
        v_an, v_bn = _after(1.0, 1.0, g["e"], u_an, g["v_B1n"])  # equal masses
        return {"v_A2n": v_an, "v_B2n": v_bn, "v_A2t": u_at, "v_B2": abs(v_bn), "v_A2": math.hypot(v_an, u_at)}

    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    slipped = swap(g["v_A1"] * s, g["v_A1"] * c)  # sin and cos swapped for A
    del slipped["v_A2n"]  # -3 either way: that line is correct, not carried
    return swap(g["v_A1"] * c, g["v_A1"] * s), slipped


def _train(g: dict, u_b: float, u_b_squared: float) -> dict:
    v = (g["m_A"] * g["v_A1"] + g["m_B"] * u_b) / (g["m_A"] + g["m_B"])
    t_1 = 0.5 * g["m_A"] * g["v_A1"] ** 2 + 0.5 * g["m_B"] * u_b_squared
    t_2 = 0.5 * (g["m_A"] + g["m_B"]) * v**2
    return {"v_A2": v, "v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _g12(g: dict) -> tuple[dict, dict]:
    true = _train(g, g["v_B1"], g["v_B1"] ** 2)
    slipped = _train(g, -g["v_B1"], 0.144)  # B's sign lost; 0.12^2 taken as 0.144
    slipped["T_lost"] = slipped["T_1"] - round(slipped["T_2"])  # 14670 - 6514, as written
    return true, slipped


def _g13(g: dict) -> tuple[dict, dict]:
    v_a, v_b = _after(g["m_A"], g["m_B"], g["e"], g["v_A1"], g["v_B1"])
    approach = g["e"] * (g["v_A1"] - g["v_B1"])
    p = 0.6  # 0.9 - 0.4 written 0.6; and v_A = v_B + 4 (restitution reversed)
    s_b = (p - g["m_A"] * approach) / (g["m_A"] + g["m_B"])
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_b + approach, "v_B2": s_b}


def _g14(g: dict) -> tuple[dict, None]:
    u_a, u_b = _after(g["m_A"], g["m_B"], g["e"], g["v_A"], -g["v_B"])
    w_b = -g["e_wall"] * u_b
    again = "yes" if w_b < u_a else "no"  # both move in -x; B behind A and faster
    return {"u_A": u_a, "u_B": u_b, "w_B": w_b, "again": again}, None


def _g15(g: dict) -> tuple[dict, dict]:
    ratio = (g["m_car"] + g["m_suv"]) / g["m_car"]
    v_true = math.sqrt(2 * g["mu_k"] * g["g"] * g["d_skid"])
    v_slip = math.sqrt(g["mu_k"] * g["g"] * g["d_skid"])  # the 1/2 dropped
    return {"V": v_true, "v_car": ratio * v_true}, {"V": v_slip, "v_car": ratio * v_slip}


NUMERIC_G: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "g01": _g01,
    "g02": _g02,
    "g03": _g03,
    "g04": _g04,
    "g05": _g05,
    "g06": _g06,
    "g07": _g07,
    "g08": _g08,
    "g09": _g09,
    "g10": _g10,
    "g11": _g11,
    "g12": _g12,
    "g13": _g13,
    "g14": _g14,
    "g15": _g15,
}


def test_every_g_case_is_worked_here() -> None:
    assert len(G_CASES) == 15
    assert {c.name[:3] for c in G_CASES} == set(NUMERIC_G)
    by_category = sorted(c.verdict.category for c in G_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in G_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_G))
def test_the_g_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_G[prefix](_given(case.verdict.problem))
    assert set(case.verdict.values) == set(true), case.name
    for name, value in case.verdict.values.items():
        if isinstance(value, str):
            assert value == true[name], f"{case.name}: {name}"
        else:
            assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    if slipped is not None:
        assert set(case.verdict.slip_values) == set(slipped), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"
