"""A remark after a dash or after question marks that talks about an expression in brackets
(``= u(3 - e)/2  -- the book has (e + 3), must be a sign``, ``?? should be (1 - e)``): words,
no part of the value, which is judged as it would be without them.

Values worked by hand: Edexcel M2 January 2010 Q2, P (2m) at 2u meets Q (m) at u head-on, along
P's way: CLM 3u = 2x + y, NEL y - x = 3eu, so x = u(1 - e), y = u(1 + 2e).
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.reader import read_relations

PROBLEM = "edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u"
WORK = """Let x be the velocity of P after and y the velocity of Q after, both in P's direction.
3u = 2x + y
y - x = 3eu
so speed of Q = {value}{remark}
"""
REMARKS = [
    "   -- the book has (2e + 1), same thing I think",
    " — the answer is (1 + 2e)u, it matches",
    " ?? they want (1 + 2e)u, check",
]


@pytest.mark.parametrize("remark", REMARKS)
def test_a_remark_about_an_expression_in_brackets_is_no_part_of_the_value(remark: str) -> None:
    assert [r.sides for r in read_relations(f"v = u(1 + 2e){remark}")] == [("v", "u(1 + 2e)")]


@pytest.mark.parametrize("remark", REMARKS)
def test_a_right_value_with_the_remark_is_correct(remark: str) -> None:
    assert worst_lines(PROBLEM, WORK.format(value="u(1 + 2e)", remark=remark))[4][0] == "correct"


def test_a_wrong_value_with_the_remark_is_wrong() -> None:
    assert worst_lines(PROBLEM, WORK.format(value="u(1 - 2e)", remark=REMARKS[0]))[4][0] == "wrong"
