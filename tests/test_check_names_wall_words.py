"""A ball's components at a wall named by their axis alone (issue #31): ``par = u cos θ``,
``perp = u sin θ`` (parallel to the wall: derive's t; perpendicular, or normal, to it: n), before
the impact, or after where primed (``perp' = e u sin θ``). The words in full stay prose ("the angle
with the normal = 90 - 1.27" is no component).

Worked by hand (pre-u-9795-2-2013-june-q12i-wall-rebound-at-right-angles): the path makes θ with
the wall, tan θ = 3, speed u; along the wall u cos θ (kept), into it u sin θ before and e u sin θ
out of it after; e = 1/9 (the mark scheme). Wrong: par = u sin θ (sine for cosine).
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

WALL = "pre-u-9795-2-2013-june-q12i-wall-rebound-at-right-angles"


@pytest.mark.parametrize(
    "work",
    [
        "par = u cos(theta)\nperp = u sin(theta)",
        "para = u cos(theta)\nperp = u sin(theta)",
        "par = u cos(theta)\nnorm = u sin(theta)\npar' = u cos(theta)",
        "par = u cos(theta)\nperp = u sin(theta)\nperp' = e u sin(theta)",  # a size, out of the wall
    ],
)
def test_components_named_by_their_axis_at_a_wall_are_read(work: str) -> None:
    assert set(statuses(WALL, work)) == {"correct"}


def test_a_component_named_by_its_axis_with_sine_for_cosine_is_wrong() -> None:
    assert statuses(WALL, "par = u sin(theta)\nperp = u sin(theta)")[0] == "wrong"


@pytest.mark.parametrize("after", ["perp' = u sin(theta)/e", "par' = e u cos(theta)"])
def test_a_component_after_named_by_its_axis_worked_wrongly_is_wrong(after: str) -> None:
    assert statuses(WALL, f"par = u cos(theta)\nperp = u sin(theta)\n{after}")[-1] == "wrong"
