"""A velocity before the impact resolved with sin for cos, however the line names the component.

The problem's text fixes what the angle is measured from; a component worked with sin where cos
is right (the angle taken from the other axis) is the slip, and a teacher finds it on the line
that resolves, whether the line calls the component by a name that says only its axis
(``v_perp = 10 cos 30°``, ``V_n = U cos α``), by its axis in LaTeX with a space before the
working (``\\text{along}: \\; 5\\sin 37.6^\\circ``), or by its body before a vector of numbers
(``A before: 5 sin 37.6 i + 5 cos 37.6 j``). The same lines resolved the right way stay correct.
A number a carried line comes to is the student's own (wrong): arithmetic worked from it is carried.

Values worked by hand:
- the test's own wall problem (support.checked.WALL_30): 10 m/s at 30° to the wall; into the wall
  (n) 10 sin 30° = 5, along it (t) 10 cos 30° = 8.660. Swapped: n 8.66, t 5.
- edexcel-fm1-2023 cushion: U at α to the cushion DC (from it, +t): n = U sin α, t = U cos α.
- notes-4c11-two-spheres: A at 5 m/s, 37.6° from the line of impact: along 5 cos 37.6° = 3.961,
  across 5 sin 37.6° = 3.051.
"""

from __future__ import annotations

from support.checked import WALL_30, text_lines, worst_lines

CUSHION = "edexcel-fm1-2023-june-q7a-cushion-show-tan-beta"
SPHERES = "notes-4c11-two-spheres"


def test_a_name_that_says_its_axis_at_a_wall_with_sin_for_cos(tmp_path) -> None:
    assert text_lines(tmp_path, WALL_30, "v_perp = 10 cos 30° = 8.66\nv_par = 10 sin 30° = 5\n") == ["wrong", "wrong"]
    assert text_lines(tmp_path, WALL_30, "v_perp = 10 sin 30° = 5\nv_par = 10 cos 30° = 8.66\n") == ["correct"] * 2


def test_a_letter_component_by_its_axis_alone_in_letters() -> None:
    swapped = worst_lines(CUSHION, "V_n = U cos(alpha)\nV_t = U sin(alpha)\n")
    assert swapped[1] == ("wrong", "sin_cos_swapped"), swapped
    assert swapped[2][0] == "wrong", swapped  # the same mistake again
    right = worst_lines(CUSHION, "V_n = U sin(alpha)\nV_t = U cos(alpha)\n")
    assert [s for s, _ in right.values()] == ["correct", "correct"], right


def test_an_axis_label_with_a_latex_space_before_the_working() -> None:
    swapped = r"$\text{along the line of impact}: \; 5\sin 37.6^\circ = 3.05, \qquad \text{across}: \; 5\cos 37.6^\circ = 3.96$"
    assert worst_lines(SPHERES, swapped + "\n")[1] == ("wrong", "sin_cos_swapped")
    right = r"$\text{along}: \, 5\cos 37.6^\circ = 3.96, \quad \text{across}: \, 5\sin 37.6^\circ = 3.05$"
    assert worst_lines(SPHERES, right + "\n")[1][0] == "correct"


def test_a_vector_of_numbers_after_a_body_label() -> None:
    axes = "i along the line of impact, j across it\n"
    swapped = worst_lines(SPHERES, axes + "A before: 5 sin 37.6 i + 5 cos 37.6 j = 3.05i + 3.96j\n")
    assert swapped[2] == ("wrong", "sin_cos_swapped"), swapped
    swapped = worst_lines(SPHERES, axes + "A: (5 sin 37.6°) i + (5 cos 37.6°) j = 3.05 i + 3.96 j\n")
    assert swapped[2] == ("wrong", "sin_cos_swapped"), swapped
    right = worst_lines(SPHERES, axes + "A before: 5 cos 37.6 i + 5 sin 37.6 j = 3.96i + 3.05j\n")
    assert right[2][0] == "correct", right


def test_arithmetic_on_an_angle_a_carried_line_came_to_is_carried(tmp_path) -> None:
    # swapped: into the wall 8.66, along 5; out of it after 0.5 × 8.66 = 4.33, at tan⁻¹(4.33/5) = 40.9°
    # to the wall (the truth: 2.5 and 8.66, 16.1°), so 180° − 30° − 40.9° = 109.1° is worked from it
    work = (
        "Along the wall: 10 sin 30° = 5\nInto the wall: 10 cos 30° = 8.66\nAfter, out of the wall: 0.5 × 8.66 = 4.33\n"
        "The ball leaves at tan⁻¹(4.33/5) = 40.9° to the wall, so it is turned through\n180° − 30° − 40.9° = 109.1°\n"
    )
    assert text_lines(tmp_path, WALL_30, work) == ["wrong", "wrong", "carried", "carried", "carried"]


def test_names_met_in_a_momentum_line_after_the_slip_are_read_by_its_shape() -> None:
    # ocr-fm-2023-oblique-discs-60deg (5 kg A at 4 m/s, 60° to the line of centres; 3 kg B at -6; e = 3/4).
    # Swapped: along 4 sin 60° = 3.46; 5(3.46) - 18 = -0.7 = 5p + 3q, q - p = 0.75(9.46) = 7.10, so
    # 8p = -22.0, p = -2.75, q = 4.35. The truth: along 2; 5p + 3q = -8, q - p = 6: p = -3.25, q = 2.75,
    # so p's carried -2.75 is minus B's true component: the momentum line, (3) in its shape with p A's
    # and q B's, reads them, not that coincidence. Every line after the slip is carried.
    work = (
        "line of centres positive from A to B\n"
        "A: 4 m/s at 60 deg to the line of centres, so par = 4 sin 60 = 3.46, perp = 4 cos 60 = 2\n"
        "B: par -6, perp 0\n"
        "momentum: 5(3.46) + 3(-6) = 5p + 3q, so 5p + 3q = -0.7\n"
        "restitution: q - p = 0.75(3.46 + 6) = 7.10\n"
        "so 5p + 3(p + 7.10) = -0.7, 8p = -22.0, p = -2.75\n"
        "q = -2.75 + 7.10 = 4.35\n"
        "|v_A| = sqrt(2.75^2 + 2^2) = 3.40, tan(theta) = 2/2.75 so theta = 36 deg with the line of centres\n"
    )
    found = worst_lines("ocr-fm-2023-oblique-discs-60deg", work)
    assert found[2] == ("wrong", "sin_cos_swapped"), found
    assert [found[n][0] for n in (4, 5, 6, 7, 8)] == ["carried"] * 5, found
