"""A chain's name declared by how a body moves after an impact, in words: "let A move at p
afterwards", "B moves off with velocity q after the collision", "B rebounds with speed w after
hitting the wall". The name is that body's velocity after the impact the line is about (its
size where the words say speed), as "let p be A's velocity after" is.

AQA M3 June 2007 Q4 (chain-aqa-m3-2007-collide-again), by hand: A 0.3 kg at 3 m/s, B 0.2 kg at
2 m/s toward it, e = 0.8: 0.3(3) + 0.2(-2) = 0.5 = 0.3p + 0.2q and q - p = 0.8(5) = 4, so
0.5p = 0.5 - 0.8, p = -0.6 and q = 3.4; B then rebounds from the wall (e = 0.7) at 0.7(3.4) = 2.38.
Three equal particles (chain-edexcel-m2-three-particles): A at 7 m/s strikes B, B strikes C,
C moves off at 4 m/s; B's velocity after the second impact is b - 4 where b(1 + e) = 8."""

from __future__ import annotations

import pytest
from support.checked import worst_lines

PROBLEM = "chain-aqa-m3-2007-collide-again"


@pytest.mark.parametrize(
    "said",
    [
        "Let A move at p afterwards, and B moves off with velocity q after the collision.",
        "A then moves at p after the impact; B moves with velocity q just after.",
    ],
)
def test_velocities_declared_by_how_the_bodies_move(said: str) -> None:
    work = f"{said}\n0.3(3) + 0.2(-2) = 0.3p + 0.2q\nq - p = 0.8(3 + 2) = 4\np = -0.6\nq = 3.4\n"
    found = worst_lines(PROBLEM, work)
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["correct"] * 4, found


def test_a_wrong_value_of_a_name_declared_so_is_wrong() -> None:
    work = "Let A move at p afterwards, and B moves off with velocity q after the collision.\np = 0.6\n"
    assert worst_lines(PROBLEM, work)[2][0] == "wrong"


def test_a_speed_after_the_wall_declared_by_the_rebound() -> None:
    work = "B rebounds with speed w after hitting the wall.\nw = 0.7(3.4) = 2.38\n"
    assert worst_lines(PROBLEM, work)[2][0] == "correct"
    work = "B rebounds with speed w after hitting the wall.\nw = 0.8(3.4) = 2.72\n"
    assert worst_lines(PROBLEM, work)[2][0] == "wrong"


def test_the_second_impact_named_in_a_bold_heading() -> None:
    # B at b after the first impact, C at rest: c + 4 = b and 4 - c = e b (c is B's velocity after)
    work = (
        "\\textbf{First impact.} Let $a$ and $b$ be the velocities of $A$ and $B$ just after: $a + b = 7$.\n"
        "\\textbf{Second impact.} $B$ moves at $b$ and $C$ is at rest; let $B$ move at $c$ afterwards.\n"
        "$c + 4 = b$\n"
        "$c - 4 = eb$\n"
    )
    found = worst_lines("chain-edexcel-m2-three-particles", work)
    assert found[3][0] == "correct" and found[4][0] == "wrong", found
