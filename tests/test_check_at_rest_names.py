"""A body at rest before an oblique impact, its velocity named without a component (``v_{Bi} = 0``,
``vB0 = 0``, the statement's letter ``v_{P1} = 0``): whichever way it is read (the vector, the speed,
either component) it is zero, so the name is the given speed 0. Before, a name with no component
in an oblique impact was left to habits and inference, which have nothing to place a zero by:
the line was not read (the corpus's xd07: "Before: v_{Q1n} = u cos α, v_{Q1t} = u sin α, v_{P1} = 0"),
or, set to another number, was placed as whatever component holds that number.

Worked by hand (notes-4c12-cue-ball: the object ball B is stationary; A at v_A1, 45° to the plane
of contact, e = 0.9, equal masses m): B's velocity before is 0 in every reading, so v_{Bi} = 0 is
right and v_{Bi} = v_A1 cos 45° (A's component along the plane, not B's) is wrong; along the line
of impact m v_A1 sin 45° + m(0) = m v_A2n + m v_B2n holds.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

CUE = "notes-4c12-cue-ball"


@pytest.mark.parametrize("name", ["v_{Bi}", "vB0", "v_{B0}", "vBi"])
def test_a_body_at_rest_named_without_a_component_is_zero(name: str) -> None:
    assert statuses(CUE, f"${name} = 0$") == ["correct"]


@pytest.mark.parametrize("name", ["v_{Bi}", "vB0"])
def test_a_body_at_rest_given_a_speed_is_wrong(name: str) -> None:
    assert statuses(CUE, f"${name} = v_{{A1}} \\cos 45^\\circ$") == ["wrong"]


def test_the_zero_in_a_momentum_line_that_holds() -> None:
    work = "$v_{Bi} = 0$\n$m v_{A1} \\sin 45^\\circ + m v_{Bi} = m v_{A2n} + m v_{B2n}$"
    assert statuses(CUE, work) == ["correct", "correct"]
