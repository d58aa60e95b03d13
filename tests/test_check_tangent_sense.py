"""The tangent's sense is the student's to choose: t components before written all with the other
sign (no t way said in words) are derive's t taken the other way round, not sign slips.

The values are worked by hand from the problems' givens: notes-4c11 has v_A1 = 5 and v_B1 = 15 at
37.6 deg to n, derive's t so that v_A1t = 5 sin 37.6 = 3.05 and v_B1t = -15 sin 37.6 = -9.15; a
student whose t points the other way writes -3.05 and +9.15, and keeps them after the impact.
"""

from __future__ import annotations

from tests.support.checked import lines

TWO_SPHERES = """\
n from A toward B along the line of centres, t along the common tangent.

v_A1t = -5 sin 37.6 = -3.05 m/s
v_B1t = 15 sin 37.6 = 9.15 m/s
v_A2t = v_A1t = -3.05 m/s
v_B2t = v_B1t = 9.15 m/s
"""


def test_both_t_components_the_other_way_are_a_frame() -> None:
    got = lines("notes-4c11-two-spheres", TWO_SPHERES)
    assert {n: got[n][0] for n in (3, 4, 5, 6)} == {3: "correct", 4: "correct", 5: "correct", 6: "correct"}


# The cue ball (notes 4.C.12): A at v at 45 deg to n, derive's v_A1t = v sin 45 = (sqrt2/2) v;
# with t the other way the student writes -(sqrt2/2) v before and after, in LaTeX.
CUE_BALL = r"""
Axes: $n$ along the line of centres, $t$ along the plane of contact.
$$v_{A1t} = -v_{A1}\sin 45^\circ = -\tfrac{\sqrt2}{2}v_{A1}$$
$$v_{A2t} = v_{A1t} = -0.707\,v_{A1}$$
"""


def test_a_symbolic_t_component_the_other_way() -> None:
    got = lines("notes-4c12-cue-ball", CUE_BALL)
    assert got[3][0] == "correct" and got[4][0] == "correct"


# One t component before with derive's sign and the other with the other sign is a slip, not a
# frame: B's -9.15 is right, A's -3.05 is wrong (derive's v_A1t is +3.05 in the frame B's sets).
MIXED = """\
v_A1t = -3.05 m/s
v_B1t = -9.15 m/s
"""


def test_a_slip_in_one_t_component_is_still_a_slip() -> None:
    got = lines("notes-4c11-two-spheres", MIXED)
    assert got[1][0] == "wrong" and got[2][0] == "correct"
