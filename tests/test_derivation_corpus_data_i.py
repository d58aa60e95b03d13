"""The `i` batch of typed derivations (a held-out batch written 2026-11-28, fourth session).

Every true value its verdicts record (`values`) and every value the carried lines hold given
the slips (`slip_values`) is worked again here from the problem file's givens with plain
Python arithmetic: momentum and Newton's law of restitution along the line of impact, the
mass-center velocity, impulse-momentum, kinetic energies with m = W/g, a fall and a rise.
Letters (u, e, m) are checked at several points. These tests read the data only, never
derive's checker.
"""

from __future__ import annotations

import math

import pytest
from test_derivation_corpus_data import CASES, _direct, _formula, _given

I_CASES = {c.name: c for c in CASES if c.name.startswith("i")}
G = 32.2  # ft/s^2, the US problems' g


def _energies(m_a: float, m_b: float, u: tuple[float, float], v: tuple[float, float]) -> dict:
    t_1 = 0.5 * m_a * u[0] ** 2 + 0.5 * m_b * u[1] ** 2
    t_2 = 0.5 * m_a * v[0] ** 2 + 0.5 * m_b * v[1] ** 2
    return {"T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}


# ---- numeric problems: (true values, values given the slips) from the givens ----


def _i01(g: dict) -> tuple[dict, dict]:
    """Mass-center velocity: v = v_G - e (u - v_G) for each suitcase (weights: g cancels)."""
    v_g = (g["W_A"] * g["v_A1"] + g["W_B"] * g["v_B1"]) / (g["W_A"] + g["W_B"])
    v_a, v_b = v_g - g["e"] * (g["v_A1"] - v_g), v_g - g["e"] * (g["v_B1"] - v_g)
    assert (v_a, v_b) == pytest.approx(_direct(g["W_A"], g["W_B"], g["e"], g["v_A1"], g["v_B1"]))
    return {"v_A2": v_a, "v_B2": v_b}, {}


def _i03(g: dict) -> tuple[dict, dict]:
    """A across the line of centres, B along it; worked in the student's +n (B's way), then flipped."""
    # 5(0) + 2(4) = 5a + 2b and a - b = e (4 - 0) in the student's axis
    speed = -g["v_B1n"]
    a = (g["m_B"] * speed + g["m_B"] * g["e"] * speed) / (g["m_A"] + g["m_B"])
    b = a - g["e"] * speed
    v_an, v_bn = -a, -b
    true = {"v_A2n": v_an, "v_B2n": v_bn, "v_A2t": g["v_A1t"], "v_A2": math.hypot(v_an, g["v_A1t"])}
    assert math.degrees(math.atan(g["v_A1t"] / abs(v_an))) == pytest.approx(63.43, abs=0.01)
    return true | {"v_B2": abs(v_bn)}, {}


def _i07(g: dict) -> tuple[dict, dict]:
    """B turned through a right angle; the slip: (v_A)_2n = -0.2196 + 0.1732."""
    alpha = math.radians(g["alpha"])
    b_n, b_t = -g["u_B"] * math.cos(alpha), g["u_B"] * math.sin(alpha)
    v_bn = b_t * math.tan(alpha)
    # the turn: the velocities before and after are perpendicular
    assert b_n * v_bn + b_t * b_t == pytest.approx(0.0, abs=1e-12)
    rest = g["v_A1n"] + b_n  # = (v_A)_2n + (v_B)_2n
    v_an = rest - v_bn
    approach = g["v_A1n"] - b_n
    slipped = rest + v_bn
    return (
        {"v_B2": math.hypot(v_bn, b_t), "v_A2n": v_an, "e": (v_bn - v_an) / approach},
        {"v_A2n": slipped, "e": (v_bn - slipped) / approach},
    )


def _i09(g: dict) -> tuple[dict, dict]:
    """Equal 47 lb disks, A at 30 deg; the slip multiplies A's t component by e."""
    u_n, u_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    a, b = _direct(g["W_A"], g["W_B"], g["e"], u_n, 0.0)
    true = {"v_A2n": a, "v_B2n": b, "v_A2t": u_t, "v_A2": math.hypot(a, u_t), "v_B2": abs(b)}
    true["J_n"] = g["W_B"] / G * b
    return true, {"v_A2t": g["e"] * u_t, "v_A2": math.hypot(a, g["e"] * u_t)}


def _i10(g: dict) -> tuple[dict, dict]:
    """2m and 3m (energies in units of m); the slip sums 1/2 m (u - v)^2."""
    m_a, m_b = 2.0, 3.0
    v_a, v_b = _direct(m_a, m_b, g["e"], g["v_A1"], g["v_B1"])
    lost = _energies(m_a, m_b, (g["v_A1"], g["v_B1"]), (v_a, v_b))["T_lost"]
    slipped = 0.5 * m_a * (g["v_A1"] - v_a) ** 2 + 0.5 * m_b * (g["v_B1"] - v_b) ** 2
    return {"v_A2": v_a, "v_B2": v_b, "T_lost": lost}, {"T_lost": slipped}


def _i12(g: dict) -> tuple[dict, dict]:
    """Plastic; the slips: B's -6 ft/s taken as +6, then the weights used as masses in T."""
    speeds = (g["v_A1"], g["v_B1"])
    total = g["W_A"] + g["W_B"]
    v = (g["W_A"] * g["v_A1"] + g["W_B"] * g["v_B1"]) / total
    true = {"v_A2": v, "v_B2": v} | _energies(g["W_A"] / G, g["W_B"] / G, speeds, (v, v))
    v_s = (g["W_A"] * g["v_A1"] - g["W_B"] * g["v_B1"]) / total
    slipped = {"v_A2": v_s, "v_B2": v_s} | _energies(g["W_A"], g["W_B"], speeds, (v_s, v_s))
    return true, slipped


def _i13(g: dict) -> tuple[dict, dict]:
    """The slips: (v_A)_2 - (v_B)_2 = e (v_A)_1, then the weights as masses in T."""
    speeds = (g["v_A1"], g["v_B1"])
    v_a, v_b = _direct(g["W_A"], g["W_B"], g["e"], g["v_A1"], g["v_B1"])
    true = {"v_A2": v_a, "v_B2": v_b} | _energies(g["W_A"] / G, g["W_B"] / G, speeds, (v_a, v_b))
    gap = g["e"] * (g["v_A1"] - g["v_B1"])
    b_s = (g["W_A"] * g["v_A1"] + g["W_B"] * g["v_B1"] - g["W_A"] * gap) / (g["W_A"] + g["W_B"])
    a_s = b_s + gap
    # the student's T_2 is worked from the velocities as written, 14.15 and 8.256
    slipped = {"v_A2": a_s, "v_B2": b_s} | _energies(g["W_A"], g["W_B"], speeds, (round(a_s, 2), round(b_s, 3)))
    return true, slipped


def _i14(g: dict) -> tuple[dict, dict]:
    """Three equal particles: each impact on one at rest gives (1 + e)/2 of the speed."""
    e = math.sqrt(4 * g["v_C"] / g["v_0"]) - 1
    u_b = _direct(1.0, 1.0, e, g["v_0"], 0.0)[1]
    assert _direct(1.0, 1.0, e, u_b, 0.0)[1] == pytest.approx(g["v_C"])
    return {"u_B": u_b, "e": e}, {}


def _i15(g: dict) -> tuple[dict, dict]:
    """Drop and rebound; the slip writes 2(9.8)(1.4) = 24.7."""

    def rest(v_1: float, v_2: float) -> dict:
        return {"v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}

    v_1 = math.sqrt(2 * g["g"] * g["h_0"])
    true = {"v_1": v_1} | rest(v_1, math.sqrt(2 * g["g"] * g["h_r"]))
    return true, rest(round(v_1, 2), round(math.sqrt(24.7), 2))


NUMERIC_I = {
    "i01-hibbeler-suitcases-mass-center-velocity.md": _i01,
    "i03-ocr-m3-2006-left-positive-n-t.txt": _i03,
    "i07-ocr-m3-2013-right-angle-sign-lost.tex": _i07,
    "i09-glancing-disks-e-on-t-calculator.txt": _i09,
    "i10-ocr-2014-ke-lost-of-velocity-change.md": _i10,
    "i12-two-cars-mathcad-two-slips.txt": _i12,
    "i13-hibbeler-suitcases-two-slips.tex": _i13,
    "i14-chain-three-particles-two-impacts.md": _i14,
    "i15-chain-drop-rebound-rise-arithmetic.txt": _i15,
}


# ---- problems in letters: (true values, values given the slips) at a point (u, e, m) ----


def _i02(u: float, _e: float, _m: float) -> tuple[dict, dict]:
    """2m at u onto m at rest, e = 1/3."""
    v_a, v_b = _direct(2.0, 1.0, 1 / 3, u, 0.0)
    return {"v_A2": v_a, "v_B2": v_b}, {}


def _i04(u: float, e: float, _m: float) -> tuple[dict, dict]:
    """2m at 2u meets 4m at u: zero momentum, so each velocity is -e times the one before."""
    v_a, v_b = _direct(2.0, 4.0, e, 2 * u, -u)
    assert 2 * 2 * u + 4 * -u == 0.0
    return {"v_A2": v_a, "v_B2": v_b}, {}


def _i05(u: float, e: float, _m: float) -> tuple[dict, dict]:
    """Equal balls, the first at 30 deg to the line of centres; the deflection's tangent too."""
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    v_n = _direct(1.0, 1.0, e, u * c, 0.0)[0]
    deflection = math.atan2(u * s, v_n) - math.radians(30)
    assert math.tan(deflection) == pytest.approx(math.sqrt(3) * (1 + e) / (5 - 3 * e))
    return {"v_A2n": v_n}, {}


def _i06(u: float, _e: float, _m: float) -> tuple[dict, dict]:
    """4m at u onto 5m at rest, e = 1/2; the slip copies e as 1/3."""
    true = dict(zip(("v_A2", "v_B2"), _direct(4.0, 5.0, 0.5, u, 0.0), strict=True))
    return true, dict(zip(("v_A2", "v_B2"), _direct(4.0, 5.0, 1 / 3, u, 0.0), strict=True))


def _i08(u: float, e: float, _m: float) -> tuple[dict, dict]:
    """m at 5u catches 7m at u; the slip takes the approach speed as 5u + u."""
    true = dict(zip(("v_A2", "v_B2"), _direct(1.0, 7.0, e, 5 * u, u), strict=True))
    # 12u = a + 7b and b - a = 6eu
    b = (12 * u + 6 * e * u) / 8
    return true, {"v_A2": b - 6 * e * u, "v_B2": b}


def _i11(u: float, _e: float, m: float) -> tuple[dict, dict]:
    """Impulse 4mu on each: 3m(v_A - 2u) = -4mu, m(v_B + u) = 4mu; the slip drops A's 1/2 after."""
    v_a, v_b = 2 * u - 4 * m * u / (3 * m), -u + 4 * m * u / m
    t_1 = 0.5 * 3 * m * (2 * u) ** 2 + 0.5 * m * u**2
    assert t_1 - (0.5 * 3 * m * v_a**2 + 0.5 * m * v_b**2) == pytest.approx(4 / 3 * m * u * u)
    t_2 = 3 * m * v_a**2 + 0.5 * m * v_b**2
    return {"v_A2": v_a, "v_B2": v_b}, {"T_2": t_2, "T_lost": t_1 - t_2}


SYMBOLIC_I = {
    "i02-edexcel-2003-eliminate-y-first.tex": _i02,
    "i04-cie-2019-zero-momentum-common-velocity.md": _i04,
    "i05-pre-u-specimen-n-t-tan-difference.tex": _i05,
    "i06-edexcel-4m-5m-e-copied-third.txt": _i06,
    "i08-aqa-2009-closing-speed-added.md": _i08,
    "i11-cie-2012-impulse-first-half-dropped.tex": _i11,
}


def test_every_i_case_is_worked_here() -> None:
    assert len(I_CASES) == 15
    assert set(NUMERIC_I) | set(SYMBOLIC_I) == set(I_CASES)
    assert not set(NUMERIC_I) & set(SYMBOLIC_I)


@pytest.mark.parametrize("name", sorted(NUMERIC_I))
def test_the_i_values_from_the_givens(name: str) -> None:
    verdict = I_CASES[name].verdict
    true, slipped = NUMERIC_I[name](_given(verdict.problem))
    assert verdict.values
    for key, value in verdict.values.items():
        assert value == pytest.approx(true[key], rel=2e-4, abs=2e-4), f"{name}: {key}"
    assert set(verdict.slip_values) <= set(slipped), name
    assert bool(verdict.slip_values) == bool(slipped), name
    for key, value in verdict.slip_values.items():
        assert value == pytest.approx(slipped[key], rel=1e-3, abs=1e-3), f"{name}: slip {key}"


@pytest.mark.parametrize("name", sorted(SYMBOLIC_I))
def test_the_i_closed_forms_at_several_points(name: str) -> None:
    verdict = I_CASES[name].verdict
    work = SYMBOLIC_I[name]
    assert verdict.values
    for u, e, m in ((1.0, 0.5, 1.0), (2.0, 0.3, 3.0), (1.5, 0.9, 0.7)):
        true, slipped = work(u, e, m)
        for key, formula in verdict.values.items():
            assert _formula(str(formula), u, e, {"m": m}) == pytest.approx(true[key], rel=1e-9), f"{name}: {key}"
        assert set(verdict.slip_values) == set(slipped), name
        for key, formula in verdict.slip_values.items():
            assert _formula(str(formula), u, e, {"m": m}) == pytest.approx(slipped[key], rel=1e-9), key


def test_the_i_batch_spread() -> None:
    by_category: dict[str, int] = {}
    for case in I_CASES.values():
        by_category[case.verdict.category] = by_category.get(case.verdict.category, 0) + 1
    assert by_category == {"correct": 5, "one_slip": 6, "two_slips": 2, "chain": 2}
    assert sorted(c.verdict.format for c in I_CASES.values()) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    chains = [c for c in I_CASES.values() if c.verdict.category == "chain"]
    assert sorted(len(c.verdict.slips) for c in chains) == [0, 1]
