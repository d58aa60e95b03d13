"""A chain's derivation read stage by stage as a teacher reads it (issue #31, chains): suvat lines
in the letters students use (``2 g h``), a slip in one stage carried into the next with the
student's own relations, general results in letters applied to each stage. Every number is
worked by hand from the problem files' givens (in the comments)."""

from __future__ import annotations

import pytest
from support.checked import worst_lines as lines

from derive.mathtext.splitting import split_relations
from derive.resources import problems_dir


# --- suvat in letters: "2 g h" is two times g times h, not 2 grams --------------------------
@pytest.mark.parametrize(
    "text",
    ["v^2 = 2 g h = 2(9.81)(3) = 58.9", "u^2 = 2 g s = 19.6", "V^2 = 2g h = 2(9.8)(0.5)", "v^2 = 2 g H = 39.2"],
)
def test_two_g_h_in_a_suvat_line_is_one_relation(text: str) -> None:
    assert len(split_relations(text)) == 1


@pytest.mark.parametrize("text", ["m = 50 g v = 3 m/s", "m_A = 40 g u = 2", "mass = 20 g v = 4"])
def test_a_mass_in_grams_before_another_given_is_still_two(text: str) -> None:
    assert len(split_relations(text)) == 2


def test_a_rise_written_as_two_g_h_is_read_and_correct() -> None:
    # OCR M2 2015 chain (thrown down at 5 m/s from 1.6 m, e = 0.7, g = 9.8): v_1^2 = 25 + 31.36
    # = 56.36, v_1 = 7.507; v_2 = 0.7(7.507) = 5.255; 5.255^2 = 27.62 = 2 g h, h = 27.62/19.6 = 1.409.
    work = (
        "v_1^2 = 5^2 + 2(9.8)(1.6) = 56.36\nv_1 = 7.507\nv_2 = 0.7(7.507) = 5.255\n"
        "v_2^2 = 2 g h = 27.62\nh = 27.62/19.6 = 1.409\n"
    )
    found = lines("chain-ocr-m2-2015-thrown-down-bounce", work)
    assert [found[n][0] for n in range(1, 6)] == ["correct"] * 5


# --- a slip carried in the student's own relations, not in numbers ---------------------------
def test_a_slip_in_letters_carried_into_the_next_impact_and_the_solve_is_carried() -> None:
    # Edexcel M2 three particles (equal masses, A at 7 m/s, C leaves at 4 m/s), in x, y (A, B after
    # the first impact) and p, q (B, C after the second). 2y = 7 + 7e is right; y = 7(1 + e) is the
    # slip (not halved: truly y = 3.5(1 + e)). Then, in the student's own relations, 2q = y(1 + e)
    # = 7(1 + e)^2, with q = 4: 8 = 7(1 + e)^2, (1 + e)^2 = 8/7 = 1.142857, 1 + e = 1.069045, e = 0.069
    # (the true e is 4/sqrt(7) - 1 = 0.512): every line after the slip is right given it.
    work = (
        "7 = x + y\ny - x = 7e\n2y = 7 + 7e\ny = 7(1 + e)\ny = p + q\nq - p = e y\n2q = y(1 + e)\n"
        "2q = 7(1 + e)^2\n8 = 7(1 + e)^2\n(1 + e)^2 = 8/7\ne = 0.069\n"
    )
    found = lines("chain-edexcel-m2-three-particles", work)
    assert [found[n][0] for n in (1, 2, 3, 5, 6, 7)] == ["correct"] * 6
    assert found[4][0] == "wrong"
    assert [found[n][0] for n in (8, 9, 10, 11)] == ["carried"] * 4


def test_an_equation_for_e_from_a_slipped_expression_is_carried_where_the_given_is_put_in() -> None:
    # The same chain in u, v (B after the first impact is u, C after the second is v = 4): u = 3.5 +
    # 3.5e is right, written u = 3.5 + 7e (one term halved). Then v = u(1 + e)/2 (right) and v = 4
    # give (3.5 + 7e)(1 + e) = 8: 7e^2 + 10.5e + 3.5 = 8, 7e^2 + 10.5e - 4.5 = 0,
    # e = (-10.5 + sqrt(110.25 + 126))/14 = (-10.5 + 15.3704)/14 = 0.348: carried, not new slips.
    work = "u = (7 + 7e)/2\nu = 3.5 + 7e\nv = u(1 + e)/2\n(3.5 + 7e)(1 + e)/2 = 4\n7e^2 + 10.5e - 4.5 = 0\ne = 0.348\n"
    found = lines("chain-edexcel-m2-three-particles", work)
    assert found[1][0] == "correct"
    assert found[2][0] == "wrong"
    assert [found[n][0] for n in (4, 5, 6)] == ["carried"] * 3


# --- a general result in letters, applied to each stage ----------------------------------------
def test_a_general_result_applied_with_its_letter_given_in_words_is_correct_stage_by_stage() -> None:
    # Edexcel M2 three particles (equal masses, A at 7 m/s, C leaves at 4 m/s). Once in letters,
    # a mass at w striking an equal one at rest: p + q = w, q - p = e w, so q = w(1 + e)/2; with
    # w = 7, u_B = 7(1 + e)/2; with w = u_B, u_C = u_B(1 + e)/2 = 7(1 + e)^2/4 = 4, (1 + e)^2 = 16/7,
    # 1 + e = 1.512, e = 0.512. "w = 7" and "w = u_B" put values into the letter: no slip.
    work = (
        "Equal masses, the second at rest, first at speed w: after, p and q.\n"
        "m w = m p + m q, so p + q = w\nq - p = e w\nq = w(1 + e)/2\n"
        "First impact, with w = 7: u_B = 7(1 + e)/2\n"
        "Second impact, putting w = u_B: u_C = u_B(1 + e)/2 = 7(1 + e)^2/4\n"
        "7(1 + e)^2/4 = 4\n1 + e = sqrt(16/7) = 1.512\ne = 0.512\n"
    )
    found = lines("chain-edexcel-m2-three-particles", work)
    assert [found[n][0] for n in range(2, 10)] == ["correct"] * 8


def test_a_wrong_number_put_into_a_general_results_letter_is_judged() -> None:
    # Edexcel M2 three particles again: q = w(1 + e)/2 for a mass at w striking an equal one at
    # rest. B strikes C at u_B = 7(1 + e)/2 = 5.29 m/s (e = 0.512), so "(w = 3)" for the second
    # impact puts in a speed the chain never has and the student never found: the line is the
    # slip (w should be u_B), and 4 = 3(1 + e)/2, e = 1.67 carry it. "(w = 7)" is A's 7 m/s.
    work = (
        "Equal mass m at speed w hits equal mass at rest: p + q = w, q - p = e w.\n"
        "So q = w(1 + e)/2.\n"
        "A hits B (w = 7): u_B = 7(1 + e)/2\n"
        "B hits C (w = 3): u_C = w(1 + e)/2\n"
        "4 = 3(1 + e)/2\n"
        "e = 1.67\n"
    )
    found = lines("chain-edexcel-m2-three-particles", work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3
    assert found[4][0] == "wrong"
    assert found[5][0] == found[6][0] == "carried"


def test_a_letter_of_a_suvat_result_given_each_stage_height_in_brackets_is_no_slip(tmp_path) -> None:
    # OCR M2 2006's chain with a drop of 2.5 m and a rebound to 1.6 m (g = 9.8): from rest through
    # h, v = sqrt(2 g h); falling (h = 2.5) v_1 = sqrt(49) = 7; rising (h = 1.6) v_2 = sqrt(31.36)
    # = 5.6; e = 5.6/7 = 0.8; the impulse 0.3(5.6 + 7) = 3.78 N s.
    text = (problems_dir() / "chain-ocr-m2-2006-drop-rebound.toml").read_text()
    problem = tmp_path / "drop.toml"
    problem.write_text(text.replace('h_0 = "2 m"', 'h_0 = "2.5 m"').replace('h_r = "1.4 m"', 'h_r = "1.6 m"'))
    work = (
        "v = sqrt(2 g h)\nfalling (h = 2.5): v_1 = sqrt(2(9.8)(2.5)) = 7\n"
        "rising (h = 1.6): v_2 = sqrt(2(9.8)(1.6)) = 5.6\ne = 5.6/7 = 0.8\nJ = 0.3(5.6 + 7) = 3.78\n"
    )
    found = lines(str(problem), work)
    assert [found[n][0] for n in range(1, 6)] == ["correct"] * 5


# --- names listed by body after "after:", a value said for each ---------------------------------
@pytest.mark.parametrize(
    "said",
    ["After: A p, B q", "after impact: A -> p, B -> q", "After: A: p, B: q"],
)
def test_names_listed_by_body_after_the_impact_then_their_values_by_body(said: str) -> None:
    # AQA M3 2007 chain (A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it, e = 0.8): 0.9 - 0.4 = 0.5
    # = 0.3p + 0.2q; q - p = 0.8(3 + 2) = 4; 0.5q = 0.5 + 1.2 = 1.7, q = 3.4, p = -0.6.
    work = f"A hits B. {said}\n0.5 = 0.3p + 0.2q\nq - p = 4\nso after: A p = -0.6, B q = 3.4\n"
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert [found[n][0] for n in (2, 3, 4)] == ["correct"] * 3


def test_a_list_of_names_after_an_impact_with_a_given_value_for_the_last() -> None:
    # The same chain: B then strikes the wall (e = 0.7) and leaves it at 0.7(3.4) = 2.38; in the
    # first impact's list, "B q = 3.4" says B's velocity after is 3.4 (with A's name p before it).
    work = "After: A p, B q = 3.4\n0.5 = 0.3p + 0.2(3.4)\np = (0.5 - 0.68)/0.3 = -0.6\n"
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3


# --- a check in brackets after a result --------------------------------------------------------
def test_a_check_in_brackets_with_its_own_brackets_is_a_relation_of_its_own() -> None:
    assert split_relations("e = 4.2/5.6 = 0.75 (check: sqrt(0.9/1.6) = sqrt(0.5625) = 0.75)") == [
        "e = 4.2/5.6 = 0.75  ",
        " check: sqrt(0.9/1.6) = sqrt(0.5625) = 0.75 ",
    ]


def test_a_result_checked_in_brackets_is_correct() -> None:
    # OCR M2 2015 chain (5 m/s down from 1.6 m, g = 9.8): v_1^2 = 25 + 31.36 = 56.36, v_1 = 7.507;
    # the check 7.507^2 = 56.36 (56.355) in brackets after it.
    work = "v_1 = sqrt(25 + 2(9.8)(1.6)) = 7.507 \\quad (check: $(7.507)^2 = 56.36$)\n"
    found = lines("chain-ocr-m2-2015-thrown-down-bounce", work)
    assert found[1][0] == "correct"


# --- a later stage worked from the student's wrong value -----------------------------------------
def test_a_later_stage_in_a_name_never_worked_is_carried_from_the_students_wrong_value() -> None:
    # MSU bullet and block (0.020 kg at 300 m/s into 4.0 kg; g = 9.81). Kinetic energy kept (the
    # slip): ½(0.020)(300)^2 = 900 = ½(4.02)V^2, V^2 = 447.76, V = 21.16 (truly 6/4.02 = 1.4925).
    # The swing from the student's V: h = 21.16^2/(2(9.81)) = 22.82, and 4.02(9.81)(22.82) = 900:
    # the rise written as 900 = 4.02 × 9.81 × h is right given the slip (truly 4.478 = 39.44 h).
    work = "energy kept: ½(0.020)(300)^2 = ½(4.02)V^2\nV^2 = 447.76, V = 21.16\nrise: 900 = 4.02 × 9.81 × h\nh = 22.8\n"
    found = lines("chain-msu-bullet-block-swings", work)
    assert found[1][0] == "wrong"
    assert [found[n][0] for n in (2, 3, 4)] == ["carried"] * 3


# --- a name set to the number it is written with is no quantity checked ---------------------
# Dropped from h_0 = 2 m (g = 9.8): the speed before the floor is sqrt(2 x 9.8 x 2) = 6.26 m/s, so
# 7.0 is no value of the chain's; a name no value fits was taken to be the number itself, and its
# line "correct" for it.
@pytest.mark.parametrize(
    "text", ["speed just before impact = 7.0", "w = 3.1", "velocity before it lands = 7.0 m/s", "v = 3.1"]
)
def test_a_name_set_to_a_number_no_value_fits_is_never_correct(text: str) -> None:
    found = lines("chain-ocr-m2-2006-drop-rebound", text + "\n")
    assert found[1][0] != "correct"


# --- the kinetic energy after the impact named in words ------------------------------------------
# Bullet 0.020 kg at 300 m/s into a 4.0 kg block: V = 6/4.02 = 1.4925 m/s, the kinetic energy after
# ½(4.02)(1.4925)² = 4.478 J. Kept instead (the slip): ½(0.020)(300)² = 900 = ½(4.02)V², V = 21.16,
# and the kinetic energy after is then 900 J, carried.
@pytest.mark.parametrize(
    "name", ["KE immediately after", "kinetic energy after the collision", "KE right after", "KE after impact"]
)
def test_the_kinetic_energy_after_in_words(name: str) -> None:
    right = lines("chain-msu-bullet-block-swings", f"0.020(300) = 4.02 V\nV = 1.4925\n{name} = 4.48\n")
    assert right[3][0] == "correct"
    wrong = lines("chain-msu-bullet-block-swings", f"0.020(300) = 4.02 V\nV = 1.4925\n{name} = 9.0\n")
    assert wrong[3][0] == "wrong"
    kept = "1/2 (0.020)(300)^2 = 1/2 (4.02) V^2\nV^2 = 447.76\nV = 21.16\n" + f"{name} = 900 J\n"
    assert lines("chain-msu-bullet-block-swings", kept)[4][0] == "carried"


# --- a wrong whole number carried into the next stage ------------------------------------------
# A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it, e = 0.8, the wall's 0.7. With e left out
# (y - x = 5): 0.5 = 0.3x + 0.2(x + 5) gives x = -1, y = 4 (truly -0.6 and 3.4), so B comes off the
# wall at 0.7 × 4 = 2.8 (truly 2.38): worked from the student's 4, a carried line, not a correct one.
@pytest.mark.parametrize(
    "head", ["right +ve. after: A x, B y", "Let x and y be the velocities of A and B after the collision."]
)
def test_a_wrong_whole_number_used_in_the_next_stage_is_carried(head: str) -> None:
    work = (
        f"{head}\n0.3(3) + 0.2(-2) = 0.3x + 0.2y\ny - x = 3 + 2 = 5\n0.5 = 0.3x + 0.2(x + 5) = 0.5x + 1\n"
        "x = -1, y = 4\nspeed off the wall = 0.7 x 4 = 2.8 m/s\n"
    )
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert found[3][0] == "wrong"
    assert found[6][0] == "carried"


# --- names no value fits stay unknown: never a yes/no answer, never the student's own numbers ---
# The same chain and slip (x = -1, y = 4 from e left out; truly -0.6 and 3.4), the names said in a
# way not read as a declaration: "again" (yes = 1) is no velocity, and x = -1 written by the student
# is no truth to judge the lines before it with.
def test_names_no_value_fits_are_not_the_answer_yes_or_the_students_numbers() -> None:
    work = (
        "after the collision: A has x, B has y (right positive)\n0.3(3) + 0.2(-2) = 0.3x + 0.2y\n"
        "y - x = 3 + 2 = 5\n0.5 = 0.3x + 0.2(x + 5) = 0.5x + 1\nx = -1, y = 4\n"
    )
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert found[4][0] != "correct"
    assert found[5][0] != "correct"


# --- names set to numbers in a chain: a mass worked from a weight; a value after a slip --------
# Suitcases: W_A = 15 lb, W_B = 10 lb, h = 6 ft, e = 0.3, g = 32.2. m_A = 15/32.2 = 0.4658 slug is
# right (0.5137 is no value of the problem's). With g taken as 9.81 (the slip): v1 = sqrt(2(9.81)(6))
# = 10.85; 15 vA + 10 vB = 15(10.85) and vB - vA = 0.3(10.85) = 3.255 give 25 vA = 130.2, vA = 5.208,
# vB = 8.463 (truly 9.435 and 15.33): those values, and the momentum line worked from 10.85, are carried.
def test_a_mass_from_a_weight_is_right_and_a_value_after_a_slip_carried() -> None:
    right = lines("chain-hibbeler-15-58-suitcases", "mA = 0.4658 slug\n")
    assert right[1][0] == "correct"
    assert lines("chain-hibbeler-15-58-suitcases", "mA = 0.5137 slug\n")[1][0] != "correct"
    work = (
        "v1 = sqrt(2(9.81)(6)) = 10.85\nmA = 0.4658, mB = 0.3106\n0.4658(10.85) = 0.4658 vA + 0.3106 vB\n"
        "vB - vA = 0.3(10.85) = 3.255\nvA = 5.208, vB = 8.463\n"
    )
    found = lines("chain-hibbeler-15-58-suitcases", work)
    assert found[1][0] == "wrong"
    assert [found[n][0] for n in (3, 5)] == ["carried", "carried"]


def test_a_line_of_givens_with_a_word_before_them_is_a_report_not_an_internal_error() -> None:
    # OCR M2 Jan 2007 Q3 (mark scheme: x = 35): v² = 21² + 2(9.8)(40) = 441 + 784 = 1225, v = 35.
    # "down +ve" before the givens once raised ParseError (unknown name 'down') out of the checker.
    work = "down +ve, u = 21, h = 40, g = 9.8\nv^2 = 21^2 + 2(9.8)(40) = 1225\nv = 35\n"
    found = lines("chain-ocr-m2-2007-rebounds-to-start", work)
    assert found[2][0] == "correct" and found[3][0] == "correct"


@pytest.mark.parametrize("end", ["\r", "\r\n", "\u2028", "\x0c"])
def test_lines_ended_otherwise_than_by_a_newline_are_numbered_as_typed(end: str) -> None:
    # OCR M2 June 2006 Q2 (mark scheme: 6.26 and 5.24): v1² = 2(9.8)(2) = 39.2, v1 = 6.261;
    # v2² = 2(9.8)(1.4) = 27.44, v2 = 5.238. A file saved with old Mac line ends ("\r") once
    # raised IndexError out of the chain's reading (lines counted two ways).
    work = end.join(["v_1^2 = 2(9.8)(2) = 39.2", "v_1 = 6.26", "v_2^2 = 2(9.8)(1.4) = 27.44", "v_2 = 5.24"])
    found = lines("chain-ocr-m2-2006-drop-rebound", work)
    assert [found.get(n, ("",))[0] for n in (1, 2, 3, 4)] == ["correct"] * 4
