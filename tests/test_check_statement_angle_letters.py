"""What a statement names by a letter: the angle asked for by a Greek letter alone ("just after,
it makes an angle β with the line of centres"; the file's ``beta_A2``), and the bodies by P and Q
in an oblique impact ("let v be the velocity of P after the impact, along the line of centres").

Values worked by hand for the problem below (Q, mass m, speed u at 30° to the line of centres; P,
mass m, at rest; e = 1/3): along the line of centres u cos 30° = x + v and v - x = (1/3) u cos 30°,
so v = (2/3) u cos 30° = u/sqrt(3) and x = (1/3) u cos 30°; across it Q keeps u sin 30° = u/2.
tan β = (u/2) / ((1/3) u cos 30°) = 3/(2 cos 30°) = sqrt(3), β = 60°.
"""

from __future__ import annotations

import pytest
from support.checked import solved_text, statuses_of

import derive

PROBLEM = '''title = "Q strikes P at rest, 30° to the line of centres"
kind = "oblique"
source = "a test of the checker's names"
statement = """A smooth sphere P lies at rest on a smooth horizontal plane. A second identical \
sphere Q, moving with speed u, collides with P. Just before the collision Q's direction of \
motion makes an angle of 30° with the line of centres; just after, it makes an angle β with \
it. The coefficient of restitution between the spheres is 1/3."""
question = "Find β."
find = ["beta_A2"]

[given]
m = "kg"
u = "m/s"
e = "1/3"
m_A = "m"
m_B = "m"
v_A1 = "u"
v_B1 = 0
alpha = "30 deg"

[A]
angle = "alpha"
from = "+n"
toward = "+t"
'''


@pytest.fixture(scope="module")
def solution(tmp_path_factory: pytest.TempPathFactory) -> derive.Solution:
    return solved_text(tmp_path_factory.mktemp("letters"), "q-strikes-p.toml", PROBLEM)


def test_the_statements_greek_letter_is_the_angle_asked(solution: derive.Solution) -> None:
    assert statuses_of(solution, "tan(beta) = sqrt(3)\n") == {1: "correct"}
    assert statuses_of(solution, "(1/3) tan(β) = 1/sqrt(3)\n") == {1: "correct"}
    assert statuses_of(solution, "tan(beta) = 1/sqrt(3)\n") == {1: "wrong"}


def test_a_body_by_the_statements_letter_in_an_oblique_impact(solution: derive.Solution) -> None:
    said = "Let $v$ be the velocity of $P$ after the impact, along the line of centres.\n"
    assert statuses_of(solution, said + "v = 2u cos(30°)/3\n") == {2: "correct"}
    assert statuses_of(solution, said + "v = u cos(30°)/3\n")[2] == "wrong"
