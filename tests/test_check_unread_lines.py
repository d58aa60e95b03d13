"""Lines a teacher marks that the checker used not to read, each family on problems and phrasings
other than the corpus's, its expected marks worked by hand from the problem's givens.

A root typed on a phone as ``rt3`` (``2rt3``, ``rt(3)``) is the root of 3, as ``sqrt3`` and
``root3`` are. AQA M3 June 2007 Q6(a): identical balls, A at u at 30 deg to the line of centres,
B at rest. A's velocity along the line of centres is u cos 30 = (rt3/2)u, across it u sin 30 = u/2;
B's after, (1 + e)(rt3/4)u (momentum x + y = (rt3/2)u, restitution y - x = e(rt3/2)u).
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.notation import student

AQA = "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b"


@pytest.mark.parametrize(
    ("typed", "plain"),
    [("rt3/2", "sqrt(3)/2"), ("2rt3", "2*sqrt(3)"), ("rt(3)u", "sqrt(3)*u"), ("u rt3", "u*sqrt(3)")],
)
def test_rt_glued_to_a_number_is_its_root(typed: str, plain: str) -> None:
    assert student(typed).replace(" ", "") == plain


def test_a_name_beginning_rt_is_not_a_root() -> None:
    assert "sqrt" not in student("rt + v_rt2")


@pytest.mark.parametrize(
    ("line", "status"),
    [
        ("A along l.o.c. before = u cos 30 = (rt3/2)u", "correct"),
        ("B's velocity after = (1 + e)(rt3/4)u", "correct"),
        ("B's velocity after = (1 + e) rt(3) u/2", "wrong"),
    ],
)
def test_rt3_lines_are_read_and_judged(line: str, status: str) -> None:
    assert worst_lines(AQA, line + "\n")[1][0] == status
