"""The xb batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xb cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of impact, Newton's law of restitution, impulse, the mass-centre velocity, energy for a fall,
a slide and a spring), with the student's slip made on purpose for the slip values. Letters (u, e,
v) are checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _formula, _given, _solve

XB_CASES = [c for c in CASES if c.name.startswith("xb")]
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) for the letters
G_US = 32.2


def _case(prefix: str):
    return next(c for c in XB_CASES if c.name.startswith(prefix))


def _pair(v_a: float, v_b: float) -> dict:
    return {"v_A2": v_a, "v_B2": v_b}


# ---- numeric problems: prefix -> givens -> (true values, slip values or None) ----


def _glancing(g: dict, e_t: float = 1.0) -> dict:
    """Equal disks, B at rest, A at 30 deg to n; e_t scales A's t-part (1: right; e: the slip)."""
    m = g["W_A"] / G_US
    a_n, a_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    v_an, v_bn = _solve(m, m, m * a_n, g["e"] * a_n)
    t = a_t * e_t
    return {
        "v_A2n": v_an,
        "v_B2n": v_bn,
        "v_A2t": t,
        "v_A2": math.hypot(v_an, t),
        "v_B2": v_bn,
        "J_n": m * v_bn,
    }


def _xb01(g: dict) -> tuple[dict, None]:
    return _glancing(g), None


def _xb09(g: dict) -> tuple[dict, dict]:
    return _glancing(g), _glancing(g, e_t=g["e"])  # slip: e applied to the t-component


def _mei_2021(g: dict, b_momentum: float | None = None) -> dict:
    w = g["v_B1t"] / math.tan(math.radians(g["alpha"]))  # B's n-part after, from the 45 deg
    impulse = g["m_B"] * w if b_momentum is None else b_momentum  # the slip writes 4(2.5) as 8
    v_a = (g["m_A"] * g["v_A1n"] - impulse) / g["m_A"]
    return {"v_B2n": w, "v_A2": v_a, "e": (w - v_a) / (g["v_A1n"] - g["v_B1n"])}


def _xb02(g: dict) -> tuple[dict, None]:
    return _mei_2021(g), None


def _xb11(g: dict) -> tuple[dict, dict]:
    return _mei_2021(g), _mei_2021(g, b_momentum=8.0)


def _backward(g: dict, u_a: float) -> tuple[float, float]:
    """v_B after from the impulse on A; e from the velocities, with A's speed before u_a."""
    impulse_on_a = g["m_A"] * (g["v_A2"] - u_a)
    v_b = g["v_B1"] - impulse_on_a / g["m_B"]
    return v_b, (v_b - g["v_A2"]) / (u_a - g["v_B1"])


def _xb05(g: dict) -> tuple[dict, None]:
    v_b, e = _backward(g, g["v_A1"])
    return {"v_B2": v_b, "e": e}, None


def _xb12(g: dict) -> tuple[dict, dict]:
    v_b, e = _backward(g, g["v_A1"])
    s_v, s_e = _backward(g, 5.0)  # slip 1: 6 m/s copied as 5
    return {"v_B2": v_b, "e": e}, {"v_B2": s_v, "e": 1 / s_e}  # slip 2: approach over separation


def _xb06(g: dict) -> tuple[dict, dict]:
    c = math.sin(math.radians(g["theta_1"]))  # A's n-part per unit speed (= its t-part at 45 deg)
    t = math.cos(math.radians(g["theta_1"]))

    def per_speed(gap: float) -> dict:
        a, b = _solve(1.0, 1.0, c, gap)
        return {"theta_A2": math.degrees(math.atan2(a, t)), "v_A2n_per_v_A1": a, "v_B2_per_v_A1": b}

    return per_speed(g["e"] * c), per_speed(-g["e"] * c)  # slip: a - b = e c


def _suitcases(g: dict, gap_sign: float, energy_mass: Callable[[float], float]) -> dict:
    """Weights in momentum (g cancels); gap_sign -1 is restitution reversed; energy_mass maps a weight to the mass used."""
    gap = gap_sign * g["e"] * g["v_A1"]
    v_a, v_b = _solve(g["W_A"], g["W_B"], g["W_A"] * g["v_A1"], gap)
    t1 = 0.5 * energy_mass(g["W_A"]) * g["v_A1"] ** 2
    t2 = 0.5 * energy_mass(g["W_A"]) * v_a**2 + 0.5 * energy_mass(g["W_B"]) * v_b**2
    return {**_pair(v_a, v_b), "T_1": t1, "T_2": t2, "T_lost": t1 - t2}


def _xb13(g: dict) -> tuple[dict, dict]:
    true = _suitcases(g, 1.0, lambda w: w / G_US)
    slipped = _suitcases(g, -1.0, lambda w: w)  # restitution reversed; weights as masses in the energy
    return true, slipped


def _xb14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    u_a, u_b = _solve(g["W_A"], g["W_B"], g["W_A"] * v_1, g["e"] * v_1)
    d = u_b**2 / (2 * g["mu_k"] * g["g"])  # 1/2 (W/g) u^2 = mu W d
    return {"v_1": v_1, "u_A": u_a, "u_B": u_b, "d_B": d}, None


def _xb15(g: dict) -> tuple[dict, dict]:
    grav, k, m_1, m_2 = g["g"], g["k"] * 1000.0, g["m_block"], g["m_pan"]
    v_1 = math.sqrt(2 * grav * g["h"])
    static = m_2 * grav / k

    def deflection(v: float) -> float:
        # 1/2 (m_1 + m_2) V^2 + (m_1 + m_2) g x = 1/2 k ((static + x)^2 - static^2)
        m = m_1 + m_2
        qa, qb, qc = k / 2, k * static - m * grav, -0.5 * m * v * v
        return (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)

    v_true = m_1 * v_1 / (m_1 + m_2)
    v_slip = v_1 * math.sqrt(m_1 / (m_1 + m_2))  # slip: kinetic energy kept in the plastic impact
    return {"v_1": v_1, "V": v_true, "x": deflection(v_true)}, {"V": v_slip, "x": deflection(v_slip)}


NUMERIC_XB: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xb01": _xb01,
    "xb02": _xb02,
    "xb05": _xb05,
    "xb06": _xb06,
    "xb09": _xb09,
    "xb11": _xb11,
    "xb12": _xb12,
    "xb13": _xb13,
    "xb14": _xb14,
    "xb15": _xb15,
}


# ---- letters: prefix -> (u, e) -> (true values, slip values or None) ----


def _xb03(u: float, e: float) -> tuple[dict, None]:
    return _pair(*_solve(1.0, 3.0, 4 * u, 4 * e * u)), None


def _xb04(u: float, e: float) -> tuple[dict, None]:
    along = u * math.cos(math.radians(30))
    v_g = along / 2
    v_b, v_a = v_g + e * v_g, v_g - e * (along - v_g)
    assert (v_a, v_b) == pytest.approx(_solve(1.0, 1.0, along, e * along))
    return {"v_B2": v_b, "v_A2n": v_a}, None


def _xb07(u: float, e: float) -> tuple[dict, dict]:
    true = _solve(5.0, 2.0, 5 * u - 4 * u, 3 * e * u)
    slipped = _solve(5.0, 2.0, 5 * u + 4 * u, 3 * e * u)  # B's momentum taken +2m(2u)
    return _pair(*true), _pair(*slipped)


def _xb08(u: float, e: float) -> tuple[dict, dict]:
    true = _solve(1.0, 2.0, 3 * u, 3 * e * u)
    slipped = _solve(2.0, 1.0, 3 * u, 3 * e * u)  # 3u = 2x + y
    return _pair(*true), _pair(*slipped)


def _xb10(v: float, _e: float) -> tuple[dict, dict]:
    e = 1 / 5
    approach = (1.5 * v + v) / e  # a + b, the speeds before added

    def before(p_before: float) -> dict:
        # 2a - 3b = p_before; a + b = approach
        b = (2 * approach - p_before) / 5
        return {"v_A1": approach - b, "v_B1": -b}

    return before(2 * (-v) + 3 * 1.5 * v), before(3.5 * v)  # slip: -2v + 9v/2 taken as 7v/2


SYMBOLIC_XB: dict[str, Callable[[float, float], tuple[dict, dict | None]]] = {
    "xb03": _xb03,
    "xb04": _xb04,
    "xb07": _xb07,
    "xb08": _xb08,
    "xb10": _xb10,
}


def test_every_xb_case_is_worked_here() -> None:
    assert len(XB_CASES) == 15
    assert {c.name[:4] for c in XB_CASES} == set(NUMERIC_XB) | set(SYMBOLIC_XB)
    by_category = sorted(c.verdict.category for c in XB_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in XB_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XB))
def test_the_xb_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XB[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XB))
def test_the_xb_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e in POINTS:
        letters = {"v": u}  # xb10's letter v, at the point u
        true, slipped = SYMBOLIC_XB[prefix](u, e)
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(slipped[name], rel=1e-9), name
