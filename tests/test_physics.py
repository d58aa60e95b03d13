"""The physics: the notes' numbers, closed forms derived by hand, and invariants.

Every expected number here comes from the notes (Examples 4.C.11 and 4.C.12),
from a formula derived by hand from momentum and restitution, or from a
conservation law; none is derive's own output pasted back.
"""

from __future__ import annotations

import math
import textwrap

import pytest
import sympy
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import derive
from derive.numbers import format_number
from derive.problem import loads
from derive.symbols import symbol


def shown(solution: derive.Solution, name: str, digits: int = 3) -> str:
    return format_number(solution.results[name].value, digits)


@pytest.fixture(scope="module")
def ex11() -> derive.Solution:
    return derive.solve(derive.load("notes-4c11-two-spheres"))


@pytest.fixture(scope="module")
def ex12() -> derive.Solution:
    return derive.solve(derive.load("notes-4c12-cue-ball"))


# ------------------------------------------------------------------ the notes


@pytest.mark.parametrize(
    ("name", "notes"),
    [("v_A2t", "3.05"), ("v_B2t", "-9.15"), ("v_A2n", "-1.11"), ("v_B2n", "8.40")],
    ids=["v_A2t", "v_B2t", "v_A2n", "v_B2n"],
)
def test_example_4c11_matches_the_notes(ex11: derive.Solution, name: str, notes: str) -> None:
    # Notes, Example 4.C.11: V_A2 = 3.05 e_t - 1.11 e_n, V_B2 = -9.15 e_t + 8.4 e_n (m/s).
    assert shown(ex11, name) == notes


def test_example_4c11_by_hand_from_momentum_and_restitution(ex11: derive.Solution) -> None:
    # Independent arithmetic with math.cos: (3) and (4) solved by hand.
    th = math.radians(37.6)
    mA, mB, e, vA, vB = 20.0, 5.0, 0.6, 5.0, 15.0
    vA1n, vB1n = vA * math.cos(th), -vB * math.cos(th)
    p = mA * vA1n + mB * vB1n  # 19.81 (the notes print 19.8, from 79.2 - 59.4)
    k = e * (vA1n - vB1n)  # 9.51 (the notes print 9.5)
    vA2n = (p - mB * k) / (mA + mB)
    vB2n = vA2n + k
    assert float(ex11.results["v_A2n"].value) == pytest.approx(vA2n, rel=1e-12)
    assert float(ex11.results["v_B2n"].value) == pytest.approx(vB2n, rel=1e-12)
    assert p == pytest.approx(19.81, abs=0.005)  # not the notes' slip 79.2 - 59.5


def test_example_4c11_energy_lost_from_the_reduced_mass_formula(ex11: derive.Solution) -> None:
    # T_lost = (1/2) m_A m_B/(m_A+m_B) (1 - e^2) (v_A1n - v_B1n)^2, a consequence of (3) and (4).
    th = math.radians(37.6)
    mu = 20 * 5 / 25
    approach = (5 + 15) * math.cos(th)
    expected = 0.5 * mu * (1 - 0.6**2) * approach**2
    assert float(ex11.results["T_lost"].value) == pytest.approx(expected, rel=1e-12)
    assert float(ex11.results["T_1"].value) == pytest.approx(0.5 * 20 * 25 + 0.5 * 5 * 225)


def test_example_4c12_closed_forms(ex12: derive.Solution) -> None:
    # Notes, Example 4.C.12: V_B2 = (sqrt2/4)(1+e) V_A1 (4), V_A2n = (sqrt2/4)(1-e) V_A1 (5),
    # V_A2t = (sqrt2/2) V_A1 (2). Their theta_1 = 45 deg is substituted in the notes.
    e, v, th = symbol("e", "nonnegative"), symbol("v_A1", "positive"), symbol("theta_1")
    at45 = {th: sympy.pi / 4}
    r = ex12.results
    assert sympy.simplify(r["v_B2n"].closed.xreplace(at45) - sympy.sqrt(2) / 4 * (1 + e) * v) == 0
    assert sympy.simplify(r["v_A2n"].closed.xreplace(at45) - sympy.sqrt(2) / 4 * (1 - e) * v) == 0
    assert sympy.simplify(r["v_A2t"].closed.xreplace(at45) - sympy.sqrt(2) / 2 * v) == 0
    assert r["v_B2t"].closed == 0


def test_example_4c12_rebound_angle(ex12: derive.Solution) -> None:
    # Notes: theta_2 = tan^-1(0.05) = 2.86 deg, independent of v_A1 and m.
    assert ex12.results["theta_A2"].value is not None
    assert shown(ex12, "theta_A2") == "2.86"
    assert float(ex12.results["theta_A2"].value) == pytest.approx(math.degrees(math.atan(0.05)), rel=1e-12)
    assert ex12.results["v_B2n"].value is None  # depends on the symbolic v_A1


def test_closed_forms_of_a_general_oblique_impact() -> None:
    # By hand from (3) and (4): v_A2n = (m_A v_A1n + m_B v_B1n - e m_B (v_A1n - v_B1n)) / (m_A + m_B)
    #                          v_B2n = (m_A v_A1n + m_B v_B1n + e m_A (v_A1n - v_B1n)) / (m_A + m_B)
    prob = loads(
        textwrap.dedent(
            """
            title = "all symbolic"
            kind = "oblique"
            [given]
            m_A = "kg"
            m_B = "kg"
            e = "1"
            v_A1n = "m/s"
            v_A1t = "m/s"
            v_B1n = "m/s"
            v_B1t = "m/s"
            """
        ).replace('e = "1"', "e = 0.5"),
        path="t.toml",
    )
    sol = derive.solve(prob)
    m_A, m_B = symbol("m_A", "positive"), symbol("m_B", "positive")
    a, b = symbol("v_A1n"), symbol("v_B1n")
    e = sympy.Rational(1, 2)
    exp_A = (m_A * a + m_B * b - e * m_B * (a - b)) / (m_A + m_B)
    exp_B = (m_A * a + m_B * b + e * m_A * (a - b)) / (m_A + m_B)
    got_A = sol.results["v_A2n"].partial
    got_B = sol.results["v_B2n"].partial
    assert sympy.simplify(got_A - exp_A) == 0
    assert sympy.simplify(got_B - exp_B) == 0
    assert sympy.simplify(sol.results["v_A2t"].partial - symbol("v_A1t")) == 0


# ------------------------------------------------------------------ invariants

masses = st.floats(min_value=0.1, max_value=100, allow_nan=False).map(lambda x: round(x, 3))
speeds = st.floats(min_value=0, max_value=50, allow_nan=False).map(lambda x: round(x, 3))
angles = st.floats(min_value=0, max_value=89, allow_nan=False).map(lambda x: round(x, 2))
restitution = st.floats(min_value=0, max_value=1, allow_nan=False).map(lambda x: round(x, 3))


def oblique_problem(mA: float, mB: float, e: float, vA: float, vB: float, thA: float, thB: float) -> str:
    return textwrap.dedent(
        f"""
        title = "random"
        kind = "oblique"
        [given]
        m_A = "{mA} kg"
        m_B = "{mB} kg"
        e = {e}
        v_A1 = "{vA} m/s"
        v_B1 = "{vB} m/s"
        theta_A1 = "{thA} deg"
        theta_B1 = "{thB} deg"
        [A]
        angle = "theta_A1"
        from = "+n"
        toward = "+t"
        [B]
        angle = "theta_B1"
        from = "-n"
        toward = "+t"
        """
    )


def values(sol: derive.Solution) -> dict[str, float]:
    return {k: float(r.value) for k, r in sol.results.items() if r.value is not None}


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(masses, masses, restitution, speeds, speeds, angles, angles)
def test_invariants_of_oblique_impacts(mA, mB, e, vA, vB, thA, thB) -> None:
    vA1n, vA1t = vA * math.cos(math.radians(thA)), vA * math.sin(math.radians(thA))
    vB1n, vB1t = -vB * math.cos(math.radians(thB)), vB * math.sin(math.radians(thB))
    if vA1n - vB1n <= 1e-6:
        return  # no approach: the loader refuses it (tested elsewhere)
    r = values(derive.solve(loads(oblique_problem(mA, mB, e, vA, vB, thA, thB), path="t.toml")))
    scale = max(1.0, abs(vA1n), abs(vB1n), abs(vA1t), abs(vB1t))
    # (3) momentum of A + B along n
    assert mA * r["v_A2n"] + mB * r["v_B2n"] == pytest.approx(mA * vA1n + mB * vB1n, abs=1e-9 * scale * (mA + mB))
    # (1), (2) each body's t velocity
    assert r["v_A2t"] == pytest.approx(vA1t, abs=1e-9 * scale)
    assert r["v_B2t"] == pytest.approx(vB1t, abs=1e-9 * scale)
    # (4) restitution, normal components only
    assert r["v_B2n"] - r["v_A2n"] == pytest.approx(e * (vA1n - vB1n), abs=1e-9 * scale)
    # kinetic energy never rises for 0 <= e <= 1
    T1 = 0.5 * mA * (vA1n**2 + vA1t**2) + 0.5 * mB * (vB1n**2 + vB1t**2)
    T2 = 0.5 * mA * (r["v_A2n"] ** 2 + r["v_A2t"] ** 2) + 0.5 * mB * (r["v_B2n"] ** 2 + r["v_B2t"] ** 2)
    assert T2 <= T1 * (1 + 1e-12) + 1e-12
    assert r["T_lost"] == pytest.approx(T1 - T2, abs=1e-9 * max(1.0, T1))
    assert r["T_lost"] >= -1e-9 * max(1.0, T1)


def direct_problem(mA: float, mB: float, e: float, vA: float, vB: float) -> str:
    return textwrap.dedent(
        f"""
        title = "random direct"
        kind = "direct"
        [given]
        m_A = "{mA} kg"
        m_B = "{mB} kg"
        e = {e}
        v_A1 = "{vA} m/s"
        v_B1 = "{vB} m/s"
        """
    )


signed = st.floats(min_value=-50, max_value=50, allow_nan=False).map(lambda x: round(x, 3))


@settings(max_examples=25, deadline=None)
@given(masses, masses, restitution, signed, signed)
def test_swapping_A_and_B_with_n_reversed_changes_nothing(mA, mB, e, vA, vB) -> None:
    if vA - vB <= 1e-6:
        return
    r = values(derive.solve(loads(direct_problem(mA, mB, e, vA, vB), path="t.toml")))
    # B becomes A, n reversed: velocities change sign.
    s = values(derive.solve(loads(direct_problem(mB, mA, e, -vB, -vA), path="t.toml")))
    assert s["v_A2"] == pytest.approx(-r["v_B2"], abs=1e-9 * max(1, abs(vA), abs(vB)))
    assert s["v_B2"] == pytest.approx(-r["v_A2"], abs=1e-9 * max(1, abs(vA), abs(vB)))
    assert s["T_lost"] == pytest.approx(r["T_lost"], rel=1e-9, abs=1e-9)
    # and the direct invariants
    assert mA * r["v_A2"] + mB * r["v_B2"] == pytest.approx(
        mA * vA + mB * vB, abs=1e-9 * (mA + mB) * max(1, abs(vA), abs(vB))
    )
    assert r["v_B2"] - r["v_A2"] == pytest.approx(e * (vA - vB), abs=1e-9 * max(1, abs(vA), abs(vB)))


def test_perfectly_elastic_conserves_energy_and_plastic_moves_together() -> None:
    elastic = values(derive.solve(loads(direct_problem(2, 3, 1, 4, -1), path="t.toml")))
    assert elastic["T_lost"] == pytest.approx(0, abs=1e-12)
    # Textbook result for e = 1: v_A2 = ((mA - mB) vA + 2 mB vB)/(mA + mB) = (-4 - 6)/5 = -2
    assert elastic["v_A2"] == pytest.approx(-2)
    assert elastic["v_B2"] == pytest.approx(3)
    plastic = values(derive.solve(loads(direct_problem(2, 3, 0, 4, -1), path="t.toml")))
    # e = 0: common velocity (mA vA + mB vB)/(mA + mB) = (8 - 3)/5 = 1
    assert plastic["v_A2"] == pytest.approx(1)
    assert plastic["v_B2"] == pytest.approx(1)


#: Bundled single impacts of every kind: oblique, letters, an unknown given, a wall, a line
#: of impact at an angle (x-y components), a quantity the file defines, "show that".
READ_IN_ANY_ORDER = (
    "notes-4c11-two-spheres",
    "notes-4c12-cue-ball",
    "ocr-mei-fmm-2024-disc-a-stops",
    "ocr-m2-2012-particle-hits-wall",
    "beer-johnston-13-13-railroad-cars-find-e",
    "fisicalab-example-7-normal-at-20deg",
    "ocr-mei-fmm-2022-offset-spheres-symbolic",
    "edexcel-m4-undated-q3-deflected-through-theta-line-at-30deg",
    "cie-9231-p2-2012-june-q2-impulse-4mu-show-ke-lost",
)


@pytest.mark.parametrize("name", READ_IN_ANY_ORDER)
def test_results_are_the_same_in_whatever_order_they_are_read(name: str) -> None:
    """A result is worked out when it is first read (``derive check`` reads only the ones it is
    asked about, issue #19). The order of reading changes nothing: the results read last to
    first have the names, closed forms and values they have read first to last."""
    from derive.physics.outcome import solve_impact

    forward = solve_impact(derive.load(name)).results
    names = list(forward)
    first = [str((forward[n].closed, forward[n].value, forward[n].partial)) for n in names]
    backward = solve_impact(derive.load(name)).results
    last = [str((backward[n].closed, backward[n].value, backward[n].partial)) for n in reversed(names)]
    assert list(backward) == names
    assert first == last[::-1]


def test_a_body_at_rest_after_the_impact_has_no_direction() -> None:
    """OCR MEI FM 2024: A is at rest just after the collision (the file's v_A2n = 0, no t
    component): its direction is not a result; B's is."""
    from derive.physics.outcome import solve_impact

    found = solve_impact(derive.load("ocr-mei-fmm-2024-disc-a-stops")).results
    assert "theta_A2" not in found and found.get("beta_A2") is None
    assert "theta_B2" in found and "beta_B2" in list(found)
