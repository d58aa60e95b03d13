"""A ball on a wall or cushion: the speed after named in words with no body ("let V be the speed
after the impact", "let the speed after the impact with the wall be w", "w is its speed after the
bounce"), and its components before named by their axis in full ("parallel = …, perpendicular =
…"): parallel to the wall is derive's t, perpendicular to it n.

Values worked by hand: Pre-U 9795/2 2013 Q12(i) (speed u at theta to the wall, tan theta = 3, so
cos theta = 1/sqrt10, sin theta = 3/sqrt10; it rebounds at right angles to its path). Along the wall
u cos theta is kept; into it u sin theta, out of it e u sin theta after. At right angles:
u^2 cos^2 theta - e u^2 sin^2 theta = 0, e = 1/9; the speed after w^2 = u^2/10 + (1/81)(9u^2/10) =
u^2/9, w = u/3.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

PROBLEM = "pre-u-9795-2-2013-june-q12i-wall-rebound-at-right-angles"


@pytest.mark.parametrize(
    "said",
    [
        "Let the speed after the impact with the wall be w.",
        "Let w be the speed after the impact.",
        "w is its speed after the bounce.",
        "Let the speed after be $w$.",
    ],
)
def test_the_speed_after_named_in_words_with_no_body(said: str) -> None:
    found = worst_lines(PROBLEM, f"{said}\nw = u/3\n")
    assert found[2][0] == "correct"
    assert worst_lines(PROBLEM, f"{said}\nw = u/2\n")[2][0] == "wrong"


def test_components_named_parallel_and_perpendicular_in_full() -> None:
    work = "Before:  parallel = u cos(theta),  perpendicular = u sin(theta)\n"
    assert worst_lines(PROBLEM, work)[1][0] == "correct"
    found = worst_lines(
        PROBLEM, work.replace("u cos(theta),", "u sin(theta),").replace("= u sin(theta)\n", "= u cos(theta)\n")
    )
    assert found[1] == ("wrong", "sin_cos_swapped")
