"""Bodies told apart in the statement by a word before one noun ("a white ball of mass … hits a
black ball at rest", "a blue puck … a red puck"), and a student's names by those words with the
habit's letters: ``u_white`` before, ``v_white`` and ``v_black`` after.

Values worked by hand for the problem below (white 0.2 kg at 5 m/s, black 0.3 kg at rest, e = 0.5):
momentum 0.2(5) = 1 = 0.2 v_white + 0.3 v_black; restitution v_black - v_white = 0.5(5) = 2.5, so
0.2 v_white + 0.3(v_white + 2.5) = 1, 0.5 v_white = 0.25, v_white = 0.5 and v_black = 3.0 (m/s).
"""

from __future__ import annotations

import pytest
from support.checked import solved_text, statuses_of

import derive
from derive.checking.statementbodies import told_apart

PROBLEM = '''title = "White ball hits a black ball at rest"
kind = "direct"
source = "a test of the checker's names"
statement = """A white ball of mass {m_A} rolls at {v_A1} and hits head-on a black ball of \
mass {m_B} at rest. The coefficient of restitution is 0.5."""
question = "Find the velocity of each ball after the impact."

[given]
m_A = "0.2 kg"
m_B = "0.3 kg"
e = 0.5
v_A1 = "5 m/s"
v_B1 = 0
'''


@pytest.fixture(scope="module")
def solution(tmp_path_factory: pytest.TempPathFactory) -> derive.Solution:
    return solved_text(tmp_path_factory.mktemp("bodywords"), "white-black.toml", PROBLEM)


def test_the_words_that_tell_the_bodies_apart() -> None:
    assert told_apart("A blue puck of mass {m_A} slides at {v_A1} and hits a red puck at rest.") == {
        "blue": "A",
        "red": "B",
    }
    assert told_apart("A smooth sphere of mass {m_A} hits a smooth sphere at rest.") == {}
    assert told_apart("A white ball hits a black ball of mass {m_B}.") == {"white": "A", "black": "B"}
    assert told_apart("A white ball hits a black ball.") == {}  # which is A not said


def test_names_by_the_bodies_words_are_read(solution: derive.Solution) -> None:
    work = "0.2 u_white = 0.2 v_white + 0.3 v_black\nv_black - v_white = 0.5(5)\nv_white = 0.5\nv_black = 3.0\n"
    assert statuses_of(solution, work) == dict.fromkeys((1, 2, 3, 4), "correct")


def test_a_wrong_value_by_a_bodys_word_is_wrong(solution: derive.Solution) -> None:
    statuses = statuses_of(solution, "v_black - v_white = 0.5(5)\nv_black = 2.5\n")
    assert statuses[1] == "correct"
    assert statuses[2] == "wrong"
