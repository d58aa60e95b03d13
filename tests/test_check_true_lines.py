"""Correct lines a teacher marks right that the checker must not call wrong (issue #31): the
names a student uses as the course teaches them, a later stage's own coefficient, and the
precision a line is written to. Every value is worked by hand from the problem's givens (in
the comments), never from derive's output."""

from __future__ import annotations

import pytest
from support.checked import worst_lines

# OCR M2 June 2006: A (2 kg) at 5 m/s hits B (1 kg) at rest and carries on at 2 m/s:
# 2(5) + 1(0) = 2(2) + 1v -> v = 6 (B after); e = (6 - 2)/5 = 0.8.
AT_REST = "ocr-m2-2006-sphere-hits-sphere-at-rest-find-e"
# OCR MEI 2023 (backward): A (0.5 kg) at 6 catches B (2 kg) at 2 and moves back at 0.2:
# 3 + 4 = -0.1 + 2v -> v = 3.55 (B after); e = (3.55 + 0.2)/(6 - 2) = 0.9375.
BACKWARD = "ocr-mei-fmm-2023-a-speed-0p2-backward"


@pytest.mark.parametrize(
    ("problem", "work"),
    [
        (AT_REST, "u_A = 5, u_B = 0, v_A = 2\n2(5) + 1(0) = 2(2) + 1v\n10 = 4 + v\nv = 6\ne = (v - 2)/5 = 0.8\n"),
        (AT_REST, "u1 = 5 m/s, u2 = 0, v1 = 2 m/s\n2 × 5 = 2 × 2 + v\nv = 6 m/s\n"),
        (AT_REST, "Let u_A = 5, u_B = 0, v_A = 2, v_B = v.\n10 = 4 + v\nv = 6\n"),
        (BACKWARD, "u_A = 6, u_B = 2, v_A = -0.2\n0.5(6) + 2(2) = 0.5(-0.2) + 2v\n7 = -0.1 + 2v\nv = 3.55\n"),
    ],
)
def test_v_alone_beside_labelled_names_is_the_one_velocity_after_not_given(problem: str, work: str) -> None:
    # u_A, u_B (u1, u2) label the bodies, and A's velocity after is given: the v the student
    # solves for is B's velocity after (the habit "u before, v after" for one body does not
    # make it A's when A's is written beside it).
    found = worst_lines(problem, work)
    assert {n: s for n, (s, _) in found.items()} == dict.fromkeys(found, "correct")


def test_v_alone_for_the_velocity_not_given_and_worked_wrongly_is_wrong() -> None:
    # 10 = 4 + v worked as v = 14 (the 4 added): wrong, whatever v is read as.
    found = worst_lines(AT_REST, "u_A = 5, u_B = 0, v_A = 2\n10 = 4 + v\nv = 14\n")
    assert found[2][0] == "correct"
    assert found[3][0] == "wrong"


# OCR FM 2023: A (5 kg) at 4 m/s, 60° from the line of centres; B (3 kg) at 6 m/s along it
# toward A; e = 3/4. A's components 4 cos 60° = 2 along the line, 4 sin 60° = 3.464 across;
# along the line -8 = 5a + 3b and b - a = 0.75(2 + 6) = 6 -> a = -3.25, b = 2.75.
DISCS = "ocr-fm-2023-oblique-discs-60deg"
SIDE_BY_SIDE = (
    "\\begin{align*}\n"
    "u_{An} &= 4\\cos 60^\\circ = 2 & u_{At} &= 4\\sin 60^\\circ = 3.464 \\\\\n"
    "5(2) + 3(-6) &= 5v_{An} + 3v_{Bn} & v_{Bn} - v_{An} &= \\tfrac34(2 + 6) = 6 \\\\\n"
    "\\text{CLM:} & -8 = 5v_{An} + 3v_{Bn} & \\text{NEL:} & v_{Bn} - v_{An} = 6 \\\\\n"
    "v_{An} &= -3.25 & v_{Bn} &= 2.75\n"
    "\\end{align*}\n"
)


def test_two_relations_side_by_side_in_an_align_row_are_read_apart() -> None:
    found = worst_lines(DISCS, SIDE_BY_SIDE)
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["correct"] * 4


def test_a_slip_in_one_of_two_relations_side_by_side_is_wrong() -> None:
    # the components resolved with sin and cos swapped: 4 sin 60° along the line
    work = "\\begin{align*}\nu_{An} &= 4\\sin 60^\\circ = 3.464 & u_{At} &= 4\\cos 60^\\circ = 2\n\\end{align*}\n"
    assert worst_lines(DISCS, work)[2] == ("wrong", "sin_cos_swapped")
