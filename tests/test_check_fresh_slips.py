"""A line that carries an earlier mistake's number and makes a new common mistake is named by the
new one: ``v_A2t = e v_A1t = 0.6 × 3.96`` after A's components were resolved with sin and cos
swapped (3.96 for 3.05) is e put on the t component, not the swap made again. Values by hand."""

from __future__ import annotations

from support.checked import lines

#: Example 4.C.11: A at 5 m/s, 37.6° from the line of centres, e = 0.6: v_A1n = 5 cos 37.6° = 3.96,
#: v_A1t = 5 sin 37.6° = 3.05 = v_A2t. Swapped: 5 sin 37.6° = 3.05 along n, 5 cos 37.6° = 3.96
#: along t; then e on t: 0.6 × 3.96 = 2.376.
NOTES = "notes-4c11-two-spheres"


def test_e_on_the_t_component_after_the_components_swapped_is_a_fresh_slip() -> None:
    work = "v_A1n = 5 sin 37.6° = 3.05\nv_A1t = 5 cos 37.6° = 3.96\nv_A2t = e v_A1t = 0.6 × 3.96 = 2.38\n"
    found = lines(NOTES, work)
    assert found[1] == ("wrong", "sin_cos_swapped", False)
    assert found[2] == ("wrong", "sin_cos_swapped", True)
    assert found[3] == ("wrong", "e_on_t", False)
