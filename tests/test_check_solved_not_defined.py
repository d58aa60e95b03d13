"""A relation that only simplifies to a name alone is an equation the student solves, not the
name's definition (derive/checking/ownnames.py, ``lone_name``); and a name placed by its value
takes the reading that holds to the figures written before one that holds only loosely
(derive/checking/byvalue.py, ``TIGHT``).

The problem (OCR MEI FMM 2024): disc A (3 kg) is stopped by B (5 kg), whose 2 m/s is at 60° to the
line of centres XY, e = 0.8. Along XY B's component before is 2 cos 60° = 1, across 2 sin 60° =
1.732. With V for A's speed before and b for B's component along XY after:
3V + 5 = 5b and b - 0 = 0.8(V - 1), so 5b = 4V - 4, V = 9 and b = 6.4 (B's speed 6.63).
Each expected mark is worked by hand from these givens."""

from __future__ import annotations

from support.checked import worst_lines

PROBLEM = "ocr-mei-fmm-2024-disc-a-stops"


def test_restitution_written_as_a_difference_with_zero_is_judged_not_taken_as_defining_the_name() -> None:
    # The student takes B's component before the wrong way in the law of restitution only:
    # b - 0 = 0.8(V + 1), then 5b = 4V + 4, 3V + 5 = 4V + 4, V = 1: the slip is the restitution
    # line (before, b was "defined" by it and the line marked correct).
    work = """Let A's speed before the impact be V.
along XY: B before 2cos60 = 1, across 2sin60 = 1.732
3V + 5(1) = 3(0) + 5b
b - 0 = 0.8(V + 1)
5b = 4V + 4
3V + 5 = 4V + 4
V = 1
"""
    got = worst_lines(PROBLEM, work)
    assert [got[n][0] for n in (2, 3)] == ["correct"] * 2
    assert got[4][0] == "wrong"
    assert [got[n][0] for n in (5, 6, 7)] == ["carried"] * 3


def test_components_swapped_then_the_name_is_read_as_the_component_that_holds_to_the_figures() -> None:
    # sin and cos swapped: along XY 2 sin 60° = 1.732, across 1. Then 3V + 8.66 = 5k,
    # k = 0.8(V - 1.732): 3V + 8.66 = 4V - 6.93, V = 15.59, k = 0.8(13.86) = 11.09. k is B's
    # component after (5k = 55.43 = 3(15.59) + 8.66 to the figures); B's speed after in that world,
    # sqrt(11.09² + 1) = 11.13, holds only to 0.4 %: k is the component, and the lines are carried.
    work = """let V be A's speed before
B's components before: along XY 2 sin 60 = 1.732, across 2 cos 60 = 1
momentum along XY: 3V + 8.66 = 5k
restitution: k - 0 = 0.8 (V - 1.732)
5k = 4V - 6.93
3V + 8.66 = 4V - 6.93
V = 15.59
"""
    got = worst_lines(PROBLEM, work)
    assert got[2] == ("wrong", "sin_cos_swapped")
    assert [got[n][0] for n in (3, 4, 5, 6, 7)] == ["carried"] * 5
