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

from derive.mathtext.reader import read_relations

PROBLEM = "cie-9231-p2-2012-june-q2-impulse-4mu-show-ke-lost"
WORK = """KE before = 1/2 (3m)(2u)^2 + 1/2 m u^2 = 13/2 m u^2
KE after = 1/2 (3m)(2u/3)^2 + 1/2 m (3u)^2 = 31/6 m u^2
loss = 13/2 m u^2 - 31/6 m u^2 = 4/3 m u^2{mark}
"""


def sides(text: str) -> list[tuple[str, ...]]:
    return [r.sides for r in read_relations(text)]


MARKS = ["   (A.G.)", " (AG)", "  [AG]", "  A.G.", " (as req'd)", " (shown)", "  Q.E.D.", " ∎"]
#: The mark schemes' star of a printed answer, and the words with no brackets (2026-11-29).
MARKS += ["  *", " * as required", "   as required", "  shown", " hence shown."]


@pytest.mark.parametrize("mark", MARKS)
def test_a_result_marked_as_the_answer_given_is_read(mark: str) -> None:
    assert worst_lines(PROBLEM, WORK.format(mark=mark))[3][0] == "correct"


@pytest.mark.parametrize("mark", [*MARKS[:2], "  *", " * as required"])
def test_a_wrong_result_marked_as_the_answer_given_is_wrong(mark: str) -> None:
    assert worst_lines(PROBLEM, WORK.format(mark=mark).replace("= 4/3 m u^2", "= 5/3 m u^2"))[3][0] == "wrong"


# --- remarks around a result: figures, doubts, dashes, long brackets, words after a comma ------
# CIE 9231/P2 June 2012 Q2 again, the impulse 4mu on each particle, +x the 3m particle's way:
# 3m v_1 - 3m(2u) = -4mu -> v_1 = 2u/3; m v_2 - m(-u) = 4mu -> v_2 = 3u.
IMPULSE = """+x the way the 3m particle moves.
3m v_1 - 3m(2u) = -4mu
v_1 = 2u/3
m v_2 - m(-u) = 4mu
v_2 = 3u{remark}
"""
REMARKS = [
    " ??? that seems fast",
    " --- faster than it was before the impact",
    "  (which is faster than it was before, I think)",
    ", and the 3m particle slows down",
]


@pytest.mark.parametrize("remark", REMARKS)
def test_a_remark_after_a_result_is_no_part_of_it(remark: str) -> None:
    assert worst_lines(PROBLEM, IMPULSE.format(remark=remark))[5][0] == "correct"


@pytest.mark.parametrize("remark", REMARKS)
def test_a_wrong_result_with_a_remark_after_it_is_wrong(remark: str) -> None:
    assert worst_lines(PROBLEM, IMPULSE.format(remark=remark).replace("v_2 = 3u", "v_2 = 5u"))[5][0] == "wrong"


def test_a_line_of_answers_in_square_brackets_is_read() -> None:
    found = worst_lines(PROBLEM, IMPULSE.format(remark="") + "[ v_1 = 2u/3 ,  v_2 = 3u ]\n")
    assert found[6] == ("correct", "")


def test_the_figures_a_value_is_given_to_are_no_part_of_it() -> None:
    assert sides("a = -4.50 m/s (to 3 s.f.), b = 6.00 m/s (3sf)") == [("a", "-4.50"), ("b", "6.00")]


def test_a_way_in_words_after_a_value_is_kept() -> None:
    (r,) = read_relations("v_B = 1.04 m/s (in the opposite direction to A now)")
    assert r.direction == -1


@pytest.mark.parametrize(
    "taken_back", ["? No -- it goes the other way:", "?? no, it moves on:", "? Nope. It moves on,"]
)
def test_a_value_taken_back_with_a_question_and_no_is_not_the_students(taken_back: str) -> None:
    # momentum after with the value kept: 3m(2u/3) + m(3u) = 5mu = 3m(2u) + m(-u) before
    work = IMPULSE.format(remark="") + f"so v_2 = -3u{taken_back} v_2 = 3u\n3m(2u/3) + m v_2 = 5mu\n"
    found = worst_lines(PROBLEM, work)
    assert found[6][0] == "correct"
    assert found[7][0] == "correct"


# BYJU'S 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5 (both +x): 4(12) + 8(4) = 80 = 4v_A + 8v_B and
# v_B - v_A = 0.5(12 - 4) = 4, so v_A = (80 - 32)/12 = 4 m/s and v_B = 8 m/s, both still +x.
CATCHES = "byjus-4kg-ball-catches-8kg-ball"


@pytest.mark.parametrize("taken_back", [" -- this is wrong, redo below", " ?? no"])
def test_a_value_taken_back_after_a_dash_or_a_doubt_is_never_wrong(taken_back: str) -> None:
    # the student takes 5 m/s back in words: a teacher does not mark it, and marks the 4 after it
    found = worst_lines(CATCHES, f"v_A = 5 m/s{taken_back}\nv_A = 4 m/s\n")
    assert found.get(1, ("not read", ""))[0] == "not read"
    assert found[2][0] == "correct"


def test_a_way_after_a_dash_is_not_taken_off() -> None:
    # B moves on at 8 m/s the way A came: "in the opposite direction to A" says -8, never right
    found = worst_lines(CATCHES, "v_B = 8 m/s -- in the opposite direction to A\n")
    assert found.get(1, ("not read", ""))[0] != "correct"
