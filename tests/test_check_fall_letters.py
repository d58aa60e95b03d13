"""A chain that starts with a fall, worked in suvat's letters as students work it: ``u``, ``v``,
``s``, ``a`` are the fall's (start speed, landing speed, height, g), whatever numbers the student
puts in for them, so a slip in the landing speed is a slip, not a name the line defines; a
decimal point moved in a step from letters to numbers is arithmetic; ``h`` is a height, the rise's;
the energy lost is worked from the student's landing speed; a given copied wrongly twice is the
same mistake again. Every number is worked by hand from the problem files' givens (in the comments).
"""

from __future__ import annotations

from support.checked import lines, worst_lines

#: OCR M2 2007: thrown down at 21 m/s from 40 m, rises back to the start, g = 9.8.
#: v_1^2 = 441 + 784 = 1225, v_1 = 35; v_2^2 = 784, v_2 = 28; e = 0.8.
START = "chain-ocr-m2-2007-rebounds-to-start"
#: OCR M2 2015: thrown down at 5 m/s from 1.6 m, e = 0.7, m = 0.2 kg, g = 9.8.
#: v_1^2 = 25 + 31.36 = 56.36, v_1 = 7.507; v_2 = 5.255; h_2 = 1.409; E_lost = 0.1(56.36)(0.51) = 2.874.
BOUNCE = "chain-ocr-m2-2015-thrown-down-bounce"


def test_the_landing_speed_with_the_start_speed_not_squared_is_the_slip() -> None:
    # 21 + 784 = 805 (21 not squared): v^2 is 1225, so the line is false; v = sqrt(805) = 28.37 is
    # right given it.
    found = lines(START, "Falling:\nv^2 = 21 + 2 x 9.8 x 40 = 805\nv = 28.37 m/s\n")
    assert found[2][:2] == ("wrong", "arithmetic")
    assert found[3][0] == "carried"


def test_the_fall_in_suvat_letters_worked_right_is_correct() -> None:
    # u = 21, a = 9.8, s = 40: v^2 = 441 + 784 = 1225, v = 35 (down positive).
    found = worst_lines(START, "u = 21, a = 9.8, s = 40\nv^2 = u^2 + 2as = 441 + 784 = 1225\nv = 35\n")
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3


def test_the_fall_with_up_positive_is_read_with_its_signs() -> None:
    # up positive: u = -21, a = -9.8, s = -40; v^2 = 441 + 784 = 1225, v = -35.
    found = worst_lines(START, "u = -21, a = -9.8, s = -40\nv^2 = u^2 + 2as = 1225\nv = -35\n")
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3


def test_a_decimal_point_moved_from_letters_to_numbers_is_arithmetic() -> None:
    # v_1^2 = 441 + 784, written 441 + 78.4 = 519.4: the step from v_1^2 to the numbers is false,
    # and holds with 78.4 ten times larger.
    found = lines(START, "v_1^2 = 441 + 78.4 = 519.4\n")
    assert found[1][:2] == ("wrong", "arithmetic")


def test_a_height_worked_from_a_slipped_rebound_speed_is_the_rise_carried() -> None:
    # v_1^2 = 5 + 31.36 = 36.36 (5 not squared), v_1 = 6.030; v_2 = 0.7(6.03) = 4.221;
    # h = 4.22^2/19.6 = 0.9086: the rise's height given the slip (truly 1.409), not a name of its own.
    work = "v_1^2 = 5 + 2(9.8)(1.6) = 36.36\nv_1 = 6.03\nv_2 = 0.7(6.03) = 4.22\n0 = 4.22^2 - 2(9.8)h\nh = 0.909\n"
    found = lines(BOUNCE, work)
    assert found[1][0] == "wrong"
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["carried"] * 4


def test_the_energy_lost_from_a_slipped_landing_speed_is_carried() -> None:
    # v_1 = sqrt(36.36) = 6.030 (the slip); lost = ½(0.2)(36.36)(1 - 0.49) = 1.8544 (the student's
    # 6.03^2 - 4.22^2 = 36.36 - 17.81 = 18.55, times 0.1: 1.855); truly 2.874.
    work = "v_1^2 = 5 + 2(9.8)(1.6) = 36.36\nv_1 = 6.03\nKE lost = 1/2(0.2)(6.03^2 - 4.22^2) = 1.855 J\n"
    found = lines(BOUNCE, work)
    assert found[1][0] == "wrong"
    assert found[3][0] == "carried"


def test_a_given_copied_wrongly_in_the_fall_and_again_in_the_rise() -> None:
    # the height 40 m copied as 45: v_1^2 = 441 + 882 = 1323 (truly 1225), v_1 = 36.37 carried;
    # the rise back to the start, 0 = v_2^2 - 2(9.8)(45), has 45 for 40 again: the same mistake;
    # v_2^2 = 882, v_2 = 29.70 is right given it.
    work = "v_1^2 = 21^2 + 2(9.8)(45) = 441 + 882 = 1323\nv_1 = 36.37\n0 = v_2^2 - 2(9.8)(45)\nv_2 = 29.70\n"
    found = lines(START, work)
    assert found[1][:2] == ("wrong", "copied_wrong")
    assert found[2][0] == "carried"
    assert found[3] == ("wrong", "copied_wrong", True)
    assert found[4][0] == "carried"


def test_the_impulse_in_words_with_the_rebound_sign_lost_is_b_sign() -> None:
    # v_1 = 7.507 down, v_2 = 5.255 up: the impulse is 0.2(7.507 + 5.255) = 2.552 N s; written
    # 0.2(7.507 - 5.255) = 0.450, the rebound is put in with its direction lost.
    found = lines(BOUNCE, "impulse on the sphere = 0.2(7.507 - 5.255) = 0.450 N s\n")
    assert found[1][:2] == ("wrong", "b_sign")
    assert lines(BOUNCE, "impulse = 0.2(5.255 + 7.507) = 2.55 N s\n")[1][0] == "correct"
