"""The acute angle with the line of centres (``alpha_A2``) measured from the other axis is named
``angle_other_axis``, as ``theta`` and ``beta`` are: it was "No common mistake reproduces 43.2"
for the 46.8° of OCR FM 2023 (found by a helper checking a derivation as a student)."""

from __future__ import annotations

import pytest

import derive

# Example 4.C.11 of the notes: v_A2n = -1.11, v_A2t = 3.05; v_B2n = 8.4, v_B2t = -9.15. The acute
# angles with the line of centres: atan(3.05/1.11) = 70.0°, atan(9.15/8.4) = 47.4°; from the
# other axis (the tangent): 20.0° and 42.6°.


@pytest.mark.parametrize(("name", "right", "other"), [("alpha_A2", "70.0", "20.0"), ("alpha_B2", "47.4", "42.6")])
def test_an_acute_angle_from_the_other_axis_is_named(name: str, right: str, other: str) -> None:
    solution = derive.solve(derive.load("notes-4c11-two-spheres"))
    report = derive.check(solution, answers={name: right})
    assert [i.status for i in report.items] == ["correct"]
    report = derive.check(solution, answers={name: other})
    (item,) = report.items
    assert item.status == "wrong"
    assert [d.mistake for d in item.diagnosis] == ["angle_other_axis"], item.message


@pytest.mark.parametrize(
    ("line", "status"),
    [
        (r"$$\alpha_{A2} = \tan^{-1}\left(\frac{3.05}{1.11}\right) = 70.0^\circ$$", "correct"),
        (r"$$\alpha_{A2} = \tan^{-1}\left(\frac{1.11}{3.05}\right) = 20.0^\circ$$", "wrong"),
        ("alpha_B2 = atan(9.15/8.4) = 47.4°", "correct"),
        ("alpha_B2 = atan(8.4/9.15) = 42.6°", "wrong"),
    ],
)
def test_the_acute_angle_by_derive_s_name_in_a_derivation(line: str, status: str) -> None:
    # derive's own name for the angle with the line of centres, typed in a derivation, is that
    # angle (it was read as a name of the student's own, defined by whatever it was set to)
    work = "v_A2n = -1.11, v_A2t = 3.05\nv_B2n = 8.4, v_B2t = -9.15\n" + line + "\n"
    report = derive.check(derive.load("notes-4c11-two-spheres"), derivation=work)
    item = next(i for i in report.items if i.kind == "line" and i.name == "3")
    assert item.status == status, item.message
    if status == "wrong":
        assert item.slip == "angle_other_axis", item.slip
