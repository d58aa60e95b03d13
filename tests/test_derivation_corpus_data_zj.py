"""The zj batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zj cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, a wall's rebound, kinetic energy, a fall and a rise),
with the student's slip made on purpose for the slip values. Answers in letters (u, e, k, lambda)
are checked at a few points against the numbers worked there. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _bounce, _given, _solve, closed_form

ZJ_CASES = [c for c in CASES if c.name.startswith("zj")]
# (u, e, k, lambda) for the letters; lambda < 1/2 and k > 1 as the questions have
POINTS = ((1.0, 0.5, 2.0, 0.2), (2.0, 0.3, 3.0, 0.1), (1.5, 0.9, 1.5, 0.4))


def _case(prefix: str):
    return next(c for c in ZJ_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _zj01(g: dict) -> tuple[dict, None]:
    v = -g["e"] * g["v_A1"]
    t_1, t_2 = 0.5 * g["m_A"] * g["v_A1"] ** 2, 0.5 * g["m_A"] * v**2
    return {"v_A2": v, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _zj03(g: dict) -> tuple[dict, None]:
    m_a, m_b = g["m_A"] * 1000, g["m_B"] * 1000  # Mg to kg, as the student writes them
    v_a = (m_a * g["v_A1"] + m_b * g["v_B1"] - m_b * g["v_B2"]) / m_a
    t_1 = 0.5 * m_a * g["v_A1"] ** 2
    t_2 = 0.5 * m_a * v_a**2 + 0.5 * m_b * g["v_B2"] ** 2
    e = (g["v_B2"] - v_a) / (g["v_A1"] - g["v_B1"])
    return {"v_A2": v_a, "e": e, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _zj07(g: dict) -> tuple[dict, dict]:
    e = (g["v_B2"] - g["v_A2"]) / (g["v_A1"] - g["v_B1"])

    def mass(v_b1: float) -> float:  # m v_A1 + m_B v_B1 = m v_A2 + m_B v_B2
        return g["m_B"] * (g["v_B2"] - v_b1) / (g["v_A1"] - g["v_A2"])

    return {"e": e, "m_A": mass(g["v_B1"])}, {"m_A": mass(-g["v_B1"])}  # B's -1.5 written +1.5


def _zj08(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"]
    true = (p - g["m_A"] * g["v_A2"]) / g["v_B2"]
    e = (g["v_B2"] - g["v_A2"]) / (g["v_A1"] - g["v_B1"])
    slipped = (p - g["m_A"] * g["v_A2"] + 1000) / g["v_B2"]  # 12000 - 7200 taken as 5800
    return {"m_B": true, "e": e}, {"m_B": slipped}


def _zj11(g: dict) -> tuple[dict, dict]:
    mass = g["m_A"] + g["m_B"]
    v = g["m_A"] * g["v_A1"] / mass

    def energies(half: float) -> dict:
        t_1, t_2 = half * g["m_A"] * g["v_A1"] ** 2, half * mass * v * v
        return {"T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    return {"v_B2": v, **energies(0.5)}, energies(1.0)  # the 1/2 left out


def _zj12(g: dict) -> tuple[dict, dict]:
    alpha = math.radians(g["alpha"])
    b_n, b_t = -g["u_B"] * math.cos(alpha), g["u_B"] * math.sin(alpha)
    b_n2 = b_t * math.tan(alpha)
    a_n2 = g["v_A1n"] + b_n - b_n2  # equal masses
    e = (b_n2 - a_n2) / (g["v_A1n"] - b_n)
    true = {"v_B2": b_t / math.sin(math.radians(90) - alpha), "v_A2n": a_n2, "e": e}
    slipped = {
        "v_B2": b_t / math.cos(math.radians(90) - alpha),  # over cos 60 for sin 60
        "e": (b_n2 - a_n2) / (g["v_A1n"] + 0.5916),  # 0.5196 copied as 0.5916
    }
    return true, slipped


def _zj14(g: dict) -> tuple[dict, None]:
    u_a, u_b, s_a, s_b = g["v_A"], -g["v_B"], g["s_A"], g["s_B"]
    e = (s_b - s_a) / (u_a - u_b)
    m_a = g["m_B"] * (s_b - u_b) / (u_a - s_a)
    w = g["I_w"] / g["m_B"] - s_b  # the rebound speed from the impulse
    return {"e": e, "m_A": m_a, "u_B": s_b, "w_B": -w, "e_wall": w / s_b}, None


def _zj15(g: dict) -> tuple[dict, dict]:
    true = _bounce(g, math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"]))
    return true, _bounce(g, math.sqrt(g["v_0"] ** 2 + g["g"] * g["h_0"]))  # 2(9.8)(1.6) as 15.68


NUMERIC_ZJ: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zj01": _zj01,
    "zj03": _zj03,
    "zj07": _zj07,
    "zj08": _zj08,
    "zj11": _zj11,
    "zj12": _zj12,
    "zj14": _zj14,
    "zj15": _zj15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _zj02(p: dict) -> tuple[dict, None]:
    u = p["u"]
    # half the energy lost: (9/10)(1 - e^2) = 1/2 (reduced mass 9m/10)
    e = math.sqrt(1 - 0.5 / 0.9)
    a, b = _solve(1.0, 9.0, u, e * u)
    assert 0.5 * a * a + 4.5 * b * b == pytest.approx(0.25 * u * u)
    return {"e": e, "v_A2": a, "v_B2": b}, None


def _zj04(p: dict) -> tuple[dict, None]:
    u = p["u"]
    a, b = _solve(2.0, 1.0, 4 * u, (2 / 3) * 2 * u)
    return {"v_A2": a, "v_B2": b}, None


def _zj05(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 2.0, u, e * u)
    return {"v_A2": a, "v_B2": b}, None


def _zj06(p: dict) -> tuple[dict, dict]:
    u, k, lam = p["u"], p["k"], p["lam"]
    v = (u + k * lam * u) / k  # S at rest after
    return {"e": v / (u - lam * u), "v_B2": v}, {"e": (u - lam * u) / v}  # upside down


def _zj09(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 7.0, 12 * u, e * 4 * u)
    sa, sb = _solve(1.0, 7.0, 12 * u, e * 6 * u)  # approach 5u + u
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _zj10(p: dict) -> tuple[dict, dict]:
    u = p["u"]

    def worked(along: float, across: float) -> dict:
        a, b = _solve(1.0, 1.0, along, 0.5 * along)
        return {"v_B2": b, "v_A2n": a, "v_A2": math.hypot(a, across)}

    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))  # sin(theta) = r/2r
    return worked(u * c, u * s), worked(u * s, u * c)


def _zj13(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(5.0, 2.0, 5 * u - 4 * u, e * 3 * u)
    # slip 1: vb - va = -eu (va = vb + eu); slip 2: 7vb = u + 5eu, not u - 5eu
    sb = (u + 5 * e * u) / 7
    return {"v_A2": a, "v_B2": b}, {"v_A2": sb + e * u, "v_B2": sb}


SYMBOLIC_ZJ: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zj02": _zj02,
    "zj04": _zj04,
    "zj05": _zj05,
    "zj06": _zj06,
    "zj09": _zj09,
    "zj10": _zj10,
    "zj13": _zj13,
}


def test_every_zj_case_is_worked_here() -> None:
    assert len(ZJ_CASES) == 15
    assert {c.name[:4] for c in ZJ_CASES} == set(NUMERIC_ZJ) | set(SYMBOLIC_ZJ)
    by_category = sorted(c.verdict.category for c in ZJ_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZJ_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in ZJ_CASES}) == 15
    for case in ZJ_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in ZJ_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZJ))
def test_the_zj_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZJ[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZJ))
def test_the_zj_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, k, lam in POINTS:
        names = {"u": u, "e": e, "k": k, "lam": lam}
        true, slipped = SYMBOLIC_ZJ[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
