"""A line that says which way its values are measured (``v_A = u(1 - 6e)/7 in its original
direction``, after working with B's direction positive): its values are read with that way
positive, as a teacher reads them, not in the frame of the working.

Worked by hand (cie-9231-p2-2018-november-q2-5m-at-u-meets-2m-at-2u): A (5m) at u meets B (2m) at
2u head-on. With A's way positive: 5mu − 4mu = 5m v_A + 2m v_B and v_B − v_A = 3eu, so
7 v_A = u − 6eu, v_A = u(1 − 6e)/7 and v_B = v_A + 3eu = u(1 + 15e)/7. With B's way positive the
same velocities are −u(1 − 6e)/7 and −u(1 + 15e)/7.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

SPHERES = "cie-9231-p2-2018-november-q2-5m-at-u-meets-2m-at-2u"
B_WAY = "I take the direction B is moving in as positive.\n$5m(-u) + 2m(2u) = 5m v_A + 2m v_B$\n$v_A = -u(1 - 6e)/7$\n"


@pytest.mark.parametrize(
    "line",
    [
        "So $v_A = u(1 - 6e)/7$ in its original direction, and $v_B = u(1 + 15e)/7$.",
        "$v_B = u(1 + 15e)/7$ in A's original direction",
        "$v_B = u(1 + 15e)/7$ in the original direction of A",
        "$v_B = -u(1 + 15e)/7$ in B's original direction",
    ],
)
def test_values_in_the_way_the_line_names_are_right(line: str) -> None:
    assert statuses(SPHERES, B_WAY + line) == ["correct", "correct", "correct"]


def test_a_value_with_the_sign_of_the_working_frame_is_wrong_in_the_way_named() -> None:
    assert statuses(SPHERES, B_WAY + "So $v_A = -u(1 - 6e)/7$ in its original direction.")[-1] == "wrong"
    assert statuses(SPHERES, B_WAY + "$v_B = u(1 + 15e)/7$ in B's original direction")[-1] == "wrong"
