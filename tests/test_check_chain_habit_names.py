"""A chain with more than one impact (A and B collide, then B strikes a wall or C): the habit's
names of the impact of A and B themselves (``v_A``, ``v_B`` after, ``v_A2``, ``(v_B)_1`` before) are
that impact's velocities, as in a chain of one impact, not names to infer from whatever values the
student's numbers make hold (a slip's numbers then "hold" with v_A2 read as e, or a reversed
restitution holds with v_A and v_B swapped). A line of givens before the working that names the
wall's e as ``e'`` states a given too.

Three particles (Edexcel M2): A at 7 onto B at rest, equal masses, one e. By hand: 7 = v_A + v_B,
v_B - v_A = 7e, so v_B = 7(1 + e)/2; reversed (v_A - v_B = 7e) is the slip, v_B = 7(1 - e)/2 from it.
AQA M3 2007: 0.3 kg at 3 and 0.2 kg at 2 toward each other, e = 0.8: 0.5 = 0.3 v_A2 + 0.2 v_B2,
v_B2 - v_A2 = 4, v_A2 = -0.6, v_B2 = 3.4; B's momentum taken +0.4: 1.3 = …, v_A2 = 1, v_B2 = 5.
"""

from __future__ import annotations

from support.checked import worst_lines

THREE = "chain-edexcel-m2-three-particles"
AGAIN = "chain-aqa-m3-2007-collide-again"

RIGHT = "CLM: m(7) = m v_A + m v_B\nNEL: v_B - v_A = 7e\nadding: 2 v_B = 7 + 7e, so v_B = 7(1 + e)/2\n"
REVERSED = "CLM: m(7) = m v_A + m v_B\nNEL: v_A - v_B = 7e\nadding: 2 v_A = 7 + 7e, so v_B = 7(1 - e)/2\n"
DATA = "Data: u_A = 3 m/s (right), u_B = 2 m/s (left), e = 0.8, e' = 0.7\n"


def test_the_first_impacts_habit_names_in_a_chain_of_two_impacts() -> None:
    assert [s for s, _ in worst_lines(THREE, RIGHT).values()] == ["correct"] * 3


def test_a_reversed_restitution_in_them_is_found() -> None:
    found = worst_lines(THREE, REVERSED)
    assert found[1][0] == "correct"
    assert found[2][0] == "wrong"
    assert found[3][0] == "carried"


def test_a_b_sign_in_the_momentum_is_found_and_carried() -> None:
    work = DATA + (
        "0.3(3) + 0.2(2) = 0.3 v_A2 + 0.2 v_B2\nv_B2 - v_A2 = 0.8(3 + 2) = 4\n"
        "1.3 = 0.3 v_A2 + 0.2(v_A2 + 4)\nv_A2 = 1, v_B2 = 5\n"
    )
    found = worst_lines(AGAIN, work)
    assert found[1][0] != "wrong"  # the givens, the wall's e as e'
    assert found[2][0] == "wrong"
    assert found[3][0] == "correct"
    assert found[4][0] == found[5][0] == "carried"


def test_the_same_worked_rightly() -> None:
    work = DATA + (
        "0.3(3) - 0.2(2) = 0.3 v_A2 + 0.2 v_B2\nv_B2 - v_A2 = 0.8(3 + 2) = 4\n"
        "0.5 = 0.3 v_A2 + 0.2(v_A2 + 4)\nv_A2 = -0.6, v_B2 = 3.4\n"
    )
    assert all(s == "correct" for s, _ in worst_lines(AGAIN, work).values())
