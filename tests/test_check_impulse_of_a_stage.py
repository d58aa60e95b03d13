"""In a chain of two impacts (two spheres, then one of them on a wall) where only the wall's
impulse is a named result, the word "impulse" on a line of the first impact is that impact's
impulse (the one the line's number is), worked from B's mass and velocities, not the wall's.

A test's own chain, worked by hand: B (0.5 kg) at 2 m/s toward A, A at 4 m/s; after, A on at
1 m/s and B back at 3 m/s: e = (3 - 1)/(4 + 2) = 1/3; the impulse on B is 0.5(3 + 2) = 2.5 N s,
on A -2.5 = m_A(1 - 4), m_A = 5/6 = 0.833 kg. The wall's impulse is 2.7 N s = 0.5(w + 3): w = 2.4,
e_wall = 2.4/3 = 0.8.
"""

from __future__ import annotations

import pytest
from support.checked import solved_text, statuses_of

PROBLEM = """
title = "Two spheres, then B on a wall (a test's own numbers)"
kind = "chain"
find = ["e", "m_A", "e_wall"]

[given]
m_B = "0.5 kg"
v_A = "4 m/s"
v_B = "2 m/s"
s_A = "1 m/s"
s_B = "3 m/s"
I_w = "2.7 N*s"
e_wall = "?"

[[stage]]
type = "impact"
title = "A and B collide"
kind = "direct"
given = { m_A = "? kg", m_B = "m_B", e = "?", v_A1 = "v_A", v_B1 = "-v_B", v_A2 = "s_A", v_B2 = "s_B" }
results = { v_B2 = "u_B" }

[[stage]]
type = "impact"
title = "B strikes the wall"
kind = "direct"
given = { m_A = "m_B", e = "e_wall", v_A1 = "u_B" }
A = { label = "B" }
B = { fixed = true, name = "wall" }
results = { J_n = "J_w", v_A2 = "w_B" }

[[stage]]
type = "solve"
condition = "J_w = I_w"
for = "e_wall"
"""


@pytest.fixture(scope="module")
def solution(tmp_path_factory):
    return solved_text(tmp_path_factory.mktemp("stageimpulse"), "two-impacts.toml", PROBLEM)


WORK = """\
e = (3 - 1)/(4 + 2) = 1/3
impulse = 0.5(3 - (-2)) = 2.5 N s
and on A: -2.5 = m_A(1 - 4), so m_A = 0.833 kg
"""


def test_the_first_impacts_impulse_in_words(solution) -> None:
    assert statuses_of(solution, WORK) == {1: "correct", 2: "correct", 3: "correct"}


def test_the_integral_of_the_force_is_the_first_impacts_impulse(solution) -> None:
    got = statuses_of(solution, WORK.replace("impulse = ", "∫F dt = "))
    assert got == {1: "correct", 2: "correct", 3: "correct"}


def test_a_wrong_impulse_of_the_first_impact_is_wrong(solution) -> None:
    # B's velocity before put in as +2 (its direction lost): 0.5(3 - 2) = 0.5, worked rightly
    got = statuses_of(solution, WORK.replace("0.5(3 - (-2)) = 2.5", "0.5(3 - 2) = 0.5"))
    assert got[2] == "wrong"
