"""An angle declared in words for a velocity before the impact ("let a be the angle between A's
velocity and the line of centres") is that angle: a line that works it out must give its value, and a
cosine taken for the sine there is the angle from the other axis (``angle_other_axis``), the
components worked from it that mistake carried. Worked by hand from the file's givens below."""

from __future__ import annotations

from pathlib import Path

import pytest
from support.checked import worst_lines

#: Discs of radius 0.1 m; A at 5 m/s, its path 0.12 m from B's centre (B at rest), e = 0.5.
#: sin a = 0.12/0.2 = 0.6: a = 36.87°; along the line of centres 5 cos a = 4, across 3.
#: v_A + v_B = 4, v_B - v_A = 0.5(4) = 2 -> v_B = 3, v_A = 1.
#: Taken from the other axis (cos a = 0.6, a = 53.13°): 5 cos 53.13° = 3, v_A + v_B = 3,
#: v_B - v_A = 1.5 -> v_B = 2.25.
OFFSET = """
title = "Equal discs, A's path 0.12 m from B's centre"
kind = "oblique"
statement = "Two equal smooth discs of radius 0.1 m; A moves at 5 m/s toward B at rest, its path 0.12 m from B's centre; e = 0.5."
question = "Find the velocities after the impact."
find = ["v_B2", "v_A2"]

[given]
m_A = "2 kg"
m_B = "2 kg"
r_A = "0.1 m"
r_B = "0.1 m"
e = 0.5
v_A1 = "5 m/s"
v_B1 = 0

[geometry]
offset = "0.12 m"

[A]
angle = "0 deg"
from = "+x"
toward = "+y"
"""


@pytest.fixture(scope="module")
def problem(tmp_path_factory: pytest.TempPathFactory) -> str:
    path = Path(tmp_path_factory.mktemp("offset")) / "offset.toml"
    path.write_text(OFFSET)
    return str(path)


def test_a_declared_angle_worked_from_the_other_axis_is_the_slip(problem: str) -> None:
    work = (
        "let a be the angle between A's velocity and the line of centres\n"
        "cos a = 0.12/0.2 = 0.6, a = 53.13°\n"
        "along loc: 5 cos 53.13° = 3\n"
        "v_A + v_B = 3\n"
        "v_B - v_A = 0.5 x 3 = 1.5\n"
        "v_B = 2.25\n"
    )
    found = worst_lines(problem, work)
    assert found[2][0] == "wrong" and "angle_other_axis" in found[2][1].split(",")
    assert [found[n][0] for n in (3, 4, 5, 6)] == ["carried"] * 4


def test_the_declared_angle_worked_rightly_is_correct(problem: str) -> None:
    work = (
        "Let $\\theta$ be the angle between A's velocity and the line of centres.\n"
        "$$\\sin\\theta = \\frac{0.12}{0.2} = 0.6 \\Rightarrow \\theta = 36.87^\\circ$$\n"
        "$$v_A + v_B = 5\\cos 36.87^\\circ = 4$$\n"
        "$$v_B - v_A = 0.5(4) = 2$$\n"
        "$$v_B = 3$$\n"
    )
    found = worst_lines(problem, work)
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["correct"] * 4
