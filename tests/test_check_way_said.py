"""A line that only says which way is positive (``right = +ve``, ``+ve = away from wall``,
``left = positive``) is a declaration, not a relation: not marked, and not "not read" (it was:
"could not read the words 'right' as a quantity", though docs/checking.md shows ``up = +ve``).
The way itself is inferred from the values, as for "Taking left as positive"."""

from __future__ import annotations

import pytest

import derive

#: AQA M3 2007: A 0.3 kg at 3 m/s (to the right), B 0.2 kg at 2 m/s toward A, e = 0.8.
#: With left positive: u_A = -3, u_B = +2; momentum 0.3(-3) + 0.2(2) = -0.5; restitution
#: v_B - v_A = -0.8(2 - (-3)) = -4; so 0.5 v_A = -0.5 + 0.8 = 0.3, v_A = 0.6 and v_B = -3.4
#: (A back to the left at 0.6, B to the right at 3.4: the notes' v_A2n = -0.6, v_B2n = 3.4).
LEFT = """{way}
0.3(-3) + 0.2(2) = 0.3 v_A + 0.2 v_B
v_B - v_A = -0.8(2 - (-3)) = -4
0.3 v_A + 0.2(v_A - 4) = -0.5
v_A = 0.6
v_B = -3.4
"""


@pytest.mark.parametrize("way", ["left = +ve", "+ve = left", "Left = positive direction", "(left = +)"])
def test_a_line_saying_the_positive_way_is_not_marked(way: str) -> None:
    report = derive.check(derive.load("aqa-m3-2007-spheres-approach-head-on"), derivation=LEFT.format(way=way))
    marks = {i.name: i.status for i in report.items if i.kind == "line"}
    assert "1" not in marks, report.text() if hasattr(report, "text") else marks
    assert marks == {str(n): "correct" for n in range(2, 7)}, marks


#: OCR M2 2006: A 2 kg and B 1 kg meet, each at 5 m/s, e = 0.8: 2(5) + 1(-5) = 5 = 2v_A + v_B and
#: v_B - v_A = 0.8(10) = 8, so v_A = -1 (A back, to the left, at 1 m/s) and v_B = 7 (to the right).
MEET = """2(5) + 1(-5) = 2v_A + v_B
v_B - v_A = 0.8(5 + 5) = 8
v_A = -1, v_B = 7
{answer}
"""


@pytest.mark.parametrize(
    ("answer", "status"),
    [
        ("A: 1 m/s to the left, B: 7 m/s to the right", "correct"),
        ("A: 1 m/s left and B: 7 m/s right", "correct"),
        ("A: 1 m/s to the right, B: 7 m/s to the right", "wrong"),  # A reverses: it moves left
    ],
)
def test_a_speed_with_its_way_in_words_is_the_velocity(answer: str, status: str) -> None:
    # it was read as "speed of A = -1" (the size, signed by the way): wrong however it was written
    report = derive.check(derive.load("ocr-m2-2006-spheres-meet-at-5-ke-lost"), derivation=MEET.format(answer=answer))
    marks = {i.name: i.status for i in report.items if i.kind == "line"}
    assert marks == {"1": "correct", "2": "correct", "3": "correct", "4": status}, marks
