"""A speed named by the path the statement says the body takes after the impact, by its two
points: the statement "It bounces off BC and moves along YZ" makes "Let the speed along YZ be
W" the speed after (as "let W be the speed after" is); "along XY", the path before, is not it.

By hand: a puck at 4 m/s, 30° to a smooth barrier, e = 0.5: along the barrier 4 cos 30° = 3.464
(12 squared), across it 4 sin 30° = 2, after 0.5 × 2 = 1: W² = 12 + 1 = 13, W = 3.606."""

from __future__ import annotations

from support.checked import text_lines

PUCK = """title = "A puck bounces off a barrier"
kind = "oblique"
statement = "A puck slides at 4 m/s along XY to a smooth barrier BC, at 30 degrees to it. It bounces off BC and moves along YZ; e = 0.5."
question = "Find its speed after the impact."

[given]
m_A = "0.2 kg"
e = 0.5
v_A1 = "4 m/s"
alpha = "30 deg"

[A]
angle = "alpha"
from = "+t"
toward = "+n"

[B]
fixed = true
name = "barrier"
"""


def test_the_speed_along_the_path_after_is_judged(tmp_path) -> None:
    assert text_lines(tmp_path, PUCK, "Let the speed along YZ be $W$.\n$W^2 = 3.464^2 + 1^2 = 13$\n") == ["correct"]
    assert text_lines(tmp_path, PUCK, "W = speed along YZ\nW^2 = 3.464^2 + 2^2 = 16\n")[-1] == "wrong"


def test_the_path_before_is_not_the_speed_after(tmp_path) -> None:
    assert text_lines(tmp_path, PUCK, "Let the speed along XY be W.\nW = 3.606\n")[-1] != "correct"
