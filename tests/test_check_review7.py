"""Review of the evening's checker rules (merge7): lines a rule made wrong that main marked right.
Every expected value is worked by hand from the problem files' givens (in the comments).
"""

from __future__ import annotations

from support.checked import lines, worst_lines

#: OCR M2 2006: dropped from rest 2 m, rebounds to 1.4 m, m = 0.3 kg, g = 9.8.
#: v_1^2 = 2(9.8)(2) = 39.2, v_1 = 6.261; v_2^2 = 2(9.8)(1.4) = 27.44, v_2 = 5.238.
DROP = "chain-ocr-m2-2006-drop-rebound"
#: OCR M2 2006 Q8: A 2 kg, B 1 kg, each at 5 m/s towards each other, e = 0.8:
#: 2(5) - 5 = 5 = 2x + y, y - x = 8: x = -1, y = 7 (A's way positive).
MEET = "ocr-m2-2006-spheres-meet-at-5-ke-lost"
WORK = (
    "Let x = velocity of A after, y = velocity of B after (A's original direction positive)\n"
    "2(5) + 1(-5) = 2x + y\n"
    "y - x = 0.8(5 + 5)\n"
    "x = -1, y = 7\n"
)


def test_a_u_for_the_landing_speed_leaves_the_rise_in_v_alone() -> None:
    # u is the student's landing speed (u^2 = 39.2 is no start speed: the drop is from rest), so
    # suvat's letters are not the fall's; v^2 = 2(9.8)(1.4) = 27.44, v = 5.24 is the rebound, right.
    work = "u^2 = 2(9.8)(2) = 39.2\nu = 6.26 m/s\nv^2 = 2(9.8)(1.4) = 27.44\nv = 5.24 m/s\n"
    found = worst_lines(DROP, work)
    assert found[3][0] == "correct"
    assert found[4][0] == "correct"


def test_the_fall_in_suvat_letters_is_still_read_so() -> None:
    # u = 0 from rest, s = 2: v^2 = 0 + 39.2 = 39.2, v = 6.26 (down positive).
    found = worst_lines(DROP, "u = 0, a = 9.8, s = 2\nv^2 = u^2 + 2as = 39.2\nv = 6.26\n")
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3


def test_the_speeds_before_listed_towards_each_other_are_no_results() -> None:
    # 5 m/s each before: not the speeds after (1 and 7), so no slip is made of them.
    found = lines(MEET, "Speeds: A: 5 m/s, B: 5 m/s (moving towards each other)\n" + WORK)
    assert found.get(1, ("not read",))[0] != "wrong"
    assert [found[n][0] for n in (3, 4, 5)] == ["correct"] * 3


def test_velocities_listed_with_their_signs_are_not_speeds() -> None:
    # A: -1 m/s is A's velocity after (its speed 1): not a wrong speed.
    found = lines(MEET, WORK + "Final velocities: A: -1 m/s, B: 7 m/s\n")
    assert found.get(5, ("not read",))[0] != "wrong"
    # unsigned, the speeds after: 1 and 7, right.
    assert lines(MEET, WORK + "Final speeds: A: 1 m/s, B: 7 m/s\n")[5][0] == "correct"


#: AQA M3 2009: A (m) at 5u catches B (7m) at u, both moving the same way (+n). 5mu + 7mu =
#: m v_A + 7m v_B, v_B - v_A = 4eu: 8 v_B = 12u + 4eu, v_B = u(3 + e)/2, v_A = u(3 - 7e)/2.
CATCH = "aqa-m3-2009-june-q6-m-at-5u-catches-7m-at-u"
CATCH_WORK = "CLM: $m(5u) + 7m(u) = mv_A + 7mv_B$\nNEL: $v_B - v_A = e(5u - u)$\nAdding: $8v_B = 12u + 4eu$\n"


def test_b_caught_up_has_the_same_original_direction_as_a() -> None:
    # B moved the way A did (+n), so u(3 + e)/2 in B's original direction is right.
    found = lines(CATCH, CATCH_WORK + "$v_B = \\frac{u(3 + e)}{2}$ in B's original direction\n")
    assert found[4][0] == "correct"
    found = lines(CATCH, CATCH_WORK + "$v_B = -\\frac{u(3 + e)}{2}$ in B's original direction\n")
    assert found[4][0] == "wrong"


def test_its_original_direction_is_the_subjects() -> None:
    # v_A = v_B - 4eu = u(3 - 7e)/2 is A's velocity in A's original direction (+n), though v_B is
    # the last body named before the words.
    work = CATCH_WORK + "$v_B = u(3 + e)/2$\n$v_A = v_B - 4eu = \\frac{u(3 - 7e)}{2}$ in its original direction\n"
    assert worst_lines(CATCH, work)[5][0] == "correct"


def test_a_right_arrow_before_and_is_the_way() -> None:
    # left positive: a = 1 (A moves left at 1), b = -7 (B moves right at 7). "v_B = 7 m/s →" is
    # B's 7 m/s to the right, -7 with left positive: right, as main read it.
    work = (
        "Taking left as positive.\nLet a, b = velocities of A and B after\n2(-5) + 1(5) = 2a + b\n"
        "b - a = -0.8(5 - (-5))\na = 1, b = -7\nv_B = 7 m/s → and v_A = 1 m/s ←\n"
    )
    assert worst_lines(MEET, work)[6][0] == "correct"


def test_speeds_before_in_a_head_on_catch_up_keep_their_signs() -> None:
    # "head-on" is a direct impact; B moves A's way at u, so q = u is B's velocity: 5mu + 7mu and
    # e(p - q) = 4eu are right.
    work = (
        "Head-on collision. Let p = speed of A before, q = speed of B before, so p = 5u and q = u\n"
        "Let x = velocity of A after, y = velocity of B after\n"
        "m p + 7m q = m x + 7m y\ny - x = e(p - q) = 4eu\n"
    )
    found = worst_lines(CATCH, work)
    assert [found[n][0] for n in (1, 3, 4)] == ["correct"] * 3


#: OCR M3 2006: A (5 kg) at 4 m/s across the line of centres, B (2 kg) at 4 m/s along it toward A,
#: e = 0.75. Along n: -8 = 5a + 2b, b - a = 3: a = -2, b = 1. A after: (-2, 4), speed sqrt(20) = 4.472.
ACROSS = "ocr-m3-2006-oblique-a-across-centres"


def test_a_velocity_from_both_components_is_the_speed() -> None:
    work = (
        "Along the line of centres: 5(0) + 2(-4) = 5a + 2b, and b - a = 0.75(4)\n"
        "so a = -2, b = 1\n"
        "A's velocity after = sqrt(2^2 + 4^2) = 4.47 m/s (along the line of centres 2 m/s back, across 4 m/s)\n"
        "Parallel to the line of centres A moves back at 2 m/s and keeps 4 m/s perpendicular to it, "
        "so A's velocity after $= \\sqrt{20} = 4.47$ m/s.\n"
    )
    found = worst_lines(ACROSS, work)
    assert found[3][0] == "correct"
    assert found[4][0] == "correct"


#: OCR M2 2012: 0.8 kg at 4 m/s into a wall, e = 0.3: rebounds at 1.2 m/s. derive's n points
#: toward the wall, so the velocity after is -1.2 with the wall's way positive, +1.2 away from it.
WALL = "ocr-m2-2012-particle-hits-wall"


def test_a_convention_in_a_name_against_the_working_frame_measures_the_line() -> None:
    work = "Away from the wall is positive.\nspeed after = 0.3 x 4 = 1.2 m/s\n"
    right = work + "velocity after (towards the wall as positive) = -1.2 m/s\n"
    assert worst_lines(WALL, right)[3][0] == "correct"
    wrong = work + "velocity after (towards the wall as positive) = 1.2 m/s\n"
    assert worst_lines(WALL, wrong)[3][0] == "wrong"


def test_the_one_bodys_v_after_words_of_before_earlier_on_the_line_is_after() -> None:
    # away from the wall positive: before -4, after 0.3 x 4 = 1.2. The v after "u = -4 m/s before
    # the impact," (or a sentence about before) is the rebound's, right.
    work = (
        "Away from the wall positive.\nu = -4 m/s before the impact, v = 0.3(4) = 1.2 m/s\n"
        "Speed 4 m/s before hitting the wall, so v = 0.3 x 4 = 1.2 m/s\n"
        "Before: 4 m/s towards the wall. v = 1.2 m/s\n"
    )
    found = worst_lines(WALL, work)
    assert [found[n][0] for n in (2, 3, 4)] == ["correct"] * 3
    # right after "before:" it is the velocity before: -4 with away positive
    assert worst_lines(WALL, "taking away from the wall as +ve (so before: v = -4, after: v = +0.3*4)\n")[1][0] == (
        "correct"
    )


def test_the_one_bodys_v_after_before_the_impact_words_is_before() -> None:
    # away positive: "Before the impact, v = -4 m/s" is the velocity before, right.
    work = "Away from the wall positive.\nBefore the impact, v = -4 m/s\n"
    assert worst_lines(WALL, work)[2][0] == "correct"
