"""An angle declared in words by the student's name of the velocity it is of ("φ is the angle
v_1' makes with the l.o.c.", "Let $\\varphi$ denote the angle between $\\vec{v}_{1f}$ and the line
of centres") is derive's angle of that velocity after the impact: a later relation between it and
the deflection (θ = φ - 30°) holds for the angle as it truly is, and is correct; the line that
works φ's tangent out from a wrong component is carried.

Pre-U specimen (equal balls, B at rest, A at u at 30° to the line of centres). True: along the
line u√3/2, across u/2; a + b = u√3/2, b - a = e u√3/2, a = (√3/4)u(1 - e), tan φ = 2/(√3(1 - e)),
θ = φ - 30°. Restitution reversed (a - b = e u√3/2): a = (√3/4)u(1 + e), tan φ = 2/(√3(1 + e)).
"""

from __future__ import annotations

import pytest
from support.checked import solution, worst_lines

from derive.checking.context import Context
from derive.checking.vectorangles import vector_angles

PRE_U = "pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg"
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
    found = worst_lines(PRE_U, PLAIN)
    assert found[2][0] == "correct"
    assert found[3][0] == "wrong"
    assert [found[n][0] for n in (4, 6)] == ["carried", "carried"]  # worked from the reversed a
    assert [found[n][0] for n in (7, 8)] == ["correct", "correct"]  # true whatever φ's value is


def test_the_same_in_latex_with_a_vector_and_varphi() -> None:
    found = worst_lines(PRE_U, LATEX)
    assert found[2][0] == "wrong"
    assert [found[n][0] for n in (3, 5)] == ["carried", "carried"]
    assert found[6][0] == "correct"


def test_a_wrong_relation_in_the_declared_angle_stays_wrong() -> None:
    work = PLAIN.replace("theta = phi - 30", "theta = phi + 30").replace("tan(theta) = (tan(phi) - tan(30))", "z = (1")
    found = worst_lines(PRE_U, work.rsplit("\n", 2)[0] + "\n")
    assert found[7][0] == "wrong"


@pytest.mark.parametrize(
    ("problem", "line", "meant"),
    [
        (PRE_U, "psi is the angle u_1 makes with the l.o.c.", {}),  # before the impact: not declared here
        (PRE_U, "β = angle between the vector v_B' and the line of centres", {"beta": "beta_B2"}),
        (CUSHION, r"Let $\phi$ be the angle between $\vec v_2$ and the cushion", {"phi": "theta_A2"}),  # v_2: after
    ],
)
def test_which_velocity_the_name_says(problem: str, line: str, meant: dict) -> None:
    found = vector_angles(line, Context(solution(problem), None))
    assert {k: str(v).lstrip("-") for k, v in found.items()} == meant
