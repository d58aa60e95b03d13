"""Two fixes found by the symbolic library (issue #14): an unknown angle assumed acute keeps
only its acute root, and a "show that" about an unknown given (e = "?") uses the value found.
Every expected value is worked by hand from equations (1)-(4)."""

from __future__ import annotations

import math
import textwrap

import pytest

import derive
from derive.problem import loads

WALL = """
title = "wall keeps 60 percent"
kind = "oblique"
equations = ["T_2 = 3/5*T_1"]
[given]
m = "kg"
U = "m/s"
m_A = "m"
e = "3/4"
v_A1 = "U"
alpha = "? deg"
{assume}
[A]
angle = "alpha"
from = "+t"
toward = "+n"
[B]
fixed = true
"""


def solved(text: str) -> derive.Solution:
    return derive.solve(loads(textwrap.dedent(text), path="t.toml"))


def test_an_unknown_angle_assumed_acute_keeps_the_acute_root() -> None:
    # v_A2t = U cos(alpha), v_A2n = -3/4 U sin(alpha); T_2/T_1 = cos^2 + 9/16 sin^2 = 3/5
    # => sin^2(alpha) = 32/35, tan^2(alpha) = 32/3: alpha = 72.98 deg or 180 deg - that
    sol = solved(WALL.format(assume='[assume]\nalpha = "acute"'))
    assert float(sol.results["alpha"].value) == pytest.approx(math.degrees(math.atan(math.sqrt(32 / 3))), rel=1e-9)


def test_a_show_that_about_an_unknown_given_uses_its_value() -> None:
    # m u = 2m v_B2 with A brought to rest: v_B2 = u/2, e = (u/2 - 0)/u = 1/2
    sol = solved(
        """
        title = "A brought to rest"
        kind = "direct"
        show = ["e = 1/2", "e = 1/3"]
        [given]
        m = "kg"
        u = "m/s"
        m_A = "m"
        m_B = "2*m"
        e = "?"
        v_A1 = "u"
        v_B1 = 0
        v_A2 = 0
        """
    )
    right, wrong = sol.shown
    assert right.holds and right.how == "exactly"
    assert not wrong.holds


def test_roots_kept_for_the_process_give_the_same_solution_again() -> None:
    """SymPy's roots of an inverse system are kept for the process (issue #19: the wall above
    takes SymPy seconds); a second solve of the same problem, loaded again, works none out again
    (it reads them, or the set-up kept for an equal problem, physics/recent.py), and what the first
    solve did with its roots (dropping the unphysical ones, ordering) does not change them.
    Young & Freedman 8.96: m_B from the momentum of the pucks, worked by hand in the file's test."""
    from derive.physics import impact

    p = derive.load("young-freedman-8-96-pucks-find-mass")
    first = derive.solve(p)
    misses = impact._roots.cache_info().misses
    again = derive.solve(derive.load("young-freedman-8-96-pucks-find-mass"))
    assert impact._roots.cache_info().misses == misses
    assert derive.render(again, "md") == derive.render(first, "md")
    assert {k: r.value for k, r in again.results.items()} == {k: r.value for k, r in first.results.items()}
