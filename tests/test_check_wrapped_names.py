"""Names declared in a sentence of words wrapped over two lines ("let p and q be the velocities of
A and B along the" / "line of centres after the collision") are read from the whole sentence:
the lines after are judged with p and q along the line of centres, not matched to whatever
components make a later line hold.

The problem (Pre-U specimen: equal balls, A at u at 30° to the line of centres, B at rest):
along the line of centres A has u cos 30° = (√3/2)u and across it u sin 30° = u/2, which it
keeps. Resolved with sin and cos swapped, u sin 30° = u/2 along the line: then p + q = u/2 and
q - p = eu/2 (q = u(1 + e)/4) are carried. Read as the components across the line, p + q = u/2
would hold (A keeps u/2, B has none): a teacher never reads it so.
"""

from __future__ import annotations

import pytest
import sympy
from support.checked import lines, solution

from derive.checking.context import Context
from derive.checking.naming import declarations

PROBLEM = "pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg"
DECLARED = "We let p and q be the velocities of A and B along the\nline of centres after the collision.\n"


@pytest.mark.parametrize("declared", [DECLARED, DECLARED.replace("along the\nline", "along\nthe line")])
def test_names_declared_over_two_lines_are_read(declared: str) -> None:
    work = declared + "along the line of centres: u sin 30 = u/2\nCLM: p + q = u/2\nNEL: q - p = eu/2\nq = u(1 + e)/4"
    found = lines(PROBLEM, work)
    assert found[3][0] == "wrong", found
    assert [found[n][0] for n in (4, 5, 6)] == ["carried"] * 3, found


def test_the_same_names_read_right_where_the_working_is_right() -> None:
    work = DECLARED + "CLM: p + q = (sqrt3/2)u\nNEL: q - p = (sqrt3/2)eu\nq = sqrt3 u(1 + e)/4"
    found = lines(PROBLEM, work)
    assert [found[n][0] for n in (3, 4, 5)] == ["correct"] * 3, found


@pytest.mark.parametrize(
    "text",
    [
        DECLARED,
        "Let the speed of A before be $u$, and let $p$ and $q$ be the velocities of $A$ and $B$ along the\n"
        "line of centres after the impact. The component of A's velocity along it is\n",
        "p and q are the velocities of A and B,\nalong the line of centres, after the collision\n",
    ],
)
def test_a_declaration_wrapped_over_two_lines_declares_its_names(text: str) -> None:
    names, _sign = declarations(text, Context(solution(PROBLEM), None))
    assert {k: str(v) for k, v in names.items() if k in "pq"} == {"p": "v_A2n", "q": "v_B2n"}, names


def test_a_line_that_goes_on_with_a_relation_is_not_joined() -> None:
    text = "We let p and q be the velocities of A and B along the\nline: p + q = u/2\n"
    names, _sign = declarations(text, Context(solution(PROBLEM), None))
    assert not {k for k in names if k in "pq"}, names
    assert sympy.Symbol("p") not in names
