"""Lines carried after a slip in worlds the student's own equations make (issue #31): an
unknown angle solved from a slip's equation, the student's own values of the quantities
after a slip. Every number is worked by hand from the problem files' givens (in the
comments), never taken from derive's output."""

from __future__ import annotations

from support.checked import lines, worst_lines

#: Edexcel M4 2018: a ball at speed U, its path at α to a smooth wall (e = 3/4), keeps 60 % of
#: its kinetic energy. α is from the wall: U cos α along it, U sin α into it, rebounding at
#: ¾U sin α: cos²α + (9/16) sin²α = 3/5, so (7/16) sin²α = 2/5, sin²α = 32/35, tan²α = 32/3,
#: α = 72.98°.
WALL = "edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke"


def test_an_angle_found_from_a_slip_in_the_energy_equation_is_carried_by_the_tangent() -> None:
    # Resolved from the other axis (U sin α along the wall, U cos α into it): sin²α +
    # (9/16) cos²α = 3/5; divided by cos²α: tan²α + 9/16 = (3/5)(1 + tan²α), (2/5) tan²α =
    # 3/5 - 9/16 = 3/80, tan²α = 3/32, tan α = 0.30619, α = 17.02°: every line after the slip
    # holds for the student's own equation, none for the problem (tan α = 3.266 there).
    work = (
        "1/2 m(U^2 sin^2 α + 9/16 U^2 cos^2 α) = 3/5 × 1/2 m U^2\n"
        "tan^2 α + 9/16 = 3/5 (1 + tan^2 α)\n"
        "2/5 tan^2 α = 3/80\n"
        "tan^2 α = 3/32\n"
        "tan α = 0.306\n"
        "α = 17.0°\n"
    )
    found = lines(WALL, work)
    assert found[1][0] == "wrong"
    assert all(found[n][0] == "carried" for n in (2, 3, 4, 5, 6)), found


def test_an_angle_worked_on_from_a_slip_solving_for_it_is_carried_and_a_further_slip_is_not() -> None:
    # Resolved rightly, then (7/16) sin²α = 0.4 solved as sin²α = 0.4 × 7/16 = 0.175 (for
    # 0.4 × 16/7 = 0.9143): sin α = √0.175 = 0.41833, α = asin 0.41833 = 24.73°, carried; 26.0°
    # is right in neither world (a further slip).
    work = (
        "1/2 m(U^2 cos^2 α + 9/16 U^2 sin^2 α) = 0.6 × 1/2 m U^2\n"
        "cos^2 α + 9/16 sin^2 α = 0.6\n"
        "1 - 7/16 sin^2 α = 0.6\n"
        "sin^2 α = 0.4 × 7/16 = 0.175\n"
        "sin α = 0.418\n"
        "α = 24.7°\n"
    )
    found = lines(WALL, work)
    assert found[1][0] == found[2][0] == found[3][0] == "correct"
    assert found[4][0] == "wrong"
    assert found[5][0] == found[6][0] == "carried", found
    found = lines(WALL, work.replace("24.7°", "26.0°"))
    assert found[6][0] == "wrong", found


def test_a_line_led_by_the_equations_it_adds_with_no_colon_is_read_and_carried() -> None:
    # AQA M3 2007: 0.3 kg at 3 m/s, 0.2 kg at 2 m/s toward it, e = 0.8; right positive, a and
    # b after: 0.3(3) + 0.2(-2) = 0.5 = 0.3a + 0.2b (1). Restitution written a - b = 4 (the
    # wrong way round, for b - a = 4); 0.2 x (2): 0.2a - 0.2b = 0.8 (3); (1) + (3): 0.5a = 1.3,
    # a = 2.6 (b = -1.4: 0.78 - 0.28 = 0.5). "(1)+(3)" before the sides names the equations
    # added, it is not 1 + 3(0.5a): read without it, the line is carried.
    work = (
        "Taking right as positive, let a and b be the velocities of A and B after.\n"
        "0.3(3) + 0.2(-2) = 0.3a + 0.2b    (1)\n"
        "a - b = 0.8(3 + 2) = 4    (2)\n"
        "0.2a - 0.2b = 0.8    (3)\n"
        "(1)+(3)  0.5a = 1.3\n"
        "a = 2.6\n"
    )
    found = lines("aqa-m3-2007-spheres-approach-head-on", work)
    assert found[2][0] == "correct"
    assert found[3][0] == "wrong"
    assert all(found[n][0] == "carried" for n in (4, 5, 6)), found
    found = lines("aqa-m3-2007-spheres-approach-head-on", work.replace("0.5a = 1.3", "0.5a = 1.5"))
    assert found[5][0] == "wrong", found  # 1.5 is right in neither world


def test_an_inverse_problem_solved_again_with_a_given_copied_wrongly_carries_the_lines_after() -> None:
    # OCR M2 2006: 2 kg at 5 m/s hits 1 kg at rest, A goes on at 2 m/s; find e. True: 10 = 4 +
    # v_B2, v_B2 = 6, e = (6 - 2)/5 = 0.8. A's speed after copied as 3: 10 = 6 + v_B2, v_B2 = 4,
    # e = (4 - 3)/5 = 0.2. The unknowns (v_B2 and e) are those of the problem solved with 3 m/s,
    # not the true ones: the momentum with 3 written in is carried, not a further slip.
    work = (
        "Data: m_A = 2 kg, m_B = 1 kg, v_A1 = 5 m/s, v_B1 = 0, v_A2 = 3 m/s\n"
        "2(5) + 1(0) = 2(3) + 1 v_B2\n"
        "v_B2 = 10 - 6 = 4 m/s\n"
        "e = (4 - 3)/(5 - 0) = 0.2\n"
    )
    found = worst_lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert found[1] == ("wrong", "copied_wrong")
    assert all(found[n][0] == "carried" for n in (2, 3, 4)), found


def test_a_slip_eliminating_one_velocity_keeps_the_restitution_the_other_is_found_from() -> None:
    # AQA M3 2009: m at 5u catches 7m at u, e. Momentum 12u = x + 7y, restitution y = x + 4eu;
    # 12u = 8x + 28eu, so x = u(3 - 7e)/2 and y = u(3 + e)/2. A sign lost moving 28eu across:
    # 8x = 12u + 28eu, x = u(3 + 7e)/2; the student then finds y from the restitution as
    # written (y = x + 4eu): u(3 + 15e)/2 is carried (the slip stands for the momentum, which
    # the line in x alone was worked from, not the restitution); u(3 + 11e)/2 is not.
    work = (
        "Let x and y be the velocities of A and B after.\n"
        "5mu + 7mu = mx + 7my\n"
        "y - x = e(5u - u) = 4eu\n"
        "12u = x + 7(x + 4eu)\n"
        "12u = 8x + 28eu\n"
        "8x = 12u + 28eu\n"
        "x = u(3 + 7e)/2\n"
        "y = u(3 + 7e)/2 + 4eu = u(3 + 15e)/2\n"
    )
    problem = "aqa-m3-2009-june-q6-m-at-5u-catches-7m-at-u"
    found = worst_lines(problem, work)
    assert all(found[n][0] == "correct" for n in (2, 3, 4, 5)), found
    assert found[6][0] == "wrong"
    assert found[7][0] == found[8][0] == "carried", found
    assert worst_lines(problem, work.replace("3 + 15e", "3 + 11e"))[8][0] == "wrong"


def test_a_name_declared_after_the_words_for_it_is_read_as_declared() -> None:
    # AQA FM specimen: 0.8 kg at 6 m/s meets 0.4 kg at 6 m/s head on; A comes back at 1.2 m/s.
    # "Let B's velocity after be v" (the name after its words) is B's velocity after, not A's
    # (u and v as habit): 4.8 - 2.4 = 2.4 = -0.96 + 0.4v, v = 3.36/0.4 = 8.4 m/s; e = (8.4 +
    # 1.2)/12 = 0.8; KE before ½(0.8)(36) + ½(0.4)(36) = 14.4 + 7.2 = 21.6 J.
    work = (
        "A (0.8 kg) at 6 m/s meets B (0.4 kg) coming the other way at 6 m/s; A comes back at 1.2 m/s."
        " Let B's velocity after be $v$.\n"
        "CLM: 0.8(6) + 0.4(-6) = 0.8(-1.2) + 0.4v\n"
        "v = (2.4 + 0.96)/0.4 = 8.4 m/s\n"
        "NEL: e = (v + 1.2)/(6 + 6) = 0.8\n"
        "KE before = 1/2 mu^2 + 1/2 (0.4)(6^2) = 14.4 + 7.2 = 21.6 J\n"
    )
    found = worst_lines("aqa-fm-specimen-discs-show-e-0p8", work)
    assert all(found[n][0] == "correct" for n in (2, 3, 4, 5)), found


def test_names_declared_by_the_statements_letters_for_the_line_of_centres_and_as_speeds() -> None:
    # OCR MEI FMM 2024: A (3 kg) along XY, the line of centres, hits B (5 kg, 2 m/s at 60° to
    # XY), e = 0.8; A stops. B along XY before: 2 cos 60° = 1. "A's speed before" (A moves
    # along XY only) and "B's speed along XY after" are the components along the line of
    # centres, U and w: 3U + 5 = 5w (right); restitution written w = 0.8(U + 1) (B's sign
    # lost, for 0.8(U - 1)): 3U + 5 = 4U + 4, U = 1, w = 0.8(2) = 1.6, all carried.
    work = (
        "Let U be A's speed before the collision, and let w be B's speed along XY after it.\n"
        "CLM along XY: 3U + 5(1) = 5w\n"
        "NEL: w = 0.8(U + 1)\n"
        "3U + 5 = 4U + 4\n"
        "U = 1 m/s\n"
        "w = 0.8(2) = 1.6 m/s\n"
    )
    said_last = "Let A's speed before be U and B's velocity parallel to XY after be w."
    for text in (work, work.replace(work.splitlines()[0], said_last)):
        found = worst_lines("ocr-mei-fmm-2024-disc-a-stops", text)
        assert found[2][0] == "correct", found
        assert found[3][0] == "wrong"
        assert all(found[n][0] == "carried" for n in (4, 5, 6)), found


def test_a_students_own_equation_numbers_are_not_taken_for_the_notes_numbers() -> None:
    # Notes 4.C.11: A 20 kg at 5 m/s, B 5 kg at 15 m/s, both at 37.6° to n, e = 0.6. Along n:
    # A 5 cos 37.6° = 3.962, B -15 cos 37.6° = -11.884; momentum 79.24 - 59.42 = 19.82 =
    # 20a + 5b (right). Restitution with B's sign lost: b - a = 0.6(3.962 - 11.884) = -4.753.
    # The student's own numbers (1), (2) are not the notes' (1), (2) (the t momenta): with
    # their momentum kept, (1) - 5x(2): 25a = 19.82 + 23.765 = 43.585, a = 1.743, b = -3.010.
    work = (
        "20(3.962) + 5(-11.884) = 20 v_A2n + 5 v_B2n\n"
        "19.82 = 20 v_A2n + 5 v_B2n        (1)\n"
        "v_B2n - v_A2n = 0.6(3.962 - 11.884) = -4.753        (2)\n"
        "(1) - 5x(2):   25 v_A2n = 19.82 + 23.765 = 43.585\n"
        "v_A2n = 1.743 m/s\n"
        "v_B2n = 1.743 - 4.753 = -3.010 m/s\n"
    )
    for tags in (("(1)", "(2)"), ("(3)", "(1)"), ("(i)", "(ii)")):
        text = work.replace("(1)", "#1", 1).replace("(2)", "#2", 1).replace("#1", tags[0]).replace("#2", tags[1])
        found = worst_lines("notes-4c11-two-spheres", text)
        assert found[2][0] == "correct", (tags, found)
        assert found[3][:2] == ("wrong", "b_sign"), (tags, found)
        assert all(found[n][0] == "carried" for n in (4, 5, 6)), (tags, found)


def test_a_restitution_numbered_as_the_notes_momentum_is_judged_as_the_restitution() -> None:
    # AQA M3 2007: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it (-2), e = 0.8. The student
    # numbers their steps, the restitution first: (3) with B's sign lost, v_B - v_A = 0.8(3 - 2)
    # = 0.8 (for 0.8(3 + 2) = 4); (4) the momentum, right: 0.9 - 0.4 = 0.5 = 0.3v_A + 0.2v_B.
    # Then 0.5 = 0.3v_A + 0.2(v_A + 0.8) = 0.5v_A + 0.16: v_A = 0.68, v_B = 1.48, carried.
    work = (
        "v_B - v_A = 0.8(3 - 2) = 0.8     (3)\n"
        "0.3(3) + 0.2(-2) = 0.3 v_A + 0.2 v_B     (4)\n"
        "0.5 = 0.3 v_A + 0.2(v_A + 0.8)\n"
        "0.5 v_A = 0.34\n"
        "v_A = 0.68 m/s\n"
        "v_B = 0.68 + 0.8 = 1.48 m/s\n"
    )
    found = worst_lines("aqa-m3-2007-spheres-approach-head-on", work)
    assert found[1][:2] == ("wrong", "b_sign"), found
    assert found[2][0] == "correct", found
    assert all(found[n][0] == "carried" for n in (3, 4, 5, 6)), found


def test_bracketed_names_with_marks_parted_by_a_comma_are_read_and_carried() -> None:
    # Notes 4.C.11 (as above): momentum along n 19.82 = 20a + 5b. The engineering names with
    # their marks parted by a comma, (v_A)_{n,2}, in LaTeX and typed (vA)_(n,2), are a and b:
    # the restitution with B's sign lost, b - a = -4.753, then 25a = 43.585 carried.
    tex = (
        "\\begin{align*}\n"
        "20(3.962) + 5(-11.884) &= 20(v_A)_{n,2} + 5(v_B)_{n,2}\\\\\n"
        "(v_B)_{n,2} - (v_A)_{n,2} &= 0.6(3.962 - 11.884) = -4.753\\\\\n"
        "25(v_A)_{n,2} &= 19.82 + 23.765 = 43.585\\\\\n"
        "(v_A)_{n,2} &= 1.743\n"
        "\\end{align*}\n"
    )
    plain = (
        "20(3.962) + 5(-11.884) = 20(vA)_(n,2) + 5(vB)_(n,2)\n"
        "(vB)_(n,2) - (vA)_(n,2) = 0.6(3.962 - 11.884) = -4.753\n"
        "25(vA)_(n,2) = 19.82 + 23.765 = 43.585\n"
        "(vA)_(n,2) = 1.743\n"
    )
    for text, first in ((tex, 2), (plain, 1)):
        found = worst_lines("notes-4c11-two-spheres", text)
        assert found[first][0] == "correct", found
        assert found[first + 1][:2] == ("wrong", "b_sign"), found
        assert found[first + 2][0] == found[first + 3][0] == "carried", found


def test_e_moved_to_the_component_along_the_cushion_is_one_mistake_made_twice() -> None:
    # Edexcel FM1 2023 (cushion DC, t along it, n out of it): truly v_A2t = U cos(alpha),
    # v_A2n = -e_1 U sin(alpha), tan(beta) = e_1 tan(alpha). With e_1 on the t component and
    # left off the n one: tan(beta) = U sin(alpha)/(e_1 U cos(alpha)) = tan(alpha)/e_1. One
    # misunderstanding (e on the wrong component) in two lines, in either order: the second is
    # the same mistake again, and the tangent is carried.
    t_first = (
        "v_A2t = e_1 U cos(alpha)\n"
        "v_A2n = -U sin(alpha)\n"
        "tan(beta) = U sin(alpha)/(e_1 U cos(alpha)) = tan(alpha)/e_1\n"
    )
    n_first = "v_A2n = -U sin(alpha)\nv_A2t = e_1 U cos(alpha)\ntan(beta) = tan(alpha)/e_1\n"
    for work in (t_first, n_first):
        found = lines("edexcel-fm1-2023-june-q7a-cushion-show-tan-beta", work)
        assert found[1][0] == "wrong" and not found[1][2], found
        assert found[2][0] == "wrong" and found[2][2], found  # again
        assert found[3][0] == "carried", found


def test_a_velocity_worked_from_a_wrong_number_is_carried_where_it_is_near_the_true_one_too() -> None:
    # OpenStax 8-30: puck 0.150 kg at 35.0 m/s, goalie 70.0 kg at rest, elastic: v_B2 - v_A2 = 35.0,
    # 5.25 = 0.150 v_A2 + 70.0 v_B2 -> 10.5 = 70.15 v_B2, v_B2 = 0.14968, v_A2 = -34.8503. The
    # division worked as 0.160 (a slip); v_A2 = 0.160 - 35.0 = -34.84 is within a unit of the
    # true -34.85 at its figures, but it is worked from the wrong 0.160 with the restitution the
    # student kept (the slip stands for the momentum it was found from): carried.
    work = (
        "m_A = 0.150 kg, v_A1 = 35.0 m/s\n"
        "m_B = 70.0 kg, v_B1 = 0\n"
        "elastic, so the relative velocity reverses: v_B2 - v_A2 = v_A1 - v_B1 = 35.0\n"
        "m_A v_A1 = m_A v_A2 + m_B v_B2\n"
        "0.150(35.0) = 0.150 v_A2 + 70.0 v_B2\n"
        "5.25 = 0.150 v_A2 + 70.0 v_B2\n"
        "put v_A2 = v_B2 - 35.0 in:\n"
        "5.25 = 0.150 v_B2 - 5.25 + 70.0 v_B2\n"
        "10.5 = 70.15 v_B2\n"
        "v_B2 = 10.5/70.15 = 0.160 m/s\n"
        "v_A2 = 0.160 - 35.0 = -34.84 m/s\n"
    )
    found = worst_lines("openstax-cp-8-30-puck-bounces-off-goalie", work)
    assert found[10][:2] == ("wrong", "arithmetic"), found
    assert found[11][0] == "carried", found


def test_a_velocity_the_slip_gives_at_its_figures_is_carried_though_a_unit_from_the_true_one() -> None:
    # OpenStax 8-30 (as above): 5.25 = 0.150(v_B2 - 35.0) + 70.0 v_B2 -> 70.15 v_B2 = 10.5,
    # v_B2 = 0.14968, v_A2 = -34.8503. The 5.25 moved across with its sign kept: 70.15 v_B2 = 0,
    # so v_A2 = 0 - 35.0 = -35.0: exactly the slip's value; the true -34.85 is -34.9 (or
    # -34.8) at those figures, within a unit of -35.0 only: carried, not correct.
    work = (
        "0.150(35.0) = 0.150 v_A2 + 70.0 v_B2\n"
        "v_B2 - v_A2 = 35.0\n"
        "5.25 = 0.150(v_B2 - 35.0) + 70.0 v_B2\n"
        "70.15 v_B2 = 5.25 - 5.25 = 0\n"
        "v_A2 = v_B2 - 35.0 = -35.0 m/s\n"
    )
    found = worst_lines("openstax-cp-8-30-puck-bounces-off-goalie", work)
    assert found[4][0] == "wrong", found
    assert found[5][0] == "carried", found


def test_two_rounded_values_per_unit_of_a_letter_subtracted_keep_both_last_digits() -> None:
    # Notes 4.C.12 (cue ball, e = 0.9, A at 45° to n, per unit of A's speed v): along n
    # 0.70711v; v_Bn2 = 0.70711v(1.9)/2 = 0.67175v, v_An2 = 0.70711v(0.1)/2 = 0.035355v.
    # Worked from the rounded 0.7071v and 0.6718v, 0.7071v - 0.6718v = 0.0353v: each may be out
    # by 0.00005v, so the difference by 0.0001v, not by the 0.00005v of its own last digit: right.
    work = (
        "v_An1 = v cos 45 = 0.7071v, v_At1 = v sin 45 = 0.7071v\n"
        "v_An2 + v_Bn2 = 0.7071v\n"
        "v_Bn2 - v_An2 = 0.9(0.7071v) = 0.6364v\n"
        "2 v_Bn2 = 1.3435v\n"
        "v_Bn2 = 0.6718v\n"
        "v_An2 = 0.7071v - 0.6718v = 0.0353v\n"
    )
    found = worst_lines("notes-4c12-cue-ball", work)
    assert all(found[n][0] == "correct" for n in range(1, 7)), found


def test_a_velocity_between_bars_worked_from_its_components_is_the_speed() -> None:
    # Notes 4.C.11 (as above): after the impact A has -1.109 along n and 5 sin 37.6° = 3.051
    # along t, B 8.398 along n and -15 sin 37.6° = -9.152 along t. |v_A'| (US texts' bars for
    # the size) worked from the components is A's speed, sqrt(1.230 + 9.308) = 3.246, and
    # |v_B'| = sqrt(70.53 + 83.76) = 12.42: not the size of the n component.
    work = (
        "v_Ax' = -1.109 m/s, v_Ay' = 3.051 m/s\n"
        "|v_A'| = sqrt((-1.109)^2 + 3.051^2) = 3.246 m/s\n"
        "|v_B'| = sqrt(8.398^2 + (-9.152)^2) = 12.42 m/s\n"
    )
    found = worst_lines("notes-4c11-two-spheres", work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3, found
