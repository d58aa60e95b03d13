"""A line that eliminates an unknown between two relations (the momentum and the impact rule
added or subtracted) with a term's coefficient lost is named from the combination it was worked
from: ``algebra`` (derive/checking/eliminated.py). Expected relations worked by hand."""

from __future__ import annotations

from support.checked import lines

#: Edexcel M2 2013: P (2m) at u hits Q (m) at rest: 2u = 2x + y, y − x = eu; subtracting,
#: 3x = 2u − eu, so x = u(2 − e)/3.
TWO_TO_ONE = "edexcel-m2-2013-june-q5-2m-hits-m-ke-three-quarters"
#: WJEC 2019: equal spheres, B at rest: x + y = u, y − x = eu; adding, 2y = u(1 + e).
EQUAL = "wjec-further-unit3-2019-june-q7-equal-spheres-b-at-rest"


def test_subtracting_with_the_unknowns_coefficient_lost() -> None:
    work = "CLM: 2u = 2x + y  (1)\nNEL: y - x = eu  (2)\n(1) - (2): x = 2u - eu\n"  # 3x lost its 3
    assert lines(TWO_TO_ONE, work)[3][:2] == ("wrong", "algebra")


def test_markdown_subtraction_with_the_coefficient_lost() -> None:
    work = "**Momentum:** $2u = 2x + y$\n\n**Restitution:** $y - x = eu$\n\nTaking one from the other, $x = 2u - eu$\n"
    assert lines(TWO_TO_ONE, work)[5][:2] == ("wrong", "algebra")  # 3x = 2u - eu: the 3 lost


def test_adding_latex_with_the_two_lost() -> None:
    work = (
        "Let $x$ and $y$ be the velocities of A and B after.\n"
        "\\[ x + y = u \\]\n"
        "\\[ y - x = eu \\]\n"
        "Adding the two equations,\n"
        "\\[ y = u + eu \\]\n"  # 2y = u + eu: the 2 lost
    )
    assert lines(EQUAL, work)[5][:2] == ("wrong", "algebra")
