"""A body's own lowercase letter with a component mark as its velocity (issue #31): ``a_n``,
``a_t`` A's components (before, where ``a_n'`` is also written for after), ``b_n'`` B's after; as
students write them beside ``n = line of centres, t = tangent``.

Worked by hand (ocr-fm-2023-oblique-discs-60deg; the OCR mark scheme: v_Ax = -13/4, v_Bx = 11/4):
A (5 kg) at 4 m/s at 60° to the line of centres: a_n = 4 cos 60° = 2, a_t = 4 sin 60° = 3.46;
B (3 kg) at 6 m/s toward A: b_n = -6. Momentum along n: 5(2) + 3(-6) = -8 = 5a_n' + 3b_n';
restitution b_n' - a_n' = 0.75(2 + 6) = 6; so 8a_n' = -8 - 18 = -26, a_n' = -3.25, b_n' = 2.75;
a_t' = a_t = 3.46 (smooth discs). Wrong: a_t' = 0.75(3.46) (e on the tangent component).
"""

from __future__ import annotations

from support.checked import line_statuses as statuses

DISCS = "ocr-fm-2023-oblique-discs-60deg"
WORK = """n along the line of centres, t along the tangent.
before: a_n = 4cos60 = 2, a_t = 4sin60 = 3.46, b_n = -6
5(2) + 3(-6) = 5a_n' + 3b_n'
b_n' - a_n' = 0.75(2 + 6) = 6
8a_n' = -26, a_n' = -3.25
b_n' = 2.75
a_t' = 3.46
"""


def test_a_bodys_letter_with_a_component_mark_is_its_velocity_component() -> None:
    assert set(statuses(DISCS, WORK)) == {"correct"}


def test_a_tangent_component_times_e_in_those_names_is_wrong() -> None:
    assert statuses(DISCS, WORK.replace("a_t' = 3.46", "a_t' = 0.75(3.46) = 2.6"))[-1] == "wrong"


def test_a_wrong_velocity_after_in_those_names_is_not_correct() -> None:
    assert statuses(DISCS, WORK.replace("b_n' = 2.75", "b_n' = 3.25"))[-2] != "correct"
