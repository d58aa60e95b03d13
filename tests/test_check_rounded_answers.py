"""An answer line as students end their work: a body's label and its velocity in words, then a
relation after a comma (``B: 8.40 m/s along n, v_B2n = 8.3983 (8.40 3sf)``); and a value with
its rounding in brackets, the figures said inside (``(8.40 3sf)``, ``(8.4, to 2 s.f.)``) or not
(``(8.40)``): the rounding is an aside, not a factor.

Values worked by hand (docs/checking.md, Example 4.C.11): v_B2n = 8.3983 m/s, 8.40 at 3 s.f.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.reader import read_relations

PROBLEM = "notes-4c11-two-spheres"


@pytest.mark.parametrize(
    "typed",
    [
        "v_B2n = 8.3983 (8.40 3sf)",
        "v_B2n = 8.3983 (8.4, to 2 s.f.)",
        "v_B2n = 8.3983 (8.40)",
        "B: 8.40 m/s along n, v_B2n = 8.3983 (8.40 3sf)",
    ],
)
def test_the_rounding_in_brackets_is_an_aside(typed: str) -> None:
    assert [r.sides for r in read_relations(typed)] == [("v_B2n", "8.3983")]


def test_a_bracket_that_is_not_the_value_rounded_stays_a_factor() -> None:
    assert [r.sides for r in read_relations("J = 0.2 (4.4)")] == [("J", "0.2 (4.4)")]


def test_an_answer_line_with_its_rounding_is_judged() -> None:
    assert worst_lines(PROBLEM, "B: 8.40 m/s along n, v_B2n = 8.3983 (8.40 3sf)\n")[1][0] == "correct"
    assert worst_lines(PROBLEM, "B: 8.30 m/s along n, v_B2n = 8.2983 (8.30 3sf)\n")[1][0] == "wrong"
