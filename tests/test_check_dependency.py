"""A line after a slip is carried when it holds once the student's own earlier values are put
in for the quantities they stand for (:mod:`derive.checking.dependency`), in a later line of
any kind: the coefficient found from a carried velocity, a result said again after a chain
of "=" lines worked from a wrong formula, a value the slip's world gives exactly. A pointer
after a value (``<- B's velocity``) is a note, not a direction. Every number is worked by hand
from the problem files' givens (in the comments)."""

from __future__ import annotations

from support.checked import lines

# OCR M2 2006 Q8: A (2 kg) at 5 m/s hits B (1 kg) at rest; A goes on at 2 m/s. True:
# 10 = 4 + v_B, v_B = 6, e = (6 - 2)/5 = 0.8. The slip: A's velocity after taken as -2 in the
# momentum only: 10 = -4 + v_B, v_B = 14; with A's +2 as given, e = (14 - 2)/5 = 2.4.
FIND_E = "ocr-m2-2006-sphere-hits-sphere-at-rest-find-e"
SLIP = "momentum: 2 x 5 = 2 x (-2) + v_B\nso v_B = 14 m/s\n"


def test_the_coefficient_found_from_a_carried_velocity_and_the_given_one_is_carried() -> None:
    found = lines(FIND_E, "2(5) = 2(-2) + v_B\nv_B = 14 m/s\ne = (v_B - v_A)/(u_A - u_B) = (14 - 2)/(5 - 0) = 2.4\n")
    assert found[1][:2] == ("wrong", "b_sign")
    assert found[2][0] == "carried"
    assert found[3][0] == "carried"  # not "kinetic energy conserved": A's 2 is the given


def test_the_coefficient_worked_in_numbers_from_a_carried_velocity_is_carried() -> None:
    # (14 - 2)/(5 - 0) is the law with 14 for v_B: with v_B = 6 it is 4/5 = e
    found = lines(FIND_E, SLIP + "e = (14 - 2)/(5 - 0) = 2.4\n")
    assert found[3][0] == "carried"


def test_a_wrong_law_worked_from_a_carried_velocity_is_still_a_slip() -> None:
    # approach over separation: 5/(14 - 2) = 0.417; with v_B = 6 it is 5/4, not e = 0.8
    found = lines(FIND_E, SLIP + "e = (5 - 0)/(14 - 2) = 0.417\n")
    assert found[3][0] == "wrong"


def test_a_result_said_again_after_a_chain_worked_from_a_wrong_formula_is_carried() -> None:
    # Edexcel M4 2005 Q3: Q (m, u at alpha to the line of centres) hits P (m) at rest: after,
    # v_n = u cos(alpha)(1 - e)/2, v_t = u sin(alpha), tan(beta) = v_t/v_n = 2 tan(alpha)/(1 - e).
    # The slip: tan(beta) = v_n/v_t, worked on to (1 - e)/(2 tan(alpha)), then said again.
    work = (
        "After the impact Q has components\n"
        "$$v_n = \\tfrac12 u\\cos\\alpha\\,(1 - e), \\qquad v_t = u\\sin\\alpha$$\n"
        "\\begin{align*}\n"
        "\\tan\\beta &= \\frac{v_n}{v_t}\\\\\n"
        "&= \\frac{\\frac12 u\\cos\\alpha(1-e)}{u\\sin\\alpha}\\\\\n"
        "&= \\frac{1-e}{2\\tan\\alpha}\n"
        "\\end{align*}\n"
        "Hence $\\tan\\beta = \\dfrac{1-e}{2\\tan\\alpha}$, which is not what the question says.\n"
    )
    found = lines("edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta", work)
    assert found[2][0] == "correct"
    assert found[4][0] == "wrong"
    assert found[5][0] == found[6][0] == "carried"
    assert found[8][0] == "carried"


def test_a_value_the_slip_gives_exactly_is_carried_not_correct_at_its_figures() -> None:
    # OpenStax 8-5: 0.150 kg at 35.0 m/s caught by 70.0 kg: v = 5.25/70.15 = 0.07484. The
    # puck's mass left out after: 5.25 = 70.0 v, v = 5.25/70.0 = 0.075 exactly; 0.075 is also
    # 0.07484 at two figures, but the student's 0.075 is the slip's.
    found = lines("openstax-cp-8-5-goalie-catches-puck", "0.150(35.0) = 70.0 v\nv = 5.25/70.0\nv = 0.075 m/s\n")
    assert found[1][0] == "wrong"
    assert found[2][0] == found[3][0] == "carried"


def test_a_left_arrow_pointing_at_a_note_is_no_direction() -> None:
    # BYJU'S: 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5: 80 = 4v_1 + 8v_2, v_2 - v_1 = 4:
    # v_1 = 4, v_2 = 8, both to the right (positive)
    work = (
        "Taking right as positive.\n"
        "4(12) + 8(4) = 4v_1 + 8v_2\n"
        "v_2 - v_1 = 0.5(12 - 4)\n"
        "v_1 = 4 m/s  <-- A's velocity after\n"
        "v_2 = 8 m/s  <- B after the impact\n"
    )
    found = lines("byjus-4kg-ball-catches-8kg-ball", work)
    assert [found[n][0] for n in (4, 5)] == ["correct", "correct"]


def test_a_left_arrow_alone_after_a_value_is_still_its_direction() -> None:
    work = "Taking right as positive.\n4(12) + 8(4) = 4v_1 + 8v_2\nv_2 - v_1 = 0.5(12 - 4)\nv_1 = 4 m/s <-\n"
    assert lines("byjus-4kg-ball-catches-8kg-ball", work)[4][0] == "wrong"  # -4: to the left
