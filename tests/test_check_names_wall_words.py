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


# OCR M2 June 2012 Q1: 0.8 kg at 4 m/s straight at a wall, e = 0.3: it rebounds at 0.3(4) = 1.2 m/s
# away from the wall. "towards the wall" after the rebound's number says the way it does not go.
PARTICLE = "ocr-m2-2012-particle-hits-wall"


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("v_1 = 4 m/s (towards the wall)\nv_2 = 1.2 m/s (away from the wall)", ["correct", "correct"]),
        ("v_2 = 1.2 m/s (towards the wall)", ["wrong"]),
        ("v_2 = 1.2 m/s towards the wall", ["wrong"]),
        ("v_2 = 0.3(4) = 1.2 (towards the wall)", ["wrong"]),
    ],
)
def test_a_rebound_said_to_go_towards_the_wall_is_wrong(work: str, expected: list) -> None:
    assert statuses(PARTICLE, work) == expected
