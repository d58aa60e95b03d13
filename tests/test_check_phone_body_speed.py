"""A body's speed typed without the possessive, as on a phone: a side that is just ``B speed``
(or ``A speed after``, ``B final speed``) is B's speed after the impact, as ``B's speed`` is.

Example 4.C.11 by hand (docs/checking.md: v_A2n = -1.109, v_B2n = 8.398): the t components
are unchanged, A 5 sin 37.6° = 3.051 and B -15 sin 37.6° = -9.154, so A's speed after is
√(1.109² + 3.051²) = 3.246 and B's √(8.398² + 9.154²) = 12.42."""

from __future__ import annotations

import pytest
from support.checked import worst_lines

PROBLEM = "notes-4c11-two-spheres"


@pytest.mark.parametrize(
    "line",
    ["B speed = √(8.398² + 9.154²) = 12.42", "A speed after = √(1.109² + 3.051²) = 3.246", "B final speed = 12.4"],
)
def test_a_speed_named_by_the_body_alone_is_judged(line: str) -> None:
    assert worst_lines(PROBLEM, line + "\n")[1][0] == "correct"


def test_a_wrong_speed_named_by_the_body_alone_is_wrong() -> None:
    assert worst_lines(PROBLEM, "B speed = √(8.398² + 15²) = 17.19\n")[1][0] == "wrong"
