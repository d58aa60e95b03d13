"""Speeds before declared in words for bodies moving towards each other (``let p, q be the speeds of
A and B before (moving towards each other)``): B's speed is the size of a velocity against
derive's n, so p = 5, q = 5 and 2p − q is the momentum.

Worked by hand (ocr-m2-2006-spheres-meet-at-5-ke-lost): A (2 kg) and B (1 kg) meet head-on at 5 m/s
each, e = 0.8: momentum 2(5) − 1(5) = 5 = 2(−1) + 1(7), A after −1, B after 7.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

from derive.checking.towardwords import toward

SPHERES = "ocr-m2-2006-spheres-meet-at-5-ke-lost"


@pytest.mark.parametrize(
    ("plain", "when", "body", "sign"),
    [
        ("let p, q be the speeds of A and B before (towards each other)", "before", "B", -1),
        ("let p, q be the speeds of A and B before (towards each other)", "before", "A", 1),
        ("let p, q be the speeds of A and B after (towards each other)", "after", "B", 1),
        ("let p, q be the velocities of A and B before, head-on", "before", "B", 1),
        ("let p, q be the speeds of A and B before", "before", "B", 1),
    ],
)
def test_only_b_speed_before_towards_each_other_is_turned_round(plain: str, when: str, body: str, sign: int) -> None:
    assert toward(plain, when, body) == sign


def test_speeds_before_towards_each_other_are_read_as_sizes() -> None:
    said = "Let p and q be the speeds of A and B before (moving towards each other).\n"
    work = "2p - q = 2(-1) + 1(7)\np = 5\nq = 5\n"
    assert statuses(SPHERES, said + work) == ["correct"] * 3
    assert statuses(SPHERES, said + work.replace("q = 5", "q = -5"))[-1] == "wrong"


def test_speeds_before_that_are_asked_are_sizes_towards_each_other() -> None:
    """Edexcel M2 January 2017 Q5: P (2m) and Q (3m) move towards each other and both reverse, P at
    v and Q at 3v/2 after, e = 1/5; the speeds before are asked. By hand: 2m a - 3m b = 2m(-v) +
    3m(3v/2) = 5mv/2 and 3v/2 + v = (a + b)/5, so a + b = 25v/2, b = 9v/2, a = 8v."""
    said = "Let a and b be the speeds of P and Q before (towards each other).\n"
    work = "2a - 3b = -2v + 9v/2\n3v/2 + v = (a + b)/5\nb = 9v/2\na = 8v\n"
    problem = "edexcel-m2-2017-january-q5-both-reverse-find-speeds-before"
    assert statuses(problem, said + work) == ["correct"] * 4
    assert statuses(problem, said + work.replace("b = 9v/2", "b = -9v/2"))[2] == "wrong"
