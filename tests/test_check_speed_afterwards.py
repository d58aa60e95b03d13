"""The one moving body's speed after an impact with a fixed body named beside "afterwards" (or
"afterward"), not "after": "afterwards speed V", "afterwards its speed is v", "speed w afterwards".
The word "after" alone was read (:mod:`derive.checking.speedwords`); "afterwards" was not, so the
name was left to inference, which cannot place it where the line naming it is wrong (the corpus's
yd12: "Before hitting DC the ball has speed U …; afterwards speed V …", then V cos β = e₁ U cos α)
and places it as the n component where a line reads as one.

Worked by hand.
pre-u-9795-2-2013-june-q12i (tan θ = 3, speed u along a path at θ to the wall): along the wall
u cos θ is kept, out of it e u sin θ, so the speed after w has w² = u² cos² θ + e² u² sin² θ;
with e not squared (w² = u² cos² θ + e u² sin² θ) the line is false.
edexcel-m4-2018-june-q2 (speed U before, 60% of the kinetic energy kept): ½ m V² = (3/5) ½ m U²,
V² = 3U²/5; V² = 3U²/4 (e put on the energy) is false.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

WALL = "pre-u-9795-2-2013-june-q12i-wall-rebound-at-right-angles"
KEEPS = "edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke"


@pytest.mark.parametrize(
    ("said", "name"),
    [
        ("Afterwards its speed is v.", "v"),
        ("It hits the wall with speed u; afterwards speed w at some angle to the wall.", "w"),
        ("The sphere bounces off, with speed s afterward.", "s"),
    ],
)
def test_a_speed_named_afterwards_is_the_speed_after(said: str, name: str) -> None:
    right = f"{said}\n{name}^2 = u^2 cos^2(theta) + e^2 u^2 sin^2(theta)"
    wrong = f"{said}\n{name}^2 = u^2 cos^2(theta) + e u^2 sin^2(theta)"
    assert statuses(WALL, right) == ["correct"]
    assert statuses(WALL, wrong) == ["wrong"]


@pytest.mark.parametrize(
    "said",
    ["Before the impact the ball has speed U; afterwards speed V.", "Afterwards, speed V (at a new angle)."],
)
def test_a_speed_named_afterwards_in_an_energy_line(said: str) -> None:
    assert statuses(KEEPS, f"{said}\nV^2 = 3/5 U^2") == ["correct"]
