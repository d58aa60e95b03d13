"""An angle after the impact declared in words about a velocity written as a name ("the angle
between v_A and the plane of contact", "$\\vec{v}_A$ makes an angle $\\beta$ with the line of
centres", "φ is the angle v_1' makes with the l.o.c.", "the angle between $\\vec{v}_{1f}$ and the
line of centres") is that velocity's direction after the impact (:mod:`derive.checking.anglenames`,
read by :func:`derive.checking.wordnames.in_words`), not a quantity of the student's own: a line
that finds it from a carried component is carried, and a law relating it to another angle is
correct. Every value is worked by hand from the givens."""

from __future__ import annotations

import pytest
from support.checked import lines, solution, worst_lines

from derive.checking.context import Context
from derive.checking.wordnames import in_words

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


# Pre-U specimen (equal balls, B at rest, A at u at 30° to the line of centres), the velocity named
# by the bodies' digits, primed or marked f for after. True: along the line u√3/2, across u/2;
# a + b = u√3/2, b - a = e u√3/2, a = (√3/4)u(1 - e), tan φ = 2/(√3(1 - e)), θ = φ - 30°.
# Restitution reversed (a - b = e u√3/2): a = (√3/4)u(1 + e), tan φ = 2/(√3(1 + e)).
PRE_U_FILE = "pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg"
CUSHION = "edexcel-fm1-2023-june-q7a-cushion-show-tan-beta"

PLAIN = """let x, y be the velocities of A and B along the line of centres after
x + y = (sqrt(3)/2)u
x - y = e(sqrt(3)/2)u
x = (sqrt(3)/4)u(1 + e)
phi is the angle v_1' makes with the l.o.c.
tan(phi) = (u/2)/((sqrt(3)/4)u(1 + e)) = 2/(sqrt(3)(1 + e))
theta = phi - 30
tan(theta) = (tan(phi) - tan(30))/(1 + tan(phi)tan(30))
"""

LATEX = r"""Momentum and restitution along the line of centres, $a$ and $b$ the components after:
\[ a + b = \tfrac{\sqrt{3}}{2}u, \qquad a - b = e\tfrac{\sqrt{3}}{2}u \]
\[ a = \tfrac{\sqrt{3}}{4}u(1 + e) \]
Let $\varphi$ denote the angle between $\vec{v}_{1f}$ and the line of centres.
\[ \tan\varphi = \frac{u/2}{\tfrac{\sqrt{3}}{4}u(1 + e)} = \frac{2}{\sqrt{3}(1 + e)} \]
\[ \theta = \varphi - 30^\circ \]
"""


def test_a_relation_in_the_declared_angle_holds_for_it_as_it_truly_is() -> None:
    found = worst_lines(PRE_U_FILE, PLAIN)
    assert found[2][0] == "correct"
    assert found[3][0] == "wrong"
    assert [found[n][0] for n in (4, 6)] == ["carried", "carried"]  # worked from the reversed a
    assert [found[n][0] for n in (7, 8)] == ["correct", "correct"]  # true whatever φ's value is


def test_the_same_in_latex_with_a_vector_and_varphi() -> None:
    found = worst_lines(PRE_U_FILE, LATEX)
    assert found[2][0] == "wrong"
    assert [found[n][0] for n in (3, 5)] == ["carried", "carried"]
    assert found[6][0] == "correct"


def test_a_wrong_relation_in_the_declared_angle_stays_wrong() -> None:
    work = PLAIN.replace("theta = phi - 30", "theta = phi + 30").replace("tan(theta) = (tan(phi) - tan(30))", "z = (1")
    found = worst_lines(PRE_U_FILE, work.rsplit("\n", 2)[0] + "\n")
    assert found[7][0] == "wrong"


@pytest.mark.parametrize(
    ("problem", "line", "meant"),
    [
        (PRE_U_FILE, "psi is the angle u_1 makes with the l.o.c.", {}),  # before the impact: not declared here
        (PRE_U_FILE, "β = angle between the vector v_B' and the line of centres", {"beta": "beta_B2"}),
        (CUSHION, r"Let $\phi$ be the angle between $\vec v_2$ and the cushion", {"phi": "theta_A2"}),  # v_2: after
    ],
)
def test_which_velocity_the_name_says(problem: str, line: str, meant: dict) -> None:
    found = in_words(line, Context(solution(problem), None))
    assert {k: str(v).lstrip("-") for k, v in found.items() if "beta" in str(v) or "theta" in str(v)} == meant


@pytest.mark.parametrize(
    ("line", "meant"),
    [
        # B leaves along the line of centres (B at rest, hit along it): its angle is B's, 0, never A's
        ("Let θ be the angle that the vector v_B' makes with the line of centres.", {"theta": "beta_B2"}),
        ("β is the angle between B's velocity after and the line of centres", {"beta": "beta_B2"}),
        (r"Let $\vartheta$ be the angle $\mathbf{v}_2'$ makes with the l.o.c.", {"theta": "beta_B2"}),
        ("α = the angle the velocity v_A makes with the line of centres", {"alpha": "beta_A2"}),
    ],
)
def test_the_body_the_words_or_the_name_say_is_the_one_whose_angle_it_is(line: str, meant: dict) -> None:
    found = in_words(line, Context(solution(PRE_U_FILE), None))
    assert {k: str(v).lstrip("-") for k, v in found.items()} == meant
