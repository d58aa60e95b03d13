"""A velocity after declared in words as minus a name ("its velocity after the impact is -v", "the
particle's velocity after the bounce is $-w$") makes the name the size of the velocity that comes
back, in the student's own frame: ``v = e u`` is then right, whatever the habit makes of the letter
v (the velocity itself), and a wrong size is wrong, not a name of the student's own.

OCR M2 2012: 0.8 kg at 4 m/s into a wall, e = 0.3, towards the wall positive. By hand: it comes back
at 0.3 × 4 = 1.2 m/s (velocity after -1.2); KE lost ½(0.8)(16 - 1.44) = 5.824 J.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

WALL = "ocr-m2-2012-particle-hits-wall"


@pytest.mark.parametrize(
    "work",
    [
        "+ve towards wall. after the impact its velocity is -v\nv = 0.3 x 4 = 1.2\n",
        "Towards the wall positive: velocity before 4, velocity after = -v.\nv = 0.3 x 4 = 1.2\n",
        "Taking the direction towards the wall as positive, the particle's velocity after the bounce is $-w$.\n\n"
        "$$w = 0.3 \\times 4 = 1.2$$\n\n$$\\Delta KE = \\tfrac12(0.8)(4^2 - w^2) = 5.824$$\n",
    ],
    ids=["plain-v", "colon-v", "markdown-w"],
)
def test_the_named_size_of_the_velocity_after(work: str) -> None:
    assert all(s == "correct" for s, _ in worst_lines(WALL, work).values())


def test_a_wrong_size_stays_wrong() -> None:
    found = worst_lines(WALL, "+ve towards wall. after the impact its velocity is -w\nw = 4/0.3 = 13.3\n")
    assert found[2][0] == "wrong"
