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
P_Q = "edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u"


@pytest.mark.parametrize(
    ("problem", "text", "expected"),
    [
        (OBLIQUE, "p = A after, q = B after (along l.o.c.)", {"p": "v_A2n", "q": "v_B2n"}),
        (OBLIQUE, "p = A after, q = B after, along the line of centres", {"p": "v_A2n", "q": "v_B2n"}),
        (OBLIQUE, "p = A after, q = B after (perpendicular to the line of centres)", {"p": "v_A2t", "q": "v_B2t"}),
        (OBLIQUE, "p = A after, q = B after", {}),  # which component: not said
        (DIRECT, "x = A after, y = B after", {"x": "v_A2", "y": "v_B2"}),
        (DIRECT, "A after=x B after=y", {"x": "v_A2", "y": "v_B2"}),  # the other way round, phone-typed
        (OBLIQUE, "along loc: A after = p, B after = q", {"p": "v_A2n", "q": "v_B2n"}),
        (P_Q, "P hits Q, P->Q +ve, P after=x Q after=y", {"x": "v_A2", "y": "v_B2"}),  # the statement's letters
        (P_Q, "P after = x + y", {}),  # a relation, not a name
        (P_Q, "vel after: P=x Q=y", {"x": "v_A2", "y": "v_B2"}),  # the time in a label, the bodies set to names
        (DIRECT, "Before impact: A = p, B = q", {"p": "v_A1", "q": "v_B1"}),
        (DIRECT, "after: A = 2, B = 3", {}),  # numbers, not names
        (P_Q, "Speed of Q after = u", {}),  # an answer: u is given
        (P_Q, "After: Q = eu", {}),  # a claim, e times u: not a name
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


def test_a_line_of_names_the_other_way_round_is_not_judged() -> None:
    """Edexcel M2 2010 Q2 by hand: 2m(2u) - mu = 2mx + my and y - x = 3eu give x = u(1 - e),
    y = u(1 + 2e); the declaration line itself is not a relation to mark."""
    work = "P hits Q, P->Q +ve, P after=x Q after=y\nclm: 2m(2u) - mu = 2mx + my\nnel: y - x = 3eu\n"
    work += "x = u(1-e)\ny = u + 2eu\n"
    found = lines(P_Q, work)
    assert 1 not in found, found
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["correct"] * 4, found


def test_names_set_to_bodies_under_a_label_of_time_make_a_slip_found() -> None:
    """Edexcel M2 2010 Q2: restitution is y - x = e(2u + u) = 3eu; written e(2u - u) = eu it has Q's
    velocity before with its sign lost, and the lines solved from it are carried (names unplaced, they
    were taken as definitions and every line passed)."""
    work = "P 2m at 2u ->, Q m at u <-\nvel after: P=x Q=y\nclm: 4mu - mu = 2mx + my\nnel: y - x = e(2u - u) = eu\n"
    work += "3x = 3u - eu\nx = u - eu/3\n"
    found = lines(P_Q, work)
    assert found[3][0] == "correct" and found[4][0] == "wrong", found
    assert [found[n][0] for n in (5, 6)] == ["carried"] * 2, found
