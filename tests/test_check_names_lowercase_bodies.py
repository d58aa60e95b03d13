"""A velocity with the body's letter in lower case (issue #31): ``vb``, ``va``, ``v_b``, ``ua`` are
v_B, v_A, …, as students type them on a phone (``2(vb - 2) = 3.1``); derive read ``vb`` as a word.

Worked by hand (byjus-4kg-ball-catches-8kg-ball): 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5.
Momentum 4(12) + 8(4) = 80 = 4 v_A + 8 v_B; restitution v_B - v_A = 0.5(12 - 4) = 4; so
80 = 4 v_A + 8(v_A + 4), 12 v_A = 48, v_A = 4, v_B = 8. Wrong: v_B = 6; v_A - v_B = 4 (reversed).
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

from derive.checking.naming import rewrite

CATCH = "byjus-4kg-ball-catches-8kg-ball"
WORK = "4(12) + 8(4) = 4va + 8vb\nvb - va = 0.5(12 - 4) = 4\n80 = 4va + 8(va + 4)\nva = 4\nvb = 8"


@pytest.mark.parametrize(("text", "expected"), [("vb-2", "v_B-2"), ("v_a", "v_A"), ("ua + ub", "u_A + u_B")])
def test_a_lowercase_body_letter_after_a_velocity_letter_is_the_body(text: str, expected: str) -> None:
    assert rewrite(text, set()) == expected


def test_lowercase_body_names_are_read_and_checked() -> None:
    assert statuses(CATCH, WORK) == ["correct"] * 5
    assert (
        statuses(CATCH, "4(12) + 8(4) = 4 v_a + 8 v_b\nv_b - v_a = 0.5(12 - 4) = 4\nv_a = 4, v_b = 8")
        == ["correct"] * 3
    )


def test_a_wrong_value_or_a_reversed_restitution_in_lowercase_names_is_wrong() -> None:
    assert statuses(CATCH, WORK.replace("vb = 8", "vb = 6"))[-1] == "wrong"
    assert statuses(CATCH, "4(12) + 8(4) = 4va + 8vb\nva - vb = 0.5(12 - 4) = 4") == ["correct", "wrong"]
