"""The md batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the md cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum, Newton's
law of restitution, kinetic energy, impulse, a fall and a rise), with the student's slip made on
purpose for the slip values (a calculator in radian mode, components rounded to 2 s.f., a sign, a
reversed ratio, a k not cancelled, sin for cos, masses swapped, 5^2 written as 5). Answers in
letters (u, e, k, lam) are checked at a few points (energies in units of m). Nothing here runs
derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _bounce, _formula, _given, _solve

MD_CASES = [c for c in CASES if c.name.startswith("md")]
POINTS = ((1.0, 0.5, 3.0, 0.2), (2.0, 0.3, 1.5, 0.4), (1.5, 0.9, 4.0, 0.1))  # (u, e, k, lam)


def _case(prefix: str):
    return next(c for c in MD_CASES if c.name.startswith(prefix))


def _ke(m: float, *speeds: float) -> float:
    return sum(0.5 * m * s * s for s in speeds)


def _deg(angle: float) -> float:
    return math.radians(angle)


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _after_a(g: dict, v_b: float | None = None) -> dict:
    """A's velocity after is given: B's from momentum, e from separation over approach."""
    if v_b is None:
        v_b = (g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"] - g["m_A"] * g["v_A2"]) / g["m_B"]
    return {"v_B2": v_b, "e": (v_b - g["v_A2"]) / (g["v_A1"] - g["v_B1"])}


def _md01(g: dict) -> tuple[dict, None]:
    return _after_a(g), None


def _md02(g: dict) -> tuple[dict, None]:
    v_b = g["v_A1"] - g["v_B1"] + g["v_A2"]  # e = 1: the relative velocity reverses
    m_b = g["m_A"] * (g["v_A1"] - g["v_A2"]) / v_b
    assert _ke(g["m_A"], g["v_A1"]) == pytest.approx(_ke(g["m_A"], g["v_A2"]) + _ke(m_b, v_b))
    return {"v_B2": v_b, "m_B": m_b}, None


def _md04(g: dict) -> tuple[dict, None]:
    e = -g["v_A2"] / g["v_A1"]
    t_1, t_2 = _ke(g["m_A"], g["v_A1"]), _ke(g["m_A"], g["v_A2"])
    return {"e": e, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _md05(g: dict) -> tuple[dict, None]:
    a_n, a_t = g["v_A1"] * math.cos(_deg(30)), g["v_A1"] * math.sin(_deg(30))
    v_an, v_bn = _solve(1.0, 1.0, a_n + g["v_B1n"], g["e"] * (a_n - g["v_B1n"]))  # equal masses m
    return {
        "v_A2n": v_an,
        "v_B2n": v_bn,
        "v_A2t": a_t,
        "v_B2": math.hypot(v_bn, g["v_B1t"]),
        "v_A2": math.hypot(v_an, a_t),
    }, None


def _md06(g: dict) -> tuple[dict, dict]:
    n, t = math.sin(_deg(g["theta_1"])), math.cos(_deg(g["theta_1"]))  # A's speed 1, theta_1 to the plane
    v_an, v_bn = _solve(1.0, 1.0, n, g["e"] * n)
    true = {"theta_A2": math.degrees(math.atan2(v_an, t)), "v_A2n_per_v_A1": v_an, "v_B2_per_v_A1": v_bn}
    return true, {"theta_A2": math.atan(v_an / t)}  # radians read as degrees


def _fisicalab(g: dict, a: tuple[float, float], b: tuple[float, float]) -> dict:
    v_an, v_bn = _solve(g["m_A"], g["m_B"], g["m_A"] * a[0] + g["m_B"] * b[0], g["e"] * (a[0] - b[0]))
    return {"v_A2n": v_an, "v_B2n": v_bn, "v_A2": math.hypot(v_an, a[1]), "v_B2": math.hypot(v_bn, b[1])}


def _md07(g: dict) -> tuple[dict, dict]:
    to_a, to_b = _deg(45 - g["phi_n"]), _deg(120 - g["phi_n"])
    a = (g["v_A1"] * math.cos(to_a), g["v_A1"] * math.sin(to_a))
    b = (g["v_B1"] * math.cos(to_b), g["v_B1"] * math.sin(to_b))
    rounded = [float(f"{x:.2g}") for x in (*a, *b)]  # 2 s.f.: 73, 34, -19, 110
    assert rounded == [73.0, 34.0, -19.0, 110.0]
    return _fisicalab(g, a, b), _fisicalab(g, tuple(rounded[:2]), tuple(rounded[2:]))


def _md09(g: dict) -> tuple[dict, dict]:
    true = _after_a(g)
    return true, {"e": 1 / true["e"]}


def _md13(g: dict) -> tuple[dict, dict]:
    true = _after_a(g)
    slipped_v = true["v_B2"] - 0.5  # 7.1/2 written 3.05
    return true, {"v_B2": slipped_v, "e": (slipped_v + g["v_A2"]) / (g["v_A1"] - g["v_B1"])}


def _md14(g: dict) -> tuple[dict, None]:
    mass = g["m_bullet"] + g["m_block"]
    p = g["m_bullet"] * g["v_0"]
    big_v = p / mass
    t_after = _ke(mass, big_v)
    assert t_after == pytest.approx(p * p / (2 * mass))
    return {"V": big_v, "T_after": t_after, "h_2": t_after / (mass * g["g"])}, None


def _md15(g: dict) -> tuple[dict, dict]:
    def worked(v_1_squared: float) -> dict:
        return _bounce(g, math.sqrt(v_1_squared))

    fall = 2 * g["g"] * g["h_0"]
    return worked(g["v_0"] ** 2 + fall), worked(g["v_0"] + fall)  # 5^2 written as 5


NUMERIC_MD: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "md01": _md01,
    "md02": _md02,
    "md04": _md04,
    "md05": _md05,
    "md06": _md06,
    "md07": _md07,
    "md09": _md09,
    "md13": _md13,
    "md14": _md14,
    "md15": _md15,
}


# ---- letters: prefix -> (u, e, k, lam) -> (true values, slip values or None), masses in units of m ----


def _md03(u: float, _e: float, _k: float, _lam: float) -> tuple[dict, None]:
    # y = 2u - 2x into x^2 + (1/2) y^2 = (3/4) u^2: 3x^2 - 4ux + 1.25u^2 = 0, the root with y > x
    disc = math.sqrt(16 * u * u - 4 * 3 * 1.25 * u * u)
    roots = [(4 * u + s * disc) / 6 for s in (1, -1)]
    x = next(r for r in roots if 2 * u - 2 * r > r)
    y = 2 * u - 2 * x
    assert _ke(2.0, x) + _ke(1.0, y) == pytest.approx(0.75 * u * u)
    return {"v_A2": x, "v_B2": y, "e": (y - x) / u}, None


def _md08(u: float, _e: float, _k: float, _lam: float) -> tuple[dict, dict]:
    def worked(u_b: float) -> dict:
        v_a = 2 * u - 4 * u / 3  # 3(v1 - 2u) = -4u
        v_b = u_b + 4 * u  # 1(v2 - u_b) = 4u
        return {"v_A2": v_a, "v_B2": v_b, "T_lost": _ke(3.0, 2 * u) + _ke(1.0, u) - _ke(3.0, v_a) - _ke(1.0, v_b)}

    true, slipped = worked(-u), worked(u)  # B's velocity before taken +u
    assert true["T_lost"] == pytest.approx(4 * u * u / 3)  # the loss the question shows (per m)
    return true, {"v_B2": slipped["v_B2"], "T_lost": slipped["T_lost"]}


def _md10(u: float, e: float, k: float, lam: float) -> tuple[dict, dict]:
    v = (u + k * lam * u) / k  # m u + k m lam u = k m v
    slipped = u / k + k * lam * u  # the k of k lam u not cancelled
    approach = u - lam * u
    return {"v_B2": v, "e": v / approach}, {"v_B2": slipped, "e": slipped / approach}


def _md11(u: float, e: float, _k: float, _lam: float) -> tuple[dict, dict]:
    def worked(along: float) -> dict:
        a, b = _solve(1.0, 1.0, along, e * along)
        return {"v_A2n": a, "v_B2n": b}

    return worked(u * math.cos(_deg(30))), worked(u * math.sin(_deg(30)))


def _md12(u: float, e: float, _k: float, _lam: float) -> tuple[dict, dict]:
    a, b = _solve(2.0, 3.0, 2 * 5 * u, 5 * e * u)
    sa, _sb = _solve(3.0, 2.0, 3 * 5 * u, 5 * e * u)  # masses swapped
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sa + 4 * e * u + 5 * e * u}  # -2eu taken as +2eu


SYMBOLIC_MD: dict[str, Callable[[float, float, float, float], tuple[dict, dict | None]]] = {
    "md03": _md03,
    "md08": _md08,
    "md10": _md10,
    "md11": _md11,
    "md12": _md12,
}


def test_every_md_case_is_worked_here() -> None:
    assert len(MD_CASES) == 15
    assert {c.name[:4] for c in MD_CASES} == set(NUMERIC_MD) | set(SYMBOLIC_MD)
    by_category = sorted(c.verdict.category for c in MD_CASES)
    assert by_category.count("correct") == 5 and by_category.count("one_slip") == 6
    assert by_category.count("two_slips") == 2 and by_category.count("chain") == 2
    assert sorted(c.verdict.format for c in MD_CASES) == ["md"] * 5 + ["tex"] * 5 + ["txt"] * 5
    for case in MD_CASES:
        slipped = case.verdict.category in ("one_slip", "two_slips") or case.verdict.summary != "0 wrong"
        assert bool(case.verdict.slip_values) == slipped, case.name


@pytest.mark.parametrize("prefix", sorted(NUMERIC_MD))
def test_the_md_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_MD[prefix](_given(case.verdict.problem))
    for name, value in case.verdict.values.items():
        assert value == pytest.approx(true[name], rel=2e-4, abs=2e-4), f"{case.name}: {name}"
    assert bool(case.verdict.slip_values) == (slipped is not None), case.name
    for name, value in (case.verdict.slip_values or {}).items():
        assert value == pytest.approx(slipped[name], rel=2e-4, abs=2e-4), f"{case.name}: slip {name}"


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_MD))
def test_the_md_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, k, lam in POINTS:
        true, slipped = SYMBOLIC_MD[prefix](u, e, k, lam)
        letters = {"k": k, "lam": lam}
        for name, formula in case.verdict.values.items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(true[name], rel=1e-9), name
        assert bool(case.verdict.slip_values) == (slipped is not None), case.name
        for name, formula in (case.verdict.slip_values or {}).items():
            assert _formula(str(formula), u, e, letters) == pytest.approx(slipped[name], rel=1e-9), name
