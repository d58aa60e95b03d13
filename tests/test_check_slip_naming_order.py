"""A slip found at its line is named as most teachers of the corpus name it (docs/checking.md,
"Naming a slip: the teachers' rules"). Each derivation is on another problem or phrasing than
the corpus file it stands for; every value is worked by hand from the problem's givens."""

from __future__ import annotations

from support.checked import worst_lines

#: 2m at 4u meets m at 3u coming the other way (CIE 2014 Nov): 8u - 3u = 5u = 2v_A2 + v_B2 and
#: v_B2 - v_A2 = e(4u + 3u) = 7eu, so v_A2 = v_B2 - 7eu and 5u = 2(v_B2 - 7eu) + v_B2 = 3v_B2 - 14eu.
MEET = "cie-9231-p2-2014-november-q1-2m-at-4u-meets-m-at-3u-a-reverses"
START = "5u = 2v_A2 + v_B2\nv_B2 - v_A2 = 7eu\nv_A2 = v_B2 - 7eu\n"


def test_a_bracket_multiplied_out_on_one_term_in_a_line_is_algebra() -> None:
    # 2(v_B2 - 7eu) written 2v_B2 - 7eu: the 2 taken to v_B2 only, so 3v_B2 - 7eu for 3v_B2 - 14eu
    found = worst_lines(MEET, START + "5u = 2(v_B2 - 7eu) + v_B2 = 3v_B2 - 7eu\n")
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3
    assert found[4] == ("wrong", "algebra")


def test_a_bracket_multiplied_out_on_one_term_from_the_line_before_is_algebra() -> None:
    # the same step over two lines: 5u = 2(v_B2 - 7eu) + v_B2 (right), then 5u = 2v_B2 - 7eu + v_B2
    found = worst_lines(MEET, START + "5u = 2(v_B2 - 7eu) + v_B2\n5u = 2v_B2 - 7eu + v_B2\n")
    assert found[4][0] == "correct"
    assert found[5] == ("wrong", "algebra")


def test_a_bracket_multiplied_out_on_every_term_with_a_number_wrong_stays_arithmetic() -> None:
    # 2 x 7eu = 14eu written 12eu: the 2 reached both terms, a product worked wrongly
    found = worst_lines(MEET, START + "5u = 2(v_B2 - 7eu) + v_B2 = 3v_B2 - 12eu\n")
    assert found[4] == ("wrong", "arithmetic")


#: OCR M2 2006 (find e): 2 kg at 5 m/s hits 1 kg at rest, A goes on at 2 m/s: 10 = 4 + v_B2, so
#: v_B2 = 6; 6 - 2 = e(5 - 0), 4 = 5e and e = 0.8.
FIND_E = "ocr-m2-2006-sphere-hits-sphere-at-rest-find-e"
E_START = "2(5) + 0 = 2(2) + v_B2\nv_B2 = 6\n6 - 2 = e(5 - 0)\n4 = 5e\n"


def test_a_division_with_its_sign_lost_is_arithmetic() -> None:
    # 4/5 = 0.8, written -0.8: nothing moved across, the division of numbers worked wrongly
    found = worst_lines(FIND_E, E_START + "e = -0.8\n")
    assert found[4][0] == "correct"
    assert found[5] == ("wrong", "arithmetic")


def test_a_division_done_as_a_multiplication_or_turned_over_is_arithmetic() -> None:
    # 4 = 5e solved as e = 4 x 5 = 20, or as e = 5/4 = 1.25
    assert worst_lines(FIND_E, E_START + "e = 4 x 5 = 20\n")[5] == ("wrong", "arithmetic")
    assert worst_lines(FIND_E, E_START + "e = 5/4 = 1.25\n")[5] == ("wrong", "arithmetic")


def test_a_number_moved_across_with_its_sign_kept_stays_algebra() -> None:
    # 10 = 4 + v_B2 then v_B2 = 10 + 4 = 14: a term moved, its sign not changed
    found = worst_lines(FIND_E, "2(5) + 0 = 2(2) + v_B2\n10 = 4 + v_B2\nv_B2 = 10 + 4 = 14\n")
    assert found[3] == ("wrong", "algebra")


#: OCR M2 2006: A (2 kg) and B (1 kg) meet head-on at 5 m/s each, e = 0.8: x = -1, y = 7; the
#: kinetic energy after is ½(2)(1) + ½(1)(49) = 1 + 24.5 = 25.5 J.
MEET5 = "ocr-m2-2006-spheres-meet-at-5-ke-lost"
M5_START = "let x = v_A2\nlet y = v_B2\n2(5) + 1(-5) = 2x + y\ny - x = 0.8(5 + 5)\nx = -1, y = 7\n"


def test_an_energy_written_out_with_the_other_bodys_mass_is_ke_formula() -> None:
    # B's term with A's 2 kg: ½(2)x² + ½(2)y² is 1 + 49 = 50, not 25.5
    found = worst_lines(MEET5, M5_START + "1/2(2)x^2 + 1/2(2)y^2 = 25.5\n")
    assert found[5][0] == "correct"
    assert found[6] == ("wrong", "ke_formula")


#: CIE 2014 June Q3: A (m) at u hits B (9m) at rest, half the kinetic energy lost: v_B = u(1 + e)/10,
#: v_A = u(1 - 9e)/10, (1 - 9e)² + 9(1 + e)² = 50, so e = 2/3, v_A = -u/2 and v_B = u/6.
HALF = "cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost"


def test_e_as_approach_over_separation_in_a_find_e_problem_is_restitution_reversed() -> None:
    # the separation is u/6 + u/2 = 2u/3, so e = (2u/3)/u = 2/3; upside down it is 3/2
    work = "v_A = -u/2\nv_B = u/6\ne = u/(u/6 + u/2) = 3/2\n"
    found = worst_lines(HALF, work)
    assert [found[n][0] for n in (1, 2)] == ["correct", "correct"]
    assert found[3] == ("wrong", "restitution_reversed")
