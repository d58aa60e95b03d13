"""A right arrow after a value with more working after it (``v_A = 1 m/s -> +ve so A goes left``) is
"so", not the way the body moves: the value keeps its sign. An arrow alone after a value
(``v_B = 7 m/s →``) is still its way.

Worked by hand (ocr-m2-2006-spheres-meet-at-5-ke-lost): A (2 kg) and B (1 kg) meet head-on at 5 m/s
each, e = 0.8: 2(5) − 1(5) = 2x + y and y − x = 0.8 × 10 = 8, so x = −1, y = 7 with A's way (right)
positive. With left positive: A after +1 (it moves left at 1 m/s), B after −7 (right at 7 m/s).
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

SPHERES = "ocr-m2-2006-spheres-meet-at-5-ke-lost"
LEFT = "taking left as positive\n2(-5) + 1(5) = 2v_A + v_B\n"


@pytest.mark.parametrize(
    "line",
    [
        "v_A = 1 m/s -> +ve so A moves to the left",
        "v_A = 1 m/s → positive, so to the left",
        "v_B = 7 m/s →",
        "v_B = 7 m/s to the right",
    ],
)
def test_an_arrow_then_more_working_is_so_and_an_arrow_alone_is_a_way(line: str) -> None:
    assert statuses(SPHERES, LEFT + line) == ["correct", "correct"]


def test_a_wrong_value_before_an_arrow_is_still_wrong() -> None:
    assert statuses(SPHERES, LEFT + "v_A = 3 m/s -> +ve so A moves to the left")[-1] == "wrong"
