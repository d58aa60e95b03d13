"""The zi batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the zi cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, components of a velocity, the zero-momentum frame,
an impulse on each body, a skid and a swing), with the student's slip made on purpose for the slip
values. Answers in letters (u, e, alpha, k, lambda) are checked at a few points. Nothing here runs
derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, letters_agree, numbers_agree

ZI_CASES = [c for c in CASES if c.name.startswith("zi")]
# (u, e, alpha in radians, k, lambda); lambda < 1/2 and k > 1 as the question has
POINTS = ((1.0, 0.5, 0.4, 2.0, 0.2), (2.0, 0.3, 0.9, 3.0, 0.1), (1.5, 0.9, 1.2, 1.5, 0.4))


def _case(prefix: str):
    return next(c for c in ZI_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _zi05(g: dict) -> tuple[dict, None]:
    b_n, b_t = g["v_B1"] * math.cos(math.radians(60)), g["v_B1"] * math.sin(math.radians(60))
    # m_A a + m_B b_n = m_B b and b = e (a - b_n): m_A a + m_B b_n = m_B e a - m_B e b_n
    a = (g["m_B"] * b_n + g["m_B"] * g["e"] * b_n) / (g["m_B"] * g["e"] - g["m_A"])
    b = g["e"] * (a - b_n)
    beta = math.degrees(math.atan(b_t / b))
    return {"v_A1n": a, "v_B2": math.sqrt(b * b + b_t * b_t), "beta_B2": beta, "delta_B": 60 - beta}, None


def _zi08(g: dict) -> tuple[dict, dict]:
    def worked(a_n: float, a_t: float) -> dict:
        b_n = g["v_B1n"]
        v_an, v_bn = _solve(1.0, 1.0, a_n + b_n, g["e"] * (a_n - b_n))
        return {"v_A2n": v_an, "v_A2t": a_t, "v_B2n": v_bn, "v_B2": abs(v_bn), "v_A2": math.hypot(v_an, a_t)}

    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    return worked(g["v_A1"] * c, g["v_A1"] * s), worked(g["v_A1"] * s, g["v_A1"] * c)  # sin for cos


def _zi10(g: dict) -> tuple[dict, dict]:
    p = g["m_A"] * g["v_A1"] + g["m_B"] * g["v_B1"]
    gap = g["e"] * (g["v_A1"] - g["v_B1"])
    true = _solve(g["m_A"], g["m_B"], p, gap)
    slipped = _solve(g["m_B"], g["m_A"], p, gap)  # 0.2 v_A + 0.3 v_B after
    return {"v_A2": true[0], "v_B2": true[1]}, {"v_A2": slipped[0], "v_B2": slipped[1]}


def _zi12(g: dict) -> tuple[dict, None]:
    m_a, m_b = g["m_A"] / 1000, g["m_B"] / 1000  # grams to kg
    # m_a u = m_a a + m_b (a + u): a = u (m_a - m_b)/(m_a + m_b)
    u = g["v_A1"]
    a = u * (m_a - m_b) / (m_a + m_b)
    return {"v_A2": a, "v_B2": a + u}, None


def _zi14(g: dict) -> tuple[dict, None]:
    mass = g["m_bullet"] + g["m_block"]
    v = g["m_bullet"] * g["v_0"] / mass
    kinetic = 0.5 * mass * v * v
    return {"V": v, "T_after": kinetic, "h_2": kinetic / (mass * g["g"])}, None


def _zi15(g: dict) -> tuple[dict, dict]:
    def worked(mu: float) -> dict:
        v = math.sqrt(2 * mu * g["g"] * g["d_skid"])
        return {"V": v, "v_car": (g["m_car"] + g["m_suv"]) * v / g["m_car"]}

    return worked(g["mu_k"]), worked(g["mu_k"] / 10)  # 0.80 copied as 0.08


NUMERIC_ZI: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zi05": _zi05,
    "zi08": _zi08,
    "zi10": _zi10,
    "zi12": _zi12,
    "zi14": _zi14,
    "zi15": _zi15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _zi01(p: dict) -> tuple[dict, None]:
    u, e = p["u"], p["e"]
    along = u * math.sqrt(3) / 2
    v_1, _ = _solve(1.0, 1.0, along, e * along)
    # the compound-angle result agrees with the angle worked directly
    theta = math.atan2(u / 2, v_1) - math.radians(30)
    assert math.tan(theta) == pytest.approx(math.sqrt(3) * (1 + e) / (5 - 3 * e))
    return {"v_A2n": v_1}, None


def _zi02(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(2.0, 3.0, 10 * u, 5 * e * u)
    sa, sb = _solve(2.0, 3.0, 10 * u, -5 * e * u)  # v_1f - v_2f = 5eu
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _zi03(p: dict) -> tuple[dict, None]:
    u = p["u"]
    cm = (2 * 2 * u) / 3
    e = 2 / 3
    return {"v_A2": cm - e * (2 * u - cm), "v_B2": cm - e * (0 - cm)}, None


def _zi04(p: dict) -> tuple[dict, dict]:
    u, al = p["u"], p["alpha"]
    c, s = u * math.cos(al), u * math.sin(al)
    a, b = _solve(2.0, 1.0, 2 * c - c, 0.5 * (c + c))
    sa, sb = _solve(2.0, 1.0, 2 * c + c, 0.5 * (c + c))  # B's momentum taken +m u cos
    return (
        {"v_A2n": a, "v_B2n": b, "v_B2": math.hypot(b, s)},
        {"v_A2n": sa, "v_B2n": sb, "v_B2": math.hypot(sb, s)},
    )


def _zi06(p: dict) -> tuple[dict, dict]:
    u, k, lam = p["u"], p["k"], p["lam"]

    def worked(w: float) -> dict:
        return {"v_B2": w, "e": (w - 0) / (u - lam * u)}

    return worked((u + k * lam * u) / k), worked(u * (1 + lam) / k)  # k dropped from k lam


def _zi07(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 7.0, 5 * u + 7 * u, e * (5 * u - u))
    sa, sb = _solve(1.0, 7.0, 13 * u, e * (5 * u + u))  # 12u written 13u; approach 6u
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _zi09(p: dict) -> tuple[dict, None]:
    u, e, al = p["u"], p["e"], p["alpha"]
    parallel, perpendicular = u * math.cos(al), e * u * math.sin(al)
    return {"beta": math.atan2(perpendicular, parallel)}, None


def _zi11(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    a, b = _solve(1.0, 2.0, u, e * u)
    _, sb = _solve(1.0, 2.0, u, -e * u)  # v_1f - v_2f = eu
    assert sb + e * u == pytest.approx(u * (1 + 2 * e) / 3)  # v_1f given slip 1 alone
    sa = (u + 3 * e * u) / 3  # u(1 - e)/3 + eu: the -e of (1 - e) dropped in adding, u(1 + 3e)/3
    return {"v_A2": a, "v_B2": b}, {"v_A2": sa, "v_B2": sb}


def _zi13(p: dict) -> tuple[dict, dict]:
    u, m = p["u"], 1.0
    w = -u + 4 * m * u / m
    v = 2 * u - 4 * m * u / (3 * m)
    t1 = 3 * m * (2 * u) ** 2 + m * u**2  # no 1/2
    t2 = 3 * m * v**2 + m * w**2
    assert 0.5 * (t1 - t2) == pytest.approx(4 / 3 * m * u * u)  # with the 1/2, the printed loss
    return {"v_A2": v, "v_B2": w}, {"T_1": t1, "T_2": t2, "T_lost": t1 - t2}


SYMBOLIC_ZI: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "zi01": _zi01,
    "zi02": _zi02,
    "zi03": _zi03,
    "zi04": _zi04,
    "zi06": _zi06,
    "zi07": _zi07,
    "zi09": _zi09,
    "zi11": _zi11,
    "zi13": _zi13,
}


def test_the_zi_batch_has_its_shape() -> None:
    batch_shape(ZI_CASES, set(NUMERIC_ZI) | set(SYMBOLIC_ZI))


@pytest.mark.parametrize("prefix", sorted(NUMERIC_ZI))
def test_the_zi_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_ZI[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_ZI))
def test_the_zi_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, alpha, k, lam in POINTS:
        names = {"u": u, "e": e, "alpha": alpha, "k": k, "lam": lam, "m": 1.0}
        true, slipped = SYMBOLIC_ZI[prefix](names)
        letters_agree(case, names, true, slipped)
