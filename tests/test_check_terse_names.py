"""Names declared tersely by a body's letter and a time, ``p = A after, q = B after (along
l.o.c.)``: each is that body's velocity after (before), along the line of centres in an oblique
impact where the line says so, across it where it says that, and nothing where it says neither.

Pre-U specimen (equal balls, A at u at 30° to the line of centres, B at rest): along the line A
has u cos 30° = (√3/2)u; with sin and cos swapped, u sin 30° = u/2, and then p + q = u/2,
q - p = eu/2 are carried (read as the components across the line they would hold: A keeps u/2).
"""

from __future__ import annotations

import pytest
from support.checked import lines, solution

from derive.checking.context import Context
from derive.checking.naming import declarations

OBLIQUE = "pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg"
DIRECT = "byjus-4kg-ball-catches-8kg-ball"


@pytest.mark.parametrize(
    ("problem", "text", "expected"),
    [
        (OBLIQUE, "p = A after, q = B after (along l.o.c.)", {"p": "v_A2n", "q": "v_B2n"}),
        (OBLIQUE, "p = A after, q = B after, along the line of centres", {"p": "v_A2n", "q": "v_B2n"}),
        (OBLIQUE, "p = A after, q = B after (perpendicular to the line of centres)", {"p": "v_A2t", "q": "v_B2t"}),
        (OBLIQUE, "p = A after, q = B after", {}),  # which component: not said
        (DIRECT, "x = A after, y = B after", {"x": "v_A2", "y": "v_B2"}),
    ],
)
def test_a_name_set_to_a_body_and_a_time_is_declared(problem: str, text: str, expected: dict) -> None:
    names, _sign = declarations(text, Context(solution(problem), None))
    assert {k: str(v) for k, v in names.items() if k in "pqxy"} == expected, names


def test_the_lines_after_a_slip_are_carried_with_the_terse_names() -> None:
    work = "along l.o.c. A has u sin 30 = u/2\np = A after, q = B after (along l.o.c.)\n"
    work += "m(u/2) = mp + mq  ->  p + q = u/2\nq - p = e(u/2)\nq = u(1 + e)/4"
    found = lines(OBLIQUE, work)
    assert found[1][0] == "wrong", found
    assert [found[n][0] for n in (3, 4, 5)] == ["carried"] * 3, found
