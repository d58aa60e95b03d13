"""The xh batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the xh cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic, with the student's
slip made on purpose for the slip values. Answers in letters (u, e, alpha) are checked at a few
points. Nothing here runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _bounce, _given, _solve, closed_form

XH_CASES = [c for c in CASES if c.name.startswith("xh")]
# (u, e, alpha in radians)
POINTS = ((1.0, 0.5, 0.4), (2.0, 0.3, 0.9), (1.5, 0.9, 1.2))


def _case(prefix: str):
    return next(c for c in XH_CASES if c.name.startswith(prefix))


def _xh02(g: dict) -> tuple[dict, None]:
    b_n = g["v_B1t"] / math.tan(math.radians(45))
    a_n = (g["m_A"] * g["v_A1n"] - g["m_B"] * b_n) / g["m_A"]
    return {"e": (b_n - a_n) / g["v_A1n"], "v_B2n": b_n, "v_A2": abs(a_n)}, None


def _xh03(g: dict) -> tuple[dict, dict]:
    th = math.radians(g["theta_1"])
    t, n = math.cos(th), math.sin(th)  # per unit v
    a, b = _solve(1.0, 1.0, n, g["e"] * n)
    sa, sb = _solve(1.0, 1.0, n, -g["e"] * n)  # a - b = e n
    true = {"theta_A2": math.degrees(math.atan(a / t)), "v_A2n_per_v_A1": a, "v_B2_per_v_A1": b}
    slip = {"theta_A2": math.degrees(math.atan(sa / t)), "v_A2n_per_v_A1": sa, "v_B2_per_v_A1": sb}
    return true, slip


def _xh04(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]

    def worked(v_a: float) -> dict:
        v_b = (p - g["m_A"] * v_a) / g["m_B"]
        return {"v_B2": v_b, "e": (v_b - v_a) / (g["v_A1"] - g["v_B1"])}

    return worked(g["v_A2"]), worked(-g["v_A2"])  # A's -0.2 written +0.2


def _xh05(g: dict) -> tuple[dict, dict]:
    a_n = g["v_A1"] * math.cos(math.radians(60))
    a_t = g["v_A1"] * math.sin(math.radians(60))
    p = g["m_A"] * a_n + g["m_B"] * g["v_B1n"]
    gap = g["e"] * (a_n - g["v_B1n"])

    def worked(a: float) -> dict:
        return {"v_A2": math.hypot(a, a_t), "angle_loc": math.degrees(math.atan(a_t / abs(a))), "v_B2n": a + gap}

    a, _ = _solve(g["m_A"], g["m_B"], p, gap)
    slipped = (p - g["m_B"] * gap + 2) / (g["m_A"] + g["m_B"])  # -8 - 18 taken as -24
    return worked(a), worked(slipped)


def _xh06(g: dict) -> tuple[dict, None]:
    c, s = math.cos(math.radians(g["theta"])), math.sin(math.radians(g["theta"]))
    a_n, a_t, b_n, b_t = g["v_A1"] * c, g["v_A1"] * s, -g["v_B1"] * c, -g["v_B1"] * s
    a, b = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n, g["e"] * (a_n - b_n))
    return {
        "v_A2t": a_t,
        "v_B2t": b_t,
        "v_A2n": a,
        "v_B2n": b,
        "v_A2": math.hypot(a, a_t),
        "v_B2": math.hypot(b, b_t),
    }, None


def _xh07(g: dict) -> tuple[dict, None]:
    p = g["m_A"] * g["v_A1n"] + g["m_B"] * g["v_B1n"]
    a, b = _solve(g["m_A"], g["m_B"], p, g["e"] * (g["v_A1n"] - g["v_B1n"]))
    return {"v_A2n": a, "v_B2n": b, "v_B2": abs(b), "v_A2": math.hypot(a, g["v_A1t"])}, None


def _xh08(g: dict) -> tuple[dict, dict]:
    def worked(along: float, across: float) -> dict:
        # m_A u + m_B along = m_B w, w = e (u - along)
        u = (g["m_B"] * along + g["m_B"] * g["e"] * along) / (g["m_B"] * g["e"] - g["m_A"])
        w = g["e"] * (u - along)
        return {"v_A1n": u, "v_B2": math.hypot(w, across)}

    c, s = math.cos(math.radians(60)), math.sin(math.radians(60))
    return worked(g["v_B1"] * c, g["v_B1"] * s), worked(g["v_B1"] * s, g["v_B1"] * c)


def _xh09(g: dict) -> tuple[dict, None]:
    a_n, a_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    a, b = _solve(1.0, 1.0, a_n + g["v_B1n"], g["e"] * (a_n - g["v_B1n"]))
    return {"v_B2": math.hypot(b, g["v_B1t"]), "v_A2": math.hypot(a, a_t)}, None


def _xh10(g: dict) -> tuple[dict, dict]:
    tan = 3.0
    # tan(phi) = e tan(theta) = 1/tan(theta); slip: tan(phi) = e / tan(theta) = 1/tan(theta)
    return {"e": 1 / tan**2}, {"e": 1.0}


def _xh12(g: dict) -> tuple[dict, dict]:
    r = math.radians
    a_n, a_t = g["v_A1"] * math.cos(r(25)), g["v_A1"] * math.sin(r(25))
    b_n, b_t = g["v_B1"] * math.cos(r(100)), g["v_B1"] * math.sin(r(100))
    gap = g["e"] * (a_n - b_n)

    def worked(p: float) -> dict:
        a, b = _solve(g["m_A"], g["m_B"], p, gap)
        return {
            "v_A2n": a,
            "v_B2n": b,
            "v_A2": math.hypot(a, a_t),
            "v_B2": math.hypot(b, b_t),
            "psi_A2": math.degrees(math.atan2(a_t, a)) + g["phi_n"],
        }

    slipped = worked(g["m_A"] * a_n - g["m_B"] * b_n)  # the 3(-19.101) added
    del slipped["psi_A2"]  # the angle line is the second slip
    return worked(g["m_A"] * a_n + g["m_B"] * b_n), slipped


def _xh14(g: dict) -> tuple[dict, None]:
    v_1 = math.sqrt(2 * g["g"] * g["h"])
    mass = g["m_block"] + g["m_pan"]
    v = g["m_block"] * v_1 / mass
    k = g["k"] * 1000
    x0 = g["m_pan"] * g["g"] / k
    a, b, c = k / 2, k * x0 - mass * g["g"], -0.5 * mass * v * v
    x = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)
    return {"v_1": v_1, "V": v, "x": x}, None


def _xh15(g: dict) -> tuple[dict, dict]:
    true = _bounce(g, math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * g["h_0"]))
    return true, _bounce(g, math.sqrt(g["v_0"] ** 2 + 2 * g["g"] * 1.5))  # 1.6 m copied as 1.5


NUMERIC_XH: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xh02": _xh02,
    "xh03": _xh03,
    "xh04": _xh04,
    "xh05": _xh05,
    "xh06": _xh06,
    "xh07": _xh07,
    "xh08": _xh08,
    "xh09": _xh09,
    "xh10": _xh10,
    "xh12": _xh12,
    "xh14": _xh14,
    "xh15": _xh15,
}


def _xh01(p: dict) -> tuple[dict, dict]:
    e, al = p["e"], p["alpha"]
    t, n = math.cos(al), math.sin(al)
    return {"beta": math.atan(e * n / t)}, {"beta": math.atan(n / (e * t))}


def _xh11(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    psi = math.radians(30)
    x, _ = _solve(1.0, 1.0, u * math.cos(psi), e * u * math.cos(psi))
    deflection = math.atan2(u * math.sin(psi), x) - psi
    assert closed_form("atan((1 + e)*sqrt(3)/(5 - 3*e))", p) == pytest.approx(deflection, rel=1e-9)
    return {"v_A2n": x}, None


def _xh13(p: dict) -> tuple[dict, dict]:
    u, al = p["u"], p["alpha"]
    c, s = math.cos(al), math.sin(al)
    a, b = _solve(2.0, 1.0, 2 * u * c - u * c, 0.5 * 2 * u * c)
    sa, sb = _solve(1.0, 2.0, u * c - 2 * u * c, 0.5 * 2 * u * c)  # masses swapped
    return {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, u * s)}, {
        "v_A2n": sa,
        "v_B2n": sb,
        "v_B2": math.hypot(sb, u * s),
    }


SYMBOLIC_XH: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "xh01": _xh01,
    "xh11": _xh11,
    "xh13": _xh13,
}


def test_every_xh_case_is_worked_here() -> None:
    assert len(XH_CASES) == 15
    assert {c.name[:4] for c in XH_CASES} == set(NUMERIC_XH) | set(SYMBOLIC_XH)
    by_category = sorted(c.verdict.category for c in XH_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in XH_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    assert len({c.verdict.problem for c in XH_CASES}) == 15
    for case in XH_CASES:
        assert bool(case.verdict.slip_values) == (case.verdict.summary != "0 wrong"), case.name
    one_slips = [s.name for c in XH_CASES if c.verdict.category == "one_slip" for s in c.verdict.slips]
    assert len(one_slips) == len(set(one_slips)) == 6


@pytest.mark.parametrize("prefix", sorted(NUMERIC_XH))
def test_the_xh_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_XH[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_XH))
def test_the_xh_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha in POINTS:
        names = {"u": u, "e": e, "alpha": alpha}
        true, slipped = SYMBOLIC_XH[prefix](names)
        for name, formula in case.verdict.values.items():
            assert closed_form(str(formula), names) == pytest.approx(true[name], rel=1e-9, abs=1e-12), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert closed_form(str(formula), names) == pytest.approx(slipped[name], rel=1e-9, abs=1e-12), name
