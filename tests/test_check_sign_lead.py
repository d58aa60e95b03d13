"""A sign convention said before a comma, then the relation (``up +ve, impulse = …``, ``taking
left as positive, v = -3``): the convention is no part of the relation's first side.

Values worked by hand: BYJU'S 4 kg ball at 12 m/s catches an 8 kg ball at 4 m/s, e = 0.5:
80 = 4 v_A + 8 v_B, v_B - v_A = 4, so v_A = 4 and v_B = 8 (m/s), both forwards.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.reader import read_relations

PROBLEM = "byjus-4kg-ball-catches-8kg-ball"


@pytest.mark.parametrize("said", ["right +ve", "forwards positive", "taking the direction of motion as positive"])
def test_the_convention_before_the_comma_is_no_part_of_the_relation(said: str) -> None:
    assert [r.sides for r in read_relations(f"{said}, v_A2 = 4")] == [("v_A2", "4")]


def test_the_relation_after_the_convention_is_judged() -> None:
    assert worst_lines(PROBLEM, "right +ve, v_A2 = 4\n")[1][0] == "correct"
    assert worst_lines(PROBLEM, "right +ve, v_A2 = 5\n")[1][0] == "wrong"
