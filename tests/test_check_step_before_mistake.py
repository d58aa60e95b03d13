"""A line worked from the relation just before it (true) with a number moved across and its
sign kept is ``algebra``, even where its result is also what a common mistake gives: in an
elastic collision with B at rest, ``m_A(u − v) = m_B V`` worked as ``m_B V = m_A u + m_A v``
always gives m_B = m_A, the masses-swapped value. The step explains the line, and the
relation before shows the physics right. Lines after are judged with the student's mass.
Values by hand."""

from __future__ import annotations

import pytest
from support.checked import solved_text

import derive

#: 2 kg at 6 m/s hits a ball at rest, elastic; A goes on at 2 m/s. V - 2 = 6: V = 8.
#: 2(6) = 2(2) + 8 m_B: 8 m_B = 12 - 4 = 8, m_B = 1 kg (check: (2 - 1)/3 x 6 = 2). The 4 moved
#: with its sign kept: 8 m_B = 16, m_B = 2 kg.
PROBLEM = """title = "Elastic: 2 kg at 6 m/s hits a ball at rest, goes on at 2 m/s; find the mass"
kind = "direct"
source = "a test's own problem"
statement = "A ball of mass {m_A} at {v_A1} hits a ball at rest; elastic; A goes on at {v_A2}."
question = "Find B's velocity after and its mass."
find = ["v_B2", "m_B"]

[given]
m_A = "2 kg"
m_B = "? kg"
e = 1
v_A1 = "6 m/s"
v_B1 = 0
v_A2 = "2 m/s"
"""

#: Young & Freedman 8.96: 0.0400 kg at 0.200 m/s, on at 0.050 m/s, elastic: V = 0.250;
#: 0.008 = 0.002 + 0.25 m: 0.25 m = 0.006, m = 0.024 kg. With the 0.002 moved, its sign kept:
#: 0.25 m = 0.010, m = 0.0400 kg. KE before ½(0.04)(0.2²) = 0.0008 J (right either way).
PUCKS = "young-freedman-8-96-pucks-find-mass"


@pytest.fixture(scope="module")
def elastic(tmp_path_factory: pytest.TempPathFactory) -> derive.Solution:
    return solved_text(tmp_path_factory.mktemp("stepslip"), "elastic-find-mass.toml", PROBLEM)


def _lines(solution: derive.Solution, work: str) -> dict[int, tuple[str, str]]:
    report = derive.check(solution, derivation=work)
    return {int(i.name): (i.status, i.slip) for i in report.items if i.kind == "line" and i.name.isdigit()}


def test_a_number_moved_with_its_sign_kept_is_algebra_not_masses_swapped(elastic) -> None:
    work = "V - 2 = 6\nV = 8\n2(6) = 2(2) + 8m_B\n8m_B = 12 + 4\nm_B = 2 kg\n"
    found = _lines(elastic, work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3
    assert found[4] == ("wrong", "algebra")
    assert found[5][0] == "carried"


def test_in_latex_with_the_energy_after(elastic) -> None:
    work = (
        "$v_B - v_A = u_A$ so $v_B = 2 + 6 = 8$\n\n"
        "$m_A u_A = m_A v_A + m_B v_B$: $12 = 4 + 8 m_B$\n\n"
        "$8 m_B = 16$\n\n"
        "$m_B = 2$\n\n"
        "$KE_1 = \\tfrac12 (2)(6)^2 = 36$\n"
    )
    found = _lines(elastic, work)
    assert found[1][0] == found[3][0] == "correct"
    assert found[5] == ("wrong", "algebra")
    assert found[7][0] == "carried"
    assert found[9][0] == "correct"


def test_on_the_pucks_with_other_names() -> None:
    work = "w = 0.200 + 0.050 = 0.250\n0.04 x 0.2 = 0.04 x 0.05 + 0.25 M\n0.25 M = 0.008 + 0.002 = 0.010\nM = 0.04\n"
    solution = derive.solve(derive.load(PUCKS))
    found = _lines(solution, work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3] == ("wrong", "algebra")
    assert found[4][0] == "carried"


#: The pucks again, with
#: the student's wrong mass 0.0400 kg, which is also blue's mass as given. KE before
#: ½(0.0400)(0.200)² = 0.000800 J is right for the problem with the data as stated: correct.
def test_a_line_right_with_the_data_is_correct_though_a_wrong_value_has_the_same_digits() -> None:
    work = (
        "V = 0.200 + 0.050 = 0.250\n0.0400(0.200) = 0.0400(0.050) + 0.250 M\n0.250 M = 0.0080 + 0.0020\n"
        "M = 0.0400 kg\nT_1 = 0.5(0.0400)(0.200)^2 = 0.000800 J\n"
    )
    found = _lines(derive.solve(derive.load(PUCKS)), work)
    assert found[3] == ("wrong", "algebra")
    assert found[4][0] == "carried"
    assert found[5][0] == "correct"
