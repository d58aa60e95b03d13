"""The me batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the me cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, components of a velocity, a fall and a rise, an
impulse), with the student's slip made on purpose for the slip values. Answers in letters (u, e,
alpha, k, lambda) are checked at a few points by solving the two linear equations numerically
there. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, letters_agree

ME_CASES = [c for c in CASES if c.name.startswith("me")]
# (u, e, alpha in radians, k, lambda) for the letters; lambda < 1/2 and k > 1 as the questions have
POINTS = ((1.0, 0.5, 0.4, 2.0, 0.2), (2.0, 0.3, 0.9, 3.0, 0.1), (1.5, 0.9, 1.2, 1.5, 0.4))


def _case(prefix: str):
    return next(c for c in ME_CASES if c.name.startswith(prefix))


def _cramer(a11: float, a12: float, a21: float, a22: float, b1: float, b2: float) -> tuple[float, float]:
    """The student's Cramer's rule, worked independently of _solve."""
    det = a11 * a22 - a12 * a21
    return (b1 * a22 - a12 * b2) / det, (a11 * b2 - b1 * a21) / det


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _me03(g: dict) -> tuple[dict, None]:
    v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_A"] * g["v_A2"]) / g["m_B"]
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _me05(g: dict) -> tuple[dict, None]:
    n = math.sin(math.radians(g["theta_1"]))  # per unit v_A1; t = cos
    t = math.cos(math.radians(g["theta_1"]))
    a, b = _solve(1.0, 1.0, n, g["e"] * n)
    return {"theta_A2": math.degrees(math.atan2(a, t)), "v_A2n_per_v_A1": a, "v_B2_per_v_A1": b}, None


def _me13(g: dict) -> tuple[dict, dict]:
    def worked(a_n: float, a_t: float, b_n: float) -> dict:
        a, b = _solve(1.0, 1.0, a_n + b_n, g["e"] * (a_n - b_n))
        return {"v_A2n": a, "v_B2n": b, "v_A2t": a_t, "v_A2": math.hypot(a, a_t), "v_B2": abs(b)}

    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))  # [A] angle = "30 deg"
    true = worked(g["v_A1"] * c, g["v_A1"] * s, g["v_B1n"])
    return true, worked(g["v_A1"] * s, g["v_A1"] * c, -g["v_B1n"])  # sin for cos; B's +3


def _me14(g: dict) -> tuple[dict, None]:
    mass = g["m_bullet"] + g["m_block"]
    v = g["m_bullet"] * g["v_0"] / mass
    return {"V": v, "T_after": 0.5 * mass * v * v, "h_2": v * v / (2 * g["g"])}, None


def _me15(g: dict) -> tuple[dict, dict]:
    def worked(v_1: float) -> dict:
        v_2 = g["e_floor"] * v_1
        lost = 0.5 * g["m"] * (v_1**2 - v_2**2)
        return {"v_1": v_1, "v_2": v_2, "h_2": v_2**2 / (2 * g["g"]), "J": g["m"] * (v_1 + v_2), "E_lost": lost}

    true = worked(math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"]))
    return true, worked(math.sqrt(g["v_0"] + 2 * g["g"] * g["h_0"]))  # u not squared


NUMERIC_ME: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "me03": _me03,
    "me05": _me05,
    "me13": _me13,
    "me14": _me14,
    "me15": _me15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _me01(p: dict) -> tuple[dict, None]:
    u, e, al = p["u"], p["e"], p["alpha"]
    x, _ = _solve(1.0, 1.0, u * math.cos(al), e * u * math.cos(al))
    y = u * math.sin(al)
    return {"v_A2t": y, "v_A2n": x, "beta_A2": math.atan2(y, x)}, None


def _me02(p: dict) -> tuple[dict, None]:
    u, al = p["u"], p["alpha"]
    c = u * math.cos(al)
    a, b = _cramer(2.0, 1.0, -1.0, 1.0, 2 * c - c, 0.5 * (c + c))
    return {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, u * math.sin(al))}, None


def _me04(p: dict) -> tuple[dict, None]:
    u = p["u"]
    # impulse 4mu: on m along +n, on 3m against it
    return {"v_A2": 2 * u - 4 * u / 3, "v_B2": -u + 4 * u}, None


def _cushion(u: float, e: float, parallel: float, perpendicular: float) -> float:
    return math.atan2(e * u * perpendicular, u * parallel)  # beta from DC


def _me06(p: dict) -> tuple[dict, dict]:
    u, e, al = p["u"], p["e"], p["alpha"]
    true = _cushion(u, e, math.cos(al), math.sin(al))
    return {"beta": true}, {"beta": _cushion(u, e, math.sin(al), math.cos(al))}


def _me07(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    along, across = u * math.cos(math.radians(30)), u * math.sin(math.radians(30))
    v_1, _ = _solve(1.0, 1.0, along, e * along)
    slipped = along * (1 + e) / 2  # (1) - (2) with the e term added

    def turned(v: float) -> float:
        return math.atan2(across, v) - math.radians(30)

    return {"v_A2n": v_1, "deflection": turned(v_1)}, {"v_A2n": slipped, "deflection": turned(slipped)}


def _me08(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    along = u * math.cos(math.radians(60))
    _, v_b = _solve(1.0, 1.0, along, e * along)
    _, slipped = _solve(1.0, 1.0, along, -e * along)  # v_A - v_B = e u cos 60
    return {"v_B2": v_b}, {"v_B2": slipped}


def _me09(p: dict) -> tuple[dict, dict]:
    u, k, lam = p["u"], p["k"], p["lam"]

    def worked(u_t: float) -> dict:
        v = (u + k * u_t) / k  # m u + k m u_T = k m v, S at rest after
        return {"v_B2": v, "e": v / (u - u_t)}

    return worked(lam * u), worked(-lam * u)


def _me10(p: dict) -> tuple[dict, dict]:
    u = p["u"]

    def worked(angle: float) -> dict:
        along = u * math.cos(math.radians(angle))
        a, b = _solve(1.0, 1.0, along, 0.5 * along)
        return {"v_B2": b, "v_A2n": a}

    return worked(math.degrees(math.asin(0.5))), worked(math.degrees(math.acos(0.5)))


def _me11(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    _, b = _solve(1.0, 1.0, u * math.cos(math.radians(30)), e * u * math.cos(math.radians(30)))
    _, slipped = _solve(1.0, 1.0, u * math.sin(math.radians(30)), e * u * math.sin(math.radians(30)))
    return {"v_B2": b}, {"v_B2": slipped}


def _me12(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    x, y = _cramer(2.0, 3.0, -1.0, 1.0, 2 * 5 * u, 5 * e * u)
    sx, _ = _cramer(2.0, 3.0, -1.0, 1.0, 5 * u, 5 * e * u)  # slip 1: momentum 5u
    sy = (2 * 5 * e * u - 5 * u) / 5  # slip 2: 2(5eu) - (5u)(-1) taken as 10eu - 5u
    return {"v_A2": x, "v_B2": y}, {"v_A2": sx, "v_B2": sy}


SYMBOLIC_ME: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "me01": _me01,
    "me02": _me02,
    "me04": _me04,
    "me06": _me06,
    "me07": _me07,
    "me08": _me08,
    "me09": _me09,
    "me10": _me10,
    "me11": _me11,
    "me12": _me12,
}


def test_every_me_case_is_worked_here() -> None:
    assert len(ME_CASES) == 15
    assert {c.name[:4] for c in ME_CASES} == set(NUMERIC_ME) | set(SYMBOLIC_ME)
    by_category = sorted(c.verdict.category for c in ME_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ME_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    for case in ME_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ME))
def test_the_me_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ME[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ME))
def test_the_me_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha, k, lam in POINTS:
        names = {"u": u, "e": e, "alpha": alpha, "k": k, "lam": lam}
        true, slipped = SYMBOLIC_ME[prefix](names)
        letters_agree(case, names, true, slipped)
