"""A chain with two impacts (A and B collide, then B strikes a wall) whose file names its givens
``v_A``, ``v_B`` (the speeds before), as a student names velocities after: the student's names
are read by the A-level habit of the impact between the two moving bodies, never as a given whose
value makes a wrong line hold. Every number is worked by hand from the file's givens below."""

from __future__ import annotations

from pathlib import Path

import pytest
from support.checked import worst_lines

#: A (2 kg) at 4 m/s toward B (1 kg) at 2 m/s, e = 0.5; then B strikes a wall, e = 0.75.
#: Truly: 2(4) + 1(-2) = 6 = 2v_A2 + v_B2, v_B2 - v_A2 = 0.5(6) = 3 -> v_A2 = 1, v_B2 = 4; off the wall 0.75(4) = 3 back: w_B = -3.
#: B's sign lost: 2(4) + 1(2) = 10 = 2v_A2 + v_B2 -> 3v_A2 + 3 = 10, v_A2 = 7/3 = 2.33, v_B2 = 5.33.
CHAIN = """
title = "Chain: A and B collide, then B strikes a wall"
kind = "chain"
statement = "Spheres A ({m_A}) and B ({m_B}) move toward each other, A at {v_A} and B at {v_B}; e = {e}. B then strikes a wall (e = {e_wall})."
question = "Find the velocities after the impact and B's after the wall."
digits = 3
find = ["u_A", "u_B", "w_B"]

[given]
m_A = "2 kg"
m_B = "1 kg"
v_A = "4 m/s"
v_B = "2 m/s"
e = 0.5
e_wall = 0.75

[[stage]]
type = "impact"
title = "A and B collide"
kind = "direct"
given = { m_A = "m_A", m_B = "m_B", e = "e", v_A1 = "v_A", v_B1 = "-v_B" }
results = { v_A2 = "u_A", v_B2 = "u_B" }

[[stage]]
type = "impact"
title = "B strikes the wall"
kind = "direct"
given = { m_A = "m_B", e = "e_wall", v_A1 = "u_B" }
A = { label = "B" }
B = { fixed = true, name = "wall" }
results = { v_A2 = "w_B" }
"""


@pytest.fixture(scope="module")
def chain(tmp_path_factory: pytest.TempPathFactory) -> str:
    path = Path(tmp_path_factory.mktemp("chain")) / "two-impacts.toml"
    path.write_text(CHAIN)
    return str(path)


def test_a_given_s_name_solved_for_is_the_velocity_after(chain: str) -> None:
    # vA, vB solved for after the momentum line: the velocities after, not the given speeds 4 and 2
    work = (
        "Take right as +ve. A: 2 kg at 4 m/s right, B: 1 kg at 2 m/s left\n"
        "CLM: 2x4 + 1x2 = 2vA + vB\n"
        "10 = 2vA + vB\n"
        "NEL: vB - vA = 0.5(4+2) = 3\n"
        "3vA + 3 = 10, vA = 2.33\n"
        "vB = 5.33\n"
    )
    found = worst_lines(chain, work)
    assert found[2] == ("wrong", "b_sign")
    assert [found[n][0] for n in (3, 5, 6)] == ["carried"] * 3
    assert found[4][0] == "correct"


def test_the_same_names_worked_rightly_are_correct(chain: str) -> None:
    work = "CLM: 2x4 - 1x2 = 2vA + vB\n6 = 2vA + vB\nNEL: vB - vA = 0.5(4+2) = 3\n3vA + 3 = 6\nvA = 1, vB = 4\n"
    found = worst_lines(chain, work)
    assert [found[n][0] for n in range(1, 6)] == ["correct"] * 5


def test_the_habit_s_names_of_before_and_after_name_the_impact_of_the_two_bodies(chain: str) -> None:
    # v_{B1} is B's velocity before the first impact (-2), not the given speed v_B (2)
    work = (
        "$$m_A v_{A1} + m_B v_{B1} = m_A v_{A2} + m_B v_{B2}$$\n"
        "$$2(4) + 1(2) = 2v_{A2} + v_{B2}$$\n"
        "$$v_{B2} - v_{A2} = 0.5(4 - (-2)) = 3$$\n"
        "$$3v_{A2} + 3 = 10$$\n"
        "$$v_{A2} = 2.33$$\n"
    )
    found = worst_lines(chain, work)
    assert found[1][0] == "correct"
    assert found[2] == ("wrong", "b_sign")
    assert found[3][0] == "correct"
    assert [found[n][0] for n in (4, 5)] == ["carried"] * 2


@pytest.mark.parametrize(
    "line",
    ["w_B = 0.75 x 4 = 3 m/s to the left", "w_B = 3 m/s ←", "$w_B = 3$ m/s $\\leftarrow$", "w_B = 3 m/s (backwards)"],
)
def test_a_way_in_words_signs_a_chain_s_value(chain: str, line: str) -> None:
    # B comes back off the wall at 0.75(4) = 3 m/s, to the left: w_B = -3 along A -> B
    found = worst_lines(chain, f"u_B = 4 m/s to the right\n{line}\n")
    assert [found[n][0] for n in (1, 2)] == ["correct", "correct"]


def test_a_way_in_words_that_is_wrong_is_not_taken_as_a_size(chain: str) -> None:
    found = worst_lines(chain, "u_B = 4 m/s to the right\nw_B = 3 m/s to the right\n")
    assert found[1][0] == "correct"
    assert found[2][0] == "wrong"
