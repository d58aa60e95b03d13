""" "Forward" said to be the positive way ("(forward +)", "Forward $= +$", "+ve forwards") is the
way the bodies go before the impact, a direction derive knows from the problem: it is the
student's declared convention, never turned round by what a later slip makes hold.

OpenStax satellites (e = 1): A 4000 kg at 0.250 m/s onto B 7500 kg at rest. True: v_A = -3500/11500
(0.250) = -0.0761, v_B = 8000/11500 (0.250) = 0.174. The masses swapped in the momentum:
1875 = 7500 v_A + 4000 v_B with v_B - v_A = 0.250 (right) gives 11500 v_A = 875, v_A = +0.0761 (the
true value's size: read with the frame turned round it would hold, which it must not), v_B = 0.326.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

import derive
from derive.checking.context import Context
from derive.checking.forwardway import forward_said, forward_sign

SATELLITES = "openstax-cp-8-satellites-elastic"

PLAIN = """+ve forwards (the way the 4000 kg satellite goes)
CLM: 7500(0.250) = 7500 vA + 4000 vB
elastic: vB - vA = 0.250
1875 = 7500 vA + 4000(vA + 0.250) = 11500 vA + 1000
vA = 875/11500 = 0.0761 m/s
vB = 0.0761 + 0.250 = 0.326 m/s
"""

LATEX = r"""Taking forward $= +$, with $v_1'$ and $v_2'$ the velocities after.
\[ 7.50\times10^{3}(0.250) = 7.50\times10^{3}\,v_1' + 4.00\times10^{3}\,v_2' \]
\[ v_2' - v_1' = 0.250 \]
\[ v_1' = \frac{1875 - 1000}{11500} = 0.0761 \]
\[ v_2' = 0.0761 + 0.250 = 0.326 \]
"""


@pytest.mark.parametrize("work", [PLAIN, LATEX], ids=["plain", "latex"])
def test_forward_positive_keeps_the_frame_a_masses_slip_would_turn_round(work: str) -> None:
    found = worst_lines(SATELLITES, work)
    assert found[2] == ("wrong", "masses_swapped")
    assert found[3][0] == "correct"  # the restitution is right in the student's own frame
    assert all(found[n][0] == "carried" for n in found if n > 3)


@pytest.mark.parametrize(
    ("line", "said"),
    [
        ("Momentum (forward +):", True),
        ("Forward $= +$", True),
        ("forwards = +ve", True),
        ("Forward positive", True),
        ("Forwards (A's direction) = positive", True),
        ("positive direction: forward", True),
        ("(A still moving forwards)", False),
        ("B goes forward at 3.1 m/s", False),
        ("impulse forwards", False),
        ("forward + 3 = 5", False),
        ("forward positive, backward negative", True),
        ("backwards = +, forward = +", False),
    ],
)
def test_forward_said_as_the_positive_way(line: str, said: bool) -> None:
    assert forward_said(line) is said


@pytest.mark.parametrize(
    ("problem", "sign"),
    [
        (SATELLITES, 1),  # A onto B at rest, along +n
        ("byjus-4kg-ball-catches-8kg-ball", 1),  # both along +n: A catches B
        ("edexcel-m2-ball-rebounds-from-wall", 1),  # toward the wall
        ("aqa-m3-2007-spheres-approach-head-on", 0),  # toward each other: no one way forward
        ("chain-aqa-m3-2007-collide-again", 0),  # a chain: left to the values
    ],
)
def test_the_way_forward_is_the_bodies_way_before_the_impact(problem: str, sign: int) -> None:
    assert forward_sign(Context(derive.solve(derive.load(problem)), None)) == sign
