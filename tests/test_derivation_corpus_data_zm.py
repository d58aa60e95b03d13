"""The zm batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zm cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's rebound, kinetic energy, a fall, a rise and
a slide), with the student's slip made on purpose for the slip values. Answers in letters (u, e,
alpha, k, lam) are checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _bounce, _given, _solve, closed_form

ZM_CASES = [c for c in CASES if c.name.startswith("zm")]
# (u, e, alpha, k, lam) for the letters
POINTS = (
    {"u": 1.0, "e": 0.5, "alpha": 0.3, "k": 2.0, "lam": 0.2},
    {"u": 2.0, "e": 0.3, "alpha": 0.7, "k": 3.0, "lam": 0.4},
    {"u": 1.5, "e": 0.9, "alpha": 1.2, "k": 0.5, "lam": 0.1},
)


def _case(prefix: str):
    return next(c for c in ZM_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _zm04(g: dict) -> tuple[dict, dict]:
    v = -g["e"] * g["v_A1"]
    lost = 0.5 * g["m_A"] * (g["v_A1"] ** 2 - v * v)
    return {"v_A2": v, "T_lost": lost}, {"T_lost": 2 * lost}  # the 1/2 left out


def _zm05(g: dict) -> tuple[dict, None]:
    n = g["phi_n"]
    a_n, a_t = g["v_A1"] * math.cos(math.radians(45 - n)), g["v_A1"] * math.sin(math.radians(45 - n))
    b_n, b_t = g["v_B1"] * math.cos(math.radians(120 - n)), g["v_B1"] * math.sin(math.radians(120 - n))
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, g["e"] * (a_n - b_n))
    return {
        "v_A2n": a,
        "v_B2n": b,
        "v_A2": math.hypot(a, a_t),
        "v_B2": math.hypot(b, b_t),
        "psi_A2": n + math.degrees(math.atan2(a_t, a)),
        "psi_B2": n + math.degrees(math.atan2(b_t, b)),
    }, None


def _zm07(g: dict) -> tuple[dict, dict]:
    u_a, u_b, e = g["v_A1"], g["v_B1"], g["e"]  # masses in units of m: 2, 3

    def worked(gap: float, t_1: float) -> dict:
        a, b = _solve(2.0, 3.0, 2 * u_a + 3 * u_b, gap)
        t_2 = 0.5 * 2 * a * a + 0.5 * 3 * b * b
        return {"v_A2": a, "v_B2": b, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    t_1 = 0.5 * 2 * u_a**2 + 0.5 * 3 * u_b**2
    slipped_t_1 = 0.5 * 2 * u_a**2 + 0.5 * 3 * abs(u_b)  # (1/2)(3m)(2)^2 worked as 3m
    return worked(e * (u_a - u_b), t_1), worked(e * (abs(u_a) - abs(u_b)), slipped_t_1)


def _zm14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    a, b = _solve(g["W_A"], g["W_B"], g["W_A"] * v_1, g["e"] * v_1)  # g cancels
    return {"v_1": v_1, "u_A": a, "u_B": b, "d_B": b * b / (2 * g["mu_k"] * g["g"])}, None


def _zm15(g: dict) -> tuple[dict, dict]:
    v_1 = math.sqrt(2 * g["g"] * g["h_0"])

    def worked(v_2: float) -> dict:
        return {"v_1": v_1, "v_2": v_2, "e_floor": v_2 / v_1, "J": g["m"] * (v_1 + v_2)}

    true = worked(math.sqrt(2 * g["g"] * g["h_r"]))
    assert _bounce(g | {"e_floor": true["e_floor"]}, v_1)["J"] == pytest.approx(true["J"])
    return true, worked(math.sqrt(g["g"] * g["h_r"]))  # v2^2 = g hr: the 2 lost


NUMERIC_ZM: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zm04": _zm04,
    "zm05": _zm05,
    "zm07": _zm07,
    "zm14": _zm14,
    "zm15": _zm15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _zm01(p: dict) -> tuple[dict, dict]:
    u, al = p["u"], p["alpha"]

    def worked(along: float, across: float) -> dict:
        a, b = _solve(2.0, 1.0, 2 * along - along, 0.5 * (along + along))
        assert a == pytest.approx(0, abs=1e-12)
        return {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, -across)}

    true, slipped = worked(u * math.cos(al), u * math.sin(al)), worked(u * math.sin(al), u * math.cos(al))
    assert slipped["v_B2"] == pytest.approx(u)  # the show line still holds
    return true, {"v_B2n": slipped["v_B2n"]}


def _zm02(p: dict) -> tuple[dict, dict]:
    u, k, lam = p["u"], p["k"], p["lam"]
    v = (u + k * lam * u) / k  # m u + k m lam u = k m v, S at rest
    return {"e": v / (u - lam * u), "v_B2": v}, {"e": (u - lam * u) / v}  # upside down


def _zm03(p: dict) -> tuple[dict, None]:
    u = p["u"]
    e = math.sqrt(1 - 0.25 / 0.45)  # (9/20)(1 - e^2) = 1/4
    a, b = _solve(1.0, 9.0, u, e * u)
    assert 0.5 * a * a + 4.5 * b * b == pytest.approx(0.25 * u * u)
    return {"e": e, "v_A2": a, "v_B2": b}, None


def _zm06(p: dict) -> tuple[dict, None]:
    u = p["u"]
    a, b = _solve(2.0, 1.0, 2 * u, u / 3)
    g = 2 * u / 3
    assert a == pytest.approx(g - (u - g) / 3) and b == pytest.approx(g + g / 3)
    return {"v_A2": a, "v_B2": b}, None


def _zm08(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    a, b = _solve(4.0, 5.0, 4 * u, u / 2)
    sa, sb = _solve(4.0, 5.0, 4 * u, u / 3)  # e copied as 1/3
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb + u / 27}  # 16u/27 added to 17u/27


def _zm09(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 7.0, 12 * u, 4 * e * u)
    sb = (12 * u - 4 * e * u) / 8  # the sign of 4eu changed
    return {"v_A2": a, "v_B2": b}, {"v_B2": sb, "v_A2": sb - 4 * e * u}


def _zm10(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    a, b = 2 * u - 4 * u / 3, -u + 4 * u  # 3m(a - 2u) = -4mu, m(b + u) = 4mu
    t_1 = 0.5 * 3 * (2 * u) ** 2 + 0.5 * u * u
    t_2 = 0.5 * 3 * a * a + 0.5 * b * b
    assert t_1 == pytest.approx(13 * u * u / 2) and t_2 == pytest.approx(31 * u * u / 6)
    assert t_1 - t_2 == pytest.approx(4 * u * u / 3)
    st_2 = 2 * (0.5 * 3 * a * a) + 0.5 * b * b  # (1/2)(3m)(2u/3)^2 doubled to 4mu^2/3
    return {"v_A2": a, "v_B2": b}, {"T_2": st_2, "T_lost": t_1 - st_2}


def _zm11(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    along = u * math.cos(math.radians(30))
    a, b = _solve(1.0, 1.0, along, e * along)
    return {"v_B2": b, "v_A2n": a}, None


def _zm12(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 1.0, 2 * 2 * u - u, 3 * e * u)
    sa, sb = _solve(1.0, 2.0, 1 * 2 * u - 2 * u, 3 * e * u)  # masses swapped
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _zm13(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    a, b = _solve(3.0, 6.0, 3 * u, e * u)
    lost = 0.5 * 3 * u * u - (0.5 * 3 * a * a + 0.5 * 6 * b * b)
    return {"v_A2": a, "v_B2": b, "T_lost": lost}, None


SYMBOLIC_ZM: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zm01": _zm01,
    "zm02": _zm02,
    "zm03": _zm03,
    "zm06": _zm06,
    "zm08": _zm08,
    "zm09": _zm09,
    "zm10": _zm10,
    "zm11": _zm11,
    "zm12": _zm12,
    "zm13": _zm13,
}


def test_every_zm_case_is_worked_here() -> None:
    assert len(ZM_CASES) == 15
    assert {c.name[:4] for c in ZM_CASES} == set(NUMERIC_ZM) | set(SYMBOLIC_ZM)
    by_category = sorted(c.verdict.category for c in ZM_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZM_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in ZM_CASES}) == 15
    for case in ZM_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in ZM_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZM))
def test_the_zm_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZM[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZM))
def test_the_zm_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for names in POINTS:
        true, slipped = SYMBOLIC_ZM[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
