"""The y batch of typed derivations (a held-out batch written 2026-11-28, second session).

Every true value (`values`) and every value a carried line holds (`slip_values`) of the
fifteen y cases is worked again here from the problem file's givens with plain Python
arithmetic, each slip made on purpose, never from derive's output.
"""

from __future__ import annotations

import math

import pytest
from test_derivation_corpus_data import CASES, _direct, _energy, _formula, _given


def _elastic_at_rest(g: dict) -> dict:
    """Target at rest, e = 1: the textbook formulas v1f = (m1 - m2)/(m1 + m2) v1i, v2f = 2 m1/(m1 + m2) v1i."""
    m1, m2, v = g["m_A"], g["m_B"], g["v_A1"]
    return {"v_A2": (m1 - m2) / (m1 + m2) * v, "v_B2": 2 * m1 / (m1 + m2) * v}


def _y01(g: dict) -> tuple[dict, dict]:
    return _elastic_at_rest(g), {}


def _y02(g: dict) -> tuple[dict, dict]:
    normal = g["v_A1"] * math.cos(math.radians(45))
    return {"v_A1n": normal, "J_n": g["m_A"] * (normal - (-normal))}, {}


def _y03(g: dict) -> tuple[dict, dict]:
    a_n, a_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    v_an, v_bn = g["v_B1n"], a_n  # equal masses, e = 1: the normal components swap
    assert a_n + g["v_B1n"] == pytest.approx(v_an + v_bn)  # momentum
    assert v_bn - v_an == pytest.approx(a_n - g["v_B1n"])  # restitution, e = 1
    return {"v_A2n": v_an, "v_B2n": v_bn, "v_A2t": a_t, "v_A2": math.hypot(v_an, a_t), "v_B2": abs(v_bn)}, {}


def _y04(g: dict) -> tuple[dict, dict]:
    v_b = g["v_A2"] + (g["v_A1"] - g["v_B1"])  # the relative velocity reverses
    return {"v_B2": v_b, "m_B": g["m_A"] * (g["v_A1"] - g["v_A2"]) / v_b}, {}


def _y05(g: dict) -> tuple[dict, dict]:
    m_a, m_b = 1000 * g["m_A"], 1000 * g["m_B"]  # Mg to kg
    impulse = m_b * (g["v_B2"] - g["v_B1"])
    v_a = g["v_A1"] - impulse / m_a
    return {"v_A2": v_a, "v_B2": g["v_B2"], "e": (g["v_B2"] - v_a) / (g["v_A1"] - g["v_B1"])}, {}


def _y06(g: dict) -> tuple[dict, dict]:
    true = _elastic_at_rest(g)
    slipped = _elastic_at_rest(g | {"m_B": 7050.0})  # 7.50 x 10^3 copied as 7.05 x 10^3
    return true, slipped


def _y07(g: dict) -> tuple[dict, dict]:
    total = g["m_A"] + g["m_B"]

    def worked(u_b: float) -> dict:
        v = (g["m_A"] * g["v_A1"] + g["m_B"] * u_b) / total
        t1, t2 = _energy(g["m_A"], g["m_B"], g["v_A1"], g["v_B1"]), _energy(total, 0, v)
        return {"v_A2": v, "v_B2": v, "T_1": t1, "T_2": t2, "T_lost": t1 - t2}

    return worked(g["v_B1"]), worked(-g["v_B1"])  # the slip: car 2's momentum added


def _y08(g: dict) -> tuple[dict, dict]:
    true = _elastic_at_rest(g)
    v1f = (g["m_B"] - g["m_A"]) / (g["m_A"] + g["m_B"]) * g["v_A1"]  # m1 and m2 exchanged
    return true, {"v_A2": v1f, "v_B2": g["v_A1"] + v1f}


def _y09(g: dict) -> tuple[dict, dict]:
    a_n, a_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    v_bn = (a_n + g["e"] * a_n) / 2  # equal masses: adding momentum and restitution
    v_an = a_n - v_bn
    true = {
        "v_A2n": v_an,
        "v_B2n": v_bn,
        "v_A2t": a_t,
        "v_A2": math.hypot(v_an, a_t),
        "v_B2": v_bn,
        "J_n": g["W_B"] / 32.2 * v_bn,
    }
    return true, {"J_n": g["W_B"] * v_bn}  # the weight used as the mass


def _y10(g: dict) -> tuple[dict, dict]:
    lost = _energy(g["m_A"], 0, g["v_A1"]) - _energy(g["m_A"], 0, g["v_A2"])
    slipped = 0.5 * g["m_A"] * (g["v_A1"] - abs(g["v_A2"])) ** 2
    return {"e": -g["v_A2"] / g["v_A1"], "T_lost": lost}, {"T_lost": slipped}


def _y12(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u = g["W_A"] / 32.2, g["W_B"] / 32.2, g["v_A1"]
    v_a, v_b = _direct(m_a, m_b, g["e"], u, 0.0)
    t1, t2 = _energy(m_a, m_b, u, 0.0), _energy(m_a, m_b, v_a, v_b)
    true = {"v_A2": v_a, "v_B2": v_b, "T_1": t1, "T_2": t2, "T_lost": t1 - t2}
    # slip 1: W_A u = W_B v_A + W_A v_B with v_B = v_A + e u; slip 2: the weights as masses in the energies
    s_a = (g["W_A"] * u - g["W_A"] * g["e"] * u) / (g["W_A"] + g["W_B"])
    s_b = s_a + g["e"] * u
    s1, s2 = _energy(g["W_A"], g["W_B"], u, 0.0), _energy(g["W_A"], g["W_B"], s_a, s_b)
    return true, {"v_A2": s_a, "v_B2": s_b, "T_1": s1, "T_2": s2, "T_lost": s1 - s2}


def _y13(g: dict) -> tuple[dict, dict]:
    total = g["m_A"] + g["m_B"]
    v = g["m_A"] * g["v_A1"] / total
    t1, t2 = _energy(g["m_A"], 0, g["v_A1"]), _energy(total, 0, v)
    true = {"v_A2": v, "v_B2": v, "T_1": t1, "T_2": t2, "T_lost": t1 - t2}
    s = 10 * g["m_A"] * g["v_A1"] / total  # 0.150 x 35.0 worked as 52.5
    slipped = {"v_B2": s, "T_2": _energy(total, 0, s), "T_lost": 0.5 * g["m_A"] * (g["v_A1"] - s) ** 2}
    return true, slipped


def _y14(g: dict) -> tuple[dict, dict]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    mass, k = g["m_block"] + g["m_pan"], 1000 * g["k"]  # kN/m to N/m
    v = g["m_block"] * v_1 / mass
    y_0 = g["m_block"] * g["g"] / k  # the new equilibrium is y_0 below the pan's position at impact
    amplitude = math.sqrt(y_0**2 + v**2 * mass / k)
    return {"v_1": v_1, "V": v, "x": y_0 + amplitude}, {}


def _y15(g: dict) -> tuple[dict, dict]:
    mass = g["m_bullet"] + g["m_block"]
    v = g["m_bullet"] * g["v_0"] / mass
    t = 0.5 * mass * v**2
    slipped = mass * v**2  # the 1/2 dropped
    true = {"V": v, "T_after": t, "h_2": t / (mass * g["g"])}
    return true, {"T_after": slipped, "h_2": slipped / (mass * g["g"])}


NUMERIC_Y = {
    "y01-openstax-goalie-bounce-elastic-formulas.md": _y01,
    "y02-giancoli-tennis-wall-impulse-components.tex": _y02,
    "y03-gramoll-equal-balls-swap-normal.txt": _y03,
    "y04-young-freedman-pucks-relative-velocity.md": _y04,
    "y05-beer-johnston-railcars-impulse-first.tex": _y05,
    "y06-openstax-satellites-mass-copied.md": _y06,
    "y07-openstax-train-cars-couple-sign.txt": _y07,
    "y08-guelph-superballs-formula-masses-swapped.tex": _y08,
    "y09-glancing-disks-impulse-weight.md": _y09,
    "y10-openstax-cushion-find-e-half-m-du-squared.txt": _y10,
    "y12-hibbeler-suitcases-two-slips.md": _y12,
    "y13-openstax-goalie-catches-two-slips.txt": _y13,
    "y14-chain-spring-pan-shm-amplitude.tex": _y14,
    "y15-chain-bullet-pendulum-half-dropped.txt": _y15,
}


def _y11(u: float) -> tuple[dict, dict]:
    """2m at 2u hits m at rest, e = 2/3 (the problem file's); the slip: v_A - v_B = e(2u)."""
    e = 2 / 3
    v_a = (4 * u - e * 2 * u) / 3  # 4u = 2 v_A + (v_A + 2eu)
    s_a = (4 * u + e * 2 * u) / 3  # 4u = 2 v_A + (v_A - 2eu)
    return {"v_A2": v_a, "v_B2": v_a + e * 2 * u}, {"v_A2": s_a, "v_B2": s_a - e * 2 * u}


SYMBOLIC_Y = {"y11-aqa-2014-symbolic-cor-upside-down.tex": _y11}

Y_CASES = [c for c in CASES if c.name.startswith("y") and c.name[1:3].isdigit()]


def test_the_y_batch_is_fifteen_and_every_case_is_worked_here() -> None:
    assert len(Y_CASES) == 15
    assert {c.name for c in Y_CASES} == set(NUMERIC_Y) | set(SYMBOLIC_Y)
    formats = sorted(c.verdict.format for c in Y_CASES)
    assert formats == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    categories = sorted(c.verdict.category for c in Y_CASES)
    assert categories == sorted(["correct"] * 5 + ["one_slip"] * 6 + ["two_slips"] * 2 + ["chain"] * 2)


@pytest.mark.parametrize("name", sorted(NUMERIC_Y))
def test_the_y_values_worked_from_the_givens(name: str) -> None:
    case = next(c for c in Y_CASES if c.name == name)
    true, slipped = NUMERIC_Y[name](_given(case.verdict.problem))
    for key, value in case.verdict.values.items():
        assert key in true, f"{name}: {key} is not worked here"
        assert value == pytest.approx(true[key], rel=2e-4, abs=2e-4), f"{name}: {key}"
    assert set(case.verdict.slip_values) <= set(slipped), name
    assert bool(case.verdict.slip_values) == bool(case.verdict.slips), name
    for key, value in case.verdict.slip_values.items():
        assert value == pytest.approx(slipped[key], rel=2e-4, abs=2e-4), f"{name}: {key}"


@pytest.mark.parametrize("name", sorted(SYMBOLIC_Y))
def test_the_y_closed_forms_at_three_points(name: str) -> None:
    case = next(c for c in Y_CASES if c.name == name)
    for u in (1.0, 2.0, 1.5):
        true, slipped = SYMBOLIC_Y[name](u)
        for key, formula in case.verdict.values.items():
            assert _formula(str(formula), u, 0.0) == pytest.approx(true[key], rel=1e-9), f"{name}: {key}"
        for key, formula in case.verdict.slip_values.items():
            assert _formula(str(formula), u, 0.0) == pytest.approx(slipped[key], rel=1e-9), f"{name}: {key}"
    assert case.verdict.slip_values


def test_the_y_slips_carry_as_the_student_wrote_them() -> None:
    """Spot checks of the student's own rounded figures against the carried values."""
    y07 = _y07(_given("openstax-cp-8-train-cars-couple"))[1]
    assert round(y07["v_A2"], 3) == 0.224
    assert round(0.5 * 260000 * 0.224**2) == 6523  # KE_f from the rounded v'
    y15 = _y15(_given("chain-msu-bullet-block-swings"))[1]
    assert round(4.02 * 1.49**2, 2) == 8.92 and round(8.92 / 39.44, 3) == 0.226
    assert round(y15["h_2"], 3) == 0.227  # unrounded: within the figures carried
