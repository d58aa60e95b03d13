"""The k batch of typed derivations: every true value and every value given a slip, worked again.

The values in the verdicts of k01-k15 are worked here from the problem files' givens with plain
Python arithmetic (momentum, Newton's law of restitution, a wall, a fall, a rise and a skid),
each slip made on purpose, never from derive's output.
"""

from __future__ import annotations

import math

import pytest
from support.derivation_corpus import agree
from test_derivation_corpus_data import CASES, _direct, _formula, _given

K_CASES = {c.name: c for c in CASES if c.name.startswith("k")}
G_FT = 32.2


def _train_cars(b_sign: float = -1.0, ke_first_car_only: bool = False) -> dict:
    """Coupled cars (e = 0); k13 takes B's velocity as +0.120 and KE_f with the first car's mass."""
    g = _given("openstax-cp-8-train-cars-couple")
    m_a, m_b = g["m_A"], g["m_B"]
    u_b = b_sign * abs(g["v_B1"])
    v = (m_a * g["v_A1"] + m_b * u_b) / (m_a + m_b)
    t_1 = 0.5 * m_a * g["v_A1"] ** 2 + 0.5 * m_b * g["v_B1"] ** 2
    t_2 = 0.5 * (m_a if ke_first_car_only else m_a + m_b) * v**2
    return {"v_A2": v, "v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _railroad() -> dict:
    g = _given("beer-johnston-13-13-railroad-cars-find-e")
    impulse = g["m_B"] * (g["v_B2"] - g["v_B1"])  # impulse first, on B
    v_a = g["v_A1"] - impulse / g["m_A"]
    return {"v_A2": v_a, "e": (g["v_B2"] - v_a) / (g["v_A1"] - g["v_B1"])}


def _two_cars_left_positive() -> dict:
    g = _given("mcasco-two-cars-no-bounce")
    m_a, m_b = g["W_A"] / G_FT, g["W_B"] / G_FT
    left = (m_a * -g["v_A1"] + m_b * -g["v_B1"]) / (m_a + m_b)  # left as positive
    return {"v_A2": -left, "v_B2": -left}


def _ocr_wall() -> dict:
    g = _given("ocr-m2-2012-particle-hits-wall")
    m, u = g["m_A"], g["v_A1"]
    speed = g["e"] * u
    t_1, t_2 = 0.5 * m * u**2, 0.5 * m * speed**2
    return {"v_A2": -speed, "J_n": m * (u + speed), "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _edexcel_wall(ke_of_difference: bool = False) -> dict:
    g = _given("edexcel-m2-ball-rebounds-from-wall")
    m, u = g["m_A"], g["v_A1"]
    speed = g["e"] * u
    lost = 0.5 * m * (u - speed) ** 2 if ke_of_difference else 0.5 * m * (u**2 - speed**2)
    return {"v_A2": -speed, "T_lost": lost}


def _elastic_at_rest(problem: str, top_mass_b: bool = False) -> dict:
    """The textbook formulas for a target at rest (k06: 2 m_B on top of B's)."""
    g = _given(problem)
    m_a, m_b, u = g["m_A"], g["m_B"], g["v_A1"]
    v_a, v_b = _direct(m_a, m_b, g["e"], u, 0.0)
    assert v_a == pytest.approx((m_a - m_b) / (m_a + m_b) * u)
    assert v_b == pytest.approx(2 * m_a / (m_a + m_b) * u)
    if top_mass_b:
        v_b = 2 * m_b / (m_a + m_b) * u
    return {"v_A2": v_a, "v_B2": v_b}


def _puck_goalie(decimal_slip: bool = False) -> dict:
    values = _elastic_at_rest("openstax-cp-8-30-puck-bounces-off-goalie")
    if decimal_slip:
        values["v_B2"] /= 10
    return values


def _satellites(slips: bool = False) -> dict:
    g = _given("openstax-cp-8-satellites-elastic")
    values = _elastic_at_rest("openstax-cp-8-satellites-elastic")
    if slips:  # masses the other way round; 8/11.5 divided as 0.6596
        values["v_A2"] = -values["v_A2"]
        values["v_B2"] = 0.6596 * g["v_A1"]
    return values


def _ocr_2006_meet(b_sign: float = -1.0) -> dict:
    g = _given("ocr-m2-2006-spheres-meet-at-5-ke-lost")
    u_b = b_sign * abs(g["v_B1"])
    momentum = g["m_A"] * g["v_A1"] + g["m_B"] * u_b
    approach = g["v_A1"] - g["v_B1"]  # NLR is right in k08
    v_a = (momentum - g["m_B"] * g["e"] * approach) / (g["m_A"] + g["m_B"])
    v_b = v_a + g["e"] * approach
    t_1 = 0.5 * g["m_A"] * g["v_A1"] ** 2 + 0.5 * g["m_B"] * g["v_B1"] ** 2
    t_2 = 0.5 * g["m_A"] * v_a**2 + 0.5 * g["m_B"] * v_b**2
    return {"v_A2": v_a, "v_B2": v_b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _find_mass(sign_lost: bool = False) -> dict:
    g = _given("web2calc-car-rear-ends-car-find-mass")
    before, after = g["m_A"] * g["v_A1"], g["m_A"] * g["v_A2"]
    m_b = (before + after if sign_lost else before - after) / g["v_A2"]
    return {"m_B": m_b, "e": (g["v_B2"] - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}


def _car_suv() -> dict:
    g = _given("chain-car-rear-ends-suv-skid")
    v = math.sqrt(2 * g["mu_k"] * g["g"] * g["d_skid"])  # (1/2) M V^2 = mu M g d
    return {"V": v, "v_car": (g["m_car"] + g["m_suv"]) * v / g["m_car"]}


def _rebounds_to_start(impulse_sign_lost: bool = False) -> dict:
    g = _given("chain-ocr-m2-2007-rebounds-to-start")
    v_1 = math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"])
    v_2 = math.sqrt(2 * g["g"] * g["h_0"])
    j = g["m"] * (v_1 - v_2 if impulse_sign_lost else v_1 + v_2)
    return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": j}


def _edexcel_2024(u: float, e: float) -> dict:
    """m at u hits 2m at rest (m = 1): momentum and w + v = eu, v P's speed backwards."""
    v = u * (2 * e - 1) / 3
    w = e * u - v
    assert u == pytest.approx(-v + 2 * w)
    return {"v_A2": -v}


def _aqa_2014(u: float, _e: float, reversed_nlr: bool = False) -> dict:
    """2m at 2u hits m at rest, e = 2/3 (the problem's, whatever e the loop passes)."""
    e = 2 / 3
    if not reversed_nlr:
        v_a, v_b = _direct(2.0, 1.0, e, 2 * u, 0.0)
        return {"v_A2": v_a, "v_B2": v_b}
    v_a = (4 * u + e * 2 * u) / 3  # 4u = 2v_A + v_B with v_A - v_B = 4u/3
    return {"v_A2": v_a, "v_B2": v_a - e * 2 * u}


SUPERBALLS = "uoguelph-8-34-superballs-grams"
NUMERIC = {
    "k01-train-cars-wolfram-paste.md": (_train_cars, None),
    "k02-railroad-find-e-impulse.txt": (_railroad, None),
    "k04-two-cars-left-positive-slugs.txt": (_two_cars_left_positive, None),
    "k05-ocr-2012-wall-away-positive.md": (_ocr_wall, None),
    "k06-superballs-formula-masses-swapped.txt": (
        lambda: _elastic_at_rest(SUPERBALLS),
        lambda: _elastic_at_rest(SUPERBALLS, top_mass_b=True),
    ),
    "k07-wall-ke-half-m-u-minus-v.md": (_edexcel_wall, lambda: _edexcel_wall(ke_of_difference=True)),
    "k08-ocr-2006-meet-b-sign.tex": (_ocr_2006_meet, lambda: _ocr_2006_meet(b_sign=1.0)),
    "k09-puck-goalie-decimal-slip.md": (_puck_goalie, lambda: _puck_goalie(decimal_slip=True)),
    "k10-web2calc-mass-sign-lost.txt": (_find_mass, lambda: _find_mass(sign_lost=True)),
    "k12-satellites-two-slips.md": (_satellites, lambda: _satellites(slips=True)),
    "k13-train-cars-two-slips.tex": (_train_cars, lambda: _train_cars(b_sign=1.0, ke_first_car_only=True)),
    "k14-chain-car-suv-work-energy.tex": (_car_suv, None),
    "k15-chain-rebounds-to-start-impulse-sign.txt": (
        _rebounds_to_start,
        lambda: _rebounds_to_start(impulse_sign_lost=True),
    ),
}
SYMBOLIC = {
    "k03-edexcel-2024-speed-of-p.tex": (_edexcel_2024, None),
    "k11-aqa-2014-nlr-wrong-way.tex": (_aqa_2014, lambda u, e: _aqa_2014(u, e, reversed_nlr=True)),
}


def test_every_k_case_is_worked_here() -> None:
    assert len(K_CASES) == 15
    assert set(K_CASES) == set(NUMERIC) | set(SYMBOLIC)
    for name, case in K_CASES.items():
        has_slip = case.verdict.wrong_count > 0
        worked = (NUMERIC | SYMBOLIC)[name][1] is not None
        assert has_slip == worked, name
        assert bool(case.verdict.slip_values) == has_slip, name


@pytest.mark.parametrize("name", sorted(NUMERIC))
def test_the_k_values_and_the_values_given_the_slip(name: str) -> None:
    verdict = K_CASES[name].verdict
    true, slipped = NUMERIC[name]
    agree(verdict.values, true(), name)
    if slipped is not None:
        agree(verdict.slip_values, slipped(), name)


@pytest.mark.parametrize("name", sorted(SYMBOLIC))
def test_the_k_closed_forms(name: str) -> None:
    verdict = K_CASES[name].verdict
    true, slipped = SYMBOLIC[name]
    for u, e in ((1.0, 0.6), (2.0, 0.75), (1.5, 0.9)):
        for key, formula in verdict.values.items():
            assert _formula(str(formula), u, e) == pytest.approx(true(u, e)[key], rel=1e-9), f"{name}: {key}"
        if slipped is not None:
            for key, formula in verdict.slip_values.items():
                assert _formula(str(formula), u, e) == pytest.approx(slipped(u, e)[key], rel=1e-9), f"{name}: {key}"


def test_the_k_slips_give_what_a_teacher_sees() -> None:
    """Hand checks: k08's slip gains energy, k10's slip quadruples the mass, k15's J shrinks."""
    assert _ocr_2006_meet(b_sign=1.0)["T_lost"] == pytest.approx(-64 / 3)
    assert _find_mass(sign_lost=True)["m_B"] == pytest.approx(4 * _find_mass()["m_B"])
    assert _rebounds_to_start()["J"] == pytest.approx(12.6)
    assert _rebounds_to_start(impulse_sign_lost=True)["J"] == pytest.approx(1.4)
