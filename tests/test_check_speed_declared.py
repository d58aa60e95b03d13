"""A name declared in words for B's *speed* before (``Let U be B's speed before``, ``let p and q
be the speeds of A and B before``, bold ``Let Q's speed before be **q**``) where the problem's
statement says the bodies move towards each other (or in opposite directions): the size of B's
velocity, so minus it along derive's n (from A toward B). A name declared for B's *velocity*
stays the velocity.

OCR M2 2006 by hand: A (2 kg) and B (1 kg) each at 5 m/s toward each other, e = 0.8: momentum
2(5) - 1(5) = 5 = 2 v_A2 + v_B2, v_B2 - v_A2 = 0.8(10) = 8: v_A2 = -1, v_B2 = 7; so with U = 5
(B's speed), 2(5) - U = 5 = 2(-1) + 7. CIE 9231 2019: A at 2u, B at u toward each other:
restitution v_B2 - v_A2 = e(2u - (-u)) = e(2u + s) with s = u, B's speed.
"""

from __future__ import annotations

import pytest

import derive

OCR = "ocr-m2-2006-spheres-meet-at-5-ke-lost"
CIE = "cie-9231-p2-2019-june-q3-2m-at-2u-meets-4m-at-u"


@pytest.mark.parametrize(
    ("problem", "work", "expected"),
    [
        (OCR, "Let U be B's speed before.\n2(5) - U = 2(-1) + 7", "correct"),
        (OCR, "Let U be B's speed before.\n2(5) + U = 2(-1) + 7", "wrong"),  # the speed added: wrong
        (OCR, "Let B's speed before be **w**.\n2(5) - 1(w) = 2(-1) + 1(7)", "correct"),
        (OCR, "Let w be B's velocity before.\n2(5) + w = 2(-1) + 7", "correct"),  # a velocity: signed
        (CIE, "Let s be B's speed before the collision.\nv_B2 - v_A2 = e(2u + s)", "correct"),
        (CIE, "Let s be B's speed before the collision.\nv_B2 - v_A2 = e(2u - s)", "wrong"),
        (CIE, "let p and q be the speeds of A and B before\nv_B2 - v_A2 = e(p + q)", "correct"),
    ],
)
def test_a_speed_before_declared_for_a_body_moving_toward_the_other(problem: str, work: str, expected: str) -> None:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    assert [i.status for i in report.items] == [expected]
