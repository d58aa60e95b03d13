"""Words that say what a number is, read where the student puts them: after the number they belong
to (``5cos37.6 = 3.96 along x and 5sin37.6 = 3.05 along y``: "along x" is the first component's,
not the second's label), and a quantity said in words just before its working with no "=" between
(``with speed of approach 12 - 4 = 8``: the speed of approach is 12 - 4, not that speed times 12).

Worked by hand. notes-4c11-two-spheres: A at 5 m/s, 37.6° from the line of centres: along it
5 cos 37.6° = 3.962, across 5 sin 37.6° = 3.051; B at 15 m/s: -15 cos 37.6° = -11.89, -15 sin 37.6°
= -9.152. byjus-4kg-ball-catches-8kg-ball: A (4 kg) at 12 m/s catches B (8 kg) at 4 m/s, e = 0.5:
the speed of approach 12 - 4 = 8, so v_B - v_A = 4; KE before ½(4)(144) + ½(8)(16) = 288 + 64 = 352.
"""

from __future__ import annotations

from support.checked import worst_lines

SPHERES = "notes-4c11-two-spheres"
BYJUS = "byjus-4kg-ball-catches-8kg-ball"
COMPONENTS = (
    "Take x along the line of centres from A to B and y across it.\n"
    "\n"
    "A before has components 5cos37.6 = 3.96 along x and 5sin37.6 = 3.05 along y.\n"
    "\n"
    "B before has components -15cos37.6 = -11.89 along x and -15sin37.6 = -9.15 along y.\n"
)


def test_the_words_after_a_number_are_its_own_axis() -> None:
    found = worst_lines(SPHERES, COMPONENTS)
    assert (found[3][0], found[5][0]) == ("correct", "correct")


def test_sin_and_cos_swapped_said_along_their_axes_are_still_found() -> None:
    swapped = COMPONENTS.replace(
        "5cos37.6 = 3.96 along x and 5sin37.6 = 3.05", "5sin37.6 = 3.05 along x and 5cos37.6 = 3.96"
    )
    assert worst_lines(SPHERES, swapped)[3] == ("wrong", "sin_cos_swapped")


APPROACH = (
    "Take the direction of motion as positive; x and y are the velocities of A and B after.\n"
    "Momentum: 4(12) + 8(4) = 4x + 8y\n"
    "Newton's law, with speed of approach 12 - 4 = 8:\n"
    "y - x = 0.5(8) = 4\n"
)


def test_a_speed_of_approach_said_before_its_working() -> None:
    found = worst_lines(BYJUS, APPROACH)
    assert [found[n][0] for n in (2, 3, 4)] == ["correct"] * 3


def test_the_speed_of_approach_with_b_taken_the_wrong_way_is_the_slip_there() -> None:
    wrong = APPROACH.replace("speed of approach 12 - 4 = 8", "approach speed 12 + 4 = 16").replace(
        "0.5(8) = 4", "0.5(16) = 8"
    )
    found = worst_lines(BYJUS, wrong)
    assert found[3] == ("wrong", "b_sign")
    assert found[4][0] == "carried"


def test_a_kinetic_energy_said_before_its_working() -> None:
    work = "KE before 0.5(4)(12)^2 + 0.5(8)(4)^2 = 288 + 64 = 352 J\n"
    assert worst_lines(BYJUS, work)[1][0] == "correct"


def test_a_one_word_label_before_a_colon_after_a_value_labels_the_next() -> None:
    """``n: 5cos37.6 = 3.96   t: 5sin37.6 = 3.05``: t is the second's axis (across: 3.05 is right)."""
    work = "x along the line of centres from A to B.\nA before: n: 5cos37.6 = 3.96   t: 5sin37.6 = 3.05\n"
    assert worst_lines(SPHERES, work)[2][0] == "correct"
    swapped = work.replace("n: 5cos37.6 = 3.96   t: 5sin37.6 = 3.05", "n: 5sin37.6 = 3.05   t: 5cos37.6 = 3.96")
    assert worst_lines(SPHERES, swapped)[2][0] == "wrong"


#: fisicalab-example-7-normal-at-20deg: the common normal at 20° from x; A moves at 45°, B at 120°,
#: so from n A's direction is 45 - 20 = 25° and B's 120 - 20 = 100°.
FISICALAB = "fisicalab-example-7-normal-at-20deg"


def test_a_name_after_from_is_the_line_an_angle_is_measured_from_not_the_angle() -> None:
    work = "Direction of A measured from n = 45 - 20 = 25°, and of B from n = 120 - 20 = 100°.\n"
    assert worst_lines(FISICALAB, work)[1][0] == "correct"
    assert worst_lines(FISICALAB, work.replace("= 100°", "= 110°"))[1][0] == "wrong"


def test_a_label_after_the_bodys_bracket_and_colon_is_the_axis() -> None:
    # OCR FM 2023: A at 4 m/s at 60° to the line of centres: along it 4 cos 60° = 2, across it
    # 4 sin 60° = 3.46. Written "∥ = 4 sin60 = 3.46" after "A (…):", the ∥ labels the component
    # along the line of centres: sin and cos swapped, at that line (the momentum after it carried).
    work = (
        "A (4 m/s, 60 deg to the line of centres): ∥ = 4 sin60 = 3.46, ⊥ = 4 cos60 = 2\n"
        "momentum: 5(3.46) + 3(-6) = 5x + 3y, so 5x + 3y = -0.7\n"
    )
    found = worst_lines("ocr-fm-2023-oblique-discs-60deg", work)
    assert found[1] == ("wrong", "sin_cos_swapped")
    assert found[2][0] == "carried"
