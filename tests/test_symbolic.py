"""Issue #14: letters anywhere, "show that", ranges, conditions and derived quantities in
one plain problem file. Every expected value is worked by hand from equations (1)-(4)."""

from __future__ import annotations

import json
import math
import textwrap

import pytest
import sympy

import derive
from derive.problem import loads

TWO_SPHERES = """
title = "m and 2m"
kind = "direct"
{extra}
[given]
m_A = "m"
m_B = "2*m"
m = "kg"
e = "e"
v_A1 = "u"
v_B1 = "0 m/s"
u = "m/s"
"""


def solved(text: str) -> derive.Solution:
    return derive.solve(loads(textwrap.dedent(text), path="t.toml"))


def test_e_kept_as_a_letter_and_a_speed_given_as_a_letter() -> None:
    # (3) m u = m v_A2 + 2m v_B2, (4) v_B2 - v_A2 = e u  =>  v_A2 = u(1 - 2e)/3, v_B2 = u(1 + e)/3
    sol = solved(TWO_SPHERES.format(extra=""))
    u, e = sympy.Symbol("u", positive=True), sympy.Symbol("e", nonnegative=True)
    assert sympy.simplify(sol.results["v_A2"].partial - u * (1 - 2 * e) / 3) == 0
    assert sympy.simplify(sol.results["v_B2"].partial - u * (1 + e) / 3) == 0


def test_show_that_ends_as_required_or_gives_a_counterexample() -> None:
    extra = 'show = ["v_B2 = u*(1 + e)/3", "v_A2 = u*(1 - e)/3"]'
    sol = solved(TWO_SPHERES.format(extra=extra))
    right, wrong = sol.shown
    assert right.holds and right.how == "exactly"
    assert not wrong.holds and wrong.counterexample
    md = derive.render(sol, "md")
    assert "as required" in md and "it does not follow" in md
    doc = json.loads(derive.render(sol, "json"))
    assert [s["holds"] for s in doc["show"]] == [True, False]


def test_the_range_of_e_for_which_a_reverses() -> None:
    # v_A2 = u(1 - 2e)/3 < 0 with u > 0  <=>  e > 1/2
    sol = solved(TWO_SPHERES.format(extra='range = { of = "e", where = "v_A2 < 0" }'))
    (found,) = sol.ranges
    assert found.interval == sympy.Interval.Lopen(sympy.Rational(1, 2), 1)
    assert r"\frac{1}{2} < e" in derive.render(sol, "md")


def test_a_direction_after_the_impact_fixes_e_and_a_quantity_defined_from_the_results() -> None:
    # A (2 kg, 4 m/s at 30° from +n toward +t) hits B (2 kg) at rest; A leaves at 10° from +t.
    # v_A2t = 4 sin 30° = 2, v_A2n = 2 tan 10°, v_B2n = 4 cos 30° - v_A2n, e = (v_B2n - v_A2n)/(4 cos 30°)
    sol = solved(
        """
        title = "direction known"
        kind = "oblique"
        find = ["e", "fraction"]
        [given]
        m_A = "2 kg"
        m_B = "2 kg"
        e = "?"
        v_A1 = "4 m/s"
        v_B1 = "0 m/s"
        theta_A2 = "10 deg"
        [A]
        angle = "30 deg"
        from = "+n"
        toward = "+t"
        [define]
        fraction = "T_lost/T_1"
        """
    )
    a2n = 2 * math.tan(math.radians(10))
    b2n = 4 * math.cos(math.radians(30)) - a2n
    e = (b2n - a2n) / (4 * math.cos(math.radians(30)))
    assert float(sol.results["e"].value) == pytest.approx(e, rel=1e-12)
    t1 = 0.5 * 2 * 16
    t2 = 0.5 * 2 * (2**2 + a2n**2) + 0.5 * 2 * b2n**2
    assert float(sol.results["fraction"].value) == pytest.approx((t1 - t2) / t1, rel=1e-12)
    md = derive.render(sol, "md")
    assert r"v_{A2n} \cos {10^\circ} = v_{A2t} \sin {10^\circ} \tag{5}" in md
    assert "0.5236" not in md  # no radians in a substitution line


def test_a_chain_range_with_a_speed_kept_as_a_letter() -> None:
    # m then 3m at rest, e a letter: w_A - w_B = -e u, never positive: they never collide again
    md = derive.render(
        solved(
            """
            title = "again"
            kind = "chain"
            [given]
            u = "m/s"
            m = "kg"
            e = "?"
            [[stage]]
            type = "impact"
            kind = "direct"
            given = { m_A = "m", m_B = "3*m", e = "e", v_A1 = "u", v_B1 = "0 m/s" }
            results = { v_A2 = "w_A", v_B2 = "w_B" }
            [[stage]]
            type = "again"
            behind = "w_A"
            ahead = "w_B"
            range_of = "e"
            """
        ),
        "md",
    )
    assert "no value of $e$ at all" in md
    assert "1.0000" not in md
