"""A component named with a body, an axis letter and a time (``v_Ay1``, ``(v_Bx)_2``) where the
student's words place x and y (derive/checking/namegrammar.py, ``_in_axes``): y along the line of
impact makes ``v_Ay1`` A's component along it, as a teacher reads it. Worked by hand."""

from __future__ import annotations

from support.checked import worst_lines

# 20 kg at 5 m/s meets 5 kg at 15 m/s, each at 37.6° to the line of impact, e = 0.6. Along it:
# A 5 cos 37.6° = 3.962, B -15 cos 37.6° = -11.885; momentum 79.24 - 59.43 = 19.81 = 20a + 5b,
# b - a = 0.6(15.847) = 9.508: a = (19.81 - 47.54)/25 = -1.109, b = 8.399.
WORK = """y-axis along the line of impact (from A to B), x-axis tangent to the contact.
v_Ay1 = {first}
v_By1 = -15 cos 37.6° = -11.885
20 v_Ay1 + 5 v_By1 = 20 v_Ay2 + 5 v_By2
v_By2 - v_Ay2 = 0.6(v_Ay1 - v_By1)
v_Ay2 = -1.109
v_By2 = 8.399
"""


def test_y_along_the_line_of_impact_makes_v_ay_the_component_along_it() -> None:
    got = worst_lines("notes-4c11-two-spheres", WORK.format(first="5 cos 37.6° = 3.962"))
    assert [got[n][0] for n in range(2, 8)] == ["correct"] * 6


def test_the_component_along_the_line_of_impact_with_sin_is_still_the_slip() -> None:
    # 5 sin 37.6° = 3.051 is the component along the tangent, not along y here.
    got = worst_lines("notes-4c11-two-spheres", WORK.format(first="5 sin 37.6° = 3.051"))
    assert got[2][0] == "wrong"
    assert got[3][0] == "correct"
