"""A body's quantity in words under the statement's own letters, matched to A and B as the
statement says, not by the exam's usual order (P as A, Q as B): in Edexcel M4 June 2005 Q3 the
sphere P lies at rest and Q moves into it, so Q is derive's A and P its B.

Values worked by hand: Q (mass m) at u, at alpha to the line of centres; P (mass m) at rest. Q's
velocity along the line of centres is u cos(alpha), across it u sin(alpha); P's speed before is 0.
After: x + y = u cos(alpha), y - x = e u cos(alpha), so P's velocity after is u cos(alpha)(1 + e)/2.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

PROBLEM = "edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta"


@pytest.mark.parametrize(
    ("line", "status"),
    [
        ("Q's velocity along the line of centres = u cos(alpha)", "correct"),
        ("Q's velocity along line of centres = u cos(alpha), across = u sin(alpha)", "correct"),
        ("Q's velocity along the line of centres = u sin(alpha)", "wrong"),
        ("speed of Q before = u", "correct"),
        ("speed of P before = u", "wrong"),
    ],
)
def test_the_statements_letters_name_its_bodies(line: str, status: str) -> None:
    assert worst_lines(PROBLEM, line + "\n")[1][0] == status


def test_a_later_line_in_the_statements_letters_is_read_so() -> None:
    work = """x = Q along the line of centres after, y = P after
m u cos(alpha) = m x + m y
y - x = e u cos(alpha)
P's velocity after = u cos(alpha)(1 + e)/2
"""
    assert worst_lines(PROBLEM, work)[4][0] == "correct"
