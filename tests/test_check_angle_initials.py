"""A given angle typed as its Greek name's initial (issue #31): with no Greek on the keyboard a
student writes ``u cos a`` for u cos(alpha), ``tan b`` for tan(beta). A sine's, cosine's or
tangent's argument is an angle: a letter there that the problem and the student use for nothing
else is the problem's one angle whose Greek name starts with it.

Values worked by hand: Edexcel M4 June 2005 Q3 (identical spheres, Q at speed u at alpha to the
line of centres hits P at rest, e): across the line of centres Q keeps u sin(alpha); along it
v_Q + v_P = u cos(alpha), v_P - v_Q = e u cos(alpha), so v_Q = u cos(alpha)(1 - e)/2 and
tan(beta) = u sin(alpha) / (u cos(alpha)(1 - e)/2) = 2 tan(alpha)/(1 - e).
"""

from __future__ import annotations

from support.checked import worst_lines

from derive.checking.spellings import angle_initials

PROBLEM = "edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta"
WORK = """x along the line of centres (Q to P), y across it; Q moves at angle a to the line of centres.
v_Qy = u sin a
v_Q + v_P = u cos a
v_P - v_Q = e u cos(a)
v_Q = u cos(a)(1 - e)/2
tan b = u sin a/(u cos(a)(1 - e)/2) = 2 tan a/(1 - e)
"""


def test_an_angles_initial_in_a_trigonometric_function_is_the_angle() -> None:
    known = {"alpha", "beta_A2", "u", "e"}
    assert angle_initials("u cos a + sin(b) - cos^2 a", known) == "u cos alpha + sin(beta_A2) - cos^2 alpha"


def test_a_letter_used_for_something_else_stays_itself() -> None:
    assert angle_initials("u cos a + a", {"alpha", "a"}) == "u cos a + a"
    assert angle_initials("u cos t", {"theta_1", "theta_2"}) == "u cos t"  # which theta: not decided


def test_a_given_angle_is_the_initial_s_angle_beside_a_result_of_its_letter() -> None:
    # alpha given, alpha_A2 (A's angle with the line of centres after) a result: a is the given
    assert angle_initials("u cos a", {"alpha", "alpha_A2", "gamma_A2"}) == "u cos alpha"


def test_work_in_angle_initials_is_read() -> None:
    found = worst_lines(PROBLEM, WORK)
    assert {n: found.get(n, ("missing", ""))[0] for n in (2, 3, 4, 5, 6)} == dict.fromkeys((2, 3, 4, 5, 6), "correct")


def test_a_slip_in_angle_initials_is_wrong() -> None:
    found = worst_lines(PROBLEM, WORK.replace("(1 - e)/2\n", "(1 - e)/3\n"))
    assert found[5][0] == "wrong"
