"""The one body's ``v`` under a lead-in that says before (``before: v = -4, after: v = 1.6``, also in
brackets after "so"): the velocity before the impact, as the words make it, not the one after.

Worked by hand (edexcel-m2-ball-rebounds-from-wall): a 2 kg ball arrives at a wall at 4 m/s,
e = 0.4, so it rebounds at 0.4 × 4 = 1.6 m/s. Away from the wall positive: before −4, after +1.6.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

WALL = "edexcel-m2-ball-rebounds-from-wall"
AWAY = "taking away from the wall as positive\n"


@pytest.mark.parametrize(
    "line",
    ["before: v = -4, after: v = 0.4*4 = 1.6", "(so before: v = -4, after: v = +1.6)", "Before: v = -4"],
)
def test_v_under_before_words_is_the_velocity_before(line: str) -> None:
    assert statuses(WALL, AWAY + line) == ["correct"]


def test_a_wrong_value_under_before_or_after_words_is_wrong() -> None:
    assert statuses(WALL, AWAY + "before: v = -4, after: v = 0.4*4 = 2.6") == ["wrong"]
    assert statuses(WALL, AWAY + "before: v = -4, after: v = -1.6")[-1] == "wrong"
