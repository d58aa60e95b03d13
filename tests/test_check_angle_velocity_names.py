"""An angle after the impact declared in words about a velocity written as a name ("the angle
between v_A and the plane of contact", "$\\vec{v}_A$ makes an angle $\\beta$ with the line of
centres") is that velocity's direction after the impact (:mod:`derive.checking.anglenames`), not
a quantity of the student's own: a line that finds it from a carried component is carried, and a
law relating it to another angle is correct. Every value is worked by hand from the givens."""

from __future__ import annotations

from support.checked import lines

# Example 4.C.12: A at v at 45° to the plane of contact hits B (equal mass) at rest, e = 0.9.
# True: v_A2n = (1 - e)/2 v sin45 = 0.05 v sin45, v_A2t = v cos45, tan(phi) = 0.05, phi = 2.86°.
# Restitution reversed (v_A2n - v_B2n = e v sin45): v_A2n = (1 + e)/2 v sin45 = 0.95 v sin45,
# tan(phi) = 0.95, phi = atan(0.95) = 43.5°: carried, not the student's own phi defined.
CUE = "notes-4c12-cue-ball"
CUE_WORK = (
    "n along the line of impact, t along the plane of contact\n"
    "phi = the angle between v_A and the plane of contact after the impact\n"
    "v_A2n + v_B2n = v_A1 sin45\n"
    "v_A2n - v_B2n = e v_A1 sin45\n"
    "v_A2n = (1 + e)/2 * v_A1 sin45 = 0.95 v_A1 sin45\n"
    "tan(phi) = 0.95 v_A1 sin45/(v_A1 cos45) = 0.95\n"
    "phi = 43.5 deg\n"
)


def test_an_angle_of_a_named_velocity_found_from_a_carried_component_is_carried() -> None:
    found = lines(CUE, CUE_WORK)
    assert found[4][0] == "wrong"
    assert [found[n][0] for n in (5, 6, 7)] == ["carried"] * 3


def test_the_angle_of_a_named_velocity_worked_rightly_is_correct() -> None:
    work = CUE_WORK.replace("v_A2n - v_B2n = e v_A1 sin45", "v_B2n - v_A2n = e v_A1 sin45")
    work = work.replace("(1 + e)", "(1 - e)").replace("0.95", "0.05").replace("43.5", "2.86")
    found = lines(CUE, work)
    assert [found[n][0] for n in (3, 4, 5, 6, 7)] == ["correct"] * 5


# Pre-U specimen Q2: equal balls, B at rest, A at u at 30° to the line of centres. True:
# v_A2n = sqrt3 u (1 - e)/4, v_A2t = u/2, tan(beta) = 2/(sqrt3 (1 - e)), deflection beta - 30°.
# Restitution reversed: v_A2n = sqrt3 u (1 + e)/4, tan(beta) = 2/(sqrt3 (1 + e)): carried; the
# deflection theta = beta - 30° holds whatever beta is: correct.
PRE_U = (
    "Take $n$ along the line of centres and $t$ across it.\n"
    "$$v_{A2n} + v_{B2n} = \\tfrac{\\sqrt3}{2}u$$\n"
    "$$v_{A2n} - v_{B2n} = \\tfrac{\\sqrt3}{2}eu$$\n"
    "$$v_{A2n} = \\tfrac{\\sqrt3}{4}u(1 + e), \\quad v_{A2t} = \\tfrac12 u$$\n"
    "After the impact $\\vec{v}_A$ makes an angle $\\beta$ with the line of centres:\n"
    "$$\\tan\\beta = \\frac{\\frac12 u}{\\frac{\\sqrt3}{4}u(1 + e)} = \\frac{2}{\\sqrt3(1 + e)}$$\n"
    "The ball is deflected through $\\theta = \\beta - 30^\\circ$.\n"
)


def test_a_vector_velocity_making_an_angle_with_the_line_of_centres_names_its_direction() -> None:
    found = lines("pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg", PRE_U)
    assert found[3][0] == "wrong"
    assert found[6][0] == "carried"
    assert found[7][0] == "correct"
