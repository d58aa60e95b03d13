"""A remark after a value set off by a dash (``-- not 4, check?``, ``— not what the book says``), as
one after an ellipsis is (``… not 4``): words about the value, no part of the relation, even where
they hold a number. A dash before mathematics (``10000 – 10500`` typed with an en dash) is a minus.

Values worked by hand (Beer & Johnston 13.13, railroad cars: m_A = 20 Mg at 0.5 m/s, m_B = 35 Mg
at rest, 0.3 m/s after): v_A2 = (10 000 − 10 500)/20 000 = −0.025 m/s; e = (0.3 + 0.025)/0.5 = 0.65.
"""

from __future__ import annotations

import pytest
from support.checked import wall_30_lines, worst_lines

CARS = "beer-johnston-13-13-railroad-cars-find-e"


@pytest.mark.parametrize(
    "line",
    [
        "e = (0.3 + 0.025)/0.5 = 0.65 -- not 0.7, check?",
        "e = (0.3 + 0.025)/0.5 = 0.65 — not 0.5 as I first thought",
        "e = 0.325/0.5 = 0.65 – which is 65 % of the approach speed",
    ],
)
def test_a_remark_after_a_dash_is_not_the_value(line: str) -> None:
    assert worst_lines(CARS, line + "\n") == {1: ("correct", "")}


def test_a_wrong_value_before_a_dash_remark_is_still_a_slip() -> None:
    got = worst_lines(CARS, "e = 0.3/0.5 = 0.6 -- not 0.65, check?\n")
    assert got[1][0] == "wrong"


def test_an_en_dash_between_numbers_is_a_minus() -> None:
    assert worst_lines(CARS, "v_A2 = (10000 – 10500)/20000 = -0.025\n") == {1: ("correct", "")}


#: A letter that is also a unit's (J, N, m, s) after an operator is a quantity, not the unit of the
#: number before it: ``m(v_A)_1 - J = m(v_A)_2`` is the impulse J taken off, never "m v_A1 −" in joules.
#: By hand (support.checked.WALL_30: 0.5 kg, 5 m/s into the wall before, 2.5 m/s out after): the
#: impulse on the wall J = 0.5(5 + 2.5) = 3.75 N s.
def test_a_unit_letter_after_a_minus_is_a_quantity(tmp_path) -> None:
    work = "J = 0.5(5 + 2.5) = 3.75\nImpulse on the ball (wall pushes in -x): 0.5(5) - J = 0.5(-2.5)\n"
    assert wall_30_lines(tmp_path, work) == ["correct", "correct"]
    slipped = "J = 3.75\n0.5(5) - J = 0.5(2.5)\n"  # the rebound's sign lost
    assert wall_30_lines(tmp_path, slipped) == ["correct", "wrong"]


#: A conclusion typed on a phone: a body's letter and its speed with no colon, then another result
#: (``so B 1.5m/s e=0.1``): that body's speed and the other result, as a teacher reads a line of answers.
@pytest.mark.parametrize(
    ("line", "verdict"),
    [
        ("so A 0.025m/s e=0.65", "correct"),
        ("ans: B 0.3 m/s, e = 0.65", "correct"),
        ("so A 0.025 m/s e=0.6", "wrong"),
    ],
)
def test_a_concluded_speed_without_a_colon(line: str, verdict: str) -> None:
    assert worst_lines(CARS, line + "\n")[1][0] == verdict
