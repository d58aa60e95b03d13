"""A sign said in words on the line that places the unit vectors ("j the normal out of the wall
(positive away from the wall)") is the unit vector's way, which the reader has already turned
into derive's frame; it is not a second convention to turn the components by again.

Values worked by hand from giancoli-7-18-tennis-ball-wall-45deg's givens: 28 m/s at 45° to the
normal, e = 1: along the wall 28 sin 45° = 19.80 before and after; out of the wall -19.80 before
and +19.80 after. With j out of the wall: u = 19.8 i - 19.8 j, v = 19.8 i + 19.8 j.
pre-u-9795-2-2013-june-q12i: speed u at θ to the wall; with ĵ out of the wall, u = u cos θ î - u sin θ ĵ
and, the normal part reversed and times e, v = u cos θ î + e u sin θ ĵ.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

WALL = "giancoli-7-18-tennis-ball-wall-45deg"
PREU = "pre-u-9795-2-2013-june-q12i-wall-rebound-at-right-angles"


@pytest.mark.parametrize(
    "axes",
    [
        "i along the wall, j the normal pointing out of the wall (positive away from the wall).",
        "Unit vectors: i along the wall; j normal to the wall pointing away from it, so away from the wall is positive.",
    ],
)
def test_positive_said_with_the_unit_vectors_is_not_applied_twice(axes: str) -> None:
    work = f"{axes}\nu = 19.8 i - 19.8 j\nv = 19.8 i + 19.8 j\n"
    assert statuses(WALL, work)[-2:] == ["correct", "correct"]


def test_symbolic_velocities_with_the_axes_and_their_sign_in_words() -> None:
    work = (
        r"Take $\hat{\imath}$ along the wall and $\hat{\jmath}$ normal to it, out of the wall (positive away from it)."
        "\n"
        r"$\vec u = u\cos\theta\,\hat\imath - u\sin\theta\,\hat\jmath$"
        "\n"
        r"$\vec v = u\cos\theta\,\hat\imath + e u\sin\theta\,\hat\jmath$"
    )
    assert "wrong" not in statuses(PREU, work)
