"""A line of givens (``**Given:**``, ``Data:``, ``Known:``) says the problem's values again, in the
student's names and signs: a teacher does not mark it, however its names are read; a given copied
wrongly there (a number that is no given's of that kind) is still the slip it is.

Worked by hand (ocr-mei-fmm-2023-a-speed-0p2-backward): A (0.5 kg) at 6 m/s catches B (2 kg) at
2 m/s; A comes back at 0.2 m/s. With the original direction positive, 3 + 4 = -0.1 + 2 v_B, so
v_B = 7.1/2 = 3.55 m/s. (ocr-m2-2012-particle-hits-wall): 0.8 kg at 4 m/s into a wall, e = 0.3.
"""

from __future__ import annotations

from support.checked import worst_lines

BACKWARD = "ocr-mei-fmm-2023-a-speed-0p2-backward"
WALL = "ocr-m2-2012-particle-hits-wall"
GIVEN_BACK = (
    "**Given:** $m_A = 0.5$ kg, $m_B = 2$ kg, $(v_A)_1 = 6$ m/s, $(v_B)_1 = 2$ m/s, "
    "$(v_A)_2 = 0.2$ m/s back the way it came.\n"
    "\n"
    "Take the original direction as positive, so $(v_A)_2 = -0.2$ m/s.\n"
    "\n"
    "$0.5(6) + 2(2) = 0.5(-0.2) + 2(v_B)_2$\n"
    "\n"
    "$(v_B)_2 = 7.1/2 = 3.55$ m/s\n"
)


def test_a_velocity_after_restated_by_its_size_and_way_in_words_is_not_marked() -> None:
    found = worst_lines(BACKWARD, GIVEN_BACK)
    assert found.get(1, ("not marked", ""))[0] in ("not marked", "correct")
    assert [found[n][0] for n in (5, 7)] == ["correct", "correct"]


def test_a_speed_copied_wrongly_on_a_data_line_is_still_the_slip() -> None:
    work = (
        "Data: m = 0.8 kg, v_1 = 5 m/s toward the wall, e = 0.3\n"
        "Speed after: v_2 = 0.3 × 5 = 1.5 m/s away from the wall\n"
    )
    found = worst_lines(WALL, work)
    assert found[1] == ("wrong", "copied_wrong")
    assert found[2][0] == "carried"


def test_a_number_that_is_another_kinds_given_is_not_a_restatement() -> None:
    """B's speed written 0.5 (A's mass is 0.5 kg, B moves at 2 m/s): a velocity copied wrongly."""
    work = GIVEN_BACK.replace("$(v_B)_1 = 2$ m/s", "$(v_B)_1 = 0.5$ m/s")
    assert worst_lines(BACKWARD, work)[1][0] == "wrong"
