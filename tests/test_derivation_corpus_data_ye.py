"""The ye batch of typed derivations (held out): its true values and the values its carried lines hold.

Every `values` and `slip_values` entry of the ye cases in tests/data/derivations/verdicts.toml is
worked again here from the problem file's givens with plain Python arithmetic (momentum along the
line of centres, Newton's law of restitution, components of a velocity, kinetic energy, a skid to
rest), with the student's slip made on purpose for the slip values. Answers in letters (u, e, v,
alpha, e_1) are checked at a few points by working the problem numerically there. Nothing here
runs derive's checker.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from test_derivation_corpus_data import CASES, _given, _solve, batch_shape, letters_agree, numbers_agree

YE_CASES = [c for c in CASES if c.name.startswith("ye")]
# (u, e, v, alpha in radians, e_1) for the letters (e_1 unused: the cushion's e_1 is written e)
POINTS = ((1.0, 0.5, 1.0, 0.4, 0.5), (2.0, 0.3, 0.7, 0.9, 0.25), (1.5, 0.9, 3.0, 1.2, 0.8))


def _case(prefix: str):
    return next(c for c in YE_CASES if c.name.startswith(prefix))


# ---- numeric problems: prefix -> (true values, slip values or None) from the givens ----


def _ye03(g: dict) -> tuple[dict, None]:
    a_n, a_t = g["v_A1"] * math.cos(math.radians(30)), g["v_A1"] * math.sin(math.radians(30))
    v_an, v_bn = _solve(1.0, 1.0, a_n + g["v_B1n"], g["e"] * (a_n - g["v_B1n"]))
    return {"v_A2n": v_an, "v_B2n": v_bn, "v_A2t": a_t, "v_A2": math.hypot(v_an, a_t), "v_B2": abs(v_bn)}, None


def _ye04(g: dict) -> tuple[dict, None]:
    p = g["m_A"] * g["v_A1"]
    mass = g["m_A"] + g["m_B"]
    t_1, t_2 = 0.5 * g["m_A"] * g["v_A1"] ** 2, p * p / (2 * mass)
    return {"v_B2": p / mass, "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}, None


def _ye06(g: dict) -> tuple[dict, dict]:
    n, t = math.sin(math.radians(g["theta_1"])), math.cos(math.radians(g["theta_1"]))  # per unit v_A1

    def worked(gap: float) -> dict:
        a, b = _solve(1.0, 1.0, n, gap)
        return {"theta_A2": math.degrees(math.atan2(a, t)), "v_A2n_per_v_A1": a, "v_B2_per_v_A1": b}

    return worked(g["e"] * n), worked(-g["e"] * n)  # slip: vAn2 - vBn2 = e vAn1


def _ye07(g: dict) -> tuple[dict, dict]:
    a_n, a_t = g["v_A1"] * math.cos(math.radians(60)), g["v_A1"] * math.sin(math.radians(60))
    gap = g["e"] * (a_n - g["v_B1n"])

    def worked(b_n_in_momentum: float) -> dict:
        x, y = _solve(g["m_A"], g["m_B"], g["m_A"] * a_n + g["m_B"] * b_n_in_momentum, gap)
        return {"v_A2n": x, "v_B2n": y, "v_A2": math.hypot(x, a_t), "angle_loc": math.degrees(math.atan2(a_t, abs(x)))}

    return worked(g["v_B1n"]), worked(-g["v_B1n"])  # slip: B's +6 in the momentum equation only


def _ye11(g: dict) -> tuple[dict, dict]:
    def worked(half: float) -> dict:
        t_1, t_2 = half * g["m_A"] * g["v_A1"] ** 2, half * g["m_A"] * g["v_A2"] ** 2
        return {"e": -g["v_A2"] / g["v_A1"], "T_1": t_1, "T_2": t_2, "T_lost": t_1 - t_2}

    return worked(0.5), worked(1.0)  # slip: KE = m v^2


def _ye13(g: dict) -> tuple[dict, dict]:
    def worked(v_b: float, power: float) -> dict:
        m_b = g["m_A"] * (g["v_A1"] - g["v_A2"]) / v_b
        t_2 = 0.5 * g["m_A"] * g["v_A2"] ** 2 + 0.5 * m_b * v_b**power
        return {"v_B2": v_b, "m_B": m_b, "T_1": 0.5 * g["m_A"] * g["v_A1"] ** 2, "T_2": t_2}  # K's: comments only

    true = worked(g["v_A2"] + g["e"] * (g["v_A1"] - g["v_B1"]), 2)
    return true, worked(0.205, 1)  # slip 1: 0.050 + 0.200 = 0.205; slip 2: 1/2 m v


def _ye14(g: dict) -> tuple[dict, None]:
    u_a, u_b, s_a, s_b = g["v_A"], -g["v_B"], g["s_A"], g["s_B"]
    e = (s_b - s_a) / (u_a - u_b)
    m_a = g["m_B"] * (s_b - u_b) / (u_a - s_a)
    w = g["I_w"] / g["m_B"] - s_b  # rebound speed
    return {"e": e, "m_A": m_a, "u_B": s_b, "w_B": -w, "e_wall": w / s_b}, None


def _ye15(g: dict) -> tuple[dict, dict]:
    def worked(factor: float) -> dict:
        v = math.sqrt(factor * g["mu_k"] * g["g"] * g["d_skid"])
        return {"V": v, "v_car": (g["m_car"] + g["m_suv"]) * v / g["m_car"]}

    return worked(2.0), worked(1.0)  # slip: no 1/2 in the KE


NUMERIC_YE: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "ye03": _ye03,
    "ye04": _ye04,
    "ye06": _ye06,
    "ye07": _ye07,
    "ye11": _ye11,
    "ye13": _ye13,
    "ye14": _ye14,
    "ye15": _ye15,
}


# ---- letters: prefix -> names -> (true values, slip values or None), masses in units of m ----


def _ye01(p: dict) -> tuple[dict, None]:
    u = p["u"]
    # 2x + y = 2u and x^2 + y^2/2 = 3u^2/4: 12x^2 - 16ux + 5u^2 = 0, the root with y >= x
    roots = [(16 * u + s * math.sqrt(256 * u * u - 240 * u * u)) / 24 for s in (1, -1)]
    x = next(r for r in roots if 2 * u - 2 * r >= r)
    y = 2 * u - 2 * x
    return {"v_A2": x, "v_B2": y, "e": (y - x) / u}, None


def _ye02(p: dict) -> tuple[dict, None]:
    u = p["u"]
    impulse = (u / 3 + u) / 1.5  # per unit m: I/m - u + I/(2m) = u/3
    return {"v_A2": u - impulse / 2, "v_B2": impulse}, None


def _ye05(p: dict) -> tuple[dict, None]:
    along = p["u"] * math.cos(math.radians(30))
    a, b = _solve(1.0, 1.0, along, p["e"] * along)
    return {"v_B2": b, "v_A2n": a}, None


def _ye08(p: dict) -> tuple[dict, dict]:
    u, e, al = 1.0, p["e"], p["alpha"]  # the question's e_1, called e in the verdict
    true = math.atan2(e * u * math.sin(al), u * math.cos(al))
    slipped = math.atan2(u * math.sin(al), e * u * math.cos(al))  # e on the component along DC
    return {"beta": true}, {"beta": slipped}


def _ye09(p: dict) -> tuple[dict, dict]:
    along = p["u"] * math.cos(math.radians(60))
    a, b = _solve(1.0, 1.0, along, p["e"] * along)
    sa, sb = _solve(1.0, 1.0, along, -p["e"] * along)  # vA - vB = e u/2
    return {"v_B2": b, "v_A2n": a}, {"v_B2": sb, "v_A2n": sa}


def _ye10(p: dict) -> tuple[dict, dict]:
    v = p["v"]
    after_a, after_b, e = -v, 1.5 * v, 0.2
    gap = (after_b - after_a) / e  # p + q, the approach speed

    def worked(m_a: float, m_b: float) -> dict:
        # m_a p - m_b q = m_a after_a + m_b after_b and p + q = gap
        rhs = m_a * after_a + m_b * after_b
        speed_p = (rhs + m_b * gap) / (m_a + m_b)
        return {"v_A1": speed_p, "v_B1": -(gap - speed_p)}

    return worked(2.0, 3.0), worked(3.0, 2.0)


def _ye12(p: dict) -> tuple[dict, dict]:
    u, e = p["u"], p["e"]
    x, y = _solve(2.0, 3.0, 10 * u, 5 * e * u)
    slipped_y = (10 * u + 5 * e * u) / 5  # 2(y - 5eu) taken as 2y - 5eu
    slipped_x = slipped_y - 5 * e * u - 2 * e * u  # eu - 5eu written -6eu
    return {"v_A2": x, "v_B2": y}, {"v_A2": slipped_x, "v_B2": slipped_y}


SYMBOLIC_YE: dict[str, Callable[[dict], tuple[dict, dict | None]]] = {
    "ye01": _ye01,
    "ye02": _ye02,
    "ye05": _ye05,
    "ye08": _ye08,
    "ye09": _ye09,
    "ye10": _ye10,
    "ye12": _ye12,
}


def test_the_ye_batch_has_its_shape() -> None:
    batch_shape(YE_CASES, set(NUMERIC_YE) | set(SYMBOLIC_YE))


@pytest.mark.parametrize("prefix", sorted(NUMERIC_YE))
def test_the_ye_numeric_values(prefix: str) -> None:
    case = _case(prefix)
    true, slipped = NUMERIC_YE[prefix](_given(case.verdict.problem))
    numbers_agree(case, true, slipped)


@pytest.mark.parametrize("prefix", sorted(SYMBOLIC_YE))
def test_the_ye_values_in_letters(prefix: str) -> None:
    case = _case(prefix)
    for u, e, v, alpha, e_1 in POINTS:
        names = {"u": u, "e": e, "v": v, "alpha": alpha, "e_1": e_1}
        true, slipped = SYMBOLIC_YE[prefix](names)
        letters_agree(case, names, true, slipped)
