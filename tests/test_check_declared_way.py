"""A positive way declared with an arrow between the bodies' letters (``+ve A→B``, ``+ve: B -> A``)
is the student's sign convention, and with a positive way declared, names met together (the
velocities after in one momentum line) are read in that convention, never all the other way round.
AQA M3 2007: A (0.3 kg) at 3 m/s toward B (0.2 kg) at 2 m/s, e = 0.8; by hand, from A toward B:
0.9 - 0.4 = 0.5 = 0.3v_A + 0.2v_B, v_B - v_A = 0.8(5) = 4 -> v_A = -0.6, v_B = 3.4."""

from __future__ import annotations

import pytest
from support.checked import solution, worst_lines

from derive.checking.context import Context
from derive.checking.naming import declarations

PROBLEM = "aqa-m3-2007-spheres-approach-head-on"


@pytest.mark.parametrize(
    ("said", "sign"),
    [("+ve A→B", 1), ("loc +ve A -> B, a b = loc cpts after", 1), ("+ve: B -> A", -1), ("B→A is +ve", -1)],
)
def test_an_arrow_between_the_bodies_says_the_positive_way(said: str, sign: int) -> None:
    ctx = Context(solution(PROBLEM), None)
    assert declarations(said, ctx, None)[1] == sign


@pytest.mark.parametrize("said", ["+ve B→A", "positive from B to A", "Taking B -> A as +ve"])
def test_a_derivation_in_the_declared_reverse_convention_is_correct(said: str) -> None:
    # B toward A positive: A before -3, B +2: -0.9 + 0.4 = -0.5 = 0.3x + 0.2y, y - x = 0.8(-3 - 2) = -4
    # -> 0.5x - 0.8 = -0.5, x = 0.6 (A's -0.6 turned), y = -3.4 (B's 3.4 turned)
    work = (
        f"{said}\n"
        "CLM: 0.3(-3) + 0.2(2) = 0.3x + 0.2y\n"
        "NEL: y - x = -0.8(3 + 2) = -4\n"
        "0.5x - 0.8 = -0.5, x = 0.6\n"
        "y = -3.4\n"
    )
    found = worst_lines(PROBLEM, work)
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["correct"] * 4


def test_b_s_sign_lost_under_a_declared_way_is_the_slip() -> None:
    # +ve A→B with B's 2 taken positive: 0.9 + 0.4 = 1.3, then x = 1, y = 5 carried
    work = "+ve A→B\nCLM: 0.3(3) + 0.2(2) = 0.3x + 0.2y\nNEL: y - x = 0.8(3 + 2) = 4\n0.5x + 0.8 = 1.3, x = 1\ny = 5\n"
    found = worst_lines(PROBLEM, work)
    assert found[2] == ("wrong", "b_sign")
    assert found[3][0] == "correct"
    assert [found[n][0] for n in (4, 5)] == ["carried", "carried"]
