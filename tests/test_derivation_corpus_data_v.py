"""The v batch of typed derivations: every true value and every value given a slip, worked again.

The values in the verdicts of v01-v15 are worked here from the problem files' givens with plain
Python arithmetic (momentum, Newton's law of restitution, a wall, a fall and a rise), each slip
made on purpose, never from derive's output.
"""

from __future__ import annotations

import math

import pytest
from support.derivation_corpus import agree
from test_derivation_corpus_data import CASES, _formula, _given
from test_derivation_corpus_data import _thrown_down as _thrown_down_from

V_CASES = {c.name: c for c in CASES if c.name.startswith("v")}
G_FT = 32.2


def _after(m_a: float, m_b: float, e: float, u_a: float, u_b: float) -> tuple[float, float]:
    """Momentum and v_B - v_A = e (u_A - u_B), solved by hand's elimination."""
    v_a = (m_a * u_a + m_b * u_b - m_b * e * (u_a - u_b)) / (m_a + m_b)
    return v_a, v_a + e * (u_a - u_b)


def _goalie(slip: bool) -> dict:
    g = _given("openstax-cp-8-5-goalie-catches-puck")
    v = g["m_A"] * g["v_A1"] / (g["m_A"] + g["m_B"])
    t_1 = 0.5 * g["m_A"] * g["v_A1"] ** 2
    mu = g["m_A"] * g["m_B"] / (g["m_A"] + g["m_B"])
    mass_after = g["m_A"] if slip else g["m_A"] + g["m_B"]  # v10: the puck's mass only
    t_2 = 0.5 * mass_after * v**2
    if not slip:
        assert t_1 - t_2 == pytest.approx(0.5 * mu * g["v_A1"] ** 2)
    return {"v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _wall(j_sign: float = 1.0, ke_of_difference: bool = False) -> dict:
    g = _given("ocr-m2-2012-particle-hits-wall")
    m, u = g["m_A"], g["v_A1"]
    speed = g["e"] * u
    t_1, t_2 = 0.5 * m * u**2, 0.5 * m * speed**2
    lost = 0.5 * m * (u - speed) ** 2 if ke_of_difference else t_1 - t_2
    return {"v_A2": -speed, "J_n": m * (u + j_sign * speed), "T_1": t_1, "T_2": t_2, "T_lost": lost}


def _two_cars() -> dict:
    g = _given("mcasco-two-cars-no-bounce")
    m_a, m_b = g["W_A"] / G_FT, g["W_B"] / G_FT
    v = (m_a * g["v_A1"] + m_b * g["v_B1"]) / (m_a + m_b)  # perfectly plastic
    return {"v_A2": v, "v_B2": v}


def _suitcases(reversed_nlr: bool = False) -> dict:
    g = _given("hibbeler-15-58-suitcases")
    m_a, m_b, u, e = g["W_A"] / G_FT, g["W_B"] / G_FT, g["v_A1"], g["e"]
    if not reversed_nlr:
        v_a, v_b = _after(m_a, m_b, e, u, 0.0)
        return {"v_A2": v_a, "v_B2": v_b}
    v_b = (m_a * u - m_a * e * u) / (m_a + m_b)  # v_A - v_B = e u
    return {"v_A2": v_b + e * u, "v_B2": v_b}


def _glancing() -> dict:
    g = _given("mcasco-glancing-disks-us")
    m_a, m_b = g["W_A"] / G_FT, g["W_B"] / G_FT
    u_n, u_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    v_an, v_bn = _after(m_a, m_b, g["e"], u_n, 0.0)
    return {"v_A2n": v_an, "v_B2n": v_bn, "v_A2t": u_t, "v_A2": math.hypot(v_an, u_t), "v_B2": abs(v_bn)}


def _aqa_2007_oblique(u: float, e: float, swapped: bool = False) -> dict:
    """Equal balls, B at rest, A's path at 30 deg to the line of centres (v09: sin for cos)."""
    along = u * (math.sin(math.radians(30)) if swapped else math.cos(math.radians(30)))
    v_a, v_b = _after(1.0, 1.0, e, along, 0.0)
    return {"v_A2n": v_a, "v_B2": v_b}


def _ocr_2006_find_e(v_a: float | None = None) -> dict:
    g = _given("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e")
    v_a = g["v_A2"] if v_a is None else v_a
    v_b = (g["m_A"] * g["v_A1"] - g["m_A"] * v_a) / g["m_B"]
    return {"v_A2": v_a, "v_B2": v_b, "e": (v_b - v_a) / g["v_A1"]}


def _ocr_2014(b_sign: float = -1.0, t_1_slip: bool = False) -> dict:
    g = _given("ocr-m2-2014-particles-2m-3m-ke-lost")  # masses 2m, 3m: energies in units of m
    u_b = b_sign * abs(g["v_B1"])
    v_a, v_b = _after(2.0, 3.0, g["e"], g["v_A1"], -abs(g["v_B1"]))
    if b_sign > 0:  # momentum with B's +2, NEL right: 2a + 3b = 14, b - a = 2.4
        v_a = (2.0 * g["v_A1"] + 3.0 * u_b - 3.0 * g["e"] * (g["v_A1"] + abs(g["v_B1"]))) / 5.0
        v_b = v_a + g["e"] * (g["v_A1"] + abs(g["v_B1"]))
    t_1 = 0.5 * 2 * g["v_A1"] ** 2 + (3.0 if t_1_slip else 0.5 * 3) * g["v_B1"] ** 2
    t_2 = 0.5 * 2 * v_a**2 + 0.5 * 3 * v_b**2
    return {"v_A2": v_a, "v_B2": v_b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _thrown_down() -> dict:
    return _thrown_down_from(_given("chain-ocr-m2-2015-thrown-down-bounce"))


def _drop_rebound(rise_factor: float = 2.0) -> dict:
    g = _given("chain-ocr-m2-2006-drop-rebound")
    v_1 = math.sqrt(2 * g["g"] * g["h_0"])
    v_2 = math.sqrt(rise_factor * g["g"] * g["h_r"])  # v15: v^2 = g h for the rise
    return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}


def _edexcel_2004(u: float, e: float, swapped: bool = False) -> dict:
    m_p, m_q = (3.0, 2.0) if swapped else (2.0, 3.0)  # masses after the impact in CLM
    v_p = (2.0 * 5 * u - m_q * 5 * e * u) / (m_p + m_q)
    return {"v_A2": v_p, "v_B2": v_p + 5 * e * u}


def _edexcel_2011(u: float, e: float) -> dict:
    v_g = 4 * u / 4  # the centre of mass
    return {"v_A2": v_g - e * (4 * u - v_g), "v_B2": v_g - e * (0 - v_g)}


def _cie_2012_q2(u: float, _e: float, ke_of_difference: bool = False) -> dict:
    v, w = 2 * u - 4 * u / 3, -u + 4 * u  # 3m(v - 2u) = -4mu, m(w + u) = 4mu (m = 1)
    before, after = 0.5 * 3 * (2 * u) ** 2 + 0.5 * u**2, 0.5 * 3 * v**2 + 0.5 * w**2
    lost = 0.5 * 3 * (2 * u - v) ** 2 + 0.5 * (-u - w) ** 2 if ke_of_difference else before - after
    return {"v_A2": v, "v_B2": w, "T_lost": lost}


NUMERIC = {
    "v02-glancing-disks-n-t.tex": (_glancing, None),
    "v03-wall-away-positive.txt": (_wall, None),
    "v04-two-cars-slugs-left.md": (_two_cars, None),
    "v06-suitcases-nlr-reversed.txt": (_suitcases, lambda: _suitcases(reversed_nlr=True)),
    "v08-ocr-2006-find-e-copied.tex": (_ocr_2006_find_e, lambda: _ocr_2006_find_e(v_a=3.0)),
    "v10-goalie-ke-after-puck-only.md": (lambda: _goalie(False), lambda: _goalie(True)),
    "v12-wall-two-slips.txt": (_wall, lambda: _wall(j_sign=-1.0, ke_of_difference=True)),
    "v13-ocr-2014-two-slips.md": (_ocr_2014, lambda: _ocr_2014(b_sign=1.0, t_1_slip=True)),
    "v14-chain-thrown-down-energy.tex": (_thrown_down, None),
    "v15-chain-drop-rebound-2-dropped.txt": (_drop_rebound, lambda: _drop_rebound(rise_factor=1.0)),
}
SYMBOLIC = {
    "v01-edexcel-2004-q-first.md": (_edexcel_2004, None),
    "v05-edexcel-2011-relative.tex": (_edexcel_2011, None),
    "v07-cie-2012-impulse-ke-diff.md": (_cie_2012_q2, lambda u, e: _cie_2012_q2(u, e, ke_of_difference=True)),
    "v09-aqa-2007-oblique-sin-cos.txt": (
        _aqa_2007_oblique,
        lambda u, e: _aqa_2007_oblique(u, e, swapped=True),
    ),
    "v11-edexcel-2004-masses-swapped.tex": (_edexcel_2004, lambda u, e: _edexcel_2004(u, e, swapped=True)),
}


def test_every_v_case_is_worked_here() -> None:
    assert len(V_CASES) == 15
    assert set(V_CASES) == set(NUMERIC) | set(SYMBOLIC)
    for name, case in V_CASES.items():
        has_slip = case.verdict.wrong_count > 0
        worked = (NUMERIC | SYMBOLIC)[name][1] is not None
        assert has_slip == worked, name
        assert bool(case.verdict.slip_values) == has_slip, name


@pytest.mark.parametrize("name", sorted(NUMERIC))
def test_the_v_values_and_the_values_given_the_slip(name: str) -> None:
    verdict = V_CASES[name].verdict
    true, slipped = NUMERIC[name]
    agree(verdict.values, true(), name)
    if slipped is not None:
        agree(verdict.slip_values, slipped(), name)


@pytest.mark.parametrize("name", sorted(SYMBOLIC))
def test_the_v_closed_forms(name: str) -> None:
    verdict = V_CASES[name].verdict
    true, slipped = SYMBOLIC[name]
    for u, e in ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9)):
        for key, formula in verdict.values.items():
            assert _formula(str(formula), u, e) == pytest.approx(true(u, e)[key], rel=1e-9), f"{name}: {key}"
        if slipped is not None:
            for key, formula in verdict.slip_values.items():
                assert _formula(str(formula), u, e) == pytest.approx(slipped(u, e)[key], rel=1e-9), f"{name}: {key}"


def test_the_v07_loss_is_four_thirds_and_the_slip_thirty_two_thirds() -> None:
    assert _cie_2012_q2(1.0, 0.0)["T_lost"] == pytest.approx(4 / 3)
    assert _cie_2012_q2(1.0, 0.0, ke_of_difference=True)["T_lost"] == pytest.approx(32 / 3)
