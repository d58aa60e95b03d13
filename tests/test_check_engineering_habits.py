"""Three habits of the engineering texts in the first lines of a derivation.

A wall, a cushion or a barrier named as a body (``(v_W)_1 = (v_W)_2 = 0``, ``vC2``, as Hibbeler writes
restitution at a fixed surface, ``e = ((v_W)_2 - (v_A)_2)/((v_A)_1 - (v_W)_1)``): its velocity is 0,
the surface does not move. A size in the problem's letters with its way as an arrow
(``(v_Q)_2 = u(1 + 2e) ←``): the velocity signed by the arrow, as a number with its arrow is. A body
named by its word's lowercase initial beside another's capital (the bullet's ``v_b1`` beside the
block's ``v_B1``): two bodies, not B twice.

Worked by hand. Edexcel M2 wall: 2 kg at 4 m/s into the wall, e = 0.4, so v_A2 = -0.4(4) = -1.6 m/s.
OCR M2 2012 wall: 0.8 kg at 4 m/s, e = 0.3, so v_A2 = -1.2 m/s. Edexcel M2 2010 Q2: P (2m) at 2u meets
Q (m) at u, toward each other; momentum 2m(2u) - mu = 3mu = 2m v_P + m v_Q, restitution
v_Q - v_P = 3eu: v_P = u(1 - e), v_Q = u(1 + 2e), both along P's first way (→, +). MSU bullet: 0.02 kg
at 300 m/s into a 4 kg block at rest, lodging: 0.02(300) = 4.02 V, V = 1.49 m/s; T_1 = ½(0.02)(300²) = 900 J.
"""

from __future__ import annotations

import pytest

import derive


def statuses(problem: str, work: str) -> list[str]:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    return [i.status for i in report.items]


WALL = "edexcel-m2-ball-rebounds-from-wall"
OCR_WALL = "ocr-m2-2012-particle-hits-wall"
P_Q = "edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u"

HIBBELER = """Positive toward the wall. The wall is fixed: $(v_W)_1 = (v_W)_2 = 0$.

$$e = \\frac{(v_W)_2 - (v_A)_2}{(v_A)_1 - (v_W)_1}$$

$$0.4 = \\frac{0 - (v_A)_2}{4 - 0}$$

$(v_A)_2 = -1.6$ m/s
"""

PHONE = """toward wall +ve
vW1 = vW2 = 0 (wall fixed)
e = (vW2 - vA2)/(vA1 - vW1)
0.3 = (0 - vA2)/(4 - 0)
vA2 = -1.2
"""


@pytest.mark.parametrize(
    ("problem", "work", "expected"),
    [
        (WALL, HIBBELER, ["correct"] * 4),
        (OCR_WALL, PHONE, ["correct"] * 4),
        (OCR_WALL, PHONE.replace("vW1 = vW2 = 0", "vW1 = 0, vW2 = 4"), ["wrong", "correct", "correct", "correct"]),
    ],
)
def test_a_fixed_surface_named_as_a_body_does_not_move(problem: str, work: str, expected: list[str]) -> None:
    assert statuses(problem, work) == expected


def test_the_fixed_surface_is_said_in_the_report() -> None:
    report = derive.check(derive.solve(derive.load(WALL)), derivation=HIBBELER)
    assert "v_W1: read as the velocity of the fixed surface (0: it does not move)." in report.text()


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("Take → positive. After: $(v_P)_2 = u(1-e) \\rightarrow$, $(v_Q)_2 = u(1+2e) \\rightarrow$.", ["correct"]),
        ("Take → positive. After: $(v_P)_2 = u(1-e) \\rightarrow$, $(v_Q)_2 = u(1+2e) \\leftarrow$.", ["wrong"]),
        ("(+->) before: (v_P)_1 = 2u ->, (v_Q)_1 = u <-", ["correct"]),
        ("(+->) before: (v_P)_1 = 2u ->, (v_Q)_1 = u ->", ["wrong"]),
        ("(+->) before: (v_P)_1 = 2u ->, (v_Q)_1 = 1u <-", ["correct"]),  # a size in letters led by a digit
    ],
)
def test_a_size_in_letters_is_signed_by_its_arrow(work: str, expected: list[str]) -> None:
    assert statuses(P_Q, work) == expected


BULLET = """bullet b, block B. m_b = 0.02 kg, v_b1 = 300 m/s; m_B = 4 kg, v_B1 = 0
CLM: m_b v_b1 + m_B v_B1 = (m_b + m_B) V
0.02(300) + 0 = 4.02 V
V = 1.49 m/s
T_1 = 0.5(0.02)(300)^2 = 900 J
"""


def test_a_bodys_lowercase_initial_beside_the_other_bodys_capital_is_its_own() -> None:
    assert statuses("msu-lectureonline-bullet-lodges-in-block", BULLET) == ["correct"] * 5
    slipped = BULLET.replace("= 900 J", "= 1800 J")
    assert statuses("msu-lectureonline-bullet-lodges-in-block", slipped) == ["correct"] * 4 + ["wrong"]
