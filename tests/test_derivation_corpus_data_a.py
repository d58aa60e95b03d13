"""The a batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the a cases (a01-a15) in
tests/data/derivations/verdicts.toml is worked again here from the problem file's givens with
plain Python arithmetic (momentum, Newton's law of restitution, a wall, a skid to rest), each
slip made on purpose for the slip values. Letters (u, e, k, lambda, alpha) are checked at a few
points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math

import pytest
from support.derivation_corpus import agree
from test_derivation_corpus_data import CASES, _formula, _given, _solve

A_CASES = {c.name: c for c in CASES if c.name.startswith("a")}
POINTS = ((1.0, 0.5), (2.0, 0.3), (1.5, 0.9))  # (u, e) where e is a letter
K, LAM, ALPHA = 2.5, 0.3, 0.7  # letters of the symbolic problems (alpha in radians)
G_FT = 32.2


# ---- symbolic problems: (u, e) -> values, and the slipped values ----


def _a01(u: float, e: float) -> dict:  # equal balls, A's path at 60 deg to the line of centres
    p, q = _solve(1.0, 1.0, u * math.cos(math.radians(60)), e * u * math.cos(math.radians(60)))
    return {"v_A2n": p, "v_B2": q}


def _a02(u: float, _e: float) -> dict:  # S (m) at u stopped by T (km) moving at lam u
    w = (u + K * LAM * u) / K  # momentum with S at rest after
    return {"v_B2": w, "e": w / (u - LAM * u)}


def _a03(u: float, e: float) -> dict:  # the angle A turns through, line of centres at 30 deg
    along, across = u * math.cos(math.radians(30)), u * math.sin(math.radians(30))
    v_1 = _solve(1.0, 1.0, along, e * along)[0]
    return {"v_A2n": v_1, "deflection": math.atan2(across, v_1) - math.radians(30)}


def _a04(u: float, _e: float) -> dict:  # A's path one radius from B's centre: 30 deg; e = 1/2
    theta = math.asin(1 / 2)
    a, b = _solve(1.0, 1.0, u * math.cos(theta), 0.5 * u * math.cos(theta))
    return {"v_A2n": a, "v_B2": b, "v_A2": math.hypot(a, u * math.sin(theta))}


def _a09(u: float, e: float, reversed_nel: bool = False) -> dict:  # P at rest, Q at alpha
    along = u * math.cos(ALPHA)
    x, y = _solve(1.0, 1.0, along, (-e if reversed_nel else e) * along)  # x - y = e along when reversed
    return {"v_A2t": u * math.sin(ALPHA), "v_A2n": x, "v_B2": y, "beta_A2": math.atan2(u * math.sin(ALPHA), x)}


def _a10(u: float, e: float, swapped: bool = False) -> dict:  # P (m) at u hits Q (2m) at rest
    m_p, m_q = (2.0, 1.0) if swapped else (1.0, 2.0)
    return {"v_A2": _solve(m_p, m_q, (2.0 if swapped else 1.0) * u, e * u)[0]}


def _a11(u: float, _e: float, b_plus: bool = False) -> dict:  # A (2m) and B (m) opposite, each at alpha
    e = _given("ocr-m3-2012-january-q2-opposite-directions-each-at-alpha")["e"]
    c, s = math.cos(ALPHA), math.sin(ALPHA)
    p = 2 * u * c + (1.0 if b_plus else -1.0) * u * c
    a, b = _solve(2.0, 1.0, p, e * (u * c + u * c))
    return {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, u * s)}


SYMBOLIC = {
    "a01-aqa-2016-wall-p-q.md": (_a01, None),
    "a02-edexcel-s-at-rest-w.tex": (_a02, None),
    "a03-m4-deflection-tan-difference.txt": (_a03, None),
    "a04-mei-2022-offset-ij.md": (_a04, None),
    "a09-m4-2005-q-p-nel-backwards.txt": (_a09, lambda u, e: _a09(u, e, reversed_nel=True)),
    "a10-edexcel-2024-reverses-masses.md": (_a10, lambda u, e: _a10(u, e, swapped=True)),
    "a11-ocr-m3-2012-alpha-both-plus.tex": (_a11, lambda u, e: _a11(u, e, b_plus=True)),
}
LETTERS = {"k": K, "lam": LAM, "alpha": ALPHA}


# ---- numeric problems: () -> values, and the slipped values ----


def _a05() -> dict:  # cos^2 + e^2 sin^2 = 3/5 at a wall
    e = _given("edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke")["e"]
    tan2 = (1 - 3 / 5) / (3 / 5 - e**2)  # 1 + e^2 t^2 = (3/5)(1 + t^2)
    return {"alpha": math.degrees(math.atan(math.sqrt(tan2)))}


def _a06(sign_lost: bool = False) -> dict:
    g = _given("beer-johnston-13-13-railroad-cars-find-e")
    rhs = g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B2"]  # 20 v'A = 10 - 10.5
    v_a = (-rhs if sign_lost else rhs) / g["m_A"]
    return {"v_A2": v_a, "e": (g["v_B2"] - v_a) / (g["v_A1"] - g["v_B1"])}


def _a07(b_plus: bool = False) -> dict:  # n at 20 deg from x; A 25 deg and B 100 deg from n
    g = _given("fisicalab-example-7-normal-at-20deg")
    c, s = (lambda d: math.cos(math.radians(d))), (lambda d: math.sin(math.radians(d)))
    a_n, a_t = g["v_A1"] * c(25), g["v_A1"] * s(25)
    b_n, b_t = g["v_B1"] * c(100), g["v_B1"] * s(100)
    b_n = abs(b_n) if b_plus else b_n
    v_an, v_bn = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, g["e"] * (a_n - b_n))
    return {
        "v_A2n": v_an,
        "v_B2n": v_bn,
        "v_A2": math.hypot(v_an, a_t),
        "v_B2": math.hypot(v_bn, b_t),
        "psi_A2": g["phi_n"] + math.degrees(math.atan2(a_t, v_an)),
        "psi_B2": g["phi_n"] + math.degrees(math.atan2(b_t, v_bn)),
    }


def _a08(energy: bool = False) -> dict:  # the cars lock: momentum (or, the slip, energy) gives the mass
    g = _given("web2calc-car-rear-ends-car-find-mass")
    if energy:
        return {"m_B": g["m_A"] * g["v_A1"] ** 2 / g["v_A2"] ** 2 - g["m_A"]}
    return {"m_B": g["m_A"] * (g["v_A1"] - g["v_A2"]) / g["v_A2"], "e": (g["v_B2"] - g["v_A2"]) / g["v_A1"]}


def _a12(slips: bool = False) -> dict:  # slugs; the slips: B's +6, and 2306.7 added as 2206.7
    g = _given("mcasco-two-cars-no-bounce")
    m_a, m_b = g["W_A"] / G_FT, g["W_B"] / G_FT
    if slips:
        m_a, m_b = round(m_a, 1), round(m_b, 1)  # the student's 139.8 and 93.2
    u_b = abs(g["v_B1"]) if slips else g["v_B1"]
    v = (m_a * g["v_A1"] + m_b * u_b) / (m_a + m_b)
    t_1 = 0.5 * m_a * g["v_A1"] ** 2 + 0.5 * m_b * g["v_B1"] ** 2 - (100.0 if slips else 0.0)
    t_2 = 0.5 * (m_a + m_b) * v**2
    return {"v_A2": v, "v_B2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


def _a13(slips: bool = False) -> dict:  # B leaves at 45 deg; the slips: 12 - 10 = 1, B's speed in NEL
    g = _given("ocr-mei-fmm-2021-b-at-45deg-find-e")
    w = g["v_B1t"] / math.tan(math.radians(45))
    v = (g["m_A"] * g["v_A1n"] - g["m_B"] * w) / g["m_A"]
    if slips:
        v = 1.0 / g["m_A"]
        return {"v_A2": v, "e": (math.hypot(w, g["v_B1t"]) - v) / g["v_A1n"]}
    return {"v_B2n": w, "v_A2": v, "e": (w - v) / g["v_A1n"]}


def _a14() -> dict:  # A (? kg) at 3 meets B (0.2 kg) at 1.5; then B against the wall
    g = _given("chain-ocr-m2-2011-find-e-mass-then-wall")
    m_a = g["m_B"] * (g["s_B"] + g["v_B"]) / (g["v_A"] - g["s_A"])
    w = g["I_w"] / g["m_B"] - g["s_B"]  # I = m_B (w + s_B), away from the wall positive
    e = (g["s_B"] - g["s_A"]) / (g["v_A"] + g["v_B"])
    return {"e": e, "m_A": m_a, "u_B": g["s_B"], "w_B": -w, "e_wall": w / g["s_B"]}


def _a15(half_lost: bool = False) -> dict:  # the skid gives V, momentum gives the car's speed
    g = _given("chain-car-rear-ends-suv-skid")
    v = math.sqrt((1.0 if half_lost else 2.0) * g["mu_k"] * g["g"] * g["d_skid"])
    return {"V": v, "v_car": v * (g["m_car"] + g["m_suv"]) / g["m_car"]}


NUMERIC = {
    "a05-m4-2018-tan-squared.tex": (_a05, None),
    "a06-railroad-cars-primes-sign-lost.txt": (_a06, lambda: _a06(sign_lost=True)),
    "a07-fisicalab-n-t-table.md": (_a07, lambda: _a07(b_plus=True)),
    "a08-web2calc-ke-conserved.tex": (_a08, lambda: _a08(energy=True)),
    "a12-two-cars-slugs-two-slips.txt": (_a12, lambda: _a12(slips=True)),
    "a13-mei-2021-vectors-two-slips.md": (_a13, lambda: _a13(slips=True)),
    "a14-chain-ocr-2011-enumerate.tex": (_a14, None),
    "a15-chain-suv-skid-half-lost.txt": (_a15, lambda: _a15(half_lost=True)),
}


def test_every_a_case_is_worked_here() -> None:
    assert len(A_CASES) == 15
    assert set(A_CASES) == set(NUMERIC) | set(SYMBOLIC)
    for name, case in A_CASES.items():
        has_slip = case.verdict.wrong_count > 0
        assert has_slip == ((NUMERIC | SYMBOLIC)[name][1] is not None), name
        assert bool(case.verdict.slip_values) == has_slip, name


@pytest.mark.parametrize("name", sorted(NUMERIC))
def test_the_a_values_and_the_values_given_the_slip(name: str) -> None:
    verdict = A_CASES[name].verdict
    true, slipped = NUMERIC[name]
    agree(verdict.values, true(), name)
    if slipped is not None:
        agree(verdict.slip_values, slipped(), name)


@pytest.mark.parametrize("name", sorted(SYMBOLIC))
def test_the_a_closed_forms(name: str) -> None:
    verdict = A_CASES[name].verdict
    true, slipped = SYMBOLIC[name]
    for u, e in POINTS:
        for key, formula in verdict.values.items():
            assert _formula(str(formula), u, e, LETTERS) == pytest.approx(true(u, e)[key], abs=1e-12, rel=1e-9), key
        if slipped is not None:
            for key, formula in verdict.slip_values.items():
                got = _formula(str(formula), u, e, LETTERS)
                assert got == pytest.approx(slipped(u, e)[key], abs=1e-12, rel=1e-9), key


def test_the_a_batch_shape() -> None:
    by_category = [c.verdict.category for c in A_CASES.values()]
    assert {k: by_category.count(k) for k in set(by_category)} == {
        "correct": 5,
        "one_slip": 6,
        "two_slips": 2,
        "chain": 2,
    }
    formats = [c.verdict.format for c in A_CASES.values()]
    assert formats.count("md") == formats.count("tex") == formats.count("txt") == 5
