"""Results listed by body, a letter, a colon and a speed (``A: 6.94 ft/s, B: 3.60 ft/s along the
line of centers``): the speeds after the impact, judged as ``speed of A = …``; a line of givens
listed the same way (``Before: A: 12 m/s, B: 4 m/s``) is the data, not a result.

Values worked by hand: BYJU'S, A (4 kg) at 12 m/s catches B (8 kg) at 4 m/s, e = 0.5. CLM
48 + 32 = 80 = 4x + 8y; NEL y - x = 0.5(12 - 4) = 4; so 12x + 32 = 80, x = 4 m/s, y = 8 m/s.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.reader import read_relations

PROBLEM = "byjus-4kg-ball-catches-8kg-ball"
WORK = """x, y = velocities of A and B after, in the direction they move.
4(12) + 8(4) = 4x + 8y
y - x = 0.5(12 - 4) = 4
12x = 48, x = 4, y = 8
{answer}
"""


@pytest.mark.parametrize(
    "answer",
    ["**A: 4 m/s, B: 8 m/s**", "Answers -- A: 4.0 m/s; B: 8.0 m/s, both forward", "P.S. A: 4 m/s and B: 8 m/s"],
)
def test_speeds_listed_by_body_are_the_speeds_after(answer: str) -> None:
    assert worst_lines(PROBLEM, WORK.format(answer=answer))[5][0] == "correct"


def test_a_wrong_speed_listed_by_body_is_wrong() -> None:
    assert worst_lines(PROBLEM, WORK.format(answer="A: 4 m/s, B: 6 m/s"))[5][0] == "wrong"


def test_a_list_of_givens_is_no_result() -> None:
    assert [r.sides for r in read_relations("Before: A: 12 m/s, B: 4 m/s")] == []
    assert [r.sides for r in read_relations("A: 4 m/s, B: 8 m/s")] == [("speed of A", "4"), ("speed of B", "8")]
