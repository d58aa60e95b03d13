"""The `x` batch of typed derivations (a held-out batch written 2026-11-28, second session).

Every true value its verdicts record (`values`) and every value the carried lines hold given
the slips (`slip_values`) is worked again here from the problem file's givens with plain
Python arithmetic: momentum, Newton's law of restitution along the line of centres, the
reduced-mass energy loss, a fall, a spring and a slide. Letters (u, v, alpha) are checked
at several points. These tests read the data only, never derive's checker.
"""

from __future__ import annotations

import math

import pytest
from test_derivation_corpus_data import _ALPHA, CASES, _direct, _formula, _given

X_CASES = {c.name: c for c in CASES if c.name.startswith("x") and c.name[1:3].isdigit()}
G = 32.2  # ft/s^2, the US problems' g


# ---- numeric problems: (true values, values given the slips) from the givens ----


def _x03(g: dict) -> tuple[dict, dict]:
    """20 Mg car at 0.5 m/s onto a 35 Mg car at rest, which moves off at 0.3 m/s."""
    v_a = (g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B2"]) / g["m_A"]
    e = (g["v_B2"] - v_a) / (g["v_A1"] - g["v_B1"])
    t_1 = 0.5 * 1000 * g["m_A"] * g["v_A1"] ** 2  # Mg to kg for the energy check
    t_2 = 0.5 * 1000 * (g["m_A"] * v_a**2 + g["m_B"] * g["v_B2"] ** 2)
    assert (t_1, round(t_2, 2), round(t_1 - t_2, 2)) == (2500.0, 1581.25, 918.75)
    return {"v_A2": v_a, "e": e}, {}


def _x05(_g: dict) -> tuple[dict, dict]:
    """tan(theta) = 3 to the wall; PA . PB = 0 gives e = cot^2(theta)."""
    cos, sin = 1 / math.sqrt(10), 3 / math.sqrt(10)
    e = cos**2 / sin**2
    assert -(cos * cos) + sin * (e * sin) == pytest.approx(0.0, abs=1e-12)
    return {"e": e}, {}


def _x06(g: dict) -> tuple[dict, dict]:
    """Elastic; the slip puts (m2 - m1) on top of A's formula."""
    v_a, v_b = _direct(g["m_A"], g["m_B"], 1.0, g["v_A1"], 0.0)
    slipped = (g["m_B"] - g["m_A"]) / (g["m_A"] + g["m_B"]) * g["v_A1"]
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": slipped}


def _x08(g: dict) -> tuple[dict, dict]:
    """Equal disks (the weights cancel); the slip reverses NEL: a - b = e u_n."""
    u_n, u_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    a, b = _direct(g["W_A"], g["W_B"], g["e"], u_n, 0.0)
    true = {"v_A2n": a, "v_B2n": b, "v_A2t": u_t, "v_A2": math.hypot(a, u_t), "v_B2": abs(b)}
    a_s = (u_n + g["e"] * u_n) / 2  # a + b = u_n, a - b = e u_n
    b_s = u_n - a_s
    return true, {"v_A2n": a_s, "v_B2n": b_s, "v_A2": math.hypot(a_s, u_t), "v_B2": abs(b_s)}


def _x09(g: dict) -> tuple[dict, dict]:
    """Masses W/g; the slip uses B's weight (10) as its mass, A's mass W_A/g kept."""
    m_a, m_b = g["W_A"] / G, g["W_B"] / G
    true = dict(zip(("v_A2", "v_B2"), _direct(m_a, m_b, g["e"], g["v_A1"], 0.0), strict=True))
    return true, dict(zip(("v_A2", "v_B2"), _direct(m_a, g["W_B"], g["e"], g["v_A1"], 0.0), strict=True))


def _x10(g: dict) -> tuple[dict, dict]:
    """e = 1: v = 2V - u with V the centre of mass velocity; the slip writes V = 1.517."""
    v = g["m_A"] * g["v_A1"] / (g["m_A"] + g["m_B"])
    assert _direct(g["m_A"], g["m_B"], 1.0, g["v_A1"], 0.0) == pytest.approx((2 * v - g["v_A1"], 2 * v))
    slipped = 1.517
    return {"v_A2": 2 * v - g["v_A1"], "v_B2": 2 * v}, {"v_A2": 2 * slipped - g["v_A1"], "v_B2": 2 * slipped}


def _x11(g: dict) -> tuple[dict, dict]:
    """A stopped: m_A U + m_B b_n = m_B w and w = e (U - b_n); the slip swaps B's components."""

    def solve(b_n: float, b_t: float) -> dict:
        # m_A U + m_B b_n = m_B e (U - b_n)
        u = (g["m_B"] * b_n + g["m_B"] * g["e"] * b_n) / (g["m_B"] * g["e"] - g["m_A"])
        return {"v_A1n": u, "v_B2": math.hypot(g["e"] * (u - b_n), b_t)}

    along, across = g["v_B1"] * math.cos(math.radians(60)), g["v_B1"] * math.sin(math.radians(60))
    return solve(along, across), solve(across, along)


def _x12(g: dict) -> tuple[dict, dict]:
    """e = 0; the slips: car 2's velocity taken + and 1/2 x 110000 x 0.0144 written 7920."""

    def energies(v: float, t_1: float) -> dict:
        t_2 = 0.5 * (g["m_A"] + g["m_B"]) * v**2
        return {"T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    v = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]) / (g["m_A"] + g["m_B"])
    t_1 = 0.5 * g["m_A"] * g["v_A1"] ** 2 + 0.5 * g["m_B"] * g["v_B1"] ** 2
    v_s = (g["m_A"] * g["v_A1"] - g["m_B"] * g["v_B1"]) / (g["m_A"] + g["m_B"])
    t_1s = 0.5 * g["m_A"] * g["v_A1"] ** 2 + 10 * (0.5 * g["m_B"] * g["v_B1"] ** 2)
    slipped = energies(round(v_s, 3), t_1s)  # the student's T_2 is worked from v rounded to 0.224
    return {"v_A2": v, "v_B2": v} | energies(v, t_1), {"v_A2": v_s} | slipped


def _x13(g: dict) -> tuple[dict, dict]:
    """A after at -0.2; the slips: 2v = 7 - 0.1 (sign lost) and 1/2(2)(2^2) written 2."""

    def rest(v: float, t_1: float) -> dict:
        t_2 = 0.5 * g["m_A"] * g["v_A2"] ** 2 + 0.5 * g["m_B"] * v**2
        e = (v - g["v_A2"]) / (g["v_A1"] - g["v_B1"])
        return {"v_B2": v, "e": e, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    t_1 = 0.5 * g["m_A"] * g["v_A1"] ** 2 + 0.5 * g["m_B"] * g["v_B1"] ** 2
    true = rest((p - g["m_A"] * g["v_A2"]) / g["m_B"], t_1)
    slipped = rest((p + g["m_A"] * g["v_A2"]) / g["m_B"], t_1 - 0.5 * g["m_B"] * g["v_B1"] ** 2 + 2.0)
    return true, slipped


def _x14(g: dict) -> tuple[dict, dict]:
    """Fall, a plastic impact on the pan, then the total compression s of the spring by energy."""
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    mass, k = g["m_block"] + g["m_pan"], 1000 * g["k"]
    v = g["m_block"] * v_1 / mass
    s_0 = g["m_pan"] * g["g"] / k
    # 1/2 M V^2 + M g (s - s_0) = 1/2 k (s^2 - s_0^2)
    a, b, c = k / 2, -mass * g["g"], -0.5 * mass * v**2 + mass * g["g"] * s_0 - 0.5 * k * s_0**2
    s = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)
    return {"v_1": v_1, "V": v, "x": s - s_0}, {}


def _x15(g: dict) -> tuple[dict, dict]:
    """Ramp, impact (weights: g cancels), slide d = u_B^2 / (2 mu g); the slip reverses NEL."""
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    u_a, u_b = _direct(g["W_A"], g["W_B"], g["e"], v_1, 0.0)
    true = {"v_1": v_1, "u_A": u_a, "u_B": u_b, "d_B": u_b**2 / (2 * g["mu_k"] * g["g"])}
    # W_A v_1 = W_A u_A + W_B u_B and u_A - u_B = e v_1
    u_b_s = (g["W_A"] * v_1 - g["W_A"] * g["e"] * v_1) / (g["W_A"] + g["W_B"])
    u_a_s = u_b_s + g["e"] * v_1
    return true, {"u_A": u_a_s, "u_B": u_b_s, "d_B": u_b_s**2 / (2 * g["mu_k"] * g["g"])}


NUMERIC_X = {
    "x03-beer-johnston-railcars-primes.txt": _x03,
    "x05-pre-u-2013-wall-dot-product.tex": _x05,
    "x06-puck-goalie-formula-masses-swapped.txt": _x06,
    "x08-glancing-disks-nel-reversed.tex": _x08,
    "x09-hibbeler-suitcases-b-weight-as-mass.txt": _x09,
    "x10-superballs-cm-velocity-arithmetic.md": _x10,
    "x11-mei-2024-disc-stops-sin-cos.tex": _x11,
    "x12-train-cars-b-sign-and-ke.txt": _x12,
    "x13-mei-2023-backward-two-slips.md": _x13,
    "x14-chain-block-spring-total-compression.tex": _x14,
    "x15-chain-suitcases-nel-reversed.txt": _x15,
}


# ---- problems in letters: (true values, values given the slips) at a point u ----


def _x01(u: float) -> tuple[dict, dict]:
    """2m at 2u onto m at rest, e = 2/3."""
    v_a, v_b = _direct(2.0, 1.0, 2 / 3, 2 * u, 0.0)
    return {"v_A2": v_a, "v_B2": v_b}, {}


def _x02(u: float) -> tuple[dict, dict]:
    """m at u onto 9m at rest; half the energy lost: 1/2 (9m/10)(1 - e^2) u^2 = 1/4 m u^2."""
    mu = 9 / 10
    e = math.sqrt(1 - (0.25 / (0.5 * mu)))
    v_a, v_b = _direct(1.0, 9.0, e, u, 0.0)
    lost = 0.5 * u**2 - (0.5 * v_a**2 + 0.5 * 9 * v_b**2)
    assert lost == pytest.approx(0.25 * u**2)
    return {"e": e, "v_A2": v_a, "v_B2": v_b}, {}


def _x04(u: float) -> tuple[dict, dict]:
    """2m and m in opposite directions, each at alpha to the line of centres, e = 1/2."""
    c, s = math.cos(_ALPHA), math.sin(_ALPHA)
    a, b = _direct(2.0, 1.0, 0.5, u * c, -u * c)
    return {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, -u * s)}, {}


def _x07(v: float) -> tuple[dict, dict]:
    """P (2m) and Q (3m) both reverse: after -v and 3v/2; speeds before x, y; e = 1/5 (slip: 1/4)."""

    def before(e: float) -> dict:
        total = (1.5 * v + v) / e  # x + y
        x = (2 * -v + 3 * 1.5 * v + 3 * total) / 5  # 2x - 3y = 2(-v) + 3(3v/2)
        return {"v_A1": x, "v_B1": -(total - x)}

    return before(1 / 5), before(1 / 4)


SYMBOLIC_X = {
    "x01-aqa-2014-centre-of-mass-frame.md": (_x01, "u"),
    "x02-cie-2014-half-ke-reduced-mass.tex": (_x02, "u"),
    "x04-ocr-m3-2012-ij-vectors.md": (_x04, "u"),
    "x07-edexcel-2017-e-copied-quarter.md": (_x07, "v"),
}


def test_every_x_case_is_worked_here() -> None:
    assert len(X_CASES) == 15
    assert set(NUMERIC_X) | set(SYMBOLIC_X) == set(X_CASES)
    assert not set(NUMERIC_X) & set(SYMBOLIC_X)


@pytest.mark.parametrize("name", sorted(NUMERIC_X))
def test_the_x_values_from_the_givens(name: str) -> None:
    verdict = X_CASES[name].verdict
    true, slipped = NUMERIC_X[name](_given(verdict.problem))
    assert verdict.values
    for key, value in verdict.values.items():
        assert value == pytest.approx(true[key], rel=2e-4, abs=2e-4), f"{name}: {key}"
    assert set(verdict.slip_values) <= set(slipped), name
    assert bool(verdict.slip_values) == bool(slipped), name
    for key, value in verdict.slip_values.items():
        assert value == pytest.approx(slipped[key], rel=1e-3, abs=1e-3), f"{name}: slip {key}"


@pytest.mark.parametrize("name", sorted(SYMBOLIC_X))
def test_the_x_closed_forms_at_several_points(name: str) -> None:
    verdict = X_CASES[name].verdict
    work, letter = SYMBOLIC_X[name]
    assert verdict.values
    for point in (1.0, 2.0, 1.5):
        true, slipped = work(point)
        letters = {letter: point, "alpha": _ALPHA}
        for key, formula in verdict.values.items():
            assert _formula(str(formula), point, 0.0, letters) == pytest.approx(true[key], rel=1e-9), f"{name}: {key}"
        assert set(verdict.slip_values) == set(slipped), name
        for key, formula in verdict.slip_values.items():
            assert _formula(str(formula), point, 0.0, letters) == pytest.approx(slipped[key], rel=1e-9), key


def test_the_x_batch_spread() -> None:
    by_category: dict[str, int] = {}
    for case in X_CASES.values():
        by_category[case.verdict.category] = by_category.get(case.verdict.category, 0) + 1
    assert by_category == {"correct": 5, "one_slip": 6, "two_slips": 2, "chain": 2}
    assert sorted(c.verdict.format for c in X_CASES.values()) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
