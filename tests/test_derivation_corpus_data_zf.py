"""The zf batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zf cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, an
impulse, Newton's law of restitution, components along and across the line of centres, a fall
and a rise, kinetic energy), with the student's slip made on purpose for the slip values.
Answers in letters (u, e, alpha, k, lam) are checked at a few points by evaluating the verdict's
closed form there (a small arithmetic reader, no eval). Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _bounce, _given, _solve
from test_derivation_corpus_data import closed_form as _closed_form

ZF_CASES = [c for c in CASES if c.name.startswith("zf")]
# (u, e, alpha in radians, k, lam) for the letters
POINTS = ((1.0, 0.5, 0.4, 2.0, 0.2), (2.0, 0.3, 0.7, 3.0, 0.3), (1.5, 0.9, 1.1, 1.5, 0.1))


def _case(prefix: str):
    return next(c for c in ZF_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _zf01(g: dict) -> tuple[dict, None]:
    impulse_on_a = g["m_A"] * (g["v_A2"] - g["v_A1"])
    v_b = g["v_B1"] - impulse_on_a / g["m_B"]  # Newton's third law
    assert g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] == pytest.approx(g["m_A"] * g["v_A2"] + g["m_B"] * v_b)
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _zf03(g: dict) -> tuple[dict, None]:
    v_b = (g["m_A"] * (g["v_A1"] - g["v_A2"]) + g["m_B"] * g["v_B1"]) / g["m_B"]
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}, None


def _zf05(g: dict) -> tuple[dict, None]:
    theta = math.radians(45)  # from the plane of contact (the problem's theta_1)
    n, t = math.sin(theta), math.cos(theta)  # per unit speed of the cue ball
    a, b = _solve(1.0, 1.0, n, g["e"] * n)
    return {"theta_A2": math.degrees(math.atan2(a, t)), "v_A2n_per_v_A1": a, "v_B2_per_v_A1": b}, None


def _zf07(g: dict) -> tuple[dict, dict]:
    def worked(a_n: float, a_t: float) -> dict:
        v_an, v_bn = _solve(1.0, 1.0, a_n + g["v_B1n"], g["e"] * (a_n - g["v_B1n"]))
        return {
            "v_A2n": v_an,
            "v_B2n": v_bn,
            "v_A2t": a_t,
            "v_B2": math.hypot(v_bn, g["v_B1t"]),
            "v_A2": math.hypot(v_an, a_t),
        }

    c, s = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    slipped = worked(s, c)  # sin and cos swapped
    del slipped["v_A2n"]  # -3 either way: that line is correct
    return worked(c, s), slipped


def _zf12(g: dict) -> tuple[dict, dict]:
    def worked(v_1_squared: float) -> dict:
        return _bounce(g, math.sqrt(v_1_squared))

    fall = 2 * g["g"] * g["h_0"]
    return worked(g["v_0"] ** 2 + fall), worked(g["v_0"] + fall)  # 5 not squared


def _zf13(g: dict) -> tuple[dict, dict]:
    gap = g["e"] * (g["v_A1"] - g["v_B1"])
    v_a, v_b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"], gap)
    # slip 1: the masses swapped -> m_B v_A1 + m_A v_B1 = m_B v_A + m_A v_B, v_B = v_A + gap
    p_swapped = g["m_B"] * g["v_A1"] + g["m_A"] * g["v_B1"]
    # slip 2: (m_A + m_B) v_A = p + m_A gap (the sign of m_A gap lost)
    s_a = (p_swapped + g["m_A"] * gap) / (g["m_A"] + g["m_B"])
    return {"v_A2": v_a, "v_B2": v_b}, {"v_A2": s_a, "v_B2": s_a + gap}


def _zf15(g: dict) -> tuple[dict, None]:
    u_a, u_b = _solve(g["m_A"], g["m_B"], g["m_A"] * g["v_A"] - g["m_B"] * g["v_B"], g["e"] * (g["v_A"] + g["v_B"]))
    w_b = -g["e_wall"] * u_b
    # both then move toward -n; B, nearer the wall, is behind A and faster when w_B < u_A
    return {"u_A": u_a, "u_B": u_b, "w_B": w_b, "again": "yes" if w_b < u_a else "no"}, None


NUMERIC_ZF: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zf01": _zf01,
    "zf03": _zf03,
    "zf05": _zf05,
    "zf07": _zf07,
    "zf12": _zf12,
    "zf13": _zf13,
    "zf15": _zf15,
}


# ---- letters: prefix -> point -> (true values, slip values or None), masses in units of m ----


def _zf02(p: dict) -> tuple[dict, None]:
    u, impulse = p["u"], 4 * p["u"]  # on the m particle, toward +n; on the 3m particle, against it
    v_a, v_b = (3 * 2 * u - impulse) / 3, -u + impulse
    assert 3 * 2 * u - u == pytest.approx(3 * v_a + v_b)  # momentum is conserved
    t_lost = 0.5 * 3 * (2 * u) ** 2 + 0.5 * u**2 - 0.5 * 3 * v_a**2 - 0.5 * v_b**2
    assert t_lost == pytest.approx(4 / 3 * u**2)  # the show-that holds for these velocities
    return {"v_A2": v_a, "v_B2": v_b}, None


def _zf04(p: dict) -> tuple[dict, None]:
    along, across = p["u"] * math.cos(p["alpha"]), p["u"] * math.sin(p["alpha"])
    a, _ = _solve(1.0, 1.0, along, p["e"] * along)
    return {"v_A2n": a, "v_A2t": across, "beta_A2": math.atan2(across, a)}, None


def _zf06(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 3.0, 2 * 5 * u, e * 5 * u)
    sa, sb = _solve(2.0, 3.0, 2 * 5 * u, -e * 5 * u)  # x - y = 5eu
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _zf08(p: dict) -> tuple[dict, dict]:
    u, k, lam = p["u"], p["k"], p["lam"]
    v = (u + k * lam * u) / k  # S (m) stops, T (km) takes the momentum
    return {"e": v / (u - lam * u), "v_B2": v}, {"e": v / (u + lam * u)}


def _zf09(p: dict) -> tuple[dict, dict]:
    def speed_b(along: float) -> float:
        return _solve(1.0, 1.0, along, p["e"] * along)[1]

    sixty = math.radians(60)
    return {"v_B2": speed_b(p["u"] * math.cos(sixty))}, {"v_B2": speed_b(p["u"] * math.sin(sixty))}


def _zf10(p: dict) -> tuple[dict, dict]:
    u, m_a, m_b = p["u"], 2.0, 1.0
    t_2 = 0.75 * u * u
    c = m_a / m_b  # Q's velocity y = c (u - x)
    qa, qb, qc = 0.5 * m_a + 0.5 * m_b * c * c, -m_b * c * c * u, 0.5 * m_b * c * c * u * u - t_2
    roots = [(-qb + sign * math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa) for sign in (1, -1)]
    x = next(r for r in roots if c * (u - r) >= r)  # Q ahead of P
    y = c * (u - x)
    return {"v_A2": x, "v_B2": y, "e": (y - x) / u}, {"e": u / (y - x)}


def _zf11(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], _given(_case("zf11").verdict.problem)["e"]  # e = 1/2 in the problem
    c, s = u * math.cos(p["alpha"]), u * math.sin(p["alpha"])
    a, b = _solve(2.0, 1.0, 2 * c - c, e * (c + c))
    sa, sb = _solve(2.0, 1.0, 2 * c + c, e * (c + c))  # B's +u cos(alpha) in the momentum only
    true = {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, s)}
    return true, {"v_A2n": sa, "v_B2n": sb, "v_B2": math.hypot(sb, s)}


def _zf14(p: dict) -> tuple[dict, dict]:
    thirty = math.radians(30)
    along = p["u"] * math.cos(thirty)
    _, b = _solve(1.0, 1.0, along, p["e"] * along)
    wrong_along = p["u"] * math.sin(thirty)  # slip 1
    _, sb = _solve(1.0, 1.0, wrong_along, p["e"] * wrong_along)
    return {"v_B2": b}, {"v_B2": 2 * sb}  # slip 2: 2 v_B not halved


SYMBOLIC_ZF: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zf02": _zf02,
    "zf04": _zf04,
    "zf06": _zf06,
    "zf08": _zf08,
    "zf09": _zf09,
    "zf10": _zf10,
    "zf11": _zf11,
    "zf14": _zf14,
}


def test_every_zf_case_is_worked_here() -> None:
    assert len(ZF_CASES) == 15
    assert {c.name[:4] for c in ZF_CASES} == set(NUMERIC_ZF) | set(SYMBOLIC_ZF)
    by_category = sorted(c.verdict.category for c in ZF_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in ZF_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in ZF_CASES}) == 15
    for case in ZF_CASES:
        slipped = case.verdict.category in ("one_slip", "two_slips") or case.verdict.summary != "0 wrong"
        assert bool(case.verdict.slip_values) == slipped, case.name


def _agrees(recorded: object, worked: object, label: str) -> None:
    if isinstance(recorded, str):
        assert recorded == worked, label
    else:
        assert recorded == pytest.approx(worked, rel=2e-4, abs=2e-4), label


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZF))
def test_the_zf_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZF[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        _agrees(value, true[name], f"{case.name}: {name}")
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        _agrees(value, slipped[name], f"{case.name}: slip {name}")


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZF))
def test_the_zf_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha, k, lam in POINTS:
        point = {"u": u, "e": e, "alpha": alpha, "k": k, "lam": lam}
        true, slipped = SYMBOLIC_ZF[prefix](point)
        for name, formula in case.verdict.values.items():
            assert _closed_form(str(formula), point) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _closed_form(str(formula), point) == pytest.approx(slipped[name], rel=1e-9), name
