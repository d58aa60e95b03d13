"""The zn batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zn cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's rebound, kinetic energy, an impulse), with
the student's slip made on purpose for the slip values. Answers in letters (u, e, alpha, k, lam)
are checked at a few points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, closed_form

ZN_CASES = [c for c in CASES if c.name.startswith("zn")]
# (u, e, alpha, k, lam) for the letters
POINTS = (
    {"u": 1.0, "e": 0.5, "alpha": 0.3, "k": 2.0, "lam": 0.2},
    {"u": 2.0, "e": 0.3, "alpha": 0.7, "k": 3.0, "lam": 0.4},
    {"u": 1.5, "e": 0.9, "alpha": 1.2, "k": 0.5, "lam": 0.1},
)


def _case(prefix: str):
    return next(c for c in ZN_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _zn02(g: dict) -> tuple[dict, dict]:
    th = math.radians(g["theta"])

    def worked(along: Callable[[float], float], across: Callable[[float], float]) -> dict:
        a_n, a_t = g["v_A1"] * along(th), g["v_A1"] * across(th)
        b_n, b_t = -g["v_B1"] * along(th), -g["v_B1"] * across(th)
        a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, g["e"] * (a_n - b_n))
        return {
            "v_A2t": a_t,
            "v_B2t": b_t,
            "v_A2n": a,
            "v_B2n": b,
            "v_A2": math.hypot(a, a_t),
            "v_B2": math.hypot(b, b_t),
        }

    return worked(math.cos, math.sin), worked(math.sin, math.cos)  # sin along the line of impact


def _zn04(g: dict) -> tuple[dict, dict]:
    e = g["e"]
    # kept fraction 3/5 = cos^2 + e^2 sin^2 (alpha from the wall); slipped: sin^2 + e^2 cos^2
    sin2 = (1 - 0.6) / (1 - e * e)
    return {"alpha": math.degrees(math.asin(math.sqrt(sin2)))}, {"alpha": math.degrees(math.acos(math.sqrt(sin2)))}


def _zn05(g: dict) -> tuple[dict, dict]:
    m, u, e = g["m_A"], g["v_A1"], g["e"]
    v = -e * u
    t_1, t_2 = 0.5 * m * u * u, 0.5 * m * v * v
    true = {"v_A2": v, "J_n": m * (u - v), "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}
    slipped_t_2 = t_2 + 0.1  # (0.4)(1.44) worked as 0.676
    return true, {"T_2": slipped_t_2, "T_lost": t_1 - slipped_t_2}


def _zn06(g: dict) -> tuple[dict, dict]:
    u_n, u_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    m = g["W_A"] / 32.2
    a, b = _solve(m, m, m * u_n, g["e"] * u_n)
    true = {"v_A2n": a, "v_B2n": b, "v_A2t": u_t, "v_A2": math.hypot(a, u_t), "v_B2": abs(b), "J_n": m * b}
    assert math.degrees(math.atan2(u_t, a)) == pytest.approx(80.17, abs=0.01)
    return true, {"J_n": g["W_B"] * b}  # the weight in lb as the mass


def _zn07(g: dict) -> tuple[dict, None]:
    big_v = g["m_A"] * g["v_A1"] / (g["m_A"] + g["m_B"])  # the centre of mass
    a, b = 2 * big_v - g["v_A1"], 2 * big_v - g["v_B1"]
    assert (a, b) == pytest.approx(_solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1"], g["v_A1"]))
    return {"v_A2": a, "v_B2": b}, None


def _zn10(g: dict) -> tuple[dict, dict]:
    u_a, u_b, v_a, v_b, m_b = g["v_A1"], g["v_B1"], g["v_A2"], g["v_B2"], g["m_B"]
    e = (v_b - v_a) / (u_a - u_b)
    m_a = m_b * (v_b - u_b) / (u_a - v_a)
    slipped_e = (v_b - v_a) / (u_a - abs(u_b))  # approach 3 - 1.5
    return {"e": e, "m_A": m_a}, {"e": slipped_e, "m_A": m_a - 0.1}  # 0.58 + 0.3 worked as 0.78


def _zn12(g: dict) -> tuple[dict, dict]:
    m_a, m_b, u, v_a = g["m_A"], g["m_B"], g["v_A1"], g["v_A2"]

    def worked(after: float) -> dict:
        v_b = (m_a * u - m_a * after) / m_b
        return {"v_B2": v_b, "e": (v_b - after) / u}

    return worked(v_a), worked(v_a + 1)  # 2 m/s copied as 3


def _zn13(g: dict) -> tuple[dict, None]:
    u_n = g["v_A1"] * math.cos(math.radians(g["theta"]))
    return {"v_A1n": u_n, "J_n": g["m_A"] * (u_n + g["e"] * u_n)}, None


def _zn14(g: dict) -> tuple[dict, None]:
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A"] - g["m_B"] * g["v_B"], g["e"] * (g["v_A"] + g["v_B"]))
    w = -g["e_wall"] * b
    return {"u_A": a, "u_B": b, "w_B": w, "again": "yes" if w < a else "no"}, None


def _zn15(g: dict) -> tuple[dict, dict]:
    def worked(v_0: float) -> dict:
        e = math.sqrt(4 * g["v_C"] / v_0) - 1  # v_0 (1 + e)^2 / 4 = v_C
        u_b = _solve(1.0, 1.0, v_0, e * v_0)[1]
        assert _solve(1.0, 1.0, u_b, e * u_b)[1] == pytest.approx(g["v_C"])
        return {"u_B": u_b, "e": e}

    return worked(g["v_0"]), worked(g["v_0"] - 1)  # 7 copied as 6


NUMERIC_ZN: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zn02": _zn02,
    "zn04": _zn04,
    "zn05": _zn05,
    "zn06": _zn06,
    "zn07": _zn07,
    "zn10": _zn10,
    "zn12": _zn12,
    "zn13": _zn13,
    "zn14": _zn14,
    "zn15": _zn15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _zn01(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 3.0, 4 * u, 4 * e * u)
    assert (a < 0) == (e > 1 / 3)
    return {"v_A2": a, "v_B2": b}, None


def _zn03(p: dict) -> tuple[dict, None]:
    u, al = p["u"], p["alpha"]
    along, across = u * math.cos(al), u * math.sin(al)
    a, b = _solve(2.0, 1.0, 2 * along - along, 0.5 * (along + along))
    return {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, -across)}, None


def _zn08(p: dict) -> tuple[dict, dict]:
    u = p["u"]
    theta = math.asin(1 / 2)  # r / 2r
    n, t = u * math.cos(theta), u * math.sin(theta)
    a, b = _solve(1.0, 1.0, n, 0.5 * n)
    sn, st = u * math.sin(theta), u * math.cos(theta)  # sin and cos swapped
    sb, sa = _solve(1.0, 1.0, sn, 0.5 * sn)  # (v_A)_2n - (v_B)_2n = e u_n: the roles exchanged
    return {"v_B2": abs(b), "v_A2": math.hypot(a, t)}, {"v_B2": abs(sb), "v_A2": math.hypot(sa, st)}


def _zn09(p: dict) -> tuple[dict, dict]:
    u, k, lam = p["u"], p["k"], p["lam"]
    v = (u + k * lam * u) / k  # m u + k m lam u = k m v, S at rest
    return {"e": v / (u - lam * u), "v_B2": v}, {"e": v / (u + lam * u)}  # the approach u + lam u


def _zn11(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    along = u * math.cos(math.radians(60))
    a, b = _solve(1.0, 1.0, along, e * along)
    return {"v_B2": b, "v_A2n": a}, None


SYMBOLIC_ZN: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zn01": _zn01,
    "zn03": _zn03,
    "zn08": _zn08,
    "zn09": _zn09,
    "zn11": _zn11,
}


def test_every_zn_case_is_worked_here() -> None:
    assert len(ZN_CASES) == 15
    assert {c.name[:4] for c in ZN_CASES} == set(NUMERIC_ZN) | set(SYMBOLIC_ZN)
    by_category = sorted(c.verdict.category for c in ZN_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZN_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in ZN_CASES}) == 15
    for case in ZN_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in ZN_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZN))
def test_the_zn_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZN[prefix](_given(case.verdict.problem))

    def agree(value: object, worked: object, what: str) -> None:
        if isinstance(value, str):
            assert value == worked, what
        else:
            assert value == pytest.approx(worked, rel=2e-4, abs=2e-4), what

    for name, value in case.verdict.values.items():
        agree(value, true[name], f"{case.name}: {name}")
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        agree(value, slipped[name], f"{case.name}: slip {name}")


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZN))
def test_the_zn_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for names in POINTS:
        true, slipped = SYMBOLIC_ZN[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
