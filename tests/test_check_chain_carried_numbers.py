"""A chain's lines worked from the student's own wrong numbers: carried. Every number is worked
by hand from the problem files' givens (in the comments), never taken from derive's output."""

from __future__ import annotations

from support.checked import worst_lines

#: OCR M2 2006: 0.3 kg dropped from 2 m rebounds to 1.4 m (g = 9.8). True: v_1 = √39.2 = 6.261,
#: v_2 = √27.44 = 5.238, e = 5.238/6.261 = 0.837.
DROP = "chain-ocr-m2-2006-drop-rebound"
#: OCR M2 2015: 0.2 kg thrown down at 5 m/s from 1.6 m (g = 9.8), e = 0.7 with the ground.
#: True: v² = 25 + 31.36 = 56.36, v = 7.507, rebound 0.7 × 7.507 = 5.255.
THROWN = "chain-ocr-m2-2015-thrown-down-bounce"


def test_a_law_worked_with_a_wrong_value_of_a_name_of_the_students_own_is_carried() -> None:
    # 2(9.8)(2) is 39.2, not 38.2 (the slip): s = √38.2 = 6.1806 = 6.18, the student's own. The
    # rise is right (5.24). e = 5.24/6.18 = 0.8476 = 0.848: the law (rebound over impact speed)
    # with the student's s; with the true s, 5.238/6.261 = 0.837.
    work = (
        "Fall: let s be the speed it hits the floor with.\n"
        "s^2 = 2(9.8)(2) = 38.2\n"
        "s = 6.18 m/s\n"
        "Rise: let r be the speed it leaves the floor with.\n"
        "r^2 = 2(9.8)(1.4) = 27.44\n"
        "r = 5.24 m/s\n"
        "e = 5.24/6.18 = 0.848\n"
    )
    found = worst_lines(DROP, work)
    assert found[2][0] == "wrong"
    assert found[3][0] == found[7][0] == "carried", found


def test_a_line_worked_from_the_wrong_value_to_more_figures_is_carried() -> None:
    # 5 for 5² (the slip): v² = 36.36, v = 6.0299 = 6.03. The rebound speed worked from 6.0299,
    # the number as the student wrote it before rounding: 0.7 × 6.0299 = 4.2209 = 4.221, right as
    # arithmetic, worked from a wrong value (the true rebound is 5.255).
    work = (
        "Down positive. v^2 = 5 + 2(9.8)(1.6) = 36.36\n"
        "v = 6.0299 = 6.03 m/s\n"
        "speed after the bounce = 0.7 x 6.0299 = 4.221 m/s\n"
    )
    found = worst_lines(THROWN, work)
    assert found[1][0] == "wrong"
    assert found[2][0] == found[3][0] == "carried", found
