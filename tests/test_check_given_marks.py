"""The mark a student puts after a result the question gave (issue #31): ``(A.G.)``, ``[AG]``,
``A.G.``, ``(as req'd)``, ``(shown)``, ``Q.E.D.``, ``∎``. It is no part of the value: the line is
judged as it would be without it (right when the value is right, wrong when it is not).

Values worked by hand: CIE 9231/P2 June 2012 Q2 (3m at 2u, m at u toward it; the impulse 4mu
leaves 3m at 2u/3 and m at 3u): KE before 1/2(3m)(4u^2) + 1/2 m u^2 = 13/2 m u^2, after
1/2(3m)(4u^2/9) + 1/2 m(9u^2) = 2/3 m u^2 + 9/2 m u^2 = 31/6 m u^2, lost 39/6 - 31/6 = 4/3 m u^2.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

PROBLEM = "cie-9231-p2-2012-june-q2-impulse-4mu-show-ke-lost"
WORK = """KE before = 1/2 (3m)(2u)^2 + 1/2 m u^2 = 13/2 m u^2
KE after = 1/2 (3m)(2u/3)^2 + 1/2 m (3u)^2 = 31/6 m u^2
loss = 13/2 m u^2 - 31/6 m u^2 = 4/3 m u^2{mark}
"""
MARKS = ["   (A.G.)", " (AG)", "  [AG]", "  A.G.", " (as req'd)", " (shown)", "  Q.E.D.", " ∎"]


@pytest.mark.parametrize("mark", MARKS)
def test_a_result_marked_as_the_answer_given_is_read(mark: str) -> None:
    assert worst_lines(PROBLEM, WORK.format(mark=mark))[3][0] == "correct"


@pytest.mark.parametrize("mark", MARKS[:2])
def test_a_wrong_result_marked_as_the_answer_given_is_wrong(mark: str) -> None:
    assert worst_lines(PROBLEM, WORK.format(mark=mark).replace("= 4/3 m u^2", "= 5/3 m u^2"))[3][0] == "wrong"
