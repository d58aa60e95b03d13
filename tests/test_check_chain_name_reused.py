"""A habit's name of a body's velocity carried on into the chain's next stage of that body: ``v_B = 3.4``
after the impact of A and B, then at the wall ``v_B = -2.38`` is B's velocity after the wall (the chain's
w_B), not its velocity after the first impact set to a wrong number (docs/checking.md, "Chains").

chain-aqa-m3-2007-collide-again by hand: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it, e = 0.8; then
B strikes a wall, e = 0.7. Momentum 0.3(3) + 0.2(-2) = 0.5 = 0.3 v_A + 0.2 v_B; restitution v_B - v_A =
0.8(3 + 2) = 4; so 0.5 = 0.5 v_A + 0.8, v_A = -0.6, v_B = 3.4. At the wall B comes back at 0.7(3.4) =
2.38: -2.38 with n from A toward B.

With the approach taken 3 - 2 (B's sign lost in the restitution): v_B - v_A = 0.8, 0.5 = 0.5 v_A + 0.16,
v_A = 0.68, v_B = 1.48; at the wall 0.7(1.48) = 1.036, so v_B = -1.036: carried."""

from __future__ import annotations

from support.checked import worst_lines

PROBLEM = "chain-aqa-m3-2007-collide-again"

RIGHT = r"""**First impact**
$0.3(3) + 0.2(-2) = 0.3v_A + 0.2v_B$
$v_B - v_A = 0.8(3 + 2) = 4$
$v_A = -0.6$, $v_B = 3.4$
**Wall**
$v_B = -0.7(3.4) = -2.38$
"""

SLIPPED = """first impact: 0.3*3 + 0.2*(-2) = 0.3 vA + 0.2 vB
NEL: vB - vA = 0.8*(3 - 2) = 0.8
0.5 = 0.5 vA + 0.16
vA = 0.68, vB = 1.48
B bounces off the wall: vB = -0.7*1.48 = -1.036
"""


def test_the_name_set_again_at_the_wall_is_the_velocity_after_the_wall() -> None:
    assert worst_lines(PROBLEM, RIGHT)[6][0] == "correct"


def test_the_name_set_again_after_a_slip_is_carried() -> None:
    got = worst_lines(PROBLEM, SLIPPED)
    assert got[2][0] == "wrong"
    assert got[5][0] == "carried"


def test_the_same_value_restated_keeps_the_name() -> None:
    """``v_B = 3.4`` said again is B's velocity after the first impact still: correct, not the wall's."""
    assert worst_lines(PROBLEM, RIGHT.replace("**Wall**\n", "so $v_B = 3.4$\n"))[5][0] == "correct"
