"""A name declared by saying what a quantity *is*, "B's velocity after is v1", "the speed of A after
is u2 (unknown)", and then used as the student types it, ``v1`` (read ``v_1``): the declaration
stands over the habit that would make ``v_1`` A's velocity after.

Worked by hand (byjus-4kg-ball-catches-8kg-ball): A (4 kg) at 12 m/s catches B (8 kg) at 4 m/s,
e = 0.5. Momentum 48 + 32 = 80 = 4 v_A + 8 v_B; restitution v_B − v_A = 0.5 (12 − 4) = 4, so
12 v_A + 32 = 80: v_A = 4 m/s, v_B = 8 m/s.
"""

from __future__ import annotations

from support.checked import worst_lines

BYJUS = "byjus-4kg-ball-catches-8kg-ball"
#: v1 is B's (against the habit v1 = A after), v2 is A's.
SWAPPED = (
    "Positive in the direction of motion. B's velocity after is v1. A's velocity after is v2 (to be found).\n"
    "4(12) + 8(4) = 4 v2 + 8 v1\n"
    "v1 - v2 = 0.5(12 - 4)\n"
    "v1 = v2 + 4\n"
    "80 = 4 v2 + 8 v2 + 32\n"
    "v2 = 4 m/s\n"
    "v1 = 8 m/s\n"
)


def test_a_name_said_to_be_a_velocity_is_that_velocity() -> None:
    found = worst_lines(BYJUS, SWAPPED)
    assert [found[n][0] for n in range(2, 8)] == ["correct"] * 6


def test_restitution_the_wrong_way_round_in_those_names_is_still_wrong() -> None:
    found = worst_lines(BYJUS, SWAPPED.replace("v1 - v2 = 0.5(12 - 4)", "v2 - v1 = 0.5(12 - 4)"))
    assert found[3][0] == "wrong"


def test_the_speed_of_a_body_said_to_be_a_name_in_latex() -> None:
    work = (
        "Take right as positive; the speed of B after is $u_2$, and A's velocity after is $u_1$.\n"
        "$4(12) + 8(4) = 4u_1 + 8u_2$\n"
        "$u_2 - u_1 = 0.5(12 - 4) = 4$\n"
        "$u_1 = 4$ m/s, $u_2 = 8$ m/s\n"
    )
    found = worst_lines(BYJUS, work)
    assert [found[n][0] for n in (2, 3, 4)] == ["correct"] * 3
