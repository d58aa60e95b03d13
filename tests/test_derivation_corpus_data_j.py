"""The j batch of typed derivations: every true value and every value given a slip, worked again.

The values in the verdicts of j01-j15 are worked here from the problem files' givens with plain
Python arithmetic (momentum, Newton's law of restitution, an impulse, a wall, components along and
across the line of centres), each slip made on purpose, never from derive's output.
"""

from __future__ import annotations

import math

import pytest
from test_derivation_corpus_data import CASES, _formula, _given

J_CASES = {c.name: c for c in CASES if c.name.startswith("j")}
ALPHA, K, LAM = 0.6, 3.0, 0.2  # the letters a symbolic problem keeps, taken at a point
LETTERS = {"alpha": ALPHA, "k": K, "lam": LAM}
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))


def _after(m_a: float, m_b: float, e: float, u_a: float, u_b: float, nel: float = 1.0) -> tuple[float, float]:
    """Momentum and v_B - v_A = e (u_A - u_B) (nel = -1: the student's v_A - v_B = e (u_A - u_B))."""
    d = nel * e * (u_a - u_b)
    v_a = (m_a * u_a + m_b * u_b - m_b * d) / (m_a + m_b)
    return v_a, v_a + d


# ---- the letters (u, e, alpha, k, lam) ----


def _j01(u: float, e: float) -> dict:
    a, b = _after(1.0, 1.0, e, u * math.cos(math.radians(60)), 0.0)
    return {"v_A2n": a, "v_B2": b}


def _j02(u: float, e: float) -> dict:
    before = (u * math.cos(math.radians(30)), u * math.sin(math.radians(30)))
    v_1 = _after(1.0, 1.0, e, before[0], 0.0)[0]
    after = (v_1, before[1])
    cross = before[0] * after[1] - before[1] * after[0]
    dot = before[0] * after[0] + before[1] * after[1]
    return {"v_A2n": v_1, "deflection": math.atan2(cross, dot)}


def _j03(u: float, _e: float) -> dict:
    impulse = u  # m (u - 0), per unit m
    w = LAM * u + impulse / K  # k m (w - lam u) = m u
    return {"v_B2": w, "e": (w - 0.0) / (u - LAM * u)}


def _j05(u: float, e: float) -> dict:
    along, normal = u * math.cos(ALPHA), e * u * math.sin(ALPHA)
    return {"beta": math.atan2(normal, along)}


def _j06(u: float, e: float, across_times_e: bool = False) -> dict:
    x = _after(1.0, 1.0, e, u * math.cos(ALPHA), 0.0)[0]
    across = (e if across_times_e else 1.0) * u * math.sin(ALPHA)
    return {"v_A2n": x, "v_A2t": across, "beta_A2": math.atan2(across, x)}


def _j07(u: float, _e: float, swapped: bool = False) -> dict:
    e = 0.5  # the problem's e
    theta = math.asin(1 / 2)  # sin theta = r/2r
    along = u * (math.sin(theta) if swapped else math.cos(theta))
    across = u * (math.cos(theta) if swapped else math.sin(theta))
    p, q = _after(1.0, 1.0, e, along, 0.0)
    return {"v_A2n": p, "v_B2": q, "v_A2": math.hypot(p, across)}


def _j09(u: float, e: float, nel: float = 1.0) -> dict:
    a, b = _after(1.0, 1.0, e, u, 0.0, nel=nel)
    return {"v_A2": a, "v_B2": b}


def _j10(u: float, e: float, masses_after: tuple[float, float] = (2.0, 1.0)) -> dict:
    total = 2.0 * 4 * u + 1.0 * (-3 * u)
    approach = 4 * u + 3 * u
    m_a, m_b = masses_after
    v_a = (total - m_b * e * approach) / (m_a + m_b)
    return {"v_A2": v_a, "v_B2": v_a + e * approach}


def _j11(u: float, e: float, algebra_slip: bool = False) -> dict:
    # u = x + 2y, y = x + eu: u = 3x + 2eu (the slip: u = 3x + eu)
    x = (u - (1 if algebra_slip else 2) * e * u) / 3
    return {"v_A2": x}


def _j13(u: float, e: float, slips: bool = False) -> dict:
    v_b = u * (1 + e) / 3  # u = v_A + 2 v_B, v_B - v_A = eu
    v_a = (3 * u - 2 * u - (-2 if slips else 2) * e * u) / 3
    m_a, m_b = (6.0, 3.0) if slips else (3.0, 6.0)  # the kinetic energy after, per unit m
    before = 0.5 * 3.0 * u**2
    after = 0.5 * m_a * v_a**2 + 0.5 * m_b * v_b**2
    return {"v_A2": v_a, "v_B2": v_b, "T_lost": before - after}


SYMBOLIC = {
    "j01-aqa-2016-wall-60-a-b.md": (_j01, None),
    "j02-m4-deflection-cross-dot.tex": (_j02, None),
    "j03-edexcel-s-at-rest-impulse.txt": (_j03, None),
    "j05-fm1-cushion-components.tex": (_j05, None),
    "j06-m4-2005-e-on-perpendicular.txt": (_j06, lambda u, e: _j06(u, e, across_times_e=True)),
    "j07-mei-2022-offset-sin-cos.md": (_j07, lambda u, e: _j07(u, e, swapped=True)),
    "j09-wjec-2019-nlr-reversed.md": (_j09, lambda u, e: _j09(u, e, nel=-1.0)),
    "j10-cie-2014-nov-masses-swapped.tex": (_j10, lambda u, e: _j10(u, e, masses_after=(1.0, 2.0))),
    "j11-edexcel-2024-speed-of-p-algebra.tex": (_j11, lambda u, e: _j11(u, e, algebra_slip=True)),
    "j13-cie-2012-q1-two-slips.tex": (_j13, lambda u, e: _j13(u, e, slips=True)),
}


# ---- the numbers ----


def _j04() -> dict:
    g = _given("web2calc-car-rear-ends-car-find-mass")
    lost_by_a = g["m_A"] * (g["v_A1"] - g["v_A2"])
    m_b = lost_by_a / (g["v_B2"] - g["v_B1"])
    assert 0.5 * g["m_A"] * g["v_A1"] ** 2 == pytest.approx(60_000)
    assert 0.5 * (g["m_A"] + m_b) * g["v_A2"] ** 2 == pytest.approx(36_000)
    return {"m_B": m_b, "e": (g["v_B2"] - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}


def _j08(b_sign: float = -1.0) -> dict:
    g = _given("aqa-fm-specimen-discs-show-e-0p8")
    u_b = b_sign * abs(g["v_B1"])  # the slip: B's velocity before taken +6 in momentum
    v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * u_b - g["m_A"] * g["v_A2"]) / g["m_B"]
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}


def _j12(v_b: float | None = None, approach_sign: float = -1.0) -> dict:
    g = _given("ocr-m2-2011-spheres-find-e-and-mass")
    v_b = g["v_B2"] if v_b is None else v_b  # the slip: 2.9 copied as 2.4
    m_a = g["m_B"] * (v_b - g["v_B1"]) / (g["v_A1"] - g["v_A2"])
    approach = g["v_A1"] + approach_sign * g["v_B1"]  # the slip: 3 - 1.5
    return {"m_A": m_a, "e": (v_b - g["v_A2"]) / approach}


def _j14() -> dict:
    g = _given("chain-ocr-m2-2011-find-e-mass-then-wall")
    impulse_on_b = g["m_B"] * (g["s_B"] - (-g["v_B"]))
    m_a = impulse_on_b / (g["v_A"] - g["s_A"])
    e = (g["s_B"] - g["s_A"]) / (g["v_A"] + g["v_B"])
    w = g["I_w"] / g["m_B"] - g["s_B"]  # I_w = m_B (w + s_B), w away from the wall
    return {"e": e, "m_A": m_a, "u_B": g["s_B"], "w_B": -w, "e_wall": w / g["s_B"]}


def _j15(b_sign: float = -1.0) -> dict:
    g = _given("chain-aqa-m3-2007-collide-again")
    total = g["m_A"] * g["v_A"] + b_sign * g["m_B"] * g["v_B"]  # the slip: +0.2 x 2
    approach = g["v_A"] + g["v_B"]
    u_a = (total - g["m_B"] * g["e"] * approach) / (g["m_A"] + g["m_B"])
    u_b = u_a + g["e"] * approach
    w_b = -g["e_wall"] * u_b
    # B is nearer the wall; after its rebound they meet again if B moves back faster than A (or A toward it)
    return {"u_A": u_a, "u_B": u_b, "w_B": w_b, "again": "yes" if w_b < u_a else "no"}


NUMERIC = {
    "j04-web2calc-mass-from-momentum-change.md": (_j04, None),
    "j08-aqa-fm-find-e-b-sign.txt": (_j08, lambda: _j08(b_sign=1.0)),
    "j12-ocr-2011-find-e-mass-two-slips.txt": (_j12, lambda: _j12(v_b=2.4, approach_sign=1.0)),
    "j14-chain-ocr-2011-impulse-first.md": (_j14, None),
    "j15-chain-aqa-2007-b-sign-carried.txt": (_j15, lambda: _j15(b_sign=1.0)),
}


def test_every_j_case_is_worked_here() -> None:
    assert len(J_CASES) == 15
    assert set(J_CASES) == set(NUMERIC) | set(SYMBOLIC)
    for name, case in J_CASES.items():
        has_slip = case.verdict.wrong_count > 0
        assert has_slip == ((NUMERIC | SYMBOLIC)[name][1] is not None), name
        assert bool(case.verdict.slip_values) == has_slip, name


def test_the_j_batch_is_five_of_each_format_and_the_brief_s_categories() -> None:
    formats = sorted(c.verdict.format for c in J_CASES.values())
    assert formats == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    categories = [c.verdict.category for c in J_CASES.values()]
    assert {k: categories.count(k) for k in set(categories)} == {
        "correct": 5,
        "one_slip": 6,
        "two_slips": 2,
        "chain": 2,
    }


def _agree(recorded: dict, truth: dict, name: str) -> None:
    for key, value in recorded.items():
        assert key in truth, f"{name}: {key} is not worked here"
        if isinstance(value, str):
            assert value == truth[key], f"{name}: {key}"
        else:
            assert value == pytest.approx(truth[key], rel=2e-4, abs=2e-4), f"{name}: {key}"


@pytest.mark.parametrize("name", sorted(NUMERIC))
def test_the_j_values_and_the_values_given_the_slip(name: str) -> None:
    verdict = J_CASES[name].verdict
    true, slipped = NUMERIC[name]
    _agree(verdict.values, true(), name)
    if slipped is not None:
        _agree(verdict.slip_values, slipped(), name)


@pytest.mark.parametrize("name", sorted(SYMBOLIC))
def test_the_j_closed_forms(name: str) -> None:
    verdict = J_CASES[name].verdict
    true, slipped = SYMBOLIC[name]
    for u, e in POINTS:
        for key, formula in verdict.values.items():
            got = _formula(str(formula), u, e, LETTERS)
            assert got == pytest.approx(true(u, e)[key], rel=1e-9), f"{name}: {key}"
        if slipped is not None:
            for key, formula in verdict.slip_values.items():
                got = _formula(str(formula), u, e, LETTERS)
                assert got == pytest.approx(slipped(u, e)[key], rel=1e-9), f"{name}: {key}"


def test_the_printed_answers_the_students_were_shown() -> None:
    """The show-that results as the questions print them, at a point."""
    u, e = 1.3, 0.4
    assert _j01(u, e)["v_B2"] == pytest.approx(u * (1 + e) / 4)
    assert math.tan(_j02(u, e)["deflection"]) == pytest.approx(math.sqrt(3) * (1 + e) / (5 - 3 * e))
    assert _j03(u, e)["e"] == pytest.approx((1 + K * LAM) / (K * (1 - LAM)))
    assert math.tan(_j05(u, e)["beta"]) == pytest.approx(e * math.tan(ALPHA))
    assert (1 - e) * math.tan(_j06(u, e)["beta_A2"]) == pytest.approx(2 * math.tan(ALPHA))
    assert _j07(u, e)["v_B2"] == pytest.approx(3 * math.sqrt(3) / 8 * u)
    assert _j13(u, e)["T_lost"] == pytest.approx(u * u * (1 - e * e))
    assert _j08()["v_B2"] == pytest.approx(8.4) and _j08()["e"] == pytest.approx(0.8)
    assert _j12() == pytest.approx({"m_A": 0.88, "e": 0.2})
